// Internal to the navigator: the constants of chapter 5 and the state one Navigator::Impl keeps
// between steps, shared by its drivers, each in its own file: the chapter-5 strategies
// (navigator_strategies.cpp), Bug2 with a bumper (navigator_bug2.cpp) and plan drive
// (navigator_plan_drive.cpp). navigator.cpp senses, keeps the status and the touch map, and picks
// the driver each step; status_text.cpp names strategies, sources and statuses.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <numbers>

#include "analysis/hole_detection.h"
#include "nav/contact_status.h"
#include "nav/hole_memory.h"
#include "nav/navigator.h"
#include "sim/robot.h"

namespace tactile::nav {

constexpr double kPi = std::numbers::pi;

// A group reads as touching above this normal value (the filtered values decay through small
// values after a release).
constexpr double kTouching = 0.2;
// Check Contact / U Turn: back off this far from what is ahead before turning in place (the front
// corners sweep 115 units round the rear axle).
constexpr double kBackOffUnits = 25.0;
// Check Contact: after the front is clear, turn on by this "slight angle" before moving on.
constexpr double kCheckExtraTurn = 0.3;
// A concave corner (the followed side pressed above kPressedSide when something is ahead): back
// off kCornerBackUnits, then arc away on a radius of kCornerArcRadiusUnits through at most
// kCornerArcRadians.
constexpr double kPressedSide = 1.0;
constexpr double kCornerBackUnits = 90.0;
constexpr double kCornerArcRadiusUnits = 100.0;
constexpr double kCornerArcRadians = 1.2;
// Check Contact: moving on this far without the side finding the wall ends the episode.
constexpr double kCheckLostUnits = 250.0;
// Check Contact: move straight this far before arcing toward the wall.
constexpr double kCheckStraightUnits = 60.0;
// Check Contact: a side touching this many steps counts as followed even while its status is
// still undecided (a model may keep a side in a rare class).
constexpr int kCheckMaxSideSteps = 25;
// Go Straight: after the whole side has lost the wall, go on this far looking for its next
// fragment (a hole narrower than this is measured); beyond it the wall has ended.
constexpr double kGapProbeUnits = 10.0;
// Rounding a wall's end: the turn rate toward the wall (an arc of about 40 units at 0.6 cruise).
constexpr double kRoundTurnFraction = 0.9;
// Move Through Wall: the approach point lies this far from the wall, where turning in place to
// face the hole clears it; the hole is passed once the rear axle is this far beyond the wall.
constexpr double kApproachUnits = 150.0;
constexpr double kThroughUnits = 150.0;
// Leaving a wall toward the goal: the goal lies away from the wall (cosine of the angle between
// the goal direction and the direction into the wall below this) and this much closer than where
// the wall was hit.
constexpr double kLeaveCosine = -0.2;
constexpr double kLeaveGainUnits = 20.0;
// Circling: back within kReturnUnits of where following started after being kDepartUnits away.
constexpr double kDepartUnits = 250.0;
constexpr double kReturnUnits = 70.0;
// Loop detection: a hit this close to an earlier one after this much path is a loop; this many
// loops exhaust the walls.
constexpr double kLoopUnits = 100.0;
constexpr double kLoopPathUnits = 1500.0;
constexpr int kLoopsToGiveUp = 6;
// Blocked this many steps in a row: the escape moves are tried in turn.
constexpr int kEscapeAfter = 3;
// Wedged (at least kWedgedBlocked of the last kWedgedWindow steps blocked, the escape moves
// failing): the robot retraces its last kBacktrackSteps moves backward, each the exact inverse of
// a command that moved it, so each lands on a pose it has been in before.
constexpr int kWedgedWindow = 20;
constexpr int kWedgedBlocked = 10;
constexpr std::size_t kBacktrackSteps = 16;
constexpr std::size_t kBacktrackMemory = 64;
// Check Contact gives up after this many steps in a row.
constexpr int kCheckBudgetSteps = 300;
// Arrived by odometry without reaching the goal: the search spiral round it.
constexpr double kSearchPitchUnits = 80.0;
constexpr double kSearchRadiusUnits = 400.0;
// Plan drive's search: a spiral point counts as reached within kSearchReachUnits of the body
// centre and is passed over after kSearchPointSteps; the points lie kSearchSpacingUnits apart.
constexpr double kSearchReachUnits = 15.0;
constexpr std::size_t kSearchPointSteps = 150;
constexpr double kSearchSpacingUnits = 40.0;
// The touch map: replan at most every kReplanSteps steps when the map changed, and at least every
// kReplanIdleSteps; Head to Destination steers to the farthest plan point in sight up to
// kLookAheadUnits along the plan. The body clears touched cells within kClearUnits of three
// points on its axis (the odometry drifts; where the body is, nothing is).
constexpr std::size_t kReplanSteps = 5;
constexpr std::size_t kReplanIdleSteps = 20;
constexpr double kLookAheadUnits = 300.0;
constexpr double kClearUnits = 25.0;
// Following a wall with the touch map: leave it (the plan heads away from the wall) only after
// kMapLeaveUnits along it and with the plan's point in sight at least kMapLeaveClearUnits away
// (room to go); turn back (the plan heads back along the wall) after kMapReverseUnits.
constexpr double kMapLeaveUnits = 20.0;
constexpr double kMapLeaveClearUnits = 100.0;
constexpr double kMapReverseUnits = 60.0;
constexpr double kMapReverseCosine = -0.5;
// A map that finds no way is started afresh this many times before the run is unreachable (old
// touches may have drifted across a way that exists).
constexpr int kMapResets = 3;
// With the touch map, arrived by odometry and this many search spirals without the goal: the run
// ends as unreachable.
constexpr int kMapSearchRounds = 2;
// Plan drive: the touch map's cells and growth (as the experiment's: a 120-wide door keeps open
// cells) and the box round start and goal it covers (as the experiment's: with 1000 the only way
// round lay outside the box on maps where 2000 finds it; docs/navigation-bench.md).
constexpr double kDriveCellUnits = 20.0;
constexpr double kDriveGrowUnits = 40.0;
constexpr double kDriveMarginUnits = 2000.0;
// Plan drive: plan steps onto cells within kDriveNearUnits of a touched cell cost kDriveNearCost
// times their length, so the plan keeps a berth from what was touched where there is room.
constexpr double kDriveNearUnits = 110.0;
constexpr double kDriveNearCost = 3.0;
// Plan drive: the body clears touched cells within kDriveClearUnits of three points on its axis,
// kDriveClearInsetUnits in from its back, its middle and kDriveClearInsetUnits in from its front.
constexpr double kDriveClearUnits = 20.0;
constexpr double kDriveClearInsetUnits = 40.0;
// Plan drive: steer to the farthest plan point in clear sight up to this far along the plan;
// turn in place when it lies more than kDriveTurnRadians off the heading.
constexpr double kDriveLookAheadUnits = 150.0;
constexpr double kDriveTurnRadians = 0.5;
// Plan drive, at a contact ahead: back off kDriveBackUnits (kDriveBackMoreUnits more for every
// contact within kDriveRepeatUnits of the last one, up to kDriveBackMaxUnits), then replan.
constexpr double kDriveBackUnits = 20.0;
constexpr double kDriveBackMoreUnits = 15.0;
constexpr double kDriveBackMaxUnits = 80.0;
constexpr double kDriveRepeatUnits = 40.0;
// Plan drive: a front corner in contact is a contact ahead when a dome of it facing ahead touches:
// one whose outward normal lies within this cosine of the heading (each front corner has one dome
// 30 degrees off the heading and one 60 degrees off it); touched only on the other, it and the
// sides only ease the robot away.
constexpr double kAheadDomeCosine = 0.7071;
// Plan drive: a contact ahead with the goal within kGoalBehindUnits of the body centre and on a
// closed cell of the map starts the search round the goal.
// So does a contact ahead there that repeats the one before (within kDriveRepeatUnits) for the
// kGoalBehindRepeats-th time (the fourth contact in a row at one place).
constexpr double kGoalBehindUnits = 150.0;
constexpr int kGoalBehindRepeats = 3;
// Plan drive: the kFrontRepeats-th repeat of a contact ahead at one place (the third contact in a
// row there) marks the front edge across the body's width: the touching domes' marks have twice
// not turned the plan away, so what stops the robot there is wider than the points they felt.
constexpr int kFrontRepeats = 2;
// Bug2's bumper following: the arc back toward an obstacle no longer touched.
constexpr double kBumperArcUnits = 90.0;

inline Vec2 toVec(const Vec2d& v) {
  return Vec2(v.x, v.y);
}

inline double normalOf(const std::array<double, kValuesPerStep>& values, int sensor) {
  return values[static_cast<std::size_t>(normalOffset(sensor))];
}

inline double groupMax(const std::array<double, kValuesPerStep>& values, SensorGroup g) {
  return sim::groupMaxNormal(values, g);
}

struct Navigator::Impl {
  // Phases inside a strategy.
  enum class Phase { None, Back, Turn, Forward, Approach, Face, Enter };

  NavigatorConfig cfg;
  std::unique_ptr<StatusEstimator> estimator;
  std::array<DomePlacement, kSensorCount> domes;

  // What the robot knows.
  bool initialised = false;
  Pose2d odo;
  Vec2 goal = Vec2::Zero();
  Command last;
  double dt = 0.1;
  std::size_t stepIndex = 0;

  // What it shows.
  Strategy strategy = Strategy::HeadToDestination;
  std::array<ContactStatus, kGroupCount> status{};
  ContactStatus integrated;
  HoleMemory memory;
  std::optional<RunOutcome> finished;
  bool arrived = false;

  // The wall episode: from a hit while heading for the goal until the robot leaves it.
  int wall = -1;
  bool wallOnLeft = true;
  Vec2 hitPoint = Vec2::Zero();
  double hitGoalDistance = 0.0;
  double farFromHit = 0.0;
  bool following = false;  // the hit point counts from the first Follow Wall step

  // Loop detection over episodes (odometry): where walls were hit, with the goal distance there
  // and the odometry path length so far.
  struct Hit {
    Vec2 at = Vec2::Zero();
    double goalDistance = 0.0;
    double path = 0.0;
  };
  std::vector<Hit> hits;
  double pathUnits = 0.0;
  int loops = 0;
  std::optional<bool> sidePreference;

  // Phase state.
  Phase phase = Phase::None;
  int phaseSteps = 0;
  double phaseUnits = 0.0;  // distance covered in the phase (odometry)
  double turned = 0.0;      // radians turned in the phase (odometry, signed)
  bool frontCleared = false;
  bool pressedSide = false;
  Strategy previousStrategy = Strategy::HeadToDestination;
  int sameStrategySteps = 0;
  int sideSteps = 0;
  std::size_t checkStarts = 0;  // Check Contact back-offs started (checkContactStarts())

  // Gap tracking along the followed side.
  bool sideWasTouching = false;
  bool sideLost = false;
  Vec2 gapStart = Vec2::Zero();
  Vec2 lastRearTouch = Vec2::Zero();
  double lostUnits = 0.0;
  bool rounding = false;
  double roundTurned = 0.0;

  // Move Through Wall.
  std::optional<std::size_t> target;
  Vec2 holeCentre = Vec2::Zero();
  Vec2 inward = Vec2::UnitX();
  int failSteps = 0;

  // Escape from blocked steps.
  int blockedStreak = 0;
  double searchAngle = 0.0;  // along the search spiral round the goal
  int searchRounds = 0;      // spirals searched out to kSearchRadiusUnits
  int escapeIndex = 0;
  int escapeSteps = 0;
  Command escape;

  // Backtracking out of a wedge: the last commands that moved the robot, the newest last.
  std::deque<Command> moved;
  std::array<bool, kWedgedWindow> recentBlocked{};
  std::size_t backtrackLeft = 0;
  bool backtracking = false;  // the last command was a backtrack step

  // Bug2 (bumper source).
  Vec2 startPoint = Vec2::Zero();

  // The touch map and the plan on it.
  TouchMap touch;
  std::optional<TouchPlan> plan;
  std::uint64_t planRevision = 0;
  std::size_t planStep = 0;
  bool planned = false;
  bool noWay = false;
  bool noStart = false;  // the last plan failed to find an open cell near the robot
  // The last step Head to Destination turned in place with the map, and which way.
  std::size_t spinStep = static_cast<std::size_t>(-2);
  double spinOmega = 0.0;
  int mapResets = 0;
  double followedUnits = 0.0;  // along the wall since following started (odometry)
  bool reversing = false;      // a U turn back along the wall the plan asked for
  // Plan drive: how far to back off, where the last contact ahead was and how many in a row were
  // there, and the way the next turn in place must go (0: toward the plan).
  double driveBack = kDriveBackUnits;
  double driveAway = -1.0;  // -1: backing off a contact ahead; +1: moving forward off one behind
  Vec2 driveHitAt = Vec2(1e300, 1e300);
  int driveRepeats = 0;
  double driveSpin = 0.0;
  std::array<double, kSensorCount> previousNormal{};
  // Plan drive, searching round the goal: the spiral point it drives to and since when.
  std::optional<Vec2> searchAim;
  std::size_t searchAimStep = 0;

  const std::array<double, kValuesPerStep>* values = nullptr;

  double cruise() const { return cfg.cruiseUnitsPerSecond; }
  Vec2 position() const { return Vec2(odo.x, odo.y); }
  // +1 turns away from the followed wall (counter-clockwise when it is on the right).
  double away() const { return wallOnLeft ? -1.0 : 1.0; }

  // Side groups of the followed side, and its near front corner / far front corner.
  SensorGroup sideGroup() const { return wallOnLeft ? SensorGroup::Left : SensorGroup::Right; }

  bool planMode() const { return cfg.planDrive && cfg.source != StatusSource::Bumper; }
  // Where plans lead: the goal, or while plan drive searches round it the spiral point.
  Vec2 aim() const { return searchAim ? *searchAim : goal; }
  Vec2 bodyPoint(double x) const { return sim::bodyToWorld(odo, Vec2(x, 0.0)); }

  // Sensing, status, the touch map, motion primitives, escapes and the step that picks a driver
  // (navigator.cpp).
  void integrate(bool blocked);
  Vec2 domeWorld(int sensor) const;
  double sideMax() const;
  double aheadMax() const;
  double frontMax() const;
  double backMax() const;
  ContactStatus groupStatus(SensorGroup g) const;
  bool inContact(SensorGroup g) const;
  bool anyContact(std::initializer_list<SensorGroup> groups) const;
  bool cornerAhead(SensorGroup corner) const;
  void setStrategy(Strategy s, Phase p = Phase::None);
  void updateStatus(const Observation& obs);
  bool useMap() const;
  TouchMap freshMap() const;
  Vec2 bodyCentre() const;
  void updateMap(bool blocked);
  Vec2 contactPoint(int sensor) const;
  void updatePlan(bool force);
  Vec2 planTarget() const;
  std::optional<Vec2> planDirection() const;
  bool mapSaysUnreachable();
  ContactStatus integratedOf() const;
  Command headTo(const Vec2& target) const;
  Command searchGoal();
  Command nextEscape();
  Command step(const Observation& obs);
  Command choose();
  Command escapeMove();

  // The chapter-5 strategies and their wall episodes (navigator_strategies.cpp).
  void startEpisode();
  bool loopAtHit();
  void beginFollowing();
  bool mayLeave() const;
  Vec2 intoWall() const;
  bool mayReverse() const;
  Command reverse();
  bool circled();
  Command wallExhausted(bool needUTurn);
  void beginHole(std::size_t index);
  void failHole();
  Command headToDestination();
  Command checkContact();
  Command followWall();
  Command goStraight();
  Command uTurn();
  Command moveThroughWall();

  // Bug2 with a binary bumper (navigator_bug2.cpp).
  Command bug2();

  // Driving the touch map's plan (navigator_plan_drive.cpp).
  Command planDrive();
  bool goalBehindContact() const;
  Vec2 driveTarget() const;
  Command planSearch();
  Command driveBackOff();
};

}  // namespace tactile::nav
