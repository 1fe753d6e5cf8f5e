// Numerical-stability tests of issue 3 (numbers refer to its list; 9, the model-file round trip,
// lives in model_file_test.cpp).
// GCC 12 reports false -Wmaybe-uninitialized inside Eigen's AVX-512 kernels at -O3.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "analysis/classifier.h"
#include "analysis/gmm.h"
#include "tests/analysis/gmm_test_util.h"

namespace tactile {
namespace {

using testing::gaussianRows;
using testing::stackRows;

// Smallest variance of a fitted model: diagonal entries, and for full forms also eigenvalues.
double smallestVariance(const GaussianMixture& m) {
  double v = std::numeric_limits<double>::infinity();
  for (const auto& c : m.covariances()) {
    v = std::min(v, c.diagonal().minCoeff());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> e(c);
    v = std::min(v, e.eigenvalues().minCoeff());
  }
  return v;
}

Eigen::MatrixXd onesAndZeros() {
  Eigen::MatrixXd x(10, 5);
  x.topRows(5).setOnes();
  x.bottomRows(5).setZero();
  return x;
}

// 1. Duplicate points, floor 0: a clear error for every covariance form.
TEST(Stability01, DuplicatePointsWithFloorZeroIsAClearError) {
  for (CovarianceForm form : kAllCovarianceForms) {
    GmmOptions o;
    o.components = 10;
    o.form = form;
    o.floor = 0.0;
    const GmmFit fit = fitGmm(onesAndZeros(), o);
    EXPECT_FALSE(fit.ok) << covarianceFormName(form);
    EXPECT_NE(fit.reason.find("singular"), std::string::npos) << fit.reason;
    EXPECT_NE(fit.reason.find("floor"), std::string::npos) << fit.reason;
  }
}

// 1. Duplicate points, floor > 0: fits, and every variance is at least the floor.
TEST(Stability01, DuplicatePointsWithPositiveFloorRespectTheFloor) {
  for (CovarianceForm form : kAllCovarianceForms) {
    for (GmmInit init : {GmmInit::KMeansPlusPlus, GmmInit::RandomFromData}) {
      GmmOptions o;
      o.components = 10;
      o.form = form;
      o.floor = 0.01;
      o.init = init;
      const GmmFit fit = fitGmm(onesAndZeros(), o);
      ASSERT_TRUE(fit.ok) << covarianceFormName(form) << ": " << fit.reason;
      EXPECT_GE(smallestVariance(fit.model), 0.01 * (1 - 1e-12)) << covarianceFormName(form);
      EXPECT_TRUE(std::isfinite(fit.logLikelihood));
    }
  }
}

// 2. A feature constant within a class: its variance is the floor, the log-likelihood finite.
TEST(Stability02, ConstantFeatureGetsTheFloorVariance) {
  Eigen::Vector3d mean(1.0, 7.0, -2.0), sd(1.0, 0.0, 2.0);
  const Eigen::MatrixXd x = gaussianRows(300, mean, sd, 5);
  ASSERT_EQ(x.col(1).minCoeff(), 7.0);
  const double floor = 0.05;
  for (CovarianceForm form : kAllCovarianceForms) {
    GmmOptions o;
    o.components = 2;
    o.form = form;
    o.floor = floor;
    const GmmFit fit = fitGmm(x, o);
    ASSERT_TRUE(fit.ok) << fit.reason;
    for (const auto& c : fit.model.covariances())
      EXPECT_NEAR(c(1, 1), floor, 1e-9 * floor) << covarianceFormName(form);
    EXPECT_TRUE(std::isfinite(fit.logLikelihood));
    EXPECT_TRUE(std::isfinite(fit.model.meanLogLikelihood(x)));
  }
  const auto g = fitGaussian(x, floor);
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->covariance(0)(1, 1), floor, 1e-9 * floor);
  EXPECT_TRUE(std::isfinite(g->meanLogLikelihood(x)));
}

// 3. Cancellation: [[9999],[0]] with 2 components: variances equal the floor, and adding 1e6 to
// the data leaves them unchanged to 1e-9 relative.
TEST(Stability03, LargeOffsetsDoNotCancelVariances) {
  const double floor = 1e-3;
  for (CovarianceForm form : {CovarianceForm::NodalDiag, CovarianceForm::NodalFull}) {
    GmmOptions o;
    o.components = 2;
    o.form = form;
    o.floor = floor;
    Eigen::MatrixXd x(2, 1);
    x << 9999.0, 0.0;
    const GmmFit a = fitGmm(x, o);
    const GmmFit b = fitGmm((x.array() + 1e6).matrix(), o);
    ASSERT_TRUE(a.ok && b.ok) << a.reason << b.reason;
    ASSERT_EQ(a.model.components(), 2);
    ASSERT_EQ(b.model.components(), 2);
    for (int k = 0; k < 2; ++k) {
      EXPECT_NEAR(a.model.covariance(k)(0, 0), floor, 1e-12);
      EXPECT_NEAR(b.model.covariance(k)(0, 0), a.model.covariance(k)(0, 0), 1e-9 * floor);
    }
    EXPECT_NEAR(a.model.means().maxCoeff(), 9999.0, 1e-9);
    EXPECT_NEAR(b.model.means().maxCoeff(), 1009999.0, 1e-6);
  }
}

// 4. Underflow: a point 1e3 standard deviations from every component.
TEST(Stability04, FarPointHasFiniteLogLikelihoodAndADefinedClass) {
  Eigen::Vector2d m0(0, 0), m1(4, 4), sd(1, 1);
  const Eigen::MatrixXd a = gaussianRows(400, m0, sd, 1);
  const Eigen::MatrixXd b = gaussianRows(400, m1, sd, 2);
  ClassifierOptions o;
  o.gmm.components = 3;
  o.gmm.form = CovarianceForm::NodalFull;
  const ClassifierFit fit = trainClassifier({a, b}, {"a", "b"}, o);
  ASSERT_TRUE(fit.ok) << fit.reason;
  Eigen::MatrixXd far(1, 2);
  far << 1000.0, -1000.0;
  for (int c = 0; c < 2; ++c) {
    const GaussianMixture& m = fit.model.model(c);
    const double l = m.logDensity(far.row(0).transpose());
    EXPECT_TRUE(std::isfinite(l));
    EXPECT_LT(l, -1e5);
    const Eigen::VectorXd r = m.responsibilities(far.row(0).transpose());
    EXPECT_TRUE(r.allFinite());
    EXPECT_NEAR(r.sum(), 1.0, 1e-12);
  }
  Eigen::MatrixXd ll;
  fit.model.logLikelihoods(far, ll);
  EXPECT_TRUE(ll.allFinite());
  const int cls = fit.model.predictOne(far.row(0).transpose());
  EXPECT_TRUE(cls == 0 || cls == 1);
}

// 5. 64 components on a class with 50 samples.
TEST(Stability05, SixtyFourComponentsOnFiftySamples) {
  Eigen::Vector3d mean(0, 1, 2), sd(1, 2, 0.5);
  const Eigen::MatrixXd x = gaussianRows(50, mean, sd, 9);
  for (CovarianceForm form : kAllCovarianceForms) {
    for (GmmInit init : {GmmInit::KMeansPlusPlus, GmmInit::RandomFromData}) {
      GmmOptions o;
      o.components = 64;
      o.form = form;
      o.floor = 1e-3;
      o.init = init;
      const GmmFit fit = fitGmm(x, o);
      ASSERT_TRUE(fit.ok) << fit.reason;
      EXPECT_TRUE(testing::allFiniteMixture(fit.model.weights(), fit.model.means(),
                                            fit.model.covariances()));
      EXPECT_NEAR(fit.model.weights().sum(), 1.0, 1e-12);
      EXPECT_TRUE(std::isfinite(fit.logLikelihood));
      EXPECT_TRUE(std::isfinite(fit.bic));
    }
  }
}

// 6. The log-likelihood never decreases from one EM step to the next. With the floor (a clamp of
// variances or eigenvalues) every M-step is the exact constrained maximiser, so EM is monotone.
Eigen::MatrixXd threeBlobs() {
  Eigen::Vector2d m0(0, 0), m1(3, 1), m2(-2, 4), sd(1, 0.7);
  return stackRows(
      {gaussianRows(700, m0, sd, 1), gaussianRows(500, m1, sd, 2), gaussianRows(300, m2, sd, 3)});
}

GmmFit tracedFit(const Eigen::MatrixXd& x, CovarianceForm form, Regularization reg, GmmInit init) {
  GmmOptions o;
  o.components = 5;
  o.form = form;
  o.reg = reg;
  o.floor = 1e-2;
  o.init = init;
  o.tolerance = 0.0;
  o.maxIterations = 60;
  o.maxReinitialisations = 0;
  o.keepTrace = true;
  return fitGmm(x, o);
}

TEST(Stability06, LogLikelihoodNeverDecreasesWithTheFloor) {
  const Eigen::MatrixXd x = threeBlobs();
  for (CovarianceForm form : kAllCovarianceForms) {
    for (GmmInit init : {GmmInit::KMeansPlusPlus, GmmInit::RandomFromData}) {
      const GmmFit fit = tracedFit(x, form, Regularization::Floor, init);
      ASSERT_TRUE(fit.ok) << fit.reason;
      ASSERT_GE(fit.trace.size(), 10u);
      for (std::size_t t = 1; t < fit.trace.size(); ++t)
        EXPECT_GE(fit.trace[t], fit.trace[t - 1] - 1e-12 * std::abs(fit.trace[t - 1]))
            << covarianceFormName(form) << " step " << t;
    }
  }
}

// 6. With `add` (Sigma = S + eps I, scikit-learn's reg_covar) the M-step is not the maximiser of
// the likelihood, so near its fixed point a plain EM step may lower it slightly. The fit undoes
// such a step and stops (docs/learning.md), so the recorded log-likelihoods never decrease here
// either, and the fit still improves on its start.
TEST(Stability06, LogLikelihoodNeverDecreasesWithAddRegularization) {
  const Eigen::MatrixXd x = threeBlobs();
  for (CovarianceForm form : kAllCovarianceForms) {
    for (GmmInit init : {GmmInit::KMeansPlusPlus, GmmInit::RandomFromData}) {
      const GmmFit fit = tracedFit(x, form, Regularization::Add, init);
      ASSERT_TRUE(fit.ok) << fit.reason;
      ASSERT_GE(fit.trace.size(), 3u);
      for (std::size_t t = 1; t < fit.trace.size(); ++t) {
        EXPECT_GE(fit.trace[t], fit.trace[t - 1] - 1e-12 * std::abs(fit.trace[t - 1]))
            << covarianceFormName(form) << " step " << t;
      }
      EXPECT_GT(fit.trace.back(), fit.trace.front());
    }
  }
}

// 7. Ill-conditioned covariance: the log-density matches a long-double reference.
TEST(Stability07, IllConditionedCovarianceMatchesLongDoubleReference) {
  Eigen::Matrix3d s;
  s << 32, 36, 8, 36, 40.5, 9, 8, 9, 2;
  s += 1e-8 * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d mu(1.0, -2.0, 0.5);
  auto m = GaussianMixture::create(Eigen::VectorXd::Ones(1), mu.transpose(), {s},
                                   CovarianceForm::NodalFull);
  ASSERT_TRUE(m.has_value());
  // Reference: long-double Gauss-Jordan inverse and determinant.
  const auto reference = [&](const Eigen::Vector3d& x) {
    long double a[3][6];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 6; ++j)
        a[i][j] = j < 3 ? static_cast<long double>(s(i, j)) : (j - 3 == i ? 1.0L : 0.0L);
    long double det = 1.0L;
    for (int c = 0; c < 3; ++c) {
      int p = c;
      for (int r = c + 1; r < 3; ++r)
        if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
      if (p != c) {
        for (int j = 0; j < 6; ++j)
          std::swap(a[p][j], a[c][j]);
        det = -det;
      }
      det *= a[c][c];
      const long double piv = a[c][c];
      for (int j = 0; j < 6; ++j)
        a[c][j] /= piv;
      for (int r = 0; r < 3; ++r) {
        if (r == c) continue;
        const long double f = a[r][c];
        for (int j = 0; j < 6; ++j)
          a[r][j] -= f * a[c][j];
      }
    }
    long double maha = 0.0L;
    long double d[3];
    for (int i = 0; i < 3; ++i)
      d[i] = static_cast<long double>(x(i)) - static_cast<long double>(mu(i));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        maha += d[i] * a[i][j + 3] * d[j];
    return static_cast<double>(
        -0.5L * (3.0L * std::log(2.0L * 3.14159265358979323846264338L) + std::log(det) + maha));
  };
  for (const Eigen::Vector3d& x :
       {Eigen::Vector3d(1.0, -2.0, 0.5), Eigen::Vector3d(5.0, 2.5, 1.5),
        Eigen::Vector3d(1.001, -2.0, 0.5), Eigen::Vector3d(-3.0, 0.0, 2.0)}) {
    const double ref = reference(x);
    EXPECT_NEAR(m->logDensity(x), ref, 1e-6 * std::abs(ref)) << x.transpose();
  }
}

// 8. Known answer.
TEST(Stability08, KnownAnswerTwoComponentMixture) {
  Eigen::MatrixXd means(2, 2);
  means << 0, 0, 3, 3;
  Eigen::Matrix2d c1;
  c1 << 2, 1, 1, 2;
  auto m =
      GaussianMixture::create(Eigen::Vector2d(0.3, 0.7), means,
                              {Eigen::MatrixXd::Identity(2, 2), c1}, CovarianceForm::NodalFull);
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(std::exp(m->logDensity(Eigen::Vector2d(0, 0))), 0.05094887202, 1e-11);
  EXPECT_NEAR(std::exp(m->logDensity(Eigen::Vector2d(3, 3))), 0.06432759685, 1e-11);
}

// 10. The best of 10 restarts never scores below a single start.
TEST(Stability10, BestOfTenRestartsIsNeverWorseThanOne) {
  Eigen::Vector2d m0(0, 0), m1(2, 2), m2(-2, 3), sd(1, 1);
  const Eigen::MatrixXd x = stackRows(
      {gaussianRows(300, m0, sd, 4), gaussianRows(300, m1, sd, 5), gaussianRows(300, m2, sd, 6)});
  for (GmmInit init : {GmmInit::KMeansPlusPlus, GmmInit::RandomFromData}) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      GmmOptions o;
      o.components = 6;
      o.form = CovarianceForm::NodalFull;
      o.init = init;
      o.seed = seed;
      const GmmFit one = fitGmm(x, o);
      o.restarts = 10;
      const GmmFit ten = fitGmm(x, o);
      ASSERT_TRUE(one.ok && ten.ok);
      EXPECT_GE(ten.logLikelihood, one.logLikelihood);
    }
  }
}

// 11. Scale: features x 1e6 and x 1e-6 (floor scaled by the square) classify as unscaled. Each
// class has two clusters and EM runs to a tight tolerance, so both fits reach the same optimum
// and only rounding separates them.
TEST(Stability11, ScaledFeaturesClassifyTheSame) {
  Eigen::Vector3d a0(0, 0, 0), a1(6, 0, 0), b0(3, 2, -1), b1(3, -4, 1), sd(1, 0.8, 1.2);
  const Eigen::MatrixXd a =
      stackRows({gaussianRows(400, a0, sd, 11), gaussianRows(400, a1, sd, 12)});
  const Eigen::MatrixXd b =
      stackRows({gaussianRows(400, b0, sd, 13), gaussianRows(400, b1, sd, 14)});
  const Eigen::MatrixXd test =
      stackRows({gaussianRows(200, a0, sd, 15), gaussianRows(200, a1, sd, 16),
                 gaussianRows(200, b0, sd, 17), gaussianRows(200, b1, sd, 18)});
  for (ClassifierMethod method : {ClassifierMethod::Gmm, ClassifierMethod::Gaussian}) {
    ClassifierOptions o;
    o.method = method;
    o.gmm.components = 2;
    o.gmm.form = CovarianceForm::NodalFull;
    o.gmm.floor = 1e-3;
    o.gmm.tolerance = 1e-13;
    o.gmm.rule = ConvergenceRule::Absolute;
    o.gmm.maxIterations = 1000;
    const ClassifierFit base = trainClassifier({a, b}, {"a", "b"}, o);
    ASSERT_TRUE(base.ok) << base.reason;
    const std::vector<int> expected = base.model.predict(test);
    for (double scale : {1e6, 1e-6}) {
      ClassifierOptions s = o;
      s.gmm.floor = o.gmm.floor * scale * scale;
      const ClassifierFit fit = trainClassifier({a * scale, b * scale}, {"a", "b"}, s);
      ASSERT_TRUE(fit.ok) << fit.reason;
      EXPECT_EQ(fit.model.predict(test * scale), expected)
          << classifierMethodName(method) << " scale " << scale;
    }
  }
}

// 12. Fewer samples than dimensions in a class: a clear error.
TEST(Stability12, FewerSamplesThanDimensionsIsAClearError) {
  const Eigen::MatrixXd big =
      gaussianRows(50, Eigen::VectorXd::Zero(5), Eigen::VectorXd::Ones(5), 1);
  const Eigen::MatrixXd small =
      gaussianRows(3, Eigen::VectorXd::Ones(5), Eigen::VectorXd::Ones(5), 2);
  for (ClassifierMethod method : {ClassifierMethod::Gmm, ClassifierMethod::Gaussian}) {
    ClassifierOptions o;
    o.method = method;
    const ClassifierFit fit = trainClassifier({big, small}, {"Wall", "Corner"}, o);
    EXPECT_FALSE(fit.ok);
    EXPECT_NE(fit.reason.find("'Corner'"), std::string::npos) << fit.reason;
    EXPECT_NE(fit.reason.find("fewer than"), std::string::npos) << fit.reason;
  }
}

// 12. A class with zero samples: a clear error.
TEST(Stability12, ClassWithoutSamplesIsAClearError) {
  const Eigen::MatrixXd big =
      gaussianRows(50, Eigen::VectorXd::Zero(2), Eigen::VectorXd::Ones(2), 1);
  for (ClassifierMethod method : {ClassifierMethod::Gmm, ClassifierMethod::Gaussian}) {
    ClassifierOptions o;
    o.method = method;
    const ClassifierFit fit =
        trainClassifier({big, Eigen::MatrixXd(0, 2)}, {"Wall", "LostWall"}, o);
    EXPECT_FALSE(fit.ok);
    EXPECT_NE(fit.reason.find("'LostWall' has no training samples"), std::string::npos)
        << fit.reason;
  }
}

}  // namespace
}  // namespace tactile
