// What a navigation run and the map benchmark report about themselves: the steps spent in each
// strategy, the Check Contact back-offs, the closest approach to the goal, and the benchmark's
// per-map records and run files (the instrumentation behind docs/navigation-bench.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <string>

#include "nav/benchmark.h"
#include "nav/navigate.h"
#include "run/run_csv.h"
#include "sim/scene.h"

namespace tactile::nav {
namespace {

sim::Obstacle box(double x0, double y0, double x1, double y1) {
  return sim::Obstacle{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}};
}

// A wall across a 1400 x 900 room with one 200-wide opening near its lower end: the goal is
// reached only by meeting the wall and following it.
std::shared_ptr<const sim::World> wallScene() {
  sim::Scene s;
  s.name = "records";
  s.bounds = {0, 0, 1400, 900};
  s.obstacles = {box(700, 0, 720, 100), box(700, 300, 720, 900)};
  s.start = {250, 600, 0};
  s.goal = Vec2(1200, 600);
  return std::make_shared<const sim::World>(std::move(s));
}

std::size_t strategyIndex(Strategy s) {
  return static_cast<std::size_t>(s);
}

TEST(NavigateRecords, StrategyStepsMatchTheRecordedColumn) {
  auto world = wallScene();
  NavigatorConfig config;
  config.source = StatusSource::Truth;
  config.planDrive = false;  // the thesis strategies
  NavigateOptions options;
  options.maxSteps = 4000;
  auto r = navigate(world, "records", world->scene().start, world->scene().goal, config, options);
  ASSERT_TRUE(r) << r.errorText();
  const NavigateResult& result = r.value();
  ASSERT_GT(result.steps, 0u);

  // Every step is counted once, under the strategy the run file names for it.
  std::size_t total = 0;
  for (std::size_t n : result.strategySteps)
    total += n;
  EXPECT_EQ(total, result.steps);
  const RunData& run = result.run;
  const std::size_t columns = run.extraColumns.size();
  ASSERT_GT(columns, 0u);
  ASSERT_EQ(run.extraColumns[0], "x_strategy");
  ASSERT_EQ(run.extraValues.size(), result.steps * columns);
  std::array<std::size_t, kStrategyCount> counted{};
  std::size_t entries = 0;  // steps where Check Contact begins after another strategy
  for (std::size_t k = 0; k < result.steps; ++k) {
    const auto s = parseStrategyKey(run.extraValues[k * columns]);
    ASSERT_TRUE(s.has_value()) << run.extraValues[k * columns];
    ++counted[strategyIndex(*s)];
    const bool previousCheck =
        k > 0 && run.extraValues[(k - 1) * columns] == strategyKey(Strategy::CheckContact);
    if (*s == Strategy::CheckContact && !previousCheck) ++entries;
  }
  EXPECT_EQ(counted, result.strategySteps);

  // The wall is met, so Check Contact runs; each entry starts with a back-off, and restarts
  // within one count too.
  EXPECT_GT(result.strategySteps[strategyIndex(Strategy::CheckContact)], 0u);
  EXPECT_GE(result.checkContactStarts, entries);
  EXPECT_GT(entries, 0u);

  // Distances to the goal: the closest approach is at most the final one; a success ends inside
  // the referee's circle.
  EXPECT_GE(result.closestGoalUnits, 0.0);
  EXPECT_LE(result.closestGoalUnits, result.finalGoalUnits);
  if (result.outcome == RunOutcome::Success) {
    EXPECT_LT(result.finalGoalUnits, options.goalRadiusUnits);
  } else {
    EXPECT_GE(result.finalGoalUnits, options.goalRadiusUnits);
  }
}

TEST(NavigateRecords, ARunThatNeverMeetsAnythingHasNoCheckContact) {
  sim::Scene s;
  s.name = "open";
  s.bounds = {0, 0, 1400, 900};
  s.start = {250, 450, 0};
  s.goal = Vec2(1000, 450);
  auto world = std::make_shared<const sim::World>(std::move(s));
  NavigatorConfig config;
  config.source = StatusSource::Truth;
  config.planDrive = false;  // the thesis strategies
  NavigateOptions options;
  options.maxSteps = 2000;
  auto r =
      navigate(world, "open", world->scene().start, world->scene().goal, config, options, false);
  ASSERT_TRUE(r) << r.errorText();
  EXPECT_EQ(r->outcome, RunOutcome::Success);
  EXPECT_EQ(r->checkContactStarts, 0u);
  EXPECT_EQ(r->strategySteps[strategyIndex(Strategy::CheckContact)], 0u);
  EXPECT_EQ(r->strategySteps[strategyIndex(Strategy::HeadToDestination)], r->steps);
  // Straight at the goal: the closest approach is the end, inside the referee's circle.
  EXPECT_DOUBLE_EQ(r->closestGoalUnits, r->finalGoalUnits);
  EXPECT_LT(r->finalGoalUnits, options.goalRadiusUnits);
}

TEST(MapBenchmark, MapRunsAddUpToTheSummaryAndWriteTheirRuns) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("tactile_bench_records_" +
       std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);

  BenchmarkOptions options;
  options.maps = 3;
  options.seed = 1;
  options.threads = 2;
  options.outDir = dir.string();  // no models: truth and bumper only
  auto recorded = runMapBenchmark(options);
  ASSERT_TRUE(recorded) << recorded.errorText();
  options.outDir.clear();
  options.threads = 1;
  auto plain = runMapBenchmark(options);
  ASSERT_TRUE(plain) << plain.errorText();

  ASSERT_EQ(recorded->sources.size(), 2u);
  ASSERT_EQ(plain->sources.size(), 2u);
  for (std::size_t s = 0; s < 2; ++s) {
    const SourceSummary& sum = recorded->sources[s];
    ASSERT_EQ(sum.mapRuns.size(), options.maps);
    std::size_t successes = 0, unreachable = 0, timeouts = 0;
    for (std::size_t m = 0; m < sum.mapRuns.size(); ++m) {
      const MapRun& run = sum.mapRuns[m];
      EXPECT_EQ(run.mapSeed, mapSeed(options.seed, m));
      successes += run.outcome == RunOutcome::Success;
      unreachable += run.outcome == RunOutcome::Unreachable;
      timeouts += run.outcome == RunOutcome::Timeout;
      std::size_t total = 0;
      for (std::size_t n : run.strategySteps)
        total += n;
      EXPECT_EQ(total, run.steps);
      EXPECT_LE(run.steps, run.budget);
      EXPECT_GE(run.budget, options.maxSteps);
      if (run.outcome == RunOutcome::Timeout) {
        EXPECT_EQ(run.steps, run.budget);
      }
      EXPECT_GT(run.pathRatio, 0.0);
      EXPECT_LE(run.closestGoalUnits, run.finalGoalUnits);

      // Recording changes nothing, nor does the thread count.
      const MapRun& again = plain->sources[s].mapRuns[m];
      EXPECT_EQ(again.outcome, run.outcome);
      EXPECT_EQ(again.steps, run.steps);
      EXPECT_EQ(again.strategySteps, run.strategySteps);
      EXPECT_EQ(again.checkContactStarts, run.checkContactStarts);
      EXPECT_DOUBLE_EQ(again.pathRatio, run.pathRatio);

      // The run file: one row a step, the navigator's columns, the map's scene.
      const std::string name = "benchmark_" + std::string(statusSourceName(sum.source)) + "_" +
                               std::to_string(run.mapSeed) + ".csv";
      auto file = readRunCsv(dir / name);
      ASSERT_TRUE(file) << name << ": " << file.errorText();
      EXPECT_EQ(file->stepCount(), run.steps);
      const std::string* scene = file->meta("scene");
      ASSERT_NE(scene, nullptr);
      EXPECT_EQ(*scene, "random:office:" + std::to_string(run.mapSeed));
      EXPECT_NE(std::find(file->extraColumns.begin(), file->extraColumns.end(), "x_strategy"),
                file->extraColumns.end());
    }
    EXPECT_EQ(successes, sum.successes);
    EXPECT_EQ(unreachable, sum.unreachable);
    EXPECT_EQ(timeouts, sum.timeouts);
  }
  std::filesystem::remove_all(dir);
}

TEST(MapBenchmark, UnwritableOutDirFails) {
  BenchmarkOptions options;
  options.maps = 1;
  options.threads = 1;
  options.outDir = "/nonexistent-dir-for-tactile-tests/sub";
  auto r = runMapBenchmark(options);
  ASSERT_FALSE(r);
  EXPECT_NE(r.errorText().find("nonexistent-dir-for-tactile-tests"), std::string::npos)
      << r.errorText();
}

}  // namespace
}  // namespace tactile::nav
