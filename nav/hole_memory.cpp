#include "nav/hole_memory.h"

namespace tactile::nav {

std::size_t HoleMemory::observe(double widthUnits, const Pose2d& pose, const Vec2& centre,
                                bool onLeft, std::size_t step, int wall) {
  for (std::size_t i = 0; i < holes_.size(); ++i) {
    RememberedHole& h = holes_[i];
    if (h.wall != wall || (h.centre - centre).norm() > kMergeUnits) continue;
    // Running means: width and centre over the readings.
    const double n = static_cast<double>(++readings_[i]);
    h.widthUnits += (widthUnits - h.widthUnits) / n;
    h.centre += (centre - h.centre) / n;
    h.pose = pose;
    h.step = step;
    return i;
  }
  RememberedHole h;
  h.widthUnits = widthUnits;
  h.pose = pose;
  h.centre = centre;
  h.onLeft = onLeft;
  h.step = step;
  h.wall = wall;
  holes_.push_back(h);
  readings_.push_back(1);
  return holes_.size() - 1;
}

std::optional<std::size_t> HoleMemory::widestPassable(double minWidthUnits, int wall) const {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < holes_.size(); ++i) {
    const RememberedHole& h = holes_[i];
    if (h.tried || h.widthUnits <= minWidthUnits) continue;
    if (wall >= 0 && h.wall != wall) continue;
    if (!best || h.widthUnits > holes_[*best].widthUnits) best = i;
  }
  return best;
}

bool HoleMemory::nearTried(const Vec2& point, double radiusUnits) const {
  for (const RememberedHole& h : holes_)
    if (h.tried && (h.centre - point).norm() < radiusUnits) return true;
  return false;
}

}  // namespace tactile::nav
