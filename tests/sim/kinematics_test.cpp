#include <gtest/gtest.h>

#include <numbers>

#include "sim/robot.h"
#include "sim_test_util.h"

namespace tactile::sim {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Kinematics, StraightLineAlongHeading) {
  const Pose2d p = integratePose({10, 20, kPi / 6}, 50.0, 0.0, 0.1);
  EXPECT_NEAR(p.x, 10 + 5 * std::cos(kPi / 6), 1e-12);
  EXPECT_NEAR(p.y, 20 + 5 * std::sin(kPi / 6), 1e-12);
  EXPECT_DOUBLE_EQ(p.theta, kPi / 6);
}

TEST(Kinematics, TurnsInPlaceAboutTheRearAxle) {
  const Pose2d p = integratePose({10, 20, 0.3}, 0.0, 1.0, 0.5);
  EXPECT_DOUBLE_EQ(p.x, 10);
  EXPECT_DOUBLE_EQ(p.y, 20);
  EXPECT_NEAR(p.theta, 0.8, 1e-15);
}

TEST(Kinematics, ArcEndsOnTheTurningCircle) {
  // v / omega = radius 100; a quarter turn from (0, 0) heading +x ends at (100, 100) heading +y.
  const Pose2d p = integratePose({0, 0, 0}, 100.0 * kPi / 2, kPi / 2, 1.0);
  EXPECT_NEAR(p.x, 100.0, 1e-9);
  EXPECT_NEAR(p.y, 100.0, 1e-9);
  EXPECT_NEAR(p.theta, kPi / 2, 1e-15);
}

TEST(Kinematics, SubStepsComposeToTheFullStep) {
  const Pose2d start{3, -4, 1.0};
  Pose2d p = start;
  for (int i = 0; i < 10; ++i)
    p = integratePose(p, 40.0, -0.7, 0.01);
  const Pose2d q = integratePose(start, 40.0, -0.7, 0.1);
  EXPECT_NEAR(p.x, q.x, 1e-12);
  EXPECT_NEAR(p.y, q.y, 1e-12);
  EXPECT_NEAR(p.theta, q.theta, 1e-12);
}

TEST(Kinematics, TinyTurnRateMatchesStraightLine) {
  const Pose2d a = integratePose({0, 0, 0}, 50.0, 1e-12, 0.1);
  EXPECT_NEAR(a.x, 5.0, 1e-12);
  EXPECT_NEAR(a.y, 0.0, 1e-12);
}

TEST(Kinematics, BodyWorldRoundTrip) {
  const Pose2d pose{100, -50, 2.5};
  const Vec2 p(12.5, -7.25);
  const Vec2 w = bodyToWorld(pose, p);
  const Vec2 back = worldToBody(pose, w);
  EXPECT_NEAR(back.x(), p.x(), 1e-12);
  EXPECT_NEAR(back.y(), p.y(), 1e-12);
  // The body x axis points along the heading.
  const Vec2 ahead = bodyToWorld(pose, Vec2(1, 0)) - Vec2(pose.x, pose.y);
  EXPECT_NEAR(ahead.x(), std::cos(2.5), 1e-12);
  EXPECT_NEAR(ahead.y(), std::sin(2.5), 1e-12);
}

TEST(Kinematics, WrapAngleStaysInHalfOpenRange) {
  EXPECT_DOUBLE_EQ(wrapAngle(0.5), 0.5);
  EXPECT_NEAR(wrapAngle(3 * kPi / 2), -kPi / 2, 1e-12);
  EXPECT_NEAR(wrapAngle(-3 * kPi / 2), kPi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(wrapAngle(kPi), kPi);
  EXPECT_NEAR(wrapAngle(-kPi), kPi, 1e-12);
  EXPECT_NEAR(wrapAngle(101.0), std::remainder(101.0, 2 * kPi), 1e-12);
}

TEST(Kinematics, SimulatorStepsLikeTheIntegrator) {
  auto sim = test::makeSim(test::roomWith({}));
  sim->step(50.0, 0.4);
  const Pose2d expected = integratePose({1000, 1000, 0}, 50.0, 0.4, 0.1);
  EXPECT_DOUBLE_EQ(sim->pose().x, expected.x);
  EXPECT_DOUBLE_EQ(sim->pose().y, expected.y);
  EXPECT_DOUBLE_EQ(sim->pose().theta, expected.theta);
  EXPECT_FALSE(sim->blocked());
}

TEST(Kinematics, NonFiniteCommandIsTreatedAsStop) {
  auto sim = test::makeSim(test::roomWith({}));
  sim->step(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity());
  EXPECT_EQ(sim->pose().x, 1000.0);
  EXPECT_EQ(sim->pose().theta, 0.0);
}

}  // namespace
}  // namespace tactile::sim
