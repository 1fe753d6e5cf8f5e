// Ground truth per sensor group per step, from the geometry (rules in docs/sim.md#ground-truth).
//
// Inputs per step: for every dome, whether it touches an obstacle (raw, unfiltered) and the
// feature it touches: the interior of an edge, or a vertex (convex = sticking out into free
// space, concave, or flat = a nearly straight joint); and the recorded (filtered) values.
// Rules for group g at step k, first match wins:
//   1. NoContact   all recorded values of g are 0 (the same rule the classifiers use).
//   2. LeavingWall no dome of g touches anything any more, but values are still decaying
//                  (a decaying Corner or DeadPath keeps its class instead).
//   3. DeadPath    g is F, FLC, FRC, L or R and touches something, while the front edge F, the
//                  left side L and the right side R all touch: a pocket the robot can only back
//                  out of.
//   4. LeavingWall g was Wall within the last kLeavingWallSteps steps on edge e, touches nothing
//                  but e and its end vertices, and either touches a convex end vertex of e
//                  (sliding off the wall's end), or g was already LeavingWall at step k-1 and no
//                  more domes touch than then (sticky until the contact ends or grows again).
//                  Turning away from a wall shows as rule 2 once the domes are released.
//   5. Corner      g touches a convex or concave vertex, or two edges whose directions differ by
//                  more than kFlatVertexDegrees (a concave corner between walls).
//   6. Wall        otherwise: all contacts on one straight wall.
// Contact features come from the closest obstacle point of each dome (sim/simulator.h), so a
// dome sees one feature; a flat vertex (edges turning by less than kFlatVertexDegrees) counts as
// part of the wall.
#pragma once

#include <array>
#include <cstddef>

#include "run/contact_class.h"
#include "run/sensor_layout.h"

namespace tactile::sim {

class World;
struct PoseContact;

inline constexpr int kLeavingWallSteps = 20;

class TruthTracker {
 public:
  void reset();
  // Classifies step `contact` (raw) with recorded values `values` (kValuesPerStep).
  void update(const World& world, const PoseContact& contact, const double* values);
  const std::array<ContactClass, kGroupCount>& classes() const { return classes_; }

 private:
  struct GroupHistory {
    long long lastWallStep = -1000000;
    int wallEdge = -1;
    int wallCount = 0;
    int leavingCount = -1;  // domes touching at the last LeavingWall step; -1 when not leaving
  };
  std::array<ContactClass, kGroupCount> classes_{};
  std::array<GroupHistory, kGroupCount> history_{};
  long long step_ = 0;
};

}  // namespace tactile::sim
