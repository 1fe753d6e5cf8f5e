// Temporal decision over a run (thesis 4.6): a classification need not be final at the first step
// of contact. Three deciders over per-step, per-class log-likelihoods of one group:
//  - consecutive count: decide class c once the per-step argmax has been c for K steps in a row;
//  - summed log-probability: sum per-class log posteriors over the current contact episode (or a
//    sliding window) and decide once the best sum leads the runner-up by a threshold (nats);
//  - HMM forward filter: classes as hidden states, self-transition probability p, the rest spread
//    evenly; decide the argmax of the filtered posterior.
// Steps without an observation (the group is all zero: NoContact by rule) end a contact episode:
// every decider resets there and outputs no decision.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace tactile::analysis {

// Per-step observations of one group over a run: logLik(t, c) = log p(x_t | class c) (N x C,
// classes in the model's order), and observed[t] = 0 where the group had no contact (that row of
// logLik is ignored). Log priors (C entries, or empty for equal) are added to each step.
struct StepLikelihoods {
  Eigen::MatrixXd logLik;
  std::vector<std::uint8_t> observed;
  Eigen::VectorXd logPriors;
};

// A per-step decision: class index, or nullopt while undecided / without contact.
using Decisions = std::vector<std::optional<int>>;

// Per-step argmax of logLik + logPriors (ties to the lowest index), nullopt where not observed.
Decisions argmaxDecisions(const StepLikelihoods& steps);

// Consecutive count: decision at t is c when the argmax was c at steps t-K+1 .. t (all observed).
// K >= 1 (K = 1 is the per-step argmax).
Decisions consecutiveCountDecisions(const StepLikelihoods& steps, int requiredCount);

// Summed log-probability: S_c(t) = sum over the episode's steps u <= t (or the last `window` steps
// of it when window > 0) of log P(c | x_u), with log P(c | x) = l_c + log pi_c - logsumexp_k(l_k +
// log pi_k). Decision at t is argmax_c S_c(t) when S_best - S_second >= thresholdNats (with one
// class: always that class).
Decisions summedLogProbabilityDecisions(const StepLikelihoods& steps, double thresholdNats,
                                        int window = 0);

// HMM forward filter in log space:
//   log alpha_t(j) = l_t(j) + logsumexp_i(log alpha_{t-1}(i) + log A(i, j)) - log Z_t,
//   A(i, i) = stay, A(i, j != i) = (1 - stay) / (C - 1),
// started at each episode from the log priors. Returns the filtered log posteriors (N x C; rows
// of unobserved steps are -inf) and their argmax decisions. stay in [0, 1]; a single class always
// has posterior 1.
struct HmmFilterResult {
  Eigen::MatrixXd logPosterior;
  Decisions decisions;
};
HmmFilterResult hmmForwardFilter(const StepLikelihoods& steps, double stayProbability);

// log(sum_i exp(v_i)) computed stably; -inf for an empty or all -inf vector.
double logSumExp(const Eigen::Ref<const Eigen::VectorXd>& v);

}  // namespace tactile::analysis
