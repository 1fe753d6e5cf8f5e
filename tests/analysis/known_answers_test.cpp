// Known answers beside the agreement tests (two paths agree, a fit is deterministic): values
// worked out by hand or in closed form here, not taken from the code under test.
//  - a two-component mixture's log-density (beside GaussianMixture.BatchedDensitiesMatch...);
//  - a one-component EM fit on four points: the ML mean, variance and log-likelihood (beside
//    FitGmm.SameSeedSameModelOtherSeedOtherStart and ResultsDoNotDependOnTheThreadCount);
//  - log-sum-exp of values with a known sum, far from and near the overflow range;
//  - one HMM prediction step on a 2-state chain, and transition estimates from hand-counted moves;
//  - balanced accuracy over well-supported classes and macro-F1 on a hand confusion matrix;
//  - k-means on two separable clusters: the cluster means and the inertia (beside
//    KMeansPlusPlus.ResultDoesNotDependOnTheThreadCount).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "analysis/gaussian.h"
#include "analysis/gaussian_mixture.h"
#include "analysis/gmm.h"
#include "analysis/kmeans.h"
#include "analysis/metrics.h"
#include "analysis/temporal.h"

namespace tactile::analysis {
namespace {
namespace known_answers {  // its own names in a unity build

constexpr double kPi = std::numbers::pi;

// 1-D normal density, written out.
double normal(double x, double mean, double variance) {
  return std::exp(-(x - mean) * (x - mean) / (2.0 * variance)) / std::sqrt(2.0 * kPi * variance);
}

TEST(KnownAnswer, TwoComponentMixtureLogDensity) {
  // w = (1/4, 3/4), means 0 and 2, variances 1 and 4.
  Eigen::VectorXd w(2);
  w << 0.25, 0.75;
  Eigen::MatrixXd means(2, 1);
  means << 0.0, 2.0;
  const std::vector<Eigen::MatrixXd> covs{Eigen::MatrixXd::Constant(1, 1, 1.0),
                                          Eigen::MatrixXd::Constant(1, 1, 4.0)};
  auto m = GaussianMixture::create(w, means, covs, CovarianceForm::NodalDiag);
  ASSERT_TRUE(m.ok()) << m.errorText();
  // At x = 1: 1/4 e^(-1/2) / sqrt(2 pi) + 3/4 e^(-1/8) / (2 sqrt(2 pi)).
  const double atOne = std::log(0.25 * std::exp(-0.5) / std::sqrt(2.0 * kPi) +
                                0.75 * std::exp(-0.125) / (2.0 * std::sqrt(2.0 * kPi)));
  Eigen::VectorXd x(1);
  x << 1.0;
  EXPECT_NEAR(m->logDensity(x), atOne, 1e-14);
  Eigen::MatrixXd rows(3, 1);
  rows << 1.0, -3.0, 10.0;
  Eigen::VectorXd batch;
  m->logDensities(rows, batch);
  ASSERT_EQ(batch.size(), 3);
  for (int r = 0; r < 3; ++r) {
    const double v = rows(r, 0);
    EXPECT_NEAR(batch(r), std::log(0.25 * normal(v, 0, 1) + 0.75 * normal(v, 2, 4)), 1e-13)
        << "x = " << v;
  }
}

TEST(KnownAnswer, OneComponentFitIsTheMaximumLikelihoodGaussian) {
  // Points 0, 2, 4, 6: mean 3, ML variance (9 + 1 + 1 + 9) / 4 = 5, log-likelihood
  // sum log N(x | 3, 5) = -2 log(10 pi) - (1/2)(20 / 5) = -2 log(10 pi) - 2.
  Eigen::MatrixXd x(4, 1);
  x << 0.0, 2.0, 4.0, 6.0;
  GmmOptions o;
  o.components = 1;
  o.varianceFloor = 1e-6;
  const GmmFit fit = fitGmm(x, o);
  ASSERT_TRUE(fit.ok) << fit.reason;
  ASSERT_EQ(fit.model.components(), 1);
  EXPECT_NEAR(fit.model.means()(0, 0), 3.0, 1e-12);
  EXPECT_NEAR(fit.model.covariance(0)(0, 0), 5.0, 1e-12);
  const double logL = -2.0 * std::log(10.0 * kPi) - 2.0;
  EXPECT_NEAR(fit.logLikelihood, logL, 1e-12);
  EXPECT_NEAR(fit.meanLogLikelihood, logL / 4.0, 1e-12);
  // 2 parameters (mean, variance; the one weight is fixed): BIC = -2 logL + 2 ln 4.
  EXPECT_NEAR(fit.bic, -2.0 * logL + 2.0 * std::log(4.0), 1e-11);
}

TEST(KnownAnswer, LogSumExp) {
  const double small[] = {std::log(1.0), std::log(2.0), std::log(3.0)};
  EXPECT_NEAR(logSumExp(small, 3), std::log(6.0), 1e-15);
  // Far beyond exp's range: 1000 + log(1 + 3).
  const double large[] = {1000.0, 1000.0 + std::log(3.0)};
  EXPECT_NEAR(logSumExp(large, 2), 1000.0 + std::log(4.0), 1e-12);
  const double tiny[] = {-1000.0, -1000.0};
  EXPECT_NEAR(logSumExp(tiny, 2), -1000.0 + std::log(2.0), 1e-12);
  Eigen::VectorXd v(3);
  v << std::log(0.5), std::log(0.25), -std::numeric_limits<double>::infinity();
  EXPECT_NEAR(logSumExp(v), std::log(0.75), 1e-15);
}

TEST(KnownAnswer, HmmPredictionStepOnTwoStates) {
  // alpha = (0.3, 0.7), A = [0.9 0.1; 0.2 0.8]: alpha A = (0.27 + 0.14, 0.03 + 0.56).
  Eigen::MatrixXd a(2, 2);
  a << 0.9, 0.1, 0.2, 0.8;
  TransitionModel chain;
  chain.set(a.array().log().matrix(), Eigen::VectorXd::Constant(2, std::log(0.5)));
  Eigen::VectorXd alpha(2);
  alpha << std::log(0.3), std::log(0.7);
  Eigen::VectorXd predicted;
  hmmPredict(alpha, chain, predicted);
  ASSERT_EQ(predicted.size(), 2);
  EXPECT_NEAR(predicted(0), std::log(0.41), 1e-14);
  EXPECT_NEAR(predicted(1), std::log(0.59), 1e-14);
}

TEST(KnownAnswer, TransitionEstimateFromHandCountedMoves) {
  // Moves 0->0, 0->1, 1->1, 1->1 and starts 0 and 1 (after the gap): with one pseudo-count,
  // A(0, .) = (1+1, 1+1) / (2+2), A(1, .) = (0+1, 2+1) / (2+2), pi = (1+1, 1+1) / (2+2).
  const TransitionModel t = estimateTransitions({{0, 0, 1, -1, 1, 1, 1}}, 2, 1.0);
  ASSERT_EQ(t.classCount(), 2);
  EXPECT_NEAR(std::exp(t.logTransition(0, 0)), 0.5, 1e-15);
  EXPECT_NEAR(std::exp(t.logTransition(0, 1)), 0.5, 1e-15);
  EXPECT_NEAR(std::exp(t.logTransition(1, 0)), 0.25, 1e-15);
  EXPECT_NEAR(std::exp(t.logTransition(1, 1)), 0.75, 1e-15);
  EXPECT_NEAR(std::exp(t.logInitial(0)), 0.5, 1e-15);
  EXPECT_NEAR(std::exp(t.logInitial(1)), 0.5, 1e-15);
}

TEST(KnownAnswer, MetricsOfAHandConfusionMatrix) {
  using enum ContactClass;
  // Rows truth, columns predicted:
  //   Wall:     40 Wall, 10 Corner             (support 50, recall 0.8)
  //   Corner:    6 Wall, 24 Corner             (support 30, recall 0.8)
  //   DeadPath:  2 Wall,  2 Corner, 6 DeadPath (support 10, recall 0.6)
  //   nothing true LeavingWall, but 0 predicted either.
  ConfusionMatrix c;
  c.add(Wall, Wall, 40);
  c.add(Wall, Corner, 10);
  c.add(Corner, Wall, 6);
  c.add(Corner, Corner, 24);
  c.add(DeadPath, Wall, 2);
  c.add(DeadPath, Corner, 2);
  c.add(DeadPath, DeadPath, 6);
  const Metrics m = computeMetrics(c);
  EXPECT_EQ(m.total, 90u);
  EXPECT_NEAR(m.accuracy, 70.0 / 90.0, 1e-15);
  EXPECT_NEAR(m.balancedAccuracy, (0.8 + 0.8 + 0.6) / 3.0, 1e-15);
  // F1 = 2 tp / (2 tp + fp + fn): Wall 80 / (80 + 8 + 10), Corner 48 / (48 + 12 + 6),
  // DeadPath 12 / (12 + 0 + 4).
  EXPECT_NEAR(m.macroF1, (80.0 / 98.0 + 48.0 / 66.0 + 12.0 / 16.0) / 3.0, 1e-15);
  // Over the classes with at least 30 test steps only: Wall and Corner.
  const std::optional<double> wellSupported = balancedAccuracyOver(m, 30);
  ASSERT_TRUE(wellSupported.has_value());
  EXPECT_NEAR(*wellSupported, 0.8, 1e-15);
  EXPECT_FALSE(balancedAccuracyOver(m, 51).has_value());
  // Cohen's kappa: po = 70/90, pe = (50*48 + 30*36 + 10*6) / 90^2 = 3540 / 8100.
  const double po = 70.0 / 90.0;
  const double pe = 3540.0 / 8100.0;
  ASSERT_TRUE(cohensKappa(c).has_value());
  EXPECT_NEAR(*cohensKappa(c), (po - pe) / (1.0 - pe), 1e-14);
}

TEST(KnownAnswer, KMeansOnTwoSeparableClusters) {
  // {(0,0), (1,0), (0,1)} and {(10,10), (11,10), (10,11)}: the centres are the cluster means
  // (1/3, 1/3) and (31/3, 31/3); each cluster's squared distances to its mean are
  // 2/9 + 5/9 + 5/9 = 4/3, so the inertia is 8/3.
  Eigen::MatrixXd x(6, 2);
  x << 0, 0, 10, 10, 1, 0, 11, 10, 0, 1, 10, 11;
  Rng rng(7);
  Eigen::MatrixXd centres = kmeansPlusPlus(x, 2, rng);
  std::vector<int> assignment;
  lloydIterations(x, centres, 20, assignment);
  ASSERT_EQ(assignment.size(), 6u);
  // Rows 0, 2, 4 together, rows 1, 3, 5 together, the two apart.
  EXPECT_EQ(assignment[0], assignment[2]);
  EXPECT_EQ(assignment[0], assignment[4]);
  EXPECT_EQ(assignment[1], assignment[3]);
  EXPECT_EQ(assignment[1], assignment[5]);
  ASSERT_NE(assignment[0], assignment[1]);
  const int low = assignment[0];
  const int high = assignment[1];
  EXPECT_NEAR(centres(low, 0), 1.0 / 3.0, 1e-14);
  EXPECT_NEAR(centres(low, 1), 1.0 / 3.0, 1e-14);
  EXPECT_NEAR(centres(high, 0), 31.0 / 3.0, 1e-13);
  EXPECT_NEAR(centres(high, 1), 31.0 / 3.0, 1e-13);
  EXPECT_NEAR(assignNearest(x, centres, assignment), 8.0 / 3.0, 1e-12);
}

}  // namespace known_answers
}  // namespace
}  // namespace tactile::analysis
