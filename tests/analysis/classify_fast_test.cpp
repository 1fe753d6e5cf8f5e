// The fast classification path against straightforward references: the blocked full-covariance
// density kernel against the textbook formula, the forward filter over raw arrays against the
// plain log-space filter, and classifyRun against evaluating every step on its own (features with
// the context walked back from each step, one row at a time through the classifier).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "analysis/classify_run.h"
#include "analysis/gaussian_mixture.h"
#include "analysis/gmm_kernels.h"
#include "analysis/temporal.h"
#include "analysis/training.h"
#include "tests/analysis/learn_test_data.h"

namespace tactile::analysis {
namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

// log p(x) of a mixture by the formula, every component on its own (Cholesky of each covariance,
// no shared frame, no blocking).
double referenceLogDensity(const GaussianMixture& m, const Eigen::VectorXd& x) {
  const int d = m.dimension();
  std::vector<double> terms;
  for (int i = 0; i < m.components(); ++i) {
    const Eigen::LLT<Eigen::MatrixXd> llt(m.covariance(i));
    const Eigen::VectorXd diff = x - m.means().row(i).transpose();
    const Eigen::VectorXd y = llt.matrixL().solve(diff);
    const double logDet = 2.0 * llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
    terms.push_back(std::log(m.weights()(i)) - 0.5 * d * std::log(2.0 * M_PI) - 0.5 * logDet -
                    0.5 * y.squaredNorm());
  }
  double top = kNegInf;
  for (double t : terms)
    top = std::max(top, t);
  double sum = 0.0;
  for (double t : terms)
    sum += std::exp(t - top);
  return top + std::log(sum);
}

GaussianMixture randomMixture(int d, int k, std::mt19937_64& rng, bool floorHit) {
  std::normal_distribution<double> normal;
  Eigen::VectorXd w(k);
  for (int i = 0; i < k; ++i)
    w(i) = 1.0 + i;
  w /= w.sum();
  Eigen::MatrixXd means(k, d);
  for (Eigen::Index i = 0; i < means.size(); ++i)
    means.data()[i] = 5.0 + normal(rng);  // a common offset: the kernel's centred frame
  std::vector<Eigen::MatrixXd> covs;
  for (int i = 0; i < k; ++i) {
    Eigen::MatrixXd a(d, d);
    for (Eigen::Index j = 0; j < a.size(); ++j)
      a.data()[j] = normal(rng);
    Eigen::MatrixXd c = a * a.transpose() / d + 0.05 * Eigen::MatrixXd::Identity(d, d);
    if (floorHit) {
      // A feature that never varies in the class: its variance is the floor, nothing else.
      c.row(d - 1).setZero();
      c.col(d - 1).setZero();
      c(d - 1, d - 1) = 1e-4;
    }
    covs.push_back(c);
  }
  auto m = GaussianMixture::create(w, means, covs, CovarianceForm::NodalFull);
  EXPECT_TRUE(m.ok()) << m.errorText();
  return std::move(m.value());
}

// Dimensions above the compile-time cases take the blocked kernel; rows around its block of 24
// rows (three vectors of eight) and around the padding to eight.
TEST(FullDensityKernel, BlockedEqualsTheFormulaOnEveryLevel) {
  const std::string before = kernelIsa();
  for (const std::string& isa : supportedKernelIsas()) {
    ASSERT_TRUE(setKernelIsa(isa));
    std::mt19937_64 rng(11);
    std::normal_distribution<double> normal;
    for (int d : {7, 13, 30, 36}) {
      for (int k : {1, 3, 8}) {
        for (bool floorHit : {false, true}) {
          const GaussianMixture m = randomMixture(d, k, rng, floorHit);
          for (Eigen::Index rows : {1, 5, 8, 23, 24, 25, 49, 300}) {
            Eigen::MatrixXd x(rows, d);
            for (Eigen::Index i = 0; i < x.size(); ++i)
              x.data()[i] = 5.0 + 1.5 * normal(rng);
            if (floorHit) x(0, d - 1) = 5.0 + 30.0;  // far along the floored direction
            Eigen::VectorXd out;
            m.logDensities(x, out);
            ASSERT_EQ(out.size(), rows);
            for (Eigen::Index r = 0; r < rows; ++r) {
              const Eigen::VectorXd row = x.row(r).transpose();
              const double ref = referenceLogDensity(m, row);
              ASSERT_TRUE(std::isfinite(out(r))) << isa << " d " << d << " k " << k << " r " << r;
              ASSERT_NEAR(out(r), ref, 1e-9 * std::max(1.0, std::abs(ref)))
                  << isa << " d " << d << " k " << k << " rows " << rows << " r " << r;
              // A row's value does not depend on where it sits in a block: alone (the
              // one-vector tail of the kernel) it is the same to the last bit.
              ASSERT_EQ(m.logDensity(row), out(r)) << isa << " d " << d << " r " << r;
            }
          }
        }
      }
    }
  }
  ASSERT_TRUE(setKernelIsa(before));
}

// The plain log-space forward filter, written as the formula reads (Eigen vectors, one step at
// a time): the reference for the filter over raw arrays.
HmmFilterResult plainForward(const StepLikelihoods& steps, const TransitionModel& chain) {
  const Eigen::Index n = steps.logLik.rows();
  const Eigen::Index c = steps.logLik.cols();
  HmmFilterResult r;
  r.logPosterior = Eigen::MatrixXd::Constant(n, c, kNegInf);
  r.decisions.resize(static_cast<std::size_t>(n));
  Eigen::VectorXd alpha(c), predicted(c), joint(c);
  bool episode = false;
  for (Eigen::Index t = 0; t < n; ++t) {
    if (steps.observed[static_cast<std::size_t>(t)] == 0) {
      episode = false;
      continue;
    }
    if (episode) {
      hmmPredict(alpha, chain, predicted);
    } else {
      predicted = chain.logInitial;
    }
    bool any = false;
    for (Eigen::Index j = 0; j < c; ++j) {
      const double v = steps.logLik(t, j);
      joint[j] = std::isnan(v) ? kNegInf : v;
      any = any || joint[j] > kNegInf;
    }
    if (!any) joint.setZero();
    joint += predicted;
    const double z = logSumExp(joint);
    if (std::isfinite(z)) {
      joint.array() -= z;
    } else if (std::isfinite(logSumExp(predicted))) {
      joint = predicted.array() - logSumExp(predicted);
    } else {
      joint.setConstant(-std::log(static_cast<double>(c)));
    }
    alpha = joint;
    episode = true;
    r.logPosterior.row(t) = alpha.transpose();
    int best = 0;
    for (Eigen::Index j = 1; j < c; ++j)
      if (alpha[j] > alpha[best]) best = static_cast<int>(j);
    r.decisions[static_cast<std::size_t>(t)] = best;
  }
  return r;
}

// Random evidence with gaps, steps whose classes are all -inf (no evidence), single -inf and NaN
// entries, and chains with a forbidden move.
TEST(ForwardFilter, RawArraysEqualThePlainFilter) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int c : {1, 2, 3, 4}) {
    for (int variant = 0; variant < 3; ++variant) {
      const Eigen::Index n = variant == 2 ? 0 : 3000;
      StepLikelihoods sl;
      sl.logLik.resize(n, c);
      sl.observed.resize(static_cast<std::size_t>(n));
      for (Eigen::Index t = 0; t < n; ++t) {
        sl.observed[static_cast<std::size_t>(t)] = unit(rng) < 0.9 ? 1 : 0;
        const double u = unit(rng);
        for (int j = 0; j < c; ++j) {
          double v = -20.0 + 10.0 * normal(rng);
          if (u < 0.05) v = kNegInf;            // every class -inf
          if (u > 0.95 && j == 0) v = kNegInf;  // one class ruled out
          if (u > 0.93 && u <= 0.95 && j == c - 1) v = std::nan("");
          sl.logLik(t, j) = v;
        }
      }
      TransitionModel chain = stayTransitions(c, 0.9);
      if (variant == 1 && c > 1) {
        // Class 0 can never be left once entered, and class 1 never follows class 0 ... the
        // evidence sometimes forbids what the chain allows and the other way round.
        Eigen::MatrixXd logA = Eigen::MatrixXd::Constant(c, c, std::log(1.0 / c));
        logA.row(0).setConstant(kNegInf);
        logA(0, 0) = 0.0;
        Eigen::VectorXd logPi = Eigen::VectorXd::Constant(c, std::log(1.0 / c));
        chain.set(logA, logPi);
      }
      const HmmFilterResult fast = hmmForward(sl, chain);
      const HmmFilterResult plain = plainForward(sl, chain);
      ASSERT_EQ(fast.decisions.size(), static_cast<std::size_t>(n));
      ASSERT_EQ(fast.decisions, plain.decisions) << c << " " << variant;
      for (Eigen::Index t = 0; t < n; ++t)
        for (int j = 0; j < c; ++j) {
          const double a = fast.logPosterior(t, j);
          const double b = plain.logPosterior(t, j);
          ASSERT_FALSE(std::isnan(a)) << t;
          ASSERT_EQ(a, b) << "c " << c << " variant " << variant << " t " << t << " j " << j;
        }
      EXPECT_EQ(hmmForwardDecisions(sl, chain), fast.decisions);
      EXPECT_EQ(decide(sl, chain, DecisionMode::Online), fast.decisions);
    }
  }
}

// Every group's classification of a run, step by step: features from groupFeatures(run, t, ...)
// (the context walked back from t), one row at a time through the classifier, the plain filter.
void expectStepByStep(const RunData& run, const ModelBundle& bundle) {
  ClassifyOptions options;
  options.decision = DecisionMode::Online;
  const RunClassification r = classifyRun(run, bundle, options);
  ASSERT_EQ(r.steps, run.stepCount());
  for (const GroupInfo& info : kSensorGroups) {
    const GroupClassification& gc = r.groups[static_cast<std::size_t>(groupIndex(info.group))];
    ASSERT_EQ(gc.noContactRule.size(), run.stepCount());
    ASSERT_EQ(gc.predicted.size(), run.stepCount());
    const GroupModel* model = bundle.find(info.group);
    ASSERT_EQ(gc.model, model);
    for (std::size_t t = 0; t < run.stepCount(); ++t)
      ASSERT_EQ(gc.noContactRule[t] != 0, groupIsZero(run, t, info.group)) << t;
    if (model == nullptr) {
      for (std::size_t t = 0; t < run.stepCount(); ++t)
        EXPECT_FALSE(gc.predicted[t].has_value());
      continue;
    }
    const int c = model->classifier.classCount();
    const int d = featureDimension(info.group, model->features);
    StepLikelihoods sl;
    sl.logLik = Eigen::MatrixXd::Constant(static_cast<Eigen::Index>(run.stepCount()), c, kNegInf);
    sl.observed.assign(run.stepCount(), 0);
    Eigen::MatrixXd x(1, d);
    Eigen::MatrixXd ll;
    Eigen::Index contactRow = 0;  // the result keeps a row per contact step, in step order
    for (std::size_t t = 0; t < run.stepCount(); ++t) {
      const auto row = static_cast<Eigen::Index>(t);
      if (groupIsZero(run, t, info.group)) {
        EXPECT_FALSE(gc.predicted[t].has_value());
        continue;
      }
      groupFeatures(run, t, info.group, model->features, x.data());
      model->classifier.logLikelihoods(x, ll);
      ASSERT_LT(contactRow, gc.logLikelihoods.rows()) << info.shortName << " t " << t;
      for (int k = 0; k < c; ++k) {
        ASSERT_EQ(gc.logLikelihoods(contactRow, k), ll(0, k)) << info.shortName << " t " << t;
        sl.logLik(row, k) = ll(0, k);
      }
      ++contactRow;
      sl.observed[t] = 1;
      ASSERT_EQ(gc.predicted[t], model->classifier.predictFromLogLikelihoods(ll)[0]) << t;
    }
    EXPECT_EQ(contactRow, gc.logLikelihoods.rows()) << info.shortName;
    if (model->transitions.empty()) continue;
    EXPECT_EQ(gc.decisionName, "online");
    EXPECT_EQ(gc.decided, plainForward(sl, model->transitions).decisions) << info.shortName;
  }
}

ModelBundle trainBundle(FeatureKind kind, int order,
                        ClassifierMethod method = ClassifierMethod::Gmm) {
  const RunData train = testdata::makeLabelledRun(2500, 21);
  TrainJob job;
  job.runs = {{&train, labelsFromTruth(train)}};
  TrainSettings s;
  s.features = kind;
  s.classifier.method = method;
  s.classifier.gbt.trees = 30;
  s.classifier.gbt.depth = 4;
  s.classifier.gmm.components = order;
  s.classifier.gmm.form = CovarianceForm::NodalFull;
  s.classifier.gmm.varianceFloor = 0.01;  // hit by the sensors a class never presses
  s.classifier.gmm.maxIterations = 15;
  s.classifier.gmm.restarts = 1;
  job.settings = GroupSettings::same(s);
  job.groups = {SensorGroup::Front, SensorGroup::FrontLeftCorner, SensorGroup::Left,
                SensorGroup::Back};
  auto out = trainAndEvaluate(job);
  EXPECT_TRUE(out.ok()) << out.errorText();
  return std::move(out->bundle);
}

// Context features (dimensions 30, 12, 36 and 30), runs longer than a slice and a block, contact
// from the first step (no lagged values yet), groups without a model.
TEST(ClassifyRun, EqualsAStepByStepReference) {
  const ModelBundle bundle = trainBundle(FeatureKind::Context, 3);
  ASSERT_EQ(bundle.models.size(), 4u);
  expectStepByStep(testdata::makeLabelledRun(1337, 77, 0.3, 0.9), bundle);
  expectStepByStep(testdata::makeLabelledRun(3, 78, 0.3, 1.0), bundle);
  // The neighbours kind reads the other groups' values of the same step.
  const ModelBundle neighbours = trainBundle(FeatureKind::Neighbours, 3);
  ASSERT_EQ(neighbours.models.size(), 4u);
  expectStepByStep(testdata::makeLabelledRun(1337, 79, 0.3, 0.9), neighbours);
  // The motion kind looks back over the commands: a run whose speed and turn change often.
  const ModelBundle motion = trainBundle(FeatureKind::Motion, 3);
  RunData moving = testdata::makeLabelledRun(1337, 80, 0.3, 0.9);
  for (std::size_t t = 0; t < moving.stepCount(); ++t) {
    moving.v[t] = static_cast<double>((t / 7) % 5) * 12.0 - 10.0;  // -10 .. 38 units/s
    moving.omega[t] = (t / 11) % 3 == 0 ? 0.7 : 0.0;
  }
  expectStepByStep(moving, motion);
  // Boosted trees: their scaled likelihoods through the same blocks and chain.
  const ModelBundle trees = trainBundle(FeatureKind::Context, 3, ClassifierMethod::Gbt);
  ASSERT_EQ(trees.models.size(), 4u);
  ASSERT_NE(trees.models[0].classifier.trees(), nullptr);
  expectStepByStep(testdata::makeLabelledRun(1337, 81, 0.3, 0.9), trees);
}

TEST(ClassifyRun, EmptyAndContactFreeRuns) {
  const ModelBundle bundle = trainBundle(FeatureKind::NormalShearTouch, 2);
  const RunData empty;
  const RunClassification r = classifyRun(empty, bundle, {});
  EXPECT_EQ(r.steps, 0u);
  for (const GroupClassification& gc : r.groups) {
    EXPECT_TRUE(gc.predicted.empty());
    EXPECT_TRUE(gc.decided.empty());
  }
  expectStepByStep(testdata::makeLabelledRun(400, 5, 0.3, 0.0), bundle);  // no contact at all
  expectStepByStep(testdata::makeLabelledRun(700, 6, 0.3, 0.75), bundle);
}

}  // namespace
}  // namespace tactile::analysis
