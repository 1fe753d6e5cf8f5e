// Default robot body and dome placement (docs/domain.md#robot).
//
// Body frame: origin at the midpoint of the rear axle, x forward, y to the left. The body is a
// rounded rectangle; the rear axle sits kRearOverhang units in front of the back edge. Dome centres
// lie on the body outline and their normals point outward, so a dome of radius r adds r to each
// side: 80 + 2 * 6 = 92 units wide, which passes a 110-wide gap and not a 90-wide one.
#pragma once

#include <array>

#include "run/sensor_layout.h"

namespace tactile {

struct Vec2d {
  double x = 0.0;
  double y = 0.0;
};

struct RobotGeometry {
  double lengthUnits = 140.0;
  double widthUnits = 80.0;
  double cornerRadiusUnits = 16.0;
  double rearOverhangUnits = 35.0;  // back edge to rear axle
  double domeRadiusUnits = 6.0;

  double frontX() const { return lengthUnits - rearOverhangUnits; }
  double backX() const { return -rearOverhangUnits; }
  double halfWidth() const { return 0.5 * widthUnits; }
};

struct DomePlacement {
  Vec2d centre;  // body frame, on the outline
  Vec2d normal;  // unit outward normal, body frame
};

// Dome centres and normals in index order (counter-clockwise from the right end of the front
// edge). Domes on a straight edge sit at the centres of equal slots along it; the two domes of a
// corner sit at 1/3 and 2/3 of its quarter arc.
std::array<DomePlacement, kSensorCount> domePlacements(const RobotGeometry& geometry = {});

}  // namespace tactile
