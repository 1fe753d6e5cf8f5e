// Internal: the blocked, vectorised density kernel shared by EM (gmm.cpp) and GaussianMixture's
// evaluation. Not part of the public API.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace tactile {

// Everything needed to evaluate log w_i + log N(x | mu_i, Sigma_i) for all components, in some
// coordinate frame (the caller subtracts the same centre from x that was subtracted from the
// means).
struct GmmDensityCache {
  int components = 0;
  int dimension = 0;
  bool diagonal = true;
  bool nodal = true;
  Eigen::MatrixXd means;               // K x D
  Eigen::MatrixXd scales;              // diagonal forms: K x D (nodal) or 1 x D, 1/sigma
  std::vector<Eigen::MatrixXd> upper;  // full forms: U_i = L_i^{-T} (upper), K or 1 of them
  Eigen::VectorXd logConstants;        // log w_i - D/2 log(2 pi) - 1/2 log|Sigma_i|
};

// Builds the cache from weights, means (in the kernel's frame) and covariances. Returns false and
// the 0-based index of the first covariance that is not positive definite in *badComponent.
bool buildDensityCache(const Eigen::VectorXd& weights, const Eigen::MatrixXd& means,
                       const std::vector<Eigen::MatrixXd>& covariances, bool diagonal, bool nodal,
                       GmmDensityCache& cache, int* badComponent);

// Rows are processed eight at a time: `rows` must be a multiple of 8 (pad the block with zero
// rows), and x must hold that many readable rows per column.

// out(b, i) = log w_i + log N(x_b | mu_i, Sigma_i) for the rows x_b of a column-major block
// (element (b, d) at x[b + d * ldx]); out is column-major rows x K with leading dimension ld.
void blockComponentLogDensities(const GmmDensityCache& cache, const double* x, Eigen::Index ldx,
                                int rows, double* out, int ld);

// M-step statistics of a block around the cached means c_i, with responsibilities resp (rows x K,
// leading dimension ld; padding rows must have responsibility 0):
// nk(i) += sum_b r_bi; s1(i, j) += sum_b r_bi (x_bj - c_ij); diagonal forms: s2(i, j) +=
// sum_b r_bi (x_bj - c_ij)^2; full forms: the lower triangle of block i of s2 (D x K*D) +=
// sum_b r_bi (x_b - c_i)(x_b - c_i)^T. Lanes are summed in a fixed order (deterministic).
void blockAccumulateStats(const GmmDensityCache& cache, const double* x, Eigen::Index ldx, int rows,
                          const double* resp, int ld, Eigen::VectorXd& nk, Eigen::MatrixXd& s1,
                          Eigen::MatrixXd& s2);

// Row-wise log-sum-exp of a column-major B x K block (B a multiple of 8; logSum holds B): logSum[b]
// = log sum_i exp(in(b, i)). If resp is non-null it receives exp(in(b, i) - logSum[b])
// (responsibilities, rows sum to 1). A row whose entries are all -inf gets logSum = -inf and
// uniform responsibilities. scratch must hold 2 * B doubles. in and resp are column-major with
// leading dimension ld >= B. Buffers should be 64-byte aligned with ld a multiple of 8 so that
// vectorised reductions over them do not depend on where they were allocated (bit-identical results
// whatever the thread).
void blockLogSumExp(const double* in, int ld, int rows, int components, double* logSum,
                    double* resp, double* scratch);

}  // namespace tactile
