#include "analysis/gaussian.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace tactile::analysis {

double logSumExp(const double* values, int count) {
  double m = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < count; ++i)
    m = std::max(m, values[i]);
  if (!std::isfinite(m)) return m;
  double sum = 0.0;
  for (int i = 0; i < count; ++i)
    sum += std::exp(values[i] - m);
  return m + std::log(sum);
}

bool choleskyLower(const Eigen::MatrixXd& sigma, Eigen::MatrixXd& lower) {
  const Eigen::Index d = sigma.rows();
  if (sigma.cols() != d) return false;
  lower.setZero(d, d);
  for (Eigen::Index j = 0; j < d; ++j) {
    double diag = sigma(j, j);
    for (Eigen::Index k = 0; k < j; ++k)
      diag -= lower(j, k) * lower(j, k);
    if (!(diag > 0.0) || !std::isfinite(diag)) return false;
    const double ljj = std::sqrt(diag);
    // A pivot that lost all but ~1e-14 of its original size is rank deficient in double precision.
    if (!(ljj > 0.0) || diag <= sigma(j, j) * 1e-14) return false;
    lower(j, j) = ljj;
    for (Eigen::Index i = j + 1; i < d; ++i) {
      double v = sigma(i, j);
      for (Eigen::Index k = 0; k < j; ++k)
        v -= lower(i, k) * lower(j, k);
      lower(i, j) = v / ljj;
    }
  }
  return true;
}

double logDeterminantFromCholesky(const Eigen::MatrixXd& lower) {
  double s = 0.0;
  for (Eigen::Index i = 0; i < lower.rows(); ++i)
    s += std::log(lower(i, i));
  return 2.0 * s;
}

double gaussianLogDensity(const Eigen::Ref<const Eigen::VectorXd>& x,
                          const Eigen::Ref<const Eigen::VectorXd>& mean,
                          const Eigen::MatrixXd& lower, double logDet) {
  const Eigen::Index d = x.size();
  Eigen::VectorXd z = x - mean;
  // Forward substitution L y = z, in place.
  for (Eigen::Index i = 0; i < d; ++i) {
    double v = z(i);
    for (Eigen::Index k = 0; k < i; ++k)
      v -= lower(i, k) * z(k);
    z(i) = v / lower(i, i);
  }
  return -0.5 * (static_cast<double>(d) * kLog2Pi + logDet + z.squaredNorm());
}

Eigen::MatrixXd clampEigenvalues(const Eigen::MatrixXd& sigma, double minimum) {
  const Eigen::MatrixXd sym = 0.5 * (sigma + sigma.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(sym);
  if (solver.info() != Eigen::Success) return sym;
  Eigen::VectorXd values = solver.eigenvalues();
  bool changed = false;
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (values(i) < minimum) {
      values(i) = minimum;
      changed = true;
    }
  }
  if (!changed) return sym;
  const Eigen::MatrixXd& u = solver.eigenvectors();
  Eigen::MatrixXd out = u * values.asDiagonal() * u.transpose();
  return 0.5 * (out + out.transpose());
}

bool allFinite(const Eigen::MatrixXd& m) {
  return m.allFinite();
}

std::uint64_t splitMix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

Rng::Rng(std::uint64_t seed) {
  std::uint64_t state = seed;
  for (auto& s : s_)
    s = splitMix64(state);
}

std::uint64_t Rng::next() {
  const auto rotl = [](std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); };
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

std::uint64_t Rng::below(std::uint64_t n) {
  // Rejection to avoid modulo bias.
  const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);
  std::uint64_t v = next();
  while (v >= limit)
    v = next();
  return v % n;
}

}  // namespace tactile::analysis
