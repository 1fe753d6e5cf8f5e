// The touch map (docs/navigation.md#the-touch-map-experimental): an occupancy grid in the
// navigator's odometry frame holding where the robot has touched something, and a grid A* on it
// from the robot to the goal. Unknown cells count as free; a cell is closed to the planner when a
// touched cell lies within the growth radius (about the robot's half width). Cells the robot's body
// has since driven through are cleared again (the odometry drifts; the body there says the cell is
// free).
//
// What it may know is what the navigator knows: its odometry pose, the goal relative to the
// start, the dome layout and which domes touch. Deterministic.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "sim/robot.h"

namespace tactile::nav {

struct TouchMapConfig {
  double cellUnits = 20.0;
  // A touched cell closes every cell whose centre lies within this distance of its centre.
  double growUnits = 40.0;
  // Open cells within this distance of a touched cell are near it: a plan step onto one costs
  // nearCost times its length, so the plan keeps off the band along a wall and crosses it square
  // on at a door. 1 (the default): no extra cost; 3 passes the 120-wide gap from more starts but
  // succeeds on fewer of the generated maps (docs/navigation-bench.md#touch-map-experiment).
  double nearUnits = 70.0;
  double nearCost = 1.0;
  // The grid covers the box round start and goal widened by this much on every side; beyond it
  // the planner does not go.
  double marginUnits = 2000.0;
};

// A plan: cell centres from the robot's cell to the goal's, in odometry coordinates.
struct TouchPlan {
  std::vector<sim::Vec2> points;
  double lengthUnits = 0.0;
};

class TouchMap {
 public:
  TouchMap() = default;
  TouchMap(const sim::Vec2& start, const sim::Vec2& goal, TouchMapConfig config = {});

  const TouchMapConfig& config() const { return cfg_; }
  int cols() const { return cols_; }
  int rows() const { return rows_; }
  bool empty() const { return cols_ == 0; }

  // Marks the cell holding `point` as touched; false when it was already (or lies off the grid).
  bool mark(const sim::Vec2& point);
  // Clears every touched cell whose centre lies within `radius` of `point`; the number cleared.
  int clear(const sim::Vec2& point, double radius);
  bool touched(const sim::Vec2& point) const;
  // Closed to the planner: off the grid, or within growUnits of a touched cell.
  bool closed(const sim::Vec2& point) const;
  int touchedCount() const { return touchedCount_; }
  // Bumped by every change of a touched cell (a plan made at an older revision may be stale).
  std::uint64_t revision() const { return revision_; }

  // Shortest eight-connected path (octile costs, no corner cutting) over open cells from `from`
  // to `to`. A point on a closed cell starts (or ends) at the nearest open cell within
  // `snapUnits`. nullopt when no path exists or an end cannot be snapped (`snapFailed` tells
  // which: true when an end had no open cell near it, false when the search found no way).
  std::optional<TouchPlan> plan(const sim::Vec2& from, const sim::Vec2& to, double snapUnits = 80.0,
                                bool* snapFailed = nullptr) const;

  // The point of `plan` the robot at `from` should steer to: the farthest plan point up to
  // `reachUnits` along the plan whose straight segment from `from` crosses only open cells
  // (at least 40 units along the plan, or its end).
  sim::Vec2 lookAhead(const TouchPlan& plan, const sim::Vec2& from, double reachUnits) const;
  // The straight segment from a to b crosses only open cells once it has left the closed cells
  // round a (a robot beside a wall stands on closed cells).
  bool lineOpen(const sim::Vec2& a, const sim::Vec2& b) const;
  // Within nearUnits of a touched cell (or off the grid).
  bool near(const sim::Vec2& point) const;

  // Cell by cell (columns along x, rows along y, row 0 at the bottom), for pictures of the map.
  sim::Vec2 cellCentre(int col, int row) const { return centre(col, row); }
  bool cellTouched(int col, int row) const { return touched_[index(col, row)] != 0; }
  bool cellClosed(int col, int row) const { return closedBy_[index(col, row)] != 0; }

 private:
  int index(int col, int row) const { return row * cols_ + col; }
  bool cellOf(const sim::Vec2& p, int& col, int& row) const;
  sim::Vec2 centre(int col, int row) const;
  bool openCell(int col, int row) const;
  void grow(int col, int row, int delta);
  std::optional<int> snap(const sim::Vec2& p, double snapUnits) const;

  TouchMapConfig cfg_;
  double x0_ = 0.0;
  double y0_ = 0.0;
  int cols_ = 0;
  int rows_ = 0;
  std::vector<std::uint8_t> touched_;
  std::vector<std::uint16_t> closedBy_;        // how many touched cells close this one
  std::vector<std::uint16_t> nearBy_;          // how many touched cells lie within nearUnits
  std::vector<std::pair<int, int>> disc_;      // cell offsets within growUnits
  std::vector<std::pair<int, int>> nearDisc_;  // cell offsets within nearUnits
  int touchedCount_ = 0;
  std::uint64_t revision_ = 0;
  // Search scratch, reused between plans.
  mutable std::vector<double> cost_;
  mutable std::vector<int> parent_;
  mutable std::vector<std::uint32_t> seen_;
  mutable std::uint32_t stamp_ = 0;
};

}  // namespace tactile::nav
