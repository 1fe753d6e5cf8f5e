#include "analysis/features.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "base/text_parse.h"

namespace tactile::analysis {

std::string_view featureKindName(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::Normal:
      return "normal";
    case FeatureKind::Magnitude:
      return "magnitude";
    case FeatureKind::NormalShear:
      return "normal+shear";
    case FeatureKind::NormalShearTouch:
      return "normal+shear+touch";
    case FeatureKind::Context:
      return "normal+shear+touch+context";
    case FeatureKind::Neighbours:
      return "normal+shear+touch+context+neighbours";
  }
  return "normal";
}

std::optional<FeatureKind> parseFeatureKind(std::string_view name) {
  for (FeatureKind k : kFeatureKinds) {
    if (featureKindName(k) == name) return k;
  }
  return std::nullopt;
}

int featureDimension(SensorGroup group, FeatureKind kind) {
  const int n = groupInfo(group).sensorCount;
  switch (kind) {
    case FeatureKind::NormalShear:
      return 2 * n;
    case FeatureKind::NormalShearTouch:
      return 2 * n + kTouchFlags;
    case FeatureKind::Context:
      return 3 * n + kTouchFlags + 3;
    case FeatureKind::Neighbours:
      return 3 * n + kTouchFlags + 3 + kNeighbourFeatures;
    case FeatureKind::Normal:
    case FeatureKind::Magnitude:
      break;
  }
  return n;
}

std::array<SensorGroup, 2> neighbourGroups(SensorGroup group) {
  const int g = groupIndex(group);
  return {kSensorGroups[static_cast<std::size_t>((g + 1) % kGroupCount)].group,
          kSensorGroups[static_cast<std::size_t>((g + kGroupCount - 1) % kGroupCount)].group};
}

bool groupIsZero(const double* stepValues, SensorGroup group) {
  const GroupInfo& info = groupInfo(group);
  const double* values = stepValues + normalOffset(info.firstSensor);
  for (int i = 0; i < 2 * info.sensorCount; ++i) {
    if (values[i] != 0.0) return false;
  }
  return true;
}

bool groupIsZero(const RunData& run, std::size_t step, SensorGroup group) {
  return groupIsZero(run.stepSensors(step), group);
}

StepContext stepContextOf(const RunData& run, std::size_t step, SensorGroup group) {
  StepContext c;
  c.values = run.stepSensors(step);
  c.laggedValues = step >= static_cast<std::size_t>(kContextLag)
                       ? run.stepSensors(step - static_cast<std::size_t>(kContextLag))
                       : nullptr;
  c.v = step < run.v.size() ? run.v[step] : 0.0;
  c.omega = step < run.omega.size() ? run.omega[step] : 0.0;
  int touched = 0;
  for (std::size_t s = step; s > 0 && touched < kContextCap; --s) {
    if (groupIsZero(run, s - 1, group)) break;
    ++touched;
  }
  c.contactSteps = touched;
  return c;
}

void groupFeatures(const StepContext& context, SensorGroup group, FeatureKind kind, double* out) {
  const GroupInfo& info = groupInfo(group);
  const double* values = context.values;
  for (int i = 0; i < info.sensorCount; ++i) {
    const int sensor = info.firstSensor + i;
    const double n = values[normalOffset(sensor)];
    const double s = values[shearOffset(sensor)];
    switch (kind) {
      case FeatureKind::Normal:
        out[i] = n;
        break;
      case FeatureKind::Magnitude:
        out[i] = std::hypot(n, s);  // |(n, s)| = sqrt(n^2 + s^2)
        break;
      case FeatureKind::NormalShear:
      case FeatureKind::NormalShearTouch:
      case FeatureKind::Context:
      case FeatureKind::Neighbours:
        out[2 * i] = n;
        out[2 * i + 1] = s;
        break;
    }
  }
  if (kind != FeatureKind::NormalShearTouch && !usesHistory(kind)) return;
  // Flags, not values: the dead-path rule asks whether F, L and R touch, not how hard, and a
  // pocket of another width presses them differently.
  double* flags = out + 2 * info.sensorCount;
  const SensorGroup around[kTouchFlags] = {SensorGroup::Front, SensorGroup::Left,
                                           SensorGroup::Right};
  for (int c = 0; c < kTouchFlags; ++c) {
    const GroupInfo& other = groupInfo(around[c]);
    bool touches = false;
    for (int i = 0; i < other.sensorCount && !touches; ++i)
      touches = values[normalOffset(other.firstSensor + i)] > 0.0;
    flags[c] = touches ? 1.0 : 0.0;
  }
  if (!usesHistory(kind)) return;
  double* extra = flags + kTouchFlags;
  for (int i = 0; i < info.sensorCount; ++i) {
    const int sensor = info.firstSensor + i;
    const double before =
        context.laggedValues != nullptr ? context.laggedValues[normalOffset(sensor)] : 0.0;
    extra[i] = values[normalOffset(sensor)] - before;
  }
  extra[info.sensorCount] = context.v;
  extra[info.sensorCount + 1] = context.omega;
  extra[info.sensorCount + 2] =
      static_cast<double>(std::min(context.contactSteps, kContextCap)) / kContextCap;
  if (kind != FeatureKind::Neighbours) return;
  double* side = extra + info.sensorCount + 3;
  for (SensorGroup other : neighbourGroups(group)) {
    const GroupInfo& o = groupInfo(other);
    double largest = 0.0, sum = 0.0;
    for (int i = 0; i < o.sensorCount; ++i) {
      const double n = values[normalOffset(o.firstSensor + i)];
      largest = std::max(largest, n);
      sum += n;
    }
    *side++ = largest;
    *side++ = sum / o.sensorCount;
  }
}

void groupFeatures(const RunData& run, std::size_t step, SensorGroup group, FeatureKind kind,
                   double* out) {
  if (!usesHistory(kind)) {
    StepContext c;
    c.values = run.stepSensors(step);
    groupFeatures(c, group, kind, out);
    return;
  }
  groupFeatures(stepContextOf(run, step, group), group, kind, out);
}

void groupFeatures(const double* stepValues, SensorGroup group, FeatureKind kind, double* out) {
  // One step without its history: the context kind sees no earlier step (zeros) and no command.
  StepContext c;
  c.values = stepValues;
  groupFeatures(c, group, kind, out);
}

GroupSteps extractGroupSteps(const RunData& run, SensorGroup group, FeatureKind kind) {
  GroupSteps out;
  out.group = group;
  out.kind = kind;
  const std::size_t steps = run.stepCount();
  const int d = featureDimension(group, kind);
  out.features.setZero(static_cast<Eigen::Index>(steps), d);
  out.isZero.assign(steps, 0);
  std::vector<double> row(static_cast<std::size_t>(d));
  for (std::size_t t = 0; t < steps; ++t) {
    if (groupIsZero(run, t, group)) {
      out.isZero[t] = 1;
      continue;
    }
    groupFeatures(run, t, group, kind, row.data());
    for (int j = 0; j < d; ++j)
      out.features(static_cast<Eigen::Index>(t), j) = row[j];
  }
  return out;
}

std::vector<std::optional<ContactClass>> labelsFromTruth(const RunData& run) {
  std::vector<std::optional<ContactClass>> labels(run.stepCount() * kGroupCount);
  if (!run.hasTruth()) return labels;
  for (std::size_t i = 0; i < labels.size(); ++i)
    labels[i] = run.truth[i];
  return labels;
}

Result<std::vector<std::optional<ContactClass>>> labelsFromSegments(
    const RunData& run, std::string_view runName, const std::vector<LabelRecord>& segments) {
  std::vector<std::optional<ContactClass>> labels(run.stepCount() * kGroupCount);
  for (const LabelRecord& seg : segments) {
    if (seg.run != runName) continue;
    if (static_cast<std::size_t>(seg.lastStep) >= run.stepCount()) {
      return Error("label segment " + std::string(groupInfo(seg.group).shortName) + " steps " +
                   std::to_string(seg.firstStep) + "-" + std::to_string(seg.lastStep) +
                   " of run '" + std::string(runName) + "' reaches past its last step " +
                   std::to_string(run.stepCount() == 0 ? 0 : run.stepCount() - 1));
    }
    for (auto t = static_cast<std::size_t>(seg.firstStep);
         t <= static_cast<std::size_t>(seg.lastStep); ++t) {
      labels[t * kGroupCount + static_cast<std::size_t>(groupIndex(seg.group))] = seg.cls;
    }
  }
  return labels;
}

std::vector<ContactClass> GroupDataSet::classesPresent() const {
  const auto counts = classCounts();
  std::vector<ContactClass> out;
  for (int c = 0; c < kContactClassCount; ++c) {
    if (counts[static_cast<std::size_t>(c)] > 0) out.push_back(static_cast<ContactClass>(c));
  }
  return out;
}

std::array<std::size_t, kContactClassCount> GroupDataSet::classCounts() const {
  std::array<std::size_t, kContactClassCount> counts{};
  for (ContactClass c : y)
    ++counts[static_cast<std::size_t>(c)];
  return counts;
}

Eigen::MatrixXd GroupDataSet::rowsOf(ContactClass c) const {
  const std::size_t n = classCounts()[static_cast<std::size_t>(c)];
  Eigen::MatrixXd out(static_cast<Eigen::Index>(n), x.cols());
  Eigen::Index r = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (y[i] == c) out.row(r++) = x.row(static_cast<Eigen::Index>(i));
  }
  return out;
}

GroupDataSet buildGroupDataSet(const std::vector<LabelledRun>& runs, SensorGroup group,
                               FeatureKind kind) {
  GroupDataSet out;
  out.group = group;
  out.kind = kind;
  const int d = featureDimension(group, kind);
  const std::size_t g = static_cast<std::size_t>(groupIndex(group));
  // First pass counts the samples so the matrix is allocated once.
  std::size_t samples = 0;
  for (const LabelledRun& lr : runs) {
    for (std::size_t t = 0; t < lr.run->stepCount(); ++t) {
      const std::optional<ContactClass>& label = lr.labels[t * kGroupCount + g];
      if (!label) {
        ++out.unlabelledRows;
      } else if (groupIsZero(*lr.run, t, group)) {
        ++out.zeroRows;
        ++out.zeroRowsByClass[static_cast<std::size_t>(*label)];
      } else {
        ++samples;
      }
    }
  }
  out.x.resize(static_cast<Eigen::Index>(samples), d);
  out.y.reserve(samples);
  out.runIndex.reserve(samples);
  out.step.reserve(samples);
  std::vector<double> row(static_cast<std::size_t>(d));
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const LabelledRun& lr = runs[r];
    for (std::size_t t = 0; t < lr.run->stepCount(); ++t) {
      const std::optional<ContactClass>& label = lr.labels[t * kGroupCount + g];
      if (!label || groupIsZero(*lr.run, t, group)) continue;
      groupFeatures(*lr.run, t, group, kind, row.data());
      const Eigen::Index i = static_cast<Eigen::Index>(out.y.size());
      for (int j = 0; j < d; ++j)
        out.x(i, j) = row[static_cast<std::size_t>(j)];
      out.y.push_back(*label);
      out.runIndex.push_back(static_cast<std::uint32_t>(r));
      out.step.push_back(static_cast<std::uint32_t>(t));
    }
  }
  return out;
}

}  // namespace tactile::analysis
