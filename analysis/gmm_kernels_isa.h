// Internal: the raw views and entry points of the per-instruction-set kernel copies
// (gmm_kernels_impl.h). Plain pointers only, no Eigen: see gmm_kernels_impl.h for why.
#pragma once

#include <cstddef>

namespace tactile::analysis {

// Raw views handed to the per-level kernels (plain pointers only; see gmm_kernels_impl.h).
struct KernelDensityView {
  int components = 0;
  int dimension = 0;
  bool diagonal = true;
  bool nodal = true;
  const double* means = nullptr;         // column-major K x D
  const double* scales = nullptr;        // column-major (K or 1) x D
  const double* upper = nullptr;         // (K or 1) column-major D x D blocks, one after another
  const double* logConstants = nullptr;  // K
};
struct KernelStatsView {
  double* nk = nullptr;  // K
  double* s1 = nullptr;  // column-major K x D
  double* s2 = nullptr;  // diagonal: column-major K x D; full: column-major D x (K*D)
};

#define TACTILE_DECLARE_KERNELS(ns)                                                                \
  namespace ns {                                                                                   \
  void blockComponentLogDensities(const KernelDensityView& c, const double* x, std::ptrdiff_t ldx, \
                                  int rows, double* out, int ld);                                  \
  void blockAccumulateStats(const KernelDensityView& c, const double* x, std::ptrdiff_t ldx,       \
                            int rows, const double* resp, int ld, const KernelStatsView& s);       \
  void blockLogSumExp(const double* in, int ld, int rows, int components, double* logSum,          \
                      double* resp);                                                               \
  double squaredDistances(const double* x, std::ptrdiff_t ldx, std::ptrdiff_t rows, int d,         \
                          const double* centre, const double* current, double* out);               \
  double nearestCentres(const double* x, std::ptrdiff_t ldx, std::ptrdiff_t rows, int d,           \
                        const double* centres, int k, int* bestIndex);                             \
  }
TACTILE_DECLARE_KERNELS(kernels_generic)
TACTILE_DECLARE_KERNELS(kernels_x86_64_v2)
TACTILE_DECLARE_KERNELS(kernels_x86_64_v3)
TACTILE_DECLARE_KERNELS(kernels_x86_64_v4)
#undef TACTILE_DECLARE_KERNELS

}  // namespace tactile::analysis
