// GCC 12 reports false -Wmaybe-uninitialized inside Eigen's AVX-512 kernels at -O3.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "analysis/classifier.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "tests/analysis/gmm_test_util.h"

namespace tactile::analysis {
namespace {

using testing::gaussianRows;
using testing::stackRows;

TEST(ClassifierNames, RoundTrip) {
  EXPECT_EQ(parseClassifierMethod(classifierMethodName(ClassifierMethod::Gaussian)),
            ClassifierMethod::Gaussian);
  EXPECT_EQ(parseClassifierMethod("gmm"), ClassifierMethod::Gmm);
  EXPECT_EQ(parsePriorMode("empirical"), PriorMode::Empirical);
  EXPECT_FALSE(parseClassifierMethod("svm").has_value());
}

TEST(FitGaussian, UsesTheUnbiasedCovariance) {
  Eigen::MatrixXd x(4, 2);
  x << 1, 2, 3, 1, 0, 0, 4, 5;
  const auto g = fitGaussian(x, 0.0);
  ASSERT_TRUE(g.ok());
  const Eigen::RowVectorXd mean = x.colwise().mean();
  const Eigen::MatrixXd c = x.rowwise() - mean;
  const Eigen::MatrixXd unbiased = c.transpose() * c / 3.0;
  EXPECT_LT((g->covariance(0) - unbiased).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((g->means().row(0) - mean).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(FitGaussian, SingularCovarianceWithoutFloorIsAnError) {
  Eigen::MatrixXd x(4, 2);
  x << 1, 2, 2, 4, 3, 6, 4, 8;  // second feature = 2 x first
  const auto singular = fitGaussian(x, 0.0, Regularization::Floor);
  ASSERT_FALSE(singular.ok());
  EXPECT_NE(singular.error().message.find("singular"), std::string::npos);
  EXPECT_TRUE(fitGaussian(x, 1e-3, Regularization::Floor).ok());
}

TEST(GaussianClassifier, OneVsRestRatioIsTheLogLikelihoodDifference) {
  Eigen::Vector2d m0(0, 0), m1(3, 0), m2(0, 3), sd(1, 1);
  const std::vector<Eigen::MatrixXd> data{
      gaussianRows(200, m0, sd, 1), gaussianRows(200, m1, sd, 2), gaussianRows(200, m2, sd, 3)};
  ClassifierOptions o;
  o.method = ClassifierMethod::Gaussian;
  const ClassifierFit fit = trainClassifier(data, {"Wall", "Corner", "LW"}, o);
  ASSERT_TRUE(fit.ok) << fit.reason;
  ASSERT_TRUE(fit.model.hasRestModels());
  // The rest model of class 0 is the unbiased Gaussian of classes 1 and 2 together.
  const auto rest = fitGaussian(stackRows({data[1], data[2]}), 0.0);
  ASSERT_TRUE(rest.ok());
  EXPECT_LT((fit.model.restModel(0).covariance(0) - rest->covariance(0)).cwiseAbs().maxCoeff(),
            1e-12);
  Eigen::VectorXd l;
  fit.model.oneVsRestLogRatio(data[0], 0, l);
  int positive = 0;
  for (int r = 0; r < l.size(); ++r) {
    const double expected = fit.model.model(0).logDensity(data[0].row(r).transpose()) -
                            rest->logDensity(data[0].row(r).transpose());
    EXPECT_NEAR(l(r), expected, 1e-9);
    positive += l(r) > 0;
  }
  EXPECT_GT(positive, 160);  // most of class 0 is called class 0
}

TEST(GmmClassifier, SeparatesSeparableClasses) {
  Eigen::Vector2d m0(0, 0), m1(10, 0), sd(1, 1);
  const std::vector<Eigen::MatrixXd> data{gaussianRows(300, m0, sd, 1),
                                          gaussianRows(300, m1, sd, 2)};
  ClassifierOptions o;
  o.gmm.components = 2;
  const ClassifierFit fit = trainClassifier(data, {"a", "b"}, o);
  ASSERT_TRUE(fit.ok) << fit.reason;
  EXPECT_EQ(fit.iterations.size(), 2u);
  EXPECT_EQ(fit.converged.size(), 2u);
  for (int c = 0; c < 2; ++c) {
    const std::vector<int> p = fit.model.predict(data[static_cast<std::size_t>(c)]);
    for (int v : p)
      EXPECT_EQ(v, c);
  }
}

TEST(GmmClassifier, EmpiricalPriorsShiftTheDecision) {
  Eigen::VectorXd m0(1), m1(1), sd(1);
  m0 << 0;
  m1 << 1;
  sd << 1;
  const std::vector<Eigen::MatrixXd> data{gaussianRows(900, m0, sd, 1),
                                          gaussianRows(100, m1, sd, 2)};
  ClassifierOptions o;
  o.gmm.components = 1;
  const ClassifierFit equal = trainClassifier(data, {"a", "b"}, o);
  o.priors = PriorMode::Empirical;
  const ClassifierFit empirical = trainClassifier(data, {"a", "b"}, o);
  ASSERT_TRUE(equal.ok && empirical.ok);
  EXPECT_NEAR(std::exp(empirical.model.logPriors()(0)), 0.9, 1e-12);
  Eigen::MatrixXd probe(1, 1);
  probe << 0.8;  // closer to class b's mean, but class a is 9x more common
  EXPECT_EQ(equal.model.predict(probe)[0], 1);
  EXPECT_EQ(empirical.model.predict(probe)[0], 0);
}

TEST(ClassModelSet, TiesGoToTheLowestClass) {
  auto g = GaussianMixture::create(Eigen::VectorXd::Ones(1), Eigen::MatrixXd::Zero(1, 1),
                                   {Eigen::MatrixXd::Ones(1, 1)}, CovarianceForm::NodalFull);
  ASSERT_TRUE(g.ok());
  auto set = ClassModelSet::create(ClassifierMethod::Gmm, {"x", "y"}, {g.value(), g.value()});
  ASSERT_TRUE(set.ok());
  EXPECT_EQ(set->predict(Eigen::MatrixXd::Zero(3, 1)), (std::vector<int>{0, 0, 0}));
}

TEST(ClassModelSet, CreateRejectsMismatches) {
  auto g1 = GaussianMixture::create(Eigen::VectorXd::Ones(1), Eigen::MatrixXd::Zero(1, 1),
                                    {Eigen::MatrixXd::Ones(1, 1)}, CovarianceForm::NodalFull);
  auto g2 = GaussianMixture::create(Eigen::VectorXd::Ones(1), Eigen::MatrixXd::Zero(1, 2),
                                    {Eigen::MatrixXd::Identity(2, 2)}, CovarianceForm::NodalFull);
  ASSERT_TRUE(g1 && g2);
  const auto dims =
      ClassModelSet::create(ClassifierMethod::Gmm, {"x", "y"}, {g1.value(), g2.value()});
  ASSERT_FALSE(dims.ok());
  EXPECT_NE(dims.error().message.find("dimension"), std::string::npos);
  EXPECT_FALSE(ClassModelSet::create(ClassifierMethod::Gmm, {"x"}, {g1.value(), g1.value()}).ok());
  const auto priors =
      ClassModelSet::create(ClassifierMethod::Gmm, {"x", "y"}, {g1.value(), g1.value()},
                            Eigen::Vector2d(std::log(0.5), std::log(0.6)));
  ASSERT_FALSE(priors.ok());
  EXPECT_NE(priors.error().message.find("priors"), std::string::npos);
}

TEST(GmmClassifier, ResultsDoNotDependOnTheThreadCount) {
  Eigen::Vector2d m0(0, 0), m1(2, 1), sd(1, 1);
  const std::vector<Eigen::MatrixXd> data{gaussianRows(5000, m0, sd, 1),
                                          gaussianRows(3000, m1, sd, 2)};
  ClassifierOptions o;
  o.gmm.components = 4;
  o.gmm.form = CovarianceForm::NodalFull;
  o.threads = 1;
  const ClassifierFit one = trainClassifier(data, {"a", "b"}, o);
  o.threads = 2;
  const ClassifierFit two = trainClassifier(data, {"a", "b"}, o);
  ASSERT_TRUE(one.ok && two.ok);
  for (int c = 0; c < 2; ++c) {
    EXPECT_TRUE(one.model.model(c).means() == two.model.model(c).means());
    EXPECT_TRUE(one.model.model(c).covariances() == two.model.model(c).covariances());
  }
}

TEST(GmmClassifier, ProgressCanCancel) {
  Eigen::Vector2d m0(0, 0), sd(1, 1);
  const std::vector<Eigen::MatrixXd> data{
      gaussianRows(100, m0, sd, 1), gaussianRows(100, m0, sd, 2), gaussianRows(100, m0, sd, 3)};
  ClassifierOptions o;
  o.threads = 1;
  const ClassifierFit fit = trainClassifier(data, {"a", "b", "c"}, o,
                                            [](std::size_t done, std::size_t) { return done < 1; });
  EXPECT_FALSE(fit.ok);
  EXPECT_EQ(fit.reason, "cancelled");
}

// A cancel returned from inside a running fit (progress is consulted after every EM iteration)
// stops that fit at once.
TEST(GmmClassifier, ProgressIsConsultedEveryIteration) {
  Eigen::Vector2d m0(0, 0), sd(1, 1);
  const std::vector<Eigen::MatrixXd> data{gaussianRows(400, m0, sd, 1)};
  ClassifierOptions o;
  o.threads = 1;
  o.gmm.components = 4;
  o.gmm.tolerance = 0.0;
  o.gmm.maxIterations = 500;
  int calls = 0;
  const ClassifierFit fit = trainClassifier(data, {"a"}, o, [&](std::size_t done, std::size_t) {
    EXPECT_EQ(done, 0u);  // the only class never finishes
    return ++calls < 3;
  });
  EXPECT_FALSE(fit.ok);
  EXPECT_EQ(fit.reason, "cancelled");
  EXPECT_EQ(calls, 3);
}

// --reg add reaches the Gaussian method: Sigma + floor * I instead of the eigenvalue clamp, for
// the class models and the one-vs-rest models alike.
TEST(GaussianClassifier, HonoursAddRegularization) {
  Eigen::Vector2d m0(0, 0), m1(3, 0), sd(1, 0.5);
  const std::vector<Eigen::MatrixXd> data{gaussianRows(200, m0, sd, 1),
                                          gaussianRows(200, m1, sd, 2)};
  const double floor = 0.5;
  const auto unbiased = [](const Eigen::MatrixXd& x) {
    const Eigen::MatrixXd c = x.rowwise() - x.colwise().mean();
    return Eigen::MatrixXd(c.transpose() * c / static_cast<double>(x.rows() - 1));
  };
  const auto add = fitGaussian(data[0], floor, Regularization::Add);
  ASSERT_TRUE(add.ok());
  const Eigen::MatrixXd want = unbiased(data[0]) + floor * Eigen::MatrixXd::Identity(2, 2);
  EXPECT_LT((add->covariance(0) - want).cwiseAbs().maxCoeff(), 1e-14);
  ClassifierOptions o;
  o.method = ClassifierMethod::Gaussian;
  o.gmm.varianceFloor = floor;
  o.gmm.reg = Regularization::Add;
  const ClassifierFit fit = trainClassifier(data, {"a", "b"}, o);
  ASSERT_TRUE(fit.ok) << fit.reason;
  for (int c = 0; c < 2; ++c) {
    const Eigen::MatrixXd w =
        unbiased(data[static_cast<std::size_t>(c)]) + floor * Eigen::MatrixXd::Identity(2, 2);
    EXPECT_LT((fit.model.model(c).covariance(0) - w).cwiseAbs().maxCoeff(), 1e-14) << c;
    const Eigen::MatrixXd r =
        unbiased(data[static_cast<std::size_t>(1 - c)]) + floor * Eigen::MatrixXd::Identity(2, 2);
    EXPECT_LT((fit.model.restModel(c).covariance(0) - r).cwiseAbs().maxCoeff(), 1e-14) << c;
  }
  // The clamp leaves eigenvalues above the floor alone: a different model.
  o.gmm.reg = Regularization::Floor;
  const ClassifierFit clamp = trainClassifier(data, {"a", "b"}, o);
  ASSERT_TRUE(clamp.ok);
  EXPECT_GT((clamp.model.model(0).covariance(0) - fit.model.model(0).covariance(0)).norm(), 0.1);
}

// One definition of the held-out mean log-likelihood: mean over finite rows, -inf rows counted,
// rows without a model skipped.
TEST(HeldOutLogLikelihood, MeanOverFiniteRowsAndNegInfRowsCounted) {
  const double inf = std::numeric_limits<double>::infinity();
  Eigen::MatrixXd ll(5, 2);
  ll << -1.0, -7.0,  //
      -inf, -2.0,    //
      -3.0, -inf,    //
      -5.0, -4.0,    //
      -inf, -inf;
  const HeldOutLogLikelihood h = heldOutLogLikelihood(ll, {0, 0, 1, 1, -1});
  ASSERT_TRUE(h.mean.has_value());
  EXPECT_DOUBLE_EQ(*h.mean, (-1.0 - 4.0) / 2.0);
  EXPECT_EQ(h.rows, 2u);
  EXPECT_EQ(h.negInfRows, 2u);
  const HeldOutLogLikelihood none = heldOutLogLikelihood(ll, {-1, 0, 1, -1, 0});
  EXPECT_FALSE(none.mean.has_value());
  EXPECT_EQ(none.rows, 0u);
  EXPECT_EQ(none.negInfRows, 3u);
}

// A test row far beyond double range of a model's Mahalanobis distance has log-likelihood -inf:
// counted, not averaged.
TEST(HeldOutLogLikelihood, RowWithZeroDensityIsCounted) {
  Eigen::Vector2d m0(0, 0), sd(1, 1);
  const std::vector<Eigen::MatrixXd> data{gaussianRows(200, m0, sd, 1)};
  ClassifierOptions o;
  o.gmm.components = 2;
  const ClassifierFit fit = trainClassifier(data, {"a"}, o);
  ASSERT_TRUE(fit.ok) << fit.reason;
  Eigen::MatrixXd test(3, 2);
  test << 0.1, 0.2, 1e200, 0.0, -0.3, 0.4;
  Eigen::MatrixXd ll;
  fit.model.logLikelihoods(test, ll);
  EXPECT_EQ(ll(1, 0), -std::numeric_limits<double>::infinity());
  const HeldOutLogLikelihood h = heldOutLogLikelihood(ll, {0, 0, 0});
  EXPECT_EQ(h.negInfRows, 1u);
  ASSERT_TRUE(h.mean.has_value());
  EXPECT_DOUBLE_EQ(*h.mean, 0.5 * (ll(0, 0) + ll(2, 0)));
}

}  // namespace
}  // namespace tactile::analysis
