#include "analysis/features.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "base/text_parse.h"
#include "run/robot_geometry.h"

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
    case FeatureKind::Motion:
      return "normal+shear+touch+motion";
    case FeatureKind::MotionNeighbours:
      return "normal+shear+touch+motion+neighbours";
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
    case FeatureKind::Motion:
      return 3 * n + kTouchFlags + 3;
    case FeatureKind::Neighbours:
    case FeatureKind::MotionNeighbours:
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

namespace {

struct GroupPoint {
  double x = 0.0;  // mean dome centre, body frame
  double y = 0.0;
  double arm = 0.0;  // its distance from the rear axle
  double nx = 0.0;   // the group's outward normal (unit mean of its domes' normals)
  double ny = 0.0;
};

const std::array<GroupPoint, kGroupCount>& groupPoints() {
  static const std::array<GroupPoint, kGroupCount> points = [] {
    std::array<GroupPoint, kGroupCount> out{};
    const auto domes = domePlacements();
    for (const GroupInfo& info : kSensorGroups) {
      GroupPoint& p = out[static_cast<std::size_t>(groupIndex(info.group))];
      for (int i = 0; i < info.sensorCount; ++i) {
        p.x += domes[static_cast<std::size_t>(info.firstSensor + i)].centre.x;
        p.y += domes[static_cast<std::size_t>(info.firstSensor + i)].centre.y;
        p.nx += domes[static_cast<std::size_t>(info.firstSensor + i)].normal.x;
        p.ny += domes[static_cast<std::size_t>(info.firstSensor + i)].normal.y;
      }
      const double norm = std::sqrt(p.nx * p.nx + p.ny * p.ny);
      p.nx /= norm;
      p.ny /= norm;
      p.x /= info.sensorCount;
      p.y /= info.sensorCount;
      p.arm = std::sqrt(p.x * p.x + p.y * p.y);
    }
    return out;
  }();
  return points;
}

static_assert(kMotionLagCap == kContextCap, "one history length for lag and contact travel");

}  // namespace

double groupLeverArm(SensorGroup group) {
  return groupPoints()[static_cast<std::size_t>(groupIndex(group))].arm;
}

double groupStepMotion(SensorGroup group, double v, double omega, double dtSeconds) {
  if (!std::isfinite(v) || !std::isfinite(omega) || !std::isfinite(dtSeconds) || dtSeconds <= 0.0)
    return 0.0;
  // The velocity of a body point p under (v, omega): (v - omega p.y, omega p.x).
  const GroupPoint& p = groupPoints()[static_cast<std::size_t>(groupIndex(group))];
  const double vx = v - omega * p.y;
  const double vy = omega * p.x;
  const double m = std::sqrt(vx * vx + vy * vy) * dtSeconds;
  return std::isfinite(m) ? m : 0.0;
}

std::array<double, 2> groupMotionDirection(SensorGroup group, double v, double omega) {
  if (!std::isfinite(v) || !std::isfinite(omega)) return {0.0, 0.0};
  const GroupPoint& p = groupPoints()[static_cast<std::size_t>(groupIndex(group))];
  const double vx = v - omega * p.y;
  const double vy = omega * p.x;
  const double speed = std::sqrt(vx * vx + vy * vy);
  if (!(speed > 0.0) || !std::isfinite(speed)) return {0.0, 0.0};
  // Outward (into what the group touches) and along the outline counter-clockwise.
  return {(vx * p.nx + vy * p.ny) / speed, (-vx * p.ny + vy * p.nx) / speed};
}

double stepSecondsOf(const RunData& run) {
  const std::optional<double> dt = run.dtSeconds();
  return dt && std::isfinite(*dt) && *dt > 0.0 ? *dt : kDefaultStepSeconds;
}

MotionLag motionLagOf(const double* motionsNewestFirst, int available) {
  MotionLag lag;
  // Walk back step by step until the domes had travelled kMotionSpan units, the run began, or
  // kMotionLagCap steps were looked at (standing still).
  while (lag.travel < kMotionSpan && lag.steps < kMotionLagCap && lag.steps < available) {
    lag.travel += motionsNewestFirst[lag.steps];
    ++lag.steps;
  }
  lag.beforeStart = lag.steps >= available;
  return lag;
}

double contactTravelOf(const double* motionsNewestFirst, int available, int contactSteps) {
  const int k = std::min({contactSteps, kContextCap, available});
  double travel = 0.0;
  for (int i = k - 1; i >= 0; --i)
    travel += motionsNewestFirst[i];
  return travel;
}

StepContext stepContextOf(const RunData& run, std::size_t step, SensorGroup group, FeatureKind kind,
                          double dtSeconds) {
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
  if (usesMotion(kind)) {
    // The group's motion of this step and the kMotionLagCap - 1 before it, newest first.
    const double dt = dtSeconds > 0.0 ? dtSeconds : stepSecondsOf(run);
    std::array<double, kMotionLagCap> motions{};
    const int available = static_cast<int>(std::min<std::size_t>(step + 1, kMotionLagCap));
    for (int i = 0; i < available; ++i) {
      const std::size_t s = step - static_cast<std::size_t>(i);
      motions[static_cast<std::size_t>(i)] = groupStepMotion(
          group, s < run.v.size() ? run.v[s] : 0.0, s < run.omega.size() ? run.omega[s] : 0.0, dt);
    }
    const int known = static_cast<int>(std::min<std::size_t>(step + 1, 1u << 30));
    const MotionLag lag = motionLagOf(motions.data(), known);
    c.laggedValues =
        lag.beforeStart ? nullptr : run.stepSensors(step - static_cast<std::size_t>(lag.steps));
    c.laggedTravel = lag.travel;
    c.contactTravel = contactTravelOf(motions.data(), known, c.contactSteps);
  }
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
      case FeatureKind::Motion:
      case FeatureKind::MotionNeighbours:
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
  // The motion kinds scale the change to kMotionSpan units of travel: a lag that took one long
  // step (fast driving) reads as one of kMotionSpan; a robot standing still gives the plain change.
  const double scale =
      usesMotion(kind) ? kMotionSpan / std::max(context.laggedTravel, kMotionSpan) : 1.0;
  for (int i = 0; i < info.sensorCount; ++i) {
    const int sensor = info.firstSensor + i;
    const double before =
        context.laggedValues != nullptr ? context.laggedValues[normalOffset(sensor)] : 0.0;
    extra[i] = (values[normalOffset(sensor)] - before) * scale;
  }
  if (usesMotion(kind)) {
    // Which way the domes move, not how fast: the unit direction of the group's motion in its own
    // frame (into the obstacle, along the outline).
    const std::array<double, 2> direction = groupMotionDirection(group, context.v, context.omega);
    extra[info.sensorCount] = direction[0];
    extra[info.sensorCount + 1] = direction[1];
    extra[info.sensorCount + 2] =
        std::min(std::max(context.contactTravel, 0.0), kMotionContactCap) / kMotionContactCap;
  } else {
    extra[info.sensorCount] = context.v;
    extra[info.sensorCount + 1] = context.omega;
    extra[info.sensorCount + 2] =
        static_cast<double>(std::min(context.contactSteps, kContextCap)) / kContextCap;
  }
  if (!usesNeighbours(kind)) return;
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
  groupFeatures(stepContextOf(run, step, group, kind), group, kind, out);
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
