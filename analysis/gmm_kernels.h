// Internal: the blocked, vectorised density kernels shared by EM (gmm.cpp), GaussianMixture's
// evaluation and k-means (kmeans.cpp). Not part of the public API.
//
// The kernels are compiled three times, for the x86-64 levels v2 (SSE4.2), v3 (AVX2 + FMA) and v4
// (AVX-512), and the best level the processor supports is chosen once at run time; the rest of
// the program is built for the baseline. On other architectures one generic copy is built.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/gmm_kernels_isa.h"

namespace tactile::analysis {

// Rows per block of the blocked density evaluation.
inline constexpr Eigen::Index kDensityBlockRows = 256;
// Rows rounded up to the kernels' vector width (8).
inline int paddedRows(Eigen::Index rows) {
  return static_cast<int>((rows + 7) / 8 * 8);
}

// Everything needed to evaluate log w_i + log N(x | mu_i, Sigma_i) for all components, in some
// coordinate frame (the caller subtracts the same centre from x that was subtracted from the
// means).
struct GmmDensityCache {
  int components = 0;
  int dimension = 0;
  bool diagonal = true;
  bool nodal = true;
  Eigen::MatrixXd means;         // K x D
  Eigen::MatrixXd scales;        // diagonal forms: K x D (nodal) or 1 x D, 1/sigma
  Eigen::MatrixXd upper;         // full forms: D x (K*D) or D x D, block i is U_i = L_i^{-T}
  Eigen::VectorXd logConstants;  // log w_i - D/2 log(2 pi) - 1/2 log|Sigma_i|
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
// uniform responsibilities. scratch is unused (kept for callers). in and resp are column-major with
// leading dimension ld >= B. Buffers should be 64-byte aligned with ld a multiple of 8 so that
// vectorised reductions over them do not depend on where they were allocated (bit-identical results
// whatever the thread).
void blockLogSumExp(const double* in, int ld, int rows, int components, double* logSum,
                    double* resp, double* scratch = nullptr);

// k-means: out[r] = min(current[r], |x_r - centre|^2) (just the distance when current is null)
// for `rows` rows of a column-major block (element (r, j) at x[r + j * ldx]); returns the sum of
// out, added in a fixed order.
double blockSquaredDistances(const double* x, Eigen::Index ldx, Eigen::Index rows, int d,
                             const double* centre, const double* current, double* out);

// k-means: index of the nearest of k centres (column-major k x d, element (i, j) at
// centres[i + j * k]) of every row, ties to the lowest index; returns the sum of the squared
// distances to them, added in a fixed order.
double blockNearestCentres(const double* x, Eigen::Index ldx, Eigen::Index rows, int d,
                           const double* centres, int k, int* bestIndex);

// The instruction-set level whose kernels run: "x86-64-v2", "x86-64-v3", "x86-64-v4" or
// "generic". Chosen on first use: the best level the processor supports, or the level named by
// the environment variable TACTILE_KERNEL_ISA when the processor supports it.
std::string kernelIsa();
// Every level this processor can run (for tests and benchmarks), best last.
std::vector<std::string> supportedKernelIsas();
// Switches to a supported level (tests and benchmarks; not while kernels run on other threads).
// Returns false, changing nothing, for an unknown or unsupported level.
bool setKernelIsa(const std::string& isa);

}  // namespace tactile::analysis
