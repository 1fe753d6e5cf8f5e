// GCC 12 reports false -Wmaybe-uninitialized inside Eigen's AVX-512 kernels at -O3.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "analysis/gmm.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "tests/analysis/gmm_test_util.h"

namespace tactile::analysis {
namespace {

using testing::gaussianRows;
using testing::stackRows;

Eigen::MatrixXd twoBlobs(int perBlob, std::uint64_t seed) {
  Eigen::VectorXd m0(2), m1(2), sd(2);
  m0 << 0, 0;
  m1 << 10, 5;
  sd << 1, 0.5;
  return stackRows(
      {gaussianRows(perBlob, m0, sd, seed), gaussianRows(3 * perBlob, m1, sd, seed + 1)});
}

TEST(GmmNames, EveryNameRoundTrips) {
  for (CovarianceForm f : kAllCovarianceForms)
    EXPECT_EQ(parseCovarianceForm(covarianceFormName(f)), f);
  EXPECT_EQ(covarianceFormName(CovarianceForm::NodalDiag), "nodal-diag");
  EXPECT_EQ(parseRegularization("add"), Regularization::Add);
  EXPECT_EQ(parseGmmInit("kmeans++"), GmmInit::KMeansPlusPlus);
  EXPECT_EQ(parseGmmInit("random-from-data"), GmmInit::RandomFromData);
  EXPECT_FALSE(parseCovarianceForm("full").has_value());
  EXPECT_EQ(parseConvergenceRule("absolute"), ConvergenceRule::Absolute);
}

// The floor warnings over several tables' rows read in place (trainClassifier's check over every
// class) say what they say over the same rows copied into one table: the variance pooled over all
// parts, not any one part's.
TEST(VarianceFloorWarnings, OverPartsEqualOverTheirRowsTogether) {
  const Eigen::Vector3d sd(1.0, 1e-6, 2e-4);
  const Eigen::MatrixXd a = gaussianRows(300, Eigen::Vector3d(0.0, 0.0, 0.0), sd, 7);
  const Eigen::MatrixXd b = gaussianRows(200, Eigen::Vector3d(1.0, 4e-6, 0.0), sd, 8);
  const Eigen::MatrixXd c = gaussianRows(1, Eigen::Vector3d(0.5, 2e-6, 1e-4), sd, 9);
  const Eigen::MatrixXd none(0, 3);
  Eigen::MatrixXd all(a.rows() + b.rows() + c.rows(), 3);
  all << a, b, c;
  const std::vector<std::string> names = {"f0", "f1", "f2"};
  const std::vector<std::string> together = varianceFloorWarnings(all, 0.01, names);
  // Features 1 and 2 are far below the floor; 0 is not.
  ASSERT_EQ(together.size(), 2u);
  EXPECT_NE(together[0].find("feature 1 (f1)"), std::string::npos) << together[0];
  EXPECT_NE(together[1].find("feature 2 (f2)"), std::string::npos) << together[1];
  const std::vector<Eigen::MatrixXd> parts = {a, none, b, c};
  EXPECT_EQ(varianceFloorWarnings(parts, 0.01, names), together);
  // Within a part, feature 1 varies 1e-6; between the parts 4e-6: the pooled figure is reported.
  EXPECT_NE(varianceFloorWarnings(std::vector<Eigen::MatrixXd>{a}, 0.01, names)[0], together[0]);
  EXPECT_TRUE(varianceFloorWarnings(std::vector<Eigen::MatrixXd>{c, none}, 0.01).empty());
  EXPECT_TRUE(varianceFloorWarnings(std::span<const Eigen::MatrixXd>(), 0.01).empty());
}

TEST(GaussianMixtureCreate, RejectsWeightsNotSummingToOne) {
  auto m = GaussianMixture::create(Eigen::Vector2d(0.5, 0.6), Eigen::MatrixXd::Zero(2, 1),
                                   {Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Ones(1, 1)},
                                   CovarianceForm::NodalDiag);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.error().message.find("sum"), std::string::npos);
}

TEST(GaussianMixtureCreate, RejectsAsymmetricAndIndefiniteCovariances) {
  Eigen::MatrixXd asym(2, 2);
  asym << 1, 0.5, 0.4, 1;
  EXPECT_NE(GaussianMixture::create(Eigen::VectorXd::Ones(1), Eigen::MatrixXd::Zero(1, 2), {asym},
                                    CovarianceForm::NodalFull)
                .errorText()
                .find("symmetric"),
            std::string::npos);
  Eigen::MatrixXd indef(2, 2);
  indef << 1, 2, 2, 1;
  EXPECT_NE(GaussianMixture::create(Eigen::VectorXd::Ones(1), Eigen::MatrixXd::Zero(1, 2), {indef},
                                    CovarianceForm::NodalFull)
                .errorText()
                .find("positive definite"),
            std::string::npos);
}

TEST(GaussianMixtureCreate, RejectsWrongShapesAndOffDiagonalsInDiagonalForms) {
  Eigen::MatrixXd full(2, 2);
  full << 1, 0.1, 0.1, 1;
  const auto offDiagonal = GaussianMixture::create(
      Eigen::VectorXd::Ones(1), Eigen::MatrixXd::Zero(1, 2), {full}, CovarianceForm::NodalDiag);
  ASSERT_FALSE(offDiagonal.ok());
  EXPECT_NE(offDiagonal.error().message.find("off-diagonal"), std::string::npos);
  const auto shape = GaussianMixture::create(Eigen::VectorXd::Ones(1), Eigen::MatrixXd::Zero(1, 3),
                                             {full}, CovarianceForm::NodalFull);
  ASSERT_FALSE(shape.ok());
  EXPECT_NE(shape.error().message.find("expected 3x3"), std::string::npos);
  EXPECT_FALSE(GaussianMixture::create(Eigen::Vector2d(0.5, 0.5), Eigen::MatrixXd::Zero(2, 2),
                                       {full}, CovarianceForm::NodalFull)
                   .ok());
}

TEST(GaussianMixture, BatchedDensitiesMatchSingleRowDensities) {
  const Eigen::MatrixXd x = twoBlobs(300, 5);
  GmmOptions o;
  o.components = 3;
  o.form = CovarianceForm::NodalFull;
  const GmmFit fit = fitGmm(x, o);
  ASSERT_TRUE(fit.ok) << fit.reason;
  Eigen::VectorXd batch;
  fit.model.logDensities(x, batch);
  for (int r = 0; r < x.rows(); r += 37) {
    // Independent reference: per-component Cholesky density and log-sum-exp.
    std::vector<double> terms;
    for (int k = 0; k < fit.model.components(); ++k) {
      Eigen::MatrixXd l;
      ASSERT_TRUE(choleskyLower(fit.model.covariance(k), l));
      terms.push_back(std::log(fit.model.weights()(k)) +
                      gaussianLogDensity(x.row(r).transpose(), fit.model.means().row(k).transpose(),
                                         l, logDeterminantFromCholesky(l)));
    }
    const double reference = logSumExp(terms.data(), static_cast<int>(terms.size()));
    EXPECT_NEAR(batch(r), reference, 1e-10 * std::abs(reference) + 1e-12);
    EXPECT_EQ(fit.model.logDensity(x.row(r).transpose()), batch(r));
  }
}

TEST(FitGmm, RecoversTwoSeparatedComponents) {
  const Eigen::MatrixXd x = twoBlobs(2000, 11);
  for (CovarianceForm form : kAllCovarianceForms) {
    GmmOptions o;
    o.components = 2;
    o.form = form;
    o.varianceFloor = 1e-6;
    const GmmFit fit = fitGmm(x, o);
    ASSERT_TRUE(fit.ok) << fit.reason;
    EXPECT_TRUE(fit.converged);
    const int big = fit.model.weights()(0) > fit.model.weights()(1) ? 0 : 1;
    EXPECT_NEAR(fit.model.weights()(big), 0.75, 0.01);
    EXPECT_NEAR(fit.model.means()(big, 0), 10.0, 0.05);
    EXPECT_NEAR(fit.model.means()(1 - big, 1), 0.0, 0.05);
    EXPECT_NEAR(fit.model.covariance(big)(0, 0), 1.0, 0.1) << covarianceFormName(form);
    EXPECT_NEAR(fit.model.covariance(big)(1, 1), 0.25, 0.03) << covarianceFormName(form);
  }
}

TEST(FitGmm, GrandFormsShareOneCovariance) {
  const Eigen::MatrixXd x = twoBlobs(500, 2);
  GmmOptions o;
  o.components = 4;
  o.form = CovarianceForm::GrandFull;
  const GmmFit fit = fitGmm(x, o);
  ASSERT_TRUE(fit.ok) << fit.reason;
  EXPECT_EQ(fit.model.covariances().size(), 1u);
  EXPECT_EQ(&fit.model.covariance(0), &fit.model.covariance(fit.model.components() - 1));
}

TEST(FitGmm, ResultsDoNotDependOnTheThreadCount) {
  const Eigen::MatrixXd x = twoBlobs(3000, 21);  // 12000 rows: several chunks
  for (CovarianceForm form : {CovarianceForm::NodalFull, CovarianceForm::NodalDiag}) {
    GmmOptions o;
    o.components = 5;
    o.form = form;
    o.threads = 1;
    const GmmFit one = fitGmm(x, o);
    o.threads = 2;
    const GmmFit two = fitGmm(x, o);
    ASSERT_TRUE(one.ok && two.ok);
    EXPECT_EQ(one.iterations, two.iterations);
    EXPECT_EQ(one.logLikelihood, two.logLikelihood);
    EXPECT_TRUE(one.model.means() == two.model.means());
    EXPECT_TRUE(one.model.weights() == two.model.weights());
  }
}

TEST(FitGmm, SameSeedSameModelOtherSeedOtherStart) {
  const Eigen::MatrixXd x = twoBlobs(400, 4);
  GmmOptions o;
  o.components = 6;
  o.init = GmmInit::RandomFromData;
  const GmmFit a = fitGmm(x, o);
  const GmmFit b = fitGmm(x, o);
  o.seed = 99;
  const GmmFit c = fitGmm(x, o);
  ASSERT_TRUE(a.ok && b.ok && c.ok);
  EXPECT_TRUE(a.model.means() == b.model.means());
  EXPECT_FALSE(a.model.means() == c.model.means());
}

TEST(FitGmm, InformationCriteriaFollowTheirFormulas) {
  const Eigen::MatrixXd x = twoBlobs(500, 8);
  GmmOptions o;
  o.components = 2;
  o.form = CovarianceForm::NodalFull;
  const GmmFit fit = fitGmm(x, o);
  ASSERT_TRUE(fit.ok);
  const int p = fit.model.parameterCount();
  EXPECT_EQ(p, 1 + 2 * 2 + 2 * 3);
  EXPECT_NEAR(fit.bic, -2 * fit.logLikelihood + p * std::log(2000.0), 1e-9);
  EXPECT_NEAR(fit.aic, -2 * fit.logLikelihood + 2 * p, 1e-9);
  EXPECT_NEAR(fit.model.meanLogLikelihood(x), fit.meanLogLikelihood, 1e-9);
}

TEST(FitGmm, NonFiniteSamplesAreAnError) {
  Eigen::MatrixXd x = twoBlobs(50, 1);
  x(3, 1) = std::nan("");
  GmmOptions o;
  const GmmFit fit = fitGmm(x, o);
  EXPECT_FALSE(fit.ok);
  EXPECT_NE(fit.reason.find("non-finite"), std::string::npos);
}

TEST(FitGmm, ProgressCanCancel) {
  const Eigen::MatrixXd x = twoBlobs(500, 3);
  GmmOptions o;
  o.components = 4;
  o.tolerance = 0;  // never converges by tolerance
  int calls = 0;
  const GmmFit fit = fitGmm(x, o, [&](std::size_t done, std::size_t total) {
    ++calls;
    EXPECT_LE(done, total);
    return done < 3;
  });
  EXPECT_FALSE(fit.ok);
  EXPECT_EQ(fit.reason, "cancelled");
  EXPECT_EQ(calls, 3);
}

TEST(FitGmm, ComponentsWithoutSamplesAreDroppedAndWeightsRenormalised) {
  Eigen::MatrixXd x(6, 1);
  x << 0, 0, 0, 5, 5, 5;
  GmmOptions o;
  o.components = 4;
  o.varianceFloor = 0.01;
  const GmmFit fit = fitGmm(x, o);
  ASSERT_TRUE(fit.ok) << fit.reason;
  EXPECT_EQ(fit.model.components() + fit.droppedComponents, 4);
  EXPECT_NEAR(fit.model.weights().sum(), 1.0, 1e-12);
}

TEST(FitGmm, RandomFromDataReinitialisesWhenNotConverged) {
  const Eigen::MatrixXd x = twoBlobs(300, 6);
  GmmOptions o;
  o.components = 8;
  o.init = GmmInit::RandomFromData;
  o.maxIterations = 2;
  o.tolerance = 0;  // cannot converge: every re-initialisation is used
  o.maxReinitialisations = 3;
  const GmmFit fit = fitGmm(x, o);
  ASSERT_TRUE(fit.ok);
  EXPECT_FALSE(fit.converged);
  EXPECT_EQ(fit.totalIterations, 2 * 4);
}

}  // namespace
}  // namespace tactile::analysis
