// The map benchmark (docs/navigation.md#the-benchmark): the simulator's generated office maps
// (`random:office:SEED`, sim/office_scene.h: rooms, doors, narrow gaps, bumps, furniture) in the
// manner of McGuire, de Croon and Tuyls (2019), on the seeds kept for benchmarks
// (sim::kFirstBenchmarkSceneSeed and up, never drawn by the training recipe); the map's own start
// and goal (in different rooms), the A* length on the map grown by the robot as the reference,
// and one run per status source.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
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

// The step budget of a map: kBudgetPerAStarPath times the steps the A* path takes at the
// navigator's cruise speed (`cruiseUnitsPerStep`), and at least `floorSteps` (--max-steps), at
// most sim::kMaxStepsPerRun. A long map gets the time a long way round needs; a short one keeps
// the floor.
inline constexpr double kBudgetPerAStarPath = 20.0;
std::size_t mapStepBudget(double astarUnits, double cruiseUnitsPerStep, std::size_t floorSteps);

// The office map `random:office:SEED` with its start and goal and the A* length between them.
// Fails for a seed below sim::kFirstBenchmarkSceneSeed (kept out of benchmarks: training draws
// them) and when no path joins start and goal.
Result<MapCase> benchmarkCase(std::uint64_t seed);

// The scene seed of map `index` of a benchmark run with `seed`:
// sim::kFirstBenchmarkSceneSeed + seed + index.
std::uint64_t mapSeed(std::uint64_t seed, std::size_t index);

struct BenchmarkOptions {
  std::size_t maps = 200;
  std::uint64_t seed = 1;       // map i is random:office:mapSeed(seed, i)
  std::size_t maxSteps = 6000;  // the floor of each map's budget (mapStepBudget)
  unsigned threads = 0;         // 0 = all cores
  std::shared_ptr<const analysis::ModelBundle> models;  // null: the model source is skipped
  bool touchMap = false;  // NavigatorConfig::touchMap for the model and truth sources
  bool planDrive = true;  // NavigatorConfig::planDrive for the model and truth sources
  // When set, every run is written here as benchmark_SOURCE_MAPSEED.csv (with the navigator's
  // x_ columns; `tactile navigate --scene random:office:MAPSEED` rebuilds its scene).
  std::string outDir;
};

// One run of the benchmark: a map and a source.
struct MapRun {
  std::uint64_t mapSeed = 0;  // random:office:mapSeed
  RunOutcome outcome = RunOutcome::Unknown;
  std::size_t steps = 0;
  std::size_t budget = 0;  // the map's step budget (mapStepBudget)
  double pathRatio = 0.0;  // path length over the A* length (whatever the outcome)
  std::size_t blockedSteps = 0;
  std::array<std::size_t, kStrategyCount> strategySteps{};  // kStrategies order
  std::size_t checkContactStarts = 0;
  double closestGoalUnits = 0.0;  // the body centre's closest approach to the goal
  double finalGoalUnits = 0.0;    // and its distance at the end
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
  double medianSteps = 0.0;     // over the successful runs
  double seconds = 0.0;         // CPU-side wall time of this source's runs, summed over threads
  std::vector<MapRun> mapRuns;  // map by map, in map order
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
