// The navigator's state machine on scripted sensor readings, its names, and the follow-wall rule
// as the commands it gives.
#include <gtest/gtest.h>

#include <initializer_list>

#include "nav/navigator.h"
#include "tests/nav/scripted_readings.h"

namespace tactile::nav {
namespace {

using test::press;
using test::Script;
using test::Truth;
using test::truthOf;
using test::Values;

void pressGroup(Values& values, SensorGroup g, double n) {
  const GroupInfo& info = groupInfo(g);
  for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d)
    values[static_cast<std::size_t>(normalOffset(d))] = n;
}

TEST(NavigatorNames, StrategiesAndStatusesReadBack) {
  for (Strategy s : kStrategies) {
    EXPECT_EQ(parseStrategyKey(strategyKey(s)), s);
    EXPECT_FALSE(strategyTitle(s).empty());
  }
  EXPECT_EQ(strategyTitle(Strategy::MoveThroughWall), "Move through Wall");
  EXPECT_FALSE(parseStrategyKey("Go Straight"));
  EXPECT_EQ(statusText(ContactStatus{StatusKind::Hole, 109.6}), "Hole(110)");
  EXPECT_EQ(statusText(ContactStatus::of(ContactClass::LeavingWall)), "LeavingWall");
  const auto hole = parseStatusText("Hole(110)");
  ASSERT_TRUE(hole);
  EXPECT_EQ(hole->kind, StatusKind::Hole);
  EXPECT_DOUBLE_EQ(hole->holeWidthUnits, 110.0);
  EXPECT_FALSE(parseStatusText("Hole(1x0)"));
  EXPECT_FALSE(parseStatusText("wall"));
  EXPECT_EQ(parseStatusText("Undecided")->kind, StatusKind::Undecided);
  EXPECT_EQ(parseStatusSource("bumper"), StatusSource::Bumper);
  EXPECT_FALSE(parseStatusSource("Truth"));
}

TEST(NavigatorCreate, ModelSourceNeedsModels) {
  NavigatorConfig config;
  config.source = StatusSource::Model;
  EXPECT_FALSE(Navigator::create(config).ok());
  config.models = std::make_shared<analysis::ModelBundle>();
  EXPECT_FALSE(Navigator::create(config).ok());
}

TEST(NavigatorStates, FreeSpaceHeadsForTheGoal) {
  Script s;
  const Command c = s.step(Values{});
  EXPECT_EQ(s.nav().strategy(), Strategy::HeadToDestination);
  EXPECT_GT(c.v, 0.0);
  EXPECT_DOUBLE_EQ(c.omega, 0.0);
  // The odometry integrates the command: one step of v * dt along +x.
  s.step(Values{});
  EXPECT_NEAR(s.nav().odometry().x, c.v * 0.1, 1e-12);
}

TEST(NavigatorStates, BlockedStepIsNoMotionToTheOdometry) {
  Script s;
  s.step(Values{});
  s.step(Values{}, /*blocked=*/true);
  EXPECT_DOUBLE_EQ(s.nav().odometry().x, 0.0);
}

TEST(NavigatorStates, FrontContactStartsCheckContactBackingOff) {
  Script s;
  s.step(Values{});
  Values front{};
  press(front, {2, 3, 4, 5}, 2.0);
  const Command c = s.step(front);
  EXPECT_EQ(s.nav().strategy(), Strategy::CheckContact);
  EXPECT_LT(c.v, 0.0);
  EXPECT_EQ(s.nav().groupStatus()[0], ContactStatus::of(ContactClass::Wall));
}

TEST(NavigatorStates, CheckContactTurnsAwayThenFollowsTheSideWall) {
  Script s;
  s.step(Values{});
  Values front{};
  press(front, {0, 1, 2}, 2.0);  // the right half of the front: the wall goes on the right
  Command c{};
  int backing = 0;
  for (int i = 0; i < 20; ++i) {
    c = s.step(front);
    if (c.v >= 0.0) break;
    ++backing;
  }
  EXPECT_GT(backing, 0);
  EXPECT_EQ(s.nav().strategy(), Strategy::CheckContact);
  EXPECT_DOUBLE_EQ(c.v, 0.0);
  EXPECT_GT(c.omega, 0.0);  // turning left, away from the wall on the right
  // Front clear: a slight angle more, then forward arcing toward the wall (right).
  int turning = 0;
  do {
    c = s.step(Values{});
    ++turning;
  } while (c.v == 0.0 && turning < 20);
  EXPECT_GT(turning, 1);
  EXPECT_GT(c.v, 0.0);
  EXPECT_DOUBLE_EQ(c.omega, 0.0);  // thesis: move straight again after the slight turn
  Values side{};
  pressGroup(side, SensorGroup::Right, 2.5);
  s.step(side);
  EXPECT_EQ(s.nav().strategy(), Strategy::FollowWall);
}

TEST(NavigatorStates, CheckContactWaitsForAWallOrCornerStatus) {
  Script s;
  s.step(Values{});
  Values front{};
  press(front, {0, 1, 2}, 2.0);
  Command c{};
  for (int i = 0; i < 40; ++i) {
    c = s.step(i < 12 ? front : Values{});
    if (c.v > 0.0) break;
  }
  ASSERT_GT(c.v, 0.0);
  Values side{};
  pressGroup(side, SensorGroup::Right, 2.5);
  // The side touches but its status is LeavingWall: not yet a wall to follow.
  s.step(side, false, ContactClass::LeavingWall);
  EXPECT_EQ(s.nav().strategy(), Strategy::CheckContact);
  s.step(side, false, ContactClass::Corner);
  EXPECT_EQ(s.nav().strategy(), Strategy::FollowWall);
}

// The follow-wall rule of thesis 5.2 as commands, wall on the right: turn away (left, omega > 0)
// when the largest value is above 4 or the touching mean above 3, toward (omega < 0) when the
// largest is below 0.5 or the mean below 2, otherwise straight.
TEST(NavigatorFollowWall, RuleOnFixedReadings) {
  Script s;
  s.step(Values{});
  Values front{};
  press(front, {0, 1, 2}, 2.0);
  for (int i = 0; i < 40 && s.nav().strategy() != Strategy::FollowWall; ++i) {
    if (i < 12) {
      s.step(front);
    } else {
      Values side{};
      pressGroup(side, SensorGroup::Right, 2.5);
      s.step(s.nav().strategy() == Strategy::CheckContact && i > 25 ? side : Values{});
    }
  }
  ASSERT_EQ(s.nav().strategy(), Strategy::FollowWall);
  const auto follow = [&](std::initializer_list<double> normals) {
    Values v{};
    int d = groupInfo(SensorGroup::Right).firstSensor;
    for (double n : normals)
      v[static_cast<std::size_t>(normalOffset(d++))] = n;
    const Command c = s.step(v);
    EXPECT_EQ(s.nav().strategy(), Strategy::FollowWall);
    return c;
  };
  EXPECT_GT(follow({4.5, 1.0, 1.0, 1.0}).omega, 0.0);  // max > 4
  EXPECT_GT(follow({3.2, 3.1, 3.3}).omega, 0.0);       // mean > 3
  EXPECT_LT(follow({0.4, 0.4, 0.3}).omega, 0.0);       // max < 0.5
  EXPECT_LT(follow({1.9, 1.1}).omega, 0.0);            // mean < 2
  const Command straight = follow({3.0, 2.0, 2.5});
  EXPECT_DOUBLE_EQ(straight.omega, 0.0);
  EXPECT_GT(straight.v, 0.0);
  EXPECT_GT(follow({4.0, 2.0}).v, 0.0);  // thresholds are strict: 4 is not above 4
  EXPECT_DOUBLE_EQ(follow({4.0, 2.0}).omega, 0.0);
}

// Losing the side goes straight across the opening; the next fragment closes it and the opening
// is remembered with the odometry distance between the last dome on the wall before and the first
// one after.
TEST(NavigatorHoles, OpeningCrossedStraightIsMeasuredByOdometry) {
  Script s;
  s.step(Values{});
  Values front{};
  press(front, {0, 1, 2}, 2.0);
  for (int i = 0; i < 40 && s.nav().strategy() != Strategy::FollowWall; ++i) {
    Values side{};
    pressGroup(side, SensorGroup::Right, 2.5);
    s.step(i < 12 ? front
                  : (s.nav().strategy() == Strategy::CheckContact && i > 25 ? side : Values{}));
  }
  ASSERT_EQ(s.nav().strategy(), Strategy::FollowWall);
  Values side{};
  pressGroup(side, SensorGroup::Right, 2.5);
  s.step(side);
  s.step(side);  // straight (max 2.5, mean 2.5): heading unchanged from here
  const auto placements = domePlacements();
  const auto world = [&](int sensor) {
    const Pose2d p = s.nav().odometry();
    const Vec2 c(placements[static_cast<std::size_t>(sensor)].centre.x,
                 placements[static_cast<std::size_t>(sensor)].centre.y);
    return Vec2(p.x + std::cos(p.theta) * c.x() - std::sin(p.theta) * c.y(),
                p.y + std::sin(p.theta) * c.x() + std::cos(p.theta) * c.y());
  };
  const Vec2 lastOnWall = world(32);  // the rear-most right dome at the last step on the wall
  const Command c = s.step(Values{});
  EXPECT_EQ(s.nav().strategy(), Strategy::GoStraight);
  EXPECT_DOUBLE_EQ(c.omega, 0.0);
  EXPECT_GT(c.v, 0.0);
  s.step(Values{});  // within the probe distance: still straight
  EXPECT_EQ(s.nav().strategy(), Strategy::GoStraight);
  EXPECT_TRUE(s.nav().holes().empty());
  Values again{};
  press(again, {43}, 1.0);  // the front-right corner meets the next fragment
  s.step(again);
  const Vec2 firstOnWall = world(43);
  EXPECT_EQ(s.nav().strategy(), Strategy::FollowWall);
  ASSERT_EQ(s.nav().holes().size(), 1u);
  const RememberedHole& h = s.nav().holes()[0];
  EXPECT_NEAR(h.widthUnits, (firstOnWall - lastOnWall).norm(), 1e-9);
  EXPECT_NEAR(h.centre.x(), 0.5 * (firstOnWall + lastOnWall).x(), 1e-9);
  EXPECT_FALSE(h.onLeft);
  EXPECT_EQ(h.wall, 0);
}

// Thesis 4.5 on the followed side: two fragments with free domes between are a hole whose width
// is measured between the domes that bound it; it shows as the side's status and is remembered.
TEST(NavigatorHoles, TwoFragmentsOnTheSideAreAHoleWithItsWidth) {
  Script s;
  s.step(Values{});
  Values front{};
  press(front, {0, 1, 2}, 2.0);
  for (int i = 0; i < 40 && s.nav().strategy() != Strategy::FollowWall; ++i) {
    Values side{};
    pressGroup(side, SensorGroup::Right, 2.5);
    s.step(i < 12 ? front
                  : (s.nav().strategy() == Strategy::CheckContact && i > 25 ? side : Values{}));
  }
  ASSERT_EQ(s.nav().strategy(), Strategy::FollowWall);
  Values split{};
  press(split, {32, 33, 34}, 2.5);  // rear fragment
  press(split, {40, 41}, 2.5);      // front fragment
  s.step(split);
  const auto placements = domePlacements();
  const double between = std::hypot(placements[40].centre.x - placements[34].centre.x,
                                    placements[40].centre.y - placements[34].centre.y);
  const double freeSpan = std::hypot(placements[39].centre.x - placements[35].centre.x,
                                     placements[39].centre.y - placements[35].centre.y);
  const ContactStatus r = s.nav().groupStatus()[groupIndex(SensorGroup::Right)];
  EXPECT_EQ(r.kind, StatusKind::Hole);
  EXPECT_NEAR(r.holeWidthUnits, 0.5 * (between + freeSpan), 1e-9);
  EXPECT_EQ(s.nav().integratedStatus().kind, StatusKind::Hole);
  ASSERT_EQ(s.nav().holes().size(), 1u);
  EXPECT_NEAR(s.nav().holes()[0].widthUnits, r.holeWidthUnits, 1e-9);
  // The same opening seen again one step on is the same hole.
  s.step(split);
  EXPECT_EQ(s.nav().holes().size(), 1u);
}

// Arrived by odometry while the run goes on (the odometry may have drifted): the robot searches
// round the goal on a growing spiral and stays near it.
TEST(NavigatorStates, ArrivedSearchesRoundTheGoal) {
  Script s;
  for (int i = 0; i < 500 && !s.nav().arrived(); ++i)
    s.step(Values{});
  ASSERT_TRUE(s.nav().arrived());
  EXPECT_LT(std::hypot(s.nav().odometry().x - 2000.0, s.nav().odometry().y), 30.0);
  double farthest = 0.0;
  for (int i = 0; i < 1500; ++i) {
    s.step(Values{});
    const double d = std::hypot(s.nav().odometry().x - 2000.0, s.nav().odometry().y);
    farthest = std::max(farthest, d);
    EXPECT_LT(d, 450.0) << "step " << i;
  }
  EXPECT_GT(farthest, 150.0);
  EXPECT_TRUE(s.nav().arrived());
}

}  // namespace
}  // namespace tactile::nav
