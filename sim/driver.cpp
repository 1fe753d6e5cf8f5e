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

WallFollowDriver::WallFollowDriver(std::uint64_t seed) : rng_(seed) {
  cruise_ = 30.0 + 30.0 * unit(rng_);
  wallSide_ = unit(rng_) < 0.5 ? -1.0 : 1.0;
}

Command WallFollowDriver::next(const Observation& obs) {
  const auto& values = *obs.values;
  const Vec2 pos(obs.pose.x, obs.pose.y);
  const Vec2 toGoal = obs.goal - pos;
  const double goalDistance = toGoal.norm();
  const double front = std::max({groupMaxNormal(values, SensorGroup::Front),
                                 groupMaxNormal(values, SensorGroup::FrontLeftCorner),
                                 groupMaxNormal(values, SensorGroup::FrontRightCorner)});
  const bool wallOnRight = wallSide_ < 0.0;
  const double side = wallOnRight ? std::max({groupMaxNormal(values, SensorGroup::Right),
                                              groupMaxNormal(values, SensorGroup::FrontRightCorner),
                                              groupMaxNormal(values, SensorGroup::RearRightCorner)})
                                  : std::max({groupMaxNormal(values, SensorGroup::Left),
                                              groupMaxNormal(values, SensorGroup::FrontLeftCorner),
                                              groupMaxNormal(values, SensorGroup::RearLeftCorner)});
  const double away = -wallSide_;  // turn direction away from the wall
  blockedStreak_ = obs.blocked ? blockedStreak_ + 1 : 0;
  const double jitter = 0.1 * (unit(rng_) - 0.5);

  // Escape: after two blocked steps in a row, try the escape manoeuvres in turn (one per
  // blocked step); the first that moves is held for a few steps. Some direction is always free,
  // since the current pose is not blocked.
  if (obs.blocked && blockedStreak_ >= 2) {
    static constexpr std::array<std::array<double, 2>, 8> kEscapes{{{-0.5, 0.0},
                                                                    {-0.4, 1.0},
                                                                    {-0.4, -1.0},
                                                                    {0.0, 1.0},
                                                                    {0.0, -1.0},
                                                                    {0.4, 1.0},
                                                                    {0.4, -1.0},
                                                                    {-0.2, 0.0}}};
    const auto& e = kEscapes[escapeIndex_++ % kEscapes.size()];
    escape_ = {e[0] * cruise_, e[1] * away * 0.5};
    escapeSteps_ = 4 + static_cast<int>(4 * unit(rng_));
    if (mode_ == Mode::GoToGoal) {
      mode_ = Mode::Follow;
      hitDistance_ = goalDistance;
      followSteps_ = 0;
    }
    return escape_;
  }
  if (escapeSteps_ > 0) {
    --escapeSteps_;
    if (!obs.blocked) return escape_;
    escapeSteps_ = 0;
  }

  if (mode_ == Mode::GoToGoal) {
    if (front > 0.2 || obs.blocked) {
      mode_ = Mode::Follow;
      hitDistance_ = goalDistance;
      followSteps_ = 0;
    } else if (leaveSteps_ > 0) {
      --leaveSteps_;
      const double sideNow = side;
      // Drift away from the wall just left while moving clear.
      return {cruise_, sideNow > 0.0 ? away * 0.4 : 0.0};
    } else {
      const double heading = wrapAngle(std::atan2(toGoal.y(), toGoal.x()) - obs.pose.theta);
      if (std::abs(heading) > 0.35) return {0.0, heading > 0 ? 0.8 : -0.8};
      return {cruise_, 1.5 * heading + jitter};
    }
  }

  // Follow: keep the wall side lightly pressed (thesis 5.2 "follow wall").
  ++followSteps_;
  ++totalFollowSteps_;
  if (totalFollowSteps_ > 4000) gaveUp_ = true;
  // Leave the wall on the start-goal line, closer than the hit point, with a clear front.
  const Vec2 s(obs.start.x, obs.start.y);
  const Vec2 line = obs.goal - s;
  const double lineLength = line.norm();
  const double offLine =
      lineLength > 0.0 ? std::abs(cross2(line, pos - s)) / lineLength : goalDistance;
  if (followSteps_ > 20 && offLine < 20.0 && goalDistance < hitDistance_ - 30.0 && front == 0.0) {
    mode_ = Mode::GoToGoal;
    followSteps_ = 0;
    leaveSteps_ = 8;  // first move clear of the obstacle along the current heading
    return {cruise_, 0.0};
  }
  if (front > 0.2 || obs.blocked) return {0.0, away * 0.8};
  if (side == 0.0) return {0.6 * cruise_, -away * 0.7};  // lost the wall: curve back to it
  if (side > 3.0) return {0.7 * cruise_, away * 0.35 + jitter};
  if (side < 1.0) return {0.8 * cruise_, -away * 0.3 + jitter};
  return {cruise_, jitter};
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
  return {"random", "wall-follow"};
}

std::unique_ptr<Driver> makeDriver(std::string_view name, std::uint64_t seed) {
  if (name == "wall-follow") return std::make_unique<WallFollowDriver>(seed);
  if (name == "random") return std::make_unique<RandomDriver>(seed);
  if (name == "manual") return std::make_unique<ManualDriver>();
  return nullptr;
}

}  // namespace tactile::sim
