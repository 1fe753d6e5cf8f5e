// The touch map (docs/navigation.md#the-touch-map): marking and clearing cells, the grid A* on
// hand-made maps (a wall with no way through leaves no plan: the navigator's `unreachable`), the
// navigator marking what its domes touch, the plan choosing the follow side, and determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <memory>
#include <tuple>

#include "nav/navigate.h"
#include "nav/navigator.h"
#include "nav/touch_map.h"
#include "run/run_csv.h"
#include "sim/robot.h"
#include "tests/nav/scripted_readings.h"

namespace tactile::nav {
namespace {

using test::box;
using test::press;
using test::ringWorld;
using test::Script;
using test::touchPoint;
using test::Truth;
using test::truthOf;
using test::Values;
using test::worldOf;

// A map over x in [0, 1000] (plus the margin), cells of 20, growth 40.
TouchMap plainMap(double margin = 300.0) {
  TouchMapConfig c;
  c.marginUnits = margin;
  return TouchMap(Vec2(0.0, 0.0), Vec2(1000.0, 0.0), c);
}

// Touches every 10 units along x = `x` from y0 to y1.
void markWall(TouchMap& map, double x, double y0, double y1) {
  for (double y = y0; y <= y1; y += 10.0)
    map.mark(Vec2(x, y));
}

TEST(TouchMap, MarkClosesCellsWithinTheGrowth) {
  TouchMap map = plainMap();
  EXPECT_FALSE(map.closed(Vec2(500.0, 0.0)));
  const auto rev = map.revision();
  EXPECT_TRUE(map.mark(Vec2(505.0, 5.0)));
  EXPECT_FALSE(map.mark(Vec2(501.0, 1.0)));  // the same cell
  EXPECT_EQ(map.touchedCount(), 1);
  EXPECT_GT(map.revision(), rev);
  EXPECT_TRUE(map.touched(Vec2(510.0, 10.0)));
  // The cell's centre is (510, 10): cells whose centres lie within 40 are closed, 60 away open.
  EXPECT_TRUE(map.closed(Vec2(550.0, 10.0)));
  EXPECT_TRUE(map.closed(Vec2(510.0, -30.0)));
  EXPECT_FALSE(map.closed(Vec2(570.0, 10.0)));
  EXPECT_FALSE(map.closed(Vec2(450.0, 10.0)));
  // Off the grid: never marked, always closed.
  EXPECT_FALSE(map.mark(Vec2(-5000.0, 0.0)));
  EXPECT_TRUE(map.closed(Vec2(-5000.0, 0.0)));
  EXPECT_FALSE(map.mark(Vec2(std::nan(""), 0.0)));
}

TEST(TouchMap, ClearOpensTheCellsAgain) {
  TouchMap map = plainMap();
  markWall(map, 500.0, -100.0, 100.0);
  const int before = map.touchedCount();
  ASSERT_GT(before, 5);
  EXPECT_EQ(map.clear(Vec2(500.0, 0.0), 25.0), 2);  // the cells centred at y -10 and 10
  EXPECT_EQ(map.touchedCount(), before - 2);
  EXPECT_FALSE(map.touched(Vec2(505.0, 5.0)));
  EXPECT_TRUE(map.touched(Vec2(505.0, 65.0)));
  EXPECT_EQ(map.clear(Vec2(500.0, 0.0), 25.0), 0);
}

TEST(TouchMap, PlanOnAnEmptyMapIsTheOctileDistance) {
  const TouchMap map = plainMap();
  const auto p = map.plan(Vec2(10.0, 10.0), Vec2(410.0, 10.0));
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->lengthUnits, 400.0, 1e-9);
  const auto d = map.plan(Vec2(10.0, 10.0), Vec2(210.0, 210.0));
  ASSERT_TRUE(d);
  EXPECT_NEAR(d->lengthUnits, 200.0 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR((d->points.front() - Vec2(10.0, 10.0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((d->points.back() - Vec2(210.0, 210.0)).norm(), 0.0, 1e-9);
}

TEST(TouchMap, PlanGoesRoundATouchedWallThroughOpenCells) {
  TouchMap map = plainMap();
  markWall(map, 500.0, -200.0, 150.0);  // a wall across the straight way, shorter above
  const auto p = map.plan(Vec2(10.0, 10.0), Vec2(990.0, 10.0));
  ASSERT_TRUE(p);
  // At least the straight legs to and from the crossing above the wall's end and its growth.
  EXPECT_GT(p->lengthUnits, 2.0 * std::hypot(490.0, 180.0));
  for (const Vec2& q : p->points)
    EXPECT_FALSE(map.closed(q)) << q.x() << ", " << q.y();
  // Round the shorter (upper) end: the crossing of x = 500 lies above the wall's end and its
  // growth.
  bool crossed = false;
  for (std::size_t i = 1; i < p->points.size(); ++i) {
    if (p->points[i - 1].x() < 500.0 && p->points[i].x() >= 500.0) {
      crossed = true;
      EXPECT_GT(p->points[i].y(), 150.0 + 40.0);
    }
  }
  EXPECT_TRUE(crossed);
  // The look-ahead sees past the cells next to the robot but not through the wall.
  const Vec2 aim = map.lookAhead(*p, Vec2(10.0, 10.0), 300.0);
  EXPECT_GT((aim - Vec2(10.0, 10.0)).norm(), 100.0);
  EXPECT_TRUE(map.lineOpen(Vec2(10.0, 10.0), aim));
}

// Cells near a touched one (within nearUnits) cost nearCost times their length: a plan along a
// touched wall to a door in it keeps out of the band along the wall (where the robot's corners
// would graze it, and meet the door's jamb at a slant) and crosses it at the door; with nearCost 1
// it runs along the edge of the closed cells. The plan's length counts the extra cost.
TEST(TouchMap, NearCellsCostMoreSoThePlanKeepsOffAWall) {
  const auto run = [](double nearCost) {
    TouchMapConfig c;
    c.marginUnits = 300.0;
    c.nearCost = nearCost;
    TouchMap map(Vec2(0.0, 0.0), Vec2(1000.0, 0.0), c);
    markWall(map, 500.0, -600.0, 0.0);  // a door from y 0 to 120 in a wall along x = 500
    markWall(map, 500.0, 120.0, 700.0);
    // Touched cell centres lie at x = 510: near within 70 of them, closed within 40.
    EXPECT_TRUE(map.near(Vec2(445.0, -200.0)));
    EXPECT_FALSE(map.near(Vec2(425.0, -200.0)));
    EXPECT_TRUE(map.near(Vec2(510.0, 70.0)));  // the whole door is near its jambs
    const auto p = map.plan(Vec2(450.0, -250.0), Vec2(700.0, 60.0));
    EXPECT_TRUE(p);
    double lo = 1e9;
    double hi = -1e9;
    if (p)
      for (const Vec2& q : p->points)
        if (q.y() >= -200.0 && q.y() <= 0.0) {
          lo = std::min(lo, q.x());
          hi = std::max(hi, q.x());
        }
    return std::tuple<double, double, double>{lo, hi, p ? p->lengthUnits : 0.0};
  };
  const auto [lo3, hi3, len3] = run(3.0);
  const auto [lo1, hi1, len1] = run(1.0);
  EXPECT_LE(hi3, 430.0 + 1e-9);  // outside the band along the wall
  EXPECT_GE(lo1, 450.0 - 1e-9);  // on the edge of the closed cells
  EXPECT_GT(len3, len1);
  EXPECT_LE(lo3, hi3);  // points in the stretch were found
  EXPECT_LE(lo1, hi1);
}

TEST(TouchMap, WallAcrossTheWholeMapLeavesNoWay) {
  TouchMap map = plainMap(200.0);
  markWall(map, 500.0, -260.0, 260.0);  // the grid spans y -200..200
  bool snapFailed = true;
  EXPECT_FALSE(map.plan(Vec2(10.0, 10.0), Vec2(990.0, 10.0), 80.0, &snapFailed));
  EXPECT_FALSE(snapFailed);  // both ends open: the search found no way
  // A 120-wide opening in it (the robot is 92 wide with its domes) lets the plan through; a 60
  // wide one does not.
  TouchMap door = plainMap(200.0);
  markWall(door, 500.0, -260.0, -60.0);
  markWall(door, 500.0, 60.0, 260.0);
  EXPECT_TRUE(door.plan(Vec2(10.0, 10.0), Vec2(990.0, 10.0)));
  TouchMap gap = plainMap(200.0);
  markWall(gap, 500.0, -260.0, -30.0);
  markWall(gap, 500.0, 30.0, 260.0);
  EXPECT_FALSE(gap.plan(Vec2(10.0, 10.0), Vec2(990.0, 10.0)));
}

TEST(TouchMap, StartOnTheGrowthOfAThinWallStaysOnItsSide) {
  TouchMap map = plainMap();
  markWall(map, 500.0, -200.0, 200.0);
  // Standing 20 in front of the wall (on closed cells): the plan starts on this side, not on the
  // open cells just beyond the wall.
  const auto p = map.plan(Vec2(480.0, 0.0), Vec2(990.0, 10.0));
  ASSERT_TRUE(p);
  EXPECT_LT(p->points.front().x(), 500.0);
  bool snapFailed = false;
  EXPECT_FALSE(map.plan(Vec2(480.0, 0.0), Vec2(990.0, 10.0), 10.0, &snapFailed));
  EXPECT_TRUE(snapFailed);
}

// ---- the navigator with the touch map ---------------------------------------------------------

TEST(TouchMapNavigator, TouchingDomesOfAContactGroupMarkTheirCells) {
  Script s(true);
  s.step(Values{});
  s.step(Values{});
  const Pose2d pose = s.nav().odometry();
  EXPECT_EQ(s.nav().touchMap().touchedCount(), 0);
  Values front{};
  press(front, {2, 3}, 2.0);
  s.step(front);
  // The pose did not change in this step (the odometry integrated the previous command first).
  const Pose2d now = s.nav().odometry();
  for (int sensor : {2, 3})
    EXPECT_TRUE(s.nav().touchMap().touched(touchPoint(now, sensor)));
  EXPECT_FALSE(s.nav().touchMap().touched(touchPoint(now, 20)));
  EXPECT_GE(s.nav().touchMap().touchedCount(), 1);
  EXPECT_LE(s.nav().touchMap().touchedCount(), 2);
  EXPECT_GT(now.x, pose.x);
  // The bumper Bug2 and a navigator with the map off keep no map.
  NavigatorConfig off;
  off.source = StatusSource::Truth;
  off.planDrive = false;
  EXPECT_TRUE(Navigator::create(off).value()->touchMap().empty());
}

TEST(TouchMapNavigator, GroupJudgedNoContactDoesNotMark) {
  Script s(true);
  s.step(Values{});
  Values front{};
  press(front, {2, 3}, 2.0);
  s.step(front, false, ContactClass::NoContact);
  EXPECT_EQ(s.nav().touchMap().touchedCount(), 0);
}

// The side to follow is the side the plan goes round: the wall goes on the other side, so Check
// Contact turns toward the plan's way (a hit on a front corner with the goal off to that side).
TEST(TouchMapNavigator, PlanChoosesTheFollowSide) {
  for (double goalY : {600.0, -600.0}) {
    Script s(true, Vec2(2000.0, goalY));
    s.step(Values{});
    // Face the goal first (Head to Destination turns in place).
    for (int i = 0; i < 60 && s.nav().strategy() == Strategy::HeadToDestination; ++i) {
      const Command c = s.step(Values{});
      if (c.v > 0.0) break;
    }
    Values hit{};
    // The front corner on the goal's side and the front face next to it.
    if (goalY > 0.0)
      press(hit, {8, 9, 6, 7}, 2.0);  // front-left corner
    else
      press(hit, {42, 43, 0, 1}, 2.0);  // front-right corner
    s.step(hit);
    ASSERT_EQ(s.nav().strategy(), Strategy::CheckContact);
    ASSERT_TRUE(s.nav().plan());
    // The plan's way from the body centre, relative to the heading.
    const Pose2d pose = s.nav().odometry();
    const Vec2 centre = sim::bodyToWorld(pose, Vec2(35.0, 0.0));
    const Vec2 goal(2000.0, goalY);
    const Vec2 aim = s.nav().touchMap().lineOpen(centre, goal)
                         ? goal
                         : s.nav().touchMap().lookAhead(*s.nav().plan(), centre, 300.0);
    const double err =
        sim::wrapAngle(std::atan2(aim.y() - centre.y(), aim.x() - centre.x()) - pose.theta);
    ASSERT_GT(std::abs(err), 0.05);
    // Back off straight, then the turn (in place, or on an arc when the corner was pressed):
    // its sign is the plan's.
    double omega = 0.0;
    for (int i = 0; i < 60 && omega == 0.0; ++i) {
      const Command c = s.step(Values{});
      if (c.v >= 0.0 && c.omega != 0.0) omega = c.omega;
    }
    EXPECT_NE(omega, 0.0);
    EXPECT_EQ(omega > 0.0, err > 0.0) << "goal y " << goalY;
  }
}

// A navigator on the simulator's truth, with or without the touch map.
std::unique_ptr<Navigator> truthNavigator(bool touchMap) {
  NavigatorConfig config;
  config.source = StatusSource::Truth;
  config.touchMap = touchMap;
  config.planDrive = false;
  return std::move(Navigator::create(config).value());
}

// Where the plan and the first-touch rule disagree, the plan decides: hit on the front-left corner
// (the first-touch rule puts that wall on the left and turns right) with the goal far off to the
// left, where the plan's way leads past the touch: the robot turns left, the wall on its right.
TEST(TouchMapNavigator, PlanOverridesTheFirstTouchRule) {
  for (bool map : {true, false}) {
    auto nav = truthNavigator(map);
    Values values{};
    Truth truth{};
    std::size_t k = 0;
    const auto step = [&](const Values& v) {
      values = v;
      truth = truthOf(v, ContactClass::Wall);
      Observation o;
      o.step = k++;
      o.dtSeconds = 0.1;
      o.start = Pose2d{0.0, 0.0, 0.0};
      o.goal = Vec2(200.0, 1500.0);
      o.values = &values;
      o.truth = &truth;
      return nav->step(o);
    };
    Values hit{};
    press(hit, {8, 9}, 2.0);
    step(hit);
    ASSERT_EQ(nav->strategy(), Strategy::CheckContact);
    double omega = 0.0;
    for (int i = 0; i < 60 && omega == 0.0; ++i) {
      const Command c = step(Values{});
      if (c.v >= 0.0 && c.omega != 0.0) omega = c.omega;
    }
    if (map)
      EXPECT_GT(omega, 0.0);  // the plan: round to the left
    else
      EXPECT_LT(omega, 0.0);  // the first-touch rule: away from the left-hand wall
  }
}

// Arrived by odometry while the run goes on (the referee has not ended it): the robot searches on a
// spiral round the goal out to 400 units. With the map, two spirals without the goal end the run as
// unreachable; without it the search goes on.
TEST(TouchMapNavigator, TwoSearchSpiralsWithoutTheGoalEndTheRunAsUnreachable) {
  for (bool map : {true, false}) {
    auto nav = truthNavigator(map);
    Values values{};
    Truth truth = truthOf(values, ContactClass::NoContact);
    double farthest = 0.0;
    std::size_t k = 0;
    for (; k < 12000 && !nav->finished(); ++k) {
      Observation o;
      o.step = k;
      o.dtSeconds = 0.1;
      o.start = Pose2d{0.0, 0.0, 0.0};
      o.goal = Vec2(10.0, 0.0);  // within the arrival radius from the start
      o.values = &values;
      o.truth = &truth;
      nav->step(o);
      const Pose2d p = nav->odometry();
      farthest = std::max(farthest, std::hypot(p.x - 10.0, p.y));
    }
    if (map) {
      ASSERT_TRUE(nav->finished()) << "after " << k << " steps";
      EXPECT_EQ(*nav->finished(), RunOutcome::Unreachable);
      EXPECT_GT(farthest, 350.0);  // it searched out to the spiral's edge first
      EXPECT_GT(k, 1000u);
    } else {
      EXPECT_FALSE(nav->finished()) << "after " << k << " steps";
    }
  }
}

// ---- whole runs --------------------------------------------------------------------------------

NavigateResult runWithMap(const std::shared_ptr<const sim::World>& world, Pose2d start,
                          std::size_t maxSteps) {
  NavigatorConfig config;
  config.source = StatusSource::Truth;
  config.touchMap = true;
  config.planDrive = false;  // the touch map under the thesis strategies
  NavigateOptions options;
  options.maxSteps = maxSteps;
  auto r = navigate(world, "test", start, world->scene().goal, config, options);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.errorText());
  return std::move(r.value());
}

TEST(TouchMapNavigate, ReachesTheGoalRoundABoxAndIsDeterministic) {
  const auto world = worldOf({box(600, 330, 700, 570)}, 1400, 900, Vec2(1200, 450));
  for (double y : {400.0, 500.0}) {
    const NavigateResult a = runWithMap(world, {200, y, 0}, 8000);
    EXPECT_EQ(a.outcome, RunOutcome::Success) << "from y " << y << " after " << a.steps;
    const NavigateResult b = runWithMap(world, {200, y, 0}, 8000);
    EXPECT_TRUE(a.run == b.run);
  }
}

// With the map the run still ends as unreachable when no way exists: a goal inside a closed ring of
// walls (the odometry drifts over the blocked steps and carries the robot "inside" the ring; the
// search round the goal then finds nothing), and a wall across the scene whose only gap (70) is
// narrower than the robot (the plan finds no way once the wall is touched along its length).
TEST(TouchMapNavigate, EnclosedGoalEndsUnreachable) {
  const auto world = ringWorld();
  for (double y : {380.0, 450.0, 520.0}) {
    const NavigateResult r = runWithMap(world, {200, y, 0}, 20000);
    EXPECT_EQ(r.outcome, RunOutcome::Unreachable)
        << "from y " << y << ": " << runOutcomeName(r.outcome) << " after " << r.steps;
  }
}

TEST(TouchMapNavigate, WallWithOnlyANarrowGapIsUnreachable) {
  const auto world =
      worldOf({box(700, 0, 720, 400), box(700, 470, 720, 900)}, 1400, 900, Vec2(1200, 450));
  for (double y : {200.0, 600.0}) {
    const NavigateResult r = runWithMap(world, {250, y, 0}, 20000);
    EXPECT_EQ(r.outcome, RunOutcome::Unreachable)
        << "from y " << y << ": " << runOutcomeName(r.outcome) << " after " << r.steps;
  }
}

}  // namespace
}  // namespace tactile::nav
