#include "nav/benchmark.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <numbers>
#include <random>
#include <thread>

#include "base/parallel.h"
#include "nav/astar.h"
#include "nav/navigate.h"
#include "run/run_csv.h"
#include "sim/office_scene.h"
#include "sim/recorder.h"
#include "sim/simulator.h"

namespace tactile::nav {
namespace {

// Grid of the A* reference; the map is inflated as the office generator inflates it to check
// that start and goal are joined: the robot's half-width with its domes plus a margin, so the
// reference path is one the robot fits along.
constexpr double kGridUnits = 10.0;

}  // namespace

std::uint64_t mapSeed(std::uint64_t seed, std::size_t index) {
  return sim::kFirstBenchmarkSceneSeed + seed + index;
}

double quantile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double pos = std::clamp(p, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (pos - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

Result<MapCase> benchmarkCase(std::uint64_t seed) {
  if (seed < sim::kFirstBenchmarkSceneSeed)
    return Error("map seed " + std::to_string(seed) + " is below " +
                 std::to_string(sim::kFirstBenchmarkSceneSeed) +
                 ": benchmark maps use the seeds kept for benchmarks");
  sim::OfficeScene office = sim::generateOfficeScene(seed);
  if (!office.connected)
    return Error("map seed " + std::to_string(seed) + ": the start and the goal are not joined");
  MapCase c;
  c.start = office.scene.start;
  c.goal = office.scene.goal;
  c.world = std::make_shared<const sim::World>(std::move(office.scene));
  const sim::OfficeOptions generator;
  const GridMap grid =
      inflatedGrid(*c.world, kGridUnits, generator.robotHalfWidthUnits + generator.marginUnits);
  // The path is measured from the body's centre (35 ahead of the rear axle), as the goal is.
  const Vec2 centre(c.start.x + 35.0 * std::cos(c.start.theta),
                    c.start.y + 35.0 * std::sin(c.start.theta));
  const auto length = shortestPathUnits(grid, centre, c.goal);
  if (!length) return Error("map seed " + std::to_string(seed) + ": no path joins start and goal");
  c.astarUnits = *length;
  return c;
}

std::size_t mapStepBudget(double astarUnits, double cruiseUnitsPerStep, std::size_t floorSteps) {
  double steps = static_cast<double>(floorSteps);
  if (cruiseUnitsPerStep > 0.0 && std::isfinite(astarUnits))
    steps = std::max(steps, std::ceil(kBudgetPerAStarPath * astarUnits / cruiseUnitsPerStep));
  return static_cast<std::size_t>(std::min(steps, static_cast<double>(sim::kMaxStepsPerRun)));
}

Result<BenchmarkResult> runMapBenchmark(const BenchmarkOptions& options,
                                        const ProgressFn& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<StatusSource> sources;
  if (options.models) sources.push_back(StatusSource::Model);
  sources.push_back(StatusSource::Truth);
  sources.push_back(StatusSource::Bumper);
  const std::size_t maps = options.maps;
  const std::size_t jobs = maps * sources.size();
  struct Outcome {
    RunOutcome outcome = RunOutcome::Unknown;
    double ratio = 0.0;
    double steps = 0.0;
    double seconds = 0.0;
    MapRun run;
  };
  std::vector<Outcome> results(jobs);
  std::vector<std::optional<MapCase>> cases(maps);
  std::vector<std::once_flag> made(maps);
  std::string firstError;
  std::mutex mutex;
  std::atomic<std::size_t> done{0};
  std::atomic<bool> stop{false};
  // Job j runs map j / sources.size() with source j % sources.size(); an exception in any job (out
  // of memory) reaches the caller after every worker stopped.
  parallelFor(jobs, options.threads, [&](std::size_t j) {
    const std::size_t m = j / sources.size();
    std::call_once(made[m], [&] {
      auto c = benchmarkCase(mapSeed(options.seed, m));
      if (c) {
        cases[m] = std::move(c.value());
      } else {
        std::lock_guard lock(mutex);
        if (firstError.empty()) firstError = c.errorText();
        stop = true;
      }
    });
    if (!cases[m]) return false;
    const MapCase& mc = *cases[m];
    NavigatorConfig config;
    config.source = sources[j % sources.size()];
    config.models = options.models;
    config.touchMap = options.touchMap;
    config.planDrive = options.planDrive;
    NavigateOptions no;
    no.maxSteps = mapStepBudget(mc.astarUnits, config.cruiseUnitsPerSecond * no.sim.dtSeconds,
                                options.maxSteps);
    no.seed = mapSeed(options.seed, m);
    const auto r0 = std::chrono::steady_clock::now();
    const bool record = !options.outDir.empty();
    auto r = navigate(mc.world, mc.world->scene().name, mc.start, mc.goal, config, no, record);
    if (!r) {
      std::lock_guard lock(mutex);
      if (firstError.empty()) firstError = r.errorText();
      stop = true;
      return false;
    }
    if (record) {
      char name[96];
      std::snprintf(name, sizeof name, "benchmark_%s_%llu.csv",
                    std::string(statusSourceName(config.source)).c_str(),
                    static_cast<unsigned long long>(no.seed));
      const Status written = writeRunCsv(r->run, std::filesystem::path(options.outDir) / name);
      r->run = RunData();
      if (!written) {
        std::lock_guard lock(mutex);
        if (firstError.empty()) firstError = written.errorText();
        stop = true;
        return false;
      }
    }
    Outcome& o = results[j];
    o.outcome = r->outcome;
    o.ratio = r->pathLengthUnits / mc.astarUnits;
    o.steps = static_cast<double>(r->steps);
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - r0).count();
    o.run.mapSeed = no.seed;
    o.run.outcome = r->outcome;
    o.run.steps = r->steps;
    o.run.budget = no.maxSteps;
    o.run.pathRatio = o.ratio;
    o.run.blockedSteps = r->blockedSteps;
    o.run.strategySteps = r->strategySteps;
    o.run.checkContactStarts = r->checkContactStarts;
    o.run.closestGoalUnits = r->closestGoalUnits;
    o.run.finalGoalUnits = r->finalGoalUnits;
    const std::size_t n = ++done;
    if (progress) {
      std::lock_guard lock(mutex);
      if (!progress(n, jobs)) stop = true;
    }
    return !stop;
  });
  if (!firstError.empty()) return Error(firstError);
  if (done < jobs) return Error("cancelled");

  BenchmarkResult out;
  out.maps = maps;
  for (std::size_t s = 0; s < sources.size(); ++s) {
    SourceSummary sum;
    sum.source = sources[s];
    std::vector<double> ratios;
    std::vector<double> steps;
    for (std::size_t m = 0; m < maps; ++m) {
      const Outcome& o = results[m * sources.size() + s];
      ++sum.runs;
      sum.seconds += o.seconds;
      sum.mapRuns.push_back(o.run);
      if (o.outcome == RunOutcome::Success) {
        ++sum.successes;
        ratios.push_back(o.ratio);
        steps.push_back(o.steps);
      } else if (o.outcome == RunOutcome::Unreachable) {
        ++sum.unreachable;
      } else {
        ++sum.timeouts;
      }
    }
    sum.successRate = sum.runs ? static_cast<double>(sum.successes) / sum.runs : 0.0;
    sum.medianPathRatio = quantile(ratios, 0.5);
    sum.p90PathRatio = quantile(ratios, 0.9);
    sum.medianSteps = quantile(steps, 0.5);
    out.sources.push_back(sum);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace tactile::nav
