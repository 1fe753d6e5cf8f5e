// The contact status of every sensor group at one step, from one of three sources
// (docs/navigation.md#status-sources). The model source decides causally: each group's class
// comes from its classifier's per-step log-likelihoods filtered forward by an HMM over the
// contact episode (OnlineGroupDecider), so a decision uses only the steps seen so far.
#pragma once

#include <Eigen/Core>

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "analysis/model_file.h"
#include "run/contact_class.h"
#include "run/sensor_layout.h"

namespace tactile::nav {

// One group's online decision: the forward filter of thesis 4.6 / analysis/temporal.h, one step
// at a time,
//   log alpha_t(j) = l_t(j) + logsumexp_i(log alpha_{t-1}(i) + log A(i, j)) - log Z_t,
//   A(i, i) = stay, A(i, j != i) = (1 - stay) / (C - 1),
// started from the log priors at the first step of each contact episode. This is the one place
// that knows how the decision is made, so a learned transition matrix can replace A here.
class OnlineGroupDecider {
 public:
  OnlineGroupDecider() = default;
  OnlineGroupDecider(Eigen::VectorXd logPriors, double stayProbability);
  // A step without contact: the episode ends.
  void reset() { started_ = false; }
  // A contact step with per-class log-likelihoods (C entries); returns the filtered class.
  int push(const Eigen::Ref<const Eigen::VectorXd>& logLik);
  // Filtered posterior probability of the decided class (1 for a single class).
  double confidence() const { return confidence_; }

 private:
  Eigen::VectorXd logPriors_;
  double logStay_ = 0.0;
  double logMove_ = 0.0;
  Eigen::VectorXd alpha_;
  Eigen::VectorXd predicted_;
  Eigen::VectorXd scratch_;
  bool started_ = false;
  double confidence_ = 1.0;
};

// Per-group classes of one step. Undecided groups (a model gave no class) read as nullopt.
using GroupClasses = std::array<std::optional<ContactClass>, kGroupCount>;

class StatusEstimator {
 public:
  virtual ~StatusEstimator() = default;
  // `values`: the 88 filtered dome values; `truth`: the simulator's classes (Truth source only).
  virtual const GroupClasses& update(const std::array<double, kValuesPerStep>& values,
                                     const std::array<ContactClass, kGroupCount>* truth) = 0;
};

// Trained models with the online decision. Groups without a model touch as Wall (a side group
// must still be followed); all-zero groups are NoContact by rule and skip their model.
class ModelStatusEstimator : public StatusEstimator {
 public:
  ModelStatusEstimator(std::shared_ptr<const analysis::ModelBundle> models, double stayProbability);
  const GroupClasses& update(const std::array<double, kValuesPerStep>& values,
                             const std::array<ContactClass, kGroupCount>* truth) override;

 private:
  std::shared_ptr<const analysis::ModelBundle> models_;
  std::array<const analysis::GroupModel*, kGroupCount> byGroup_{};
  std::array<OnlineGroupDecider, kGroupCount> deciders_;
  std::array<Eigen::MatrixXd, kGroupCount> features_;  // 1 x D scratch
  Eigen::MatrixXd logLik_;
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
