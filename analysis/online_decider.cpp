#include "analysis/online_decider.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tactile::analysis {

namespace {

int argmaxOf(const Eigen::Ref<const Eigen::VectorXd>& v) {
  int best = 0;
  for (Eigen::Index i = 1; i < v.size(); ++i) {
    if (v[i] > v[best]) best = static_cast<int>(i);
  }
  return best;
}

}  // namespace

std::optional<ContactClass> decideStep(const GroupModel& model, const StepContext& context,
                                       DecisionMode mode, OnlineGroupState& state) {
  if (groupIsZero(context.values, model.group)) {
    state.logAlpha.resize(0);
    state.features.resize(0);
    state.contactSteps = 0;
    state.perStep.reset();
    state.decided.reset();
    state.noContact = true;
    return ContactClass::NoContact;
  }
  const int c = model.classifier.classCount();
  if (c == 0) return std::nullopt;
  StepContext here = context;
  here.contactSteps = state.noContact ? 0 : state.contactSteps + 1;
  Eigen::MatrixXd x(1, featureDimension(model.group, model.features));
  groupFeatures(here, model.group, model.features, x.data());
  state.features = x.row(0);
  Eigen::MatrixXd ll;
  // The batch evaluation (not GaussianMixture::logDensity): bit for bit what classifyRun computes.
  model.classifier.logLikelihoods(x, ll);
  // One step of the same chain code as the whole-run filter (hmmForward), from the kept state.
  StepLikelihoods step;
  step.logLik = ll;
  step.observed = {1};
  step.logPriors = model.classifier.logPriors();
  state.perStep = argmaxDecisions(step)[0];
  const bool useChain = mode != DecisionMode::Step && !model.transitions.empty() &&
                        model.transitions.classCount() == c;
  if (useChain) {
    // Continue the episode: the previous filtered posterior pushed through the chain is this
    // step's "initial" distribution (the same hmmPredict as the whole-run filter).
    TransitionModel chain = model.transitions;
    if (state.logAlpha.size() == c) hmmPredict(state.logAlpha, model.transitions, chain.logInitial);
    const HmmFilterResult r = hmmForward(step, chain);
    state.logAlpha = r.logPosterior.row(0).transpose();
    state.decided = argmaxOf(state.logAlpha);
  } else {
    state.logAlpha.resize(0);
    state.decided = state.perStep;
  }
  state.contactSteps = here.contactSteps;
  state.noContact = false;
  if (!state.decided) return std::nullopt;
  return model.classes[static_cast<std::size_t>(*state.decided)];
}

OnlineDecider::OnlineDecider(const ModelBundle& bundle) : bundle_(&bundle) {
  for (const GroupInfo& g : kSensorGroups)
    models_[static_cast<std::size_t>(groupIndex(g.group))] = bundle.find(g.group);
}

OnlineDecider::OnlineDecider(const ModelBundle& bundle, DecisionMode mode) : OnlineDecider(bundle) {
  mode_ = isCausal(mode) ? mode : DecisionMode::Online;
}

void OnlineDecider::update(const double* stepValues, double v, double omega) {
  constexpr auto history = static_cast<std::size_t>(kHistory);
  if (pastValues_.empty()) pastValues_.assign(history * kValuesPerStep, 0.0);
  const std::size_t t = steps_;
  pastV_[t % history] = v;
  pastOmega_[t % history] = omega;
  const auto valuesOf = [&](std::size_t s) {
    return pastValues_.data() + (s % history) * kValuesPerStep;
  };
  StepContext context;
  context.values = stepValues;
  context.laggedValues =
      t >= static_cast<std::size_t>(kContextLag) ? valuesOf(t - kContextLag) : nullptr;
  context.v = v;
  context.omega = omega;
  // Steps fed so far with this one, as the run form's step + 1.
  const int known = static_cast<int>(std::min<std::size_t>(t + 1, 1u << 30));
  for (std::size_t g = 0; g < models_.size(); ++g) {
    const GroupModel* model = models_[g];
    if (model == nullptr) {
      const bool zero = groupIsZero(stepValues, kSensorGroups[g].group);
      decided_[g] = zero ? std::optional<ContactClass>(ContactClass::NoContact) : std::nullopt;
      perStep_[g] = decided_[g];
      continue;
    }
    const DecisionMode mode = mode_.value_or(model->decision);
    StepContext here = context;
    if (usesMotion(model->features)) {
      // The group's motion of this step and the ones before it, newest first.
      std::array<double, kMotionLagCap> motions{};
      const int n = std::min(known, kMotionLagCap);
      for (int i = 0; i < n; ++i) {
        const std::size_t s = (t - static_cast<std::size_t>(i)) % history;
        motions[static_cast<std::size_t>(i)] =
            groupStepMotion(model->group, pastV_[s], pastOmega_[s], stepSeconds_);
      }
      const MotionLag lag = motionLagOf(motions.data(), known);
      here.laggedValues =
          lag.beforeStart ? nullptr : valuesOf(t - static_cast<std::size_t>(lag.steps));
      here.laggedTravel = lag.travel;
      const OnlineGroupState& s = states_[g];
      here.contactTravel =
          contactTravelOf(motions.data(), known, s.noContact ? 0 : s.contactSteps + 1);
    }
    decided_[g] = decideStep(*model, here, mode, states_[g]);
    const OnlineGroupState& s = states_[g];
    perStep_[g] =
        s.noContact ? std::optional<ContactClass>(ContactClass::NoContact)
        : s.perStep
            ? std::optional<ContactClass>(model->classes[static_cast<std::size_t>(*s.perStep)])
            : std::nullopt;
  }
  // Keep this step's values for the steps after it.
  std::copy(stepValues, stepValues + kValuesPerStep,
            pastValues_.data() + (t % history) * kValuesPerStep);
  ++steps_;
}

void OnlineDecider::setStepSeconds(double dtSeconds) {
  stepSeconds_ = std::isfinite(dtSeconds) && dtSeconds > 0.0 ? dtSeconds : kDefaultStepSeconds;
}

std::optional<ContactClass> OnlineDecider::decided(SensorGroup group) const {
  return decided_[static_cast<std::size_t>(groupIndex(group))];
}

std::optional<ContactClass> OnlineDecider::perStep(SensorGroup group) const {
  return perStep_[static_cast<std::size_t>(groupIndex(group))];
}

void OnlineDecider::reset() {
  states_ = {};
  decided_ = {};
  perStep_ = {};
  pastValues_.clear();
  pastV_ = {};
  pastOmega_ = {};
  steps_ = 0;
}

}  // namespace tactile::analysis
