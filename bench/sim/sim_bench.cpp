// Simulator step rate: one step = driver command, sub-stepped motion with the blocked rule, all
// 44 domes with the spring-damper, ground truth, and recording into a RunData in memory.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "sim/polygon_check.h"
#include "sim/recorder.h"
#include "sim/scene.h"
#include "sim/scene_source.h"

namespace tactile::sim {
namespace {

std::shared_ptr<const World> worldFor(const std::string& spec) {
  Result<Scene> r = loadScene(spec);
  if (!r) throw std::runtime_error(r.errorText());
  return std::make_shared<const World>(std::move(r.value()));
}

// Runs `steps` steps of a driver per iteration; reports steps per second.
void runSteps(benchmark::State& state, const std::shared_ptr<const World>& world,
              const char* driver, bool useIndex, std::size_t steps) {
  std::size_t contactSteps = 0;
  for (auto _ : state) {
    RunOptions options;
    options.maxSteps = steps;
    options.seed = 1;
    options.driver = driver;
    options.stopAtGoal = false;
    options.config.useIndex = useIndex;
    RunResult r = simulateRun(world, "bench", options);
    if (!r.ok()) {
      state.SkipWithError(r.errorText().c_str());
      return;
    }
    contactSteps = 0;
    for (std::size_t k = 0; k < r->run.stepCount(); ++k) {
      for (int g = 0; g < kGroupCount; ++g) {
        if (r->run.truth[k * kGroupCount + g] != ContactClass::NoContact) {
          ++contactSteps;
          break;
        }
      }
    }
    benchmark::DoNotOptimize(r->run.sensors.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * steps));
  state.counters["contact_fraction"] = static_cast<double>(contactSteps) / steps;
}

void BM_ClutteredRoom(benchmark::State& state) {
  static const auto world = worldFor("room1");
  runSteps(state, world, state.range(0) == 0 ? "wall-follow" : "random", true, 20000);
}
BENCHMARK(BM_ClutteredRoom)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_Procedural(benchmark::State& state) {
  const auto world = worldFor("random:" + std::to_string(state.range(0)) + ":1");
  runSteps(state, world, "random", true, 20000);
}
BENCHMARK(BM_Procedural)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_ProceduralBruteForce(benchmark::State& state) {
  const auto world = worldFor("random:" + std::to_string(state.range(0)) + ":1");
  runSteps(state, world, "random", false, 1000);
}
BENCHMARK(BM_ProceduralBruteForce)
    ->Arg(10)
    ->Arg(100)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond);

// Scene validation of one obstacle of N vertices (a star-shaped simple polygon, the worst case:
// every edge is checked), through the whole JSON parse as a user's scene file is read, and the
// polygon check alone; the pair-by-pair check it replaced, at small N, as the baseline.
std::vector<Vec2> starPolygon(std::size_t n) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> radius(3.0e5, 1.0e6);
  std::vector<Vec2> poly;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    const double r = radius(rng);
    poly.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return poly;
}

std::string starSceneJson(std::size_t n) {
  Scene scene;
  scene.name = "star";
  scene.bounds = {-2.0e6, -2.0e6, 2.0e6, 2.0e6};
  scene.obstacles.push_back({starPolygon(n)});
  scene.start = {1.5e6, 1.5e6, 0.0};
  scene.goal = Vec2(-1.5e6, -1.5e6);
  return sceneToJson(scene);
}

void BM_SceneJsonLargePolygon(benchmark::State& state) {
  const std::string text = starSceneJson(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    Result<Scene> r = parseSceneJson(text, "star.json");
    if (!r) {
      state.SkipWithError(r.errorText().c_str());
      return;
    }
    benchmark::DoNotOptimize(r->obstacles.data());
  }
}
BENCHMARK(BM_SceneJsonLargePolygon)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_PolygonSweep(benchmark::State& state) {
  const auto poly = starPolygon(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(polygonSelfContactSweep(poly));
}
BENCHMARK(BM_PolygonSweep)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_PolygonPairByPair(benchmark::State& state) {
  const auto poly = starPolygon(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(polygonSelfContactBruteForce(poly));
}
BENCHMARK(BM_PolygonPairByPair)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tactile::sim

BENCHMARK_MAIN();
