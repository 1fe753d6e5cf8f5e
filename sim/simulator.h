// The simulator: robot body with 44 compliant domes in a World, stepping (v, omega) commands with
// the dome contact model, the blocked rule and no tunnelling (docs/domain.md#dome-model,
// thesis 2.1, 2.2, 2.4).
#pragma once

#include <array>
#include <limits>
#include <memory>
#include <vector>

#include "run/robot_geometry.h"
#include "sim/robot.h"
#include "sim/truth.h"
#include "sim/world.h"

namespace tactile::sim {

// Commands are clamped to these (a safety net: the sub-step count grows with speed).
inline constexpr double kMaxSpeedUnits = 3000.0;  // units/s
inline constexpr double kMaxTurnRate = 20.0;      // rad/s

struct SimConfig {
  RobotGeometry geometry;
  double dtSeconds = 0.1;
  // Time constant c/k of the dome's spring-damper; 0 passes the raw displacement straight through.
  double filterTauSeconds = 0.03;
  // Largest motion of any body point between two collision checks within a step (no tunnelling).
  double maxSubstepUnits = 1.0;
  // Filtered values of a released dome below this are recorded as exactly 0 (1% of full
  // compression), so a released dome reads zero within a few steps.
  double zeroBelowUnits = 0.05;
  // false: test every edge of the scene (the brute-force reference of the spatial index).
  bool useIndex = true;
};

// What one dome sees at one pose, before filtering.
struct DomeContact {
  double normal = 0.0;  // compression along the inward normal, 0..5
  double shear = 0.0;   // displacement along the counter-clockwise tangent, -5..5
  int edge = -1;        // closest edge within reach, -1 for none (no contact)
  int vertex = -1;      // the global vertex id when the closest point is an edge end, else -1
};

// Contact of the whole robot at one pose.
struct PoseContact {
  bool blocked = false;  // body overlaps an obstacle, or a dome would be compressed past 5
  std::array<DomeContact, kSensorCount> domes{};
  double clearanceUnits = std::numeric_limits<double>::infinity();  // body outline to nearest edge
};

class Simulator {
 public:
  Simulator(std::shared_ptr<const World> world, SimConfig config = {});

  // Puts the robot at `pose` with relaxed domes; returns false (and keeps the old state) when the
  // pose is blocked.
  bool reset(const Pose2d& pose);

  // One step of dt: tries to move by (v, omega) (non-finite values count as 0; clamped to
  // kMaxSpeedUnits and kMaxTurnRate). If a sub-pose along the way is blocked, the robot stops at
  // the last free sub-pose before it (blocked() true; the pose is kept when even the first
  // sub-pose is blocked). Then the dome values are filtered toward the raw contact at the
  // resulting pose and the ground truth is updated.
  void step(double v, double omega);

  // Raw contact at an arbitrary pose (does not change the state).
  PoseContact evaluate(const Pose2d& pose);
  // Just the blocked rule at a pose (faster than evaluate).
  bool isBlocked(const Pose2d& pose);

  const Pose2d& pose() const { return pose_; }
  bool blocked() const { return blocked_; }
  std::size_t stepIndex() const { return steps_; }
  // Filtered values n0, s0, ..., n43, s43 of the current step.
  const std::array<double, kValuesPerStep>& sensors() const { return sensors_; }
  const std::array<ContactClass, kGroupCount>& truth() const { return truth_.classes(); }
  const PoseContact& contact() const { return contact_; }
  const World& world() const { return *world_; }
  const SimConfig& config() const { return config_; }
  // Bound on how far any body point moves during one step of (v, omega):
  //   M = (|v| + |omega| R) dt, R = largest distance of the outline from the rear axle.
  double motionBound(double v, double omega) const;

 private:
  void gatherCandidates(const Pose2d& pose, double reach);
  void evaluateInto(const Pose2d& pose, PoseContact& out);
  bool blockedAt(const Pose2d& pose);
  void transformCandidates(const Pose2d& pose);

  std::shared_ptr<const World> world_;
  SimConfig config_;
  std::array<DomePlacement, kSensorCount> domes_;
  Vec2 innerLo_, innerHi_;  // the body is this box grown by the corner radius
  double cornerRadius_ = 0.0;
  double outlineRadius_ = 0.0;  // largest distance of an outline point from the rear axle

  Pose2d pose_;
  bool blocked_ = false;
  std::size_t steps_ = 0;
  std::array<double, kValuesPerStep> sensors_{};
  PoseContact contact_;
  TruthTracker truth_;

  // Scratch reused every step (no allocation in the step loop).
  EdgeQueryScratch scratch_;
  std::vector<int> candidates_;
  std::vector<Vec2> bodyA_, bodyB_;
};

}  // namespace tactile::sim
