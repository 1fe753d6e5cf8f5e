// Temporal deciders over a run (thesis 4.6): consecutive count, summed log-probability, HMM filter.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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
