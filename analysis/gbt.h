// Gradient-boosted trees as a per-group classifier beside the Gaussian mixtures, over XGBoost's C
// API (Debian libxgboost-dev): multi-class, class-balanced, trained on one thread with a fixed
// seed so that the same rows, settings and seed give the same model bit for bit.
//
// The class chain (temporal.h) wants, per step and class, a log-likelihood log p(x | c). A
// discriminative model gives a posterior P(c | x) instead; divided by the class prior it was
// trained under, it is a likelihood up to a factor that does not depend on the class (a "scaled
// likelihood", as hybrid HMM speech recognisers use): p(x | c) / p(x) = P(c | x) / P(c). Trained
// with class-balanced weights, every class has the same prior 1/C, so
//   log p(x | c) = log P(c | x) + log C   (up to a term shared by the classes of a step),
// which the chain's decisions never see (it normalises each step). All in log space; a posterior
// of 0 never reaches the chain (it is kept at or above the smallest positive float).
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/progress.h"

namespace tactile::analysis {

struct GbtSettings {
  int trees = 100;              // boosting rounds (each adds one tree per class)
  int depth = 6;                // largest tree depth
  double learningRate = 0.1;    // shrinkage of each round (XGBoost's eta)
  double minChildWeight = 1.0;  // least summed weight in a leaf
  std::uint64_t seed = 1;
};

// The settings as text, "trees 100, depth 6, learning rate 0.1, min child weight 1", and the one
// check of them ("" when sound): trees 1-5000, depth 1-16, learning rate in (0, 1], min child
// weight >= 0 and finite.
std::string describeGbtSettings(const GbtSettings& settings);
std::string checkGbtSettings(const GbtSettings& settings);

// A trained boosted-tree classifier over C classes of D features. Move-only (it owns XGBoost's
// booster).
class GbtModel {
 public:
  GbtModel();
  ~GbtModel();
  GbtModel(GbtModel&&) noexcept;
  GbtModel& operator=(GbtModel&&) noexcept;
  GbtModel(const GbtModel&) = delete;
  GbtModel& operator=(const GbtModel&) = delete;

  // Trains on samplesPerClass[c] (N_c x D rows of class c), each class weighted so that all
  // classes weigh the same in total. Errors: fewer than two classes, a class without rows,
  // mismatched dimensions, a non-finite value, settings out of range, XGBoost's own failure.
  // `progress` is called after each round with (rounds done, trees); returning false stops the
  // fit with the error "cancelled".
  static Result<GbtModel> train(const std::vector<Eigen::MatrixXd>& samplesPerClass,
                                const GbtSettings& settings, const ProgressFn& progress = {});
  // A model from the bytes of `serialize()`; errors name what is wrong.
  static Result<GbtModel> load(const std::string& bytes, int classCount, int dimension);

  int classCount() const { return classes_; }
  int dimension() const { return dimension_; }
  // XGBoost's own JSON form of the trees (stored inside this product's model file).
  Result<std::string> serialize() const;

  // log P(c | x) for every row: out is N x C, each row's exponentials summing to 1.
  void logPosteriors(const Eigen::MatrixXd& samples, Eigen::MatrixXd& out) const;
  // The chain's emission scores: log P(c | x) + log C (see the header comment). out is N x C.
  void logScaledLikelihoods(const Eigen::MatrixXd& samples, Eigen::MatrixXd& out) const;

 private:
  // log P(c | x) into out (N x C); false when XGBoost gives no answer of that shape.
  bool predict(const Eigen::MatrixXd& samples, Eigen::MatrixXd& out) const;
  struct Booster;
  std::unique_ptr<Booster> booster_;
  int classes_ = 0;
  int dimension_ = 0;
};

}  // namespace tactile::analysis
