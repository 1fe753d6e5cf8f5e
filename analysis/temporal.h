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
#include <string_view>
#include <vector>

namespace tactile::analysis {

// Per-step observations of one group over a run: observed[t] = 0 where the group had no contact,
// and the log-likelihoods log p(x_t | class c) (classes in the model's order) in one of two
// layouts:
//  - a row per step: logLik is N x C, logLik(t, c), the rows of unobserved steps ignored;
//  - compact: a row per observed step, in step order (a run's contact steps are few: classifyRun
//    keeps only theirs). The layout is compact when `observed` has more entries than logLik has
//    rows; its rows must then number the observed steps, else no decider decides any step.
// Log priors (C entries, or empty for equal) are added to each step.
struct StepLikelihoods {
  Eigen::MatrixXd logLik;
  std::vector<std::uint8_t> observed;
  Eigen::VectorXd logPriors;

  // The number of steps N.
  Eigen::Index steps() const;
  // True when logLik holds a row per observed step only.
  bool compact() const;
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

// A hidden Markov model over one group's classes (thesis 4.6): the classes are the hidden states,
// the classifier's per-class log-likelihoods the emissions. A contact episode starts from
// `logInitial`; each next step of contact moves from class i to class j with probability
// exp(logTransition(i, j)). Empty (size 0) means "no transitions stored".
struct TransitionModel {
  Eigen::MatrixXd logTransition;  // C x C, rows sum to 1 in probability
  Eigen::VectorXd logInitial;     // C, sums to 1 in probability
  double pseudoCount = 0.0;       // the Dirichlet prior the counts were smoothed with
  Eigen::MatrixXd counts;         // C x C transition counts it was estimated from (may be empty)
  Eigen::VectorXd initialCounts;  // C episode-start counts (may be empty)
  Eigen::MatrixXd transition;     // exp(logTransition), kept for the filter's inner loop
  // The weight w of the evidence in the online and offline deciders: each step's log-likelihoods
  // enter as w * l_t(j) (a tempered likelihood, p(x | j)^w). Consecutive steps of contact are
  // far from independent given the class, so the raw likelihoods of a few steps outweigh any
  // transition probability; w < 1 lets the chain act. w > 0 and finite; 1 is the plain HMM.
  double emissionWeight = 1.0;

  // Sets logTransition and logInitial (and the cached probabilities).
  void set(Eigen::MatrixXd logA, Eigen::VectorXd logPi);
  int classCount() const { return static_cast<int>(logInitial.size()); }
  bool empty() const { return logInitial.size() == 0; }
};

// The pseudo-count added to every transition and every start count when estimating transitions:
// an add-one (Dirichlet(1, ..., 1)) prior, so a transition never seen in training keeps a small
// probability, 1 / (n_i + C) for a class seen n_i times followed by a step of contact.
inline constexpr double kTransitionPseudoCount = 1.0;

// Counts of class-to-class moves in label sequences: one sequence per run, one entry per step,
// the class index (0 .. classes-1) or -1 where the step is not a scored contact step (no contact,
// unlabelled, or a class without a model). A move t-1 -> t is counted when both are >= 0; an
// entry >= 0 after a -1 (or at the start) counts as an episode start. The smoothed estimate is
//   A(i, j) = (n_ij + a) / (sum_k n_ik + C a),   pi(j) = (s_j + a) / (sum_k s_k + C a),
// with a = pseudoCount > 0 (a prior that keeps unseen moves possible).
TransitionModel estimateTransitions(const std::vector<std::vector<int>>& sequences, int classes,
                                    double pseudoCount = kTransitionPseudoCount);

// The fixed "stay" chain: A(i, i) = stay, the rest spread evenly, starting from `logInitial`
// (the classifier's log priors; equal when empty).
TransitionModel stayTransitions(int classes, double stayProbability,
                                const Eigen::VectorXd& logInitial = {});

// One prediction step of the chain: logPredicted(j) = log sum_i exp(logAlpha(i)) A(i, j),
// computed as m + log(sum_i exp(logAlpha(i) - m) A(i, j)) with m = max logAlpha (C exponentials
// per step, not C^2). logAlpha must have a finite entry.
void hmmPredict(const Eigen::VectorXd& logAlpha, const TransitionModel& chain,
                Eigen::VectorXd& logPredicted);

// Forward filter (online, causal: the posterior at t uses steps <= t only) with the given chain.
// Episodes (runs of observed steps) start from logInitial; the step priors of `steps` are not
// used. A step whose likelihoods are all -inf carries no evidence (its likelihood row is taken as
// 0). Returns the filtered log posteriors (rows of unobserved steps -inf) and their argmax.
HmmFilterResult hmmForward(const StepLikelihoods& steps, const TransitionModel& chain);

// The decisions of hmmForward alone (the same, without keeping the posteriors).
Decisions hmmForwardDecisions(const StepLikelihoods& steps, const TransitionModel& chain);

// Forward-backward (offline: the posterior at t uses the whole episode): log gamma_t(j) =
// log alpha_t(j) + log beta_t(j) - log Z, per episode, log space throughout. Same conventions as
// hmmForward.
HmmFilterResult hmmForwardBackward(const StepLikelihoods& steps, const TransitionModel& chain);

// How a model's per-step evidence becomes a decision:
//  - step: the per-step argmax of log-likelihood + log prior (no memory);
//  - online: the HMM forward filter's argmax (causal: what a navigator may use at step t);
//  - offline: the forward-backward posterior's argmax (the whole contact episode: what an
//    annotator reviews; not causal).
enum class DecisionMode : std::uint8_t { Step, Online, Offline };
inline constexpr DecisionMode kDecisionModes[] = {DecisionMode::Step, DecisionMode::Online,
                                                  DecisionMode::Offline};
// "step", "online", "offline".
std::string_view decisionModeName(DecisionMode mode);
std::optional<DecisionMode> parseDecisionMode(std::string_view name);
// True for the modes a navigator may use (step, online).
inline bool isCausal(DecisionMode mode) {
  return mode != DecisionMode::Offline;
}

// The decisions of one mode. Without a chain (empty, or of another class count) online and
// offline fall back to the per-step argmax.
Decisions decide(const StepLikelihoods& steps, const TransitionModel& chain, DecisionMode mode);

// log(sum_i exp(v_i)) computed stably; -inf for an empty or all -inf vector.
double logSumExp(const Eigen::Ref<const Eigen::VectorXd>& v);

}  // namespace tactile::analysis
