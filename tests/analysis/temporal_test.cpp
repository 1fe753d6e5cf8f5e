// Temporal deciders over a run (thesis 4.6): consecutive count, summed log-probability, HMM filter.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>
#include <vector>

#include "analysis/temporal.h"

namespace tactile::analysis {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Observations that favour `cls[t]` by `margin` nats over the other of two classes; -1 = no
// contact.
StepLikelihoods twoClass(const std::vector<int>& cls, double margin = 2.0) {
  StepLikelihoods s;
  s.logLik = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(cls.size()), 2);
  s.observed.assign(cls.size(), 1);
  for (std::size_t t = 0; t < cls.size(); ++t) {
    if (cls[t] < 0) {
      s.observed[t] = 0;
      continue;
    }
    s.logLik(static_cast<Eigen::Index>(t), cls[t]) = -1.0;
    s.logLik(static_cast<Eigen::Index>(t), 1 - cls[t]) = -1.0 - margin;
  }
  return s;
}

TEST(Temporal, LogSumExpIsStable) {
  Eigen::VectorXd v(3);
  v << 1000.0, 1000.0, -kInf;
  EXPECT_NEAR(logSumExp(v), 1000.0 + std::log(2.0), 1e-12);
  v << -kInf, -kInf, -kInf;
  EXPECT_EQ(logSumExp(v), -kInf);
  EXPECT_EQ(logSumExp(Eigen::VectorXd()), -kInf);
}

TEST(Temporal, ArgmaxSkipsUnobservedSteps) {
  const Decisions d = argmaxDecisions(twoClass({0, 1, -1, 1}));
  EXPECT_EQ(d[0], 0);
  EXPECT_EQ(d[1], 1);
  EXPECT_FALSE(d[2].has_value());
  EXPECT_EQ(d[3], 1);
}

TEST(Temporal, ConsecutiveCountNeedsKInARow) {
  const Decisions d = consecutiveCountDecisions(twoClass({0, 0, 1, 1, 1, 1, 0}), 3);
  EXPECT_FALSE(d[1].has_value());  // only 2 of class 0
  EXPECT_FALSE(d[3].has_value());  // 2 of class 1
  EXPECT_EQ(d[4], 1);              // 3rd in a row
  EXPECT_EQ(d[5], 1);
  EXPECT_FALSE(d[6].has_value());  // class changed
}

TEST(Temporal, ConsecutiveCountResetsAtNoContact) {
  const Decisions d = consecutiveCountDecisions(twoClass({0, 0, -1, 0, 0, 0}), 3);
  EXPECT_FALSE(d[2].has_value());
  EXPECT_FALSE(d[4].has_value());  // the run restarted after the gap
  EXPECT_EQ(d[5], 0);
}

TEST(Temporal, CountOfOneIsPerStepArgmax) {
  const StepLikelihoods s = twoClass({0, 1, 0, -1, 1});
  EXPECT_EQ(consecutiveCountDecisions(s, 1), argmaxDecisions(s));
}

TEST(Temporal, SummedLogProbabilityWaitsForMargin) {
  // Each step gives log P(c0|x) - log P(c1|x) = 2 nats for class 0.
  const StepLikelihoods s = twoClass({0, 0, 0, 0});
  const Decisions d = summedLogProbabilityDecisions(s, 5.0);
  EXPECT_FALSE(d[0].has_value());  // margin 2
  EXPECT_FALSE(d[1].has_value());  // margin 4
  EXPECT_EQ(d[2], 0);              // margin 6
  EXPECT_EQ(d[3], 0);
}

TEST(Temporal, SummedLogProbabilityWindowForgets) {
  // 4 steps of class 0 then 2 of class 1: with a window of 2 the decision follows class 1.
  const StepLikelihoods s = twoClass({0, 0, 0, 0, 1, 1});
  const Decisions unlimited = summedLogProbabilityDecisions(s, 1.0);
  const Decisions windowed = summedLogProbabilityDecisions(s, 1.0, 2);
  EXPECT_EQ(unlimited[5], 0);
  EXPECT_EQ(windowed[5], 1);
  EXPECT_FALSE(windowed[4].has_value());  // one for each: margin 0
}

TEST(Temporal, SummedLogProbabilityHandlesUnderflowWithoutNaN) {
  StepLikelihoods s = twoClass({0, 0, 0});
  s.logLik(1, 0) = -kInf;  // class 0 impossible at step 1
  s.logLik(1, 1) = -kInf;  // ... and class 1 too: falls back to the priors
  s.logLik(2, 1) = -kInf;
  const Decisions d = summedLogProbabilityDecisions(s, 1.0);
  ASSERT_TRUE(d[2].has_value());
  EXPECT_EQ(d[2], 0);
}

TEST(Temporal, HmmPosteriorsAreNormalised) {
  const HmmFilterResult r = hmmForwardFilter(twoClass({0, 1, 1, -1, 0, 0}), 0.9);
  for (Eigen::Index t = 0; t < r.logPosterior.rows(); ++t) {
    if (t == 3) {
      EXPECT_FALSE(r.decisions[3].has_value());
      continue;
    }
    EXPECT_NEAR(logSumExp(r.logPosterior.row(t).transpose()), 0.0, 1e-12);
  }
}

TEST(Temporal, HmmWithHighStayIgnoresOneOutlier) {
  const StepLikelihoods s = twoClass({0, 0, 0, 0, 0, 1, 0, 0});
  EXPECT_EQ(argmaxDecisions(s)[5], 1);
  const HmmFilterResult r = hmmForwardFilter(s, 0.95);
  EXPECT_EQ(r.decisions[5], 0);
}

TEST(Temporal, HmmWithUniformTransitionsIsPerStepPosterior) {
  // stay = 1/C makes every transition equally likely: the filter forgets the past.
  const StepLikelihoods s = twoClass({0, 0, 0, 1, 0}, 1.5);
  const HmmFilterResult r = hmmForwardFilter(s, 0.5);
  for (Eigen::Index t = 0; t < 5; ++t) {
    const Eigen::VectorXd l = s.logLik.row(t).transpose();
    EXPECT_NEAR(r.logPosterior(t, 0), l[0] - logSumExp(l), 1e-12);
  }
  EXPECT_EQ(r.decisions, argmaxDecisions(s));
}

TEST(Temporal, HmmStaysDefinedWhenAllLikelihoodsUnderflow) {
  StepLikelihoods s = twoClass({0, 0, 0});
  s.logLik.row(1).setConstant(-kInf);
  const HmmFilterResult r = hmmForwardFilter(s, 0.9);
  for (Eigen::Index t = 0; t < 3; ++t) {
    EXPECT_FALSE(std::isnan(r.logPosterior(t, 0)));
    EXPECT_FALSE(std::isnan(r.logPosterior(t, 1)));
    EXPECT_TRUE(r.decisions[static_cast<std::size_t>(t)].has_value());
  }
  EXPECT_EQ(r.decisions[1], 0);  // the prediction carries over
}

// stay = 1: the state cannot change within an episode, so the filtered posterior is the
// posterior of the whole episode, proportional to the prior times the product of likelihoods.
TEST(Temporal, HmmStayOneIsEpisodePosterior) {
  const StepLikelihoods s = twoClass({0, 1, 1, 1, 1}, 3.0);
  const HmmFilterResult r = hmmForwardFilter(s, 1.0);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(2);
  for (Eigen::Index t = 0; t < 5; ++t) {
    sum += s.logLik.row(t).transpose();
    EXPECT_NEAR(r.logPosterior(t, 1), sum[1] - logSumExp(sum), 1e-9);
  }
  EXPECT_EQ(r.decisions[1], 0);  // tie goes to the lowest index
  EXPECT_EQ(r.decisions[2], 1);
}

TEST(Temporal, SingleClassAlwaysDecidesIt) {
  StepLikelihoods s;
  s.logLik = Eigen::MatrixXd::Constant(3, 1, -50.0);
  s.observed = {1, 1, 1};
  EXPECT_EQ(summedLogProbabilityDecisions(s, 10.0)[0], 0);
  const HmmFilterResult r = hmmForwardFilter(s, 0.9);
  EXPECT_EQ(r.decisions[2], 0);
  EXPECT_NEAR(r.logPosterior(2, 0), 0.0, 1e-15);
}

TEST(Temporal, PriorsShiftTheArgmax) {
  StepLikelihoods s = twoClass({0}, 0.5);
  s.logPriors.resize(2);
  s.logPriors << std::log(0.1), std::log(0.9);
  EXPECT_EQ(argmaxDecisions(s)[0], 1);
}

}  // namespace
}  // namespace tactile::analysis

// ---- HMM with an estimated chain: forward, forward-backward, estimation, causality ----

namespace tactile::analysis {
namespace {

// A random chain over `c` classes (rows and start drawn from a fixed generator).
TransitionModel randomChain(int c, unsigned seed) {
  std::srand(seed);
  auto draw = [] { return 0.05 + static_cast<double>(std::rand() % 1000) / 1000.0; };
  Eigen::MatrixXd a(c, c);
  Eigen::VectorXd pi(c);
  for (int i = 0; i < c; ++i) {
    double sum = 0.0;
    for (int j = 0; j < c; ++j)
      sum += a(i, j) = draw();
    a.row(i) /= sum;
  }
  double sum = 0.0;
  for (int i = 0; i < c; ++i)
    sum += pi[i] = draw();
  pi /= sum;
  TransitionModel m;
  m.set(a.array().log().matrix(), pi.array().log().matrix());
  return m;
}

StepLikelihoods randomSteps(int t, int c, unsigned seed) {
  std::srand(seed);
  StepLikelihoods s;
  s.logLik.resize(t, c);
  for (int i = 0; i < t; ++i)
    for (int j = 0; j < c; ++j)
      s.logLik(i, j) = -5.0 * static_cast<double>(std::rand() % 1000) / 1000.0;
  s.observed.assign(static_cast<std::size_t>(t), 1);
  return s;
}

// Brute force over every path of one episode (steps first..last): the joint probability of each
// path, summed into the filtered marginal at `upTo` (paths of steps first..upTo) or the smoothed
// marginal (paths over the whole episode).
Eigen::VectorXd bruteMarginal(const StepLikelihoods& s, const TransitionModel& m, int first,
                              int last, int at, bool smoothed) {
  const int c = static_cast<int>(s.logLik.cols());
  const int end = smoothed ? last : at;
  const int len = end - first + 1;
  Eigen::VectorXd out = Eigen::VectorXd::Zero(c);
  std::vector<int> path(static_cast<std::size_t>(len), 0);
  while (true) {
    double p = std::exp(m.logInitial[path[0]] + s.logLik(first, path[0]));
    for (int k = 1; k < len; ++k) {
      p *= std::exp(m.logTransition(path[k - 1], path[k]) + s.logLik(first + k, path[k]));
    }
    out[path[static_cast<std::size_t>(at - first)]] += p;
    int k = 0;
    while (k < len && ++path[static_cast<std::size_t>(k)] == c)
      path[static_cast<std::size_t>(k++)] = 0;
    if (k == len) break;
  }
  return out / out.sum();
}

TEST(Hmm, ForwardAndForwardBackwardMatchBruteForceEnumeration) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const int c = 2 + static_cast<int>(seed % 3);  // 2, 3 or 4 classes
    const TransitionModel chain = randomChain(c, seed);
    StepLikelihoods s = randomSteps(9, c, 100 + seed);
    s.observed[4] = 0;  // two episodes: steps 0-3 and 5-8
    const HmmFilterResult f = hmmForward(s, chain);
    const HmmFilterResult b = hmmForwardBackward(s, chain);
    for (const auto& [first, last] : {std::pair{0, 3}, std::pair{5, 8}}) {
      for (int t = first; t <= last; ++t) {
        const Eigen::VectorXd fw = bruteMarginal(s, chain, first, last, t, false);
        const Eigen::VectorXd fb = bruteMarginal(s, chain, first, last, t, true);
        for (int j = 0; j < c; ++j) {
          EXPECT_NEAR(std::exp(f.logPosterior(t, j)), fw[j], 1e-12) << seed << " " << t;
          EXPECT_NEAR(std::exp(b.logPosterior(t, j)), fb[j], 1e-12) << seed << " " << t;
        }
      }
    }
    for (int j = 0; j < c; ++j) {
      EXPECT_EQ(f.logPosterior(4, j), -kInf);
      EXPECT_EQ(b.logPosterior(4, j), -kInf);
    }
    EXPECT_FALSE(f.decisions[4].has_value());
    // The last step of an episode has nothing after it: smoothed = filtered.
    for (int j = 0; j < c; ++j)
      EXPECT_NEAR(f.logPosterior(8, j), b.logPosterior(8, j), 1e-12);
  }
}

// With emission weight w, forward and forward-backward are the HMM whose evidence is w times the
// log-likelihoods: checked against brute-force enumeration over the scaled evidence, for a weight
// below and above 1, with an impossible class (-inf) at one step that must stay impossible.
TEST(Hmm, EmissionWeightTempersTheEvidenceOfEveryStep) {
  for (double w : {0.1, 0.35, 2.0}) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const int c = 2 + static_cast<int>(seed % 3);
      TransitionModel chain = randomChain(c, seed);
      chain.emissionWeight = w;
      StepLikelihoods s = randomSteps(7, c, 200 + seed);
      s.logLik(2, 0) = -kInf;
      StepLikelihoods scaled = s;
      scaled.logLik = s.logLik * w;
      const HmmFilterResult f = hmmForward(s, chain);
      const HmmFilterResult b = hmmForwardBackward(s, chain);
      const TransitionModel plain = [&] {
        TransitionModel p = chain;
        p.emissionWeight = 1.0;
        return p;
      }();
      for (int t = 0; t < 7; ++t) {
        const Eigen::VectorXd fw = bruteMarginal(scaled, plain, 0, 6, t, false);
        const Eigen::VectorXd fb = bruteMarginal(scaled, plain, 0, 6, t, true);
        for (int j = 0; j < c; ++j) {
          EXPECT_NEAR(std::exp(f.logPosterior(t, j)), fw[j], 1e-12) << w << " " << seed << " " << t;
          EXPECT_NEAR(std::exp(b.logPosterior(t, j)), fb[j], 1e-12) << w << " " << seed << " " << t;
        }
      }
      EXPECT_EQ(f.logPosterior(2, 0), -kInf);
      EXPECT_EQ(b.logPosterior(2, 0), -kInf);
    }
  }
}

// Why the weight exists: with a sticky chain estimated from long episodes (stay 0.99) one step of
// strong evidence (20 nats) flips the plain filter at once, the tempered one keeps the class the
// episode has shown, and a sustained change still goes through after a few steps.
TEST(Hmm, EmissionWeightLetsTheChainOutweighOneStrongStep) {
  std::vector<int> labels(30, 0);
  for (int t = 20; t < 30; ++t)
    labels[static_cast<std::size_t>(t)] = 1;
  StepLikelihoods s = twoClass(labels, 3.0);
  s.logLik(10, 0) = -21.0;  // one step strongly for class 1 inside the class-0 stretch
  s.logLik(10, 1) = -1.0;
  TransitionModel chain = stayTransitions(2, 0.99);
  const Decisions plain = decide(s, chain, DecisionMode::Online);
  EXPECT_EQ(plain[10], 1);
  chain.emissionWeight = 0.1;
  const Decisions online = decide(s, chain, DecisionMode::Online);
  const Decisions offline = decide(s, chain, DecisionMode::Offline);
  EXPECT_EQ(online[10], 0);
  EXPECT_EQ(offline[10], 0);
  EXPECT_EQ(online[29], 1);
  EXPECT_EQ(offline[25], 1);
  // Online needs a few steps of the new class before it follows (0.3 nats each against the
  // chain's 4.6 for leaving); offline sees the change coming.
  EXPECT_EQ(online[20], 0);
}

TEST(Hmm, OfflineDecisionUsesTheFutureOnlineDoesNot) {
  // Two classes, sticky chain: a weak step for class 1 between strong steps for class 0.
  TransitionModel chain = stayTransitions(2, 0.95);
  StepLikelihoods s = twoClass({0, 0, 0, 0}, 3.0);
  s.logLik(3, 0) = -1.0 - 8.0;  // the last step strongly says class 1
  s.logLik(3, 1) = -1.0;
  s.logLik(2, 0) = -1.0 - 0.5;  // step 2 weakly says class 1
  s.logLik(2, 1) = -1.0;
  const Decisions online = decide(s, chain, DecisionMode::Online);
  const Decisions offline = decide(s, chain, DecisionMode::Offline);
  const Decisions step = decide(s, chain, DecisionMode::Step);
  EXPECT_EQ(step[2], 1);
  EXPECT_EQ(online[2], 0);   // the past (class 0) outweighs a weak step
  EXPECT_EQ(offline[2], 1);  // the strong class-1 step after it pulls it over
  EXPECT_EQ(online[3], 1);
}

TEST(Hmm, TransitionEstimateKeepsAnUnseenTransitionPossible) {
  // Class 1 is never followed by class 0, class 2 never seen at all.
  const TransitionModel m = estimateTransitions({{0, 0, 1, 1, -1, 1, 1}, {-1, 0}}, 3, 1.0);
  // Row 0: 0->0 once, 0->1 once: (1+1)/(2+3), (1+1)/(2+3), (0+1)/(2+3).
  EXPECT_NEAR(std::exp(m.logTransition(0, 0)), 2.0 / 5.0, 1e-15);
  EXPECT_NEAR(std::exp(m.logTransition(0, 1)), 2.0 / 5.0, 1e-15);
  EXPECT_NEAR(std::exp(m.logTransition(0, 2)), 1.0 / 5.0, 1e-15);
  // Row 1: 1->1 twice (steps 2-3 and 5-6), never 1->0: (0+1)/(2+3) > 0.
  EXPECT_NEAR(std::exp(m.logTransition(1, 0)), 1.0 / 5.0, 1e-15);
  EXPECT_NEAR(std::exp(m.logTransition(1, 1)), 3.0 / 5.0, 1e-15);
  // Row 2: no data: uniform.
  for (int j = 0; j < 3; ++j)
    EXPECT_NEAR(std::exp(m.logTransition(2, j)), 1.0 / 3.0, 1e-15);
  // Starts: 0 (run 1 step 0), 1 (run 1 step 5), 0 (run 2 step 1): (2+1)/6, (1+1)/6, 1/6.
  EXPECT_NEAR(std::exp(m.logInitial[0]), 3.0 / 6.0, 1e-15);
  EXPECT_NEAR(std::exp(m.logInitial[1]), 2.0 / 6.0, 1e-15);
  EXPECT_NEAR(std::exp(m.logInitial[2]), 1.0 / 6.0, 1e-15);
  EXPECT_EQ(m.counts(1, 0), 0.0);
  EXPECT_EQ(m.counts(1, 1), 2.0);
  // The unseen move can still be taken when the evidence demands it.
  StepLikelihoods s = randomSteps(3, 3, 7);
  s.logLik.row(0) << 0.0, -30.0, -30.0;
  s.logLik.row(1) << -30.0, 0.0, -30.0;
  s.logLik.row(2) << 0.0, -30.0, -30.0;  // 1 -> 0, never seen in training
  const Decisions d = decide(s, m, DecisionMode::Online);
  EXPECT_EQ(d[2], 0);
}

TEST(Hmm, OnlineDecisionIsCausal) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const TransitionModel chain = randomChain(3, seed);
    const StepLikelihoods s = randomSteps(40, 3, 50 + seed);
    const HmmFilterResult base = hmmForward(s, chain);
    for (int t = 0; t + 1 < 40; t += 3) {
      StepLikelihoods changed = s;
      // Change step t+1 and everything after it.
      for (int u = t + 1; u < 40; ++u)
        changed.logLik.row(u) = s.logLik.row(u).reverse() * 2.0;
      changed.observed[static_cast<std::size_t>(t + 1)] = (t % 2 == 0) ? 0 : 1;
      const HmmFilterResult r = hmmForward(changed, chain);
      for (int u = 0; u <= t; ++u) {
        EXPECT_EQ(r.decisions[static_cast<std::size_t>(u)],
                  base.decisions[static_cast<std::size_t>(u)]);
        for (int j = 0; j < 3; ++j)
          EXPECT_EQ(r.logPosterior(u, j), base.logPosterior(u, j));
      }
    }
  }
}

TEST(Hmm, UnderflowingStepAndForbiddingChainStayFinite) {
  const TransitionModel chain = randomChain(3, 3);
  StepLikelihoods s = randomSteps(5, 3, 9);
  s.logLik.row(2).setConstant(-kInf);
  s.logLik(3, 1) = std::numeric_limits<double>::quiet_NaN();
  for (const HmmFilterResult& r : {hmmForward(s, chain), hmmForwardBackward(s, chain)}) {
    for (int t = 0; t < 5; ++t) {
      EXPECT_NEAR(std::exp(logSumExp(r.logPosterior.row(t).transpose())), 1.0, 1e-12) << t;
      for (int j = 0; j < 3; ++j)
        EXPECT_FALSE(std::isnan(r.logPosterior(t, j)));
    }
  }
  // stay = 1 forbids every move: evidence for another class cannot be followed, but stays defined.
  const TransitionModel frozen = stayTransitions(2, 1.0);
  const StepLikelihoods two = twoClass({0, 1, 1});
  StepLikelihoods hard = two;
  hard.logLik(1, 0) = -kInf;
  for (const HmmFilterResult& r : {hmmForward(hard, frozen), hmmForwardBackward(hard, frozen)}) {
    for (int t = 0; t < 3; ++t)
      for (int j = 0; j < 2; ++j)
        EXPECT_FALSE(std::isnan(r.logPosterior(t, j)));
  }
}

// The compact layout (a row per observed step) decides exactly what the row-per-step layout does,
// for every decider, with episodes at the run's start and end, single steps, an underflowing
// step and weighted evidence; a compact layout short of a row decides nothing.
TEST(Hmm, CompactLikelihoodsDecideAsARowPerStep) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const int c = 2 + static_cast<int>(seed % 3);
    const int n = 400;
    StepLikelihoods full = randomSteps(n, c, seed);
    std::srand(seed * 7919u);
    for (int t = 0; t < n; ++t)
      full.observed[static_cast<std::size_t>(t)] = (std::rand() % 5 == 0) ? 0 : 1;
    full.observed[static_cast<std::size_t>(n - 1)] = seed % 2;  // an episode at the end, or not
    full.observed[0] = 1;
    for (int j = 0; j < c; ++j)
      full.logLik(7, j) = -kInf;  // an underflowing step (observed or not)
    full.logPriors = Eigen::VectorXd::Constant(c, -std::log(static_cast<double>(c)));
    full.logPriors[0] += 0.1;
    StepLikelihoods compact;
    compact.observed = full.observed;
    compact.logPriors = full.logPriors;
    std::vector<Eigen::Index> rows;
    for (int t = 0; t < n; ++t)
      if (full.observed[static_cast<std::size_t>(t)]) rows.push_back(t);
    compact.logLik.resize(static_cast<Eigen::Index>(rows.size()), c);
    for (std::size_t r = 0; r < rows.size(); ++r)
      compact.logLik.row(static_cast<Eigen::Index>(r)) = full.logLik.row(rows[r]);
    // Rows of unobserved steps in the full layout are ignored: make them noise.
    for (int t = 0; t < n; ++t)
      if (!full.observed[static_cast<std::size_t>(t)]) full.logLik.row(t).setConstant(123.0);
    ASSERT_TRUE(compact.compact());
    ASSERT_FALSE(full.compact());
    ASSERT_EQ(compact.steps(), n);

    TransitionModel chain = randomChain(c, seed);
    chain.emissionWeight = 0.5 + 0.5 * static_cast<double>(seed % 3);
    EXPECT_EQ(argmaxDecisions(compact), argmaxDecisions(full)) << seed;
    EXPECT_EQ(consecutiveCountDecisions(compact, 3), consecutiveCountDecisions(full, 3)) << seed;
    EXPECT_EQ(summedLogProbabilityDecisions(compact, 2.0, 4),
              summedLogProbabilityDecisions(full, 2.0, 4))
        << seed;
    for (DecisionMode mode : kDecisionModes)
      EXPECT_EQ(decide(compact, chain, mode), decide(full, chain, mode)) << seed;
    const HmmFilterResult a = hmmForwardBackward(compact, chain);
    const HmmFilterResult b = hmmForwardBackward(full, chain);
    EXPECT_EQ(a.decisions, b.decisions) << seed;
    ASSERT_EQ(a.logPosterior.rows(), n);
    for (int t = 0; t < n; ++t)
      for (int j = 0; j < c; ++j)
        if (full.observed[static_cast<std::size_t>(t)]) {
          ASSERT_EQ(a.logPosterior(t, j), b.logPosterior(t, j)) << seed << " t " << t;
        } else {
          ASSERT_EQ(a.logPosterior(t, j), -kInf);
        }
    std::size_t decided = 0;
    for (const auto& d : a.decisions)
      decided += d.has_value() ? 1 : 0;
    EXPECT_EQ(decided, rows.size());

    // One row short: nothing is decided, nothing is read past the end.
    StepLikelihoods shortOfOne = compact;
    shortOfOne.logLik.conservativeResize(compact.logLik.rows() - 1, c);
    for (DecisionMode mode : kDecisionModes) {
      const Decisions d = decide(shortOfOne, chain, mode);
      ASSERT_EQ(d.size(), static_cast<std::size_t>(n));
      for (const auto& x : d)
        EXPECT_FALSE(x.has_value());
    }
  }
}

TEST(Hmm, DecisionModeNames) {
  for (DecisionMode m : kDecisionModes)
    EXPECT_EQ(parseDecisionMode(decisionModeName(m)), m);
  EXPECT_FALSE(parseDecisionMode("smoothed").has_value());
  EXPECT_TRUE(isCausal(DecisionMode::Online));
  EXPECT_FALSE(isCausal(DecisionMode::Offline));
}

}  // namespace
}  // namespace tactile::analysis
