// Hole detection (thesis 4.5): along a side of the robot, contacted sensors form fragments; the
// space between two fragments is a hole, and its width is the distance between the last sensor of
// one fragment and the first sensor of the next.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "run/robot_geometry.h"
#include "run/run.h"
#include "run/sensor_layout.h"

namespace tactile::analysis {

// A run of consecutive contacted sensors, by sensor index (inclusive).
struct ContactFragment {
  int firstSensor = 0;
  int lastSensor = 0;
};

// The gap between two consecutive fragments.
struct Hole {
  int lastSensorBefore = 0;  // last sensor of the earlier fragment
  int firstSensorAfter = 0;  // first sensor of the later fragment
  // Thesis 4.5: |c_after - c_before|, distance between the two dome centres (scene units). The
  // obstacle edges lie between these two domes, so this bounds the opening from above.
  double widthUnits = 0.0;
  // Span of the free domes in between, |c_last_free - c_first_free| (0 for a single free dome): a
  // lower bound on the opening.
  double freeSpanUnits = 0.0;
};

struct HoleScan {
  std::vector<ContactFragment> fragments;
  std::vector<Hole> holes;  // fragments.size() - 1 entries (none with fewer than 2 fragments)
};

// Scans sensors firstSensor .. firstSensor + count - 1 (indices taken modulo kSensorCount, so a
// side may run across index 43 -> 0) for fragments of contact; `contact[i]` says whether sensor i
// touches. Positions come from `placements` (domePlacements()).
HoleScan scanSide(const std::array<bool, kSensorCount>& contact, int firstSensor, int count,
                  const std::array<DomePlacement, kSensorCount>& placements);

// Contact of every sensor at a step: n > thresholdUnits (thesis: any non-zero normal deflection).
std::array<bool, kSensorCount> sensorContacts(const RunData& run, std::size_t step,
                                              double thresholdUnits = 0.0);

// Sides used for hole detection: a straight edge together with its two corner groups, as index
// ranges (front: FRC+F+FLC, left: FLC+L+RLC, back: RLC+B+RRC, right: RRC+R+FRC).
struct SideRange {
  const char* name;
  int firstSensor;
  int count;
};
inline constexpr std::array<SideRange, 4> kSides{{
    {"front", 42, 12},  // 42, 43, 0..7, 8, 9
    {"left", 8, 14},    // 8..21
    {"back", 20, 12},   // 20..31
    {"right", 30, 14},  // 30..43
}};

// Holes on one side at every step of a run: result[t] is the scan of step t.
std::vector<HoleScan> scanRun(const RunData& run, const SideRange& side,
                              const RobotGeometry& geometry = {}, double thresholdUnits = 0.0);

}  // namespace tactile::analysis
