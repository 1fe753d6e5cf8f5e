#include "workspace/workspace.h"

#include "base/text_rules.h"

#include <algorithm>
#include <array>
#include <limits>
#include <set>
#include <sstream>
#include <utility>

#include "analysis/metrics.h"
#include "run/json_text.h"

#ifndef TACTILE_VERSION
#define TACTILE_VERSION "unknown"
#endif

namespace tactile::workspace {

using nlohmann::json;

namespace {

Error failure(std::string message) {
  return Error(std::move(message));
}

std::vector<analysis::RunReference> runRefs(const std::vector<storage::RunInfo>& infos) {
  std::vector<analysis::RunReference> out;
  for (const storage::RunInfo& r : infos)
    out.push_back({r.name, r.stepCount, r.checksum, r.scene});
  return out;
}

std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

}  // namespace

json runsJson(const std::vector<storage::RunInfo>& infos) {
  json out = json::array();
  for (const storage::RunInfo& r : infos)
    out.push_back({{"name", r.name}, {"steps", r.stepCount}, {"checksum", r.checksum}});
  return out;
}

std::optional<SplitMode> parseSplitMode(std::string_view name) {
  if (name == "by-run") return SplitMode::ByRun;
  if (name == "leave-one-run-out") return SplitMode::LeaveOneRunOut;
  if (name == "by-scene") return SplitMode::ByScene;
  return std::nullopt;
}

std::string_view splitModeName(SplitMode mode) {
  switch (mode) {
    case SplitMode::ByRun:
      return "by-run";
    case SplitMode::LeaveOneRunOut:
      return "leave-one-run-out";
    case SplitMode::ByScene:
      return "by-scene";
  }
  return "by-run";
}

std::string_view programVersion() {
  return TACTILE_VERSION;
}

Result<std::unique_ptr<Workspace>> Workspace::open(const std::filesystem::path& path,
                                                   const storage::OpenOptions& options) {
  auto db = storage::RunDatabase::open(path, options);
  if (!db) return db.error();
  return std::make_unique<Workspace>(std::move(db.value()));
}

Workspace::Workspace(std::unique_ptr<storage::RunDatabase> database) : db_(std::move(database)) {}

Result<RunData> Workspace::loadRun(std::string_view name) {
  auto info = db_->runs().find(name);
  if (!info) return info.error();
  return db_->runs().load(info->id);
}

Result<storage::RunWindow> Workspace::loadWindow(std::string_view name, std::int64_t firstStep,
                                                 std::int64_t count) {
  auto info = db_->runs().find(name);
  if (!info) return info.error();
  return db_->runs().loadWindow(info->id, firstStep, count);
}

Result<storage::RunTrack> Workspace::loadTrack(std::string_view name) {
  auto info = db_->runs().find(name);
  if (!info) return info.error();
  return db_->runs().loadTrack(info->id);
}

namespace {

// Group-steps per run as percent of the run's steps x 8.
Result<std::vector<std::pair<std::int64_t, double>>> percentOfRuns(
    storage::RunDatabase& db, Result<std::vector<std::pair<std::int64_t, std::int64_t>>> covered) {
  if (!covered) return covered.error();
  auto runs = db.runs().list();
  if (!runs) return runs.error();
  std::vector<std::pair<std::int64_t, double>> out;
  for (const auto& [runId, groupSteps] : covered.value()) {
    const auto run = std::find_if(runs->begin(), runs->end(),
                                  [id = runId](const storage::RunInfo& r) { return r.id == id; });
    if (run == runs->end() || run->stepCount == 0) continue;
    out.emplace_back(runId, 100.0 * static_cast<double>(groupSteps) /
                                static_cast<double>(run->stepCount * kGroupCount));
  }
  return out;
}

}  // namespace

Result<std::vector<std::pair<std::int64_t, double>>> Workspace::modelLabelCoverage(
    std::int64_t setId) {
  return percentOfRuns(*db_, db_->labels().modelLabelledSteps(setId));
}

Result<std::vector<std::pair<std::int64_t, double>>> Workspace::labelCoverage(std::int64_t setId) {
  auto covered = db_->labels().labelledSteps(setId);
  if (!covered) return covered.error();
  auto runs = db_->runs().list();
  if (!runs) return runs.error();
  std::vector<std::pair<std::int64_t, double>> out;
  for (const auto& [runId, groupSteps] : covered.value()) {
    const auto run = std::find_if(runs->begin(), runs->end(),
                                  [id = runId](const storage::RunInfo& r) { return r.id == id; });
    if (run == runs->end() || run->stepCount == 0) continue;
    out.emplace_back(runId, 100.0 * static_cast<double>(groupSteps) /
                                static_cast<double>(run->stepCount * kGroupCount));
  }
  return out;
}

namespace {

// Per group: the agreeing share, kappa and the chance agreement of a confusion (rows one rater,
// columns the other).
std::vector<GroupAgreement> agreementOf(
    const std::array<analysis::ConfusionMatrix, kGroupCount>& confusion) {
  std::vector<GroupAgreement> out;
  for (const GroupInfo& info : kSensorGroups) {
    const analysis::ConfusionMatrix& c =
        confusion[static_cast<std::size_t>(groupIndex(info.group))];
    GroupAgreement a;
    a.group = info.group;
    a.comparedSteps = static_cast<std::int64_t>(c.total());
    double chance = 0.0;
    for (int i = 0; i < kContactClassCount; ++i) {
      const auto cls = static_cast<ContactClass>(i);
      a.agreeingSteps += static_cast<std::int64_t>(c.count(cls, cls));
      chance += static_cast<double>(c.trueCount(cls)) * static_cast<double>(c.predictedCount(cls));
    }
    if (a.comparedSteps > 0) {
      const auto n = static_cast<double>(a.comparedSteps);
      a.percent = 100.0 * static_cast<double>(a.agreeingSteps) / n;
      a.chancePercent = 100.0 * chance / (n * n);
    }
    a.kappa = analysis::cohensKappa(c);
    out.push_back(a);
  }
  return out;
}

}  // namespace

std::vector<GroupAgreement> truthAgreement(const storage::RunTrack& track,
                                           const std::vector<storage::LabelSegment>& segments) {
  if (!track.hasTruth()) return {};
  std::array<analysis::ConfusionMatrix, kGroupCount> confusion;
  const auto steps = static_cast<std::int64_t>(track.stepCount());
  for (const storage::LabelSegment& s : segments) {
    const std::int64_t first = std::max<std::int64_t>(0, s.firstStep);
    const std::int64_t last = std::min(steps - 1, s.lastStep);
    // Rows are the truth, columns the labels.
    for (std::int64_t k = first; k <= last; ++k) {
      confusion[static_cast<std::size_t>(groupIndex(s.group))].add(
          track.truthAt(static_cast<std::size_t>(k), s.group), s.cls);
    }
  }
  return agreementOf(confusion);
}

std::vector<GroupAgreement> labelAgreement(std::int64_t stepCount,
                                           const std::vector<storage::LabelSegment>& first,
                                           const std::vector<storage::LabelSegment>& second) {
  // Each group's classes per step from the first set (-1: unlabelled), then the second set's
  // segments read against them.
  constexpr std::int8_t kNone = -1;
  const std::int64_t steps = std::max<std::int64_t>(0, stepCount);
  std::array<std::vector<std::int8_t>, kGroupCount> byStep;
  for (auto& v : byStep)
    v.assign(static_cast<std::size_t>(steps), kNone);
  for (const storage::LabelSegment& s : first) {
    auto& v = byStep[static_cast<std::size_t>(groupIndex(s.group))];
    for (std::int64_t k = std::max<std::int64_t>(0, s.firstStep);
         k <= std::min(steps - 1, s.lastStep); ++k)
      v[static_cast<std::size_t>(k)] = static_cast<std::int8_t>(s.cls);
  }
  std::array<analysis::ConfusionMatrix, kGroupCount> confusion;
  for (const storage::LabelSegment& s : second) {
    const auto g = static_cast<std::size_t>(groupIndex(s.group));
    for (std::int64_t k = std::max<std::int64_t>(0, s.firstStep);
         k <= std::min(steps - 1, s.lastStep); ++k) {
      const std::int8_t c = byStep[g][static_cast<std::size_t>(k)];
      if (c != kNone) confusion[g].add(static_cast<ContactClass>(c), s.cls);
    }
  }
  return agreementOf(confusion);
}

std::string defaultSweepName(const std::string& labelSet, const analysis::SweepGrid& grid) {
  auto number = [](double v) {
    std::ostringstream out;
    out << v;
    return out.str();
  };
  // Values sorted and unique; a list of several numbers reads "first-last".
  auto numbers = [&](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return std::make_pair(v.size(), v.size() > 1 ? number(v.front()) + "-" + number(v.back())
                                                 : (v.empty() ? std::string() : number(v[0])));
  };
  auto names = [](const auto& values, auto name) {
    std::vector<std::string> out;
    for (const auto& v : values) {
      const std::string n(name(v));
      if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
    }
    std::string joined;
    for (const std::string& n : out)
      joined += (joined.empty() ? "" : "/") + n;
    return std::make_pair(out.size(), joined);
  };
  const bool gmm = std::find(grid.methods.begin(), grid.methods.end(),
                             analysis::ClassifierMethod::Gmm) != grid.methods.end();
  std::vector<std::pair<std::size_t, std::string>> parts;
  parts.emplace_back(names(grid.methods, analysis::classifierMethodName));
  parts.back().second = "method " + parts.back().second;
  if (gmm) {
    parts.emplace_back(numbers(std::vector<double>(grid.orders.begin(), grid.orders.end())));
    parts.back().second = "order " + parts.back().second;
    parts.emplace_back(names(grid.forms, analysis::covarianceFormName));
    parts.back().second = "covariance " + parts.back().second;
  }
  const bool mixtures =
      gmm || std::find(grid.methods.begin(), grid.methods.end(),
                       analysis::ClassifierMethod::Gaussian) != grid.methods.end();
  if (mixtures) {
    parts.emplace_back(numbers(grid.varianceFloors));
    parts.back().second = "floor " + parts.back().second;
  }
  if (std::find(grid.methods.begin(), grid.methods.end(), analysis::ClassifierMethod::Gbt) !=
      grid.methods.end()) {
    parts.emplace_back(
        numbers(std::vector<double>(grid.treeCounts.begin(), grid.treeCounts.end())));
    parts.back().second = "trees " + parts.back().second;
    parts.emplace_back(numbers(std::vector<double>(grid.depths.begin(), grid.depths.end())));
    parts.back().second = "depth " + parts.back().second;
    parts.emplace_back(numbers(grid.learningRates));
    parts.back().second = "learning rate " + parts.back().second;
    parts.emplace_back(numbers(grid.minChildWeights));
    parts.back().second = "min child weight " + parts.back().second;
  }
  parts.emplace_back(names(grid.features, analysis::featureKindName));
  parts.back().second = "features " + parts.back().second;
  parts.emplace_back(numbers(std::vector<double>(grid.seeds.begin(), grid.seeds.end())));
  parts.back().second = "seed " + parts.back().second;
  std::string varied;
  for (const auto& [count, text] : parts)
    if (count > 1) varied += (varied.empty() ? "" : " x ") + text;
  if (varied.empty()) {  // one cell: its settings
    for (const auto& [count, text] : parts)
      if (count == 1) varied += (varied.empty() ? "" : "; ") + text;
  }
  std::string name = labelSet + ": " + varied;
  if (!grid.groups.empty() && grid.groups.size() < static_cast<std::size_t>(kGroupCount)) {
    name += " (";
    for (std::size_t i = 0; i < grid.groups.size(); ++i)
      name += (i > 0 ? " " : "") + std::string(groupInfo(grid.groups[i]).shortName);
    name += ")";
  }
  // Names follow the one name rule (no comma, at most kMaxNameBytes): a long one is cut at a
  // character boundary.
  if (name.size() > kMaxNameBytes) {
    std::size_t cut = kMaxNameBytes - 3;
    while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80)
      --cut;
    name = name.substr(0, cut) + "...";
  }
  return name;
}

// ---- label edits -------------------------------------------------------------------------------

namespace {

// The range an edit can touch: the edit's own range widened to every segment overlapping it (an
// edit trims or splits only those; they do not overlap one another).
std::pair<std::int64_t, std::int64_t> widened(const std::vector<storage::LabelSegment>& overlapping,
                                              std::int64_t first, std::int64_t last) {
  for (const storage::LabelSegment& s : overlapping) {
    first = std::min(first, s.firstStep);
    last = std::max(last, s.lastStep);
  }
  return {first, last};
}

}  // namespace

Result<LabelEdit> Workspace::addSegment(std::int64_t setId, const storage::LabelSegment& segment,
                                        const storage::EditOptions& options) {
  std::int64_t runId = segment.runId;
  if (runId == 0) {
    auto info = db_->runs().find(segment.run);
    if (!info) return info.error();
    runId = info->id;
  }
  LabelEdit edit{setId, runId, segment.group, {}, {}, 0};
  auto before = db_->labels().segmentsInRange(setId, runId, segment.group, segment.firstStep,
                                              segment.lastStep);
  if (!before) return before.error();
  edit.before = std::move(before.value());
  storage::LabelSegment toAdd = segment;
  toAdd.runId = runId;
  auto id = db_->labels().addSegment(setId, toAdd, options);
  if (!id) return id.error();
  edit.segmentId = id.value();
  edit.revision = db_->labels().lastRevision();
  const auto [first, last] = widened(edit.before, segment.firstStep, segment.lastStep);
  auto after = db_->labels().segmentsInRange(setId, runId, segment.group, first, last);
  if (!after) return after.error();
  edit.after = std::move(after.value());
  return edit;
}

Result<LabelEdit> Workspace::changeSegment(std::int64_t setId, std::int64_t segmentId,
                                           const storage::LabelSegment& segment,
                                           const storage::EditOptions& options) {
  auto old = db_->labels().segment(setId, segmentId);
  if (!old) return old.error();
  if (segment.group != old->group || (segment.runId != 0 && segment.runId != old->runId)) {
    return failure("a segment keeps its run and group when changed; add a new one instead");
  }
  const std::int64_t runId = old->runId;
  const std::int64_t first = std::min(old->firstStep, segment.firstStep);
  const std::int64_t last = std::max(old->lastStep, segment.lastStep);
  LabelEdit edit{setId, runId, old->group, {}, {}, segmentId};
  auto before = db_->labels().segmentsInRange(setId, runId, old->group, first, last);
  if (!before) return before.error();
  edit.before = std::move(before.value());
  storage::LabelSegment changed = segment;
  changed.runId = runId;
  if (Status s = db_->labels().changeSegment(segmentId, changed, options); !s) return s.error();
  edit.revision = db_->labels().lastRevision();
  const auto [wideFirst, wideLast] = widened(edit.before, first, last);
  auto after = db_->labels().segmentsInRange(setId, runId, old->group, wideFirst, wideLast);
  if (!after) return after.error();
  edit.after = std::move(after.value());
  return edit;
}

Result<LabelEdit> Workspace::removeSegment(std::int64_t setId, std::int64_t segmentId,
                                           const storage::EditOptions& options) {
  auto old = db_->labels().segment(setId, segmentId);
  if (!old) return old.error();
  LabelEdit edit{setId, old->runId, old->group, {old.value()}, {}, 0};
  if (Status s = db_->labels().removeSegment(segmentId, options); !s) return s.error();
  edit.revision = db_->labels().lastRevision();
  return edit;
}

namespace {

std::pair<std::int64_t, std::int64_t> extent(const LabelEdit& edit) {
  std::int64_t first = std::numeric_limits<std::int64_t>::max();
  std::int64_t last = std::numeric_limits<std::int64_t>::min();
  for (const auto* list : {&edit.before, &edit.after}) {
    for (const storage::LabelSegment& s : *list) {
      first = std::min(first, s.firstStep);
      last = std::max(last, s.lastStep);
    }
  }
  return {first, last};
}

}  // namespace

Status Workspace::undo(LabelEdit& edit, const storage::EditOptions& options) {
  const auto [first, last] = extent(edit);
  if (first > last) return Status::success();
  storage::EditOptions undoing = options;
  if (undoing.action.empty()) undoing.action = "undo";
  Status done = db_->labels().replaceSegmentsInRange(edit.setId, edit.runId, edit.group, first,
                                                     last, edit.before, undoing);
  if (done) edit.revision = db_->labels().lastRevision();
  return done;
}

Status Workspace::redo(LabelEdit& edit, const storage::EditOptions& options) {
  const auto [first, last] = extent(edit);
  if (first > last) return Status::success();
  storage::EditOptions redoing = options;
  if (redoing.action.empty()) redoing.action = "redo";
  Status done = db_->labels().replaceSegmentsInRange(edit.setId, edit.runId, edit.group, first,
                                                     last, edit.after, redoing);
  if (done) edit.revision = db_->labels().lastRevision();
  return done;
}

// ---- learning ----------------------------------------------------------------------------------

Result<std::array<std::size_t, kGroupCount>> Workspace::labelledContactSteps(
    std::string_view labelSet, const std::vector<std::string>& runs) {
  std::array<std::size_t, kGroupCount> out{};
  if (runs.empty()) return out;
  auto set = db_->labels().find(std::string(labelSet));
  if (!set) return set.error();
  auto loaded = loadLabelled(set->id, runs);
  if (!loaded) return loaded.error();
  for (const GroupInfo& g : kSensorGroups) {
    out[static_cast<std::size_t>(groupIndex(g.group))] =
        analysis::buildGroupDataSet(loaded->labelled, g.group, analysis::FeatureKind::Normal)
            .size();
  }
  return out;
}

Result<Workspace::Labelled> Workspace::loadLabelled(std::int64_t setId,
                                                    const std::vector<std::string>& names) {
  Labelled out;
  for (const std::string& name : names) {
    auto info = db_->runs().find(name);
    if (!info) return info.error();
    auto run = db_->runs().load(info->id);
    if (!run) return run.error();
    auto segments = db_->labels().segments(setId, info->id);
    if (!segments) return segments.error();
    std::vector<LabelRecord> records;
    records.reserve(segments->size());
    for (const storage::LabelSegment& s : segments.value())
      records.push_back({name, s.group, s.firstStep, s.lastStep, s.cls, s.annotator, 0});
    out.runs.push_back(std::make_unique<RunData>(std::move(run.value())));
    analysis::LabelledRun lr{out.runs.back().get(), {}};
    auto labels = analysis::labelsFromSegments(*lr.run, name, records);
    if (!labels) return failure("run '" + name + "': " + labels.errorText());
    lr.labels = std::move(labels.value());
    out.labelled.push_back(std::move(lr));
    out.infos.push_back(info.value());
  }
  return out;
}

RunSplit holdOutEveryFourth(std::vector<std::string> runs) {
  RunSplit split;
  runs = sorted(std::move(runs));
  for (std::size_t i = 0; i < runs.size(); ++i)
    (i % 4 == 3 ? split.test : split.train).push_back(runs[i]);
  if (split.test.empty() && split.train.size() >= 2) {
    split.test.push_back(split.train.back());
    split.train.pop_back();
  }
  return split;
}

Result<TrainOutcome> Workspace::train(const TrainRequest& request, const ProgressFn& progress) {
  auto set = db_->labels().find(request.labelSet);
  if (!set) return set.error();
  if (!request.modelName.empty()) {
    // A taken name is found before the work, not after it.
    if (auto taken = db_->models().info(request.modelName); taken) {
      return failure("a model named '" + request.modelName +
                     "' is already stored; choose another name or delete it first");
    }
  }
  TrainOutcome outcome;

  // Runs.
  std::vector<std::string> labelled;
  {
    auto catalog = db_->labels().catalog();
    if (!catalog) return catalog.error();
    for (const storage::LabelSetCatalogEntry& e : catalog.value())
      if (e.set.id == set->id) labelled = e.runs;
  }
  std::vector<std::string> trainRuns = sorted(request.trainRuns);
  std::vector<std::string> testRuns = sorted(request.testRuns);
  for (const std::string& t : testRuns) {
    if (std::find(trainRuns.begin(), trainRuns.end(), t) != trainRuns.end()) {
      return failure("run '" + t + "' is given both for training and for testing");
    }
  }
  const bool automaticTrain = trainRuns.empty();
  if (automaticTrain) {
    for (const std::string& r : sorted(labelled))
      if (std::find(testRuns.begin(), testRuns.end(), r) == testRuns.end()) trainRuns.push_back(r);
  }
  if (request.split == SplitMode::ByScene) {
    if (!testRuns.empty()) {
      return failure("by-scene scores every scene in turn; give no test runs");
    }
  } else if (request.split == SplitMode::LeaveOneRunOut) {
    if (!testRuns.empty()) {
      return failure("leave-one-run-out scores every run in turn; give no test runs");
    }
    if (trainRuns.size() < 2) {
      return failure("leave-one-run-out needs at least two runs, label set '" + request.labelSet +
                     "' labels " + std::to_string(trainRuns.size()));
    }
    outcome.evaluatedOn = "leave-one-run-out";
  } else if (testRuns.empty() && automaticTrain && trainRuns.size() >= 2) {
    RunSplit split = holdOutEveryFourth(trainRuns);
    trainRuns = std::move(split.train);
    testRuns = std::move(split.test);
    outcome.evaluatedOn = "test runs";
  } else {
    outcome.evaluatedOn = testRuns.empty() ? "training runs" : "test runs";
  }
  if (trainRuns.empty()) {
    return failure("label set '" + request.labelSet + "' labels no run to train on");
  }

  auto train = loadLabelled(set->id, trainRuns);
  if (!train) return train.error();
  Labelled test;
  if (!testRuns.empty()) {
    auto loaded = loadLabelled(set->id, testRuns);
    if (!loaded) return loaded.error();
    test = std::move(loaded.value());
  }
  outcome.trainRuns = trainRuns;
  outcome.testRuns = testRuns;

  analysis::TrainJob job;
  job.runs = train->labelled;
  job.runRefs = runRefs(train->infos);
  job.testRuns = test.labelled;
  job.testRunRefs = runRefs(test.infos);
  job.split = request.split == SplitMode::LeaveOneRunOut ? analysis::EvaluationSplit::LeaveOneRunOut
              : request.split == SplitMode::ByScene      ? analysis::EvaluationSplit::ByScene
                                                         : analysis::EvaluationSplit::TestRuns;
  job.groups = request.groups;
  job.settings = request.settings;
  job.minRowsPerGroup = request.minRowsPerGroup;
  job.provenance.labelSet = request.labelSet;
  job.provenance.programVersion = std::string(programVersion());
  auto trained = analysis::trainAndEvaluate(job, progress);
  if (!trained) return trained.error();
  outcome.evaluatedOn = trained->evaluatedOn;
  outcome.bundle = std::move(trained->bundle);
  for (const analysis::GroupJobReport& r : trained->groups) {
    GroupTrainReport report;
    report.group = r.group;
    report.trained = r.trained;
    report.skippedBecause = r.skippedBecause;
    report.samplesTrain = r.samplesTrain;
    report.warnings = r.warnings;
    if (const analysis::GroupModel* m = outcome.bundle.find(r.group)) {
      const analysis::ModelEvaluation& e = m->evaluation;
      report.samplesTest = e.samplesTest();
      report.decision = m->decision;
      report.accuracy = e.accuracy(m->decision);
      report.balancedAccuracy = e.balancedAccuracy(m->decision);
      for (analysis::DecisionMode mode : analysis::kDecisionModes)
        report.balancedAccuracyByDecision[analysis::decisionIndex(mode)] = e.balancedAccuracy(mode);
      report.sceneMean = analysis::meanSceneBalancedAccuracy(e.scenes, m->decision);
      report.fitSeconds = e.fitSeconds;
    }
    outcome.groups.push_back(std::move(report));
  }
  outcome.provenance = analysis::bundleProvenanceToJson(outcome.bundle);
  if (!request.store) return outcome;
  return storeTrained(std::move(outcome), request);
}

Result<TrainOutcome> Workspace::storeTrained(TrainOutcome outcome, const TrainRequest& request) {
  std::string name = request.modelName;
  if (!name.empty()) {
    if (auto taken = db_->models().info(name); taken) {
      return failure("a model named '" + name +
                     "' is already stored; choose another name or delete it first");
    }
  }
  if (name.empty()) {
    auto models = db_->models().list();
    if (!models) return models.error();
    std::set<std::string> taken;
    for (const storage::ModelInfo& m : models.value())
      taken.insert(m.name);
    for (int n = 1;; ++n) {
      name = request.labelSet + "-" + std::to_string(n);
      if (!taken.count(name)) break;
    }
  }
  auto id = db_->models().add(name, dumpJson(analysis::bundleToJson(outcome.bundle)),
                              dumpJson(outcome.provenance),
                              dumpJson(analysis::bundleMetricsToJson(outcome.bundle)));
  if (!id) return id.error();
  outcome.modelName = name;
  outcome.modelId = id.value();
  return outcome;
}

Result<analysis::SweepResult> Workspace::loadSweep(std::int64_t sweepId) {
  auto info = db_->sweeps().info(sweepId);
  if (!info) return info.error();
  auto cells = db_->sweeps().cells(sweepId);
  if (!cells) return cells.error();
  json doc;
  try {
    doc = json::parse(info->configurationJson);
    json list = json::array();
    for (const storage::SweepCellRecord& c : cells.value())
      list.push_back(json::parse(c.metricsJson));
    doc["cells"] = std::move(list);
  } catch (const json::exception& e) {
    return failure("sweep " + std::to_string(sweepId) +
                   ": stored JSON is malformed: " + plainJsonError(e));
  }
  auto result = analysis::sweepFromJson(doc);
  if (!result) return failure("sweep " + std::to_string(sweepId) + ": " + result.errorText());
  // Cells are stored as they finish (on several threads not in grid order); a SweepResult lists
  // them in grid order, as the sweep itself returned them.
  const std::vector<analysis::SweepCell> grid = analysis::expandGrid(result->grid);
  auto position = [&grid](const analysis::SweepCell& c) {
    for (std::size_t i = 0; i < grid.size(); ++i) {
      if (grid[i] == c) return i;
    }
    return grid.size();
  };
  std::stable_sort(result->cells.begin(), result->cells.end(),
                   [&](const analysis::SweepCellResult& a, const analysis::SweepCellResult& b) {
                     return position(a.cell) < position(b.cell);
                   });
  return result;
}

Result<analysis::ModelBundle> Workspace::loadModel(std::string_view name) {
  auto text = db_->models().load(std::string(name));
  if (!text) return text.error();
  return analysis::parseModelJson(text.value(), "model '" + std::string(name) + "'");
}

Result<Workspace::Classified> Workspace::classify(std::string_view modelName,
                                                  std::string_view runName,
                                                  const analysis::ClassifyOptions& options) {
  auto bundle = loadModel(modelName);
  if (!bundle) return bundle.error();
  auto run = loadRun(runName);
  if (!run) return run.error();
  Classified out;
  out.bundle = std::make_unique<analysis::ModelBundle>(std::move(bundle.value()));
  out.run = std::move(run.value());
  out.result = analysis::classifyRun(out.run, *out.bundle, options);
  return out;
}

nlohmann::json trainReportJson(const TrainOutcome& outcome, const TrainRequest& request) {
  nlohmann::json groups = nlohmann::json::array();
  for (const GroupTrainReport& r : outcome.groups) {
    const analysis::GroupJobReport job{r.group, r.trained, r.skippedBecause, r.samplesTrain,
                                       r.warnings};
    groups.push_back(analysis::groupReportJson(job, outcome.bundle.find(r.group)));
  }
  return nlohmann::json{
      {"model", outcome.modelName},          {"id", outcome.modelId},
      {"label_set", request.labelSet},       {"train_runs", outcome.trainRuns},
      {"test_runs", outcome.testRuns},       {"split", std::string(splitModeName(request.split))},
      {"evaluated_on", outcome.evaluatedOn}, {"groups", std::move(groups)}};
}

}  // namespace tactile::workspace
