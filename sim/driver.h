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

// Bug-2 style explorer: heads for the goal; on touching something, follows the wall by touch
// (on a side chosen from the seed), keeping that side's domes lightly pressed; leaves the wall
// where it crosses the start-goal line closer to the goal than where it hit. Gives up after
// following walls for too long. Speeds and side vary with the seed so runs differ.
class WallFollowDriver : public Driver {
 public:
  explicit WallFollowDriver(std::uint64_t seed);
  std::string name() const override { return "wall-follow"; }
  Command next(const Observation& obs) override;
  bool gaveUp() const override { return gaveUp_; }

 private:
  enum class Mode { GoToGoal, Follow };
  std::mt19937_64 rng_;
  double cruise_ = 40.0;
  double wallSide_ = -1.0;  // -1: wall on the right (turn left to avoid), +1: wall on the left
  Mode mode_ = Mode::GoToGoal;
  Command escape_;
  int escapeSteps_ = 0;
  int leaveSteps_ = 0;
  std::size_t escapeIndex_ = 0;
  double hitDistance_ = 0.0;
  std::size_t followSteps_ = 0;
  std::size_t totalFollowSteps_ = 0;
  int blockedStreak_ = 0;
  bool gaveUp_ = false;
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
std::vector<std::string> autonomousDriverNames();  // "random", "wall-follow"
// A driver by name, or nullptr for an unknown name.
std::unique_ptr<Driver> makeDriver(std::string_view name, std::uint64_t seed);

}  // namespace tactile::sim
