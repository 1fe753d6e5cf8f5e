#include "run/robot_geometry.h"

#include <cmath>
#include <numbers>

namespace tactile {
namespace {

// `count` domes at the centres of equal slots from `from` to `to`, all with one normal.
void placeAlongEdge(std::array<DomePlacement, kSensorCount>& out, int first, int count, Vec2d from,
                    Vec2d to, Vec2d normal) {
  for (int i = 0; i < count; ++i) {
    const double t = (i + 0.5) / count;
    out[first + i] = {{from.x + t * (to.x - from.x), from.y + t * (to.y - from.y)}, normal};
  }
}

// Two domes at 1/3 and 2/3 of the quarter arc that starts at angle `startRadians`.
void placeOnCorner(std::array<DomePlacement, kSensorCount>& out, int first, Vec2d centre,
                   double radius, double startRadians) {
  for (int i = 0; i < 2; ++i) {
    const double a = startRadians + (i + 1) * (std::numbers::pi / 6.0);
    const Vec2d n{std::cos(a), std::sin(a)};
    out[first + i] = {{centre.x + radius * n.x, centre.y + radius * n.y}, n};
  }
}

}  // namespace

std::array<DomePlacement, kSensorCount> domePlacements(const RobotGeometry& g) {
  std::array<DomePlacement, kSensorCount> out{};
  const double r = g.cornerRadiusUnits;
  const double front = g.frontX();
  const double back = g.backX();
  const double half = g.halfWidth();
  const double pi = std::numbers::pi;
  // Counter-clockwise from the right end of the front edge.
  placeAlongEdge(out, 0, 8, {front, -half + r}, {front, half - r}, {1, 0});
  placeOnCorner(out, 8, {front - r, half - r}, r, 0.0);
  placeAlongEdge(out, 10, 10, {front - r, half}, {back + r, half}, {0, 1});
  placeOnCorner(out, 20, {back + r, half - r}, r, 0.5 * pi);
  placeAlongEdge(out, 22, 8, {back, half - r}, {back, -half + r}, {-1, 0});
  placeOnCorner(out, 30, {back + r, -half + r}, r, pi);
  placeAlongEdge(out, 32, 10, {back + r, -half}, {front - r, -half}, {0, -1});
  placeOnCorner(out, 42, {front - r, -half + r}, r, 1.5 * pi);
  return out;
}

}  // namespace tactile
