// Gaussian mixture models fitted by expectation-maximisation (thesis 4.4). The model type is
// analysis/gaussian_mixture.h.
//
// Data layout: every function here takes samples as an Eigen::MatrixXd with ONE ROW PER SAMPLE
// (N x D, Eigen's default column-major storage). EM works on blocks of rows of that matrix with
// matrix products against all components at once, so no transposed copy is made.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/gaussian_mixture.h"
#include "base/progress.h"

namespace tactile::analysis {

// How the variance floor is applied after each M-step.
//  Floor: clamp, sigma^2 = max(sigma^2, floor) on the diagonal entries of diagonal forms and on
//         the eigenvalues of full forms (the thesis's variance minimum constraint).
//  Add:   Sigma + floor * I (scikit-learn's reg_covar).
enum class Regularization { Floor, Add };
// "floor", "add".
std::string_view regularizationName(Regularization reg);
std::optional<Regularization> parseRegularization(std::string_view name);

// Initialisation of EM.
//  KMeansPlusPlus: k-means++ seeding followed by a few Lloyd iterations, then one M-step from the
//                  hard assignment (default).
//  RandomFromData: means are distinct random training rows, weights equal, covariances the data
//                  covariance; re-initialised when maxIterations do not converge (thesis 4.4.2.1).
enum class GmmInit { KMeansPlusPlus, RandomFromData };
// "kmeans++", "random-from-data".
std::string_view gmmInitName(GmmInit init);
std::optional<GmmInit> parseGmmInit(std::string_view name);

// Convergence rule on the mean log-likelihood per sample l_t = (1/N) sum_n log p(x_n) of the
// parameters before M-step t:
//  Relative: |l_t - l_{t-1}| < tolerance * max(1, |l_t|)   (default)
//  Absolute: |l_t - l_{t-1}| < tolerance                    (scikit-learn's rule)
enum class ConvergenceRule { Relative, Absolute };
std::string_view convergenceRuleName(ConvergenceRule rule);
std::optional<ConvergenceRule> parseConvergenceRule(std::string_view name);

// The largest model order (components per class) a fit takes: every component holds a mean and a
// covariance, so a larger order is a typing mistake, not a model, and could not be held in memory.
inline constexpr int kMaxModelOrder = 4096;

// The smallest nonzero variance floor: the smallest normal double. Below it (a subnormal such as
// 1e-320) the floor is lost to rounding and cannot keep a variance away from zero; 0 means no
// floor.
inline constexpr double kMinVarianceFloor = std::numeric_limits<double>::min();

struct GmmOptions {
  int components = 1;  // model order M
  CovarianceForm form = CovarianceForm::NodalDiag;
  double varianceFloor = 1e-3;  // clamp (Floor) or reg_covar (Add); 0 or >= kMinVarianceFloor
  Regularization reg = Regularization::Floor;
  GmmInit init = GmmInit::KMeansPlusPlus;
  std::uint64_t seed = 1;
  int restarts = 1;  // independent initialisations; the best final log-likelihood is kept
  int maxIterations = 100;
  double tolerance = 1e-3;
  ConvergenceRule rule = ConvergenceRule::Relative;
  int kmeansIterations = 10;     // Lloyd iterations after k-means++ seeding (0 = seeding only)
  int maxReinitialisations = 5;  // RandomFromData: extra attempts when EM does not converge
  int threads = 1;               // worker threads for E/M steps (0 = all cores); results do not
                                 // depend on this number
  bool keepTrace = false;        // record the mean log-likelihood of every E-step (GmmFit::trace)
  // Test hook, empty in normal use: called after every M-step with the iteration number and the
  // new parameters (weights, means in the fit's centred frame, covariances), which it may change.
  // Lets a test corrupt a step to check that EM detects a fall in the log-likelihood.
  std::function<void(int iteration, Eigen::VectorXd& weights, Eigen::MatrixXd& means,
                     std::vector<Eigen::MatrixXd>& covariances)>
      afterMStep;
};

// Warnings for a variance floor that is at least 100 times the whole variance of a feature over
// `samples` (the floor then hides that feature's spread: every model sees it as noise of the
// floor's size, and classes that differ only there are not told apart). Features with zero
// variance carry no information whatever the floor and are not reported. featureNames (optional,
// one per column) name the features in the messages; otherwise "feature j" (0-based).
std::vector<std::string> varianceFloorWarnings(const Eigen::MatrixXd& samples, double varianceFloor,
                                               const std::vector<std::string>& featureNames = {});
// The same over the rows of every matrix of `parts` together (all with the same columns), read
// where they are: the variance over all classes' rows without copying them into one table.
std::vector<std::string> varianceFloorWarnings(std::span<const Eigen::MatrixXd> parts,
                                               double varianceFloor,
                                               const std::vector<std::string>& featureNames = {});

struct GmmFit {
  bool ok = false;
  std::string reason;  // why the fit failed (ok == false), empty otherwise
  GaussianMixture model;
  int iterations = 0;              // EM iterations of the kept run
  int totalIterations = 0;         // over all restarts and re-initialisations
  bool converged = false;          // the kept run met the tolerance within maxIterations
  double logLikelihood = 0.0;      // total log-likelihood of the training data under `model`, nats
  double meanLogLikelihood = 0.0;  // logLikelihood / N
  double bic = 0.0;                // -2 logL + p ln N
  double aic = 0.0;                // -2 logL + 2 p
  int droppedComponents = 0;       // components removed because they lost all their weight
  // A step that lowered the log-likelihood and was undone (docs/learning.md, "Monotone EM"): the
  // EM iteration whose E-step saw the fall (0 = none) and the fall in nats per sample. The model
  // is the one before that step. With the floor clamp only a fall within rounding is undone (a
  // larger one fails the fit); with `add` also a fall within the step's regularisation bound.
  int undoneIteration = 0;
  double likelihoodDrop = 0.0;
  // options.keepTrace: for the kept run, the mean log-likelihood computed by every E-step, in
  // order: that of the parameters before each M-step, including a step that was then undone,
  // then that of the returned model.
  std::vector<double> trace;
  // Warnings that do not stop the fit (e.g. a variance floor that hides a feature's spread).
  std::vector<std::string> warnings;
};

// Fits a mixture to samples (N x D, one row per sample) by EM. Never returns NaN parameters: a
// fit that cannot succeed (too few samples, non-finite input, singular covariance with variance
// floor 0, an EM step that lowers the log-likelihood by more than rounding, cancellation through
// progress) has ok == false and a reason. The progress callback is called
// once per EM iteration with (iterations done, maximum iterations over all attempts); returning
// false cancels the fit.
GmmFit fitGmm(const Eigen::MatrixXd& samples, const GmmOptions& options,
              const ProgressFn& progress = {});

}  // namespace tactile::analysis
