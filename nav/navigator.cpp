#include "nav/navigator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <numbers>

#include "analysis/hole_detection.h"
#include "nav/contact_status.h"
#include "nav/hole_memory.h"
#include "sim/robot.h"

namespace tactile::nav {
namespace {

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

constexpr std::array<std::string_view, kStrategyCount> kTitles{
    "Go Straight",       "Head to Destination", "Check Contact", "Follow Wall",
    "Move through Wall", "Right U Turn",        "Left U Turn"};
constexpr std::array<std::string_view, kStrategyCount> kKeys{
    "GoStraight",      "HeadToDestination", "CheckContact", "FollowWall",
    "MoveThroughWall", "RightUTurn",        "LeftUTurn"};
constexpr std::array<std::string_view, 3> kSourceNames{"model", "truth", "bumper"};
constexpr std::array<std::string_view, 7> kKindNames{"NoContact", "Wall", "Corner",   "LeavingWall",
                                                     "DeadPath",  "Hole", "Undecided"};

Vec2 toVec(const Vec2d& v) {
  return Vec2(v.x, v.y);
}

double normalOf(const std::array<double, kValuesPerStep>& values, int sensor) {
  return values[static_cast<std::size_t>(normalOffset(sensor))];
}

double groupMax(const std::array<double, kValuesPerStep>& values, SensorGroup g) {
  return sim::groupMaxNormal(values, g);
}

}  // namespace

std::string_view strategyTitle(Strategy s) {
  return kTitles[static_cast<std::size_t>(s)];
}
std::string_view strategyKey(Strategy s) {
  return kKeys[static_cast<std::size_t>(s)];
}
std::optional<Strategy> parseStrategyKey(std::string_view key) {
  for (std::size_t i = 0; i < kKeys.size(); ++i)
    if (kKeys[i] == key) return static_cast<Strategy>(i);
  return std::nullopt;
}
std::string_view statusSourceName(StatusSource s) {
  return kSourceNames[static_cast<std::size_t>(s)];
}
std::optional<StatusSource> parseStatusSource(std::string_view name) {
  for (std::size_t i = 0; i < kSourceNames.size(); ++i)
    if (kSourceNames[i] == name) return static_cast<StatusSource>(i);
  return std::nullopt;
}

ContactStatus ContactStatus::of(ContactClass c) {
  return ContactStatus{static_cast<StatusKind>(c), 0.0};
}

std::string statusText(const ContactStatus& s) {
  if (s.kind == StatusKind::Hole) {
    const double w = std::isfinite(s.holeWidthUnits) ? std::round(s.holeWidthUnits) : 0.0;
    char buf[48];
    std::snprintf(buf, sizeof buf, "Hole(%.0f)", w == 0.0 ? 0.0 : w);
    return buf;
  }
  return std::string(kKindNames[static_cast<std::size_t>(s.kind)]);
}

std::optional<ContactStatus> parseStatusText(std::string_view text) {
  for (std::size_t i = 0; i < kKindNames.size(); ++i) {
    if (i == static_cast<std::size_t>(StatusKind::Hole)) continue;
    if (kKindNames[i] == text) return ContactStatus{static_cast<StatusKind>(i), 0.0};
  }
  if (text.size() > 6 && text.starts_with("Hole(") && text.ends_with(")")) {
    const std::string_view digits = text.substr(5, text.size() - 6);
    double w = 0.0;
    for (char c : digits) {
      if (c < '0' || c > '9') return std::nullopt;
      w = 10.0 * w + (c - '0');
    }
    return ContactStatus{StatusKind::Hole, w};
  }
  return std::nullopt;
}

Vec2 domeContactPoint(const DomePlacement& dome, double normalValue, double shearValue,
                      double domeRadiusUnits) {
  const Vec2 normal = toVec(dome.normal);
  const Vec2 tangent(-normal.y(), normal.x());
  const double push = std::hypot(normalValue, shearValue);
  if (!(push > 0.0) || !std::isfinite(push)) return toVec(dome.centre) + domeRadiusUnits * normal;
  const Vec2 towards = (normalValue * normal - shearValue * tangent) / push;
  return toVec(dome.centre) + std::max(domeRadiusUnits - push, 0.0) * towards;
}

Observation observe(const sim::Simulator& simulator, std::size_t step, const Pose2d& start,
                    const Vec2& goal) {
  Observation o;
  o.step = step;
  o.dtSeconds = simulator.config().dtSeconds;
  o.pose = simulator.pose();
  o.start = start;
  o.goal = goal;
  o.blocked = simulator.blocked();
  o.values = &simulator.sensors();
  o.truth = &simulator.truth();
  return o;
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

  void integrate(bool blocked) {
    if (blocked) {
      // The simulator ends a blocked step somewhere between its start and its end, where the
      // robot cannot tell. The thesis navigators count no motion; plan drive counts the share
      // cfg.blockedStepShare of the step (by default half: the estimate whose error is at most
      // half the step either way, where counting none may be wrong by the whole step).
      if (planMode() && cfg.blockedStepShare > 0.0) {
        odo = sim::integratePose(odo, cfg.blockedStepShare * last.v,
                                 cfg.blockedStepShare * last.omega, dt);
        odo.theta = sim::wrapAngle(odo.theta);
      }
      return;
    }
    if (!backtracking && (last.v != 0.0 || last.omega != 0.0)) {
      moved.push_back(last);
      if (moved.size() > kBacktrackMemory) moved.pop_front();
    }
    const double theta = odo.theta;
    odo = sim::integratePose(odo, last.v, last.omega, dt);
    odo.theta = sim::wrapAngle(odo.theta);
    phaseUnits += std::abs(last.v) * dt;
    pathUnits += std::abs(last.v) * dt;
    turned += sim::wrapAngle(odo.theta - theta);
    if (sideLost) lostUnits += std::abs(last.v) * dt;
    followedUnits += std::abs(last.v) * dt;
    if (rounding) roundTurned += std::abs(sim::wrapAngle(odo.theta - theta));
  }

  Vec2 domeWorld(int sensor) const {
    return sim::bodyToWorld(odo, toVec(domes[static_cast<std::size_t>(sensor)].centre));
  }

  // Side groups of the followed side, and its near front corner / far front corner.
  SensorGroup sideGroup() const { return wallOnLeft ? SensorGroup::Left : SensorGroup::Right; }
  double sideMax() const {
    using G = SensorGroup;
    return wallOnLeft
               ? std::max({groupMax(*values, G::Left), groupMax(*values, G::FrontLeftCorner),
                           groupMax(*values, G::RearLeftCorner)})
               : std::max({groupMax(*values, G::Right), groupMax(*values, G::FrontRightCorner),
                           groupMax(*values, G::RearRightCorner)});
  }
  // The front face and the far front corner (the near one touches while following).
  double aheadMax() const {
    using G = SensorGroup;
    return std::max(groupMax(*values, G::Front),
                    groupMax(*values, wallOnLeft ? G::FrontRightCorner : G::FrontLeftCorner));
  }
  double frontMax() const {
    using G = SensorGroup;
    return std::max({groupMax(*values, G::Front), groupMax(*values, G::FrontLeftCorner),
                     groupMax(*values, G::FrontRightCorner)});
  }
  double backMax() const {
    using G = SensorGroup;
    return std::max({groupMax(*values, G::Back), groupMax(*values, G::RearLeftCorner),
                     groupMax(*values, G::RearRightCorner)});
  }
  ContactStatus groupStatus(SensorGroup g) const {
    return status[static_cast<std::size_t>(groupIndex(g))];
  }
  // Plan drive: whether a group touches something is its status's to say (per the source: the
  // models' online decision, the simulator's truth); the readings only say where.
  bool inContact(SensorGroup g) const {
    const StatusKind k = groupStatus(g).kind;
    return k != StatusKind::NoContact && k != StatusKind::Undecided;
  }
  bool anyContact(std::initializer_list<SensorGroup> groups) const {
    return std::any_of(groups.begin(), groups.end(), [&](SensorGroup g) { return inContact(g); });
  }
  // A front corner in contact meets something ahead (rather than grazing it beside the robot)
  // when a dome of it facing ahead touches.
  bool cornerAhead(SensorGroup corner) const {
    if (!inContact(corner)) return false;
    const GroupInfo& info = groupInfo(corner);
    for (int s = info.firstSensor; s < info.firstSensor + info.sensorCount; ++s)
      if (domes[static_cast<std::size_t>(s)].normal.x > kAheadDomeCosine &&
          normalOf(*values, s) > 0.0)
        return true;
    return false;
  }

  void setStrategy(Strategy s, Phase p = Phase::None) {
    if (s == Strategy::CheckContact && p == Phase::Back &&
        !(strategy == Strategy::CheckContact && phase == Phase::Back))
      ++checkStarts;
    strategy = s;
    phase = p;
    phaseSteps = 0;
    phaseUnits = 0.0;
    turned = 0.0;
    frontCleared = false;
    sideSteps = 0;
    failSteps = 0;
  }

  // ---- status -------------------------------------------------------------------------------

  void updateStatus(const Observation& obs) {
    estimator->command(last.v, last.omega);
    const GroupClasses& classes = estimator->update(*obs.values, obs.truth);
    for (std::size_t g = 0; g < kGroupCount; ++g) {
      status[g] =
          classes[g] ? ContactStatus::of(*classes[g]) : ContactStatus{StatusKind::Undecided, 0.0};
    }
    // Holes on the long sides (thesis 4.5): two fragments of contact with free domes between.
    std::array<bool, kSensorCount> contact{};
    for (int s = 0; s < kSensorCount; ++s)
      contact[static_cast<std::size_t>(s)] = normalOf(*obs.values, s) > 0.0;
    for (const analysis::SideRange& side : analysis::kSides) {
      const bool left = side.firstSensor == analysis::kSides[1].firstSensor;
      const bool right = side.firstSensor == analysis::kSides[3].firstSensor;
      if (!left && !right) continue;
      const SensorGroup sideG = left ? SensorGroup::Left : SensorGroup::Right;
      const analysis::HoleScan scan =
          analysis::scanSide(contact, side.firstSensor, side.count, domes);
      if (scan.holes.empty()) continue;
      // The widest opening of the side; its width between the two bounding domes less one dome
      // slot (the domes next to the opening may sit a radius beyond its edges).
      const analysis::Hole* best = &scan.holes.front();
      for (const analysis::Hole& h : scan.holes)
        if (h.widthUnits > best->widthUnits) best = &h;
      const double width = 0.5 * (best->widthUnits + best->freeSpanUnits);
      status[static_cast<std::size_t>(groupIndex(sideG))] = ContactStatus{StatusKind::Hole, width};
      if (wall >= 0 && (strategy == Strategy::FollowWall || strategy == Strategy::GoStraight) &&
          left == wallOnLeft) {
        const Vec2 centre =
            0.5 * (domeWorld(best->lastSensorBefore) + domeWorld(best->firstSensorAfter));
        memory.observe(width, odo, centre, left, stepIndex, wall);
      }
    }
    // The rear-most dome of the followed side on the wall: where an opening starts once the whole
    // side has lost the wall.
    const int first = wallOnLeft ? 21 : 30;
    const int stepDir = wallOnLeft ? -1 : 1;
    for (int i = 0, s = first; i < 14; ++i, s += stepDir) {
      if (normalOf(*obs.values, s) > 0.0) {
        lastRearTouch = domeWorld(s);
        break;
      }
    }
    integrated = integratedOf();
  }

  // ---- the touch map ----------------------------------------------------------------------------

  bool useMap() const {
    return (cfg.touchMap || cfg.planDrive) && cfg.source != StatusSource::Bumper;
  }
  bool planMode() const { return cfg.planDrive && cfg.source != StatusSource::Bumper; }
  TouchMap freshMap() const {
    TouchMapConfig m;
    if (planMode()) {
      m.cellUnits = kDriveCellUnits;
      m.growUnits = kDriveGrowUnits;
      m.marginUnits = kDriveMarginUnits;
      m.nearUnits = kDriveNearUnits;
      m.nearCost = kDriveNearCost;
    }
    return TouchMap(startPoint, goal, m);
  }
  // Where plans lead: the goal, or while plan drive searches round it the spiral point.
  Vec2 aim() const { return searchAim ? *searchAim : goal; }
  Vec2 bodyPoint(double x) const { return sim::bodyToWorld(odo, Vec2(x, 0.0)); }
  Vec2 bodyCentre() const {
    return bodyPoint(0.5 * (cfg.geometry.frontX() + cfg.geometry.backX()));
  }

  // Touching domes of the groups whose status is a contact mark their cells (the touched surface
  // lies a dome radius out along the dome's normal); the body clears the cells it stands on.
  void updateMap(bool blocked) {
    if (!blocked) {
      // Plan drive clears well inside the body: a cell is up to half a cell diagonal from the
      // touch that marked it, and a mark ahead of the front must survive the back-off.
      const double radius = planMode() ? kDriveClearUnits : kClearUnits;
      const double inset = planMode() ? kDriveClearInsetUnits : kClearUnits;
      const double back = cfg.geometry.backX() + inset;
      const double front = cfg.geometry.frontX() - inset;
      for (double x : {back, 0.5 * (back + front), front})
        touch.clear(bodyPoint(x), radius);
    }
    for (int s = 0; s < kSensorCount; ++s) {
      // Plan drive: every reading dome of a group its status calls a contact marks; the thesis
      // strategies with the map: the domes above kTouching of such a group.
      if (normalOf(*values, s) <= (planMode() ? 0.0 : kTouching)) continue;
      const SensorGroup g = groupOfSensor(s);
      if (planMode() ? !inContact(g) : groupStatus(g).kind == StatusKind::NoContact) continue;
      // Plan drive: a reading that fell since the step before is a dome leaving what it touched
      // (or its value decaying after the release): where the dome is now is not where that is.
      if (planMode() && normalOf(*values, s) < previousNormal[static_cast<std::size_t>(s)])
        continue;
      const DomePlacement& d = domes[static_cast<std::size_t>(s)];
      // Plan drive: where the normal and shear values put the touch; otherwise a dome radius out
      // along the dome's normal.
      const Vec2 surface =
          planMode() ? contactPoint(s)
                     : Vec2(toVec(d.centre) + cfg.geometry.domeRadiusUnits * toVec(d.normal));
      touch.mark(sim::bodyToWorld(odo, surface));
    }
    for (int s = 0; s < kSensorCount; ++s)
      previousNormal[static_cast<std::size_t>(s)] = normalOf(*values, s);
  }

  Vec2 contactPoint(int sensor) const {
    return domeContactPoint(domes[static_cast<std::size_t>(sensor)], normalOf(*values, sensor),
                            (*values)[static_cast<std::size_t>(shearOffset(sensor))],
                            cfg.geometry.domeRadiusUnits);
  }

  // Replans when the map has changed (at most every kReplanSteps) or the plan is old; `force`
  // replans now. noWay: the search found no way from an open cell near the robot to the goal.
  void updatePlan(bool force) {
    if (!useMap()) return;
    const std::size_t age = stepIndex - planStep;
    if (!force && planned && !(touch.revision() != planRevision && age >= kReplanSteps) &&
        age < kReplanIdleSteps)
      return;
    bool snapFailed = false;
    plan = touch.plan(bodyCentre(), aim(), 80.0, &snapFailed);
    planned = true;
    planRevision = touch.revision();
    planStep = stepIndex;
    noWay = !plan && !snapFailed;
    noStart = !plan && snapFailed;
  }

  // Where Head to Destination heads: the plan's farthest point in sight, or the goal.
  Vec2 planTarget() const {
    if (!useMap() || !plan || plan->points.size() < 2) return goal;
    if (touch.lineOpen(bodyCentre(), goal)) return goal;  // nothing touched in the way
    const Vec2 p = touch.lookAhead(*plan, bodyCentre(), kLookAheadUnits);
    if ((p - plan->points.back()).norm() < 1e-9) return goal;
    return p;
  }

  // The direction of the plan from the robot (unit), or nullopt without a plan.
  std::optional<Vec2> planDirection() const {
    if (!useMap() || !plan || plan->points.size() < 2) return std::nullopt;
    const Vec2 d = planTarget() - bodyCentre();
    if (d.norm() < 1e-9) return std::nullopt;
    return d / d.norm();
  }

  // No way on the map: start it afresh (kMapResets times), then the goal is unreachable.
  bool mapSaysUnreachable() {
    if (!useMap() || !noWay) return false;
    if (mapResets < kMapResets) {
      ++mapResets;
      touch = freshMap();
      updatePlan(true);
      return noWay;
    }
    return true;
  }

  // The robot's status as the panel shows it: the followed side while following; otherwise the
  // most telling group (a hole, then a dead path, corner, leaving wall, wall).
  ContactStatus integratedOf() const {
    if (strategy == Strategy::FollowWall || strategy == Strategy::GoStraight) {
      const ContactStatus s = groupStatus(sideGroup());
      if (s.kind != StatusKind::NoContact) return s;
    }
    static constexpr std::array<StatusKind, 6> kOrder{StatusKind::Hole,   StatusKind::DeadPath,
                                                      StatusKind::Corner, StatusKind::LeavingWall,
                                                      StatusKind::Wall,   StatusKind::Undecided};
    for (StatusKind k : kOrder) {
      ContactStatus found{StatusKind::NoContact, 0.0};
      for (const ContactStatus& s : status)
        if (s.kind == k && (k != StatusKind::Hole || s.holeWidthUnits > found.holeWidthUnits))
          found = s;
      if (found.kind == k) return found;
    }
    return {};
  }

  // ---- motion primitives ----------------------------------------------------------------------

  Command headTo(const Vec2& target) const {
    const Vec2 d = target - position();
    const double err = sim::wrapAngle(std::atan2(d.y(), d.x()) - odo.theta);
    const double turn = cfg.turnRadiansPerSecond;
    if (std::abs(err) > 0.3) return {0.0, err > 0 ? turn : -turn};
    return {cruise(), std::clamp(1.5 * err, -turn, turn)};
  }

  // Arrived by odometry while the run goes on: the odometry has drifted (blocked steps). Search
  // round the goal on a spiral of pitch kSearchPitchUnits out to kSearchRadiusUnits (then again),
  // skipping ahead on the spiral at a contact. (Plan drive searches by its plans: planSearch.)
  Command searchGoal() {
    if (escapeSteps > 0) {
      --escapeSteps;
      return escape;
    }
    if (frontMax() > kTouching || blockedStreak > 0) {
      searchAngle += 0.8;
      escape = {-0.5 * cruise(), 0.0};
      escapeSteps = 4;
      return escape;
    }
    for (int i = 0; i < 200; ++i) {
      const double r = kSearchPitchUnits * searchAngle / (2.0 * kPi);
      if (r > kSearchRadiusUnits) {
        searchAngle = 0.0;
        // With the map: the goal was not found in kMapSearchRounds spirals round where the
        // odometry puts it. The odometry took the robot through what it touched (a closed ring
        // round the goal); the goal is unreachable.
        if (useMap() && ++searchRounds >= kMapSearchRounds) {
          finished = RunOutcome::Unreachable;
          return {};
        }
      }
      const Vec2 target = goal + r * Vec2(std::cos(searchAngle), std::sin(searchAngle));
      if ((target - position()).norm() > 25.0) return headTo(target);
      searchAngle += std::max(0.05, 20.0 / std::max(r, 20.0));
    }
    return {};
  }

  // Escape moves tried in turn after several blocked steps, each held a few steps: back, turn
  // either way, forward.
  Command nextEscape() {
    static constexpr std::array<std::array<double, 2>, 6> kMoves{
        {{-0.5, 0.0}, {0.0, 0.6}, {-0.4, -0.6}, {0.6, 0.0}, {0.0, -0.6}, {-0.4, 0.6}}};
    // Plan drive adds arcs about points of the rear axle's line close to the body (radius about
    // 20 and 40 units, forward and backward, either way): a robot wedged across a passage between
    // a front corner and the opposite rear corner frees both only by such a pivot.
    static constexpr std::array<std::array<double, 2>, 12> kDriveMoves{{{-0.5, 0.0},
                                                                        {0.0, 0.6},
                                                                        {-0.4, -0.6},
                                                                        {0.6, 0.0},
                                                                        {0.0, -0.6},
                                                                        {-0.4, 0.6},
                                                                        {0.2, 0.6},
                                                                        {-0.2, -0.6},
                                                                        {0.2, -0.6},
                                                                        {-0.2, 0.6},
                                                                        {0.4, 0.6},
                                                                        {0.4, -0.6}}};
    const auto& m = planMode()
                        ? kDriveMoves[static_cast<std::size_t>(escapeIndex++) % kDriveMoves.size()]
                        : kMoves[static_cast<std::size_t>(escapeIndex++) % kMoves.size()];
    // Turns are mirrored so the first turn goes away from the followed wall.
    escape = {m[0] * cruise(), m[1] * away() * cfg.turnRadiansPerSecond / 0.8 * 0.8};
    escapeSteps = 4;
    return escape;
  }

  // ---- episodes -------------------------------------------------------------------------------

  void startEpisode() {
    ++wall;
    using G = SensorGroup;
    // The wall goes on the side that touched first: front-left contact means turning right.
    double left = groupMax(*values, G::FrontLeftCorner) + groupMax(*values, G::Left);
    double right = groupMax(*values, G::FrontRightCorner) + groupMax(*values, G::Right);
    for (int s = 0; s < 8; ++s)
      (s < 4 ? right : left) += normalOf(*values, s);
    std::optional<double> planTurn;
    if (useMap()) {
      updatePlan(true);
      if (auto d = planDirection()) {
        const double err = sim::wrapAngle(std::atan2(d->y(), d->x()) - odo.theta);
        if (std::abs(err) > 0.05) planTurn = err;
      }
    }
    if (planTurn) {
      wallOnLeft = *planTurn < 0.0;  // the plan goes round to the right: the wall on the left
    } else if (sidePreference) {
      wallOnLeft = *sidePreference;
    } else if (left == right) {
      const Vec2 g = goal - position();
      const double err = sim::wrapAngle(std::atan2(g.y(), g.x()) - odo.theta);
      wallOnLeft = err < 0.0;  // turn toward the goal's side
    } else {
      wallOnLeft = left > right;
    }
    following = false;
    reversing = false;
    farFromHit = 0.0;
    hitGoalDistance = (goal - position()).norm();
    sideLost = false;
    rounding = false;
    sideWasTouching = false;
    setStrategy(Strategy::CheckContact, Phase::Back);
  }

  // A hit within kLoopUnits of an earlier one, no closer to the goal (by kLeaveGainUnits), after
  // kLoopPathUnits of odometry path: the robot is going round in a loop. Records the hit.
  bool loopAtHit() {
    const Vec2 p = position();
    const double d = (goal - p).norm();
    bool loop = false;
    for (const Hit& h : hits) {
      if ((p - h.at).norm() < kLoopUnits && pathUnits - h.path > kLoopPathUnits &&
          d > h.goalDistance - kLeaveGainUnits)
        loop = true;
    }
    if (loop) hits.clear();
    hits.push_back({p, d, pathUnits});
    return loop;
  }

  void beginFollowing() {
    if (!following) {
      following = true;
      hitPoint = position();
      farFromHit = 0.0;
      followedUnits = 0.0;
    }
    sideLost = false;
    rounding = false;
    setStrategy(Strategy::FollowWall);
  }

  // The goal lies away from the followed wall and closer than where the wall was hit. With the
  // touch map: the plan heads away from the wall.
  bool mayLeave() const {
    if (useMap() && plan) {
      const auto d = planDirection();
      if (!d || followedUnits < kMapLeaveUnits) return false;
      if ((planTarget() - bodyCentre()).norm() < kMapLeaveClearUnits) return false;
      return d->dot(intoWall()) < kLeaveCosine && aheadMax() <= kTouching;
    }
    const Vec2 g = goal - position();
    const double d = g.norm();
    if (d <= 0.0 || d > hitGoalDistance - kLeaveGainUnits) return false;
    const Vec2 into = wallOnLeft ? Vec2(-std::sin(odo.theta), std::cos(odo.theta))
                                 : Vec2(std::sin(odo.theta), -std::cos(odo.theta));
    return g.dot(into) / d < kLeaveCosine && aheadMax() <= kTouching;
  }

  // The unit direction from the robot into the followed wall.
  Vec2 intoWall() const {
    return wallOnLeft ? Vec2(-std::sin(odo.theta), std::cos(odo.theta))
                      : Vec2(std::sin(odo.theta), -std::cos(odo.theta));
  }

  // With the touch map: the plan heads back along the wall (behind the robot, not away from the
  // wall) after kMapReverseUnits of following: U turn, then head to the plan.
  bool mayReverse() const {
    if (!useMap() || !plan || followedUnits < kMapReverseUnits) return false;
    const auto d = planDirection();
    if (!d) return false;
    const Vec2 forward(std::cos(odo.theta), std::sin(odo.theta));
    return d->dot(forward) < kMapReverseCosine && d->dot(intoWall()) >= kLeaveCosine;
  }

  Command reverse() {
    target.reset();
    following = false;
    reversing = true;
    setStrategy(wallOnLeft ? Strategy::RightUTurn : Strategy::LeftUTurn, Phase::Back);
    return uTurn();
  }

  // Back where following started, having been away: the obstacle was walked round.
  bool circled() {
    if (!following || useMap()) return false;
    const double d = (position() - hitPoint).norm();
    farFromHit = std::max(farFromHit, d);
    return farFromHit > kDepartUnits && d < kReturnUnits;
  }

  // The wall is exhausted: go for the widest passable hole left, or give up.
  Command wallExhausted(bool needUTurn) {
    if (auto h = memory.widestPassable(cfg.passableWidthUnits, -1)) {
      beginHole(*h);
      // Back along the wall: following it again later starts a new circuit from there.
      following = false;
      if (needUTurn)
        setStrategy(wallOnLeft ? Strategy::RightUTurn : Strategy::LeftUTurn, Phase::Back);
      return {};
    }
    finished = RunOutcome::Unreachable;
    return {};
  }

  void beginHole(std::size_t index) {
    target = index;
    const RememberedHole& h = memory.holes()[index];
    holeCentre = h.centre;
    inward = h.onLeft ? Vec2(-std::sin(h.pose.theta), std::cos(h.pose.theta))
                      : Vec2(std::sin(h.pose.theta), -std::cos(h.pose.theta));
    setStrategy(Strategy::MoveThroughWall, Phase::Approach);
  }

  void failHole() {
    if (target) memory.markTried(*target);
    target.reset();
    setStrategy(Strategy::CheckContact, Phase::Back);
  }

  // ---- strategies -----------------------------------------------------------------------------

  Command headToDestination() {
    if (frontMax() > kTouching || blockedStreak > 0) {
      if (!useMap() && loopAtHit()) {
        // Hit again where it was hit before, no closer to the goal, after a long way round: a
        // loop. Follow walls on the other side from then on; at the kLoopsToGiveUp-th loop the
        // walls are exhausted (the widest passable hole left, or unreachable).
        if (++loops >= kLoopsToGiveUp) return wallExhausted(false);
        sidePreference = !wallOnLeft;
      }
      startEpisode();
      return checkContact();
    }
    Command c = headTo(planTarget());
    // With the map, turning in place toward the plan keeps the way it turned on the step before:
    // the body centre (the plan's start) moves as the robot turns, and the plan's target can flip
    // between the two ways round an obstacle from one step to the next; without this the robot
    // turns back and forth on the spot for the rest of its run.
    if (useMap() && c.v == 0.0 && c.omega != 0.0) {
      if (spinStep + 1 == stepIndex && (c.omega > 0.0) != (spinOmega > 0.0)) c.omega = spinOmega;
      spinStep = stepIndex;
      spinOmega = c.omega;
    }
    // A side brushing something while the way ahead is free: ease away from it.
    const double l = std::max(groupMax(*values, SensorGroup::Left),
                              groupMax(*values, SensorGroup::RearLeftCorner));
    const double r = std::max(groupMax(*values, SensorGroup::Right),
                              groupMax(*values, SensorGroup::RearRightCorner));
    if (c.v > 0.0 && l > kTouching && r <= kTouching) c.omega = -cfg.slightTurnRadiansPerSecond;
    if (c.v > 0.0 && r > kTouching && l <= kTouching) c.omega = cfg.slightTurnRadiansPerSecond;
    return c;
  }

  // Thesis 5.2 (3): back off what is ahead, turn away by a slight angle past a clear front, move
  // on arcing gently toward the wall until the side follows it (status Wall or Corner).
  Command checkContact() {
    ++phaseSteps;
    switch (phase) {
      case Phase::Back:
      case Phase::None:
        if (phase == Phase::None) setStrategy(Strategy::CheckContact, Phase::Back);
        if (phaseSteps == 1) pressedSide = sideMax() > kPressedSide;
        // Back off straight: a little from a wall met head-on, further from a concave corner
        // (the side pressed), where turning in place would swing the rear corner into the side.
        if (phaseUnits < (pressedSide ? kCornerBackUnits : kBackOffUnits) &&
            groupMax(*values, SensorGroup::Back) <= kTouching && blockedStreak < 2 &&
            phaseSteps < 40 &&
            (pressedSide || frontMax() > 0.5 || phaseUnits < 0.4 * kBackOffUnits)) {
          return {-0.5 * cruise(), 0.0};
        }
        setStrategy(Strategy::CheckContact, Phase::Turn);
        [[fallthrough]];
      case Phase::Turn: {
        if (blockedStreak >= 2) {
          setStrategy(Strategy::CheckContact, Phase::Back);
          pressedSide = true;
          return {-0.5 * cruise(), 0.0};
        }
        if (!frontCleared && aheadMax() <= 0.0 && frontMax() <= kTouching) {
          frontCleared = true;
          turned = 0.0;
        }
        if ((frontCleared && std::abs(turned) >= kCheckExtraTurn) ||
            (pressedSide && std::abs(turned) >= kCornerArcRadians)) {
          setStrategy(Strategy::CheckContact, Phase::Forward);
        } else {
          if (phaseSteps > 120) {  // turned round without clearing: a pocket
            setStrategy(Strategy::CheckContact, Phase::Forward);
          }
          // Beside a pressed side: an arc away (the rear corner swings out about a unit).
          if (pressedSide) {
            if (aheadMax() > kTouching) {
              setStrategy(Strategy::CheckContact, Phase::Back);
              return {-0.5 * cruise(), 0.0};
            }
            return {0.6 * cruise(), away() * 0.6 * cruise() / kCornerArcRadiusUnits};
          }
          return {0.0, away() * cfg.turnRadiansPerSecond};
        }
        [[fallthrough]];
      }
      case Phase::Forward: {
        if (aheadMax() > kTouching || blockedStreak >= 2) {
          setStrategy(Strategy::CheckContact, Phase::Back);
          return {-0.5 * cruise(), 0.0};
        }
        const double side = sideMax();
        if (side > 0.0) {
          ++sideSteps;
          const StatusKind k = groupStatus(sideGroup()).kind;
          if (k == StatusKind::Wall || k == StatusKind::Corner || k == StatusKind::Hole ||
              sideSteps >= kCheckMaxSideSteps) {
            beginFollowing();
            return followWall();
          }
          // Touching on the side but not yet judged: line up with the wall by the follow-wall
          // rule rather than arc on into it (the near front corner would hit it head on).
          switch (sim::followWallAction(*values, !wallOnLeft)) {
            case sim::FollowAction::Away:
              return {0.5 * cruise(), away() * 2.0 * cfg.slightTurnRadiansPerSecond};
            case sim::FollowAction::Toward:
              return {0.6 * cruise(), -away() * cfg.slightTurnRadiansPerSecond};
            case sim::FollowAction::Straight:
              return {0.6 * cruise(), 0.0};
          }
        }
        if (phaseUnits > kCheckLostUnits) {
          // Nothing found beside: the obstacle was small; head for the goal again.
          setStrategy(Strategy::HeadToDestination);
          return headTo(planTarget());
        }
        // Straight first (thesis: move straight, turn a slight angle when stopped); then arc
        // gently toward the wall side to find it.
        if (phaseUnits < kCheckStraightUnits) return {0.6 * cruise(), 0.0};
        return {0.6 * cruise(), -away() * 2.0 * cfg.slightTurnRadiansPerSecond};
      }
      default:
        break;
    }
    setStrategy(Strategy::CheckContact, Phase::Back);
    return {};
  }

  // Thesis 5.2 (4): keep the side on the wall with the 4 / 3 / 0.5 / 2 rule.
  Command followWall() {
    if (circled()) return wallExhausted(false);
    if (mayLeave()) {
      setStrategy(Strategy::HeadToDestination);
      return headTo(planTarget());
    }
    if (mayReverse()) return reverse();
    const StatusKind front = groupStatus(SensorGroup::Front).kind;
    if (aheadMax() > kTouching || front == StatusKind::DeadPath) {
      // The end of this wall: a wall ahead. With a passable hole behind, go back to the widest
      // one (thesis 5.3.2); else turn along the next wall.
      if (memory.widestPassable(cfg.passableWidthUnits, wall)) return wallExhausted(true);
      setStrategy(Strategy::CheckContact, Phase::Back);
      return checkContact();
    }
    if (blockedStreak > 0) return {0.0, away() * 0.5 * cfg.turnRadiansPerSecond};
    const double side = sideMax();
    const StatusKind s = groupStatus(sideGroup()).kind;
    if (side <= 0.0 || s == StatusKind::LeavingWall) {
      setStrategy(Strategy::GoStraight);
      return goStraight();
    }
    switch (sim::followWallAction(*values, !wallOnLeft)) {
      case sim::FollowAction::Away:
        return {0.7 * cruise(), away() * cfg.slightTurnRadiansPerSecond};
      case sim::FollowAction::Toward:
        return {0.8 * cruise(), -away() * cfg.slightTurnRadiansPerSecond};
      case sim::FollowAction::Straight:
        break;
    }
    return {cruise(), 0.0};
  }

  // Thesis 5.2 (1), used to cross what the side has lost (a hole, a door) while checking the
  // wall; the width of the opening is measured by odometry from the last dome on the wall before
  // it to the first dome on the wall after it.
  Command goStraight() {
    if (circled()) return wallExhausted(false);
    if (mayLeave()) {
      setStrategy(Strategy::HeadToDestination);
      return headTo(planTarget());
    }
    if (aheadMax() > kTouching) {
      if (memory.widestPassable(cfg.passableWidthUnits, wall)) return wallExhausted(true);
      setStrategy(Strategy::CheckContact, Phase::Back);
      return checkContact();
    }
    const double side = sideMax();
    // Re-contact after rounding a wall's end is the next face, not the far side of an opening.
    if (side > 0.0 && sideLost && !rounding) {
      // The next fragment: the opening between the last contact and this one.
      const int first = wallOnLeft ? 8 : 43;
      const int step = wallOnLeft ? 1 : -1;
      for (int i = 0, s = first; i < 14; ++i, s += step) {
        if (normalOf(*values, s) > 0.0) {
          const Vec2 end = domeWorld(s);
          memory.observe((end - gapStart).norm(), odo, 0.5 * (end + gapStart), wallOnLeft,
                         stepIndex, wall);
          break;
        }
      }
      sideLost = false;
      rounding = false;
    }
    if (side > 0.0) {
      if (groupStatus(sideGroup()).kind != StatusKind::LeavingWall) {
        beginFollowing();
        return followWall();
      }
      return {cruise(), 0.0};
    }
    if (!sideLost) {
      sideLost = true;
      lostUnits = 0.0;
      gapStart = lastRearTouch;
    }
    if (lostUnits > kGapProbeUnits || rounding) {
      // The wall has ended (or turned away): round its end, as a wall follower does.
      if (!rounding) {
        rounding = true;
        roundTurned = 0.0;
      }
      if (roundTurned > 2.0 * kPi) {
        setStrategy(Strategy::HeadToDestination);
        return headTo(planTarget());
      }
      return {0.6 * cruise(), -away() * kRoundTurnFraction * cfg.turnRadiansPerSecond};
    }
    return {cruise(), 0.0};
  }

  // Thesis 5.2 (6): turn 180 degrees away from the wall, after backing off what is ahead.
  Command uTurn() {
    ++phaseSteps;
    const double dir = strategy == Strategy::RightUTurn ? -1.0 : 1.0;
    if (phase == Phase::Back) {
      // Back off along the wall, then arc away from it before spinning: in place beside the wall
      // the rear corner would swing into it.
      if (phaseUnits < kCornerBackUnits && groupMax(*values, SensorGroup::Back) <= kTouching &&
          blockedStreak < 2 && phaseSteps < 40) {
        return {-0.5 * cruise(), 0.0};
      }
      phase = Phase::Forward;
      turned = 0.0;
    }
    if (phase == Phase::Forward) {
      if (std::abs(turned) < 0.6 && aheadMax() <= kTouching && blockedStreak < 2 &&
          phaseSteps < 80) {
        return {0.6 * cruise(), dir * 0.6 * cruise() / kCornerArcRadiusUnits};
      }
      phase = Phase::Turn;
    }
    if (std::abs(turned) >= kPi - 0.05 || phaseSteps > 250) {
      if (target) {
        const std::size_t t = *target;
        beginHole(t);
        return moveThroughWall();
      }
      if (reversing) {
        reversing = false;
        setStrategy(Strategy::HeadToDestination);
        return headTo(planTarget());
      }
      setStrategy(Strategy::CheckContact, Phase::Forward);
      return {};
    }
    if (blockedStreak >= 2) return {(phaseSteps / 4) % 2 ? 0.3 * cruise() : -0.3 * cruise(), 0.0};
    return {0.0, dir * cfg.turnRadiansPerSecond};
  }

  // Thesis 5.2 (5): go to a point in front of the remembered hole, face it, move through.
  Command moveThroughWall() {
    ++phaseSteps;
    const Vec2 approach = holeCentre - kApproachUnits * inward;
    const Vec2 through = holeCentre + kThroughUnits * inward;
    if (blockedStreak >= 3 ||
        (phase != Phase::Enter && groupMax(*values, SensorGroup::Front) > 1.0)) {
      if (++failSteps > 3 || phase == Phase::Enter) {
        failHole();
        return checkContact();
      }
    }
    if (phase == Phase::Approach) {
      if ((approach - position()).norm() < 12.0 || phaseSteps > 800) {
        phase = Phase::Face;
      } else {
        Command c = headTo(approach);
        const double l = std::max(groupMax(*values, SensorGroup::Left),
                                  groupMax(*values, SensorGroup::FrontLeftCorner));
        const double r = std::max(groupMax(*values, SensorGroup::Right),
                                  groupMax(*values, SensorGroup::FrontRightCorner));
        if (l > kTouching && r <= kTouching) c = {0.5 * cruise(), -cfg.turnRadiansPerSecond * 0.5};
        if (r > kTouching && l <= kTouching) c = {0.5 * cruise(), cfg.turnRadiansPerSecond * 0.5};
        return c;
      }
    }
    if (phase == Phase::Face) {
      const Vec2 d = through - position();
      const double err = sim::wrapAngle(std::atan2(d.y(), d.x()) - odo.theta);
      if (std::abs(err) > 0.04)
        return {0.0, err > 0 ? cfg.turnRadiansPerSecond : -cfg.turnRadiansPerSecond};
      phase = Phase::Enter;
      phaseUnits = 0.0;
    }
    // Enter: straight through, easing away from a jamb a front corner or a side touches.
    if ((position() - holeCentre).dot(inward) > kThroughUnits - 30.0) {
      if (target) memory.markTried(*target);
      target.reset();
      following = false;
      setStrategy(Strategy::HeadToDestination);
      return headTo(goal);
    }
    if (groupMax(*values, SensorGroup::Front) > 1.5 ||
        phaseUnits > 3.0 * kThroughUnits + kApproachUnits) {
      failHole();
      return checkContact();
    }
    using G = SensorGroup;
    const double l = std::max(groupMax(*values, G::FrontLeftCorner), groupMax(*values, G::Left));
    const double r = std::max(groupMax(*values, G::FrontRightCorner), groupMax(*values, G::Right));
    const Vec2 d = through - position();
    const double err = sim::wrapAngle(std::atan2(d.y(), d.x()) - odo.theta);
    double omega = std::clamp(err, -0.3, 0.3);
    if (l > kTouching && l > r) omega = -0.4;
    if (r > kTouching && r > l) omega = 0.4;
    return {0.5 * cruise(), omega};
  }

  // ---- Bug2 with a binary bumper ----------------------------------------------------------------

  Command bug2() {
    const bool front = frontMax() > 0.0;
    const bool side = sideMax() > 0.0;
    if (strategy == Strategy::HeadToDestination) {
      if (!front && blockedStreak == 0) return headTo(goal);
      ++wall;
      wallOnLeft = false;  // left-hand rule: keep the obstacle on the right, turn left
      hitGoalDistance = (goal - position()).norm();
      hitPoint = position();
      following = true;
      farFromHit = 0.0;
      setStrategy(Strategy::CheckContact, Phase::Back);
    }
    if (circled()) {
      finished = RunOutcome::Unreachable;
      return {};
    }
    // Leave on the start-goal line, closer than the hit point, the front free.
    const Vec2 line = goal - startPoint;
    const double len = line.norm();
    const Vec2 p = position();
    const double off = len > 0.0 ? std::abs(sim::cross2(line, p - startPoint)) / len : 0.0;
    if (strategy == Strategy::FollowWall && off < 15.0 &&
        (goal - p).norm() < hitGoalDistance - kLeaveGainUnits && !front) {
      setStrategy(Strategy::HeadToDestination);
      return headTo(goal);
    }
    if (strategy == Strategy::CheckContact) {
      ++phaseSteps;
      if (phase == Phase::Back) {
        if (phaseSteps <= 3 && !(backMax() > 0.0)) return {-0.5 * cruise(), 0.0};
        phase = Phase::Turn;
      }
      if (phase == Phase::Turn) {
        phase = Phase::Forward;
        turned = 0.0;
      }
      // Turn away until nothing ahead touches and the obstacle lies along the side.
      if (front || blockedStreak > 0 || (std::abs(turned) < 1.0 && !side))
        return {0.0, away() * cfg.turnRadiansPerSecond};
      setStrategy(Strategy::FollowWall);
      roundTurned = 0.0;
    }
    if (front || blockedStreak > 0) {
      setStrategy(Strategy::CheckContact, Phase::Back);
      return {-0.5 * cruise(), 0.0};
    }
    // Binary bumper following: touching -> veer away, free -> arc back toward the wall.
    if (side) {
      roundTurned = 0.0;
      return {0.8 * cruise(), away() * 2.0 * cfg.slightTurnRadiansPerSecond};
    }
    // Nothing beside: arc back toward the obstacle on a radius of kBumperArcUnits; a full circle
    // without meeting it again: it is lost, head for the goal.
    roundTurned += std::abs(0.6 * cruise() / kBumperArcUnits) * dt;
    if (roundTurned > 2.0 * kPi) {
      setStrategy(Strategy::HeadToDestination);
      return headTo(goal);
    }
    return {0.6 * cruise(), -away() * 0.6 * cruise() / kBumperArcUnits};
  }

  // ---- one step
  // -----------------------------------------------------------------------------------

  Command step(const Observation& obs) {
    values = obs.values;
    if (!initialised) {
      initialised = true;
      odo = obs.start;
      dt = obs.dtSeconds;
      estimator->setStepSeconds(dt);
      // The goal as the robot knows it: its offset from the start (thesis ch. 5: direction and
      // distance to the destination).
      goal = obs.goal;
      startPoint = Vec2(obs.start.x, obs.start.y);
      if (useMap()) touch = freshMap();
    } else {
      integrate(obs.blocked);
    }
    backtracking = false;
    stepIndex = obs.step;
    blockedStreak = obs.blocked ? blockedStreak + 1 : 0;
    recentBlocked[obs.step % kWedgedWindow] = obs.blocked;
    updateStatus(obs);
    if (useMap() && !finished) {
      updateMap(obs.blocked);
      updatePlan(false);
      if (!arrived && mapSaysUnreachable()) finished = RunOutcome::Unreachable;
    }
    if (finished) return last = Command{};
    if (!arrived && (goal - position()).norm() < cfg.arriveRadiusUnits) {
      arrived = true;
      searchAngle = 0.0;
      escapeSteps = 0;
    }
    if (arrived) {
      integrated = integratedOf();
      if (planMode()) {
        Command c = planSearch();
        if (finished) c = {};
        return last = c;
      }
      return last = searchGoal();
    }
    // A Check Contact that has not settled in kCheckBudgetSteps (a pocket it keeps backing out
    // of): leave it and head for the goal again; the next contact starts a new check.
    sameStrategySteps = strategy == previousStrategy ? sameStrategySteps + 1 : 0;
    previousStrategy = strategy;
    if (strategy == Strategy::CheckContact && sameStrategySteps > kCheckBudgetSteps &&
        cfg.source != StatusSource::Bumper) {
      setStrategy(Strategy::HeadToDestination);
      sameStrategySteps = 0;
      escapeSteps = 0;
      return last = nextEscape();
    }
    Command c = choose();
    if (finished) c = {};
    integrated = integratedOf();
    return last = c;
  }

  Command choose() {
    backtracking = false;
    if (backtrackLeft == 0 &&
        std::count(recentBlocked.begin(), recentBlocked.end(), true) >= kWedgedBlocked) {
      backtrackLeft = std::min(kBacktrackSteps, moved.size());
      recentBlocked.fill(false);
      escapeSteps = 0;
    }
    if (backtrackLeft > 0 && !moved.empty()) {
      --backtrackLeft;
      const Command undo{-moved.back().v, -moved.back().omega};
      moved.pop_back();
      backtracking = true;
      return undo;
    }
    backtrackLeft = 0;
    if (cfg.source == StatusSource::Bumper) {
      if (blockedStreak >= kEscapeAfter + 2 || escapeSteps > 0) return escapeMove();
      return bug2();
    }
    if (blockedStreak >= kEscapeAfter + 3 || escapeSteps > 0) return escapeMove();
    if (planMode()) return planDrive();
    switch (strategy) {
      case Strategy::HeadToDestination:
        return headToDestination();
      case Strategy::CheckContact:
        return checkContact();
      case Strategy::FollowWall:
        return followWall();
      case Strategy::GoStraight:
        return goStraight();
      case Strategy::RightUTurn:
      case Strategy::LeftUTurn:
        return uTurn();
      case Strategy::MoveThroughWall:
        return moveThroughWall();
    }
    return {};
  }

  // ---- plan drive -------------------------------------------------------------------------------

  // Follows the touch map's plan: Head to Destination while driving, Check Contact while backing
  // off a contact ahead.
  Command planDrive() {
    ++phaseSteps;
    if (strategy == Strategy::CheckContact) {
      // Moving off the contact: stopped by a contact or a blocked step the way it moves.
      const bool stop = driveAway < 0.0
                            ? anyContact({SensorGroup::Back, SensorGroup::RearLeftCorner,
                                          SensorGroup::RearRightCorner}) ||
                                  (blockedStreak > 0 && last.v < 0.0)
                            : anyContact({SensorGroup::Front, SensorGroup::FrontLeftCorner,
                                          SensorGroup::FrontRightCorner}) ||
                                  (blockedStreak > 0 && last.v > 0.0);
      if (phaseUnits < driveBack && !stop && phaseSteps < 60)
        return {driveAway * 0.5 * cruise(), 0.0};
      setStrategy(Strategy::HeadToDestination);
      updatePlan(true);
    }
    strategy = Strategy::HeadToDestination;
    using G = SensorGroup;
    const bool ahead = inContact(G::Front) || cornerAhead(G::FrontLeftCorner) ||
                       cornerAhead(G::FrontRightCorner) || (blockedStreak > 0 && last.v >= 0.0);
    if (ahead && !arrived && goalBehindContact()) {
      // As near as the odometry lets it come: search round the goal from here.
      arrived = true;
      searchAngle = 0.0;
      escapeSteps = 0;
      return planSearch();
    }
    if (ahead) return driveBackOff();
    if (noStart && !moved.empty()) {
      // Hemmed in on the map (no open cell near the robot to plan from): retrace the last moves
      // (each lands on a pose the robot has been in), then replan.
      driveRepeats = 0;
      noStart = false;
      driveSpin = 0.0;
      backtrackLeft = std::min(kBacktrackSteps, moved.size()) - 1;
      const Command undo{-moved.back().v, -moved.back().omega};
      moved.pop_back();
      backtracking = true;
      planned = false;
      return undo;
    }
    const Vec2 target = driveTarget();
    const Vec2 d = target - position();
    const double err = sim::wrapAngle(std::atan2(d.y(), d.x()) - odo.theta);
    const double turn = cfg.turnRadiansPerSecond;
    if (std::abs(err) > kDriveTurnRadians) {
      // Turning in place keeps the way it turned on the step before (the plan's target can flip
      // between the two ways round an obstacle as the body turns); after a contact while turning,
      // the other way.
      double omega = err > 0.0 ? turn : -turn;
      if (driveSpin != 0.0)
        omega = driveSpin;
      else if (spinStep + 1 == stepIndex)
        omega = spinOmega;
      spinStep = stepIndex;
      spinOmega = omega;
      return {0.0, omega};
    }
    driveSpin = 0.0;
    Command c{std::abs(err) < 0.2 ? cruise() : 0.6 * cruise(), std::clamp(2.0 * err, -turn, turn)};
    // A side or a front corner brushing something: ease away from it.
    const bool l = anyContact({G::Left, G::RearLeftCorner, G::FrontLeftCorner});
    const bool r = anyContact({G::Right, G::RearRightCorner, G::FrontRightCorner});
    const double ease = 2.0 * cfg.slightTurnRadiansPerSecond;
    if (l && !r) c.omega = std::min(c.omega, -ease);
    if (r && !l) c.omega = std::max(c.omega, ease);
    return c;
  }

  // A contact ahead with the goal (where the odometry puts it) close by and on cells closed by
  // what was touched: the goal lies at or behind the touched surface, where the robot cannot
  // stand; its odometry has drifted (or the goal is walled in).
  bool goalBehindContact() const {
    if ((goal - bodyCentre()).norm() > kGoalBehindUnits) return false;
    if (touch.closed(goal)) return true;
    // Or the contacts keep stopping the robot at one place there: as near as it comes.
    return (position() - driveHitAt).norm() < kDriveRepeatUnits &&
           driveRepeats + 1 >= kGoalBehindRepeats;
  }

  // The plan's farthest point in clear sight (or the goal when nothing touched is in the way).
  Vec2 driveTarget() const {
    if (!plan || plan->points.size() < 2) return aim();
    const Vec2 p = touch.lookAhead(*plan, bodyCentre(), kDriveLookAheadUnits);
    if ((p - plan->points.back()).norm() < 1e-9) return aim();
    return p;
  }

  // Plan drive, arrived by odometry while the run goes on: search round the goal on the spiral
  // (pitch kSearchPitchUnits, out to kSearchRadiusUnits) by driving to its points one after the
  // other on plans of the touch map, as to the goal. A point on a closed cell, one the plan finds
  // no way to, and one not reached in kSearchPointSteps steps are passed over; kMapSearchRounds
  // spirals without the goal end the run as unreachable.
  Command planSearch() {
    for (int i = 0; i < 2000; ++i) {
      const double r = kSearchPitchUnits * searchAngle / (2.0 * kPi);
      if (r > kSearchRadiusUnits) {
        searchAngle = 0.0;
        searchAim.reset();
        if (++searchRounds >= kMapSearchRounds) {
          finished = RunOutcome::Unreachable;
          return {};
        }
        continue;
      }
      const Vec2 point = goal + r * Vec2(std::cos(searchAngle), std::sin(searchAngle));
      const bool current = searchAim && (*searchAim - point).norm() < 1e-9;
      bool pass = (point - bodyCentre()).norm() < kSearchReachUnits || touch.closed(point);
      if (!pass && current)
        pass = (noWay && !noStart) || stepIndex - searchAimStep > kSearchPointSteps;
      if (!pass && !current) {
        searchAim = point;
        searchAimStep = stepIndex;
        updatePlan(true);
        pass = noWay && !noStart;
      }
      if (!pass) break;
      searchAngle += std::max(0.05, kSearchSpacingUnits / std::max(r, 20.0));
    }
    return choose();
  }

  // A contact ahead: its domes are marked (updateMap); back off, the further the more often the
  // robot meets something at the same place, then replan. A contact while turning in place makes
  // the next turn go the other way.
  Command driveBackOff() {
    const Vec2 p = position();
    driveRepeats = (p - driveHitAt).norm() < kDriveRepeatUnits ? driveRepeats + 1 : 0;
    driveHitAt = p;
    if (driveRepeats >= kFrontRepeats) {
      // Met here again and again: the marks so far leave the plan a line into it (a dome touching
      // a corner marks a point; the plan passes it within half a body width). Mark the front edge,
      // a dome radius out, from side to side.
      const double x = cfg.geometry.frontX() + cfg.geometry.domeRadiusUnits;
      const double w = cfg.geometry.halfWidth();
      const int n = static_cast<int>(std::ceil(2.0 * w / kDriveCellUnits));
      for (int i = 0; i <= n; ++i)
        touch.mark(sim::bodyToWorld(odo, Vec2(x, -w + 2.0 * w * i / n)));
    }
    driveBack = std::min(kDriveBackUnits + kDriveBackMoreUnits * driveRepeats, kDriveBackMaxUnits);
    if (last.v == 0.0 && last.omega != 0.0) driveSpin = -last.omega;
    // Off the contact: back off from what is ahead; forward from what the back alone touches (a
    // turn in place blocked by the back corners sweeping into a wall behind).
    using G = SensorGroup;
    driveAway = anyContact({G::Back, G::RearLeftCorner, G::RearRightCorner}) &&
                        !anyContact({G::Front, G::FrontLeftCorner, G::FrontRightCorner})
                    ? 1.0
                    : -1.0;
    setStrategy(Strategy::CheckContact, Phase::Back);
    ++phaseSteps;
    return {driveAway * 0.5 * cruise(), 0.0};
  }

  Command escapeMove() {
    if (escapeSteps > 0 && blockedStreak == 0) {
      --escapeSteps;
      return escape;
    }
    if (escapeSteps > 0 && blockedStreak > 0) escapeSteps = 0;
    if (blockedStreak >= kEscapeAfter) return nextEscape();
    escapeSteps = 0;
    return {};
  }
};

Result<std::unique_ptr<Navigator>> Navigator::create(NavigatorConfig config) {
  auto impl = std::make_unique<Impl>();
  switch (config.source) {
    case StatusSource::Model: {
      if (!config.models || config.models->models.empty())
        return Error("the model status source needs a trained model bundle");
      bool side = false;
      for (const analysis::GroupModel& m : config.models->models)
        side = side || m.group == SensorGroup::Left || m.group == SensorGroup::Right;
      if (!side) return Error("the model bundle has no model for the left or right side");
      impl->estimator = std::make_unique<ModelStatusEstimator>(config.models);
      break;
    }
    case StatusSource::Truth:
      impl->estimator = std::make_unique<TruthStatusEstimator>();
      break;
    case StatusSource::Bumper:
      impl->estimator = std::make_unique<BumperStatusEstimator>();
      break;
  }
  if (!(config.cruiseUnitsPerSecond > 0.0) || !(config.turnRadiansPerSecond > 0.0))
    return Error("speeds must be positive");
  impl->domes = domePlacements(config.geometry);
  impl->cfg = std::move(config);
  return std::unique_ptr<Navigator>(new Navigator(std::move(impl)));
}

Navigator::Navigator(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Navigator::~Navigator() = default;

Command Navigator::step(const Observation& observation) {
  return impl_->step(observation);
}

std::string Navigator::name() const {
  return impl_->cfg.source == StatusSource::Bumper
             ? std::string("bug2-bumper")
             : "navigator-" + std::string(statusSourceName(impl_->cfg.source));
}

Command Navigator::next(const sim::Observation& observation) {
  Observation o;
  static_cast<sim::Observation&>(o) = observation;
  return impl_->step(o);
}

std::optional<RunOutcome> Navigator::finished() const {
  return impl_->finished;
}
const NavigatorConfig& Navigator::config() const {
  return impl_->cfg;
}
Strategy Navigator::strategy() const {
  return impl_->strategy;
}
const std::array<ContactStatus, kGroupCount>& Navigator::groupStatus() const {
  return impl_->status;
}
ContactStatus Navigator::integratedStatus() const {
  return impl_->integrated;
}
const std::vector<RememberedHole>& Navigator::holes() const {
  return impl_->memory.holes();
}
const Pose2d& Navigator::odometry() const {
  return impl_->odo;
}
std::size_t Navigator::checkContactStarts() const {
  return impl_->checkStarts;
}
bool Navigator::arrived() const {
  return impl_->arrived;
}
const TouchMap& Navigator::touchMap() const {
  return impl_->touch;
}
const std::optional<TouchPlan>& Navigator::plan() const {
  return impl_->plan;
}

}  // namespace tactile::nav
