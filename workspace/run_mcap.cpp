#include "workspace/run_mcap.h"

#include <fstream>

#include "base/file_text.h"
#include "base/text_rules.h"
#include "mcap/ros2_bag.h"
#include "mcap/run_mcap.h"
#include "run/run_csv.h"
#include "workspace/workspace.h"

namespace tactile::workspace {

namespace {

// A label set's segments on the run as per-step classes and annotators.
Result<mcap::LabelTrack> labelTrack(storage::LabelStore labels, const std::string& set,
                                    std::int64_t runId, std::size_t steps) {
  auto info = labels.find(set);
  if (!info) return info.error();
  auto segments = labels.segments(info->id, runId);
  if (!segments) return segments.error();
  mcap::LabelTrack track;
  track.set = set;
  track.classes.assign(steps * kGroupCount, -1);
  track.annotator.assign(steps * kGroupCount, 0);
  track.annotators.push_back("");
  for (const storage::LabelSegment& s : segments.value()) {
    std::uint16_t a = 0;
    const std::string& who = s.annotator.empty() ? info->annotator : s.annotator;
    const auto it = std::find(track.annotators.begin(), track.annotators.end(), who);
    if (it == track.annotators.end()) {
      if (track.annotators.size() >= 65535)
        return Error("label set '" + set + "' has too many annotators");
      track.annotators.push_back(who);
      a = static_cast<std::uint16_t>(track.annotators.size() - 1);
    } else {
      a = static_cast<std::uint16_t>(it - track.annotators.begin());
    }
    const auto last = std::min<std::int64_t>(s.lastStep, static_cast<std::int64_t>(steps) - 1);
    for (std::int64_t k = std::max<std::int64_t>(s.firstStep, 0); k <= last; ++k) {
      const std::size_t i =
          static_cast<std::size_t>(k) * kGroupCount + static_cast<std::size_t>(groupIndex(s.group));
      track.classes[i] = static_cast<std::int8_t>(s.cls);
      track.annotator[i] = a;
    }
  }
  return track;
}

}  // namespace

Result<McapExportReport> exportRunMcap(Workspace& workspace, const McapExportRequest& request) {
  storage::RunStore runs = workspace.runStore();
  if (Status writable = checkWritable(request.out); !writable) return writable.error();
  auto info = runs.find(request.run);
  if (!info) return info.error();
  // The steps are read a window at a time as the export goes (a 1,000,000-step run would take
  // over 700 MB whole); the first window also gives the metadata and columns. 16,384 steps keep a
  // window's sensor column (12 MB) below the C library's limit for memory mapped afresh, so each
  // window reuses the last one's memory instead of faulting in new pages (0.4 s of a 1,000,000-step
  // export).
  constexpr std::int64_t kWindowSteps = 16384;
  auto run = runs.loadWindow(info->id, 0, kWindowSteps);
  if (!run) return run.error();
  const std::size_t steps = static_cast<std::size_t>(info->stepCount);
  std::optional<storage::RunWindow> window;
  struct WindowFailed {
    Error error;
  };
  McapExportReport report;
  report.run = info->name;
  report.steps = info->stepCount;
  mcap::RunExport what;
  what.run = &run->data;
  what.steps = steps;
  what.truth = info->hasTruth;
  what.window = [&](std::size_t first) -> const RunData* {
    if (first == 0) return &run->data;
    auto next = runs.loadWindow(info->id, static_cast<std::int64_t>(first), kWindowSteps);
    if (!next) throw WindowFailed{next.error()};
    window = std::move(next.value());
    return &window->data;
  };
  what.name = info->name;
  what.library = "tactile " + std::string(programVersion());
  auto scene = runs.sceneJson(info->id);
  if (!scene) return scene.error();
  what.sceneJson = scene.value();
  if (!what.sceneJson && !info->scene.empty()) {
    report.warnings.push_back("run '" + info->name + "': scene '" + info->scene +
                              "' is not stored; the export has no /scene");
  }
  for (const std::string& set : request.labelSets) {
    auto track = labelTrack(workspace.labelStore(), set, info->id, steps);
    if (!track) return track.error();
    what.labels.push_back(std::move(track.value()));
  }
  if (!request.model.empty()) {
    analysis::ClassifyOptions options;
    options.allDecisions = true;
    auto classified = workspace.classify(request.model, info->name, options);
    if (!classified) return classified.error();
    mcap::DecisionTrack track;
    track.model = request.model;
    track.classes.assign(steps * kGroupCount, -1);
    bool allOnline = true;
    for (int g = 0; g < kGroupCount; ++g) {
      const analysis::GroupClassification& gc =
          classified->result.groups[static_cast<std::size_t>(g)];
      const bool online = !gc.online.empty();
      allOnline = allOnline && (online || gc.model == nullptr);
      const analysis::Decisions& decisions = online ? gc.online : gc.decided;
      for (std::size_t k = 0; k < steps; ++k) {
        const std::string name = gc.nameOf(decisions, k);
        if (const auto cls = parseContactClass(name)) {
          track.classes[k * kGroupCount + static_cast<std::size_t>(g)] =
              static_cast<std::int8_t>(*cls);
        }
      }
    }
    track.decision = allOnline ? "online" : "online where the model has one, else its default";
    if (!allOnline) {
      report.warnings.push_back("model '" + request.model +
                                "': a group has no online decision (no transitions); its default "
                                "decision is exported");
    }
    what.decisions.push_back(std::move(track));
  }
  // Streamed to a temporary file beside the output as chunks are finished, then renamed over it.
  AtomicFileWriter file;
  if (Status opened = file.open(request.out); !opened) return opened.error();
  std::optional<Error> writeError;
  struct SinkFailed {};
  auto sink = [&](std::string_view piece) {
    if (Status written = file.write(piece); !written) {
      writeError = written.error();
      throw SinkFailed{};
    }
    report.bytes += piece.size();
  };
  try {
    if (!mcap::writeRunMcap(what, sink, request.writer, request.progress)) {
      file.abandon();
      return Error(request.out.string(), "export cancelled; nothing written");
    }
  } catch (const SinkFailed&) {
    return *writeError;
  } catch (const WindowFailed& e) {
    return e.error;
  } catch (const std::runtime_error& e) {
    return Error(request.out.string(), e.what());
  } catch (const std::bad_alloc&) {
    return Error(request.out.string(),
                 "out of memory: the run is too large for this machine's memory");
  }
  if (Status committed = file.commit(); !committed) return committed.error();
  report.topics = {"/tactile", "/robot/state", "/robot/pose"};
  if (info->hasTruth) report.topics.push_back("/truth");
  for (const std::string& set : request.labelSets)
    report.topics.push_back("/labels/" + set);
  if (!request.model.empty()) report.topics.push_back("/decisions/" + request.model);
  if (!run->data.extraColumns.empty()) report.topics.push_back("/extra");
  if (what.sceneJson) report.topics.push_back("/scene");
  return report;
}

storage::ImportOutcome importMcap(storage::RunStore runs, const McapImportRequest& request) {
  storage::ImportOutcome failed;
  failed.file = request.file.string();
  failed.status = storage::ImportStatus::Failed;
  const std::string fileName = request.file.string();
  FileText text;
  if (Status loaded = text.load(request.file); !loaded) {
    failed.message = loaded.errorText();
    return failed;
  }
  const std::string name =
      request.name.empty() ? nameFromFileStem(request.file.stem().string()) : request.name;
  if (request.mapping || request.mappingText) {
    auto mappingText = request.mapping ? readFileText(*request.mapping)
                                       : Result<std::string>(*request.mappingText);
    if (!mappingText) {
      failed.message = mappingText.errorText();
      return failed;
    }
    auto mapping = mcap::parseMapping(mappingText.value(),
                                      request.mapping ? request.mapping->string() : "the mapping");
    if (!mapping) {
      failed.message = mapping.errorText();
      return failed;
    }
    auto bag = mcap::readRos2Bag(text.view(), fileName, mapping.value());
    if (!bag) {
      failed.message = bag.errorText();
      return failed;
    }
    if (Status ok = checkName(name, "run"); !ok) {
      failed.message = fileName + ": " + ok.errorText() + " (give a name with --name)";
      return failed;
    }
    text = FileText();  // the bag's pages are no longer needed while the run is stored
    storage::ImportOutcome outcome =
        runs.importRun(std::move(bag->run), name, fileName, request.sceneResolver);
    for (std::string& w : bag->warnings)
      outcome.warnings.insert(outcome.warnings.begin(), std::move(w));
    return outcome;
  }
  auto own = mcap::readRunMcap(text.view(), fileName);
  if (!own) {
    failed.message = own.errorText();
    return failed;
  }
  // Through the run-file reader: the same checks, and the same stored run, as the run file.
  const std::string csv = formatRunCsv(own->run);
  storage::ImportOptions options;
  options.name = request.name;
  options.sceneResolver = request.sceneResolver;
  storage::ImportOutcome outcome = runs.importText(csv, fileName, options);
  outcome.file = fileName;
  return outcome;
}

bool isRunMcapFile(const std::filesystem::path& file) {
  FileText text;
  if (!text.load(file)) return false;
  return mcap::looksLikeRunMcap(text.view());
}

}  // namespace tactile::workspace
