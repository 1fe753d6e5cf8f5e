// Labels from a model: a stored model's decisions written into a label set as ordinary edits,
// marked with the annotator "model:NAME" so that history, agreement and exports tell them from
// people's labels.
#include <algorithm>

#include "workspace/workspace.h"

namespace tactile::workspace {

std::string modelAnnotator(std::string_view modelName) {
  return "model:" + std::string(modelName);
}

std::vector<storage::LabelSegment> decisionSegments(const analysis::GroupClassification& group,
                                                    SensorGroup sensorGroup, std::int64_t first,
                                                    std::int64_t last,
                                                    const std::string& annotator) {
  std::vector<storage::LabelSegment> out;
  for (std::int64_t step = std::max<std::int64_t>(0, first); step <= last; ++step) {
    const std::optional<ContactClass> cls =
        parseContactClass(group.className(static_cast<std::size_t>(step)));
    if (!cls) continue;  // no model could say
    if (!out.empty() && out.back().lastStep == step - 1 && out.back().cls == *cls) {
      out.back().lastStep = step;
      continue;
    }
    storage::LabelSegment segment;
    segment.group = sensorGroup;
    segment.firstStep = step;
    segment.lastStep = step;
    segment.cls = *cls;
    segment.annotator = annotator;
    out.push_back(std::move(segment));
  }
  return out;
}

Result<LabelEdit> Workspace::replaceLabels(std::int64_t setId, std::int64_t runId,
                                           SensorGroup group, std::int64_t first, std::int64_t last,
                                           std::vector<storage::LabelSegment> segments,
                                           const storage::EditOptions& options) {
  if (first > last) {
    return Error("the range " + std::to_string(first) + "-" + std::to_string(last) +
                 " holds no step");
  }
  auto before = db_->labels().segmentsInRange(setId, runId, group, first, last);
  if (!before) return before.error();
  // The parts of the segments it touches that lie outside the range stay.
  std::int64_t lo = first;
  std::int64_t hi = last;
  for (const storage::LabelSegment& s : before.value()) {
    lo = std::min(lo, s.firstStep);
    hi = std::max(hi, s.lastStep);
    if (s.firstStep < first) {
      storage::LabelSegment left = s;
      left.lastStep = first - 1;
      segments.push_back(left);
    }
    if (s.lastStep > last) {
      storage::LabelSegment right = s;
      right.firstStep = last + 1;
      segments.push_back(right);
    }
  }
  std::sort(segments.begin(), segments.end(),
            [](const storage::LabelSegment& a, const storage::LabelSegment& b) {
              return a.firstStep < b.firstStep;
            });
  storage::EditOptions writing = options;
  if (writing.action.empty()) writing.action = "model";
  if (Status s =
          db_->labels().replaceSegmentsInRange(setId, runId, group, lo, hi, segments, writing);
      !s) {
    return s.error();
  }
  LabelEdit edit{setId, runId, group, std::move(before.value()), {}, 0};
  edit.revision = db_->labels().lastRevision();
  auto after = db_->labels().segmentsInRange(setId, runId, group, lo, hi);
  if (!after) return after.error();
  edit.after = std::move(after.value());
  return edit;
}

Result<ModelLabelling> Workspace::labelFromModel(const std::string& setName,
                                                 const std::string& modelName,
                                                 const std::vector<std::string>& runs,
                                                 const std::vector<SensorGroup>& groups,
                                                 const ProgressFn& progress) {
  auto bundle = loadModel(modelName);
  if (!bundle) return bundle.error();
  std::vector<std::string> names = runs;
  if (names.empty()) {
    auto all = db_->runs().list();
    if (!all) return all.error();
    for (const storage::RunInfo& r : all.value())
      names.push_back(r.name);
  }
  std::vector<SensorGroup> chosen = groups;
  ModelLabelling out;
  if (chosen.empty()) {
    for (const GroupInfo& g : kSensorGroups)
      if (bundle->find(g.group) != nullptr) chosen.push_back(g.group);
  }
  for (const SensorGroup g : chosen) {
    if (bundle->find(g) == nullptr) {
      out.warnings.push_back("model '" + modelName + "' has no model for group " +
                             std::string(groupInfo(g).shortName) + ": left as it is");
    }
  }
  auto set = db_->labels().find(setName);
  std::int64_t setId = 0;
  if (set) {
    setId = set->id;
  } else {
    auto created = db_->labels().create(setName);
    if (!created) return created.error();
    setId = created.value();
  }
  const std::string annotator = modelAnnotator(modelName);
  analysis::ClassifyOptions options;
  options.decision = analysis::DecisionMode::Offline;
  std::size_t done = 0;
  for (const std::string& name : names) {
    auto run = loadRun(name);
    if (!run) return run.error();
    auto info = db_->runs().find(name);
    if (!info) return info.error();
    const analysis::RunClassification result =
        analysis::classifyRun(run.value(), bundle.value(), options);
    const std::int64_t steps = static_cast<std::int64_t>(result.steps);
    if (steps == 0) continue;
    for (const SensorGroup g : chosen) {
      const analysis::GroupClassification& gc =
          result.groups[static_cast<std::size_t>(groupIndex(g))];
      if (gc.model == nullptr) continue;
      std::vector<storage::LabelSegment> segments =
          decisionSegments(gc, g, 0, steps - 1, annotator);
      const std::int64_t count = static_cast<std::int64_t>(segments.size());
      storage::EditOptions edit;
      edit.annotator = annotator;
      auto written = replaceLabels(setId, info->id, g, 0, steps - 1, std::move(segments), edit);
      if (!written) return written.error();
      ++out.groups;
      out.segments += count;
    }
    ++out.runs;
    if (progress && !progress(++done, names.size())) break;
  }
  return out;
}

}  // namespace tactile::workspace
