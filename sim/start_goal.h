// Start and goal of an experiment run drawn from a seed (thesis 3.1: the start and the destination
// are chosen at random, and the subject does not know the room).
#pragma once

#include <cstdint>

#include "base/error.h"
#include "run/robot_geometry.h"
#include "sim/scene.h"

namespace tactile::sim {

// Free space kept round a drawn start (the robot touches nothing there) and round a drawn goal
// (the goal circle of the run loop lies in free space).
inline constexpr double kDrawnStartClearanceUnits = 20.0;
inline constexpr double kDrawnGoalClearanceUnits = 70.0;

// `scene` with a start pose and a goal drawn from `seed`: the start where the robot's body is at
// least kDrawnStartClearanceUnits from every edge, the goal outside every obstacle and at least
// kDrawnGoalClearanceUnits from every edge, and the two at least a third of the room's diagonal
// apart. Whether a path joins them is not checked (it need not exist, as with a person's random
// choice). Deterministic in (scene, seed). Fails when no such pair turns up in 20000 draws.
Result<Scene> drawStartGoal(const Scene& scene, std::uint64_t seed,
                            const RobotGeometry& geometry = {});

}  // namespace tactile::sim
