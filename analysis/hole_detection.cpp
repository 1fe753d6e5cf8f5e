#include "analysis/hole_detection.h"

#include <cmath>

namespace tactile::analysis {
namespace {

double distance(const Vec2d& a, const Vec2d& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

}  // namespace

HoleScan scanSide(const std::array<bool, kSensorCount>& contact, int firstSensor, int count,
                  const std::array<DomePlacement, kSensorCount>& placements) {
  HoleScan scan;
  if (count <= 0) return scan;
  if (count > kSensorCount) count = kSensorCount;
  auto sensorAt = [&](int i) {
    return ((firstSensor + i) % kSensorCount + kSensorCount) % kSensorCount;
  };
  bool inFragment = false;
  for (int i = 0; i < count; ++i) {
    const int s = sensorAt(i);
    if (contact[static_cast<std::size_t>(s)]) {
      if (!inFragment) scan.fragments.push_back({s, s});
      scan.fragments.back().lastSensor = s;
      inFragment = true;
    } else {
      inFragment = false;
    }
  }
  // Hole between fragment k-1 and k: width = |c(first of k) - c(last of k-1)| (thesis 4.5).
  for (std::size_t k = 1; k < scan.fragments.size(); ++k) {
    Hole hole;
    hole.lastSensorBefore = scan.fragments[k - 1].lastSensor;
    hole.firstSensorAfter = scan.fragments[k].firstSensor;
    hole.widthUnits = distance(placements[static_cast<std::size_t>(hole.lastSensorBefore)].centre,
                               placements[static_cast<std::size_t>(hole.firstSensorAfter)].centre);
    const int firstFree = (hole.lastSensorBefore + 1) % kSensorCount;
    const int lastFree = (hole.firstSensorAfter + kSensorCount - 1) % kSensorCount;
    hole.freeSpanUnits = distance(placements[static_cast<std::size_t>(firstFree)].centre,
                                  placements[static_cast<std::size_t>(lastFree)].centre);
    scan.holes.push_back(hole);
  }
  return scan;
}

std::array<bool, kSensorCount> sensorContacts(const RunData& run, std::size_t step,
                                              double thresholdUnits) {
  std::array<bool, kSensorCount> contact{};
  for (int s = 0; s < kSensorCount; ++s) {
    contact[static_cast<std::size_t>(s)] = run.normal(step, s) > thresholdUnits;
  }
  return contact;
}

std::vector<HoleScan> scanRun(const RunData& run, const SideRange& side,
                              const RobotGeometry& geometry, double thresholdUnits) {
  const auto placements = domePlacements(geometry);
  std::vector<HoleScan> out;
  out.reserve(run.stepCount());
  for (std::size_t t = 0; t < run.stepCount(); ++t) {
    out.push_back(
        scanSide(sensorContacts(run, t, thresholdUnits), side.firstSensor, side.count, placements));
  }
  return out;
}

}  // namespace tactile::analysis
