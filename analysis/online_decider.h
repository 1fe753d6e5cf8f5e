// Deciding contact classes step by step while the robot drives (docs/learning.md#temporal-models):
// the navigator feeds each step's sensor values and command as they come and reads every group's
// decided class. It uses only the steps seen so far (causal), so a decision at step t is what
// `tactile classify` writes for step t with the online decision on the same run.
//
//   analysis::OnlineDecider decider(bundle);             // bundle outlives the decider
//   for each step:
//     decider.update(stepValues, v, omega);              // kValuesPerStep values, RunData layout
//     std::optional<ContactClass> c = decider.decided(SensorGroup::Front);
//
// Per group the decision is the model's default (its `decision`: online with transitions, else
// the per-step argmax), or the mode given to the constructor when it is causal. A group whose
// values are all zero is NoContact by rule (and its filter restarts at the next contact); a group
// without a model decides nothing (nullopt).
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

#include "analysis/model_file.h"
#include "analysis/temporal.h"
#include "run/contact_class.h"
#include "run/sensor_layout.h"

namespace tactile::analysis {

// The state of one group's online filter: what it keeps between steps.
struct OnlineGroupState {
  Eigen::VectorXd logAlpha;     // filtered log posterior of the last step; empty between contacts
  int contactSteps = 0;         // steps of the current contact before this one
  std::optional<int> perStep;   // the last step's per-step argmax (class index into the model)
  std::optional<int> decided;   // the last step's decision (class index into the model)
  bool noContact = true;        // the last step had the group all zero
  Eigen::RowVectorXd features;  // the last step's feature row (empty when it had no contact)
};

// One group, one step: updates `state` with the step and returns the decided class (NoContact
// when the group is all zero). `context` carries the step's values (and, for the context feature
// kind, the lagged values, command and contact count: use OnlineDecider to have them kept).
// mode must be causal; Offline is treated as Online.
std::optional<ContactClass> decideStep(const GroupModel& model, const StepContext& context,
                                       DecisionMode mode, OnlineGroupState& state);

class OnlineDecider {
 public:
  // Every group decides with its model's default decision.
  explicit OnlineDecider(const ModelBundle& bundle);
  // Every group decides with `mode` (Offline is not causal and is taken as Online).
  OnlineDecider(const ModelBundle& bundle, DecisionMode mode);

  // Feeds one step: kValuesPerStep sensor values (normal and shear of every dome, in the layout of
  // RunData::stepSensors), the commanded speed v and turn rate omega that led to them.
  void update(const double* stepValues, double v = 0.0, double omega = 0.0);
  // The length of a step in seconds, for the motion feature kinds (default kDefaultStepSeconds,
  // the simulator's; a run's `dt`). Non-positive or non-finite values mean the default.
  void setStepSeconds(double dtSeconds);
  double stepSeconds() const { return stepSeconds_; }
  // The decision of the last step fed: NoContact by rule, the model's class, or nullopt (no
  // model for the group, or no step fed yet).
  std::optional<ContactClass> decided(SensorGroup group) const;
  // The per-step argmax of the last step (the decision without memory).
  std::optional<ContactClass> perStep(SensorGroup group) const;
  const OnlineGroupState& state(SensorGroup group) const {
    return states_[static_cast<std::size_t>(groupIndex(group))];
  }
  // Forgets every step fed (a new run).
  void reset();
  std::size_t stepsFed() const { return steps_; }

 private:
  const ModelBundle* bundle_;
  std::optional<DecisionMode> mode_;
  std::array<const GroupModel*, kGroupCount> models_{};
  std::array<OnlineGroupState, kGroupCount> states_{};
  std::array<std::optional<ContactClass>, kGroupCount> decided_{};
  std::array<std::optional<ContactClass>, kGroupCount> perStep_{};
  // The values of the last kHistory steps before this one and the commands of the last kHistory
  // steps with this one, step s in slot s % kHistory, for the context and motion features.
  static constexpr int kHistory = kMotionLagCap > kContextLag ? kMotionLagCap : kContextLag;
  std::vector<double> pastValues_;
  std::array<double, kHistory> pastV_{};
  std::array<double, kHistory> pastOmega_{};
  double stepSeconds_ = kDefaultStepSeconds;
  std::size_t steps_ = 0;
};

}  // namespace tactile::analysis
