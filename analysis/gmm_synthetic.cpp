#include "analysis/gmm_synthetic.h"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

#include "analysis/gaussian.h"

namespace tactile::analysis {

namespace {
// Standard normal by Box-Muller (one value per call; deterministic).
double normal(Rng& rng) {
  double u = rng.uniform();
  while (u <= 0.0)
    u = rng.uniform();
  const double v = rng.uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
}
}  // namespace

FeatureTable makeSyntheticTable(const SyntheticTableSpec& spec) {
  const int d = spec.dimension;
  const int clusters = spec.classes * spec.clustersPerClass;
  Rng paramRng(spec.seed);
  std::vector<Eigen::VectorXd> centres;
  std::vector<Eigen::MatrixXd> factors;
  for (int k = 0; k < clusters; ++k) {
    Eigen::VectorXd mu(d);
    for (int j = 0; j < d; ++j)
      mu(j) = spec.clusterSpread * normal(paramRng);
    Eigen::MatrixXd a(d, d);
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j)
        a(i, j) = normal(paramRng);
    Eigen::MatrixXd cov = a * a.transpose() / d + 0.05 * Eigen::MatrixXd::Identity(d, d);
    Eigen::LLT<Eigen::MatrixXd> llt(cov);
    centres.push_back(mu);
    factors.push_back(llt.matrixL());
  }
  FeatureTable t;
  for (int c = 0; c < spec.classes; ++c)
    t.classNames.push_back("class" + std::to_string(c));
  t.features.resize(spec.rows, d);
  t.labels.resize(static_cast<std::size_t>(spec.rows));
  Rng rng(spec.seed * 0x9E3779B97F4A7C15ULL + spec.sampleSeed);
  Eigen::VectorXd z(d);
  for (int r = 0; r < spec.rows; ++r) {
    const int c = r % spec.classes;
    const int k = c * spec.clustersPerClass +
                  static_cast<int>(rng.below(static_cast<std::uint64_t>(spec.clustersPerClass)));
    for (int j = 0; j < d; ++j)
      z(j) = normal(rng);
    t.features.row(r) =
        (centres[static_cast<std::size_t>(k)] + factors[static_cast<std::size_t>(k)] * z)
            .transpose();
    t.labels[static_cast<std::size_t>(r)] = c;
  }
  return t;
}

}  // namespace tactile::analysis
