// The per-instruction-set kernel copies (x86-64-v2, v3, v4, generic): each level the processor
// supports is checked against plain scalar references, and EM fits are compared across levels.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "analysis/gmm.h"
#include "analysis/gmm_kernels.h"
#include "analysis/kmeans.h"
#include "tests/analysis/gmm_test_util.h"

namespace tactile::analysis {
namespace {

using testing::gaussianRows;
using testing::standardNormal;

// Restores the level chosen at start-up when a test ends.
struct IsaGuard {
  std::string saved = kernelIsa();
  ~IsaGuard() { setKernelIsa(saved); }
};

const double kNegInf = -std::numeric_limits<double>::infinity();

// Relative difference, with an absolute floor of 1 for values near 0.
double relDiff(double a, double b) {
  return std::abs(a - b) / std::max(1.0, std::abs(b));
}

TEST(KernelIsa, TheBestSupportedLevelIsTheDefaultAndUnknownLevelsAreRefused) {
  const std::vector<std::string> levels = supportedKernelIsas();
  ASSERT_FALSE(levels.empty());
  EXPECT_EQ(levels.front(), "generic");
  IsaGuard guard;
  for (const std::string& level : levels) {
    EXPECT_TRUE(setKernelIsa(level)) << level;
    EXPECT_EQ(kernelIsa(), level);
  }
  const std::string before = kernelIsa();
  EXPECT_FALSE(setKernelIsa("x86-64-v9"));
  EXPECT_EQ(kernelIsa(), before);
#if defined(__x86_64__)
  // Every x86-64 processor this program runs on has SSE4.2 or better in practice; the test
  // machines do.
  EXPECT_GE(levels.size(), 2u);
#endif
}

// log-sum-exp and responsibilities of two-column rows against std::exp/std::log, over differences
// from 0 to beyond the flush-to-zero limit, with -inf entries and an all -inf row.
TEST(KernelIsa, LogSumExpMatchesTheLibraryOnEveryLevel) {
  IsaGuard guard;
  const int rows = 256;
  const int ld = rows;
  Eigen::VectorXd in(2 * ld), lse(rows), resp(2 * ld);
  for (int r = 0; r < rows; ++r) {
    const double a = -3.0 + 0.25 * r;
    const double diff = r < 200 ? 0.02 * r * r : 700.0 + r;  // up to 796 and beyond 708
    in(r) = a;
    in(ld + r) = a - diff;
  }
  in(ld + 7) = kNegInf;  // one impossible component
  in(9) = kNegInf;       // a whole row impossible
  in(ld + 9) = kNegInf;
  for (const std::string& level : supportedKernelIsas()) {
    ASSERT_TRUE(setKernelIsa(level));
    blockLogSumExp(in.data(), ld, rows, 2, lse.data(), resp.data());
    for (int r = 0; r < rows; ++r) {
      const double a = in(r), b = in(ld + r);
      if (r == 9) {
        EXPECT_EQ(lse(r), kNegInf) << level;
        EXPECT_EQ(resp(r), 0.5) << level;
        EXPECT_EQ(resp(ld + r), 0.5) << level;
        continue;
      }
      const double hi = std::max(a, b), lo = std::min(a, b);
      const double expected = hi + std::log1p(std::exp(lo - hi));
      EXPECT_LE(relDiff(lse(r), expected), 4e-16) << level << " row " << r;
      const double ra = std::exp(a - expected), rb = std::exp(b - expected);
      EXPECT_NEAR(resp(r), ra, 1e-15) << level << " row " << r;
      EXPECT_NEAR(resp(ld + r), rb, 1e-15) << level << " row " << r;
      EXPECT_TRUE(std::isfinite(resp(r)) && std::isfinite(resp(ld + r)));
    }
  }
}

// A random density cache of K components in dimension D.
GmmDensityCache randomCache(int k, int d, bool diagonal, bool nodal, std::uint64_t seed) {
  Rng rng(seed);
  Eigen::VectorXd w(k);
  for (int i = 0; i < k; ++i)
    w(i) = 0.5 + rng.uniform();
  w /= w.sum();
  Eigen::MatrixXd means(k, d);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < d; ++j)
      means(i, j) = 3.0 * standardNormal(rng);
  std::vector<Eigen::MatrixXd> covs;
  for (int i = 0; i < (nodal ? k : 1); ++i) {
    Eigen::MatrixXd a(d, d);
    for (int r = 0; r < d; ++r)
      for (int c = 0; c < d; ++c)
        a(r, c) = standardNormal(rng);
    Eigen::MatrixXd cov = a * a.transpose() / d + 0.2 * Eigen::MatrixXd::Identity(d, d);
    if (diagonal) cov = Eigen::MatrixXd(cov.diagonal().asDiagonal());
    covs.push_back(cov);
  }
  GmmDensityCache cache;
  int bad = -1;
  EXPECT_TRUE(buildDensityCache(w, means, covs, diagonal, nodal, cache, &bad));
  return cache;
}

// log w_i + log N(x | mu_i, Sigma_i) in long double, from the cache's own factors.
long double referenceLogDensity(const GmmDensityCache& c, const Eigen::MatrixXd& x, int row,
                                int i) {
  const int d = c.dimension;
  long double q = 0.0L;
  if (c.diagonal) {
    for (int j = 0; j < d; ++j) {
      const long double t =
          (static_cast<long double>(x(row, j)) - c.means(i, j)) * c.scales(c.nodal ? i : 0, j);
      q += t * t;
    }
  } else {
    const auto u = c.upper.middleCols(static_cast<Eigen::Index>(c.nodal ? i : 0) * d, d);
    for (int j = 0; j < d; ++j) {
      long double y = 0.0L;
      for (int l = 0; l <= j; ++l)
        y += (static_cast<long double>(x(row, l)) - c.means(i, l)) * u(l, j);
      q += y * y;
    }
  }
  return c.logConstants(i) - 0.5L * q;
}

struct Shape {
  int k;
  int d;
  bool diagonal;
  bool nodal;
};
// Compile-time dimensions (3, 10) and the run-time path (7, 20: beyond the unrolled cases).
const Shape kShapes[] = {{5, 3, true, true},   {9, 10, true, true},   {4, 10, false, true},
                         {3, 10, true, false}, {6, 10, false, false}, {3, 7, false, true},
                         {2, 20, false, true}, {3, 20, true, true}};

TEST(KernelIsa, DensitiesAndStatisticsMatchAScalarReferenceOnEveryLevel) {
  IsaGuard guard;
  const int rows = 64;
  for (const Shape& s : kShapes) {
    const GmmDensityCache cache = randomCache(s.k, s.d, s.diagonal, s.nodal, 17 + s.k * s.d);
    const Eigen::MatrixXd x =
        gaussianRows(rows, Eigen::VectorXd::Zero(s.d), Eigen::VectorXd::Constant(s.d, 3.0), 5);
    // Responsibilities: any non-negative weights will do for the statistics.
    Eigen::MatrixXd resp(rows, s.k);
    for (int r = 0; r < rows; ++r)
      for (int i = 0; i < s.k; ++i)
        resp(r, i) = ((r * 7 + i * 3) % 11) / 10.0;
    for (const std::string& level : supportedKernelIsas()) {
      ASSERT_TRUE(setKernelIsa(level));
      Eigen::MatrixXd out(rows, s.k);
      blockComponentLogDensities(cache, x.data(), rows, rows, out.data(), rows);
      for (int r = 0; r < rows; ++r)
        for (int i = 0; i < s.k; ++i) {
          const long double ref = referenceLogDensity(cache, x, r, i);
          EXPECT_LE(relDiff(out(r, i), static_cast<double>(ref)), 1e-13)
              << level << " K=" << s.k << " D=" << s.d << " diag=" << s.diagonal;
        }
      Eigen::VectorXd nk = Eigen::VectorXd::Zero(s.k);
      Eigen::MatrixXd s1 = Eigen::MatrixXd::Zero(s.k, s.d);
      Eigen::MatrixXd s2 =
          s.diagonal ? Eigen::MatrixXd::Zero(s.k, s.d) : Eigen::MatrixXd::Zero(s.d, s.k * s.d);
      blockAccumulateStats(cache, x.data(), rows, rows, resp.data(), rows, nk, s1, s2);
      for (int i = 0; i < s.k; ++i) {
        long double n = 0.0L;
        std::vector<long double> a1(static_cast<std::size_t>(s.d), 0.0L);
        std::vector<long double> a2(static_cast<std::size_t>(s.d * s.d), 0.0L);
        for (int r = 0; r < rows; ++r) {
          n += resp(r, i);
          for (int j = 0; j < s.d; ++j) {
            const long double zj = static_cast<long double>(x(r, j)) - cache.means(i, j);
            a1[static_cast<std::size_t>(j)] += resp(r, i) * zj;
            for (int l = 0; l < s.d; ++l) {
              const long double zl = static_cast<long double>(x(r, l)) - cache.means(i, l);
              a2[static_cast<std::size_t>(j * s.d + l)] += resp(r, i) * zj * zl;
            }
          }
        }
        EXPECT_LE(relDiff(nk(i), static_cast<double>(n)), 1e-14) << level;
        for (int j = 0; j < s.d; ++j) {
          EXPECT_LE(relDiff(s1(i, j), static_cast<double>(a1[static_cast<std::size_t>(j)])), 1e-13)
              << level;
          if (s.diagonal) {
            EXPECT_LE(
                relDiff(s2(i, j), static_cast<double>(a2[static_cast<std::size_t>(j * s.d + j)])),
                1e-13)
                << level;
          } else {
            for (int l = 0; l <= j; ++l)
              EXPECT_LE(relDiff(s2(j, i * s.d + l),
                                static_cast<double>(a2[static_cast<std::size_t>(j * s.d + l)])),
                        1e-13)
                  << level << " K=" << s.k << " D=" << s.d;
          }
        }
      }
    }
  }
}

TEST(KernelIsa, KMeansDistancesMatchAScalarReferenceOnEveryLevel) {
  IsaGuard guard;
  const int d = 6, k = 7;
  const int rows = 29;  // not a multiple of 8: the scalar tail runs too
  const Eigen::MatrixXd x =
      gaussianRows(rows, Eigen::VectorXd::Zero(d), Eigen::VectorXd::Constant(d, 2.0), 11);
  Eigen::MatrixXd centres = x.topRows(k);
  centres.row(3) = centres.row(1);  // a tie: the lower index must win
  Eigen::VectorXd current(rows);
  for (int r = 0; r < rows; ++r)
    current(r) = 2.0 * r;
  for (const std::string& level : supportedKernelIsas()) {
    ASSERT_TRUE(setKernelIsa(level));
    Eigen::VectorXd out(rows);
    const Eigen::VectorXd c2 = centres.row(2).transpose();  // contiguous copy of one centre
    const double total2 =
        blockSquaredDistances(x.data(), rows, rows, d, c2.data(), current.data(), out.data());
    double sum = 0.0;
    for (int r = 0; r < rows; ++r) {
      const double ref = std::min(current(r), (x.row(r).transpose() - c2).squaredNorm());
      EXPECT_LE(relDiff(out(r), ref), 1e-15) << level << " row " << r;
      sum += ref;
    }
    EXPECT_LE(relDiff(total2, sum), 1e-14) << level;
    std::vector<int> best(static_cast<std::size_t>(rows), -1);
    const double inertia =
        blockNearestCentres(x.data(), rows, rows, d, centres.data(), k, best.data());
    double refInertia = 0.0;
    for (int r = 0; r < rows; ++r) {
      int bi = 0;
      double bd = std::numeric_limits<double>::infinity();
      for (int i = 0; i < k; ++i) {
        const double dist = (x.row(r) - centres.row(i)).squaredNorm();
        if (dist < bd) {
          bd = dist;
          bi = i;
        }
      }
      EXPECT_EQ(best[static_cast<std::size_t>(r)], bi) << level << " row " << r;
      EXPECT_NE(best[static_cast<std::size_t>(r)], 3) << "ties go to the lower index";
      refInertia += bd;
    }
    EXPECT_LE(relDiff(inertia, refInertia), 1e-13) << level;
  }
}

// Whether a level's kernels contract a * b + c into fused multiply-adds (GCC does so wherever the
// instruction set has them). The generic copy is built with the same flags as this test.
bool usesFma(const std::string& level) {
  if (level == "x86-64-v3" || level == "x86-64-v4") return true;
  if (level == "generic") {
#if defined(__FMA__)
    return true;
#else
    return false;
#endif
  }
  return false;
}

// Eight lanes and the same operation order on every level: an EM fit is bit-identical on levels
// that agree on fused multiply-adds, and within rounding (1e-9 relative) across them.
TEST(KernelIsa, FitsAgreeOnEveryLevel) {
  IsaGuard guard;
  const Eigen::MatrixXd x = testing::stackRows(
      {gaussianRows(3000, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 0.5), 1),
       gaussianRows(3000, Eigen::Vector3d(4, -1, 2), Eigen::Vector3d(0.7, 1, 1), 2)});
  const std::vector<std::string> levels = supportedKernelIsas();
  for (CovarianceForm form : kAllCovarianceForms) {
    GmmOptions o;
    o.components = 4;
    o.form = form;
    o.threads = 2;
    std::vector<GmmFit> fits;
    for (const std::string& level : levels) {
      ASSERT_TRUE(setKernelIsa(level));
      fits.push_back(fitGmm(x, o));
      ASSERT_TRUE(fits.back().ok) << level << ": " << fits.back().reason;
    }
    for (std::size_t a = 0; a < fits.size(); ++a)
      for (std::size_t b = a + 1; b < fits.size(); ++b) {
        const std::string what =
            std::string(covarianceFormName(form)) + " " + levels[a] + " vs " + levels[b];
        EXPECT_LE(relDiff(fits[a].logLikelihood, fits[b].logLikelihood), 1e-9) << what;
        EXPECT_LE((fits[a].model.means() - fits[b].model.means()).cwiseAbs().maxCoeff(), 1e-6)
            << what;
        if (usesFma(levels[a]) != usesFma(levels[b])) continue;
        EXPECT_EQ(fits[a].logLikelihood, fits[b].logLikelihood) << what;
        EXPECT_EQ(fits[a].iterations, fits[b].iterations) << what;
        EXPECT_TRUE(fits[a].model.means() == fits[b].model.means()) << what;
        EXPECT_TRUE(fits[a].model.weights() == fits[b].model.weights()) << what;
      }
  }
}

}  // namespace
}  // namespace tactile::analysis

namespace tactile::analysis {
namespace {

// k-means reads samples through their outer stride: rows of a taller matrix (as EM's padded,
// centred copy) give exactly what a plain copy of the same rows gives.
TEST(KernelIsa, KMeansReadsSamplesThroughTheirOuterStride) {
  const Eigen::MatrixXd tall =
      testing::gaussianRows(9005, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 1, 2), 3);
  const Eigen::MatrixXd plain = tall.topRows(9001);
  Rng a(5), b(5);
  Eigen::MatrixXd ca = kmeansPlusPlus(plain, 6, a, 2);
  Eigen::MatrixXd cb = kmeansPlusPlus(tall.topRows(9001), 6, b, 2);
  EXPECT_TRUE(ca == cb);
  std::vector<int> sa, sb;
  lloydIterations(plain, ca, 5, sa, 2);
  lloydIterations(tall.topRows(9001), cb, 5, sb, 2);
  EXPECT_TRUE(ca == cb);
  EXPECT_EQ(sa, sb);
  EXPECT_EQ(sa.size(), 9001u);
}

}  // namespace
}  // namespace tactile::analysis
