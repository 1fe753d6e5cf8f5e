#include "sim/driver.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/robot.h"

namespace tactile::sim {
namespace {

// Uniform double in [0, 1) from 53 random bits (portable, unlike std::uniform_real_distribution).
double unit(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// Escape manoeuvres tried in turn after blocked steps: (fraction of the cruise speed, turn rate in
// rad/s, positive away from the followed wall). Plain forward is one of them: after a blocked turn
// the way ahead is often the free one (a robot wedged at the edge of a hole).
struct EscapeMove {
  double speed;
  double turn;
};
constexpr std::array<EscapeMove, 8> kEscapes{{{-0.5, 0.0},
                                              {0.0, 0.5},
                                              {1.0, 0.0},
                                              {-0.4, 0.5},
                                              {-0.4, -0.5},
                                              {0.0, -0.5},
                                              {0.4, 0.5},
                                              {0.4, -0.5}}};

constexpr std::array<SensorGroup, 3> kRightSideGroups{
    SensorGroup::Right, SensorGroup::FrontRightCorner, SensorGroup::RearRightCorner};
constexpr std::array<SensorGroup, 3> kLeftSideGroups{
    SensorGroup::Left, SensorGroup::FrontLeftCorner, SensorGroup::RearLeftCorner};

// A slight follow-wall turn, rad/s, drawn per run in this range. A turn of w rad/s moves the front
// of the side sideways by about 9 w units per 0.1 s step; these keep that near 1 unit, small
// against the 2 units between the values that turn toward and away.
constexpr double kSlightTurnMin = 0.1;
constexpr double kSlightTurnMax = 0.15;
// Turn rate, rad/s, that curves back to a wall the side no longer touches (round its end).
constexpr double kLostWallTurn = 0.7;
// Front values: above kTouchingFront something is there; above kPressedFront it is pressed.
constexpr double kTouchingFront = 0.2;
constexpr double kPressedFront = 1.5;
// Leaving the wall: within kLeaveLineUnits of the start-goal line and at least kLeaveGainUnits
// closer to the goal than at the hit point. The robot then arcs away from the wall on a radius of
// kLeaveArcRadiusUnits through kLeaveArcRadians before heading for the goal: turning in place next
// to the wall swings the rear corner into it, and heading for the goal at once re-touches a round
// obstacle and circles it.
constexpr double kLeaveLineUnits = 20.0;
constexpr double kLeaveGainUnits = 30.0;
constexpr double kLeaveArcRadiusUnits = 150.0;
constexpr double kLeaveArcRadians = 0.5;
// Concave corners and pockets: a wall ahead while the followed side (behind its front corner)
// reads above kCornerSideValue, or being blocked with both sides touching, starts a back-off of
// kCornerBackUnits (or until something touches behind), then an arc away from the wall of radius
// kCornerArcRadiusUnits through at most kCornerArcRadians. Turning in place needs about 7 units of
// clearance at the rear corner, more than following leaves; on this arc the rear corner swings out
// by about 1 unit.
constexpr double kCornerSideValue = 1.0;
constexpr double kCornerBackUnits = 90.0;
constexpr double kCornerArcRadiusUnits = 100.0;
constexpr double kCornerArcRadians = 1.2;
// Speeds of the back-off and of the arc, as fractions of the cruise speed.
constexpr double kBackSpeed = 0.5;
constexpr double kArcSpeed = 0.6;

// Steps to cover `units` at `speed` units/s.
int stepsFor(double units, double speed, double dtSeconds) {
  return static_cast<int>(std::ceil(units / (speed * std::max(dtSeconds, 1e-3))));
}

// Largest normal value of any of the groups.
template <class... Groups>
double maxNormal(const std::array<double, kValuesPerStep>& values, Groups... groups) {
  return std::max({groupMaxNormal(values, groups)...});
}

}  // namespace

double groupMaxNormal(const std::array<double, kValuesPerStep>& values, SensorGroup g) {
  const GroupInfo& info = groupInfo(g);
  double m = 0.0;
  for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
    m = std::max(m, values[normalOffset(d)]);
  }
  return m;
}

Command ManualDriver::next(const Observation&) {
  std::lock_guard lock(mutex_);
  if (queue_.empty()) return {};
  Command c = queue_.front().first;
  if (--queue_.front().second <= 0) queue_.pop_front();
  return c;
}

void ManualDriver::push(Command command, int steps) {
  if (steps <= 0) return;
  std::lock_guard lock(mutex_);
  queue_.emplace_back(command, steps);
}

void ManualDriver::clear() {
  std::lock_guard lock(mutex_);
  queue_.clear();
}

std::size_t ManualDriver::pending() const {
  std::lock_guard lock(mutex_);
  return queue_.size();
}

FollowAction followWallAction(const std::array<double, kValuesPerStep>& values, bool wallOnRight) {
  const auto& groups = wallOnRight ? kRightSideGroups : kLeftSideGroups;
  double largest = 0.0;
  double sum = 0.0;
  int touching = 0;
  for (SensorGroup g : groups) {
    const GroupInfo& info = groupInfo(g);
    for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d) {
      const double n = values[normalOffset(d)];
      largest = std::max(largest, n);
      if (n > 0.0) {
        sum += n;
        ++touching;
      }
    }
  }
  const double mean = touching > 0 ? sum / touching : 0.0;
  if (largest > kFollowAwayMax || mean > kFollowAwayMean) return FollowAction::Away;
  if (largest < kFollowTowardMax || mean < kFollowTowardMean) return FollowAction::Toward;
  return FollowAction::Straight;
}

struct WallFollowDriver::Touch {
  double ahead = 0.0;       // front face and the far front corner
  double anyFront = 0.0;    // front face and both front corners
  double side = 0.0;        // followed side with both its corners (the follow-wall groups)
  double sideBehind = 0.0;  // followed side and its rear corner
  double farSide = 0.0;     // the other side and its front corner
  double behind = 0.0;      // back and the far rear corner
};

WallFollowDriver::Touch WallFollowDriver::readTouch(
    const std::array<double, kValuesPerStep>& values, bool wallOnRight) {
  using G = SensorGroup;
  const G near = wallOnRight ? G::Right : G::Left;
  const G nearFront = wallOnRight ? G::FrontRightCorner : G::FrontLeftCorner;
  const G nearRear = wallOnRight ? G::RearRightCorner : G::RearLeftCorner;
  const G far = wallOnRight ? G::Left : G::Right;
  const G farFront = wallOnRight ? G::FrontLeftCorner : G::FrontRightCorner;
  const G farRear = wallOnRight ? G::RearLeftCorner : G::RearRightCorner;
  Touch t;
  t.ahead = maxNormal(values, G::Front, farFront);
  t.anyFront = std::max(t.ahead, groupMaxNormal(values, nearFront));
  t.sideBehind = maxNormal(values, near, nearRear);
  t.side = std::max(t.sideBehind, groupMaxNormal(values, nearFront));
  t.farSide = maxNormal(values, far, farFront);
  t.behind = maxNormal(values, G::Back, farRear);
  return t;
}

WallFollowDriver::WallFollowDriver(std::uint64_t seed) : WallFollowDriver(seed, Options{}) {}

WallFollowDriver::WallFollowDriver(std::uint64_t seed, Options options)
    : options_(std::move(options)), rng_(seed), switchesLeft_(options_.sideSwitches) {
  cruise_ = 30.0 + 30.0 * unit(rng_);
  wallSide_ = unit(rng_) < 0.5 ? -1.0 : 1.0;
  if (options_.side) wallSide_ = *options_.side == FollowSide::Right ? -1.0 : 1.0;
  turn_ = kSlightTurnMin + (kSlightTurnMax - kSlightTurnMin) * unit(rng_);
}

namespace {

WallFollowDriver::Options bugOptions() {
  WallFollowDriver::Options o;
  o.name = "bug";
  o.giveUpSteps = BugDriver::kGiveUpSteps;
  o.sidePerObstacle = true;
  o.sideSwitches = 1;
  return o;
}

WallFollowDriver::Options withSide(WallFollowDriver::Options o, std::optional<FollowSide> side) {
  o.side = side;
  return o;
}

}  // namespace

BugDriver::BugDriver(std::uint64_t seed, std::optional<FollowSide> side)
    : WallFollowDriver(seed, withSide(bugOptions(), side)) {}

std::string_view followSideName(FollowSide side) {
  return side == FollowSide::Left ? "left" : "right";
}

std::optional<FollowSide> parseFollowSide(std::string_view name) {
  if (name == "left") return FollowSide::Left;
  if (name == "right") return FollowSide::Right;
  return std::nullopt;
}

std::optional<RunOutcome> WallFollowDriver::finished() const {
  if (unreachable_) return RunOutcome::Unreachable;
  if (gaveUp_) return RunOutcome::GaveUp;
  return std::nullopt;
}

void WallFollowDriver::startFollowing(double goalDistance) {
  mode_ = Mode::Follow;
  if (options_.sidePerObstacle) {
    wallSide_ = unit(rng_) < 0.5 ? -1.0 : 1.0;
    if (options_.side) wallSide_ = *options_.side == FollowSide::Right ? -1.0 : 1.0;
    switchesLeft_ = options_.sideSwitches;
  }
  hitPointSet_ = false;
  hitDistance_ = goalDistance;
  farFromHitUnits_ = 0.0;
  followSteps_ = 0;
}

Command WallFollowDriver::escape() {
  const EscapeMove& e = kEscapes[escapeIndex_++ % kEscapes.size()];
  escape_ = {e.speed * cruise_, e.turn * -wallSide_};
  escapeSteps_ = 4 + static_cast<int>(4 * unit(rng_));
  return escape_;
}

Command WallFollowDriver::backOffThenArc(const Observation& obs) {
  backSteps_ = stepsFor(kCornerBackUnits, kBackSpeed * cruise_, obs.dtSeconds);
  arcing_ = true;
  arcStartTheta_ = obs.pose.theta;
  return {-kBackSpeed * cruise_, 0.0};
}

Command WallFollowDriver::headForGoal(const Observation& obs, const Vec2& toGoal) {
  if (leaveSteps_ > 0) {
    --leaveSteps_;
    // Blocked arcing away: the rear corner met the wall just left. Turning away in place frees
    // it more often than going straight on (measured over the built-in scenes).
    if (obs.blocked) return {0.0, -wallSide_ * 0.5};
    return {cruise_, -wallSide_ * cruise_ / kLeaveArcRadiusUnits};
  }
  const double jitter = 0.1 * (unit(rng_) - 0.5);
  const double heading = wrapAngle(std::atan2(toGoal.y(), toGoal.x()) - obs.pose.theta);
  if (std::abs(heading) > 0.35) return {0.0, heading > 0 ? 0.8 : -0.8};
  return {cruise_, 1.5 * heading + jitter};
}

Command WallFollowDriver::next(const Observation& obs) {
  if (gaveUp_ || unreachable_) return {};
  const auto& values = *obs.values;
  const Vec2 pos(obs.pose.x, obs.pose.y);
  const Vec2 toGoal = obs.goal - pos;
  const double goalDistance = toGoal.norm();
  const Touch touch = readTouch(values, wallOnRight());
  blockedStreak_ = obs.blocked ? blockedStreak_ + 1 : 0;

  // Every step after the first contact counts toward giving up, whatever the driver is doing.
  if (!contacted_) {
    contacted_ =
        obs.blocked || std::any_of(values.begin(), values.end(), [](double x) { return x != 0.0; });
  } else if (++stepsSinceContact_ >= options_.giveUpSteps) {
    gaveUp_ = true;
    return {};
  }

  // Back where following this obstacle started, having been away: it has been walked round and
  // the start-goal line never crossed closer to the goal (Bug-2: the goal is unreachable).
  if (mode_ == Mode::Follow && hitPointSet_) {
    const double fromHit = (pos - hitPoint_).norm();
    farFromHitUnits_ = std::max(farFromHitUnits_, fromHit);
    if (farFromHitUnits_ > kHitDepartUnits && fromHit < kHitReturnUnits) {
      if (switchesLeft_ <= 0) {
        unreachable_ = true;
        return {};
      }
      // Follow the obstacle the other way round from here: the robot turns away from the wall
      // it now has on the other side, and the hit point is taken again once it touches.
      --switchesLeft_;
      wallSide_ = -wallSide_;
      hitPointSet_ = false;
      farFromHitUnits_ = 0.0;
      followSteps_ = 0;
    }
  }

  // Escape: after two blocked steps in a row, try the escape manoeuvres in turn (one per blocked
  // step); the first that moves is held for a few steps.
  if (obs.blocked && blockedStreak_ >= 2) {
    if (mode_ == Mode::GoToGoal) startFollowing(goalDistance);
    return escape();
  }
  if (escapeSteps_ > 0) {
    --escapeSteps_;
    if (!obs.blocked) return escape_;
    escapeSteps_ = 0;
  }

  if (mode_ == Mode::GoToGoal) {
    // While moving clear of the wall just left, the side and the near corner still brush it:
    // not a new hit.
    if (leaveSteps_ > 0 && touch.ahead <= kTouchingFront) return headForGoal(obs, toGoal);
    if (touch.anyFront <= kTouchingFront) {
      if (!obs.blocked) return headForGoal(obs, toGoal);
      // Blocked with nothing ahead: a turn toward the goal swung the rear or a side into the
      // wall just left. Moving on along the heading clears it; it is not a new obstacle.
      return {cruise_, 0.0};
    }
    startFollowing(goalDistance);
  }
  return follow(obs, touch, pos, goalDistance);
}

Command WallFollowDriver::follow(const Observation& obs, const Touch& touch, const Vec2& pos,
                                 double goalDistance) {
  const double away = -wallSide_;  // turn direction away from the wall
  ++followSteps_;
  // Leave the wall on the start-goal line, closer than the hit point, with a clear front.
  const Vec2 s(obs.start.x, obs.start.y);
  const Vec2 line = obs.goal - s;
  const double lineLength = line.norm();
  const double offLine =
      lineLength > 0.0 ? std::abs(cross2(line, pos - s)) / lineLength : goalDistance;
  if (followSteps_ > 20 && offLine < kLeaveLineUnits &&
      goalDistance < hitDistance_ - kLeaveGainUnits && touch.ahead == 0.0) {
    mode_ = Mode::GoToGoal;
    backSteps_ = 0;
    arcing_ = false;
    leaveSteps_ = stepsFor(kLeaveArcRadiusUnits * kLeaveArcRadians, cruise_, obs.dtSeconds);
    return headForGoal(obs, obs.goal - pos);
  }

  // A corner manoeuvre in progress: back off straight, then arc away.
  if (backSteps_ > 0) {
    --backSteps_;
    if (!obs.blocked && touch.behind <= kTouchingFront) return {-kBackSpeed * cruise_, 0.0};
    backSteps_ = 0;
  }
  if (arcing_) {
    const double turned = std::abs(wrapAngle(obs.pose.theta - arcStartTheta_));
    if (touch.ahead > kTouchingFront || obs.blocked || turned > kCornerArcRadians) {
      arcing_ = false;
    } else {
      return {kArcSpeed * cruise_, away * kArcSpeed * cruise_ / kCornerArcRadiusUnits};
    }
  }
  // Squeezed between the followed wall and something on the far side (a pocket, or a passage
  // narrower than the robot's turn): back out, then arc away.
  if (obs.blocked && touch.farSide > kTouchingFront && touch.sideBehind > kTouchingFront) {
    return backOffThenArc(obs);
  }
  if (touch.ahead > kTouchingFront) {
    // A wall ahead and the followed wall pressed: a concave corner.
    if (touch.sideBehind > kCornerSideValue) return backOffThenArc(obs);
    // Turning in place swings the near front corner forward into what is ahead, so back off
    // while turning when already pressed.
    if (touch.ahead > kPressedFront || obs.blocked) return {-0.3 * cruise_, away * 0.6};
    return {0.0, away * 0.8};
  }
  // Blocked by the side alone: pressed too hard, ease off the wall.
  if (obs.blocked) return {0.0, away * 0.5};
  if (!hitPointSet_ && touch.side > 0.0) {
    // Where following starts: the rear axle is then at its following distance from the wall, as
    // it will be when it comes round again (at the first touch it may be a body length away).
    hitPoint_ = pos;
    hitPointSet_ = true;
  }
  switch (followWallAction(*obs.values, wallOnRight())) {
    case FollowAction::Away:
      return {0.7 * cruise_, away * turn_};
    case FollowAction::Toward:
      // A side that touches nothing has lost the wall (e.g. at its end): curve back round it.
      if (touch.side == 0.0) return {0.6 * cruise_, -away * kLostWallTurn};
      return {0.8 * cruise_, -away * turn_};
    case FollowAction::Straight:
      break;
  }
  return {cruise_, 0.0};
}

RandomDriver::RandomDriver(std::uint64_t seed) : rng_(seed) {}

double RandomDriver::uniform(double lo, double hi) {
  return lo + (hi - lo) * unit(rng_);
}

Command RandomDriver::next(const Observation& obs) {
  if (obs.blocked) {
    current_ = {-current_.v * 0.5 + uniform(-5.0, 5.0), uniform(-1.0, 1.0)};
    remaining_ = 3 + static_cast<int>(uniform(0.0, 5.0));
  } else if (remaining_ <= 0) {
    current_ = {uniform(-20.0, 60.0), uniform(-1.0, 1.0)};
    remaining_ = 5 + static_cast<int>(uniform(0.0, 26.0));
  }
  --remaining_;
  return current_;
}

std::vector<std::string> autonomousDriverNames() {
  return {"bug", "random", "wall-follow"};
}

std::unique_ptr<Driver> makeDriver(std::string_view name, std::uint64_t seed,
                                   std::optional<FollowSide> side) {
  if (!side) return makeDriver(name, seed);
  if (name == "wall-follow") {
    WallFollowDriver::Options o;
    o.side = side;
    return std::make_unique<WallFollowDriver>(seed, o);
  }
  if (name == "bug") return std::make_unique<BugDriver>(seed, side);
  return nullptr;
}

std::unique_ptr<Driver> makeDriver(std::string_view name, std::uint64_t seed) {
  if (name == "wall-follow") return std::make_unique<WallFollowDriver>(seed);
  if (name == "bug") return std::make_unique<BugDriver>(seed);
  if (name == "random") return std::make_unique<RandomDriver>(seed);
  if (name == "manual") return std::make_unique<ManualDriver>();
  return nullptr;
}

}  // namespace tactile::sim
