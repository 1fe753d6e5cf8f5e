// Helpers for the GMM/classifier tests: deterministic data generation.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <vector>

#include "analysis/gaussian.h"

namespace tactile::analysis::testing {

inline double standardNormal(Rng& rng) {
  double u = rng.uniform();
  while (u <= 0.0)
    u = rng.uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * rng.uniform());
}

// n rows from N(mean, diag(sd^2)).
inline Eigen::MatrixXd gaussianRows(int n, const Eigen::VectorXd& mean, const Eigen::VectorXd& sd,
                                    std::uint64_t seed) {
  Rng rng(seed);
  Eigen::MatrixXd x(n, mean.size());
  for (int r = 0; r < n; ++r)
    for (Eigen::Index j = 0; j < mean.size(); ++j)
      x(r, j) = mean(j) + sd(j) * standardNormal(rng);
  return x;
}

// Stacks row blocks.
inline Eigen::MatrixXd stackRows(const std::vector<Eigen::MatrixXd>& parts) {
  Eigen::Index n = 0;
  for (const auto& p : parts)
    n += p.rows();
  Eigen::MatrixXd out(n, parts.front().cols());
  Eigen::Index r = 0;
  for (const auto& p : parts) {
    out.middleRows(r, p.rows()) = p;
    r += p.rows();
  }
  return out;
}

inline bool allFiniteMixture(const Eigen::VectorXd& w, const Eigen::MatrixXd& m,
                             const std::vector<Eigen::MatrixXd>& c) {
  bool ok = w.allFinite() && m.allFinite();
  for (const auto& s : c)
    ok = ok && s.allFinite();
  return ok;
}

}  // namespace tactile::analysis::testing
