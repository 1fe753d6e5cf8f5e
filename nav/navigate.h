// One navigation run: a Simulator, a Navigator and a referee. The referee (this loop, not the
// navigator) says `success` when the body centre comes within the goal radius, `timeout` after the
// step budget; the navigator itself may end the run as `unreachable`. Every step is recorded with
// the navigator's strategy and per-group status as `x_` columns (docs/navigation.md#run-files).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "base/error.h"
#include "nav/navigator.h"
#include "run/run.h"
#include "sim/simulator.h"
#include "sim/world.h"

namespace tactile::nav {

// Column names of the navigator's state in a run file.
inline constexpr std::string_view kStrategyColumn = "x_strategy";
inline constexpr std::string_view kIntegratedStatusColumn = "x_status";
// Per group: "x_status_F", "x_status_FLC", ... in sensor-group order.
std::string groupStatusColumn(SensorGroup group);
// All the navigator's columns, in the order a run file holds them: x_strategy, x_status, then
// x_status_<group> in sensor-group order. Every recorder of navigator runs (navigate below, the
// simulator window's autonomous mode) writes these, so the workbench reads them alike.
std::vector<std::string> navigatorColumns();
// Appends the navigator's state after its last step: one value per column of navigatorColumns(),
// in that order.
void appendNavigatorState(const Navigator& navigator, std::vector<std::string>& values);

struct NavigateOptions {
  std::size_t maxSteps = 6000;
  double goalRadiusUnits = 60.0;  // body centre to goal, as the simulator's runs use
  sim::SimConfig sim;
  std::uint64_t seed = 1;  // recorded as metadata
};

struct NavigateResult {
  RunData run;
  RunOutcome outcome = RunOutcome::Unknown;  // Success, Unreachable or Timeout
  std::size_t steps = 0;
  double pathLengthUnits = 0.0;  // distance the rear-axle midpoint travelled (simulator truth)
  std::size_t blockedSteps = 0;
  // Steps spent in each strategy (kStrategies order) and the Check Contact episodes started
  // (every back-off of a Check Contact, also a restart within one).
  std::array<std::size_t, kStrategyCount> strategySteps{};
  std::size_t checkContactStarts = 0;
  // The body centre's closest approach to the goal and its distance at the end (simulator truth).
  double closestGoalUnits = 0.0;
  double finalGoalUnits = 0.0;
};

// Runs the navigator from `start` toward `goal` in `world`. Fails when the start pose is blocked
// or the navigator cannot be made (NavigatorConfig). `record` false keeps only the figures (the
// run then has no steps; benchmarks).
Result<NavigateResult> navigate(std::shared_ptr<const sim::World> world, std::string_view sceneName,
                                const Pose2d& start, const Vec2& goal,
                                const NavigatorConfig& config, const NavigateOptions& options,
                                bool record = true);

// The start pose of seed `seed` in a scene: for the chapter-5 scene (a wall across the scene
// between start and goal) a free pose on the start's side of the wall, at least a body length
// from it, facing anywhere within 90 degrees of the goal; elsewhere a free pose near the scene's
// start. Deterministic per (scene, seed). Seed 0 is the scene's own start pose, where the map
// benchmark starts each map, so a benchmark map's run can be driven again (and watched).
Pose2d drawStart(const std::shared_ptr<const sim::World>& world, std::uint64_t seed);

}  // namespace tactile::nav
