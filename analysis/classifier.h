// Per-class model sets: the Gaussian classifier (thesis 4.3) and the GMM classifier (thesis 4.4).
//
// Classes are indices 0..C-1 with names; samples are Eigen matrices with one row per sample
// (N x D), see gmm.h.
#pragma once

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/gbt.h"
#include "analysis/gmm.h"
#include "base/progress.h"

namespace tactile::analysis {

// Gradient-boosted trees (Gbt, analysis/gbt.h) give the class chain scaled likelihoods instead of
// densities; everything downstream of logLikelihoods() treats the three alike.
enum class ClassifierMethod { Gaussian, Gmm, Gbt };
// "gaussian", "gmm", "gbt".
std::string_view classifierMethodName(ClassifierMethod method);
std::optional<ClassifierMethod> parseClassifierMethod(std::string_view name);

// Class priors added to the log-likelihoods before the argmax.
enum class PriorMode { Equal, Empirical };
std::string_view priorModeName(PriorMode mode);
std::optional<PriorMode> parsePriorMode(std::string_view name);

struct ClassifierOptions {
  ClassifierMethod method = ClassifierMethod::Gmm;
  // GMM settings (method Gmm). For method Gaussian only `varianceFloor` and `reg` are used: floor
  // 0 = plain unbiased covariance (singular is an error); > 0 = its eigenvalues clamped at the
  // floor (reg Floor) or the floor added to its diagonal (reg Add).
  GmmOptions gmm;
  // Tree settings (method Gbt); its seed is gmm.seed, so that sweeps' fit seeds apply alike.
  GbtSettings gbt;
  PriorMode priors = PriorMode::Equal;
  // Gaussian method: also fit a "rest" Gaussian per class (all other classes' samples) for the
  // one-vs-rest log-likelihood ratio of thesis 4.3.
  bool oneVsRest = true;
  int threads = 1;  // 0 = all cores; results do not depend on it
  // Also fit a class with fewer training samples than dimensions, its covariance held up by the
  // variance floor (which must then be > 0), as scikit-learn's estimators fit any data they are
  // given. Off for the CLI and the workbench, which refuse such a class as too little to learn
  // from.
  bool fewSamples = false;
  // Names of the feature columns, used in warnings only (empty: "feature j").
  std::vector<std::string> featureNames;
};

// A trained (or loaded) classifier: one GaussianMixture per class (a one-component NodalFull
// mixture for the Gaussian method), log priors, and for the Gaussian method optional one-vs-rest
// "rest" models.
class ClassModelSet {
 public:
  ClassModelSet() = default;

  // Validates and builds a model set: names and models non-empty, same size, all models of the
  // same dimension; logPriors empty (= equal) or one finite value per class with
  // logsumexp(logPriors) = 0 within 1e-9; restModels empty or one per class.
  static Result<ClassModelSet> create(ClassifierMethod method, std::vector<std::string> classNames,
                                      std::vector<GaussianMixture> models,
                                      Eigen::VectorXd logPriors = {},
                                      std::vector<GaussianMixture> restModels = {});

  // A set of boosted trees (method Gbt) over the named classes, shared by the copies of the set.
  static Result<ClassModelSet> createTrees(std::vector<std::string> classNames,
                                           std::shared_ptr<const GbtModel> trees,
                                           Eigen::VectorXd logPriors = {});

  ClassifierMethod method() const { return method_; }
  int classCount() const { return static_cast<int>(names_.size()); }
  int dimension() const {
    if (trees_) return trees_->dimension();
    return models_.empty() ? 0 : models_.front().dimension();
  }
  // The trees of a Gbt set (null for the Gaussian methods, whose model(c) are the mixtures).
  const GbtModel* trees() const { return trees_.get(); }
  const std::vector<std::string>& classNames() const { return names_; }
  const GaussianMixture& model(int c) const { return models_[static_cast<std::size_t>(c)]; }
  const std::vector<GaussianMixture>& models() const { return models_; }
  bool hasRestModels() const { return !restModels_.empty(); }
  const GaussianMixture& restModel(int c) const { return restModels_[static_cast<std::size_t>(c)]; }
  const std::vector<GaussianMixture>& restModels() const { return restModels_; }
  const Eigen::VectorXd& logPriors() const { return logPriors_; }  // always C entries

  // log p(x_n | class c) for every row: out is N x C (for trees, the scaled likelihoods).
  void logLikelihoods(const Eigen::MatrixXd& samples, Eigen::MatrixXd& out) const;
  // argmax_c [log p(x | c) + log P(c)]; ties go to the lowest class index. Every row gets a
  // defined class even when all likelihoods underflow (log space throughout).
  std::vector<int> predict(const Eigen::MatrixXd& samples) const;
  int predictOne(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // Same as predict, given precomputed logLikelihoods (N x C).
  std::vector<int> predictFromLogLikelihoods(const Eigen::MatrixXd& logLik) const;
  // One-vs-rest log-likelihood ratio with equal priors (thesis 4.3):
  // L = log N(x | mu_c, Sigma_c) - log N(x | mu_rest, Sigma_rest); L > 0 means class c.
  // Requires hasRestModels(). out is N.
  void oneVsRestLogRatio(const Eigen::MatrixXd& samples, int c, Eigen::VectorXd& out) const;

 private:
  ClassifierMethod method_ = ClassifierMethod::Gmm;
  std::vector<std::string> names_;
  std::vector<GaussianMixture> models_;
  std::vector<GaussianMixture> restModels_;
  std::shared_ptr<const GbtModel> trees_;
  Eigen::VectorXd logPriors_;
};

struct ClassifierFit {
  bool ok = false;
  std::string reason;  // names the class that failed and why
  ClassModelSet model;
  std::vector<int> iterations;                 // per class (1 for the Gaussian method)
  std::vector<bool> converged;                 // per class
  std::vector<double> trainMeanLogLikelihood;  // per class, nats
  // Per class: mixture components removed for lack of mass (the model has order minus these).
  std::vector<int> droppedComponents;
  // Per class: the fall of the log-likelihood (nats per sample) of an EM step that was undone,
  // 0 when none (GmmFit::likelihoodDrop).
  std::vector<double> likelihoodDrop;
  // Warnings that did not stop the fit (varianceFloorWarnings over all classes' rows together).
  std::vector<std::string> warnings;
  double fitSeconds = 0.0;  // wall time of the fits alone
};

// Held-out log-likelihood of labelled rows: the one definition used by `tactile fit`, `train` and
// `sweep`. For every row r with truth[r] >= 0, v = logLik(r, truth[r]) (log p(x | model of the
// row's own class)); rows whose v is not finite (-inf: zero density under that model) are counted
// in negInfRows and left out; mean is the mean of v over the other rows, nullopt when there is
// none. Rows with truth[r] < 0 (a class without a model) are not scored.
struct HeldOutLogLikelihood {
  std::optional<double> mean;  // nats
  std::size_t rows = 0;        // rows in the mean
  std::size_t negInfRows = 0;  // rows left out because their log-likelihood is -inf
};
HeldOutLogLikelihood heldOutLogLikelihood(const Eigen::MatrixXd& logLik,
                                          const std::vector<int>& truth);

// Trains one model per class. samplesPerClass[c] holds class c's training rows (N_c x D).
// Errors (ok == false, reason naming the class): no classes, a class with zero samples, a class
// with fewer samples than dimensions (unless options.fewSamples with a variance floor > 0),
// mismatched dimensions, non-finite values, a failed fit.
// Progress: (classes done, classes), called after each class and also after every EM iteration of
// each running fit (with unchanged counts; serialised, never from two threads at once); returning
// false cancels, and running fits stop within one EM iteration.
ClassifierFit trainClassifier(const std::vector<Eigen::MatrixXd>& samplesPerClass,
                              const std::vector<std::string>& classNames,
                              const ClassifierOptions& options, const ProgressFn& progress = {});

// Unbiased (N-1) maximum-likelihood Gaussian of thesis 4.3 as a one-component NodalFull mixture:
// mu = (1/N) sum x_n, Sigma = 1/(N-1) sum (x_n - mu)(x_n - mu)^T (two-pass, centred). With a
// variance floor > 0, reg Floor clamps the eigenvalues of Sigma at the floor, reg Add uses
// Sigma + floor * I. Fails for N < 2, N < D with floor 0, or a singular Sigma with floor 0.
Result<GaussianMixture> fitGaussian(const Eigen::MatrixXd& samples, double varianceFloor,
                                    Regularization reg = Regularization::Floor);

}  // namespace tactile::analysis
