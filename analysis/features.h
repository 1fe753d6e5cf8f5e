// Feature vectors per sensor group and step (docs/analysis.md#features-featuresh), and labelled
// data sets built from runs for training and testing the per-group classifiers.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/error.h"
#include "run/contact_class.h"
#include "run/label_file.h"
#include "run/run.h"
#include "run/sensor_layout.h"

namespace tactile::analysis {

// What a group's feature vector holds at one step.
enum class FeatureKind : std::uint8_t {
  Normal,       // the group's n values (default)
  Magnitude,    // sqrt(n^2 + s^2) per sensor
  NormalShear,  // n0, s0, n1, s1, ... per sensor
  // normal+shear, then three touch flags of the whole robot: 1 when any n value of the front, of
  // the left side, of the right side is above 0, else 0 (the groups whose joint touch makes a
  // dead path).
  NormalShearTouch,
  // normal+shear+touch, then context from the steps before: per sensor the change of its n value
  // over the last kContextLag steps (n_t - n_{t-k}, 0 before the run's first step), the commanded
  // v and omega, and the steps since the group's contact began (0 at its first step), capped at
  // kContextCap and divided by it.
  Context,
  // normal+shear+touch+context, then the two neighbouring groups round the body (F: FLC and FRC,
  // L: FLC and RLC, FLC: F and L, ...), each by the largest and the mean of its n values, the
  // neighbour counter-clockwise first: the same contact seen from the side (a vertex on F's face
  // presses a front corner group too; a wall's end passing back along L reaches RLC).
  Neighbours,
  // normal+shear+touch, then context taken over the group's MOTION instead of its steps, with no
  // speed in it (docs/analysis.md#features-featuresh): per sensor the change of its n value since
  // the step at which the group's domes were at least kMotionSpan units back along their path,
  // scaled to kMotionSpan units of travel (n_t - n_lag) * kMotionSpan / max(travel, kMotionSpan);
  // the unit direction of the group's motion in the group's own frame (groupMotionDirection:
  // into the obstacle, along the outline; 0 and 0 standing still); the units the group's domes
  // travelled during the contact (over at most its last kContextCap steps), capped at
  // kMotionContactCap and divided by it.
  Motion,
  // normal+shear+touch+motion and the neighbours' readings of the neighbours kind.
  MotionNeighbours,
};
inline constexpr int kTouchFlags = 3;
inline constexpr int kNeighbourFeatures = 4;
inline constexpr int kContextLag = 3;
inline constexpr int kContextCap = 20;
// The motion kinds' lag: half a dome's radius of travel (3 steps at the training recipe's typical
// 10 units/s and dt 0.1 s, the context kind's lag there), looked back at most kMotionLagCap steps
// (a robot standing still).
inline constexpr double kMotionSpan = 3.0;
inline constexpr int kMotionLagCap = 20;
// The motion kinds' contact length cap: 20 units (20 steps at the recipe's typical speed, the
// context kind's cap there).
inline constexpr double kMotionContactCap = 20.0;
// The step length assumed where a run or a stream does not give one (the simulator's default).
inline constexpr double kDefaultStepSeconds = 0.1;
inline constexpr std::array<FeatureKind, 8> kFeatureKinds{
    FeatureKind::Normal,           FeatureKind::Magnitude,       FeatureKind::NormalShear,
    FeatureKind::NormalShearTouch, FeatureKind::Context,         FeatureKind::Neighbours,
    FeatureKind::Motion,           FeatureKind::MotionNeighbours};

// True for the kinds taken over the robot's motion (motion, motion+neighbours).
constexpr bool usesMotion(FeatureKind kind) {
  return kind == FeatureKind::Motion || kind == FeatureKind::MotionNeighbours;
}
// True for the kinds that read the steps before (context, neighbours and the motion kinds).
constexpr bool usesHistory(FeatureKind kind) {
  return kind == FeatureKind::Context || kind == FeatureKind::Neighbours || usesMotion(kind);
}
// True for the kinds that end with the neighbours' readings.
constexpr bool usesNeighbours(FeatureKind kind) {
  return kind == FeatureKind::Neighbours || kind == FeatureKind::MotionNeighbours;
}

// How far the group's domes move during one step of the command (v, omega) over dtSeconds: the
// speed of the mean of the group's dome centres (body frame, rear-axle origin) times dt, >= 0
// (0 for non-finite input or a non-positive dt).
double groupStepMotion(SensorGroup group, double v, double omega, double dtSeconds);
// The distance of the mean of the group's dome centres from the rear axle.
double groupLeverArm(SensorGroup group);
// The unit direction in which the mean of the group's dome centres moves under (v, omega), in the
// group's own frame: {along its outward normal (into what it touches), along the outline
// counter-clockwise}; {0, 0} standing still or for non-finite input.
std::array<double, 2> groupMotionDirection(SensorGroup group, double v, double omega);
// A run's step length: its `dt` metadata when positive and finite, else kDefaultStepSeconds.
double stepSecondsOf(const RunData& run);

// The two groups next to `group` round the body: counter-clockwise (F -> FLC -> L -> ...) first.
std::array<SensorGroup, 2> neighbourGroups(SensorGroup group);

// "normal", "magnitude", "normal+shear", "normal+shear+touch", "normal+shear+touch+context",
// "normal+shear+touch+context+neighbours", "normal+shear+touch+motion",
// "normal+shear+touch+motion+neighbours".
std::string_view featureKindName(FeatureKind kind);
std::optional<FeatureKind> parseFeatureKind(std::string_view name);

// Dimension D of a group's feature vector: sensorCount, 2 * sensorCount for normal+shear, plus
// kTouchFlags with the touch flags, plus sensorCount + 3 with the context or the motion, plus
// kNeighbourFeatures with the neighbours.
int featureDimension(SensorGroup group, FeatureKind kind);

// True when every n and s value of the group is exactly zero at `step`: NoContact by rule, and no
// model is evaluated for it.
bool groupIsZero(const RunData& run, std::size_t step, SensorGroup group);

// True when every n and s value of the group is zero in one step's kValuesPerStep values.
bool groupIsZero(const double* stepValues, SensorGroup group);

// What a feature vector is computed from at one step: the step's kValuesPerStep sensor values
// and, for the context kinds, the values of the lagged step (context: kContextLag steps before;
// motion: see motionLagOf; null before the run's first step: zeros), the commanded v and omega,
// and how many steps the group has touched before this one without a break (0 at the first step
// of contact). The motion kinds also read how far the group's domes travelled since the lagged
// step (laggedTravel) and during the contact (contactTravel, over at most kContextCap steps).
struct StepContext {
  const double* values = nullptr;
  const double* laggedValues = nullptr;
  double v = 0.0;
  double omega = 0.0;
  int contactSteps = 0;
  double laggedTravel = 0.0;
  double contactTravel = 0.0;
};
// The context of `step` of a run for the given kind (steps since contact counted back at most
// kContextCap steps; the motion kinds' lag and travel from the run's commands and dtSeconds,
// which is stepSecondsOf(run) when 0).
StepContext stepContextOf(const RunData& run, std::size_t step, SensorGroup group,
                          FeatureKind kind = FeatureKind::Context, double dtSeconds = 0.0);

// The motion kinds' history from the group's motion of the steps before, newest first:
// motions[i] is how far the domes moved during the step that led to step t - i (i = 0: to this
// step), for i < available (available = t + 1 in a run: the first step's motion is the move that
// led to it). The lag is the smallest k with motions[0] + ... + motions[k - 1] >= kMotionSpan, at
// most kMotionLagCap; `before` is true when the run has no step t - k (then the lagged values are
// zeros). contactTravel sums the last contactSteps motions, oldest first.
struct MotionLag {
  int steps = 0;
  bool beforeStart = false;
  double travel = 0.0;
};
MotionLag motionLagOf(const double* motionsNewestFirst, int available);
double contactTravelOf(const double* motionsNewestFirst, int available, int contactSteps);

// Writes the group's feature vector into out[0 .. featureDimension): the one feature function;
// the run form and the online decider both call it.
void groupFeatures(const StepContext& context, SensorGroup group, FeatureKind kind, double* out);
// Writes the group's feature vector at `step` into out[0 .. featureDimension).
void groupFeatures(const RunData& run, std::size_t step, SensorGroup group, FeatureKind kind,
                   double* out);
// The same from one step's kValuesPerStep values (n0, s0, ..., n43, s43): what a navigator sees.
void groupFeatures(const double* stepValues, SensorGroup group, FeatureKind kind, double* out);

// All steps of one run for one group: one row per step, and the no-contact flag of each step.
struct GroupSteps {
  SensorGroup group = SensorGroup::Front;
  FeatureKind kind = FeatureKind::Normal;
  Eigen::MatrixXd features;          // stepCount x D (rows of zero groups are zero)
  std::vector<std::uint8_t> isZero;  // 1 where the group is NoContact by rule
};
GroupSteps extractGroupSteps(const RunData& run, SensorGroup group, FeatureKind kind);

// Per-step classes of one run for every group: stepCount * kGroupCount entries in group order,
// nullopt where no label covers the step. From the run's truth columns...
std::vector<std::optional<ContactClass>> labelsFromTruth(const RunData& run);
// ...or from label segments whose `run` equals `runName` (later segments override earlier ones).
// Segments reaching past the run's last step are an error.
Result<std::vector<std::optional<ContactClass>>> labelsFromSegments(
    const RunData& run, std::string_view runName, const std::vector<LabelRecord>& segments);

// A run together with its per-step, per-group labels (as produced by the two functions above).
struct LabelledRun {
  const RunData* run = nullptr;
  std::vector<std::optional<ContactClass>> labels;  // stepCount * kGroupCount
};

// Labelled samples of one group from many runs. Rows whose group is all zero are not samples
// (NoContact by rule); they are counted in `zeroRows` (and `zeroRowsByClass` by their label, to
// score the rule in reports). Unlabelled steps are skipped.
struct GroupDataSet {
  SensorGroup group = SensorGroup::Front;
  FeatureKind kind = FeatureKind::Normal;
  Eigen::MatrixXd x;                    // N x D
  std::vector<ContactClass> y;          // N labels
  std::vector<std::uint32_t> runIndex;  // which LabelledRun each row came from
  std::vector<std::uint32_t> step;      // which step
  std::size_t zeroRows = 0;
  std::array<std::size_t, kContactClassCount> zeroRowsByClass{};
  std::size_t unlabelledRows = 0;

  std::size_t size() const { return y.size(); }
  int dimension() const { return static_cast<int>(x.cols()); }
  // Classes present among the samples, in ContactClass order: only these are modelled.
  std::vector<ContactClass> classesPresent() const;
  // Samples per class, indexed by ContactClass.
  std::array<std::size_t, kContactClassCount> classCounts() const;
  // Rows of one class, in data order.
  Eigen::MatrixXd rowsOf(ContactClass c) const;
};

GroupDataSet buildGroupDataSet(const std::vector<LabelledRun>& runs, SensorGroup group,
                               FeatureKind kind);

}  // namespace tactile::analysis
