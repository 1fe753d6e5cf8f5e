// Plan drive (docs/navigation.md#plan-drive): the robot follows the touch map's plan; at a contact
// ahead it marks the touching domes' cells, backs off and replans; no way on the map ends the run
// as unreachable; runs are deterministic.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "nav/navigate.h"
#include "nav/navigator.h"
#include "nav/touch_map.h"
#include "sim/robot.h"
#include "tests/nav/scripted_readings.h"

namespace tactile::nav {
namespace {

using test::box;
using test::press;
using test::ringWorld;
using test::Script;
using test::touchPoint;
using test::Values;
using test::worldOf;

TEST(PlanDrive, ContactAheadMarksBacksOffAndReplansRoundIt) {
  Script s(false, Vec2(2000.0, 0.0), true);
  // Free way: straight at the goal, on a plan to it.
  Command c{};
  for (int k = 0; k < 5; ++k)
    c = s.step(Values{});
  EXPECT_GT(c.v, 0.0);
  EXPECT_LT(std::abs(c.omega), 0.1);  // at most a cell's offset (the plan runs on cell centres)
  EXPECT_EQ(s.nav().strategy(), Strategy::HeadToDestination);
  ASSERT_TRUE(s.nav().plan());
  EXPECT_FALSE(s.nav().touchMap().empty());
  EXPECT_EQ(s.nav().touchMap().touchedCount(), 0);

  // The front meets something: its domes mark their cells, and the robot backs off.
  Values front{};
  press(front, {2, 3, 4, 5}, 2.0);
  c = s.step(front);
  const Pose2d hit = s.nav().odometry();
  std::vector<Vec2> marks;
  for (int sensor : {2, 3, 4, 5}) {
    marks.push_back(touchPoint(hit, sensor));
    EXPECT_TRUE(s.nav().touchMap().touched(marks.back()));
  }
  EXPECT_LT(c.v, 0.0);
  EXPECT_EQ(s.nav().strategy(), Strategy::CheckContact);

  // Backs off a little (20 units: a handful of steps at half cruise), then turns off the straight
  // line on a new plan that keeps clear of the marks.
  int backSteps = 0;
  while (s.nav().strategy() == Strategy::CheckContact && backSteps < 100) {
    c = s.step(Values{});
    ++backSteps;
  }
  EXPECT_GE(backSteps, 5);
  EXPECT_LE(backSteps, 12);
  EXPECT_LT(s.nav().odometry().x, hit.x - 15.0);
  ASSERT_TRUE(s.nav().plan());
  for (const Vec2& p : s.nav().plan()->points)
    for (const Vec2& m : marks)
      EXPECT_GT((p - m).norm(), 40.0) << "plan point " << p.transpose();
  EXPECT_NE(c.omega, 0.0);
  // Driving on, it passes beside the marks and comes back toward the goal's line.
  double farthestSide = 0.0;
  for (int k = 0; k < 200; ++k) {
    s.step(Values{});
    farthestSide = std::max(farthestSide, std::abs(s.nav().odometry().y));
  }
  EXPECT_GT(s.nav().odometry().x, hit.x + 150.0);
  EXPECT_GT(farthestSide, 40.0);
  for (const Vec2& m : marks)
    EXPECT_TRUE(s.nav().touchMap().touched(m));
  EXPECT_FALSE(s.nav().finished());
}

// ---- whole runs --------------------------------------------------------------------------------

NavigateResult drive(const std::shared_ptr<const sim::World>& world, Pose2d start,
                     std::size_t maxSteps, StatusSource source = StatusSource::Truth) {
  NavigatorConfig config;
  config.source = source;
  config.planDrive = true;
  NavigateOptions options;
  options.maxSteps = maxSteps;
  auto r = navigate(world, "test", start, world->scene().goal, config, options);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.errorText());
  return std::move(r.value());
}

std::size_t stepsIn(const NavigateResult& r, Strategy s) {
  return r.strategySteps[static_cast<std::size_t>(s)];
}

TEST(PlanDriveNavigate, ReachesTheGoalRoundABoxAndIsDeterministic) {
  const auto world = worldOf({box(600, 300, 700, 600)}, 1400, 900, Vec2(1200, 450));
  for (double y : {380.0, 450.0, 520.0}) {
    const NavigateResult a = drive(world, {200, y, 0}, 6000);
    EXPECT_EQ(a.outcome, RunOutcome::Success) << "from y " << y << " after " << a.steps;
    // Round a 300-long box in well under the way a wall follower circles it.
    EXPECT_LT(a.pathLengthUnits, 2.0 * 1000.0) << "from y " << y;
    EXPECT_GT(stepsIn(a, Strategy::CheckContact), 0u);  // it met the box
    EXPECT_EQ(stepsIn(a, Strategy::FollowWall), 0u);    // and never followed a wall
    const NavigateResult b = drive(world, {200, y, 0}, 6000);
    EXPECT_EQ(a.steps, b.steps);
    EXPECT_TRUE(a.run == b.run);  // byte for byte the same run
  }
}

// A wall across the scene at x = 700..720 with openings [y0, y1).
std::vector<sim::Obstacle> wallWithOpenings(std::vector<std::pair<double, double>> openings) {
  std::vector<sim::Obstacle> out;
  double y = 0.0;
  for (const auto& [y0, y1] : openings) {
    if (y0 > y) out.push_back(box(700, y, 720, y0));
    y = y1;
  }
  if (y < 900.0) out.push_back(box(700, y, 720, 900.0));
  return out;
}

// A 120-wide gap in a wall across the room is passed from 27 starts spread over the start's side
// (three gap heights, three heights, three headings). One start is still missed (documented in
// docs/navigation.md#figures-and-known-misses): from (250, 150) heading 0 toward the gap at 250 the
// robot meets the lower jamb at a slant with its front corner, backs off, and meets it again the
// same way until its budget ends. Every other start passes.
TEST(PlanDriveNavigate, GapOf120IsPassedFromAllButOneStart) {
  int passed = 0;
  int runs = 0;
  for (double gapY : {250.0, 450.0, 650.0}) {
    const auto world =
        worldOf(wallWithOpenings({{gapY - 60.0, gapY + 60.0}}), 1400, 900, Vec2(1200, 450));
    for (double y : {150.0, 450.0, 750.0}) {
      for (double theta : {-0.7, 0.0, 0.7}) {
        const NavigateResult r = drive(world, {250, y, theta}, 8000);
        ++runs;
        const bool known = gapY == 250.0 && y == 150.0 && theta == 0.0;
        if (r.outcome == RunOutcome::Success) {
          ++passed;
        } else {
          EXPECT_TRUE(known) << "gap at " << gapY << " from (" << y << ", " << theta
                             << "): " << runOutcomeName(r.outcome) << " after " << r.steps;
        }
      }
    }
  }
  EXPECT_GE(passed, runs - 1);
}

// A 90-wide gap (the robot with its domes is 92 wide) is never driven through: the run goes round
// the wall's end, and never uses Move through Wall.
TEST(PlanDriveNavigate, GapOf90IsGoneRound) {
  for (double gapY : {300.0, 450.0}) {
    const auto world = worldOf(wallWithOpenings({{gapY - 45.0, gapY + 45.0}, {650.0, 900.0}}), 1400,
                               900, Vec2(1200, 450));
    for (double y : {200.0, 450.0, 700.0}) {
      const NavigateResult r = drive(world, {250, y, 0.0}, 8000);
      EXPECT_EQ(r.outcome, RunOutcome::Success)
          << "gap at " << gapY << " from y " << y << " after " << r.steps;
      EXPECT_LT(r.steps, 4000u) << "gap at " << gapY << " from y " << y;
      EXPECT_EQ(stepsIn(r, Strategy::MoveThroughWall), 0u);
    }
  }
}

// A contact ahead with the goal close by on cells the contact closed (the goal where the odometry
// puts it lies at or behind what was touched): the robot searches round the goal from there
// instead of backing off and driving into the same contact again. A goal close by but clear of
// the marks, or a closed goal far away, does not start the search.
TEST(PlanDrive, ContactWithTheGoalBehindItStartsTheSearch) {
  struct Case {
    Vec2 goal;
    bool search;
  };
  for (const Case& k : {Case{Vec2(150.0, 0.0), true}, Case{Vec2(150.0, 10.0), true},
                        Case{Vec2(130.0, 110.0), false}, Case{Vec2(400.0, 0.0), false}}) {
    Script s(false, k.goal, true);
    for (int i = 0; i < 4; ++i)
      s.step(Values{});
    ASSERT_FALSE(s.nav().arrived());
    const double goalAhead = k.goal.x() - s.nav().odometry().x;
    Values front{};
    press(front, {0, 1, 2, 3, 4, 5}, 2.0);
    const Command c = s.step(front);
    EXPECT_LT(c.v, 0.0) << "goal " << k.goal.transpose();  // off the contact either way
    EXPECT_EQ(s.nav().arrived(), k.search)
        << "goal " << k.goal.transpose() << ", " << goalAhead << " ahead of the axle";
    EXPECT_EQ(s.nav().touchMap().closed(k.goal), k.goal.x() < 300.0 && k.goal.y() < 50.0);
  }
}

// No way exists: a goal in a closed ring of walls, and a wall across the scene whose only gap
// (70) is narrower than the robot. Both end as unreachable, well before the step budget.
TEST(PlanDriveNavigate, EnclosedGoalEndsUnreachable) {
  const auto ring = ringWorld();
  for (double y : {380.0, 450.0, 520.0}) {
    const NavigateResult r = drive(ring, {200, y, 0}, 20000);
    EXPECT_EQ(r.outcome, RunOutcome::Unreachable)
        << "from y " << y << ": " << runOutcomeName(r.outcome) << " after " << r.steps;
  }
  const auto narrow =
      worldOf({box(700, 0, 720, 400), box(700, 470, 720, 900)}, 1400, 900, Vec2(1200, 450));
  for (double y : {200.0, 450.0, 600.0}) {
    const NavigateResult r = drive(narrow, {250, y, 0}, 20000);
    EXPECT_EQ(r.outcome, RunOutcome::Unreachable)
        << "from y " << y << ": " << runOutcomeName(r.outcome) << " after " << r.steps;
  }
}

// The bumper source keeps its Bug2: plan drive does not apply to it.
TEST(PlanDriveNavigate, BumperSourceKeepsItsBug2) {
  const auto world = worldOf({box(600, 300, 700, 600)}, 1400, 900, Vec2(1200, 450));
  NavigatorConfig plain;
  plain.source = StatusSource::Bumper;
  NavigatorConfig drive = plain;
  drive.planDrive = true;
  NavigateOptions options;
  options.maxSteps = 3000;
  auto a = navigate(world, "test", {200, 400, 0}, world->scene().goal, plain, options);
  auto b = navigate(world, "test", {200, 400, 0}, world->scene().goal, drive, options);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_TRUE(a->run == b->run);
}

}  // namespace
}  // namespace tactile::nav
