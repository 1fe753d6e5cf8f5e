// The map benchmark (docs/navigation.md#benchmark): generated office-like maps (rooms, doors,
// furniture) in the manner of McGuire, de Croon and Tuyls (2019); per map a start and a goal drawn
// from the seed in different rooms, the A* length on the map grown by the robot as the reference,
// and one run per status source.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "analysis/model_file.h"
#include "base/error.h"
#include "base/progress.h"
#include "nav/navigator.h"
#include "sim/world.h"

namespace tactile::nav {

// One benchmark case: a map, a start pose, a goal, and the reference path length.
struct MapCase {
  std::shared_ptr<const sim::World> world;
  Pose2d start;
  Vec2 goal = Vec2::Zero();
  double astarUnits = 0.0;
};

// The map of seed `seed` with a start and a goal that A* connects; fails only when no such pair
// is found in many draws.
Result<MapCase> benchmarkCase(std::uint64_t seed);

struct BenchmarkOptions {
  std::size_t maps = 200;
  std::uint64_t seed = 1;  // map i uses seed + i
  std::size_t maxSteps = 6000;
  unsigned threads = 0;                                 // 0 = all cores
  std::shared_ptr<const analysis::ModelBundle> models;  // null: the model source is skipped
};

struct SourceSummary {
  StatusSource source = StatusSource::Model;
  std::size_t runs = 0;
  std::size_t successes = 0;
  std::size_t unreachable = 0;
  std::size_t timeouts = 0;
  double successRate = 0.0;
  // Path length over the A* length, over the successful runs (0 when none succeeded).
  double medianPathRatio = 0.0;
  double p90PathRatio = 0.0;
  double medianSteps = 0.0;  // over the successful runs
  double seconds = 0.0;      // CPU-side wall time of this source's runs, summed over threads
};

struct BenchmarkResult {
  std::size_t maps = 0;
  std::size_t mapsWithoutPath = 0;  // should stay 0: cases are drawn with a path
  std::vector<SourceSummary> sources;
  double seconds = 0.0;  // wall time of the whole benchmark
};

// Runs every map with every source (model only when models are given), spread over threads; the
// figures do not depend on the thread count. `progress` gets (runs done, runs).
Result<BenchmarkResult> runMapBenchmark(const BenchmarkOptions& options,
                                        const ProgressFn& progress = {});

// p-quantile (0..1) by linear interpolation between order statistics; 0 for an empty list.
double quantile(std::vector<double> values, double p);

}  // namespace tactile::nav
