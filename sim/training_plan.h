// The standard training corpus (docs/sim.md#training-corpus): a deterministic recipe of runs
// that, together, show every group each class it can have. Run i of a plan with seed S is one of
// these kinds, in turn:
//   wall-follow   the wall follower in a built-in scene (room1, room2, room3, chapter5, in turn)
//   cluttered     the wall follower in a procedural room (random:N:SEED, N 20..60)
//   wall-end      a short corridor about as wide as the robot: the robot drives out of one end,
//                 turns in place, drives back through and out of the other end, always forwards,
//                 at speeds 10..60 (Wall, then LeavingWall on the sides; Corner where it meets
//                 the walls' ends coming in)
//   inside-corner the robot pushes into a concave corner ahead at an angle, wiggling, then backs
//                 off; repeated (front Wall and Corner, corner groups Corner, sides Wall)
//   tips          five convex tips (squares turned 45 degrees) round the start, each off its ray
//                 by its own lateral offset (stratified over -45..45): the robot turns in place to
//                 each, drives in front first, pushes, comes back; then the same with the back
//                 (Corner on every front and back group, at every place along them)
//   reverse       the robot backs into a concave corner behind it (left, right) or a plain wall, in
//                 turn; the back wall is turned so its end at the side wall is the nearer (back
//                 Wall and Corner, rear corners Corner on both walls)
//   pocket        a dead-end pocket whose sides press the side domes: in to the end, push, back
//                 out (DeadPath on F, FLC, FRC, L, R)
//   slow wall-end the wall-end corridor narrower, at speeds 5..15 (more corner-group contact)
//   tips          a second run of the kind above (its own offsets)
//   side tip      rows of tips along both sides, driven past and back (Corner on the side and
//                 corner groups)
//   office bug    the Bug-2 driver in a generated office map (random:office:SEED), to its goal
//   office wall-follow  the wall follower in another generated office map
// Between them, every second run is an extra: of every three extras, two are *office drives* (the
// wall follower in a generated office map of its own, keeping the wall on the left and on the
// right in turn: driving as the robot drives when it is used) and one is another pocket run (with
// the drives' many Wall rows, the few pockets of the numbered kinds left DeadPath under-shown).
// The other runs are numbered on their own: the j-th of them is kind j mod kTrainingPlanKinds,
// and it does not depend on the extras around it.
// Start poses, speeds, angles, gaps and sizes are drawn from the seed; the corridor and pocket
// widths are stratified over a kind's runs, so that a few runs cover their whole range.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "sim/driver.h"
#include "sim/recorder.h"
#include "sim/scene.h"

namespace tactile::sim {

struct PlannedRun {
  std::string kind;
  // What the run's `scene` metadata says: a built-in name or `random:N:SEED`; empty when the
  // scene was generated for this run only (then `scene` must be written beside the run).
  std::string sceneName;
  Scene scene;
  std::unique_ptr<Driver> driver;
  RunOptions options;
};

inline constexpr int kTrainingPlanKinds = 12;
// The recipe's documented size: its first 40 numbered runs and the 40 extras between them
// (`tactile simulate --plan training` without --runs).
inline constexpr int kTrainingPlanRuns = 80;
inline constexpr const char* kOfficeDriveKindLeft = "office drive left";
inline constexpr const char* kOfficeDriveKindRight = "office drive right";
inline constexpr const char* kExtraPocketKind = "extra pocket";

// Run `index` of the plan with `seed`; the same (seed, index) always gives the same run.
PlannedRun planTrainingRun(std::uint64_t seed, std::size_t index);

// Where run `index` sits in the recipe: the how-manieth office drive, extra pocket or numbered run.
struct PlanSlot {
  enum class Kind { Numbered, OfficeDrive, ExtraPocket };
  Kind kind = Kind::Numbered;
  std::size_t number = 0;
};
PlanSlot trainingPlanSlot(std::size_t index);

// A driver that plays a fixed list of (v, omega, steps) legs, then stops (gives up).
class ScriptDriver : public Driver {
 public:
  struct Leg {
    Command command;
    int steps = 0;
  };
  explicit ScriptDriver(std::vector<Leg> legs) : legs_(std::move(legs)) {}
  std::string name() const override { return "script"; }
  Command next(const Observation& obs) override;
  bool gaveUp() const override { return leg_ >= legs_.size(); }
  std::size_t totalSteps() const;

 private:
  std::vector<Leg> legs_;
  std::size_t leg_ = 0;
  int done_ = 0;
};

}  // namespace tactile::sim
