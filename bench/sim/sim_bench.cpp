// Simulator step rate: one step = driver command, sub-stepped motion with the blocked rule, all
// 44 domes with the spring-damper, ground truth, and recording into a RunData in memory.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "sim/recorder.h"
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

}  // namespace
}  // namespace tactile::sim

BENCHMARK_MAIN();
