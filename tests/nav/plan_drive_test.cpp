// Plan drive (docs/navigation.md#plan-drive): the robot follows the touch map's plan; at a contact
// ahead it marks the touching domes' cells, backs off and replans; no way on the map ends the run
// as unreachable; runs are deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "nav/navigate.h"
#include "nav/navigator.h"
#include "nav/touch_map.h"
#include "sim/robot.h"
#include "sim/scene_source.h"
#include "sim/simulator.h"
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

// The simulator ends a blocked step somewhere along it, where the robot cannot tell: plan drive's
// odometry counts half the step (wrong by at most half a step either way), the wall-follow
// navigator none; with the share set to 0, plan drive counts none as well.
TEST(PlanDrive, ABlockedStepCountsAsHalfItsCommand) {
  struct Case {
    bool planDrive;
    double share;
    double counted;  // the share of the command the odometry should move
  };
  for (const Case& k : {Case{true, 0.5, 0.5}, Case{true, 0.0, 0.0}, Case{false, 0.5, 0.0}}) {
    SCOPED_TRACE(::testing::Message() << "planDrive " << k.planDrive << " share " << k.share);
    Script s(false, Vec2(2000.0, 300.0), k.planDrive, k.share);
    Command c{};
    for (int i = 0; i < 8; ++i)
      c = s.step(Values{});
    ASSERT_TRUE(c.v != 0.0 || c.omega != 0.0);
    const Pose2d before = s.nav().odometry();
    s.step(Values{}, true);  // the command c was blocked
    const Pose2d after = s.nav().odometry();
    const Pose2d expected = sim::integratePose(before, k.counted * c.v, k.counted * c.omega, 0.1);
    EXPECT_NEAR(after.x, expected.x, 1e-9);
    EXPECT_NEAR(after.y, expected.y, 1e-9);
    EXPECT_NEAR(sim::wrapAngle(after.theta - expected.theta), 0.0, 1e-9);
    if (k.counted > 0.0) {
      EXPECT_GT(std::hypot(after.x - before.x, after.y - before.y) +
                    std::abs(sim::wrapAngle(after.theta - before.theta)),
                1e-3);
    }
  }
}

// A contact ahead met at one place for the third time in a row: the marks of the touching domes
// have not turned the plan away, so the front edge is marked from side to side (not before).
TEST(PlanDrive, TheThirdContactInARowAtOnePlaceMarksTheWholeFront) {
  Script s(false, Vec2(2000.0, 0.0), true);
  for (int k = 0; k < 5; ++k)
    s.step(Values{});
  Values front{};
  press(front, {4}, 2.0);  // one dome near the middle of the front
  const RobotGeometry g;
  const auto edge = [&g](const Pose2d& pose, double y) {
    return sim::bodyToWorld(pose, Vec2(g.frontX() + g.domeRadiusUnits, y));
  };
  std::vector<Pose2d> hits;
  for (int k = 0; k < 200 && hits.size() < 3; ++k) {
    const std::size_t before = s.nav().checkContactStarts();
    s.step(front);
    if (s.nav().checkContactStarts() > before) hits.push_back(s.nav().odometry());
    if (hits.size() < 3) {
      for (const Pose2d& h : hits) {
        EXPECT_FALSE(s.nav().touchMap().touched(edge(h, g.halfWidth())));
        EXPECT_FALSE(s.nav().touchMap().touched(edge(h, -g.halfWidth())));
      }
    }
  }
  ASSERT_EQ(hits.size(), 3u);
  // Each contact lies within the repeat distance of the one before (the back-offs are short).
  for (std::size_t i = 1; i < hits.size(); ++i)
    EXPECT_LT(std::hypot(hits[i].x - hits[i - 1].x, hits[i].y - hits[i - 1].y), 40.0);
  for (double y : {-g.halfWidth(), -0.5 * g.halfWidth(), 0.0, 0.5 * g.halfWidth(), g.halfWidth()})
    EXPECT_TRUE(s.nav().touchMap().touched(edge(hits[2], y))) << "y " << y;
}

// Contacts ahead at places apart never mark the whole front.
TEST(PlanDrive, ContactsAtDifferentPlacesDoNotMarkTheWholeFront) {
  Script s(false, Vec2(4000.0, 0.0), true);
  const RobotGeometry g;
  Values front{};
  press(front, {4}, 2.0);
  int contacts = 0;
  for (int round = 0; round < 4; ++round) {
    // Drive on well past the last contact (more than the repeat distance), then touch.
    for (int k = 0; k < 60; ++k)
      s.step(Values{});
    const std::size_t before = s.nav().checkContactStarts();
    s.step(front);
    ASSERT_GT(s.nav().checkContactStarts(), before);
    ++contacts;
    const Pose2d hit = s.nav().odometry();
    for (double y : {-g.halfWidth(), g.halfWidth()})
      EXPECT_FALSE(s.nav().touchMap().touched(
          sim::bodyToWorld(hit, Vec2(g.frontX() + g.domeRadiusUnits, y))));
  }
  EXPECT_EQ(contacts, 4);
}

// Whether a group touches is its status's to say (per the source); the readings only say which
// domes. A front reading hard but called NoContact neither marks the map nor stops the robot; a
// front reading faintly (below any pressure threshold) but called a contact marks its domes and
// backs the robot off.
TEST(PlanDrive, TheStatusSourceDecidesContactNotTheReadings) {
  Script s(false, Vec2(2000.0, 0.0), true);
  for (int k = 0; k < 5; ++k)
    s.step(Values{});
  Values hard{};
  press(hard, {2, 3, 4, 5}, 3.0);
  Command c = s.step(hard, test::Truth{});  // every group NoContact
  EXPECT_EQ(s.nav().touchMap().touchedCount(), 0);
  EXPECT_GT(c.v, 0.0);
  EXPECT_EQ(s.nav().strategy(), Strategy::HeadToDestination);

  Values faint{};
  press(faint, {0, 7}, 0.1);
  test::Truth front{};
  front[static_cast<std::size_t>(groupIndex(SensorGroup::Front))] = ContactClass::Wall;
  c = s.step(faint, front);
  const Pose2d hit = s.nav().odometry();
  EXPECT_EQ(s.nav().touchMap().touchedCount(), 2);
  EXPECT_TRUE(s.nav().touchMap().touched(touchPoint(hit, 0)));
  EXPECT_TRUE(s.nav().touchMap().touched(touchPoint(hit, 7)));
  EXPECT_LT(c.v, 0.0);
  EXPECT_EQ(s.nav().strategy(), Strategy::CheckContact);
}

// A side eases the robot away when its status is a contact, however faint the reading, and not
// when its status is NoContact, however hard.
TEST(PlanDrive, SideEasingFollowsTheStatus) {
  for (bool contact : {true, false}) {
    // Two steps in: the plan of the first step still holds (the map's marks are taken into a
    // new plan at most every 5 steps), so what the step does is the easing alone.
    Script s(false, Vec2(2000.0, 0.0), true);
    for (int k = 0; k < 2; ++k)
      s.step(Values{});
    Values side{};
    press(side, {12, 13, 14}, contact ? 0.1 : 3.0);
    test::Truth t{};
    if (contact) t[static_cast<std::size_t>(groupIndex(SensorGroup::Left))] = ContactClass::Wall;
    const Command c = s.step(side, t);
    EXPECT_GT(c.v, 0.0) << "contact " << contact;
    if (contact)
      EXPECT_LE(c.omega, -0.29);  // away from the left, at least 0.3 rad/s
    else
      EXPECT_LT(std::abs(c.omega), 0.1);
  }
}

// A turn in place blocked by the back sweeping into something behind (only the back groups in
// contact): the robot moves forward off it, not back into it; blocked with the front in contact it
// backs off as ever.
TEST(PlanDrive, BlockedTurnWithTheBackTouchingMovesForward) {
  for (bool back : {true, false}) {
    Script s(false, Vec2(-2000.0, 0.0), true);  // the goal behind: it turns in place
    Command c{};
    for (int k = 0; k < 3; ++k)
      c = s.step(Values{});
    ASSERT_EQ(c.v, 0.0);
    ASSERT_NE(c.omega, 0.0);
    Values v{};
    if (back)
      press(v, {22, 23, 30}, 2.0);
    else
      press(v, {3, 4}, 2.0);
    c = s.step(v, true);
    EXPECT_EQ(s.nav().strategy(), Strategy::CheckContact) << "back " << back;
    if (back)
      EXPECT_GT(c.v, 0.0);
    else
      EXPECT_LT(c.v, 0.0);
    // It keeps moving that way while nothing stops it.
    c = s.step(Values{});
    EXPECT_EQ(c.v > 0.0, back) << "back " << back;
  }
}

// A front corner in contact is a contact ahead when a dome of it facing ahead touches (the one 30
// degrees off the heading), however lightly; touched only on its dome facing the side (60 degrees
// off), however hard, the robot grazes something beside it: it eases away and drives on. Either
// way the touching domes mark the map.
TEST(PlanDrive, AFrontCornerIsAContactAheadByWhereItTouches) {
  struct Case {
    int dome;
    double value;
    bool ahead;
    double away;  // the sign of the easing turn when not ahead
  };
  for (const Case& k : {Case{8, 0.3, true, 0.0}, Case{43, 0.3, true, 0.0},
                        Case{9, 4.0, false, -1.0}, Case{42, 4.0, false, 1.0}}) {
    Script s(false, Vec2(2000.0, 0.0), true);
    for (int i = 0; i < 2; ++i)
      s.step(Values{});
    Values v{};
    press(v, {k.dome}, k.value);
    const Command c = s.step(v);
    const RobotGeometry g;
    const Vec2 at = sim::bodyToWorld(
        s.nav().odometry(), domeContactPoint(domePlacements(g)[static_cast<std::size_t>(k.dome)],
                                             k.value, 0.0, g.domeRadiusUnits));
    EXPECT_TRUE(s.nav().touchMap().touched(at)) << k.dome;
    if (k.ahead) {
      EXPECT_LT(c.v, 0.0) << "dome " << k.dome;
      EXPECT_EQ(s.nav().strategy(), Strategy::CheckContact) << "dome " << k.dome;
    } else {
      EXPECT_GT(c.v, 0.0) << "dome " << k.dome;
      EXPECT_GT(k.away * c.omega, 0.29) << "dome " << k.dome;
    }
  }
}

// Where a dome touches, from its normal and shear values: on the obstacle's outline, also when the
// obstacle meets the dome off its normal (a vertex between two domes), where the point a dome
// radius out along the normal is several units off.
TEST(PlanDrive, DomeContactPointLiesOnWhatIsTouched) {
  // A wedge whose tip (308, 300) sits between front domes 3 and 4 of a robot at (200, 300, 0).
  const std::vector<Vec2> wedge{Vec2(308, 300), Vec2(500, 295), Vec2(500, 305)};
  const auto world = worldOf({sim::Obstacle{wedge}}, 800, 600, Vec2(700, 300));
  sim::Simulator sim(world);
  ASSERT_TRUE(sim.reset(Pose2d{200, 300, 0}));
  for (int k = 0; k < 10; ++k)
    sim.step(0.0, 0.0);  // standing still: the filtered values settle on the raw ones
  const auto outlineDistance = [&](const Vec2& p) {
    double best = 1e9;
    for (std::size_t i = 0; i < wedge.size(); ++i) {
      const Vec2 a = wedge[i];
      const Vec2 b = wedge[(i + 1) % wedge.size()];
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + t * (b - a) - p).norm());
    }
    return best;
  };
  const RobotGeometry g;
  const auto domes = domePlacements(g);
  int reading = 0;
  double worstAlongNormal = 0.0;
  for (int d = 0; d < kSensorCount; ++d) {
    const double n = sim.sensors()[static_cast<std::size_t>(normalOffset(d))];
    const double sh = sim.sensors()[static_cast<std::size_t>(shearOffset(d))];
    if (n <= 0.0) continue;
    ++reading;
    const DomePlacement& dome = domes[static_cast<std::size_t>(d)];
    const Vec2 p = sim::bodyToWorld(sim.pose(), domeContactPoint(dome, n, sh, g.domeRadiusUnits));
    EXPECT_LT(outlineDistance(p), 0.5) << "dome " << d << " at " << p.transpose();
    worstAlongNormal = std::max(worstAlongNormal, outlineDistance(touchPoint(sim.pose(), d)));
  }
  EXPECT_GE(reading, 2);
  EXPECT_GT(worstAlongNormal, 2.0);
  // Nothing read: a dome radius out along the normal.
  const Vec2 none = domeContactPoint(domes[3], 0.0, 0.0, g.domeRadiusUnits);
  EXPECT_NEAR(none.x(), domes[3].centre.x + g.domeRadiusUnits, 1e-12);
  EXPECT_NEAR(none.y(), domes[3].centre.y, 1e-12);
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

// The chapter-5 scene from 50 seeded starts (the truth source): every run reaches the goal. From
// seed 4, with blocked steps counted as half their command but the front never marked at a
// repeated contact, the robot drove the same line into one corner over and over (timeout).
TEST(PlanDriveNavigate, Chapter5IsReachedFromFiftyStarts) {
  auto loaded = sim::loadScene("chapter5");
  ASSERT_TRUE(loaded.ok());
  const auto world = std::make_shared<const sim::World>(std::move(loaded.value()));
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const NavigateResult r = drive(world, drawStart(world, seed), 6000);
    EXPECT_EQ(r.outcome, RunOutcome::Success)
        << "seed " << seed << ": " << runOutcomeName(r.outcome) << " after " << r.steps;
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

// A 120-wide gap in a wall across the room is passed from every one of 27 starts spread over the
// start's side (three gap heights, three heights, three headings).
TEST(PlanDriveNavigate, GapOf120IsPassedFromEveryStart) {
  for (double gapY : {250.0, 450.0, 650.0}) {
    const auto world =
        worldOf(wallWithOpenings({{gapY - 60.0, gapY + 60.0}}), 1400, 900, Vec2(1200, 450));
    for (double y : {150.0, 450.0, 750.0}) {
      for (double theta : {-0.7, 0.0, 0.7}) {
        const NavigateResult r = drive(world, {250, y, theta}, 8000);
        EXPECT_EQ(r.outcome, RunOutcome::Success)
            << "gap at " << gapY << " from (" << y << ", " << theta
            << "): " << runOutcomeName(r.outcome) << " after " << r.steps;
      }
    }
  }
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

// Searching round the goal (arrived by odometry while the run goes on), plan drive goes from
// spiral point to spiral point on plans of the touch map: never to a point on a closed cell and
// never straight through what it touched (the marks the contact left survive the search), and two
// spirals without the goal end the run as unreachable.
TEST(PlanDrive, SearchRoundTheGoalDrivesByThePlan) {
  Script s(false, Vec2(150.0, 0.0), true);
  for (int i = 0; i < 4; ++i)
    s.step(Values{});
  Values front{};
  press(front, {0, 1, 2, 3, 4, 5, 6, 7}, 2.0);
  s.step(front);
  ASSERT_TRUE(s.nav().arrived());
  ASSERT_GT(s.nav().touchMap().touchedCount(), 0);
  // Where the front touched (the middle of the front face, a little inside the dome radius).
  const Pose2d hit = s.nav().odometry();
  const Vec2 touched = sim::bodyToWorld(hit, Vec2(109.0, 0.0));
  const Vec2 goal(150.0, 0.0);
  double farthest = 0.0;
  int steps = 0;
  int through = 0;  // steps with the body centre within 40 units of the touched face
  while (!s.nav().finished() && steps < 20000) {
    s.step(Values{});
    ++steps;
    const Pose2d& p = s.nav().odometry();
    const Vec2 centre = sim::bodyToWorld(p, Vec2(35.0, 0.0));
    if (steps > 40 && std::abs(centre.x() - touched.x()) < 40.0 &&
        std::abs(centre.y() - touched.y()) < 21.0)
      ++through;
    if (s.nav().plan() && s.nav().plan()->points.size() >= 2) {
      EXPECT_FALSE(s.nav().touchMap().closed(s.nav().plan()->points.back()))
          << "step " << steps << ": a plan to a closed cell";
    }
    const Pose2d& o = s.nav().odometry();
    farthest = std::max(farthest, (Vec2(o.x, o.y) - goal).norm());
  }
  EXPECT_EQ(through, 0);       // it went round what it touched, never through it
  EXPECT_GT(farthest, 300.0);  // out along the spiral
  EXPECT_LT(farthest, 600.0);
  ASSERT_TRUE(s.nav().finished());
  EXPECT_EQ(*s.nav().finished(), RunOutcome::Unreachable);
}

// A robot wedged across a passage as wide as it is long, its front-right corner on one wall and
// its rear-left corner on the other, is freed only by pivoting about a point of its axle line
// close to the body (going forward or back and turning either way in place each press a corner
// harder): plan drive's escape moves include such pivots, and it goes on to the goal.
TEST(PlanDriveNavigate, WedgedAcrossAPassageEscapesByAPivot) {
  // Walls at y <= 200 and y >= 352: a passage 152 wide (the robot with its domes is 152 long).
  const auto world =
      worldOf({box(0, 190, 2000, 200), box(0, 352, 2000, 362)}, 2000, 600, Vec2(1500, 276));
  const NavigateResult r = drive(world, {1000, 306, -1.028}, 4000);
  EXPECT_EQ(r.outcome, RunOutcome::Success)
      << runOutcomeName(r.outcome) << " after " << r.steps << ", blocked " << r.blockedSteps;
  EXPECT_LT(r.blockedSteps, 300u);
}

// Contacts ahead that keep stopping the robot at one place (four in a row, each within 40 units of
// the one before) with
// the goal within 150 units: as near as the robot comes (its odometry has drifted, or what it
// meets stands between it and the goal), so it searches round the goal from there. Far from the
// goal the same contacts only back it off.
TEST(PlanDrive, RepeatedContactsNearTheGoalStartTheSearch) {
  // The goal behind on the left: the robot turns in place toward it and meets something with its
  // front while turning (the marks lie far from the goal, which stays on open cells); each
  // back-off is blocked at once, so every contact is met at the same place.
  for (const Vec2& goal : {Vec2(-100.0, 60.0), Vec2(-600.0, 60.0)}) {
    const bool near = goal.x() > -300.0;
    Script s(false, goal, true);
    for (int i = 0; i < 2; ++i)
      s.step(Values{});
    for (int contact = 1; contact <= 4; ++contact) {
      Values front{};
      press(front, {0, 1, 2, 3, 4, 5, 6, 7}, 2.0);
      s.step(front);
      EXPECT_EQ(s.nav().arrived(), near && contact == 4)
          << "goal " << goal.transpose() << ", contact " << contact;
      // The back-off is blocked at once (the robot stays where it met the contact).
      s.step(Values{}, true);
    }
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

// The only way round lies far outside the box round start and goal (a wall between them whose
// end is 1,600 units beyond both): the touch map must reach that far, or the robot ends
// `unreachable` beside the goal's room.
TEST(PlanDriveNavigate, AWayFarOutsideTheStartGoalBoxIsFound) {
  sim::Scene s;
  s.name = "far way round";
  s.bounds = {0, 0, 900, 2000};
  s.obstacles = {box(440, 0, 460, 1750)};
  s.start = {200, 150, 0};
  s.goal = Vec2(700, 150);
  const auto world = std::make_shared<const sim::World>(std::move(s));
  for (double theta : {0.0, 1.2}) {
    const NavigateResult r = drive(world, {200, 150, theta}, 12000);
    EXPECT_EQ(r.outcome, RunOutcome::Success)
        << "heading " << theta << ": " << runOutcomeName(r.outcome) << " after " << r.steps;
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
