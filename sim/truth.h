// Ground truth per sensor group per step, from the geometry (rules in docs/sim.md#ground-truth).
//
// Inputs per step: the robot's pose, for every dome the obstacle edge it touches (raw, unfiltered)
// and whether its closest point is an end vertex, and the recorded (filtered) values. A dome
// "sits on" a vertex when its closest point is that vertex. Rules for group g at step k, first
// match wins:
//   1. NoContact   all recorded values of g are 0 (the same rule the classifiers use).
//   2. (tail)      no dome of g touches any more, values still decaying: the class g had at its
//                  last touching step (a released Wall stays Wall until the values reach 0).
//   3. DeadPath    g is F, FLC, FRC, L or R and touches, while F, L and R all touch: a pocket the
//                  robot can only back out of ("cannot move anywhere but retrace its steps").
//   4. Corner      two domes of g touch edge interiors whose directions differ by more than
//                  kFlatVertexDegrees (a concave corner).
//   5. LeavingWall g is L, R, RLC or RRC and touches only one wall e (and e's ends), e runs along
//                  the robot (within kFlatVertexDegrees of its heading), a convex end v of e has
//                  reached g's front-most touching dome (it sits on v, or v lies between it and
//                  the next dome of g ahead), and g's front-most dome is off the wall or on v.
//                  Entered from Wall when v moves rearward in the robot's frame while a dome of
//                  g is still on e's interior (sliding off forwards); kept while it holds and
//                  a dome of g is still on e's interior (a group left on the end alone feels a
//                  vertex: rule 6).
//   6. Corner      a dome of g sits on a non-flat vertex; or g was Corner and a non-flat end of
//                  an edge it touches lies within a dome radius of a touching dome's centre.
//   7. Wall        otherwise: all contacts on one straight wall.
// Then, over the whole run (smoothTruth), a segment shorter than kMinTruthSegmentSteps inside one
// contact episode of a group takes the class of the segment before it (the episode's first
// segment, if short, that of the segment after it).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "run/contact_class.h"
#include "run/robot_geometry.h"
#include "run/run.h"
#include "run/sensor_layout.h"

namespace tactile::sim {

class World;
struct PoseContact;

// Shorter segments within one contact episode are merged into the segment before them (a short
// first segment into the one after).
inline constexpr int kMinTruthSegmentSteps = 3;

class TruthTracker {
 public:
  explicit TruthTracker(const RobotGeometry& geometry = {});
  void reset();
  // Classifies the step whose raw contact at `pose` is `contact`, with recorded values `values`
  // (kValuesPerStep).
  void update(const World& world, const Pose2d& pose, const PoseContact& contact,
              const double* values);
  const std::array<ContactClass, kGroupCount>& classes() const { return classes_; }

 private:
  ContactClass touching(const World& world, const Pose2d& pose, const PoseContact& contact,
                        const GroupInfo& info, ContactClass previous) const;

  RobotGeometry geometry_;
  std::array<DomePlacement, kSensorCount> domes_;
  std::array<ContactClass, kGroupCount> classes_{};
  // The class each group had at its last step with a touching dome (for decay tails).
  std::array<ContactClass, kGroupCount> lastTouching_{};
  std::optional<Pose2d> previousPose_;
};

// Applies the merge rule to a run's truth (steps * kGroupCount classes, step-major as in
// RunData::truth): within each contact episode (maximal steps of one group not NoContact), a
// segment shorter than kMinTruthSegmentSteps that is not the episode's first takes the class of
// the segment before it; then a short first segment followed by another takes that one's class.
void smoothTruth(std::vector<ContactClass>& truth, std::size_t steps);

}  // namespace tactile::sim
