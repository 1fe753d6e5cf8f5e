#include "nav/navigate.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "sim/recorder.h"
#include "sim/robot.h"

namespace tactile::nav {
namespace {

// Uniform double in [0, 1) from 53 random bits (the same on every standard library).
double unit(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

}  // namespace

std::string groupStatusColumn(SensorGroup group) {
  return "x_status_" + std::string(groupInfo(group).shortName);
}

std::vector<std::string> navigatorColumns() {
  std::vector<std::string> names;
  names.reserve(2 + kGroupCount);
  names.emplace_back(kStrategyColumn);
  names.emplace_back(kIntegratedStatusColumn);
  for (const GroupInfo& info : kSensorGroups)
    names.push_back(groupStatusColumn(info.group));
  return names;
}

void appendNavigatorState(const Navigator& navigator, std::vector<std::string>& values) {
  values.emplace_back(strategyKey(navigator.strategy()));
  values.push_back(statusText(navigator.integratedStatus()));
  for (const ContactStatus& s : navigator.groupStatus())
    values.push_back(statusText(s));
}

Result<NavigateResult> navigate(std::shared_ptr<const sim::World> world, std::string_view sceneName,
                                const Pose2d& start, const Vec2& goal,
                                const NavigatorConfig& config, const NavigateOptions& options,
                                bool record) {
  if (options.maxSteps == 0 || options.maxSteps > sim::kMaxStepsPerRun)
    return Error("the step budget must be between 1 and " + std::to_string(sim::kMaxStepsPerRun));
  auto made = Navigator::create(config);
  if (!made) return made.error();
  Navigator& navigator = *made.value();
  sim::Simulator simulator(world, options.sim);
  if (!simulator.reset(start)) return Error("the start pose overlaps an obstacle");

  std::optional<sim::Recorder> recorder;
  std::vector<std::string> extra;
  constexpr std::size_t kColumns = 2 + kGroupCount;
  if (record) {
    recorder.emplace(simulator, sceneName, navigator.name(),
                     std::min<std::size_t>(options.maxSteps, 1u << 14));
    recorder->setMeta("goal", sim::formatNumber(goal.x()) + "," + sim::formatNumber(goal.y()));
    recorder->setMeta("driver", navigator.name());
    recorder->setMeta("seed", std::to_string(options.seed));
    recorder->setMeta("status_source", std::string(statusSourceName(config.source)));
    extra.reserve(std::min<std::size_t>(options.maxSteps, 1u << 14) * kColumns);
  }
  const double centreOffset = 0.5 * (options.sim.geometry.frontX() + options.sim.geometry.backX());
  NavigateResult result;
  result.outcome = RunOutcome::Timeout;
  Pose2d previous = simulator.pose();
  for (std::size_t k = 0; k < options.maxSteps; ++k) {
    const Observation obs = observe(simulator, k, start, goal);
    const Command command = navigator.step(obs);
    simulator.step(command.v, command.omega);
    const Pose2d& p = simulator.pose();
    result.pathLengthUnits += std::hypot(p.x - previous.x, p.y - previous.y);
    previous = p;
    if (simulator.blocked()) ++result.blockedSteps;
    ++result.steps;
    ++result.strategySteps[static_cast<std::size_t>(navigator.strategy())];
    if (recorder) {
      recorder->record(simulator, command);
      appendNavigatorState(navigator, extra);
    }
    const Vec2 centre = sim::bodyToWorld(p, Vec2(centreOffset, 0.0));
    result.finalGoalUnits = (centre - goal).norm();
    result.closestGoalUnits =
        k == 0 ? result.finalGoalUnits : std::min(result.closestGoalUnits, result.finalGoalUnits);
    if ((centre - goal).norm() < options.goalRadiusUnits) {
      result.outcome = RunOutcome::Success;
      break;
    }
    if (const std::optional<RunOutcome> ended = navigator.finished()) {
      result.outcome = *ended;
      break;
    }
  }
  result.checkContactStarts = navigator.checkContactStarts();
  if (recorder) {
    recorder->setOutcome(result.outcome);
    result.run = recorder->take();
    result.run.extraColumns = navigatorColumns();
    result.run.extraValues = std::move(extra);
  }
  return result;
}

Pose2d drawStart(const std::shared_ptr<const sim::World>& world, std::uint64_t seed) {
  const sim::Scene& scene = world->scene();
  if (seed == 0) return scene.start;
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 0x5851F42D4C957F2Dull);
  sim::Simulator probe(world);
  const double pi = std::numbers::pi;
  const Vec2 s(scene.start.x, scene.start.y);
  // The chapter-5 scene: a wall across the scene at x = 1000..1020, the goal beyond it. Starts
  // anywhere on the start's side, a body length clear of the wall and the bounds.
  const bool chapter5 = scene.name == "chapter5";
  for (int attempt = 0; attempt < 1000; ++attempt) {
    Pose2d p;
    if (chapter5) {
      const double wallX = 985.0;
      const double xmin = scene.bounds.xmin + 150.0;
      const double xmax = wallX - 250.0;
      p.x = xmin + (xmax - xmin) * unit(rng);
      p.y = scene.bounds.ymin + 150.0 + (scene.bounds.ymax - scene.bounds.ymin - 300.0) * unit(rng);
    } else {
      const double r = 100.0 * std::sqrt(unit(rng));
      const double a = 2.0 * pi * unit(rng);
      p.x = s.x() + r * std::cos(a);
      p.y = s.y() + r * std::sin(a);
    }
    const Vec2 toGoal = scene.goal - Vec2(p.x, p.y);
    p.theta = sim::wrapAngle(std::atan2(toGoal.y(), toGoal.x()) + pi * (unit(rng) - 0.5));
    if (p.x < scene.bounds.xmin || p.x > scene.bounds.xmax || p.y < scene.bounds.ymin ||
        p.y > scene.bounds.ymax)
      continue;
    if (!probe.isBlocked(p) && probe.evaluate(p).clearanceUnits > 20.0) return p;
  }
  return scene.start;
}

}  // namespace tactile::nav
