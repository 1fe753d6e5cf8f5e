// The contact status of every sensor group at one step, from one of three sources
// (docs/navigation.md#status-sources). The model source decides causally with the learning part's
// online decision (analysis::OnlineDecider): each group's class from the steps seen so far, as
// `tactile classify` decides it online on the same run.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "analysis/model_file.h"
#include "analysis/online_decider.h"
#include "run/contact_class.h"
#include "run/sensor_layout.h"

namespace tactile::nav {

// Per-group classes of one step. Undecided groups (a model gave no class) read as nullopt.
using GroupClasses = std::array<std::optional<ContactClass>, kGroupCount>;

class StatusEstimator {
 public:
  virtual ~StatusEstimator() = default;
  // `values`: the 88 filtered dome values; `truth`: the simulator's classes (Truth source only).
  virtual const GroupClasses& update(const std::array<double, kValuesPerStep>& values,
                                     const std::array<ContactClass, kGroupCount>* truth) = 0;
  // The command that led to the next update's values (the model source's context features use
  // it; the others ignore it).
  virtual void command(double /*v*/, double /*omega*/) {}
  // The run's step length in seconds, given before the first update (the model source's motion
  // features measure the domes' travel with it; the others ignore it).
  virtual void setStepSeconds(double /*dtSeconds*/) {}
};

// Trained models with the learning part's online decision (each model's own decision: the
// forward filter through its transition chain, or the per-step argmax). All-zero groups are
// NoContact by rule; a touching group without a model reads Wall (a side group must still be
// followed).
class ModelStatusEstimator : public StatusEstimator {
 public:
  explicit ModelStatusEstimator(std::shared_ptr<const analysis::ModelBundle> models);
  const GroupClasses& update(const std::array<double, kValuesPerStep>& values,
                             const std::array<ContactClass, kGroupCount>* truth) override;
  void command(double v, double omega) override {
    v_ = v;
    omega_ = omega;
  }
  void setStepSeconds(double dtSeconds) override { decider_.setStepSeconds(dtSeconds); }
  const analysis::OnlineDecider& decider() const { return decider_; }

 private:
  std::shared_ptr<const analysis::ModelBundle> models_;
  analysis::OnlineDecider decider_;
  double v_ = 0.0;
  double omega_ = 0.0;
  GroupClasses out_{};
};

// The simulator's ground truth (the ceiling): NoContact where the truth is missing.
class TruthStatusEstimator : public StatusEstimator {
 public:
  const GroupClasses& update(const std::array<double, kValuesPerStep>& values,
                             const std::array<ContactClass, kGroupCount>* truth) override;

 private:
  GroupClasses out_{};
};

// A binary bumper: a group touching anything is Wall, else NoContact.
class BumperStatusEstimator : public StatusEstimator {
 public:
  const GroupClasses& update(const std::array<double, kValuesPerStep>& values,
                             const std::array<ContactClass, kGroupCount>* truth) override;

 private:
  GroupClasses out_{};
};

// Whether any n or s value of the group is non-zero.
bool groupTouches(const std::array<double, kValuesPerStep>& values, SensorGroup group);

}  // namespace tactile::nav
