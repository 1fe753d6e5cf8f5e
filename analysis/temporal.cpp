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

// Whether the likelihoods can be read: a compact layout needs a row for every observed step.
bool readable(const StepLikelihoods& steps) {
  if (!steps.compact()) return true;
  const auto observed = std::count_if(steps.observed.begin(), steps.observed.end(),
                                      [](std::uint8_t o) { return o != 0; });
  return static_cast<Eigen::Index>(observed) == steps.logLik.rows();
}

// The row of logLik that holds an observed step's likelihoods, for a walk over the steps in order
// (forward, or backward with Backward): compact layouts count the observed steps walked.
class RowWalk {
 public:
  enum Direction { Forward, Backward };
  RowWalk(const StepLikelihoods& steps, Direction direction)
      : compact_(steps.compact()),
        direction_(direction),
        next_(direction == Forward ? 0 : steps.logLik.rows() - 1) {}
  // Called once for each observed step t, in the walk's order.
  Eigen::Index rowOf(Eigen::Index t) {
    if (!compact_) return t;
    const Eigen::Index row = next_;
    next_ += direction_ == Forward ? 1 : -1;
    return row;
  }

 private:
  bool compact_;
  Direction direction_;
  Eigen::Index next_;
};

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

Eigen::Index StepLikelihoods::steps() const {
  return std::max(static_cast<Eigen::Index>(observed.size()), logLik.rows());
}

bool StepLikelihoods::compact() const {
  return static_cast<Eigen::Index>(observed.size()) > logLik.rows();
}

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
  Decisions out(static_cast<std::size_t>(steps.steps()));
  if (steps.logLik.cols() == 0 || !readable(steps)) return out;
  RowWalk rows(steps, RowWalk::Forward);
  for (Eigen::Index t = 0; t < steps.steps(); ++t) {
    if (!isObserved(steps, t)) continue;
    out[static_cast<std::size_t>(t)] =
        argmaxOf(steps.logLik.row(rows.rowOf(t)).transpose() + priors);
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
  const Eigen::Index n = steps.steps();
  const Eigen::Index c = steps.logLik.cols();
  const Eigen::VectorXd priors = priorsOf(steps);
  Decisions out(static_cast<std::size_t>(n));
  if (c == 0 || !readable(steps)) return out;
  RowWalk rows(steps, RowWalk::Forward);
  // Per-step log posteriors of the current episode, kept for the sliding window.
  std::vector<Eigen::VectorXd> episode;
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(c);
  for (Eigen::Index t = 0; t < n; ++t) {
    if (!isObserved(steps, t)) {
      episode.clear();
      sum.setZero();
      continue;
    }
    episode.push_back(logPosteriorOf(steps.logLik.row(rows.rowOf(t)).transpose(), priors));
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

void TransitionModel::set(Eigen::MatrixXd logA, Eigen::VectorXd logPi) {
  logTransition = std::move(logA);
  logInitial = std::move(logPi);
  transition = logTransition.array().exp().matrix();
}

void hmmPredict(const Eigen::VectorXd& logAlpha, const TransitionModel& chain,
                Eigen::VectorXd& logPredicted) {
  const Eigen::Index c = logAlpha.size();
  logPredicted.resize(c);
  double m = kNegInf;
  for (Eigen::Index i = 0; i < c; ++i)
    m = std::max(m, logAlpha[i]);
  const bool cached = chain.transition.rows() == c && chain.transition.cols() == c;
  // Weights of the previous step relative to its largest entry: in (0, 1], exp(-inf) = 0.
  double w[16];
  std::vector<double> wide;
  double* weights = w;
  if (c > 16) {
    wide.resize(static_cast<std::size_t>(c));
    weights = wide.data();
  }
  for (Eigen::Index i = 0; i < c; ++i)
    weights[i] = std::exp(logAlpha[i] - m);
  for (Eigen::Index j = 0; j < c; ++j) {
    double sum = 0.0;
    for (Eigen::Index i = 0; i < c; ++i) {
      const double a = cached ? chain.transition(i, j) : std::exp(chain.logTransition(i, j));
      sum += weights[i] * a;
    }
    logPredicted[j] = sum > 0.0 ? m + std::log(sum) : kNegInf;
  }
}

TransitionModel estimateTransitions(const std::vector<std::vector<int>>& sequences, int classes,
                                    double pseudoCount) {
  TransitionModel m;
  const Eigen::Index c = std::max(classes, 0);
  const double a =
      pseudoCount > 0.0 && std::isfinite(pseudoCount) ? pseudoCount : kTransitionPseudoCount;
  m.pseudoCount = a;
  m.counts = Eigen::MatrixXd::Zero(c, c);
  m.initialCounts = Eigen::VectorXd::Zero(c);
  for (const std::vector<int>& seq : sequences) {
    int previous = -1;
    for (const int k : seq) {
      const int now = k >= 0 && k < classes ? k : -1;
      if (now >= 0) {
        if (previous >= 0) {
          m.counts(previous, now) += 1.0;
        } else {
          m.initialCounts[now] += 1.0;
        }
      }
      previous = now;
    }
  }
  Eigen::MatrixXd logA(c, c);
  Eigen::VectorXd logPi(c);
  const double ca = static_cast<double>(c) * a;
  double startTotal = 0.0;
  for (Eigen::Index j = 0; j < c; ++j)
    startTotal += m.initialCounts[j];
  for (Eigen::Index i = 0; i < c; ++i) {
    double rowTotal = 0.0;
    for (Eigen::Index j = 0; j < c; ++j)
      rowTotal += m.counts(i, j);
    for (Eigen::Index j = 0; j < c; ++j)
      logA(i, j) = std::log(m.counts(i, j) + a) - std::log(rowTotal + ca);
    logPi[i] = std::log(m.initialCounts[i] + a) - std::log(startTotal + ca);
  }
  m.set(std::move(logA), std::move(logPi));
  return m;
}

TransitionModel stayTransitions(int classes, double stayProbability,
                                const Eigen::VectorXd& logInitial) {
  TransitionModel m;
  const Eigen::Index c = std::max(classes, 0);
  const double stay = std::clamp(stayProbability, 0.0, 1.0);
  const double logStay = std::log(stay);  // -inf when stay = 0
  const double logMove = c > 1 ? std::log((1.0 - stay) / static_cast<double>(c - 1)) : kNegInf;
  Eigen::MatrixXd logA = Eigen::MatrixXd::Constant(c, c, logMove);
  for (Eigen::Index i = 0; i < c; ++i)
    logA(i, i) = c > 1 ? logStay : 0.0;
  m.set(std::move(logA),
        logInitial.size() == c
            ? logInitial
            : Eigen::VectorXd::Constant(c, c > 0 ? -std::log(static_cast<double>(c)) : 0.0));
  return m;
}

namespace {

// The evidence of one step: its log-likelihoods, or no evidence (zeros) when every class is -inf
// (or NaN), so that the chain alone carries the belief through an underflowing step.
// Writes the evidence of logLik's row `row` into `l` (sized already: no allocation per step).
void evidenceInto(const StepLikelihoods& steps, Eigen::Index row, double weight,
                  Eigen::VectorXd& l) {
  bool any = false;
  for (Eigen::Index j = 0; j < l.size(); ++j) {
    const double v = steps.logLik(row, j);
    l[j] = std::isnan(v) ? kNegInf : weight * v;
    any = any || l[j] > kNegInf;
  }
  if (!any) l.setZero();
}

// Normalises `joint` in place (log space); when it cannot be normalised (every entry -inf: the
// chain forbids every state the evidence allows) falls back to `fallback`, normalised, then to
// `last`.
void normalise(Eigen::VectorXd& joint, const Eigen::VectorXd& fallback,
               const Eigen::VectorXd& last) {
  const double z = logSumExp(joint);
  if (std::isfinite(z)) {
    joint.array() -= z;
    return;
  }
  const double zf = logSumExp(fallback);
  if (std::isfinite(zf)) {
    joint = fallback.array() - zf;
    return;
  }
  joint = last;
}

}  // namespace

namespace {

// logSumExp over n contiguous values, the same arithmetic as logSumExp(Eigen::Ref).
double logSumExpOf(const double* v, Eigen::Index n) {
  if (n == 0) return kNegInf;
  double m = v[0];
  for (Eigen::Index i = 1; i < n; ++i)
    m = std::max(m, v[i]);
  if (!std::isfinite(m)) return m;
  double sum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i)
    sum += std::exp(v[i] - m);
  return m + std::log(sum);
}

// The forward filter over raw per-class arrays (no Eigen temporaries per step): the arithmetic of
// hmmPredict, evidenceInto and normalise, step for step, so the posteriors are bit for bit those
// of the plain formulation. Fills decisions (n entries) and, when logPosterior is given, its rows.
void forwardPass(const StepLikelihoods& steps, const TransitionModel& chain,
                 Eigen::MatrixXd* logPosterior, Decisions& decisions) {
  const Eigen::Index n = steps.steps();
  const Eigen::Index rowCount = steps.logLik.rows();
  const Eigen::Index c = steps.logLik.cols();
  const auto cs = static_cast<std::size_t>(c);
  // A(i, j) at a[i * c + j]: the cached probabilities, or exp of the logs as hmmPredict takes them.
  const bool cached = chain.transition.rows() == c && chain.transition.cols() == c;
  std::vector<double> a(cs * cs);
  for (Eigen::Index i = 0; i < c; ++i)
    for (Eigen::Index j = 0; j < c; ++j)
      a[static_cast<std::size_t>(i * c + j)] =
          cached ? chain.transition(i, j) : std::exp(chain.logTransition(i, j));
  const double logUniform = -std::log(static_cast<double>(c));
  const double weight = chain.emissionWeight;
  std::vector<double> buffer(4 * cs);
  double* alpha = buffer.data();  // log posterior of the previous step
  double* predicted = alpha + c;  // log prediction of this step
  double* joint = predicted + c;  // evidence + prediction, then normalised
  double* weights = joint + c;    // exp(alpha - max alpha)
  const double* logLik = steps.logLik.data();
  bool episode = false;  // whether alpha belongs to the current contact episode
  RowWalk rows(steps, RowWalk::Forward);
  for (Eigen::Index t = 0; t < n; ++t) {
    if (!isObserved(steps, t)) {
      episode = false;
      continue;
    }
    const Eigen::Index row = rows.rowOf(t);
    if (!episode) {
      for (Eigen::Index j = 0; j < c; ++j)
        predicted[j] = chain.logInitial[j];
    } else {
      double m = kNegInf;
      for (Eigen::Index i = 0; i < c; ++i)
        m = std::max(m, alpha[i]);
      for (Eigen::Index i = 0; i < c; ++i)
        weights[i] = std::exp(alpha[i] - m);
      for (Eigen::Index j = 0; j < c; ++j) {
        double sum = 0.0;
        for (Eigen::Index i = 0; i < c; ++i)
          sum += weights[i] * a[static_cast<std::size_t>(i * c + j)];
        predicted[j] = sum > 0.0 ? m + std::log(sum) : kNegInf;
      }
    }
    // The evidence, weighted (zeros when every class is -inf or NaN), then the prediction added.
    bool any = false;
    for (Eigen::Index j = 0; j < c; ++j) {
      const double v = logLik[row + j * rowCount];
      joint[j] = std::isnan(v) ? kNegInf : weight * v;
      any = any || joint[j] > kNegInf;
    }
    if (!any)
      for (Eigen::Index j = 0; j < c; ++j)
        joint[j] = 0.0;
    for (Eigen::Index j = 0; j < c; ++j)
      joint[j] += predicted[j];
    // Normalised; when it cannot be, the prediction normalised, else uniform.
    const double z = logSumExpOf(joint, c);
    if (std::isfinite(z)) {
      for (Eigen::Index j = 0; j < c; ++j)
        joint[j] -= z;
    } else {
      const double zf = logSumExpOf(predicted, c);
      for (Eigen::Index j = 0; j < c; ++j)
        joint[j] = std::isfinite(zf) ? predicted[j] - zf : logUniform;
    }
    std::swap(alpha, joint);
    episode = true;
    int best = 0;
    for (Eigen::Index j = 1; j < c; ++j)
      if (alpha[j] > alpha[best]) best = static_cast<int>(j);
    decisions[static_cast<std::size_t>(t)] = best;
    if (logPosterior != nullptr)
      for (Eigen::Index j = 0; j < c; ++j)
        (*logPosterior)(t, j) = alpha[j];
  }
}

}  // namespace

HmmFilterResult hmmForward(const StepLikelihoods& steps, const TransitionModel& chain) {
  const Eigen::Index n = steps.steps();
  const Eigen::Index c = steps.logLik.cols();
  HmmFilterResult result;
  result.logPosterior = Eigen::MatrixXd::Constant(n, c, kNegInf);
  result.decisions.resize(static_cast<std::size_t>(n));
  if (c == 0 || chain.classCount() != c || !readable(steps)) return result;
  forwardPass(steps, chain, &result.logPosterior, result.decisions);
  return result;
}

Decisions hmmForwardDecisions(const StepLikelihoods& steps, const TransitionModel& chain) {
  const Eigen::Index c = steps.logLik.cols();
  Decisions decisions(static_cast<std::size_t>(steps.steps()));
  if (c == 0 || chain.classCount() != c || !readable(steps)) return decisions;
  forwardPass(steps, chain, nullptr, decisions);
  return decisions;
}

HmmFilterResult hmmForwardBackward(const StepLikelihoods& steps, const TransitionModel& chain) {
  HmmFilterResult result = hmmForward(steps, chain);
  const Eigen::Index n = steps.steps();
  const Eigen::Index c = steps.logLik.cols();
  if (c == 0 || chain.classCount() != c || !readable(steps)) return result;
  Eigen::VectorXd beta(c), next(c), terms(c), message(c);
  bool haveNext = false;  // whether step t+1 belongs to the same episode
  RowWalk rows(steps, RowWalk::Backward);
  Eigen::Index nextRow = 0;  // the row of step t+1 when haveNext
  // Backwards over the steps: beta_t(i) = logsumexp_j(logA(i, j) + l_{t+1}(j) + beta_{t+1}(j)),
  // normalised at every step (any per-step constant cancels in gamma).
  for (Eigen::Index t = n - 1; t >= 0; --t) {
    if (!isObserved(steps, t)) {
      haveNext = false;
      continue;
    }
    const Eigen::Index row = rows.rowOf(t);
    if (!haveNext) {
      beta.setZero();
    } else {
      // beta_t(i) = mm + log(sum_j A(i, j) exp(message_j - mm)), mm = max message.
      evidenceInto(steps, nextRow, chain.emissionWeight, message);
      message += next;
      double mm = kNegInf;
      for (Eigen::Index j = 0; j < c; ++j)
        mm = std::max(mm, message[j]);
      for (Eigen::Index j = 0; j < c; ++j)
        terms[j] = std::isfinite(mm) ? std::exp(message[j] - mm) : 0.0;
      const bool cached = chain.transition.rows() == c && chain.transition.cols() == c;
      for (Eigen::Index i = 0; i < c; ++i) {
        double sum = 0.0;
        for (Eigen::Index j = 0; j < c; ++j)
          sum += (cached ? chain.transition(i, j) : std::exp(chain.logTransition(i, j))) * terms[j];
        beta[i] = sum > 0.0 ? mm + std::log(sum) : kNegInf;
      }
      const double z = logSumExp(beta);
      if (std::isfinite(z)) {
        beta.array() -= z;
      } else {
        beta.setZero();  // the future forbids every state: it carries no information
      }
    }
    Eigen::VectorXd gamma = result.logPosterior.row(t).transpose() + beta;
    const Eigen::VectorXd filtered = result.logPosterior.row(t).transpose();
    normalise(gamma, filtered, filtered);
    result.logPosterior.row(t) = gamma.transpose();
    result.decisions[static_cast<std::size_t>(t)] = argmaxOf(gamma);
    next = beta;
    nextRow = row;
    haveNext = true;
  }
  return result;
}

std::string_view decisionModeName(DecisionMode mode) {
  switch (mode) {
    case DecisionMode::Step:
      return "step";
    case DecisionMode::Online:
      return "online";
    case DecisionMode::Offline:
      return "offline";
  }
  return "step";
}

std::optional<DecisionMode> parseDecisionMode(std::string_view name) {
  for (DecisionMode m : kDecisionModes)
    if (decisionModeName(m) == name) return m;
  return std::nullopt;
}

Decisions decide(const StepLikelihoods& steps, const TransitionModel& chain, DecisionMode mode) {
  const bool haveChain = !chain.empty() && chain.classCount() == steps.logLik.cols();
  if (mode == DecisionMode::Step || !haveChain) return argmaxDecisions(steps);
  if (mode == DecisionMode::Online) return hmmForwardDecisions(steps, chain);
  return hmmForwardBackward(steps, chain).decisions;
}

HmmFilterResult hmmForwardFilter(const StepLikelihoods& steps, double stayProbability) {
  return hmmForward(steps, stayTransitions(static_cast<int>(steps.logLik.cols()), stayProbability,
                                           priorsOf(steps)));
}

}  // namespace tactile::analysis
