// Drivers turn what the robot senses into (v, omega) commands, one per step. The simulator loop
// (sim/recorder.h) asks the driver, steps, records. A new strategy (e.g. the thesis chapter-5
// navigator that classifies contacts with trained models) is one more Driver subclass; it sees
// exactly what a real robot would: its pose estimate, the blocked flag, the 88 dome values and
// the goal.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "run/run.h"
#include "run/sensor_layout.h"
#include "sim/geometry.h"

namespace tactile::sim {

struct Command {
  double v = 0.0;      // forward speed, units/s
  double omega = 0.0;  // turn rate, rad/s (counter-clockwise positive)
};

// What a driver may look at before choosing the next command.
struct Observation {
  std::size_t step = 0;  // index of the step about to be taken
  double dtSeconds = 0.1;
  Pose2d pose;
  Pose2d start;
  Vec2 goal = Vec2::Zero();
  bool blocked = false;                                        // the previous step was cancelled
  const std::array<double, kValuesPerStep>* values = nullptr;  // filtered n0, s0, ... (never null)
};

class Driver {
 public:
  virtual ~Driver() = default;
  // Recorded as the run's `subject` and `driver` metadata.
  virtual std::string name() const = 0;
  virtual Command next(const Observation& obs) = 0;
  // True once the driver has given up (the run then ends with outcome `gave-up`).
  virtual bool gaveUp() const { return false; }
  // How the driver ended the run on its own, or nullopt while it is still driving. The run loop
  // stops on the first step this is set. Defaults to `gave-up` when gaveUp() is true.
  virtual std::optional<RunOutcome> finished() const {
    return gaveUp() ? std::optional<RunOutcome>(RunOutcome::GaveUp) : std::nullopt;
  }
};

// Largest normal value of a group.
double groupMaxNormal(const std::array<double, kValuesPerStep>& values, SensorGroup g);

// A command queue the GUI fills: each entry is held for a number of steps; an empty queue
// gives (0, 0). push() may be called from another thread.
class ManualDriver : public Driver {
 public:
  std::string name() const override { return "manual"; }
  Command next(const Observation& obs) override;
  void push(Command command, int steps = 1);
  void clear();
  std::size_t pending() const;

 private:
  mutable std::mutex mutex_;
  std::deque<std::pair<Command, int>> queue_;
};

// Follow-wall rule of thesis 5.2 on the followed side's domes (the side group and its two corner
// groups; normal values, upper bound 5): turn away from the wall when the largest value is above
// kFollowAwayMax or the mean of the touching (non-zero) values is above kFollowAwayMean; turn
// toward it when the largest is below kFollowTowardMax or that mean is below kFollowTowardMean
// (so a side that touches nothing turns toward the wall); otherwise go straight.
enum class FollowAction { Away, Toward, Straight };
inline constexpr double kFollowAwayMax = 4.0;
inline constexpr double kFollowAwayMean = 3.0;
inline constexpr double kFollowTowardMax = 0.5;
inline constexpr double kFollowTowardMean = 2.0;
FollowAction followWallAction(const std::array<double, kValuesPerStep>& values, bool wallOnRight);

// The side of the robot on which a wall follower keeps the wall.
enum class FollowSide { Left, Right };
// "left", "right".
std::string_view followSideName(FollowSide side);
std::optional<FollowSide> parseFollowSide(std::string_view name);

// Bug-2 style explorer: heads for the goal; on touching something, follows the wall by touch on a
// side chosen from the seed (followWallAction); leaves the wall where it crosses the start-goal
// line closer to the goal than where it hit, with a clear front. Ends the run as `unreachable`
// when it comes back to the point where it started following the current obstacle (the wall
// closes around start or goal), and as `gave-up` after kGiveUpSteps steps since its first
// contact. Speeds and side vary with the seed so runs differ; no allocation per step.
class WallFollowDriver : public Driver {
 public:
  // Steps after the first contact (every step: following, escaping, heading for the goal) after
  // which the driver gives up.
  static constexpr std::size_t kGiveUpSteps = 4000;
  // Back within kHitReturnUnits of the hit point after having been more than kHitDepartUnits
  // from it: the obstacle has been walked round without finding a way to the goal.
  static constexpr double kHitReturnUnits = 40.0;
  static constexpr double kHitDepartUnits = 100.0;

  // What varies between this driver and its Bug-2 variant (BugDriver).
  struct Options {
    std::string name = "wall-follow";
    // The followed side, when given; else drawn from the seed. The draw is made either way, so
    // the seed's other choices (speeds, turn) stay the same.
    std::optional<FollowSide> side;
    std::size_t giveUpSteps = kGiveUpSteps;
    // Draw the followed side again at every new obstacle (else once per run).
    bool sidePerObstacle = false;
    // Back at the hit point: follow the obstacle the other way round this many times before
    // ending the run as unreachable.
    int sideSwitches = 0;
  };

  explicit WallFollowDriver(std::uint64_t seed);
  WallFollowDriver(std::uint64_t seed, Options options);
  std::string name() const override { return options_.name; }
  Command next(const Observation& obs) override;
  bool gaveUp() const override { return gaveUp_; }
  bool unreachable() const { return unreachable_; }
  std::optional<RunOutcome> finished() const override;
  bool wallOnRight() const { return wallSide_ < 0.0; }

 private:
  enum class Mode { GoToGoal, Follow };
  struct Touch;  // what the domes say, seen from the followed side
  static Touch readTouch(const std::array<double, kValuesPerStep>& values, bool wallOnRight);
  Command headForGoal(const Observation& obs, const Vec2& toGoal);
  Command follow(const Observation& obs, const Touch& touch, const Vec2& pos, double goalDistance);
  Command escape();
  Command backOffThenArc(const Observation& obs);
  void startFollowing(double goalDistance);

  Options options_;
  std::mt19937_64 rng_;
  int switchesLeft_ = 0;
  double cruise_ = 40.0;    // units/s
  double turn_ = 0.12;      // rad/s of a slight follow-wall turn
  double wallSide_ = -1.0;  // -1: wall on the right (turn left to avoid), +1: wall on the left
  Mode mode_ = Mode::GoToGoal;
  Command escape_;
  int escapeSteps_ = 0;
  std::size_t escapeIndex_ = 0;
  int blockedStreak_ = 0;
  int leaveSteps_ = 0;   // arcing away from the wall just left
  int backSteps_ = 0;    // backing off in a corner manoeuvre, then
  bool arcing_ = false;  // arcing away from the wall
  double arcStartTheta_ = 0.0;
  Vec2 hitPoint_ = Vec2::Zero();  // where following the current obstacle started
  bool hitPointSet_ = false;
  double hitDistance_ = 0.0;      // goal distance at the first touch of the current obstacle
  double farFromHitUnits_ = 0.0;  // largest distance from the hit point while following
  std::size_t followSteps_ = 0;
  bool contacted_ = false;
  std::size_t stepsSinceContact_ = 0;
  bool gaveUp_ = false;
  bool unreachable_ = false;
};

// Bug-2 for collecting data in generated maps: heads for the goal; at each obstacle follows it by
// touch (the wall follower above) on a side drawn from the seed for that obstacle; leaves it on
// the start-goal line where it is closer to the goal than where it met the obstacle, with a clear
// front. Back at the point where it met the obstacle, it follows it the other way round once;
// back there again, the run ends `unreachable`. Gives up kGiveUpSteps steps after the first
// contact. It steers by the pose it is given (the simulator's): a data-collection driver, not a
// navigator.
class BugDriver : public WallFollowDriver {
 public:
  static constexpr std::size_t kGiveUpSteps = 12000;
  explicit BugDriver(std::uint64_t seed, std::optional<FollowSide> side = std::nullopt);
};

// Bounded random walk: holds a random (v, omega) in [-20, 60] x [-1, 1] for 5..30 steps; after a
// blocked step it backs off for a few steps.
class RandomDriver : public Driver {
 public:
  explicit RandomDriver(std::uint64_t seed);
  std::string name() const override { return "random"; }
  Command next(const Observation& obs) override;

 private:
  double uniform(double lo, double hi);
  std::mt19937_64 rng_;
  Command current_;
  int remaining_ = 0;
};

// Names accepted by makeDriver (for the CLI).
std::vector<std::string> autonomousDriverNames();  // "bug", "random", "wall-follow"
// A driver by name, or nullptr for an unknown name.
std::unique_ptr<Driver> makeDriver(std::string_view name, std::uint64_t seed);
// Same, the wall followers (wall-follow, bug) keeping the wall on `side` when it is given (bug: the
// side it takes at every obstacle first); nullptr as well for a side given to another driver.
std::unique_ptr<Driver> makeDriver(std::string_view name, std::uint64_t seed,
                                   std::optional<FollowSide> side);

}  // namespace tactile::sim
