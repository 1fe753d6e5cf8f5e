#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "sim_test_util.h"

namespace tactile::sim {
namespace {

using test::box;
using test::makeSim;
using test::roomWith;

ContactClass classOf(const Simulator& sim, SensorGroup g) {
  return sim.truth()[groupIndex(g)];
}

TEST(Truth, OpenSpaceIsNoContact) {
  auto sim = makeSim(roomWith({}));
  sim->step(10, 0);
  for (ContactClass c : sim->truth())
    EXPECT_EQ(c, ContactClass::NoContact);
}

TEST(Truth, SideAlongAStraightWallIsWall) {
  auto sim = makeSim(roomWith({box(700, 800, 1300, 1000 - 43)}));  // 3 units below the right side
  sim->step(0, 0);
  EXPECT_EQ(classOf(*sim, SensorGroup::Right), ContactClass::Wall);
  EXPECT_EQ(classOf(*sim, SensorGroup::Left), ContactClass::NoContact);
  EXPECT_EQ(classOf(*sim, SensorGroup::Front), ContactClass::NoContact);
}

TEST(Truth, FrontOnAConvexVertexIsCorner) {
  // A square turned 45 degrees, its corner 3 units ahead of the middle of the front edge.
  const double tip = 1000 + 105 + 3;
  Obstacle diamond{
      {Vec2(tip, 1000), Vec2(tip + 60, 940), Vec2(tip + 120, 1000), Vec2(tip + 60, 1060)}};
  auto sim = makeSim(roomWith({diamond}));
  sim->step(0, 0);
  EXPECT_EQ(classOf(*sim, SensorGroup::Front), ContactClass::Corner);
}

TEST(Truth, CornerGroupInAConcaveCornerIsCorner) {
  // An L-shaped obstacle: a wall 3 units ahead and a wall 3 units to the left, meeting in a
  // concave corner at the front-left corner of the robot.
  Obstacle l{{Vec2(1108, 800), Vec2(1300, 800), Vec2(1300, 1300), Vec2(800, 1300), Vec2(800, 1043),
              Vec2(1108, 1043)}};
  auto sim = makeSim(roomWith({l}));
  sim->step(0, 0);
  EXPECT_EQ(classOf(*sim, SensorGroup::FrontLeftCorner), ContactClass::Corner);
  EXPECT_EQ(classOf(*sim, SensorGroup::Front), ContactClass::Wall);
  EXPECT_EQ(classOf(*sim, SensorGroup::Left), ContactClass::Wall);
  EXPECT_EQ(classOf(*sim, SensorGroup::Right), ContactClass::NoContact);
}

// The classes a group shows, in order, with repeats collapsed ("Wall LeavingWall NoContact").
std::string sequenceOf(const std::vector<ContactClass>& seen) {
  std::string out;
  ContactClass last = ContactClass::NoContact;
  bool first = true;
  for (ContactClass c : seen) {
    if (!first && c == last) continue;
    if (!out.empty()) out += ' ';
    out += contactClassName(c);
    last = c;
    first = false;
  }
  return out;
}

TEST(Truth, DrivingPastTheEndOfAWallIsWallThenLeavingWallThenCornerAtAnySpeed) {
  // A wall along the right side that ends at x = 1100; drive forward past its end with the
  // default spring-damper, at speeds 10 to 60. The rear-most dome, last on the wall, rolls over
  // its end alone: a vertex felt (Corner), and its values fade with that class.
  for (double speed : {10.0, 20.0, 30.0, 40.0, 50.0, 60.0}) {
    auto sim = makeSim(roomWith({box(500, 800, 1100, 1000 - 43)}), SimConfig{});
    std::vector<ContactClass> right;
    std::vector<ContactClass> frontRight;
    sim->step(0, 0);  // settle on the wall
    for (int k = 0; k < static_cast<int>(2000 / speed); ++k) {
      sim->step(speed, 0);
      ASSERT_FALSE(sim->blocked());
      right.push_back(classOf(*sim, SensorGroup::Right));
      frontRight.push_back(classOf(*sim, SensorGroup::FrontRightCorner));
    }
    EXPECT_EQ(sequenceOf(right), "Wall LeavingWall Corner NoContact") << "speed " << speed;
    // The front corner group never leaves a wall (no such class there).
    EXPECT_EQ(std::count(frontRight.begin(), frontRight.end(), ContactClass::LeavingWall), 0)
        << "speed " << speed << ": " << sequenceOf(frontRight);
  }
}

// Leaving starts where the readings show it: while the front-most dome of R is still on the
// wall's interior the group reads as on the wall, and is Wall.
TEST(Truth, LeavingWallStartsOnlyOnceTheEndHasReachedTheFrontMostDome) {
  const int front = groupInfo(SensorGroup::Right).firstSensor + 9;  // dome 41, R's front-most
  auto sim = makeSim(roomWith({box(500, 800, 1100, 1000 - 43)}), SimConfig{});
  sim->step(0, 0);
  int leaving = 0;
  for (int k = 0; k < 100; ++k) {
    sim->step(10, 0);
    const DomeContact& fc = sim->contact().domes[front];
    const ContactClass r = classOf(*sim, SensorGroup::Right);
    if (fc.edge >= 0 && fc.vertex < 0) {
      EXPECT_EQ(r, ContactClass::Wall) << "step " << k;
    }
    if (r == ContactClass::LeavingWall) ++leaving;
  }
  EXPECT_GT(leaving, 50);
}

// LeavingWall is the group's front off the wall while its rear is still on it: at every such step
// a dome of the group touches the wall's interior. A group left with nothing but the end under
// it feels a vertex, as it would any convex corner passing along the side: Corner.
bool onAnEdgeInterior(const Simulator& sim, SensorGroup g) {
  const GroupInfo& info = groupInfo(g);
  for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
    const DomeContact& dc = sim.contact().domes[d];
    if (dc.edge >= 0 && dc.vertex < 0) return true;
  }
  return false;
}

TEST(Truth, LeavingWallOnlyWhileADomeOfTheGroupIsStillOnTheWall) {
  // Straight off the end of a wall along the right side, and off the end of a wall that closes
  // in on the side toward its end (only the front domes touch it, the end then runs back along
  // the side alone), at several speeds.
  const double surface = 1000 - 46;  // the right side's domes, undeformed
  const Obstacle straight = box(500, 800, 1100, 1000 - 43);
  const double slope = std::tan(8.0 * std::numbers::pi / 180.0);
  const Obstacle closing{{Vec2(1060, surface + 2), Vec2(700, surface + 2 - 360 * slope),
                          Vec2(700, 800), Vec2(1060, 800)}};
  for (int shape = 0; shape < 2; ++shape) {
    const Obstacle& wall = shape == 0 ? straight : closing;
    for (double speed : {5.0, 10.0, 30.0}) {
      auto sim = makeSim(roomWith({wall}), SimConfig{});
      std::vector<ContactClass> right;
      int leaving = 0;
      int vertexOnly = 0;
      for (int k = 0; k < static_cast<int>(3000 / speed); ++k) {  // 300 units
        sim->step(speed, 0);
        ASSERT_FALSE(sim->blocked());
        const ContactClass r = classOf(*sim, SensorGroup::Right);
        right.push_back(r);
        if (r == ContactClass::LeavingWall) {
          ++leaving;
          EXPECT_TRUE(onAnEdgeInterior(*sim, SensorGroup::Right))
              << "speed " << speed << " step " << k << ": " << sequenceOf(right);
        }
        bool touches = false;
        const GroupInfo& info = groupInfo(SensorGroup::Right);
        for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d)
          touches = touches || sim->contact().domes[d].edge >= 0;
        if (touches && !onAnEdgeInterior(*sim, SensorGroup::Right)) {
          ++vertexOnly;
          EXPECT_EQ(r, ContactClass::Corner) << "speed " << speed << " step " << k;
        }
      }
      EXPECT_GT(vertexOnly, 0) << "speed " << speed << ": " << sequenceOf(right);
      if (shape == 0) {
        EXPECT_GT(leaving, 0) << sequenceOf(right);
      }
    }
  }
}

// Backing along a wall onto its end reads like leaving it, but the robot is not leaving.
TEST(Truth, BackingOntoTheEndOfAWallIsNeverLeavingWall) {
  for (double speed : {10.0, 30.0}) {
    // The wall's end is 20 units behind the robot's rear; the robot backs along it.
    auto sim = makeSim(roomWith({box(500, 800, 1000 - 35 - 20, 1000 - 43)}), SimConfig{});
    std::vector<ContactClass> right;
    for (int k = 0; k < static_cast<int>(4000 / speed); ++k) {  // 400 units
      sim->step(-speed, 0);
      ASSERT_FALSE(sim->blocked());
      right.push_back(classOf(*sim, SensorGroup::Right));
    }
    EXPECT_EQ(std::count(right.begin(), right.end(), ContactClass::LeavingWall), 0)
        << "speed " << speed << ": " << sequenceOf(right);
    EXPECT_EQ(right.back(), ContactClass::Wall) << sequenceOf(right);
  }
}

// A two-dome rear corner along a side wall touches it with its side dome only: when that dome
// rolls off the wall's end no dome of the group is left on the wall, so the group shows a corner
// there, not leaving.
TEST(Truth, RearCornerRollingOffAWallEndIsCornerNotLeavingWall) {
  // The wall presses the right side's domes by 4 units, enough for RRC's side dome to touch.
  auto sim = makeSim(roomWith({box(500, 800, 1100, 1000 - 42)}), SimConfig{});
  sim->step(0, 0);
  ASSERT_EQ(classOf(*sim, SensorGroup::RearRightCorner), ContactClass::Wall);
  std::vector<ContactClass> rrc;
  for (int k = 0; k < 150; ++k) {
    sim->step(10, 0);
    rrc.push_back(classOf(*sim, SensorGroup::RearRightCorner));
  }
  EXPECT_EQ(sequenceOf(rrc), "Wall Corner NoContact");
}

TEST(Truth, TouchingAndReleasingAWallGivesOnlyWallAndNoContact) {
  // Default spring-damper: the released domes fade out over a few steps and keep their class.
  for (double omega : {0.4, 0.6}) {
    auto sim = makeSim(roomWith({box(500, 800, 1500, 1000 - 43)}), SimConfig{});
    std::vector<ContactClass> seen;
    sim->step(0, 0);
    seen.push_back(classOf(*sim, SensorGroup::Right));
    for (int k = 0; k < 30; ++k) {
      sim->step(30, omega);  // veer left, away from the wall
      seen.push_back(classOf(*sim, SensorGroup::Right));
    }
    EXPECT_EQ(sequenceOf(seen), "Wall NoContact") << "omega " << omega;
  }
}

TEST(Truth, HexagonTipIsCornerOnEveryContactStepWhileTurningInPlace) {
  // A hexagon whose tip sits 2 units ahead of the middle of the front edge; the robot turns in
  // place one way and back, its front domes rolling over the tip.
  const double tip = 1000 + 105 + 6 - 4;  // 4 units of compression on the middle dome
  Obstacle hexagon;
  for (int i = 0; i < 6; ++i) {
    const double a = std::numbers::pi + i * std::numbers::pi / 3;
    hexagon.polygon.push_back(Vec2(tip + 50 + 50 * std::cos(a), 1000 + 50 * std::sin(a)));
  }
  auto sim = makeSim(roomWith({hexagon}), SimConfig{});
  int contactSteps = 0;
  for (int k = 0; k < 40; ++k) {
    sim->step(0, k < 20 ? 0.05 : -0.05);
    const ContactClass f = classOf(*sim, SensorGroup::Front);
    if (f == ContactClass::NoContact) continue;
    ++contactSteps;
    EXPECT_EQ(f, ContactClass::Corner) << "step " << k;
  }
  EXPECT_GT(contactSteps, 30);
}

// Leaving is for a group that was on a wall: sliding past a convex tip met side-on is moving
// round a corner, Corner throughout.
TEST(Truth, PassingATipBesideTheSideIsCornerNotLeavingWall) {
  // A square turned 45 degrees below the robot, its top vertex 2 units into the right side's
  // domes, 30 units ahead of the rear axle.
  const double top = 1000 - 46 + 2;
  Obstacle diamond{
      {Vec2(1030, top), Vec2(970, top - 60), Vec2(1030, top - 120), Vec2(1090, top - 60)}};
  auto sim = makeSim(roomWith({diamond}), SimConfig{});
  std::vector<ContactClass> right;
  for (int k = 0; k < 40; ++k) {
    sim->step(10, 0);
    right.push_back(classOf(*sim, SensorGroup::Right));
  }
  EXPECT_EQ(std::count(right.begin(), right.end(), ContactClass::LeavingWall), 0)
      << sequenceOf(right);
  EXPECT_GT(std::count(right.begin(), right.end(), ContactClass::Corner), 5) << sequenceOf(right);
}

// Working round a corner: a dome rolling on and off the vertex keeps the group on Corner.
TEST(Truth, RollingOnAndOffAVertexStaysCorner) {
  // A square turned 45 degrees, its top vertex 3 units into the right side's domes; the robot
  // rocks forward and back by less than a dome's width over it.
  const double top = 1000 - 46 + 3;
  Obstacle diamond{
      {Vec2(1030, top), Vec2(970, top - 60), Vec2(1030, top - 120), Vec2(1090, top - 60)}};
  auto sim = makeSim(roomWith({diamond}), SimConfig{});
  std::vector<ContactClass> right;
  for (int k = 0; k < 60; ++k) {
    sim->step((k / 4) % 2 == 0 ? 10.0 : -10.0, 0);
    right.push_back(classOf(*sim, SensorGroup::Right));
  }
  EXPECT_EQ(sequenceOf(right), "Corner") << sequenceOf(right);
}

TEST(Truth, SmoothingMergesShortSegmentsInsideAContactEpisode) {
  // One group's classes over 38 steps; the other groups stay NoContact.
  const std::string in = "..WWWLWWCCCWLW..LLW.WCCCC.WW.CCWWWWLL.";
  const std::string out = "..WWWWWWCCCCCC..LLL.CCCCC.WW.WWWWWWWW.";
  const auto decode = [](char c) {
    switch (c) {
      case 'W':
        return ContactClass::Wall;
      case 'C':
        return ContactClass::Corner;
      case 'L':
        return ContactClass::LeavingWall;
      default:
        return ContactClass::NoContact;
    }
  };
  std::vector<ContactClass> truth(in.size() * kGroupCount, ContactClass::NoContact);
  for (std::size_t k = 0; k < in.size(); ++k)
    truth[k * kGroupCount + 2] = decode(in[k]);
  smoothTruth(truth, in.size());
  std::string got;
  for (std::size_t k = 0; k < in.size(); ++k) {
    const ContactClass c = truth[k * kGroupCount + 2];
    got += c == ContactClass::Wall          ? 'W'
           : c == ContactClass::Corner      ? 'C'
           : c == ContactClass::LeavingWall ? 'L'
                                            : '.';
    for (int g = 0; g < kGroupCount; ++g) {
      if (g == 2) continue;
      EXPECT_EQ(truth[k * kGroupCount + g], ContactClass::NoContact);
    }
  }
  EXPECT_EQ(got, out);
}

TEST(Truth, FadingCornerContactStaysCorner) {
  SimConfig config;  // default spring-damper: values decay over a few steps after release
  const double tip = 1000 + 105 + 3;
  Obstacle diamond{
      {Vec2(tip, 1000), Vec2(tip + 60, 940), Vec2(tip + 120, 1000), Vec2(tip + 60, 1060)}};
  auto sim = makeSim(roomWith({diamond}), config);
  sim->step(0, 0);
  ASSERT_EQ(classOf(*sim, SensorGroup::Front), ContactClass::Corner);
  sim->step(-50, 0);  // released, values decaying
  ASSERT_GT(sim->sensors()[normalOffset(4)], 0.0);
  EXPECT_EQ(classOf(*sim, SensorGroup::Front), ContactClass::Corner);
  for (int k = 0; k < 10; ++k)
    sim->step(0, 0);
  EXPECT_EQ(classOf(*sim, SensorGroup::Front), ContactClass::NoContact);
}

TEST(Truth, DeadEndOfANarrowCorridorIsDeadPath) {
  // A U-shaped pocket 86 wide (3 units of clearance each side) with its end 3 units ahead.
  Obstacle u{{Vec2(800, 957), Vec2(1108, 957), Vec2(1108, 1043), Vec2(800, 1043), Vec2(800, 1100),
              Vec2(1200, 1100), Vec2(1200, 900), Vec2(800, 900)}};
  auto sim = makeSim(roomWith({u}));
  sim->step(0, 0);
  for (SensorGroup g : {SensorGroup::Front, SensorGroup::FrontLeftCorner,
                        SensorGroup::FrontRightCorner, SensorGroup::Left, SensorGroup::Right}) {
    EXPECT_EQ(classOf(*sim, g), ContactClass::DeadPath) << groupInfo(g).shortName;
  }
  EXPECT_EQ(classOf(*sim, SensorGroup::Back), ContactClass::NoContact);
  EXPECT_EQ(classOf(*sim, SensorGroup::RearLeftCorner), ContactClass::Wall);
  // Only backing out is possible.
  sim->step(50, 0);
  EXPECT_TRUE(sim->blocked());
  sim->step(0, 0.5);
  EXPECT_TRUE(sim->blocked());
  sim->step(-20, 0);
  EXPECT_FALSE(sim->blocked());
}

TEST(Truth, CorridorWithOpenFrontIsWallNotDeadPath) {
  Obstacle u{{Vec2(800, 957), Vec2(1300, 957), Vec2(1300, 900), Vec2(800, 900)}};
  Obstacle top{{Vec2(800, 1043), Vec2(1300, 1043), Vec2(1300, 1100), Vec2(800, 1100)}};
  auto sim = makeSim(roomWith({u, top}));
  sim->step(0, 0);
  EXPECT_EQ(classOf(*sim, SensorGroup::Left), ContactClass::Wall);
  EXPECT_EQ(classOf(*sim, SensorGroup::Right), ContactClass::Wall);
  EXPECT_EQ(classOf(*sim, SensorGroup::Front), ContactClass::NoContact);
}

}  // namespace
}  // namespace tactile::sim
