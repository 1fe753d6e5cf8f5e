// GCC 12 reports false -Wmaybe-uninitialized inside Eigen's AVX-512 kernels at -O3.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "analysis/gmm_kernels.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "analysis/gaussian.h"

namespace tactile {

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
  cache.upper.clear();
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
    cache.upper.resize(static_cast<std::size_t>(covCount));
    Eigen::MatrixXd lower;
    for (int i = 0; i < covCount; ++i) {
      if (!choleskyLower(covariances[static_cast<std::size_t>(i)], lower)) {
        if (badComponent) *badComponent = i;
        return false;
      }
      logDets(i) = logDeterminantFromCholesky(lower);
      Eigen::MatrixXd inv =
          lower.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(d, d));
      cache.upper[static_cast<std::size_t>(i)] = inv.transpose().triangularView<Eigen::Upper>();
      if (!cache.upper[static_cast<std::size_t>(i)].allFinite() || !std::isfinite(logDets(i))) {
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

// Eight doubles: one AVX-512 register (two AVX2 registers on machines without AVX-512). GCC's
// generic vectors keep the kernels portable; -march decides the instructions.
typedef double V __attribute__((vector_size(64)));
constexpr int kLanes = 8;
inline V loadV(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void storeV(double* p, V v) {
  std::memcpy(p, &v, sizeof v);
}
inline V splat(double a) {
  return V{} + a;
}
// Lanes summed in a fixed order (deterministic).
inline double hsum(V v) {
  return ((v[0] + v[1]) + (v[2] + v[3])) + ((v[4] + v[5]) + (v[6] + v[7]));
}

typedef long long VI __attribute__((vector_size(64)));

// exp(x) for x <= 0 (x = -inf allowed): Cody-Waite reduction x = n ln2 + r, |r| <= ln2/2, degree
// 13 Taylor polynomial (truncation < 1e-17 relative), scaled by 2^n through the exponent bits.
// Results below exp(-708) (about 1e-308) are flushed to 0.
inline V expNonPositive(V x) {
  const V lowest = splat(-708.0);
  const auto under = x < lowest;
  x = under ? lowest : x;
  const V n = (x * 1.4426950408889634 + 0x1.8p52) - 0x1.8p52;  // round to nearest
  V r = x - n * 6.93147180369123816490e-01;                    // ln2, high part (exact product)
  r = r - n * 1.90821492927058770002e-10;                      // ln2, low part
  V p = splat(1.0 / 6227020800.0);
  p = p * r + 1.0 / 479001600.0;
  p = p * r + 1.0 / 39916800.0;
  p = p * r + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  VI bits = __builtin_convertvector(n, VI) + 1023;
  bits <<= 52;
  const V result = p * (V)bits;
  return under ? V{} : result;
}

// log(x) for normal x > 0 (here x >= 1, a sum of exponentials containing exp(0)): x = m 2^e with
// m in [sqrt(1/2), sqrt(2)), log m = 2 atanh(s), s = (m - 1)/(m + 1), series to s^21.
inline V logAtLeastOne(V x) {
  const VI bits = (VI)x;
  const VI e = (bits >> 52) - 1023;
  const VI mbits = (bits & 0x000FFFFFFFFFFFFFLL) | 0x3FF0000000000000LL;
  V m = (V)mbits;
  const auto big = m > 1.4142135623730951;
  m = big ? m * 0.5 : m;
  const V ef = __builtin_convertvector(e, V) + (big ? splat(1.0) : V{});
  const V s = (m - 1.0) / (m + 1.0);
  const V s2 = s * s;
  V p = splat(1.0 / 21.0);
  p = p * s2 + 1.0 / 19.0;
  p = p * s2 + 1.0 / 17.0;
  p = p * s2 + 1.0 / 15.0;
  p = p * s2 + 1.0 / 13.0;
  p = p * s2 + 1.0 / 11.0;
  p = p * s2 + 1.0 / 9.0;
  p = p * s2 + 1.0 / 7.0;
  p = p * s2 + 1.0 / 5.0;
  p = p * s2 + 1.0 / 3.0;
  p = p * s2 + 1.0;
  return ef * 6.93147180369123816490e-01 + (ef * 1.90821492927058770002e-10 + 2.0 * s * p);
}

// E-step kernel for dimension D (compile-time when D > 0, runtime d otherwise).
template <int D>
void logDensitiesKernel(const GmmDensityCache& cache, const double* x, Eigen::Index ldx, int rows,
                        double* out, int ld) {
  const int d = D > 0 ? D : cache.dimension;
  const int k = cache.components;
  std::vector<double> m(static_cast<std::size_t>(d)), sc(static_cast<std::size_t>(d));
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < d; ++j)
      m[static_cast<std::size_t>(j)] = cache.means(i, j);
    const V c = splat(cache.logConstants(i));
    double* o = out + static_cast<std::ptrdiff_t>(i) * ld;
    if (cache.diagonal) {
      const int row = cache.nodal ? i : 0;
      for (int j = 0; j < d; ++j)
        sc[static_cast<std::size_t>(j)] = cache.scales(row, j);
      for (int r = 0; r < rows; r += kLanes) {
        V acc = V{};
        for (int j = 0; j < d; ++j) {
          const V t = (loadV(x + j * ldx + r) - m[static_cast<std::size_t>(j)]) *
                      sc[static_cast<std::size_t>(j)];
          acc += t * t;
        }
        storeV(o + r, c - 0.5 * acc);
      }
    } else {
      const double* u = cache.upper[static_cast<std::size_t>(cache.nodal ? i : 0)].data();
      constexpr int kMaxZ = D > 0 ? D : 16;
      if (d > kMaxZ) {
        // Large dimensions: z in a scratch column per dimension.
        std::vector<V> z(static_cast<std::size_t>(d));
        for (int r = 0; r < rows; r += kLanes) {
          for (int j = 0; j < d; ++j)
            z[static_cast<std::size_t>(j)] =
                loadV(x + j * ldx + r) - m[static_cast<std::size_t>(j)];
          V acc = V{};
          for (int j = 0; j < d; ++j) {
            V y = V{};
            for (int l = 0; l <= j; ++l)
              y += z[static_cast<std::size_t>(l)] * u[l + j * d];
            acc += y * y;
          }
          storeV(o + r, c - 0.5 * acc);
        }
        continue;
      }
      for (int r = 0; r < rows; r += kLanes) {
        V z[kMaxZ];
        for (int j = 0; j < d; ++j)
          z[j] = loadV(x + j * ldx + r) - m[static_cast<std::size_t>(j)];
        V acc = V{};
        // y_j = sum_{l <= j} z_l U_lj (U = L^{-T} upper triangular); acc = |y|^2.
        for (int j = 0; j < d; ++j) {
          V y = z[0] * u[j * d];
          for (int l = 1; l <= j; ++l)
            y += z[l] * u[l + j * d];
          acc += y * y;
        }
        storeV(o + r, c - 0.5 * acc);
      }
    }
  }
}

// M-step statistics around the cached means, for dimension D (runtime d when D == 0).
template <int D>
void statsKernel(const GmmDensityCache& cache, const double* x, Eigen::Index ldx, int rows,
                 const double* resp, int ld, Eigen::VectorXd& nk, Eigen::MatrixXd& s1,
                 Eigen::MatrixXd& s2) {
  const int d = D > 0 ? D : cache.dimension;
  const int k = cache.components;
  constexpr int kMax = D > 0 ? D : 1;
  std::vector<double> m(static_cast<std::size_t>(d));
  std::vector<V> a1v(D > 0 ? 0 : static_cast<std::size_t>(d));
  std::vector<V> a2v(D > 0 ? 0 : static_cast<std::size_t>(cache.diagonal ? d : d * d));
  std::vector<V> zv(D > 0 ? 0 : static_cast<std::size_t>(2 * d));
  for (int i = 0; i < k; ++i) {
    const double* w = resp + static_cast<std::ptrdiff_t>(i) * ld;
    for (int j = 0; j < d; ++j)
      m[static_cast<std::size_t>(j)] = cache.means(i, j);
    V a1s[kMax];
    V a2s[kMax * kMax];
    V* a1 = D > 0 ? a1s : a1v.data();
    V* a2 = D > 0 ? a2s : a2v.data();
    const int n2 = cache.diagonal ? d : d * d;
    for (int j = 0; j < d; ++j)
      a1[j] = V{};
    for (int j = 0; j < n2; ++j)
      a2[j] = V{};
    V ws = V{};
    bool any = false;
    for (int r = 0; r < rows; r += kLanes) {
      const V wv = loadV(w + r);
      ws += wv;
      any = true;
      if (cache.diagonal) {
        for (int j = 0; j < d; ++j) {
          const V z = loadV(x + j * ldx + r) - m[static_cast<std::size_t>(j)];
          const V wz = wv * z;
          a1[j] += wz;
          a2[j] += wz * z;
        }
      } else {
        V zs[kMax * 2];
        V* z = D > 0 ? zs : zv.data();
        V* wz = z + d;
        for (int j = 0; j < d; ++j) {
          z[j] = loadV(x + j * ldx + r) - m[static_cast<std::size_t>(j)];
          wz[j] = wv * z[j];
          a1[j] += wz[j];
        }
        for (int j = 0; j < d; ++j)
          for (int l = 0; l <= j; ++l)
            a2[j * d + l] += wz[j] * z[l];
      }
    }
    if (!any) continue;
    const double wsum = hsum(ws);
    if (wsum == 0.0) continue;  // contributes exactly nothing
    nk(i) += wsum;
    for (int j = 0; j < d; ++j)
      s1(i, j) += hsum(a1[j]);
    if (cache.diagonal) {
      for (int j = 0; j < d; ++j)
        s2(i, j) += hsum(a2[j]);
    } else {
      auto block = s2.middleCols(static_cast<Eigen::Index>(i) * d, d);
      for (int j = 0; j < d; ++j)
        for (int l = 0; l <= j; ++l)
          block(j, l) += hsum(a2[j * d + l]);
    }
  }
}

}  // namespace

void blockComponentLogDensities(const GmmDensityCache& cache, const double* x, Eigen::Index ldx,
                                int rows, double* out, int ld) {
  switch (cache.dimension) {
    case 1:
      return logDensitiesKernel<1>(cache, x, ldx, rows, out, ld);
    case 2:
      return logDensitiesKernel<2>(cache, x, ldx, rows, out, ld);
    case 3:
      return logDensitiesKernel<3>(cache, x, ldx, rows, out, ld);
    case 4:
      return logDensitiesKernel<4>(cache, x, ldx, rows, out, ld);
    case 5:
      return logDensitiesKernel<5>(cache, x, ldx, rows, out, ld);
    case 6:
      return logDensitiesKernel<6>(cache, x, ldx, rows, out, ld);
    case 8:
      return logDensitiesKernel<8>(cache, x, ldx, rows, out, ld);
    case 10:
      return logDensitiesKernel<10>(cache, x, ldx, rows, out, ld);
    case 12:
      return logDensitiesKernel<12>(cache, x, ldx, rows, out, ld);
    default:
      return logDensitiesKernel<0>(cache, x, ldx, rows, out, ld);
  }
}

void blockAccumulateStats(const GmmDensityCache& cache, const double* x, Eigen::Index ldx, int rows,
                          const double* resp, int ld, Eigen::VectorXd& nk, Eigen::MatrixXd& s1,
                          Eigen::MatrixXd& s2) {
  switch (cache.dimension) {
    case 1:
      return statsKernel<1>(cache, x, ldx, rows, resp, ld, nk, s1, s2);
    case 2:
      return statsKernel<2>(cache, x, ldx, rows, resp, ld, nk, s1, s2);
    case 3:
      return statsKernel<3>(cache, x, ldx, rows, resp, ld, nk, s1, s2);
    case 4:
      return statsKernel<4>(cache, x, ldx, rows, resp, ld, nk, s1, s2);
    case 5:
      return statsKernel<5>(cache, x, ldx, rows, resp, ld, nk, s1, s2);
    case 6:
      return statsKernel<6>(cache, x, ldx, rows, resp, ld, nk, s1, s2);
    case 8:
      return statsKernel<8>(cache, x, ldx, rows, resp, ld, nk, s1, s2);
    case 10:
      return statsKernel<10>(cache, x, ldx, rows, resp, ld, nk, s1, s2);
    case 12:
      return statsKernel<12>(cache, x, ldx, rows, resp, ld, nk, s1, s2);
    default:
      return statsKernel<0>(cache, x, ldx, rows, resp, ld, nk, s1, s2);
  }
}

void blockLogSumExp(const double* in, int ld, int rows, int components, double* logSum,
                    double* resp, double* /*scratch*/) {
  const double ninf = -std::numeric_limits<double>::infinity();
  bool anyDead = false;
  for (int r = 0; r < rows; r += kLanes) {
    V mx = splat(ninf);
    for (int i = 0; i < components; ++i) {
      const V v = loadV(in + static_cast<std::ptrdiff_t>(i) * ld + r);
      mx = v > mx ? v : mx;
    }
    // Rows whose max is -inf (every component impossible) are shifted by 0 (no inf - inf).
    const auto dead = mx == splat(ninf);
    const V shift = dead ? V{} : mx;
    V sum = V{};
    for (int i = 0; i < components; ++i) {
      const V e = expNonPositive(loadV(in + static_cast<std::ptrdiff_t>(i) * ld + r) - shift);
      if (resp) storeV(resp + static_cast<std::ptrdiff_t>(i) * ld + r, e);
      sum += e;
    }
    if (resp) {
      const V inv = 1.0 / sum;
      for (int i = 0; i < components; ++i) {
        double* p = resp + static_cast<std::ptrdiff_t>(i) * ld + r;
        storeV(p, loadV(p) * inv);
      }
    }
    storeV(logSum + r, logAtLeastOne(sum) + shift);
    for (int l = 0; l < kLanes; ++l)
      anyDead = anyDead || dead[l] != 0;
  }
  if (!anyDead) return;
  for (int r = 0; r < rows; ++r) {
    bool isDead = true;
    for (int i = 0; i < components && isDead; ++i)
      isDead = !(in[static_cast<std::ptrdiff_t>(i) * ld + r] > ninf);
    if (!isDead) continue;
    logSum[r] = ninf;
    if (resp)
      for (int i = 0; i < components; ++i)
        resp[static_cast<std::ptrdiff_t>(i) * ld + r] = 1.0 / components;
  }
}

}  // namespace tactile
