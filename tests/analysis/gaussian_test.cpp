// GCC 12 reports false -Wmaybe-uninitialized inside Eigen's AVX-512 kernels at -O3.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "analysis/gaussian.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <vector>

namespace tactile::analysis {
namespace {

TEST(LogSumExp, MatchesDirectSumForModerateValues) {
  const std::vector<double> v{-1.0, 0.5, 2.0};
  const double direct = std::log(std::exp(-1.0) + std::exp(0.5) + std::exp(2.0));
  EXPECT_NEAR(logSumExp(v.data(), 3), direct, 1e-14);
}

TEST(LogSumExp, StaysFiniteWhereExpUnderflows) {
  const std::vector<double> v{-1e5, -1e5 - std::log(3.0)};
  EXPECT_NEAR(logSumExp(v.data(), 2), -1e5 + std::log(1.0 + 1.0 / 3.0), 1e-9);
}

TEST(LogSumExp, AllMinusInfinityGivesMinusInfinity) {
  const double ninf = -std::numeric_limits<double>::infinity();
  const std::vector<double> v{ninf, ninf};
  EXPECT_EQ(logSumExp(v.data(), 2), ninf);
  EXPECT_EQ(logSumExp(v.data(), 0), ninf);
}

TEST(Cholesky, ReconstructsAPositiveDefiniteMatrix) {
  Eigen::MatrixXd a(3, 3);
  a << 4, 2, 0.4, 2, 5, 1, 0.4, 1, 3;
  Eigen::MatrixXd l;
  ASSERT_TRUE(choleskyLower(a, l));
  EXPECT_LT((l * l.transpose() - a).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(logDeterminantFromCholesky(l), std::log(a.determinant()), 1e-12);
}

TEST(Cholesky, RejectsSingularAndIndefiniteMatrices) {
  Eigen::MatrixXd singular(2, 2);
  singular << 1, 1, 1, 1;
  Eigen::MatrixXd l;
  EXPECT_FALSE(choleskyLower(singular, l));
  Eigen::MatrixXd indefinite(2, 2);
  indefinite << 1, 2, 2, 1;
  EXPECT_FALSE(choleskyLower(indefinite, l));
}

TEST(GaussianLogDensity, MatchesTheClosedFormInTwoDimensions) {
  Eigen::MatrixXd s(2, 2);
  s << 2, 1, 1, 2;
  Eigen::VectorXd mu(2), x(2);
  mu << 1, -1;
  x << 0.3, 0.2;
  Eigen::MatrixXd l;
  ASSERT_TRUE(choleskyLower(s, l));
  const Eigen::VectorXd d = x - mu;
  const double expected =
      -std::log(2 * M_PI) - 0.5 * std::log(s.determinant()) - 0.5 * d.dot(s.inverse() * d);
  EXPECT_NEAR(gaussianLogDensity(x, mu, l, logDeterminantFromCholesky(l)), expected, 1e-13);
}

TEST(ClampEigenvalues, RaisesSmallEigenvaluesToTheFloorOnly) {
  Eigen::MatrixXd s(2, 2);
  s << 1, 0.999, 0.999, 1;  // eigenvalues 1.999 and 0.001
  const Eigen::MatrixXd c = clampEigenvalues(s, 0.1);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> e(c);
  EXPECT_NEAR(e.eigenvalues()(0), 0.1, 1e-12);
  EXPECT_NEAR(e.eigenvalues()(1), 1.999, 1e-12);
  const Eigen::MatrixXd same = clampEigenvalues(s, 1e-4);
  EXPECT_LT((same - s).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(Rng, IsDeterministicPerSeedAndUniformInRange) {
  Rng a(7), b(7), c(8);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const double u = a.uniform();
    EXPECT_EQ(u, b.uniform());
    differs = differs || u != c.uniform();
    EXPECT_GE(u, 0.0);
    EXPECT_LT(u, 1.0);
  }
  EXPECT_TRUE(differs);
  for (int i = 0; i < 100; ++i)
    EXPECT_LT(a.below(3), 3u);
}

}  // namespace
}  // namespace tactile::analysis
