#include "nav/contact_status.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/features.h"
#include "analysis/temporal.h"

namespace tactile::nav {

OnlineGroupDecider::OnlineGroupDecider(Eigen::VectorXd logPriors, double stayProbability)
    : logPriors_(std::move(logPriors)) {
  const auto classes = static_cast<double>(logPriors_.size());
  const double stay = std::clamp(stayProbability, 0.0, 1.0);
  logStay_ = std::log(stay);
  logMove_ = classes > 1.0 ? std::log((1.0 - stay) / (classes - 1.0))
                           : -std::numeric_limits<double>::infinity();
  alpha_.resize(logPriors_.size());
  predicted_.resize(logPriors_.size());
  scratch_.resize(logPriors_.size());
}

int OnlineGroupDecider::push(const Eigen::Ref<const Eigen::VectorXd>& logLik) {
  const Eigen::Index c = logPriors_.size();
  if (c == 0) return 0;
  // The prediction from the previous step (the priors at an episode's first step), in the same
  // operation order as analysis::hmmForwardFilter so the two agree bit for bit.
  if (!started_) {
    predicted_ = logPriors_;
  } else if (c == 1) {
    predicted_.setZero();
  } else {
    for (Eigen::Index j = 0; j < c; ++j) {
      for (Eigen::Index i = 0; i < c; ++i)
        scratch_[i] = alpha_[i] + (i == j ? logStay_ : logMove_);
      predicted_[j] = analysis::logSumExp(scratch_);
    }
  }
  started_ = true;
  alpha_ = logLik + predicted_;
  const double z = analysis::logSumExp(alpha_);
  if (std::isfinite(z)) {
    alpha_.array() -= z;
  } else {
    // Every class underflowed: keep the prediction, renormalised, so the filter stays defined.
    alpha_ = predicted_.array() - analysis::logSumExp(predicted_);
    Eigen::Index top = 0;
    for (Eigen::Index j = 1; j < c; ++j)
      if (alpha_(j) > alpha_(top)) top = j;
    if (!std::isfinite(alpha_(top))) alpha_ = logPriors_;
  }
  Eigen::Index best = 0;
  for (Eigen::Index j = 1; j < c; ++j)
    if (alpha_(j) > alpha_(best)) best = j;
  confidence_ = std::exp(alpha_(best));
  return static_cast<int>(best);
}

bool groupTouches(const std::array<double, kValuesPerStep>& values, SensorGroup group) {
  const GroupInfo& info = groupInfo(group);
  for (int i = 0; i < 2 * info.sensorCount; ++i)
    if (values[static_cast<std::size_t>(normalOffset(info.firstSensor) + i)] != 0.0) return true;
  return false;
}

ModelStatusEstimator::ModelStatusEstimator(std::shared_ptr<const analysis::ModelBundle> models,
                                           double stayProbability)
    : models_(std::move(models)) {
  for (const GroupInfo& info : kSensorGroups) {
    const auto g = static_cast<std::size_t>(groupIndex(info.group));
    byGroup_[g] = models_ ? models_->find(info.group) : nullptr;
    if (byGroup_[g] == nullptr) continue;
    deciders_[g] = OnlineGroupDecider(byGroup_[g]->classifier.logPriors(), stayProbability);
    features_[g].resize(1, featureDimension(info.group, byGroup_[g]->features));
  }
}

const GroupClasses& ModelStatusEstimator::update(const std::array<double, kValuesPerStep>& values,
                                                 const std::array<ContactClass, kGroupCount>*) {
  for (const GroupInfo& info : kSensorGroups) {
    const auto g = static_cast<std::size_t>(groupIndex(info.group));
    if (!groupTouches(values, info.group)) {
      deciders_[g].reset();
      out_[g] = ContactClass::NoContact;
      continue;
    }
    const analysis::GroupModel* model = byGroup_[g];
    if (model == nullptr) {
      out_[g] = ContactClass::Wall;
      continue;
    }
    analysis::groupFeatures(values.data(), info.group, model->features, features_[g].data());
    model->classifier.logLikelihoods(features_[g], logLik_);
    const int c = deciders_[g].push(logLik_.row(0).transpose());
    out_[g] = model->classes[static_cast<std::size_t>(c)];
  }
  return out_;
}

const GroupClasses& TruthStatusEstimator::update(
    const std::array<double, kValuesPerStep>&, const std::array<ContactClass, kGroupCount>* truth) {
  for (std::size_t g = 0; g < kGroupCount; ++g)
    out_[g] = truth ? (*truth)[g] : ContactClass::NoContact;
  return out_;
}

const GroupClasses& BumperStatusEstimator::update(const std::array<double, kValuesPerStep>& values,
                                                  const std::array<ContactClass, kGroupCount>*) {
  for (const GroupInfo& info : kSensorGroups) {
    out_[static_cast<std::size_t>(groupIndex(info.group))] =
        groupTouches(values, info.group) ? ContactClass::Wall : ContactClass::NoContact;
  }
  return out_;
}

}  // namespace tactile::nav
