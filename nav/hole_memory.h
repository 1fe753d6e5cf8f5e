// Holes remembered along the walls (thesis 5.3.2): each with its width and where the robot was by
// odometry when it measured it. A hole is seen on many steps while the robot passes it; readings
// whose openings lie within kMergeUnits of a remembered one on the same wall are the same hole,
// and its width is the mean of its readings.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "nav/navigator.h"

namespace tactile::nav {

class HoleMemory {
 public:
  static constexpr double kMergeUnits = 60.0;

  // Adds one reading; returns the index of the hole it went to.
  std::size_t observe(double widthUnits, const Pose2d& pose, const Vec2& centre, bool onLeft,
                      std::size_t step, int wall);
  // The widest hole of `wall` (any wall when wall < 0) not yet tried and wider than
  // minWidthUnits; ties go to the one found first. nullopt when there is none.
  std::optional<std::size_t> widestPassable(double minWidthUnits, int wall) const;
  void markTried(std::size_t index) { holes_[index].tried = true; }
  // Whether a hole that was tried lies within `radiusUnits` of `point`.
  bool nearTried(const Vec2& point, double radiusUnits) const;
  const std::vector<RememberedHole>& holes() const { return holes_; }
  void clear() {
    holes_.clear();
    readings_.clear();
  }

 private:
  std::vector<RememberedHole> holes_;
  std::vector<std::size_t> readings_;  // per hole, readings in its mean
};

}  // namespace tactile::nav
