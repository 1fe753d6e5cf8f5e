// Internal: the bodies of the hot EM and k-means kernels, compiled once per instruction-set level
// (gmm_kernels_x86_64_v2.cpp, _v3.cpp, _v4.cpp, each with its own -march) and chosen at run time
// by gmm_kernels.cpp. The including file defines TACTILE_KERNEL_NS, the namespace of its copy.
//
// Everything here has internal linkage or lives in that per-level namespace, and the code uses
// raw pointers only (no Eigen or standard-library templates): an inline function from a shared
// header compiled with AVX-512 in one copy could otherwise be merged by the linker into code that
// runs on machines without it.
#ifndef TACTILE_KERNEL_NS
#error "define TACTILE_KERNEL_NS before including gmm_kernels_impl.h"
#endif

// The 64-byte vector type is passed between inline helpers only; no ABI is at stake.
#pragma GCC diagnostic ignored "-Wpsabi"

#include <cstddef>
#include <new>

#include "analysis/gmm_kernels_isa.h"

namespace tactile::analysis::TACTILE_KERNEL_NS {
namespace {

// Eight rows per vector on every level, held as one AVX-512 register, two AVX2 registers or four
// SSE registers (the widest the level has: GCC splits wider generic vectors badly, comparisons
// and selects lane by lane through memory). The same eight lanes everywhere keep the order of
// every sum the same on every level.
#if defined(__AVX512F__)
constexpr int kNative = 8;
#elif defined(__AVX__)
constexpr int kNative = 4;
#else
constexpr int kNative = 2;
#endif
constexpr int kLanes = 8;
constexpr int kParts = kLanes / kNative;
typedef double N __attribute__((vector_size(kNative * 8)));
typedef long long NI __attribute__((vector_size(kNative * 8)));
typedef unsigned long long NU __attribute__((vector_size(kNative * 8)));

// Eight doubles.
struct V {
  N p[kParts];
};
// Eight lane masks (all bits set where true), as from a comparison of N.
struct M {
  NI p[kParts];
};

#define TACTILE_PACK_OP(op)                      \
  inline V operator op(const V& a, const V& b) { \
    V r;                                         \
    for (int i = 0; i < kParts; ++i)             \
      r.p[i] = a.p[i] op b.p[i];                 \
    return r;                                    \
  }                                              \
  inline V operator op(const V& a, double b) {   \
    V r;                                         \
    for (int i = 0; i < kParts; ++i)             \
      r.p[i] = a.p[i] op b;                      \
    return r;                                    \
  }                                              \
  inline V operator op(double a, const V& b) {   \
    V r;                                         \
    for (int i = 0; i < kParts; ++i)             \
      r.p[i] = a op b.p[i];                      \
    return r;                                    \
  }                                              \
  inline V& operator op##=(V& a, const V& b) {   \
    for (int i = 0; i < kParts; ++i)             \
      a.p[i] = a.p[i] op b.p[i];                 \
    return a;                                    \
  }
TACTILE_PACK_OP(+)
TACTILE_PACK_OP(-)
TACTILE_PACK_OP(*)
TACTILE_PACK_OP(/)
#undef TACTILE_PACK_OP

inline M less(const V& a, const V& b) {
  M m;
  for (int i = 0; i < kParts; ++i)
    m.p[i] = a.p[i] < b.p[i];
  return m;
}
inline M equal(const V& a, const V& b) {
  M m;
  for (int i = 0; i < kParts; ++i)
    m.p[i] = a.p[i] == b.p[i];
  return m;
}
// m ? a : b, lane by lane.
inline V select(const M& m, const V& a, const V& b) {
  V r;
  for (int i = 0; i < kParts; ++i)
    r.p[i] = m.p[i] ? a.p[i] : b.p[i];
  return r;
}
inline bool anyLane(const M& m) {
  NI acc = m.p[0];
  for (int i = 1; i < kParts; ++i)
    acc |= m.p[i];
  for (int l = 0; l < kNative; ++l)
    if (acc[l]) return true;
  return false;
}
inline double lane(const V& v, int l) {
  return v.p[l / kNative][l % kNative];
}

// Unaligned, aliasing access to a native vector's worth of doubles (a memcpy into the pack goes
// through the stack on AVX2).
typedef double NA __attribute__((vector_size(kNative * 8), aligned(8), may_alias));
inline V loadV(const double* p) {
  V v;
  for (int i = 0; i < kParts; ++i)
    v.p[i] = *reinterpret_cast<const NA*>(p + i * kNative);
  return v;
}
inline void storeV(double* p, const V& v) {
  for (int i = 0; i < kParts; ++i)
    *reinterpret_cast<NA*>(p + i * kNative) = v.p[i];
}
inline V splat(double a) {
  V r;
  for (int i = 0; i < kParts; ++i)
    r.p[i] = N{} + a;
  return r;
}
inline V zero() {
  return splat(0.0);
}
// Lanes summed in a fixed order (deterministic).
inline double hsum(const V& v) {
  return ((lane(v, 0) + lane(v, 1)) + (lane(v, 2) + lane(v, 3))) +
         ((lane(v, 4) + lane(v, 5)) + (lane(v, 6) + lane(v, 7)));
}

// 1.5 * 2^52: adding it rounds a double of magnitude below 2^51 to an integer held in the low
// mantissa bits, which is how the exponential and the logarithm convert between doubles and
// integers with 64-bit integer adds and shifts only (AVX2 has no double <-> int64 conversion).
constexpr double kRoundMagic = 0x1.8p52;
constexpr long long kRoundMagicBits = 0x4338000000000000LL;

// exp(x) for x <= 0 (x = -inf allowed): Cody-Waite reduction x = n ln2 + r, |r| <= ln2/2, degree
// 13 Taylor polynomial (truncation < 1e-17 relative), scaled by 2^n through the exponent bits.
// Results below exp(-708) (about 1e-308) are flushed to 0.
inline N expNonPositive(N in) {
  const N lowest = N{} - 708.0;
  const auto under = in < lowest;
  const N x = under ? lowest : in;
  const N shifted = x * 1.4426950408889634 + kRoundMagic;  // n in the low mantissa bits
  const N n = shifted - kRoundMagic;                       // round to nearest, -1022 <= n <= 0
  N r = x - n * 6.93147180369123816490e-01;                // ln2, high part (exact product)
  r = r - n * 1.90821492927058770002e-10;                  // ln2, low part
  N p = N{} + 1.0 / 6227020800.0;
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
  // 2^n: biased exponent n + 1023 (>= 1) moved into place.
  const NI bits = (((NI)shifted - kRoundMagicBits) + 1023) << 52;
  const N result = p * (N)bits;
  return under ? N{} : result;
}
inline V expNonPositive(const V& x) {
  V r;
  for (int i = 0; i < kParts; ++i)
    r.p[i] = expNonPositive(x.p[i]);
  return r;
}

// log(x) for normal x > 0 (here x >= 1, a sum of exponentials containing exp(0)): x = m 2^e with
// m in [sqrt(1/2), sqrt(2)), log m = 2 atanh(s), s = (m - 1)/(m + 1), series to s^21.
inline N logAtLeastOne(N x) {
  const NU bits = (NU)x;
  const NU biased = bits >> 52;  // x > 0: the sign bit is 0
  const NU mbits = (bits & 0x000FFFFFFFFFFFFFULL) | 0x3FF0000000000000ULL;
  N m = (N)mbits;
  const auto big = m > 1.4142135623730951;
  m = big ? m * 0.5 : m;
  // The biased exponent as a double, through the same magic number as in expNonPositive.
  const N e = ((N)(biased + (NU)(N{} + kRoundMagic)) - kRoundMagic) - 1023.0;
  const N ef = e + (big ? N{} + 1.0 : N{});
  const N s = (m - 1.0) / (m + 1.0);
  const N s2 = s * s;
  N p = N{} + 1.0 / 21.0;
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
inline V logAtLeastOne(const V& x) {
  V r;
  for (int i = 0; i < kParts; ++i)
    r.p[i] = logAtLeastOne(x.p[i]);
  return r;
}

// A heap array of vectors for dimensions above the compile-time cases (new[] honours V's 64-byte
// alignment).
struct VBuffer {
  explicit VBuffer(std::size_t n) : p(n ? new V[n] : nullptr) {}
  ~VBuffer() { delete[] p; }
  VBuffer(const VBuffer&) = delete;
  VBuffer& operator=(const VBuffer&) = delete;
  V* p;
};

// Row vectors of eight rows evaluated together by the blocked full-covariance kernel below: two
// where a vector is one register (AVX-512), one where it is split over several (the accumulators
// would not fit in AVX2's or SSE's sixteen registers).
constexpr int kBlockRowVectors = kParts == 1 ? 3 : 1;
// Columns of the triangular product computed together.
constexpr int kBlockColumns = 4;

// Full covariance, runtime dimension: the Mahalanobis sums of `rowVectors` (1 or R) vectors of
// eight rows, kBlockColumns columns of y = U^T z at a time, so that each broadcast coefficient of U
// serves every row vector and each loaded z serves every column. Every y_j is summed over l in
// the same order as the plain loop (l = 0, 1, ..., j) and |y|^2 over j in the same order, so the
// result is bit for bit the plain kernel's.
template <int R>
void fullMahalanobisBlock(const V* const* z, const double* u, int d, V* acc) {
  for (int q = 0; q < R; ++q)
    acc[q] = zero();
  for (int j0 = 0; j0 < d; j0 += kBlockColumns) {
    const int jb = d - j0 < kBlockColumns ? d - j0 : kBlockColumns;
    V y[R][kBlockColumns];
    const double* col[kBlockColumns];
    for (int a = 0; a < kBlockColumns; ++a)
      col[a] = u + static_cast<std::ptrdiff_t>(j0 + (a < jb ? a : 0)) * d;
    for (int q = 0; q < R; ++q)
      for (int a = 0; a < kBlockColumns; ++a)
        y[q][a] = z[q][0] * col[a][0];
    // Rows l = 1 .. j0 belong to every column of the block.
    for (int l = 1; l <= j0; ++l) {
      for (int q = 0; q < R; ++q) {
        const V zl = z[q][l];
        for (int a = 0; a < kBlockColumns; ++a)
          y[q][a] += zl * col[a][l];
      }
    }
    // The triangle inside the block: column j0 + a also takes rows j0 + 1 .. j0 + a.
    for (int a = 1; a < jb; ++a)
      for (int l = j0 + 1; l <= j0 + a; ++l)
        for (int q = 0; q < R; ++q)
          y[q][a] += z[q][l] * col[a][l];
    for (int a = 0; a < jb; ++a)
      for (int q = 0; q < R; ++q)
        acc[q] += y[q][a] * y[q][a];
  }
}

// E-step kernel for dimension D (compile-time when D > 0, runtime d otherwise).
template <int D>
void logDensitiesKernel(const KernelDensityView& c, const double* x, std::ptrdiff_t ldx, int rows,
                        double* out, int ld) {
  const int d = D > 0 ? D : c.dimension;
  const int k = c.components;
  constexpr int kMaxZ = D > 0 ? D : 16;
  VBuffer zHeap(D == 0 ? static_cast<std::size_t>(kBlockRowVectors * d) : 0);
  for (int i = 0; i < k; ++i) {
    const double* m = c.means + i;  // column-major K x D: m[j * k]
    const V logConstant = splat(c.logConstants[i]);
    double* o = out + static_cast<std::ptrdiff_t>(i) * ld;
    if (c.diagonal) {
      const int row = c.nodal ? i : 0;
      const int covCount = c.nodal ? k : 1;
      const double* sc = c.scales + row;  // column-major covCount x D
      for (int r = 0; r < rows; r += kLanes) {
        V acc = zero();
        for (int j = 0; j < d; ++j) {
          const V t = (loadV(x + j * ldx + r) - m[j * k]) * sc[j * covCount];
          acc += t * t;
        }
        storeV(o + r, logConstant - 0.5 * acc);
      }
      continue;
    }
    const double* u = c.upper + static_cast<std::ptrdiff_t>(c.nodal ? i : 0) * d * d;
    if constexpr (D == 0) {
      // Runtime dimension (the large ones): blocked over rows and columns.
      V* zr[kBlockRowVectors];
      for (int q = 0; q < kBlockRowVectors; ++q)
        zr[q] = zHeap.p + static_cast<std::ptrdiff_t>(q) * d;
      V acc[kBlockRowVectors];
      int r = 0;
      for (; r + kBlockRowVectors * kLanes <= rows; r += kBlockRowVectors * kLanes) {
        for (int q = 0; q < kBlockRowVectors; ++q)
          for (int j = 0; j < d; ++j)
            zr[q][j] = loadV(x + j * ldx + r + q * kLanes) - m[j * k];
        fullMahalanobisBlock<kBlockRowVectors>(zr, u, d, acc);
        for (int q = 0; q < kBlockRowVectors; ++q)
          storeV(o + r + q * kLanes, logConstant - 0.5 * acc[q]);
      }
      for (; r < rows; r += kLanes) {
        for (int j = 0; j < d; ++j)
          zr[0][j] = loadV(x + j * ldx + r) - m[j * k];
        fullMahalanobisBlock<1>(zr, u, d, acc);
        storeV(o + r, logConstant - 0.5 * acc[0]);
      }
      continue;
    }
    V zStack[kMaxZ];
    V* z = d > kMaxZ ? zHeap.p : zStack;
    for (int r = 0; r < rows; r += kLanes) {
      for (int j = 0; j < d; ++j)
        z[j] = loadV(x + j * ldx + r) - m[j * k];
      V acc = zero();
      // y_j = sum_{l <= j} z_l U_lj (U = L^{-T} upper triangular); acc = |y|^2.
      for (int j = 0; j < d; ++j) {
        V y = z[0] * u[j * d];
        for (int l = 1; l <= j; ++l)
          y += z[l] * u[l + j * d];
        acc += y * y;
      }
      storeV(o + r, logConstant - 0.5 * acc);
    }
  }
}

// M-step statistics around the cached means, for dimension D (runtime d when D == 0).
template <int D>
void statsKernel(const KernelDensityView& c, const double* x, std::ptrdiff_t ldx, int rows,
                 const double* resp, int ld, const KernelStatsView& s) {
  const int d = D > 0 ? D : c.dimension;
  const int k = c.components;
  constexpr int kMax = D > 0 ? D : 1;
  const int n2 = c.diagonal ? d : d * d;
  VBuffer heap(D > 0 ? 0 : static_cast<std::size_t>(d + n2 + 2 * d));
  V a1s[kMax];
  V a2s[kMax * kMax];
  V zs[kMax * 2];
  V* a1 = D > 0 ? a1s : heap.p;
  V* a2 = D > 0 ? a2s : heap.p + d;
  V* z = D > 0 ? zs : heap.p + d + n2;
  V* wz = z + d;
  for (int i = 0; i < k; ++i) {
    const double* w = resp + static_cast<std::ptrdiff_t>(i) * ld;
    const double* m = c.means + i;
    for (int j = 0; j < d; ++j)
      a1[j] = zero();
    for (int j = 0; j < n2; ++j)
      a2[j] = zero();
    V ws = zero();
    for (int r = 0; r < rows; r += kLanes) {
      const V wv = loadV(w + r);
      ws += wv;
      if (c.diagonal) {
        for (int j = 0; j < d; ++j) {
          const V t = loadV(x + j * ldx + r) - m[j * k];
          const V wt = wv * t;
          a1[j] += wt;
          a2[j] += wt * t;
        }
      } else {
        for (int j = 0; j < d; ++j) {
          z[j] = loadV(x + j * ldx + r) - m[j * k];
          wz[j] = wv * z[j];
          a1[j] += wz[j];
        }
        for (int j = 0; j < d; ++j)
          for (int l = 0; l <= j; ++l)
            a2[j * d + l] += wz[j] * z[l];
      }
    }
    const double wsum = hsum(ws);
    if (rows == 0 || wsum == 0.0) continue;  // contributes exactly nothing
    s.nk[i] += wsum;
    for (int j = 0; j < d; ++j)
      s.s1[i + j * k] += hsum(a1[j]);
    if (c.diagonal) {
      for (int j = 0; j < d; ++j)
        s.s2[i + j * k] += hsum(a2[j]);
    } else {
      // Block i of the D x (K*D) column-major s2: element (j, l) at j + (i*D + l) * D.
      double* block = s.s2 + static_cast<std::ptrdiff_t>(i) * d * d;
      for (int j = 0; j < d; ++j)
        for (int l = 0; l <= j; ++l)
          block[j + l * d] += hsum(a2[j * d + l]);
    }
  }
}

}  // namespace

void blockComponentLogDensities(const KernelDensityView& c, const double* x, std::ptrdiff_t ldx,
                                int rows, double* out, int ld) {
  switch (c.dimension) {
    case 1:
      return logDensitiesKernel<1>(c, x, ldx, rows, out, ld);
    case 2:
      return logDensitiesKernel<2>(c, x, ldx, rows, out, ld);
    case 3:
      return logDensitiesKernel<3>(c, x, ldx, rows, out, ld);
    case 4:
      return logDensitiesKernel<4>(c, x, ldx, rows, out, ld);
    case 5:
      return logDensitiesKernel<5>(c, x, ldx, rows, out, ld);
    case 6:
      return logDensitiesKernel<6>(c, x, ldx, rows, out, ld);
    case 8:
      return logDensitiesKernel<8>(c, x, ldx, rows, out, ld);
    case 10:
      return logDensitiesKernel<10>(c, x, ldx, rows, out, ld);
    case 12:
      return logDensitiesKernel<12>(c, x, ldx, rows, out, ld);
    default:
      return logDensitiesKernel<0>(c, x, ldx, rows, out, ld);
  }
}

void blockAccumulateStats(const KernelDensityView& c, const double* x, std::ptrdiff_t ldx, int rows,
                          const double* resp, int ld, const KernelStatsView& s) {
  switch (c.dimension) {
    case 1:
      return statsKernel<1>(c, x, ldx, rows, resp, ld, s);
    case 2:
      return statsKernel<2>(c, x, ldx, rows, resp, ld, s);
    case 3:
      return statsKernel<3>(c, x, ldx, rows, resp, ld, s);
    case 4:
      return statsKernel<4>(c, x, ldx, rows, resp, ld, s);
    case 5:
      return statsKernel<5>(c, x, ldx, rows, resp, ld, s);
    case 6:
      return statsKernel<6>(c, x, ldx, rows, resp, ld, s);
    case 8:
      return statsKernel<8>(c, x, ldx, rows, resp, ld, s);
    case 10:
      return statsKernel<10>(c, x, ldx, rows, resp, ld, s);
    case 12:
      return statsKernel<12>(c, x, ldx, rows, resp, ld, s);
    default:
      return statsKernel<0>(c, x, ldx, rows, resp, ld, s);
  }
}

void blockLogSumExp(const double* in, int ld, int rows, int components, double* logSum,
                    double* resp) {
  const double ninf = -__builtin_inf();
  bool anyDead = false;
  for (int r = 0; r < rows; r += kLanes) {
    V mx = splat(ninf);
    for (int i = 0; i < components; ++i) {
      const V v = loadV(in + static_cast<std::ptrdiff_t>(i) * ld + r);
      mx = select(less(mx, v), v, mx);
    }
    // Rows whose max is -inf (every component impossible) are shifted by 0 (no inf - inf).
    const M dead = equal(mx, splat(ninf));
    const V shift = select(dead, zero(), mx);
    V sum = zero();
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
    anyDead = anyDead || anyLane(dead);
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

double squaredDistances(const double* x, std::ptrdiff_t ldx, std::ptrdiff_t rows, int d,
                        const double* centre, const double* current, double* out) {
  V total = zero();
  std::ptrdiff_t r = 0;
  for (; r + kLanes <= rows; r += kLanes) {
    V acc = zero();
    for (int j = 0; j < d; ++j) {
      const V t = loadV(x + j * ldx + r) - centre[j];
      acc += t * t;
    }
    if (current) {
      const V cur = loadV(current + r);
      acc = select(less(cur, acc), cur, acc);
    }
    storeV(out + r, acc);
    total += acc;
  }
  double tail = 0.0;
  for (; r < rows; ++r) {
    double acc = 0.0;
    for (int j = 0; j < d; ++j) {
      const double t = x[j * ldx + r] - centre[j];
      acc += t * t;
    }
    if (current && current[r] < acc) acc = current[r];
    out[r] = acc;
    tail += acc;
  }
  return hsum(total) + tail;
}

double nearestCentres(const double* x, std::ptrdiff_t ldx, std::ptrdiff_t rows, int d,
                      const double* centres, int k, int* bestIndex) {
  V inertia = zero();
  std::ptrdiff_t r = 0;
  for (; r + kLanes <= rows; r += kLanes) {
    V best = splat(__builtin_inf());
    V index = zero();  // small integers, exact as doubles
    for (int i = 0; i < k; ++i) {
      V acc = zero();
      for (int j = 0; j < d; ++j) {
        const V t = loadV(x + j * ldx + r) - centres[i + j * k];
        acc += t * t;
      }
      const M better = less(acc, best);  // strict: ties keep the lowest index
      best = select(better, acc, best);
      index = select(better, splat(static_cast<double>(i)), index);
    }
    for (int l = 0; l < kLanes; ++l)
      bestIndex[r + l] = static_cast<int>(lane(index, l));
    inertia += best;
  }
  double tail = 0.0;
  for (; r < rows; ++r) {
    double best = __builtin_inf();
    int index = 0;
    for (int i = 0; i < k; ++i) {
      double acc = 0.0;
      for (int j = 0; j < d; ++j) {
        const double t = x[j * ldx + r] - centres[i + j * k];
        acc += t * t;
      }
      if (acc < best) {
        best = acc;
        index = i;
      }
    }
    bestIndex[r] = index;
    tail += best;
  }
  return hsum(inertia) + tail;
}

}  // namespace tactile::analysis::TACTILE_KERNEL_NS
