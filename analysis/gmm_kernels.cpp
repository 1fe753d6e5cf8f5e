#include "analysis/gmm_kernels.h"

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "analysis/gaussian.h"

namespace tactile::analysis {

bool buildDensityCache(const Eigen::VectorXd& weights, const Eigen::MatrixXd& means,
                       const std::vector<Eigen::MatrixXd>& covariances, bool diagonal, bool nodal,
                       GmmDensityCache& cache, int* badComponent) {
  const int k = static_cast<int>(weights.size());
  const int d = static_cast<int>(means.cols());
  cache.components = k;
  cache.dimension = d;
  cache.diagonal = diagonal;
  cache.nodal = nodal;
  cache.means = means;
  cache.logConstants.resize(k);
  cache.upper.resize(0, 0);
  const int covCount = nodal ? k : 1;
  Eigen::VectorXd logDets(covCount);
  if (diagonal) {
    cache.scales.resize(covCount, d);
    for (int i = 0; i < covCount; ++i) {
      double logDet = 0.0;
      for (int j = 0; j < d; ++j) {
        const double v = covariances[static_cast<std::size_t>(i)](j, j);
        const double s = 1.0 / std::sqrt(v);
        if (!(v > 0.0) || !std::isfinite(v) || !std::isfinite(s)) {
          if (badComponent) *badComponent = i;
          return false;
        }
        cache.scales(i, j) = s;
        logDet += std::log(v);
      }
      logDets(i) = logDet;
    }
  } else {
    cache.scales.resize(0, 0);
    cache.upper.resize(d, static_cast<Eigen::Index>(covCount) * d);
    Eigen::MatrixXd lower;
    for (int i = 0; i < covCount; ++i) {
      if (!choleskyLower(covariances[static_cast<std::size_t>(i)], lower)) {
        if (badComponent) *badComponent = i;
        return false;
      }
      logDets(i) = logDeterminantFromCholesky(lower);
      Eigen::MatrixXd inv =
          lower.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(d, d));
      auto block = cache.upper.middleCols(static_cast<Eigen::Index>(i) * d, d);
      block = inv.transpose().triangularView<Eigen::Upper>();
      if (!block.allFinite() || !std::isfinite(logDets(i))) {
        if (badComponent) *badComponent = i;
        return false;
      }
    }
  }
  for (int i = 0; i < k; ++i) {
    const double logDet = logDets(nodal ? i : 0);
    const double w = weights(i);
    cache.logConstants(i) = (w > 0.0 ? std::log(w) : -std::numeric_limits<double>::infinity()) -
                            0.5 * (static_cast<double>(d) * kLog2Pi + logDet);
  }
  return true;
}

namespace {

struct KernelTable {
  const char* isa;
  decltype(&kernels_generic::blockComponentLogDensities) logDensities;
  decltype(&kernels_generic::blockAccumulateStats) accumulateStats;
  decltype(&kernels_generic::blockLogSumExp) logSumExp;
  decltype(&kernels_generic::squaredDistances) squaredDistances;
  decltype(&kernels_generic::nearestCentres) nearestCentres;
};

#define TACTILE_KERNEL_TABLE(name, ns)                                                     \
  KernelTable {                                                                            \
    name, &ns::blockComponentLogDensities, &ns::blockAccumulateStats, &ns::blockLogSumExp, \
        &ns::squaredDistances, &ns::nearestCentres                                         \
  }

// Supported levels, worst first.
std::vector<KernelTable> supportedTables() {
  std::vector<KernelTable> tables;
#if defined(TACTILE_KERNELS_X86_64)
  __builtin_cpu_init();
  // The level names test exactly the feature sets -march=x86-64-vN compiles for (GCC 12+), and
  // include the operating system's support for the wider registers.
  const bool v2 = __builtin_cpu_supports("x86-64-v2");
  const bool v3 = v2 && __builtin_cpu_supports("x86-64-v3");
  const bool v4 = v3 && __builtin_cpu_supports("x86-64-v4");
  tables.push_back(TACTILE_KERNEL_TABLE("generic", kernels_generic));
  if (v2) tables.push_back(TACTILE_KERNEL_TABLE("x86-64-v2", kernels_x86_64_v2));
  if (v3) tables.push_back(TACTILE_KERNEL_TABLE("x86-64-v3", kernels_x86_64_v3));
  if (v4) tables.push_back(TACTILE_KERNEL_TABLE("x86-64-v4", kernels_x86_64_v4));
#else
  tables.push_back(TACTILE_KERNEL_TABLE("generic", kernels_generic));
#endif
  return tables;
}
#undef TACTILE_KERNEL_TABLE

const KernelTable* chooseInitial() {
  static const std::vector<KernelTable> tables = supportedTables();
  const char* wanted = std::getenv("TACTILE_KERNEL_ISA");
  if (wanted && *wanted)
    for (const KernelTable& t : tables)
      if (std::strcmp(t.isa, wanted) == 0) return &t;
  return &tables.back();
}

std::atomic<const KernelTable*>& current() {
  static std::atomic<const KernelTable*> table{chooseInitial()};
  return table;
}

const KernelTable& kernels() {
  return *current().load(std::memory_order_relaxed);
}

KernelDensityView viewOf(const GmmDensityCache& c) {
  KernelDensityView v;
  v.components = c.components;
  v.dimension = c.dimension;
  v.diagonal = c.diagonal;
  v.nodal = c.nodal;
  v.means = c.means.data();
  v.scales = c.scales.data();
  v.upper = c.upper.data();
  v.logConstants = c.logConstants.data();
  return v;
}

}  // namespace

std::string kernelIsa() {
  return kernels().isa;
}

std::vector<std::string> supportedKernelIsas() {
  std::vector<std::string> names;
  for (const KernelTable& t : supportedTables())
    names.emplace_back(t.isa);
  return names;
}

bool setKernelIsa(const std::string& isa) {
  static const std::vector<KernelTable> tables = supportedTables();
  for (const KernelTable& t : tables)
    if (isa == t.isa) {
      current().store(&t, std::memory_order_relaxed);
      return true;
    }
  return false;
}

void blockComponentLogDensities(const GmmDensityCache& cache, const double* x, Eigen::Index ldx,
                                int rows, double* out, int ld) {
  kernels().logDensities(viewOf(cache), x, ldx, rows, out, ld);
}

void blockAccumulateStats(const GmmDensityCache& cache, const double* x, Eigen::Index ldx, int rows,
                          const double* resp, int ld, Eigen::VectorXd& nk, Eigen::MatrixXd& s1,
                          Eigen::MatrixXd& s2) {
  KernelStatsView s;
  s.nk = nk.data();
  s.s1 = s1.data();
  s.s2 = s2.data();
  kernels().accumulateStats(viewOf(cache), x, ldx, rows, resp, ld, s);
}

void blockLogSumExp(const double* in, int ld, int rows, int components, double* logSum,
                    double* resp, double* /*scratch*/) {
  kernels().logSumExp(in, ld, rows, components, logSum, resp);
}

double blockSquaredDistances(const double* x, Eigen::Index ldx, Eigen::Index rows, int d,
                             const double* centre, const double* current, double* out) {
  return kernels().squaredDistances(x, ldx, rows, d, centre, current, out);
}

double blockNearestCentres(const double* x, Eigen::Index ldx, Eigen::Index rows, int d,
                           const double* centres, int k, int* bestIndex) {
  return kernels().nearestCentres(x, ldx, rows, d, centres, k, bestIndex);
}

}  // namespace tactile::analysis
