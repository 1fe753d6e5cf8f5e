// Whole navigation runs in small hand-made scenes: the goal reached round an obstacle and through
// a hole, an enclosed goal ending as unreachable, a too-narrow gap never forced, determinism.
#include <gtest/gtest.h>

#include "nav/navigate.h"
#include "run/run_csv.h"
#include "sim/scene.h"
#include "sim/scene_source.h"

namespace tactile::nav {
namespace {

sim::Obstacle box(double x0, double y0, double x1, double y1) {
  return sim::Obstacle{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}};
}

std::shared_ptr<const sim::World> worldOf(std::vector<sim::Obstacle> obstacles, double width = 1400,
                                          double height = 900,
                                          std::optional<Vec2> goal = std::nullopt) {
  sim::Scene s;
  s.name = "test";
  s.bounds = {0, 0, width, height};
  s.obstacles = std::move(obstacles);
  s.start = {200, 450, 0};
  s.goal = goal ? *goal : Vec2(width - 200, 450);
  return std::make_shared<const sim::World>(std::move(s));
}

// A wall across the scene at x = 700..720 with openings [y0, y1).
std::vector<sim::Obstacle> wallWithOpenings(std::vector<std::pair<double, double>> openings,
                                            double height = 900) {
  std::vector<sim::Obstacle> out;
  double y = 0.0;
  for (const auto& [y0, y1] : openings) {
    if (y0 > y) out.push_back(box(700, y, 720, y0));
    y = y1;
  }
  if (y < height) out.push_back(box(700, y, 720, height));
  return out;
}

NavigateResult run(const std::shared_ptr<const sim::World>& world, StatusSource source,
                   Pose2d start, std::size_t maxSteps = 8000) {
  NavigatorConfig config;
  config.source = source;
  config.planDrive = false;  // the thesis strategies
  NavigateOptions options;
  options.maxSteps = maxSteps;
  auto r = navigate(world, "test", start, world->scene().goal, config, options);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.errorText());
  return std::move(r.value());
}

TEST(Navigate, TinySceneReachesTheGoalRoundABox) {
  const auto world = worldOf({box(600, 330, 700, 570)});
  for (StatusSource source : {StatusSource::Truth, StatusSource::Bumper}) {
    for (double y : {400.0, 500.0}) {
      const NavigateResult r = run(world, source, {200, y, 0});
      EXPECT_EQ(r.outcome, RunOutcome::Success)
          << statusSourceName(source) << " from y " << y << ": " << runOutcomeName(r.outcome)
          << " after " << r.steps << " steps";
      EXPECT_GT(r.pathLengthUnits, 900.0);
      EXPECT_EQ(r.run.stepCount(), r.steps);
    }
  }
}

// Known miss: hitting the box dead-on (from y 450) with the truth source still times out: the
// odometry drifts over the blocked steps of Check Contact and the robot stops short of the goal.
TEST(Navigate, TinySceneDeadOnHit) {
  const auto world = worldOf({box(600, 330, 700, 570)});
  EXPECT_EQ(run(world, StatusSource::Truth, {200, 450, 0}).outcome, RunOutcome::Success);
}

TEST(Navigate, EnclosedGoalEndsUnreachable) {
  // The goal inside a closed ring of four walls.
  const auto world = worldOf({box(950, 250, 1250, 270), box(950, 630, 1250, 650),
                              box(950, 270, 970, 630), box(1230, 270, 1250, 630)},
                             2000, 1000, Vec2(1100, 450));
  for (StatusSource source : {StatusSource::Truth, StatusSource::Bumper}) {
    const NavigateResult r = run(world, source, {200, 450, 0}, 20000);
    EXPECT_EQ(r.outcome, RunOutcome::Unreachable)
        << statusSourceName(source) << ": " << runOutcomeName(r.outcome) << " after " << r.steps;
    EXPECT_EQ(*r.run.meta("outcome"), "unreachable");
  }
}

// A wall across the scene with only a gap narrower than the robot: the robot goes round the
// closed half (hitting the wall again where it hit it before, no closer to the goal) and ends
// as unreachable, never in a timeout.
TEST(Navigate, WallWithOnlyANarrowGapIsUnreachable) {
  // 70 wide: narrower than the body with its domes fully compressed (82).
  const auto world = worldOf(wallWithOpenings({{400, 470}}));
  for (double y : {200.0, 600.0}) {
    const NavigateResult r = run(world, StatusSource::Truth, {250, y, 0}, 20000);
    EXPECT_EQ(r.outcome, RunOutcome::Unreachable) << "from y " << y << " after " << r.steps;
  }
}

// A 120-wide gap in a wall across the whole scene is passed from starts spread over the start's
// side, facing within 40 degrees of the goal. Target: always; measured 23 of 27: in the misses
// Check Contact does not settle beside a wall met nearly head on, and the loop detection then
// gives up (unreachable) or the run times out (docs/navigation.md#figures-and-known-misses).
// This holds the line at 20.
TEST(Navigate, GapOf120IsPassed) {
  int passed = 0;
  int runs = 0;
  for (double gapY : {250.0, 450.0, 650.0}) {
    const auto world = worldOf(wallWithOpenings({{gapY - 60.0, gapY + 60.0}}));
    for (double y : {150.0, 450.0, 750.0}) {
      for (double theta : {-0.7, 0.0, 0.7}) {
        const NavigateResult r = run(world, StatusSource::Truth, {250, y, theta}, 8000);
        ++runs;
        passed += r.outcome == RunOutcome::Success ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(passed, runs) << passed << " of " << runs;
}

// A 90-wide gap (the robot with its domes is 92 wide) is never tried for long: with a way round
// the wall's end, the robot goes round, and the steps spent moving through a hole stay few.
TEST(Navigate, GapOf90IsGivenUpQuickly) {
  for (double gapY : {300.0, 450.0}) {
    // The wall stops 250 short of the top bound: the way round.
    auto obstacles = wallWithOpenings({{gapY - 45.0, gapY + 45.0}, {650.0, 900.0}});
    const auto world = worldOf(std::move(obstacles));
    for (double y : {200.0, 450.0, 700.0}) {
      const NavigateResult r = run(world, StatusSource::Truth, {250, y, 0.0}, 8000);
      EXPECT_EQ(r.outcome, RunOutcome::Success)
          << "gap at " << gapY << " from y " << y << ": " << runOutcomeName(r.outcome) << " after "
          << r.steps;
      EXPECT_LT(r.steps, 4000u) << "gap at " << gapY << " from y " << y;
      std::size_t through = 0;
      const std::size_t cols = r.run.extraColumns.size();
      for (std::size_t k = 0; k < r.run.stepCount(); ++k)
        through += r.run.extraValues[k * cols] == "MoveThroughWall" ? 1 : 0;
      EXPECT_LT(through, 300u) << "gap at " << gapY << " from y " << y;
    }
  }
}

TEST(Navigate, HoleWiderThanTheRobotIsPassed) {
  const auto world = worldOf(wallWithOpenings({{400, 520}}));
  for (double y : {200.0, 450.0, 700.0}) {
    const NavigateResult r = run(world, StatusSource::Truth, {250, y, 0});
    EXPECT_EQ(r.outcome, RunOutcome::Success) << "from y " << y << " after " << r.steps;
  }
}

TEST(Navigate, RunsAreDeterministicAndCarryTheNavigatorColumns) {
  const auto world = worldOf({box(600, 330, 700, 570)});
  const NavigateResult a = run(world, StatusSource::Truth, {200, 420, 0.1});
  const NavigateResult b = run(world, StatusSource::Truth, {200, 420, 0.1});
  EXPECT_TRUE(a.run == b.run);
  ASSERT_EQ(a.run.extraColumns.size(), 2u + kGroupCount);
  EXPECT_EQ(a.run.extraColumns[0], "x_strategy");
  EXPECT_EQ(a.run.extraColumns[1], "x_status");
  EXPECT_EQ(a.run.extraColumns[2], "x_status_F");
  EXPECT_EQ(a.run.extraValues.size(), a.run.stepCount() * a.run.extraColumns.size());
  // Every strategy cell reads back; the first step heads for the goal.
  for (std::size_t k = 0; k < a.run.stepCount(); ++k)
    EXPECT_TRUE(parseStrategyKey(a.run.extraValues[k * a.run.extraColumns.size()]));
  EXPECT_EQ(a.run.extraValues[0], "HeadToDestination");
  // And the run file round-trips through the one reader.
  const std::string text = formatRunCsv(a.run);
  auto back = parseRunCsv(text, "nav.csv");
  ASSERT_TRUE(back.ok()) << back.errorText();
  EXPECT_TRUE(back.value() == a.run);
}

// Office map 900014 with the bumper Bug2 from seed 1's start: the robot drives into a spot between
// furniture and wall where every escape move (turns, short backs and pushes) is blocked. Without
// retracing its own moves it stays there until the budget ends (4076 of 6000 steps blocked); with
// it, it backs out the way it came.
TEST(Navigate, WedgedRobotRetracesItsMoves) {
  auto loaded = sim::loadScene("random:office:900014");
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  auto world = std::make_shared<const sim::World>(std::move(loaded.value()));
  const Pose2d start = drawStart(world, 1);
  const NavigateResult r = run(world, StatusSource::Bumper, start, 6000);
  EXPECT_GT(r.steps, 1000u);
  EXPECT_LT(r.blockedSteps, r.steps / 10);
  // The same holds for the touch navigator on the same map.
  const NavigateResult t = run(world, StatusSource::Truth, start, 6000);
  EXPECT_LT(t.blockedSteps, t.steps / 10);
}

TEST(Navigate, DrawStartIsDeterministicAndFree) {
  auto loaded = sim::loadScene("chapter5");
  ASSERT_TRUE(loaded.ok());
  const auto world = std::make_shared<const sim::World>(std::move(loaded.value()));
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Pose2d a = drawStart(world, seed);
    const Pose2d b = drawStart(world, seed);
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.theta, b.theta);
    EXPECT_LT(a.x, 1000.0 - 200.0);  // the start's side of the wall
    sim::Simulator probe(world);
    EXPECT_FALSE(probe.isBlocked(a));
  }
  EXPECT_NE(drawStart(world, 1).y, drawStart(world, 2).y);
}

}  // namespace
}  // namespace tactile::nav
