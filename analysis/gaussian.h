// Gaussian densities in log space through Cholesky factors, and small numerical helpers shared by
// the Gaussian classifier and EM.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <string>

namespace tactile::analysis {

inline constexpr double kLog2Pi = 1.83787706640934548356065947281123527;

// log sum_i exp(v_i), stable: m + log sum_i exp(v_i - m) with m = max_i v_i. -inf for an empty
// list or when every v_i is -inf.
double logSumExp(const double* values, int count);

// Sigma = L L^T for a symmetric matrix (only the lower triangle is read). Returns false when a
// pivot is not positive and finite, i.e. Sigma is not (numerically) positive definite.
bool choleskyLower(const Eigen::MatrixXd& sigma, Eigen::MatrixXd& lower);

// log|Sigma| = 2 sum_i log L_ii.
double logDeterminantFromCholesky(const Eigen::MatrixXd& lower);

// log N(x | mu, Sigma) = -D/2 log(2 pi) - 1/2 log|Sigma| - 1/2 |L^{-1}(x - mu)|^2, with Sigma = L
// L^T (forward substitution on x - mu, no inverse formed).
double gaussianLogDensity(const Eigen::Ref<const Eigen::VectorXd>& x,
                          const Eigen::Ref<const Eigen::VectorXd>& mean,
                          const Eigen::MatrixXd& lower, double logDet);

// Symmetric matrix with its eigenvalues clamped from below: U max(Lambda, minimum) U^T (the
// constrained maximum-likelihood covariance with smallest eigenvalue >= minimum). Symmetrises the
// input first.
Eigen::MatrixXd clampEigenvalues(const Eigen::MatrixXd& sigma, double minimum);

// True when every entry is finite.
bool allFinite(const Eigen::MatrixXd& m);

// splitmix64: the seed mixer used for every random stream of the learning code, so streams are
// identical on every platform and standard library.
std::uint64_t splitMix64(std::uint64_t& state);

// Small deterministic random source (xoshiro256**), seeded through splitmix64.
class Rng {
 public:
  explicit Rng(std::uint64_t seed);
  std::uint64_t next();
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  // Uniform integer in [0, n), n > 0.
  std::uint64_t below(std::uint64_t n);

 private:
  std::uint64_t s_[4];
};

}  // namespace tactile::analysis
