// A coarse occupancy grid of a scene for a disc of a given radius: a cell is free when its centre
// is at least `radius` from every obstacle edge and from the bounds and lies outside every
// obstacle. Used to tell whether two points are connected for the robot (the map "inflated" by
// the robot's half-width plus a margin), e.g. by the office-scene generator.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "sim/geometry.h"
#include "sim/scene.h"

namespace tactile::sim {

class ClearanceGrid {
 public:
  // Cells of `cellUnits` (> 0) covering the scene bounds; `radiusUnits` >= 0.
  ClearanceGrid(const Scene& scene, double radiusUnits, double cellUnits);

  int columns() const { return cols_; }
  int rows() const { return rows_; }
  double cellUnits() const { return cell_; }
  double radiusUnits() const { return radius_; }
  // Whether cell (column, row) is free; cells outside the grid are not.
  bool free(int column, int row) const;
  // The cell holding a point, or nullopt outside the bounds.
  std::optional<std::pair<int, int>> cellOf(const Vec2& p) const;
  Vec2 cellCentre(int column, int row) const;
  // Whether a path of free cells (4-neighbours) joins the cells of a and b. False when either
  // cell is not free.
  bool connected(const Vec2& a, const Vec2& b) const;
  // Labels of the 4-connected free components (-1 for occupied cells), row-major.
  std::vector<int> components() const;

 private:
  std::size_t at(int column, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(cols_) +
           static_cast<std::size_t>(column);
  }
  double x0_ = 0.0;
  double y0_ = 0.0;
  double cell_ = 1.0;
  double radius_ = 0.0;
  int cols_ = 0;
  int rows_ = 0;
  std::vector<std::uint8_t> free_;
};

}  // namespace tactile::sim
