// Differential-drive kinematics of the robot (thesis 2.2) and body/world frame conversions.
#pragma once

#include <cmath>
#include <numbers>

#include "run/run.h"
#include "sim/geometry.h"

namespace tactile::sim {

// Wraps an angle to (-pi, pi].
inline double wrapAngle(double a) {
  if (a > -std::numbers::pi && a <= std::numbers::pi) return a;
  a = std::remainder(a, 2.0 * std::numbers::pi);
  if (a <= -std::numbers::pi) a += 2.0 * std::numbers::pi;
  return a;
}

// Body to world: p_I = t + R(theta) p_R, with R(theta) = [cos -sin; sin cos] (thesis 2.2, R_R^I).
inline Vec2 bodyToWorld(const Pose2d& pose, const Vec2& p) {
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  return Vec2(pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y());
}

// World to body: p_R = R(theta)^T (p_I - t) (thesis 2.2, R_I^R).
inline Vec2 worldToBody(const Pose2d& pose, const Vec2& p) {
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  const double dx = p.x() - pose.x;
  const double dy = p.y() - pose.y;
  return Vec2(c * dx + s * dy, -s * dx + c * dy);
}

// Integrates the command (v, omega) exactly over `seconds` (the rear-axle midpoint moves on an
// arc; heading is not wrapped here):
//   theta' = theta + omega t,
//   [x' y'] = [x y] + v t sinc(omega t / 2) [cos(theta + omega t / 2), sin(theta + omega t / 2)]
// (the chord of the arc), which reduces to a straight line for omega = 0 with no division by 0.
inline Pose2d integratePose(const Pose2d& pose, double v, double omega, double seconds) {
  const double half = 0.5 * omega * seconds;
  const double sinc = std::abs(half) < 1e-4 ? 1.0 - half * half / 6.0 : std::sin(half) / half;
  const double chord = v * seconds * sinc;
  const double mid = pose.theta + half;
  return Pose2d{pose.x + chord * std::cos(mid), pose.y + chord * std::sin(mid),
                pose.theta + omega * seconds};
}

}  // namespace tactile::sim
