#include <gtest/gtest.h>

#include <algorithm>

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

TEST(Truth, DrivingPastTheEndOfAWallIsLeavingWall) {
  // A wall along the right side that ends at x = 1100; drive forward past its end.
  auto sim = makeSim(roomWith({box(500, 800, 1100, 1000 - 43)}));
  std::vector<ContactClass> seen;
  for (int k = 0; k < 60; ++k) {
    sim->step(50, 0);
    ASSERT_FALSE(sim->blocked());
    seen.push_back(classOf(*sim, SensorGroup::Right));
  }
  ASSERT_EQ(seen.front(), ContactClass::Wall);
  std::string trace;
  for (ContactClass c : seen)
    trace += std::string(contactClassName(c)) + " ";
  SCOPED_TRACE(trace);
  const auto firstLeaving = std::find(seen.begin(), seen.end(), ContactClass::LeavingWall);
  ASSERT_NE(firstLeaving, seen.end());
  const auto firstNone = std::find(firstLeaving, seen.end(), ContactClass::NoContact);
  ASSERT_NE(firstNone, seen.end());
  // Wall ... Wall, LeavingWall ... LeavingWall, NoContact ...: never Corner at the wall's end.
  EXPECT_TRUE(std::all_of(seen.begin(), firstLeaving,
                          [](ContactClass c) { return c == ContactClass::Wall; }));
  EXPECT_TRUE(std::all_of(firstLeaving, firstNone,
                          [](ContactClass c) { return c == ContactClass::LeavingWall; }));
  EXPECT_TRUE(std::all_of(firstNone, seen.end(),
                          [](ContactClass c) { return c == ContactClass::NoContact; }));
}

TEST(Truth, TurningAwayFromAWallIsLeavingWall) {
  // Default spring-damper: the released domes fade out over a few steps (rule 2).
  auto sim = makeSim(roomWith({box(500, 800, 1500, 1000 - 43)}), SimConfig{});
  sim->step(0, 0);
  ASSERT_EQ(classOf(*sim, SensorGroup::Right), ContactClass::Wall);
  bool leaving = false;
  for (int k = 0; k < 30 && classOf(*sim, SensorGroup::Right) != ContactClass::NoContact; ++k) {
    sim->step(30, 0.6);  // veer left, away from the wall
    leaving = leaving || classOf(*sim, SensorGroup::Right) == ContactClass::LeavingWall;
  }
  EXPECT_TRUE(leaving);
  EXPECT_EQ(classOf(*sim, SensorGroup::Right), ContactClass::NoContact);
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
