// The reference shortest path of the map benchmark: a grid A* on the scene's free space shrunk by
// the robot (every obstacle and the bounds grown by the robot's half width with its domes), as in
// McGuire, de Croon and Tuyls (2019). Eight-connected with octile costs; a diagonal move may not
// cut the corner of a blocked cell.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "sim/world.h"

namespace tactile::nav {

struct GridMap {
  double x0 = 0.0;  // lower-left corner of cell (0, 0)
  double y0 = 0.0;
  double cellUnits = 10.0;
  int cols = 0;
  int rows = 0;
  std::vector<std::uint8_t> blocked;  // rows * cols, row-major

  bool isBlocked(int col, int row) const {
    return col < 0 || row < 0 || col >= cols || row >= rows ||
           blocked[static_cast<std::size_t>(row) * cols + col] != 0;
  }
};

// Cells whose centre lies inside an obstacle, outside the bounds, or within `inflateUnits` of an
// obstacle edge or the bounds are blocked.
GridMap inflatedGrid(const sim::World& world, double cellUnits, double inflateUnits);

// Length (scene units) of the shortest eight-connected path between the cells of `from` and `to`,
// or nullopt when there is none. A point in a blocked cell starts from the nearest free cell
// within `snapUnits` (the robot stands closer to a wall than the inflated map allows).
std::optional<double> shortestPathUnits(const GridMap& grid, const sim::Vec2& from,
                                        const sim::Vec2& to, double snapUnits = 60.0);

}  // namespace tactile::nav
