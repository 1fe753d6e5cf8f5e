// Office-like maps for the navigation benchmark: a grid of rooms separated by 20-unit walls with
// doors, joined into one connected floor, and furniture boxes inside the rooms.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/scene.h"

namespace tactile::nav {

struct OfficeRoom {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // inner extent (between the walls)
};

struct OfficeMap {
  sim::Scene scene;
  std::vector<OfficeRoom> rooms;
};

// Deterministic per seed: 2 x 2 to 3 x 3 rooms of 450..750 units, doors 130..220 wide on a
// random spanning tree of the rooms plus a few more, 0..2 furniture boxes per room kept 150 units
// from the walls.
OfficeMap generateOfficeMap(std::uint64_t seed);

}  // namespace tactile::nav
