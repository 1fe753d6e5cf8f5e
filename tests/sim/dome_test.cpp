#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/driver.h"
#include "sim/scene_source.h"
#include "sim_test_util.h"

namespace tactile::sim {
namespace {

using test::box;
using test::makeSim;
using test::roomWith;

constexpr double kFront = 105.0;  // front edge of the body, body frame

// A wall in front of a robot at (1000, 1000) facing +x, `gap` units ahead of the front edge.
Scene wallAhead(double gap) {
  return roomWith({box(1000 + kFront + gap, 800, 1400, 1200)});
}

TEST(DomeModel, NormalContactGivesRMinusDistance) {
  auto sim = makeSim(wallAhead(3.5));
  sim->step(0, 0);
  for (int d = 0; d < 8; ++d) {
    EXPECT_DOUBLE_EQ(sim->sensors()[normalOffset(d)], 6.0 - 3.5) << d;
    EXPECT_NEAR(sim->sensors()[shearOffset(d)], 0.0, 1e-12) << d;
  }
  // Back and sides touch nothing.
  for (int d = 10; d < 42; ++d)
    EXPECT_EQ(sim->sensors()[normalOffset(d)], 0.0) << d;
  EXPECT_FALSE(sim->blocked());
}

TEST(DomeModel, CornerDomeShearIsCounterClockwisePositive) {
  // Dome 8 sits at 30 degrees on the front-left corner: the front wall pushes it backwards,
  // which is along its counter-clockwise tangent (-sin 30, cos 30): positive shear.
  auto sim = makeSim(wallAhead(1.5));
  sim->step(0, 0);
  const double n8 = sim->sensors()[normalOffset(8)];
  const double s8 = sim->sensors()[shearOffset(8)];
  EXPECT_GT(n8, 0.0);
  EXPECT_GT(s8, 0.0);
  EXPECT_NEAR(s8 / n8, std::tan(std::numbers::pi / 6), 1e-12);
  // The mirror dome on the front-right corner (43) shears the other way.
  EXPECT_NEAR(sim->sensors()[shearOffset(43)], -s8, 1e-12);
  EXPECT_NEAR(sim->sensors()[normalOffset(43)], n8, 1e-12);
}

TEST(DomeModel, FortyFiveDegreeContactSplitsEqually) {
  // A sharp obstacle tip 4 units from dome 4's centre, 45 degrees to the left of its normal.
  const double y4 = -24.0 + 4.5 * 6.0;  // dome 4 on the front edge
  const Vec2 c(1000 + kFront, 1000 + y4);
  const Vec2 u(std::sqrt(0.5), std::sqrt(0.5));
  const Vec2 perp(-u.y(), u.x());
  const Vec2 tip = c + 4.0 * u;
  Obstacle tri{{tip, tip + 60 * u + 20 * perp, tip + 60 * u - 20 * perp}};
  auto sim = makeSim(roomWith({tri}));
  sim->step(0, 0);
  const double n = sim->sensors()[normalOffset(4)];
  const double s = sim->sensors()[shearOffset(4)];
  EXPECT_NEAR(n, 2.0 * std::sqrt(0.5), 1e-9);
  // The tip pushes the dome clockwise (toward -y): negative shear.
  EXPECT_NEAR(s, -2.0 * std::sqrt(0.5), 1e-9);
  EXPECT_EQ(sim->contact().domes[4].vertex >= 0, true);
}

TEST(DomeModel, ContactIsTheSameWhenTheWholeSceneIsRotated) {
  // The 45-degree tip of the previous test, with robot and obstacle turned by 0.7 rad together.
  const Pose2d pose{1000, 1000, 0.7};
  const Vec2 c(kFront, -24.0 + 4.5 * 6.0);
  const Vec2 u(std::sqrt(0.5), std::sqrt(0.5));
  const Vec2 perp(-u.y(), u.x());
  const Vec2 tip = c + 4.0 * u;
  Obstacle tri{{bodyToWorld(pose, tip), bodyToWorld(pose, tip + 60 * u + 20 * perp),
                bodyToWorld(pose, tip + 60 * u - 20 * perp)}};
  auto sim = makeSim(roomWith({tri}, pose));
  sim->step(0, 0);
  EXPECT_NEAR(sim->sensors()[normalOffset(4)], 2.0 * std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(sim->sensors()[shearOffset(4)], -2.0 * std::sqrt(0.5), 1e-9);
}

TEST(DomeModel, FullCompressionSaturatesAtFive) {
  auto sim = makeSim(wallAhead(1.0));  // r - d = 5 exactly
  sim->step(0, 0);
  EXPECT_FALSE(sim->blocked());
  for (int d = 0; d < 8; ++d)
    EXPECT_DOUBLE_EQ(sim->sensors()[normalOffset(d)], 5.0) << d;
  for (double v : sim->sensors()) {
    EXPECT_LE(v, kMaxNormal);
    EXPECT_GE(v, -kMaxShear);
  }
}

TEST(DomeModel, PushingPastFullCompressionIsBlocked) {
  auto sim = makeSim(wallAhead(1.0));
  sim->step(0, 0);
  const Pose2d before = sim->pose();
  sim->step(5.0, 0.0);  // half a unit further would compress past 5
  EXPECT_TRUE(sim->blocked());
  EXPECT_EQ(sim->pose().x, before.x);
  EXPECT_EQ(sim->pose().y, before.y);
  EXPECT_EQ(sim->pose().theta, before.theta);
  EXPECT_DOUBLE_EQ(sim->sensors()[normalOffset(3)], 5.0);
}

// A blocked step moves as far as is free, so the run records the contact that stopped it.
TEST(DomeModel, BlockedStepStopsAtTheLastFreeSubPoseAndBackingOutWorks) {
  auto sim = makeSim(wallAhead(3.0));  // front domes compressed 3 already
  sim->step(50.0, 0.0);                // 5 units: the front domes would need 8 units of compression
  EXPECT_TRUE(sim->blocked());
  // Sub-poses are 1 unit apart: 2 units on, the domes are at full compression, 3 is too far.
  EXPECT_NEAR(sim->pose().x, 1002.0, 1e-9);
  EXPECT_FALSE(sim->isBlocked(sim->pose()));
  EXPECT_DOUBLE_EQ(sim->sensors()[normalOffset(3)], 5.0);
  sim->step(-50.0, 0.0);
  EXPECT_FALSE(sim->blocked());
  EXPECT_NEAR(sim->pose().x, 997.0, 1e-9);
}

TEST(DomeModel, TurningIntoAWallIsBlocked) {
  // A wall along the right side, 2 units from the outline: turning right swings the front-right
  // corner into it.
  auto sim = makeSim(roomWith({box(800, 1000 - 40 - 2 - 100, 1300, 1000 - 40 - 2)}));
  sim->step(0.0, -0.2);
  EXPECT_TRUE(sim->blocked());
  // Turned as far as is free: a little, never into the wall.
  EXPECT_LE(sim->pose().theta, 0.0);
  EXPECT_GT(sim->pose().theta, -0.02);
  EXPECT_FALSE(sim->isBlocked(sim->pose()));
  sim->step(0.0, 0.2);  // turning away (slowly: the rear swings out) is free
  EXPECT_FALSE(sim->blocked());
}

TEST(DomeModel, StartPoseOverlappingIsRefusedByReset) {
  auto sim = makeSim(wallAhead(10.0));
  EXPECT_FALSE(sim->reset({1000 + 20, 1000, 0}));  // body would overlap the wall
  EXPECT_EQ(sim->pose().x, 1000.0);
  EXPECT_FALSE(sim->reset({1000 + 9.5, 1000, 0}));  // gap 0.5: domes past full compression
  EXPECT_TRUE(sim->reset({1000 + 8.0, 1000, 0}));   // gap 2
}

TEST(DomeModel, SpringDamperFiltersTowardTheRawValue) {
  SimConfig config = test::rawConfig();
  config.filterTauSeconds = 0.05;
  auto sim = makeSim(wallAhead(2.0), config);
  const double a = 0.1 / (0.05 + 0.1);
  sim->step(0, 0);
  EXPECT_NEAR(sim->sensors()[normalOffset(2)], a * 4.0, 1e-12);
  sim->step(0, 0);
  EXPECT_NEAR(sim->sensors()[normalOffset(2)], a * 4.0 + a * (4.0 - a * 4.0), 1e-12);
  for (int i = 0; i < 60; ++i)
    sim->step(0, 0);
  EXPECT_NEAR(sim->sensors()[normalOffset(2)], 4.0, 1e-9);
  // Backing away releases the domes; the value decays and reaches exactly zero.
  for (int i = 0; i < 3; ++i)
    sim->step(-50.0, 0);
  for (int i = 0; i < 60; ++i)
    sim->step(0, 0);
  EXPECT_EQ(sim->sensors()[normalOffset(2)], 0.0);
}

TEST(NoTunnelling, FastStepThroughAThinWallIsBlocked) {
  // A wall 0.5 thick 45 units ahead; one step at top speed (300 units) would land the whole
  // robot beyond it.
  auto sim = makeSim(roomWith({box(1150, 100, 1150.5, 1900)}));
  const Pose2d landing = integratePose(sim->pose(), kMaxSpeedUnits, 0.0, 0.1);
  ASSERT_GT(landing.x - 35.0, 1150.5) << "the landing pose must be clear of the wall";
  ASSERT_FALSE(sim->isBlocked(landing));
  sim->step(kMaxSpeedUnits, 0.0);
  EXPECT_TRUE(sim->blocked());
  // Stopped in front of the wall, the front domes on it: not through it.
  EXPECT_LT(sim->pose().x + kFront, 1150.0);
  EXPECT_GT(sim->pose().x + kFront, 1150.0 - 6.0);
  EXPECT_FALSE(sim->isBlocked(sim->pose()));
}

TEST(NoTunnelling, CommandsAreClampedToTopSpeed) {
  auto sim = makeSim(roomWith({}, {100, 1000, 0}));
  sim->step(1e12, 0.0);
  EXPECT_DOUBLE_EQ(sim->pose().x, 100 + kMaxSpeedUnits * 0.1);
}

TEST(NoTunnelling, FastTurnThroughAThinPostIsBlocked) {
  // A thin post beside the robot, hit only midway through a 180-degree turn in one step.
  auto sim = makeSim(roomWith({box(1020, 1080, 1020.5, 1120)}));
  sim->step(0.0, std::numbers::pi / 0.1);
  EXPECT_TRUE(sim->blocked());
  // Turned only until the post stopped it, not past it (the post sits 80-120 units to the left,
  // so the rear swings into it well before a quarter turn).
  EXPECT_GE(sim->pose().theta, 0.0);
  EXPECT_LT(sim->pose().theta, std::numbers::pi / 2);
  EXPECT_FALSE(sim->isBlocked(sim->pose()));
}

// Independent overlap check: the body outline as a polygon inscribed in the rounded rectangle
// must not cross any obstacle edge, contain an obstacle vertex, or leave the bounds.
bool overlapsAnything(const Scene& scene, const Pose2d& pose) {
  const RobotGeometry g;
  std::vector<Vec2> outline;
  const double r = g.cornerRadiusUnits;
  const Vec2 centres[4] = {{g.frontX() - r, g.halfWidth() - r},
                           {g.backX() + r, g.halfWidth() - r},
                           {g.backX() + r, -g.halfWidth() + r},
                           {g.frontX() - r, -g.halfWidth() + r}};
  for (int c = 0; c < 4; ++c) {
    for (int i = 0; i <= 8; ++i) {
      const double a = (c + i / 8.0) * std::numbers::pi / 2;
      outline.push_back(bodyToWorld(pose, centres[c] + r * Vec2(std::cos(a), std::sin(a))));
    }
  }
  for (const Vec2& p : outline) {
    if (p.x() < scene.bounds.xmin || p.x() > scene.bounds.xmax || p.y() < scene.bounds.ymin ||
        p.y() > scene.bounds.ymax) {
      return true;
    }
  }
  for (const Obstacle& o : scene.obstacles) {
    const auto& poly = o.polygon;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      if (pointInPolygon(poly[i], outline)) return true;
      for (std::size_t j = 0; j < outline.size(); ++j) {
        if (segmentsIntersect(poly[i], poly[(i + 1) % poly.size()], outline[j],
                              outline[(j + 1) % outline.size()])) {
          return true;
        }
      }
    }
    if (pointInPolygon(outline[0], poly)) return true;
  }
  return false;
}

TEST(NoTunnelling, NoRecordedPoseEverOverlapsAnObstacle) {
  int blockedSteps = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const Scene scene = generateProceduralScene(40, seed);
    auto world = std::make_shared<const World>(scene);
    Simulator sim(world, SimConfig{});
    RandomDriver driver(seed);
    Observation obs;
    obs.values = &sim.sensors();
    for (int k = 0; k < 3000; ++k) {
      obs.pose = sim.pose();
      obs.blocked = sim.blocked();
      Command c = driver.next(obs);
      // Occasionally a burst of top speed and fast turning, to try to tunnel.
      if (k % 97 == 0) c = {600.0, 0.0};
      if (k % 89 == 0) c = {0.0, 20.0};
      sim.step(c.v, c.omega);
      blockedSteps += sim.blocked();
      ASSERT_FALSE(overlapsAnything(scene, sim.pose())) << "seed " << seed << " step " << k;
    }
  }
  EXPECT_GT(blockedSteps, 0) << "the drive never touched anything hard";
}

}  // namespace
}  // namespace tactile::sim
