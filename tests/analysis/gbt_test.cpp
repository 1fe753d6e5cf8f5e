// Gradient-boosted trees (analysis/gbt.h): they learn what separates classes, give log posteriors
// whose exponentials sum to one and scaled likelihoods log C above them, train bit for bit the
// same for the same rows, settings and seed, survive a round trip through their stored form, and
// refuse what cannot be learnt with one clear line.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis/gbt.h"
#include "analysis/temporal.h"

namespace tactile::analysis {
namespace {

// Class c's rows scattered round (3c, -3c, 0) in three features; the third carries nothing.
std::vector<Eigen::MatrixXd> blobs(int classes, int rowsPerClass, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<Eigen::MatrixXd> out;
  for (int c = 0; c < classes; ++c) {
    Eigen::MatrixXd m(rowsPerClass + 7 * c, 3);
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
      m(r, 0) = 3.0 * c + noise(rng);
      m(r, 1) = -3.0 * c + noise(rng);
      m(r, 2) = noise(rng);
    }
    out.push_back(std::move(m));
  }
  return out;
}

GbtSettings quick() {
  GbtSettings s;
  s.trees = 20;
  s.depth = 3;
  s.learningRate = 0.3;
  return s;
}

TEST(Gbt, LearnsSeparatedClassesWithPosteriorsThatSumToOne) {
  const auto train = blobs(3, 200, 1);
  auto model = GbtModel::train(train, quick());
  ASSERT_TRUE(model.ok()) << model.errorText();
  EXPECT_EQ(model->classCount(), 3);
  EXPECT_EQ(model->dimension(), 3);
  const auto test = blobs(3, 100, 2);
  int right = 0;
  int total = 0;
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd logPost;
    model->logPosteriors(test[static_cast<std::size_t>(c)], logPost);
    ASSERT_EQ(logPost.cols(), 3);
    ASSERT_TRUE(logPost.allFinite());
    for (Eigen::Index r = 0; r < logPost.rows(); ++r) {
      EXPECT_NEAR(logPost.row(r).array().exp().sum(), 1.0, 1e-12);
      Eigen::Index best = 0;
      logPost.row(r).maxCoeff(&best);
      right += best == c ? 1 : 0;
      ++total;
    }
  }
  EXPECT_GT(static_cast<double>(right) / total, 0.9);
  Eigen::MatrixXd logPost;
  Eigen::MatrixXd scaled;
  model->logPosteriors(test[0], logPost);
  model->logScaledLikelihoods(test[0], scaled);
  EXPECT_TRUE(((scaled - logPost).array() - std::log(3.0)).abs().maxCoeff() < 1e-12);
}

TEST(Gbt, TheSameRowsSettingsAndSeedGiveTheSameModelBitForBit) {
  const auto train = blobs(2, 300, 5);
  auto a = GbtModel::train(train, quick());
  auto b = GbtModel::train(train, quick());
  ASSERT_TRUE(a.ok() && b.ok());
  auto textA = a->serialize();
  auto textB = b->serialize();
  ASSERT_TRUE(textA.ok() && textB.ok());
  EXPECT_EQ(textA.value(), textB.value());
  GbtSettings other = quick();
  other.depth = 2;
  auto c = GbtModel::train(train, other);
  ASSERT_TRUE(c.ok());
  EXPECT_NE(c->serialize().value(), textA.value());
}

TEST(Gbt, StoredTreesLoadAndPredictTheSame) {
  const auto train = blobs(4, 150, 7);
  auto model = GbtModel::train(train, quick());
  ASSERT_TRUE(model.ok());
  auto text = model->serialize();
  ASSERT_TRUE(text.ok());
  auto loaded = GbtModel::load(text.value(), 4, 3);
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  Eigen::MatrixXd before;
  Eigen::MatrixXd after;
  model->logPosteriors(train[2], before);
  loaded->logPosteriors(train[2], after);
  EXPECT_TRUE(before == after);
  // Stored trees of another shape, or bytes that are no trees, are refused.
  EXPECT_FALSE(GbtModel::load(text.value(), 3, 3).ok());
  auto garbage = GbtModel::load("{\"not\": \"trees\"}", 4, 3);
  ASSERT_FALSE(garbage.ok());
  EXPECT_NE(garbage.errorText().find("stored trees"), std::string::npos) << garbage.errorText();
}

TEST(Gbt, WhatCannotBeLearntIsRefusedWithOneLine) {
  auto one = GbtModel::train(blobs(1, 50, 1), quick());
  ASSERT_FALSE(one.ok());
  EXPECT_NE(one.errorText().find("at least two classes"), std::string::npos);
  auto empty = blobs(2, 50, 1);
  empty[1].resize(0, 3);
  EXPECT_FALSE(GbtModel::train(empty, quick()).ok());
  auto nan = blobs(2, 50, 1);
  nan[0](3, 1) = std::nan("");
  auto refused = GbtModel::train(nan, quick());
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.errorText().find("finite"), std::string::npos);
  GbtSettings deep = quick();
  deep.depth = 40;
  auto tooDeep = GbtModel::train(blobs(2, 50, 1), deep);
  ASSERT_FALSE(tooDeep.ok());
  EXPECT_NE(tooDeep.errorText().find("depth 40"), std::string::npos);
  EXPECT_EQ(checkGbtSettings(GbtSettings{}), "");
}

// Constant features: the trees cannot split, every class stays equally likely, nothing is NaN.
TEST(Gbt, ConstantFeaturesGiveEqualPosteriorsNeverNaN) {
  std::vector<Eigen::MatrixXd> flat{Eigen::MatrixXd::Constant(40, 2, 1.5),
                                    Eigen::MatrixXd::Constant(90, 2, 1.5)};
  auto model = GbtModel::train(flat, quick());
  ASSERT_TRUE(model.ok()) << model.errorText();
  Eigen::MatrixXd logPost;
  model->logPosteriors(flat[0], logPost);
  ASSERT_TRUE(logPost.allFinite());
  // Class-balanced weights: the larger class gets no head start.
  EXPECT_NEAR(logPost(0, 0), std::log(0.5), 1e-6);
  EXPECT_NEAR(logPost(0, 1), std::log(0.5), 1e-6);
}

// The hybrid chain: the online and offline decisions over the trees' scaled likelihoods (posterior
// over the balanced prior 1/C, in log space) are the posteriors of the chain whose evidence at
// each step is P(c | x) / (1/C), checked against brute-force enumeration of every class path in
// plain probabilities on a tiny chain.
TEST(Gbt, TheChainOverScaledLikelihoodsMatchesBruteForceEnumeration) {
  const auto train = blobs(3, 150, 11);
  auto model = GbtModel::train(train, quick());
  ASSERT_TRUE(model.ok()) << model.errorText();
  // Six steps drifting from class 0 to class 2, some between classes.
  Eigen::MatrixXd x(6, 3);
  for (int t = 0; t < 6; ++t)
    x.row(t) << 1.2 * t, -1.2 * t, 0.1 * t;
  Eigen::MatrixXd logPost;
  model->logPosteriors(x, logPost);
  StepLikelihoods steps;
  model->logScaledLikelihoods(x, steps.logLik);
  steps.observed.assign(6, 1);
  Eigen::MatrixXd a(3, 3);
  a << 0.8, 0.15, 0.05, 0.1, 0.7, 0.2, 0.05, 0.15, 0.8;
  Eigen::VectorXd pi(3);
  pi << 0.5, 0.3, 0.2;
  TransitionModel chain;
  chain.set(a.array().log().matrix(), pi.array().log().matrix());
  const HmmFilterResult online = hmmForward(steps, chain);
  const HmmFilterResult offline = hmmForwardBackward(steps, chain);
  // Every path's weight in plain probabilities: pi, A and 3 P(c | x) at every step.
  const auto marginal = [&](int at, int end) {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(3);
    std::vector<int> path(static_cast<std::size_t>(end + 1), 0);
    while (true) {
      double p = pi[path[0]] * 3.0 * std::exp(logPost(0, path[0]));
      for (int k = 1; k <= end; ++k)
        p *= a(path[static_cast<std::size_t>(k - 1)], path[static_cast<std::size_t>(k)]) * 3.0 *
             std::exp(logPost(k, path[static_cast<std::size_t>(k)]));
      out[path[static_cast<std::size_t>(at)]] += p;
      int k = 0;
      while (k <= end && ++path[static_cast<std::size_t>(k)] == 3)
        path[static_cast<std::size_t>(k++)] = 0;
      if (k > end) break;
    }
    return Eigen::VectorXd(out / out.sum());
  };
  for (int t = 0; t < 6; ++t) {
    const Eigen::VectorXd filtered = marginal(t, t);
    const Eigen::VectorXd smoothed = marginal(t, 5);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(std::exp(online.logPosterior(t, c)), filtered[c], 1e-12) << t << " " << c;
      EXPECT_NEAR(std::exp(offline.logPosterior(t, c)), smoothed[c], 1e-12) << t << " " << c;
    }
  }
  // The drift is followed: class 0 first, class 2 last.
  ASSERT_TRUE(online.decisions[0].has_value() && online.decisions[5].has_value());
  EXPECT_EQ(*online.decisions[0], 0);
  EXPECT_EQ(*online.decisions[5], 2);
}

}  // namespace
}  // namespace tactile::analysis
