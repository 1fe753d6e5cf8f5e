// A Gaussian mixture as a model: its parameters, their validation and every density it gives.
// How a mixture is fitted to data (EM) is in analysis/gmm.h.
//
// Samples are Eigen matrices with ONE ROW PER SAMPLE (N x D).
#pragma once

#include <Eigen/Core>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/gmm_kernels.h"
#include "base/error.h"

namespace tactile::analysis {

// Covariance form of a mixture: nodal = one covariance per component, grand = one covariance
// shared (tied) by all components; full or diagonal.
enum class CovarianceForm { NodalFull, NodalDiag, GrandFull, GrandDiag };
inline constexpr CovarianceForm kAllCovarianceForms[] = {
    CovarianceForm::NodalFull, CovarianceForm::NodalDiag, CovarianceForm::GrandFull,
    CovarianceForm::GrandDiag};
// "nodal-full", "nodal-diag", "grand-full", "grand-diag".
std::string_view covarianceFormName(CovarianceForm form);
std::optional<CovarianceForm> parseCovarianceForm(std::string_view name);
inline bool isDiagonal(CovarianceForm f) {
  return f == CovarianceForm::NodalDiag || f == CovarianceForm::GrandDiag;
}
inline bool isNodal(CovarianceForm f) {
  return f == CovarianceForm::NodalFull || f == CovarianceForm::NodalDiag;
}

// A fitted or loaded mixture p(x) = sum_i w_i N(x | mu_i, Sigma_i). Immutable after creation;
// caches the Cholesky factors and log-determinants used by every density evaluation, so a model
// rebuilt from the same weights/means/covariances (e.g. read from a model file) evaluates to
// bit-identical densities.
class GaussianMixture {
 public:
  GaussianMixture() = default;  // empty (0 components); logDensity of an empty model is -inf

  // Validates and builds a mixture. weights: K; means: K x D; covariances: K matrices (nodal
  // forms) or 1 matrix (grand forms), each D x D, symmetric (relative 1e-12), positive definite,
  // with zero off-diagonal entries for diagonal forms; weights non-negative, summing to 1 within
  // 1e-9 (they are then renormalised). An error names the offending component.
  static Result<GaussianMixture> create(const Eigen::VectorXd& weights,
                                        const Eigen::MatrixXd& means,
                                        const std::vector<Eigen::MatrixXd>& covariances,
                                        CovarianceForm form);

  int components() const { return static_cast<int>(weights_.size()); }
  int dimension() const { return static_cast<int>(means_.cols()); }
  CovarianceForm form() const { return form_; }
  const Eigen::VectorXd& weights() const { return weights_; }
  const Eigen::MatrixXd& means() const { return means_; }  // K x D, one row per component
  // K matrices (nodal) or 1 (grand), each D x D (diagonal forms: off-diagonals exactly zero).
  const std::vector<Eigen::MatrixXd>& covariances() const { return covariances_; }
  // Covariance of component k (the shared one for grand forms).
  const Eigen::MatrixXd& covariance(int k) const {
    return covariances_[isNodal(form_) ? static_cast<std::size_t>(k) : 0];
  }

  // log p(x) = logsumexp_i [log w_i - D/2 log(2 pi) - 1/2 log|Sigma_i|
  //                         - 1/2 |L_i^{-1}(x - mu_i)|^2],  Sigma_i = L_i L_i^T.
  double logDensity(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // log p(x_n) for every row of samples (N x D) into out (resized to N). Blocked and vectorised.
  void logDensities(const Eigen::MatrixXd& samples, Eigen::VectorXd& out) const;
  // Buffers of blockLogDensities, kept by the caller between calls (no allocation per block).
  struct BlockScratch {
    Eigen::MatrixXd centred;  // kDensityBlockRows x D
    Eigen::MatrixXd logp;     // kDensityBlockRows x K
    Eigen::VectorXd logSum;   // kDensityBlockRows
  };
  // log p(x_r) for `rows` <= kDensityBlockRows rows of a column-major block (element (r, j) at
  // x[r + j * ldx]) into out[0 .. rows): the same arithmetic as logDensities, bit for bit.
  void blockLogDensities(const double* x, Eigen::Index ldx, Eigen::Index rows, double* out,
                         BlockScratch& scratch) const;
  // Posterior p(i | x) of each component for one sample (sums to 1; computed in log space).
  Eigen::VectorXd responsibilities(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // Mean over rows of log p(x_n), in nats (held-out score).
  double meanLogLikelihood(const Eigen::MatrixXd& samples) const;
  // Free parameters: (K-1) + K*D + covariance parameters of the form.
  int parameterCount() const;

 private:
  // Computes the cached factors from weights_/means_/covariances_; false if not positive definite.
  bool buildCache(std::string* error);

  CovarianceForm form_ = CovarianceForm::NodalDiag;
  Eigen::VectorXd weights_;
  Eigen::MatrixXd means_;
  std::vector<Eigen::MatrixXd> covariances_;
  // Cache, rebuilt deterministically from the parameters: the kernel works in a frame centred on
  // the weighted mean of the component means (centre_), which keeps large common offsets out of
  // the Mahalanobis sums.
  Eigen::VectorXd centre_;
  GmmDensityCache cache_;
};

}  // namespace tactile::analysis
