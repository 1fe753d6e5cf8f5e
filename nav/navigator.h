// The chapter-5 navigator (docs/navigation.md, thesis ch. 5): a state machine over the strategies
// Go Straight, Head to Destination, Check Contact, Follow Wall, Move Through Wall and the two U
// turns, driven by the contact status of every sensor group and the holes found along the walls;
// or (plan drive, the default: NavigatorConfig::planDrive) by a plan on a map of where the robot
// touched things, backing off and replanning at each contact ahead.
//
// Stepped one simulator step at a time: step(observation) -> (v, omega). What it may know is what
// the thesis's robot knew: its own commands integrated over time (odometry, with blocked steps
// counted as no motion), the goal's position relative to the start, the blocked flag and the 88
// dome values. It never reads the scene, the simulator's pose or (except with
// StatusSource::Truth) the simulator's ground truth.
//
// Three status sources:
//  - Model:  each group's class from a trained model bundle with a causal (online) decision;
//  - Truth:  the simulator's ground truth per group (the ceiling);
//  - Bumper: a classic Bug2 that treats the skin as a binary bumper (the baseline).
// Deterministic: the same observations give the same commands, bit for bit.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/model_file.h"
#include "base/error.h"
#include "nav/touch_map.h"
#include "run/contact_class.h"
#include "run/robot_geometry.h"
#include "run/run.h"
#include "run/sensor_layout.h"
#include "sim/driver.h"
#include "sim/simulator.h"

namespace tactile::nav {

using sim::Command;
using sim::Vec2;

// The strategies of thesis 5.2, in the order of the experiment panel (5.3.1).
enum class Strategy : std::uint8_t {
  GoStraight,
  HeadToDestination,
  CheckContact,
  FollowWall,
  MoveThroughWall,
  RightUTurn,
  LeftUTurn,
};
inline constexpr int kStrategyCount = 7;
inline constexpr std::array<Strategy, kStrategyCount> kStrategies{
    Strategy::GoStraight, Strategy::HeadToDestination, Strategy::CheckContact,
    Strategy::FollowWall, Strategy::MoveThroughWall,   Strategy::RightUTurn,
    Strategy::LeftUTurn};
// Panel text: "Go Straight", "Head to Destination", ..., "Left U Turn".
std::string_view strategyTitle(Strategy strategy);
// File spelling (the x_strategy column): "GoStraight", "HeadToDestination", ..., "LeftUTurn".
std::string_view strategyKey(Strategy strategy);
std::optional<Strategy> parseStrategyKey(std::string_view key);

enum class StatusSource : std::uint8_t { Model, Truth, Bumper };
// "model", "truth", "bumper".
std::string_view statusSourceName(StatusSource source);
std::optional<StatusSource> parseStatusSource(std::string_view name);

// What a group (or the robot as a whole) is judged to touch: a contact class, a hole with its
// width (thesis 4.5), or undecided (the online decision has not settled yet).
enum class StatusKind : std::uint8_t {
  NoContact,
  Wall,
  Corner,
  LeavingWall,
  DeadPath,
  Hole,
  Undecided
};
struct ContactStatus {
  StatusKind kind = StatusKind::NoContact;
  double holeWidthUnits = 0.0;  // kind Hole only

  static ContactStatus of(ContactClass c);
  bool operator==(const ContactStatus&) const = default;
};
// "NoContact", "Wall", ..., "Hole(110)" (width rounded to a whole unit), "Undecided".
std::string statusText(const ContactStatus& status);
// Reads statusText's spellings back; nullopt for anything else.
std::optional<ContactStatus> parseStatusText(std::string_view text);

// A hole remembered along a wall: its width, where the robot was (odometry, in the world frame
// anchored at the start pose) when it measured it, and the middle of the opening there.
struct RememberedHole {
  double widthUnits = 0.0;
  Pose2d pose;                 // odometry pose at the measurement
  Vec2 centre = Vec2::Zero();  // middle of the opening, odometry frame
  bool onLeft = true;          // the side that found it
  std::size_t step = 0;        // step of the (last) measurement
  int wall = 0;                // which wall episode found it (counts from 0)
  bool tried = false;          // the robot went for it (a failed try is not tried again)
};

// Tunable constants; the defaults are the documented ones (docs/navigation.md).
struct NavigatorConfig {
  StatusSource source = StatusSource::Model;
  // Model source: the trained per-group classifiers (must outlive nothing: shared).
  std::shared_ptr<const analysis::ModelBundle> models;
  RobotGeometry geometry;
  double cruiseUnitsPerSecond = 50.0;
  double turnRadiansPerSecond = 0.8;         // turning in place
  double slightTurnRadiansPerSecond = 0.15;  // a follow-wall correction
  // Thesis 5.2: Move Through Wall needs a hole wider than this.
  double passableWidthUnits = 100.0;
  // The navigator stops (and waits for the referee) when its odometry puts it this close to the
  // goal.
  double arriveRadiusUnits = 30.0;
  // The touch map (docs/navigation.md#the-touch-map-experimental), opt-in: remember where the robot
  // touched things in the odometry frame and plan on it where Head to Destination heads, which side
  // to follow and when to leave a wall; the plan finding no way (after kMapResets fresh starts),
  // or two search spirals round the goal without reaching it once the odometry says it has
  // arrived, end the run as unreachable, replacing the loop rule and the return-point test. Off
  // (the default): the navigator as the figures in docs/navigation-bench.md give it. The bumper
  // Bug2 never uses it.
  bool touchMap = false;
  // Plan drive (docs/navigation.md#plan-drive), the default; implies the touch map: the robot
  // follows the map's plan with a path-tracking controller instead of following walls; at a
  // contact ahead it marks the touching domes' cells, backs off just enough to turn free and
  // replans. false: the thesis strategies (wall following, with or without `touchMap`). The
  // bumper Bug2 never uses it.
  bool planDrive = true;
  // Plan drive's odometry: a blocked step counts as this share of its command (the simulator stops
  // it somewhere along the way, where the robot cannot tell; half errs by at most half a step).
  // 0: no motion, as the thesis navigators count it (they always do).
  double blockedStepShare = 0.5;
};

// One step's input. The base holds what every driver sees (its `pose` is the simulator's and is
// never read here); `truth` is read only by StatusSource::Truth.
struct Observation : sim::Observation {
  const std::array<ContactClass, kGroupCount>* truth = nullptr;
};
// Where a dome touches, in the body frame, from its normal and shear values: the simulator pushes
// a dome back along the line from the touched point to its centre (docs/sim.md#dome-model), so
// the point lies in the direction n * normal - s * tangent (tangent: the normal turned a quarter
// counter-clockwise) from the centre, the dome radius less the push, sqrt(n^2 + s^2), away. A dome
// reading nothing gives the point a dome radius out along its normal.
Vec2 domeContactPoint(const DomePlacement& dome, double normalValue, double shearValue,
                      double domeRadiusUnits);

// The observation of the simulator's current step (values, blocked flag, truth).
Observation observe(const sim::Simulator& simulator, std::size_t step, const Pose2d& start,
                    const Vec2& goal);

class Navigator : public sim::Driver {
 public:
  // Fails when the model source has no models (or none for a side group it needs).
  static Result<std::unique_ptr<Navigator>> create(NavigatorConfig config);
  ~Navigator() override;
  Navigator(const Navigator&) = delete;
  Navigator& operator=(const Navigator&) = delete;

  // One step: updates the status of every group from the observation, the odometry from the
  // previous command, the hole memory, and the strategy; returns the command for this step.
  Command step(const Observation& observation);

  // sim::Driver: next() is step() without truth (the Truth source then sees no contact).
  std::string name() const override;
  Command next(const sim::Observation& observation) override;
  // Unreachable (the obstacle circled with no passable hole left), or nullopt while driving.
  // Timeout and success are the run loop's to say (navigate.h).
  std::optional<RunOutcome> finished() const override;

  const NavigatorConfig& config() const;
  Strategy strategy() const;
  // Per sensor group, in sensor-group order (side groups carry Hole(w) while one is measured).
  const std::array<ContactStatus, kGroupCount>& groupStatus() const;
  // The integrated status of the robot (thesis 5.3.1 "Status").
  ContactStatus integratedStatus() const;
  const std::vector<RememberedHole>& holes() const;
  // Odometry: the integrated commands, in the world frame anchored at the start pose.
  const Pose2d& odometry() const;
  // Check Contact episodes started so far (each back-off, also a restart within one).
  std::size_t checkContactStarts() const;
  // True once the odometry says the goal is reached.
  bool arrived() const;
  // The touch map (empty before the first step and for the bumper source or with touchMap off)
  // and the latest plan on it (nullopt when none was made or no way was found).
  const TouchMap& touchMap() const;
  const std::optional<TouchPlan>& plan() const;

 private:
  struct Impl;
  explicit Navigator(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tactile::nav
