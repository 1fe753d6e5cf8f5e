// Numerical-stability cases of the learning core (docs/learning.md, "Stability cases"; the
// model-file round trip lives in model_file_test.cpp).
// GCC 12 reports false -Wmaybe-uninitialized inside Eigen's AVX-512 kernels at -O3.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "analysis/classifier.h"
#include "analysis/gmm.h"
#include "tests/analysis/gmm_test_util.h"

namespace tactile::analysis {
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

// Duplicate points, variance floor 0: a clear error for every covariance form, in the core's words
// ("variance floor", not the command-line option).
TEST(GmmStability, DuplicatePointsWithZeroVarianceFloorIsAClearError) {
  for (CovarianceForm form : kAllCovarianceForms) {
    GmmOptions o;
    o.components = 10;
    o.form = form;
    o.varianceFloor = 0.0;
    const GmmFit fit = fitGmm(onesAndZeros(), o);
    EXPECT_FALSE(fit.ok) << covarianceFormName(form);
    EXPECT_NE(fit.reason.find("singular"), std::string::npos) << fit.reason;
    EXPECT_NE(fit.reason.find("variance floor 0"), std::string::npos) << fit.reason;
    EXPECT_EQ(fit.reason.find("--floor"), std::string::npos) << fit.reason;
  }
}

// Duplicate points, variance floor > 0: fits, and every variance is at least the floor.
TEST(GmmStability, DuplicatePointsRespectThePositiveVarianceFloor) {
  for (CovarianceForm form : kAllCovarianceForms) {
    for (GmmInit init : {GmmInit::KMeansPlusPlus, GmmInit::RandomFromData}) {
      GmmOptions o;
      o.components = 10;
      o.form = form;
      o.varianceFloor = 0.01;
      o.init = init;
      const GmmFit fit = fitGmm(onesAndZeros(), o);
      ASSERT_TRUE(fit.ok) << covarianceFormName(form) << ": " << fit.reason;
      EXPECT_GE(smallestVariance(fit.model), 0.01 * (1 - 1e-12)) << covarianceFormName(form);
      EXPECT_TRUE(std::isfinite(fit.logLikelihood));
    }
  }
}

// A feature constant within a class: its variance is the floor, the log-likelihood finite.
TEST(GmmStability, ConstantFeatureGetsTheFloorVariance) {
  Eigen::Vector3d mean(1.0, 7.0, -2.0), sd(1.0, 0.0, 2.0);
  const Eigen::MatrixXd x = gaussianRows(300, mean, sd, 5);
  ASSERT_EQ(x.col(1).minCoeff(), 7.0);
  const double floor = 0.05;
  for (CovarianceForm form : kAllCovarianceForms) {
    GmmOptions o;
    o.components = 2;
    o.form = form;
    o.varianceFloor = floor;
    const GmmFit fit = fitGmm(x, o);
    ASSERT_TRUE(fit.ok) << fit.reason;
    for (const auto& c : fit.model.covariances())
      EXPECT_NEAR(c(1, 1), floor, 1e-9 * floor) << covarianceFormName(form);
    EXPECT_TRUE(std::isfinite(fit.logLikelihood));
    EXPECT_TRUE(std::isfinite(fit.model.meanLogLikelihood(x)));
  }
  const auto g = fitGaussian(x, floor);
  ASSERT_TRUE(g.ok());
  EXPECT_NEAR(g->covariance(0)(1, 1), floor, 1e-9 * floor);
  EXPECT_TRUE(std::isfinite(g->meanLogLikelihood(x)));
}

// Two samples [[9999],[0]] with 2 components: variances equal the floor, and adding 1e6 to the
// data leaves them unchanged to 1e-9 relative.
TEST(GmmStability, OffsetDoesNotChangeFloorVariances) {
  const double floor = 1e-3;
  for (CovarianceForm form : {CovarianceForm::NodalDiag, CovarianceForm::NodalFull}) {
    GmmOptions o;
    o.components = 2;
    o.form = form;
    o.varianceFloor = floor;
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

// Catastrophic cancellation: two clusters of 20,000 points each, every feature offset by 1e8,
// spreads 1e-2 and 2e-2. E[x^2] - E[x]^2 loses every digit here (x^2 ~ 1e16 has an ulp of 2,
// the variances are ~1e-4); the fitted variances must equal the clusters' sample variances to
// 1e-9 relative in every covariance form.
TEST(GmmStability, CancellationAtLargeOffset) {
  const double offset = 1e8;
  const int perCluster = 20000;
  const Eigen::Vector2d m0(offset, offset), m1(offset + 1.0, offset - 1.0);
  const Eigen::Vector2d sd(1e-2, 2e-2);
  const std::vector<Eigen::MatrixXd> clusters{gaussianRows(perCluster, m0, sd, 31),
                                              gaussianRows(perCluster, m1, sd, 32)};
  const Eigen::MatrixXd x = stackRows(clusters);
  // Reference: biased (1/N) sample covariance of each cluster, two-pass in long double on the
  // stored values.
  std::vector<Eigen::Matrix2d> truth;
  for (const Eigen::MatrixXd& c : clusters) {
    long double mean[2] = {0.0L, 0.0L};
    for (Eigen::Index r = 0; r < c.rows(); ++r)
      for (int j = 0; j < 2; ++j)
        mean[j] += static_cast<long double>(c(r, j));
    for (long double& m : mean)
      m /= static_cast<long double>(c.rows());
    long double s[2][2] = {{0.0L, 0.0L}, {0.0L, 0.0L}};
    for (Eigen::Index r = 0; r < c.rows(); ++r)
      for (int j = 0; j < 2; ++j)
        for (int l = 0; l < 2; ++l)
          s[j][l] += (static_cast<long double>(c(r, j)) - mean[j]) *
                     (static_cast<long double>(c(r, l)) - mean[l]);
    Eigen::Matrix2d t;
    for (int j = 0; j < 2; ++j)
      for (int l = 0; l < 2; ++l)
        t(j, l) = static_cast<double>(s[j][l] / static_cast<long double>(c.rows()));
    truth.push_back(t);
  }
  // The data really exercise cancellation: the naive one-pass formula is wrong by more than the
  // variance itself.
  {
    const Eigen::VectorXd c = clusters[0].col(0);
    const double naive = c.array().square().mean() - c.mean() * c.mean();
    EXPECT_GT(std::abs(naive - truth[0](0, 0)), 0.5 * truth[0](0, 0)) << "naive " << naive;
  }
  const Eigen::Matrix2d pooled = 0.5 * (truth[0] + truth[1]);  // equal cluster sizes
  for (CovarianceForm form : kAllCovarianceForms) {
    GmmOptions o;
    o.components = 2;
    o.form = form;
    o.varianceFloor = 1e-12;
    const GmmFit fit = fitGmm(x, o);
    ASSERT_TRUE(fit.ok) << covarianceFormName(form) << ": " << fit.reason;
    ASSERT_EQ(fit.model.components(), 2) << covarianceFormName(form);
    for (int k = 0; k < 2; ++k) {
      // The component near m1 has the larger first coordinate.
      const int cluster = fit.model.means()(k, 0) > offset + 0.5 ? 1 : 0;
      EXPECT_NEAR(fit.model.weights()(k), 0.5, 1e-12);
      const Eigen::Matrix2d& want =
          isNodal(form) ? truth[static_cast<std::size_t>(cluster)] : pooled;
      const Eigen::MatrixXd& got = fit.model.covariance(k);
      for (int j = 0; j < 2; ++j)
        EXPECT_NEAR(got(j, j), want(j, j), 1e-9 * want(j, j))
            << covarianceFormName(form) << " component " << k << " feature " << j;
      if (!isDiagonal(form)) {
        EXPECT_NEAR(got(0, 1), want(0, 1), 1e-9 * std::sqrt(want(0, 0) * want(1, 1)))
            << covarianceFormName(form) << " component " << k;
      }
    }
  }
}

// Underflow: a point 1e3 standard deviations from every component.
TEST(GmmStability, FarPointHasFiniteLogLikelihoodAndADefinedClass) {
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

// 64 components on a class with 50 samples.
TEST(GmmStability, SixtyFourComponentsOnFiftySamples) {
  Eigen::Vector3d mean(0, 1, 2), sd(1, 2, 0.5);
  const Eigen::MatrixXd x = gaussianRows(50, mean, sd, 9);
  for (CovarianceForm form : kAllCovarianceForms) {
    for (GmmInit init : {GmmInit::KMeansPlusPlus, GmmInit::RandomFromData}) {
      GmmOptions o;
      o.components = 64;
      o.form = form;
      o.varianceFloor = 1e-3;
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

// Components that lose their mass are removed and counted: order 64 on data with 4 distinct
// points keeps 4 components and reports 60 dropped, in the fit and in the classifier.
TEST(GmmStability, DroppedComponentsAreCounted) {
  Eigen::MatrixXd x(40, 2);
  for (int r = 0; r < 40; ++r)
    x.row(r) << (r % 4) * 3.0, (r % 4 == 3 ? 5.0 : -1.0);
  for (CovarianceForm form : kAllCovarianceForms) {
    GmmOptions o;
    o.components = 64;
    o.form = form;
    o.varianceFloor = 1e-2;
    const GmmFit fit = fitGmm(x, o);
    ASSERT_TRUE(fit.ok) << covarianceFormName(form) << ": " << fit.reason;
    EXPECT_EQ(fit.model.components(), 4) << covarianceFormName(form);
    EXPECT_EQ(fit.droppedComponents, 60) << covarianceFormName(form);
  }
  ClassifierOptions c;
  c.gmm.components = 64;
  c.gmm.varianceFloor = 1e-2;
  const ClassifierFit fit = trainClassifier({x}, {"a"}, c);
  ASSERT_TRUE(fit.ok) << fit.reason;
  EXPECT_EQ(fit.model.model(0).components(), 4);
  EXPECT_EQ(fit.droppedComponents, std::vector<int>{60});
}

// Monotone EM: the log-likelihood of every E-step, of accepted and undone steps alike, is
// recorded in the trace and checked by the fit.
Eigen::MatrixXd threeBlobs() {
  Eigen::Vector2d m0(0, 0), m1(3, 1), m2(-2, 4), sd(1, 0.7);
  return stackRows(
      {gaussianRows(700, m0, sd, 1), gaussianRows(500, m1, sd, 2), gaussianRows(300, m2, sd, 3)});
}

GmmOptions tracedOptions(CovarianceForm form, Regularization reg, GmmInit init) {
  GmmOptions o;
  o.components = 5;
  o.form = form;
  o.reg = reg;
  o.varianceFloor = 1e-2;
  o.init = init;
  o.tolerance = 0.0;  // run until EM stops improving (or the limit)
  o.maxIterations = 200;
  o.maxReinitialisations = 0;
  o.keepTrace = true;
  return o;
}

double rounding(double l) {
  return 1e-12 * std::max(1.0, std::abs(l));
}

// With the floor clamp every M-step is the exact constrained maximiser: no E-step, of an accepted
// or an undone step, sees the log-likelihood fall by more than rounding (1e-12 relative).
TEST(GmmStability, MonotoneLikelihoodWithTheFloorClamp) {
  const Eigen::MatrixXd x = threeBlobs();
  for (CovarianceForm form : kAllCovarianceForms) {
    for (GmmInit init : {GmmInit::KMeansPlusPlus, GmmInit::RandomFromData}) {
      const GmmFit fit = fitGmm(x, tracedOptions(form, Regularization::Floor, init));
      ASSERT_TRUE(fit.ok) << fit.reason;
      ASSERT_EQ(fit.droppedComponents, 0);
      // One entry per E-step: iterations + 1 (the check of the last step), plus the returned
      // model's value again when that step was undone.
      ASSERT_GE(fit.trace.size(), static_cast<std::size_t>(fit.iterations) + 1);
      for (std::size_t t = 1; t < fit.trace.size(); ++t)
        EXPECT_GE(fit.trace[t], fit.trace[t - 1] - rounding(fit.trace[t - 1]))
            << covarianceFormName(form) << " step " << t;
      EXPECT_LE(fit.likelihoodDrop, rounding(fit.trace.back()));
      if (fit.undoneIteration > 0) {
        EXPECT_TRUE(fit.converged);
      }
      EXPECT_DOUBLE_EQ(fit.trace.back(), fit.meanLogLikelihood);
    }
  }
}

// With `add` (Sigma = S + eps I, scikit-learn's reg_covar) the M-step does not maximise the
// likelihood, and near its fixed point a step does lower it (here by up to ~1e-6 nats per
// sample). Such a fall is allowed only within the step's bound (docs/learning.md), only as the
// last, undone step, and is reported; every earlier step is monotone within rounding.
TEST(GmmStability, MonotoneLikelihoodWithAddUndoesOnlyTheLastBoundedFall) {
  const Eigen::MatrixXd x = threeBlobs();
  int beyondRounding = 0;
  for (CovarianceForm form : kAllCovarianceForms) {
    for (GmmInit init : {GmmInit::KMeansPlusPlus, GmmInit::RandomFromData}) {
      const GmmFit fit = fitGmm(x, tracedOptions(form, Regularization::Add, init));
      ASSERT_TRUE(fit.ok) << fit.reason;
      ASSERT_EQ(fit.droppedComponents, 0);
      const std::vector<double>& t = fit.trace;
      ASSERT_GE(t.size(), 3u);
      // Without an undone step the trace is monotone throughout; with one, its E-step is the
      // second-to-last entry and the last repeats the kept model's value.
      const std::size_t monotoneEnd = fit.undoneIteration > 0 ? t.size() - 2 : t.size();
      for (std::size_t i = 1; i < monotoneEnd; ++i)
        EXPECT_GE(t[i], t[i - 1] - rounding(t[i - 1])) << covarianceFormName(form) << " step " << i;
      if (fit.undoneIteration > 0) {
        const double before = t[t.size() - 3];
        const double fell = t[t.size() - 2];
        EXPECT_DOUBLE_EQ(fit.likelihoodDrop, before - fell);
        EXPECT_GT(fit.likelihoodDrop, 0.0);
        EXPECT_LT(fit.likelihoodDrop, 1e-4);
        EXPECT_EQ(t.back(), before);
        if (fit.likelihoodDrop > rounding(before)) ++beyondRounding;
      }
      EXPECT_DOUBLE_EQ(t.back(), fit.meanLogLikelihood);
      EXPECT_GT(t.back(), t.front());
    }
  }
  // The drift of `add` is real on this data (this is why it has its own bound).
  EXPECT_GT(beyondRounding, 0);
}

// A step that lowers the log-likelihood by more than rounding (and, for `add`, more than its
// bound) fails the fit with a reason naming the iteration and the fall; it is never reported as
// converged. The fall is injected by moving every mean after M-step 5.
TEST(GmmStability, LikelihoodFallFailsTheFit) {
  const Eigen::MatrixXd x = threeBlobs();
  for (Regularization reg : {Regularization::Floor, Regularization::Add}) {
    for (CovarianceForm form : kAllCovarianceForms) {
      GmmOptions o = tracedOptions(form, reg, GmmInit::KMeansPlusPlus);
      o.afterMStep = [](int iteration, Eigen::VectorXd&, Eigen::MatrixXd& means,
                        std::vector<Eigen::MatrixXd>&) {
        if (iteration == 5) means.array() += 3.0;
      };
      const GmmFit fit = fitGmm(x, o);
      EXPECT_FALSE(fit.ok) << covarianceFormName(form);
      EXPECT_FALSE(fit.converged);
      EXPECT_NE(fit.reason.find("log-likelihood fell by"), std::string::npos) << fit.reason;
      EXPECT_NE(fit.reason.find("iteration 6"), std::string::npos) << fit.reason;
    }
  }
}

// Ill-conditioned covariance: the log-density matches a long-double reference.
TEST(GmmStability, IllConditionedCovarianceMatchesLongDoubleReference) {
  Eigen::Matrix3d s;
  s << 32, 36, 8, 36, 40.5, 9, 8, 9, 2;
  s += 1e-8 * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d mu(1.0, -2.0, 0.5);
  auto m = GaussianMixture::create(Eigen::VectorXd::Ones(1), mu.transpose(), {s},
                                   CovarianceForm::NodalFull);
  ASSERT_TRUE(m.ok());
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

// Known answer.
TEST(GmmStability, KnownAnswerTwoComponentMixture) {
  Eigen::MatrixXd means(2, 2);
  means << 0, 0, 3, 3;
  Eigen::Matrix2d c1;
  c1 << 2, 1, 1, 2;
  auto m =
      GaussianMixture::create(Eigen::Vector2d(0.3, 0.7), means,
                              {Eigen::MatrixXd::Identity(2, 2), c1}, CovarianceForm::NodalFull);
  ASSERT_TRUE(m.ok());
  EXPECT_NEAR(std::exp(m->logDensity(Eigen::Vector2d(0, 0))), 0.05094887202, 1e-11);
  EXPECT_NEAR(std::exp(m->logDensity(Eigen::Vector2d(3, 3))), 0.06432759685, 1e-11);
}

// The best of 10 restarts never scores below a single start.
TEST(GmmStability, BestOfTenRestartsIsNeverWorseThanOne) {
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

// Scale: features x 1e6 and x 1e-6 (floor scaled by the square) classify as unscaled. Each
// class has two clusters and EM runs to a tight tolerance, so both fits reach the same optimum
// and only rounding separates them.
TEST(GmmStability, ScaledFeaturesClassifyTheSame) {
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
    o.gmm.varianceFloor = 1e-3;
    o.gmm.tolerance = 1e-13;
    o.gmm.rule = ConvergenceRule::Absolute;
    o.gmm.maxIterations = 1000;
    const ClassifierFit base = trainClassifier({a, b}, {"a", "b"}, o);
    ASSERT_TRUE(base.ok) << base.reason;
    const std::vector<int> expected = base.model.predict(test);
    for (double scale : {1e6, 1e-6}) {
      ClassifierOptions s = o;
      s.gmm.varianceFloor = o.gmm.varianceFloor * scale * scale;
      const ClassifierFit fit = trainClassifier({a * scale, b * scale}, {"a", "b"}, s);
      ASSERT_TRUE(fit.ok) << fit.reason;
      EXPECT_EQ(fit.model.predict(test * scale), expected)
          << classifierMethodName(method) << " scale " << scale;
    }
  }
}

// Fewer samples than dimensions in a class: a clear error.
TEST(GmmStability, FewerSamplesThanDimensionsIsAClearError) {
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

// Fewer samples than dimensions with fewSamples (the scikit-learn estimators): fitted when the
// variance floor holds the covariance up, every log-likelihood finite; a clear error without a
// floor. Classes with enough samples get the model they get without the option.
TEST(GmmStability, FewSamplesFitsOnTheFloorAlone) {
  const Eigen::MatrixXd big =
      gaussianRows(50, Eigen::VectorXd::Zero(5), Eigen::VectorXd::Ones(5), 1);
  const Eigen::MatrixXd test =
      gaussianRows(40, Eigen::VectorXd::Constant(5, 0.5), Eigen::VectorXd::Ones(5), 3);
  for (const Eigen::Index smallRows : {1, 2, 3}) {
    const Eigen::MatrixXd small =
        gaussianRows(smallRows, Eigen::VectorXd::Ones(5), Eigen::VectorXd::Ones(5), 2);
    for (ClassifierMethod method : {ClassifierMethod::Gmm, ClassifierMethod::Gaussian}) {
      SCOPED_TRACE(std::string(classifierMethodName(method)) + ", " + std::to_string(smallRows) +
                   " rows");
      ClassifierOptions o;
      o.method = method;
      o.oneVsRest = false;
      o.fewSamples = true;
      const ClassifierFit fit = trainClassifier({big, small}, {"Wall", "Corner"}, o);
      if (method == ClassifierMethod::Gaussian && smallRows < 2) {
        // One sample has no unbiased covariance: still an error.
        EXPECT_FALSE(fit.ok);
        EXPECT_NE(fit.reason.find("at least 2 samples"), std::string::npos) << fit.reason;
        continue;
      }
      ASSERT_TRUE(fit.ok) << fit.reason;
      Eigen::MatrixXd logLik;
      fit.model.logLikelihoods(test, logLik);
      EXPECT_TRUE(logLik.allFinite());
      // The few samples are where their class is most likely.
      Eigen::MatrixXd atSmall;
      fit.model.logLikelihoods(small, atSmall);
      for (Eigen::Index r = 0; r < small.rows(); ++r)
        EXPECT_GT(atSmall(r, 1), atSmall(r, 0));
      // The big class's model is the one fitted without the option.
      ClassifierOptions plain = o;
      plain.fewSamples = false;
      const ClassifierFit alone = trainClassifier({big, big}, {"Wall", "Wall2"}, plain);
      ASSERT_TRUE(alone.ok) << alone.reason;
      Eigen::MatrixXd fromAlone;
      alone.model.logLikelihoods(test, fromAlone);
      EXPECT_TRUE(fromAlone.col(0) == logLik.col(0));

      o.gmm.varianceFloor = 0.0;
      const ClassifierFit noFloor = trainClassifier({big, small}, {"Wall", "Corner"}, o);
      EXPECT_FALSE(noFloor.ok);
      EXPECT_NE(noFloor.reason.find("'Corner'"), std::string::npos) << noFloor.reason;
      EXPECT_NE(noFloor.reason.find("variance floor"), std::string::npos) << noFloor.reason;
    }
  }
}

// A class with zero samples: a clear error.
TEST(GmmStability, ClassWithoutSamplesIsAClearError) {
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

// A variance floor 100 or more times a feature's whole variance (here 1e10 times: feature 1 is on
// the 1e-6 scale) is reported, naming the feature and its scale, instead of silently deciding one
// class. Features on the floor's own scale give no warning.
TEST(GmmStability, VarianceFloorFarAboveAFeatureVarianceWarns) {
  const Eigen::Vector2d m0(0.0, 0.0), m1(3.0, 5e-6), sd(1.0, 1e-6);
  const Eigen::MatrixXd a = gaussianRows(300, m0, sd, 41);
  const Eigen::MatrixXd b = gaussianRows(300, m1, sd, 42);
  for (ClassifierMethod method : {ClassifierMethod::Gmm, ClassifierMethod::Gaussian}) {
    ClassifierOptions o;
    o.method = method;
    o.gmm.components = 2;
    o.gmm.varianceFloor = 0.01;
    o.featureNames = {"f0", "f1"};
    const ClassifierFit fit = trainClassifier({a, b}, {"a", "b"}, o);
    ASSERT_TRUE(fit.ok) << fit.reason;
    ASSERT_EQ(fit.warnings.size(), 1u) << classifierMethodName(method);
    const std::string& w = fit.warnings[0];
    EXPECT_NE(w.find("variance floor 0.01"), std::string::npos) << w;
    EXPECT_NE(w.find("feature 1 (f1)"), std::string::npos) << w;
    EXPECT_NE(w.find("standard deviation 2."), std::string::npos) << w;  // ~2.5e-06 pooled
    o.gmm.varianceFloor = 1e-14;
    EXPECT_TRUE(trainClassifier({a, b}, {"a", "b"}, o).warnings.empty());
  }
  GmmOptions g;
  g.varianceFloor = 0.01;
  const GmmFit fit = fitGmm(a, g);
  ASSERT_TRUE(fit.ok) << fit.reason;
  ASSERT_EQ(fit.warnings.size(), 1u);
  EXPECT_NE(fit.warnings[0].find("feature 1 "), std::string::npos) << fit.warnings[0];
}

}  // namespace
}  // namespace tactile::analysis
