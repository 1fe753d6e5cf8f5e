// Counts over recorded runs that say whether the truth is usable for training: steps of each
// class per group, how often a group's class changes between two contact classes (flicker), and
// how many blocked steps recorded no contact at all (docs/sim.md#ground-truth).
#pragma once

#include <array>
#include <cstdint>

#include "run/contact_class.h"
#include "run/run.h"
#include "run/sensor_layout.h"

namespace tactile::sim {

struct TruthStats {
  // Steps of each class, per group (index by groupIndex, then by class value).
  std::array<std::array<std::int64_t, kContactClassCount>, kGroupCount> classSteps{};
  // Consecutive steps of one group whose classes are two different contact classes (a change
  // to or from NoContact is not counted).
  std::array<std::int64_t, kGroupCount> contactChanges{};
  std::int64_t steps = 0;
  std::int64_t blockedSteps = 0;
  std::int64_t blockedWithoutReadings = 0;  // blocked steps whose 88 values are all zero

  // Adds a run (its truth, if any, and its blocked flags and values).
  void add(const RunData& run);
  void merge(const TruthStats& other);

  std::int64_t contactSteps(SensorGroup g) const;
  // contactChanges per 100 contact steps of the group; 0 without contact.
  double changesPer100ContactSteps(SensorGroup g) const;
  // Share of blocked steps with all values zero; 0 without blocked steps.
  double blockedWithoutReadingsShare() const;
};

}  // namespace tactile::sim
