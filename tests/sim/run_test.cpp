#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <mutex>

#include "run/run_csv.h"
#include "sim/recorder.h"
#include "sim/scene_source.h"
#include "sim_test_util.h"

namespace tactile::sim {
namespace {

std::shared_ptr<const World> builtinWorld(const char* name) {
  Result<Scene> r = loadScene(name);
  EXPECT_TRUE(r.ok()) << r.errorText();
  return std::make_shared<const World>(std::move(r.value()));
}

// FNV-1a, enough to compare run files by hash.
std::uint64_t fnv1a(std::string_view text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text)
    h = (h ^ c) * 1099511628211ULL;
  return h;
}

TEST(Recorder, RunCarriesMetadataStepsAndTruth) {
  RunOptions options;
  options.maxSteps = 400;
  options.seed = 5;
  options.driver = "random";
  RunResult r = simulateRun(builtinWorld("room1"), "room1", options);
  ASSERT_TRUE(r.ok()) << r.errorText();
  const RunData& run = r->run;
  EXPECT_EQ(run.stepCount(), 400u);
  ASSERT_NE(run.meta("format"), nullptr);
  EXPECT_EQ(*run.meta("format"), "tactile-run 1");
  EXPECT_EQ(*run.meta("scene"), "room1");
  EXPECT_EQ(*run.meta("subject"), "random");
  EXPECT_EQ(*run.meta("driver"), "random");
  EXPECT_EQ(*run.meta("seed"), "5");
  EXPECT_EQ(run.dtSeconds(), 0.1);
  ASSERT_TRUE(run.start().has_value());
  EXPECT_EQ(run.start()->x, 150.0);
  ASSERT_TRUE(run.goal().has_value());
  EXPECT_EQ(run.goal()->first, 1450.0);
  EXPECT_EQ(run.outcome(), RunOutcome::Timeout);
  ASSERT_TRUE(run.hasTruth());
  EXPECT_EQ(run.truth.size(), 400u * kGroupCount);
  EXPECT_EQ(run.sensors.size(), 400u * kValuesPerStep);
  // The random walk touches things: some truth is not NoContact and some steps are blocked or
  // carry non-zero values.
  const bool anyContact = std::any_of(run.truth.begin(), run.truth.end(),
                                      [](ContactClass c) { return c != ContactClass::NoContact; });
  EXPECT_TRUE(anyContact);
  for (std::size_t k = 0; k < run.stepCount(); ++k) {
    for (const GroupInfo& g : kSensorGroups) {
      bool zero = true;
      for (int d = g.firstSensor; d < g.firstSensor + g.sensorCount; ++d) {
        zero = zero && run.normal(k, d) == 0.0 && run.shear(k, d) == 0.0;
      }
      // Rule 1 of the truth: all-zero groups, and only those, are NoContact.
      ASSERT_EQ(zero, run.truthAt(k, g.group) == ContactClass::NoContact) << k;
    }
  }
}

TEST(Recorder, ReachingTheGoalEndsTheRunWithSuccess) {
  Scene s = test::roomWith({});
  s.goal = Vec2(1400, 1000);
  RunOptions options;
  options.maxSteps = 2000;
  RunResult r = simulateRun(std::make_shared<const World>(s), "open", options);
  ASSERT_TRUE(r.ok());
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->outcome, RunOutcome::Success);
  EXPECT_LT(r->run.stepCount(), 2000u);
  EXPECT_EQ(*r->run.meta("outcome"), "success");
}

TEST(Recorder, TooManyStepsIsAnError) {
  RunOptions options;
  options.maxSteps = kMaxStepsPerRun + 1;
  RunResult r = simulateRun(builtinWorld("practice"), "practice", options);
  EXPECT_FALSE(r.ok());
}

TEST(Recorder, UnknownDriverIsAnError) {
  RunOptions options;
  options.driver = "teleport";
  RunResult r = simulateRun(builtinWorld("practice"), "practice", options);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("teleport"), std::string::npos);
}

TEST(Recorder, WrittenFileReadsBackEqual) {
  RunOptions options;
  options.maxSteps = 300;
  options.driver = "wall-follow";
  RunResult r = simulateRun(builtinWorld("chapter5"), "chapter5", options);
  ASSERT_TRUE(r.ok());
  const auto path = std::filesystem::temp_directory_path() /
                    ("tactile_sim_test_" + std::to_string(::getpid()) + ".csv");
  ASSERT_TRUE(writeRunCsv(r->run, path).ok());
  RunCsvResult back = readRunCsv(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(back.ok()) << back.errorText();
  EXPECT_TRUE(back.value() == r->run);
}

TEST(Determinism, SameSeedGivesByteIdenticalFiles) {
  for (const char* driver : {"wall-follow", "random"}) {
    RunOptions options;
    options.maxSteps = 1500;
    options.seed = 42;
    options.driver = driver;
    auto world = builtinWorld("room2");
    const std::string a = formatRunCsv(simulateRun(world, "room2", options)->run);
    const std::string b = formatRunCsv(simulateRun(world, "room2", options)->run);
    EXPECT_EQ(fnv1a(a), fnv1a(b)) << driver;
    options.seed = 43;
    const std::string c = formatRunCsv(simulateRun(world, "room2", options)->run);
    EXPECT_NE(fnv1a(a), fnv1a(c)) << driver;
  }
}

std::vector<std::uint64_t> batchHashes(unsigned threads) {
  RunOptions options;
  options.maxSteps = 400;
  options.seed = 100;
  options.driver = "random";
  std::vector<std::uint64_t> hashes(8, 0);
  std::mutex m;
  const Status batch = simulateBatch(builtinWorld("room3"), "room3", options, hashes.size(),
                                     threads, [&](std::size_t i, SimulatedRun& r) {
                                       const std::uint64_t h = fnv1a(formatRunCsv(r.run));
                                       std::lock_guard lock(m);
                                       hashes[i] = h;
                                       return Status::success();
                                     });
  EXPECT_TRUE(batch.ok());
  return hashes;
}

TEST(Determinism, BatchIsIndependentOfThreadCount) {
  const auto one = batchHashes(1);
  const auto two = batchHashes(2);
  const auto four = batchHashes(4);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, four);
  // Run i uses seed + i: the runs differ from each other, and run 0 equals a single run.
  EXPECT_NE(one[0], one[1]);
  RunOptions options;
  options.maxSteps = 400;
  options.seed = 100;
  options.driver = "random";
  EXPECT_EQ(one[0], fnv1a(formatRunCsv(simulateRun(builtinWorld("room3"), "room3", options)->run)));
}

TEST(Batch, SinkErrorStopsTheBatch) {
  RunOptions options;
  options.maxSteps = 50;
  const Status batch = simulateBatch(
      builtinWorld("practice"), "practice", options, 20, 2, [](std::size_t i, SimulatedRun&) {
        return i == 3 ? Status(Error("disk full")) : Status::success();
      });
  ASSERT_FALSE(batch.ok());
  EXPECT_EQ(batch.errorText(), "disk full");
}

TEST(Batch, ProgressCanCancel) {
  RunOptions options;
  options.maxSteps = 50;
  std::size_t calls = 0;
  const Status batch = simulateBatch(builtinWorld("practice"), "practice", options, 50, 1, {},
                                     [&](std::size_t, std::size_t) { return ++calls < 3; });
  ASSERT_FALSE(batch.ok());
  EXPECT_EQ(batch.errorText(), "cancelled");
  EXPECT_EQ(calls, 3u);
}

TEST(ManualDriver, ReplaysTheQueueThenStops) {
  ManualDriver driver;
  driver.push({10, 0}, 2);
  driver.push({0, 1}, 1);
  driver.push({5, 5}, 0);  // ignored
  Observation obs;
  EXPECT_EQ(driver.pending(), 2u);
  EXPECT_EQ(driver.next(obs).v, 10);
  EXPECT_EQ(driver.next(obs).v, 10);
  EXPECT_EQ(driver.next(obs).omega, 1);
  const Command idle = driver.next(obs);
  EXPECT_EQ(idle.v, 0);
  EXPECT_EQ(idle.omega, 0);
}

TEST(WallFollow, ReachesTheGoalInThePracticeScene) {
  // The practice scene has one box between start and goal: Bug-2 must get around it.
  int successes = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    RunOptions options;
    options.maxSteps = 5000;
    options.seed = seed;
    RunResult r = simulateRun(builtinWorld("practice"), "practice", options);
    ASSERT_TRUE(r.ok());
    successes += r->outcome == RunOutcome::Success;
  }
  EXPECT_GE(successes, 3);
}

}  // namespace
}  // namespace tactile::sim
