// Deterministic synthetic feature tables for benchmarks and tests: each class is a mixture of
// correlated Gaussian clusters.
#pragma once

#include <cstdint>

#include "analysis/feature_table.h"

namespace tactile::analysis {

struct SyntheticTableSpec {
  int rows = 100000;
  int dimension = 10;
  int classes = 3;
  int clustersPerClass = 8;
  double clusterSpread = 1.5;    // standard deviation of cluster centres around the origin
  std::uint64_t seed = 1;        // the mixture parameters depend only on this...
  std::uint64_t sampleSeed = 1;  // ...and the rows on this too (train and test differ here)
};

// Class c has clustersPerClass clusters with centres ~ N(0, spread^2 I) and covariances
// A A^T / D + 0.05 I (A with N(0,1) entries); rows are assigned to classes round-robin and to
// clusters uniformly. Same spec, same table, on every platform.
FeatureTable makeSyntheticTable(const SyntheticTableSpec& spec);

}  // namespace tactile::analysis
