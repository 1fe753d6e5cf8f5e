#include "analysis/temporal.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tactile::analysis {
namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

Eigen::VectorXd priorsOf(const StepLikelihoods& steps) {
  const Eigen::Index c = steps.logLik.cols();
  if (steps.logPriors.size() == c) return steps.logPriors;
  return Eigen::VectorXd::Constant(c, c > 0 ? -std::log(static_cast<double>(c)) : 0.0);
}

bool isObserved(const StepLikelihoods& steps, Eigen::Index t) {
  const auto i = static_cast<std::size_t>(t);
  return i < steps.observed.size() ? steps.observed[i] != 0 : true;
}

// Index of the largest finite-or-not entry, ties to the lowest index; 0 when all are -inf/NaN.
int argmaxOf(const Eigen::Ref<const Eigen::VectorXd>& v) {
  int best = 0;
  for (Eigen::Index i = 1; i < v.size(); ++i) {
    if (v[i] > v[best]) best = static_cast<int>(i);
  }
  return best;
}

// log posterior of each class at one step: l + log pi - logsumexp(l + log pi). A step whose
// likelihoods all underflow to -inf gives the prior.
Eigen::VectorXd logPosteriorOf(const Eigen::Ref<const Eigen::VectorXd>& logLik,
                               const Eigen::VectorXd& logPriors) {
  Eigen::VectorXd joint = logLik + logPriors;
  const double z = logSumExp(joint);
  if (!std::isfinite(z)) return logPriors;
  joint.array() -= z;
  return joint;
}

}  // namespace

double logSumExp(const Eigen::Ref<const Eigen::VectorXd>& v) {
  // Plain loops: GCC 12 reports a false maybe-uninitialized inside Eigen's AVX-512 reductions.
  if (v.size() == 0) return kNegInf;
  double m = v[0];
  for (Eigen::Index i = 1; i < v.size(); ++i)
    m = std::max(m, v[i]);
  if (!std::isfinite(m)) return m;  // all -inf (or +inf)
  double sum = 0.0;
  for (Eigen::Index i = 0; i < v.size(); ++i)
    sum += std::exp(v[i] - m);
  return m + std::log(sum);
}

Decisions argmaxDecisions(const StepLikelihoods& steps) {
  const Eigen::VectorXd priors = priorsOf(steps);
  Decisions out(static_cast<std::size_t>(steps.logLik.rows()));
  for (Eigen::Index t = 0; t < steps.logLik.rows(); ++t) {
    if (!isObserved(steps, t) || steps.logLik.cols() == 0) continue;
    out[static_cast<std::size_t>(t)] = argmaxOf(steps.logLik.row(t).transpose() + priors);
  }
  return out;
}

Decisions consecutiveCountDecisions(const StepLikelihoods& steps, int requiredCount) {
  const Decisions perStep = argmaxDecisions(steps);
  Decisions out(perStep.size());
  const int k = std::max(requiredCount, 1);
  int runLength = 0;
  std::optional<int> runClass;
  for (std::size_t t = 0; t < perStep.size(); ++t) {
    if (!perStep[t]) {
      runLength = 0;
      runClass.reset();
      continue;
    }
    if (runClass == perStep[t]) {
      ++runLength;
    } else {
      runClass = perStep[t];
      runLength = 1;
    }
    if (runLength >= k) out[t] = runClass;
  }
  return out;
}

Decisions summedLogProbabilityDecisions(const StepLikelihoods& steps, double thresholdNats,
                                        int window) {
  const Eigen::Index n = steps.logLik.rows();
  const Eigen::Index c = steps.logLik.cols();
  const Eigen::VectorXd priors = priorsOf(steps);
  Decisions out(static_cast<std::size_t>(n));
  if (c == 0) return out;
  // Per-step log posteriors of the current episode, kept for the sliding window.
  std::vector<Eigen::VectorXd> episode;
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(c);
  for (Eigen::Index t = 0; t < n; ++t) {
    if (!isObserved(steps, t)) {
      episode.clear();
      sum.setZero();
      continue;
    }
    episode.push_back(logPosteriorOf(steps.logLik.row(t).transpose(), priors));
    sum += episode.back();
    if (window > 0 && static_cast<int>(episode.size()) > window) {
      // Recompute rather than subtract, so that -inf terms leaving the window do not leave NaN.
      episode.erase(episode.begin());
      sum.setZero();
      for (const Eigen::VectorXd& e : episode)
        sum += e;
    }
    const int best = argmaxOf(sum);
    if (c == 1) {
      out[static_cast<std::size_t>(t)] = 0;
      continue;
    }
    double second = kNegInf;
    for (Eigen::Index i = 0; i < c; ++i) {
      if (i != best) second = std::max(second, sum[i]);
    }
    // A margin of inf - inf cannot happen: log posteriors are <= 0 and the best is finite unless
    // every class is -inf, which logPosteriorOf prevents (it falls back to the priors).
    const double margin = sum[best] - second;
    if (margin >= thresholdNats) out[static_cast<std::size_t>(t)] = best;
  }
  return out;
}

HmmFilterResult hmmForwardFilter(const StepLikelihoods& steps, double stayProbability) {
  const Eigen::Index n = steps.logLik.rows();
  const Eigen::Index c = steps.logLik.cols();
  const Eigen::VectorXd priors = priorsOf(steps);
  HmmFilterResult result;
  result.logPosterior = Eigen::MatrixXd::Constant(n, c, kNegInf);
  result.decisions.resize(static_cast<std::size_t>(n));
  if (c == 0) return result;
  const double stay = std::clamp(stayProbability, 0.0, 1.0);
  const double logStay = std::log(stay);  // -inf when stay = 0
  const double logMove = c > 1 ? std::log((1.0 - stay) / static_cast<double>(c - 1)) : kNegInf;
  Eigen::VectorXd alpha;  // log posterior of the previous step; empty at an episode start
  Eigen::VectorXd predicted(c);
  Eigen::VectorXd terms(c);
  for (Eigen::Index t = 0; t < n; ++t) {
    if (!isObserved(steps, t)) {
      alpha.resize(0);
      continue;
    }
    if (alpha.size() == 0) {
      predicted = priors;
    } else if (c == 1) {
      predicted.setZero();
    } else {
      // predicted(j) = logsumexp_i(alpha(i) + log A(i, j))
      for (Eigen::Index j = 0; j < c; ++j) {
        for (Eigen::Index i = 0; i < c; ++i)
          terms[i] = alpha[i] + (i == j ? logStay : logMove);
        predicted[j] = logSumExp(terms);
      }
    }
    Eigen::VectorXd joint = steps.logLik.row(t).transpose() + predicted;
    const double z = logSumExp(joint);
    if (std::isfinite(z)) {
      joint.array() -= z;
    } else {
      // Every class underflowed (or the transitions forbid every state): keep the prediction,
      // renormalised, so the filter stays defined.
      joint = predicted.array() - logSumExp(predicted);
      if (!std::isfinite(joint[argmaxOf(joint)])) joint = priors;
    }
    alpha = joint;
    result.logPosterior.row(t) = alpha.transpose();
    result.decisions[static_cast<std::size_t>(t)] = argmaxOf(alpha);
  }
  return result;
}

}  // namespace tactile::analysis
