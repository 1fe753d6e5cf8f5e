#include "sim/recorder.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <mutex>
#include <thread>
#include <vector>

#include "base/parallel.h"
#include "sim/scene_source.h"

namespace tactile::sim {

std::string formatNumber(double value) {
  char buf[64];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return ec == std::errc() ? std::string(buf, ptr) : std::string("0");
}

Recorder::Recorder(const Simulator& sim, std::string_view sceneName, std::string_view subject,
                   std::size_t reserveSteps) {
  const Scene& scene = sim.world().scene();
  const Pose2d& p = sim.pose();
  run_.setMeta("format", std::string(kRunFormat));
  run_.setMeta("scene", std::string(sceneName));
  run_.setMeta("subject", std::string(subject));
  run_.setMeta("dt", formatNumber(sim.config().dtSeconds));
  run_.setMeta("start", formatNumber(p.x) + "," + formatNumber(p.y) + "," + formatNumber(p.theta));
  run_.setMeta("goal", formatNumber(scene.goal.x()) + "," + formatNumber(scene.goal.y()));
  run_.setMeta("outcome", std::string(runOutcomeName(RunOutcome::Unknown)));
  if (reserveSteps > 0) run_.reserve(reserveSteps, true);
}

void Recorder::record(const Simulator& sim, const Command& command) {
  const Pose2d& p = sim.pose();
  run_.appendStep(p.x, p.y, p.theta, command.v, command.omega, sim.blocked(), sim.sensors().data(),
                  sim.truth().data());
}

RunResult simulateRun(std::shared_ptr<const World> world, std::string_view sceneName,
                      const RunOptions& options, const ProgressFn& progress) {
  std::unique_ptr<Driver> driver = makeDriver(options.driver, options.seed, options.followSide);
  if (!driver) {
    if (options.followSide && makeDriver(options.driver, options.seed))
      return Error("driver '" + options.driver + "' follows no wall: a side cannot be given");
    return Error("unknown driver '" + options.driver + "'");
  }
  return simulateRunWith(std::move(world), sceneName, *driver, options, progress);
}

RunLoop::RunLoop(std::shared_ptr<const World> world, std::string_view sceneName,
                 std::string_view subject, const RunOptions& options)
    : world_(world),
      options_(options),
      sim_(world, options.config),
      // Reserve for typical runs only: a run that ends early should not hold memory for maxSteps.
      recorder_(sim_, sceneName, subject, std::min<std::size_t>(options.maxSteps, 1u << 16)) {
  obs_.dtSeconds = options.config.dtSeconds;
  obs_.start = sim_.pose();
  obs_.goal = world->scene().goal;
  obs_.values = &sim_.sensors();
  centreOffset_ = 0.5 * (options.config.geometry.frontX() + options.config.geometry.backX());
  if (options.maxSteps == 0) ended_ = RunOutcome::Timeout;
}

Result<std::unique_ptr<RunLoop>> RunLoop::start(std::shared_ptr<const World> world,
                                                std::string_view sceneName,
                                                std::string_view subject,
                                                const RunOptions& options) {
  if (options.maxSteps > kMaxStepsPerRun) {
    return Error("at most " + std::to_string(kMaxStepsPerRun) + " steps per run");
  }
  // The robot's body at the start: not overlapping an obstacle, nor wholly inside one.
  if (Status start = checkStartPose(world->scene(), options.config.geometry); !start) {
    return start.error();
  }
  return std::unique_ptr<RunLoop>(new RunLoop(std::move(world), sceneName, subject, options));
}

const Observation& RunLoop::observation() {
  obs_.step = sim_.stepIndex();
  obs_.pose = sim_.pose();
  obs_.blocked = sim_.blocked();
  return obs_;
}

double RunLoop::goalDistance() const {
  const Vec2 centre = bodyToWorld(sim_.pose(), Vec2(centreOffset_, 0.0));
  return (centre - world_->scene().goal).norm();
}

std::optional<RunOutcome> RunLoop::step(Driver& driver) {
  if (ended_) return ended_;
  const Command command = driver.next(observation());
  return afterStep(command, &driver);
}

std::optional<RunOutcome> RunLoop::step(const Command& command) {
  if (ended_) return ended_;
  return afterStep(command, nullptr);
}

std::optional<RunOutcome> RunLoop::step(const Command& command, const Driver& driver) {
  if (ended_) return ended_;
  return afterStep(command, &driver);
}

std::optional<RunOutcome> RunLoop::afterStep(const Command& command, const Driver* driver) {
  sim_.step(command.v, command.omega);
  recorder_.record(sim_, command);
  if (options_.stopAtGoal && goalDistance() < options_.goalRadiusUnits) {
    ended_ = RunOutcome::Success;
  } else if (options_.stopAtGoal && driver != nullptr) {
    if (const std::optional<RunOutcome> finished = driver->finished()) ended_ = *finished;
  }
  if (!ended_ && recorder_.run().stepCount() >= options_.maxSteps) ended_ = RunOutcome::Timeout;
  if (ended_) recorder_.setOutcome(*ended_);
  return ended_;
}

void RunLoop::end(RunOutcome outcome) {
  if (ended_) return;
  ended_ = outcome;
  recorder_.setOutcome(outcome);
}

RunData RunLoop::take() {
  recorder_.setOutcome(ended_.value_or(RunOutcome::Unknown));
  return recorder_.take();
}

RunResult simulateRunWith(std::shared_ptr<const World> world, std::string_view sceneName,
                          Driver& driver, const RunOptions& options, const ProgressFn& progress) {
  const std::string name = driver.name();
  Result<std::unique_ptr<RunLoop>> started =
      RunLoop::start(std::move(world), sceneName, name, options);
  if (!started) return started.error();
  RunLoop& loop = *started.value();
  loop.recorder().setMeta("driver", name);
  loop.recorder().setMeta("seed", std::to_string(options.seed));
  for (std::size_t k = 0; !loop.ended(); ++k) {
    loop.step(driver);
    if (!loop.ended() && progress && (k & 1023) == 1023 && !progress(k + 1, options.maxSteps)) {
      return Error("cancelled");
    }
  }
  SimulatedRun result;
  result.outcome = *loop.outcome();
  result.run = loop.take();
  return result;
}

Status simulateBatch(std::shared_ptr<const World> world, std::string_view sceneName,
                     const RunOptions& options, std::size_t runs, unsigned threads,
                     const RunSink& sink, const ProgressFn& progress) {
  if (runs > kMaxRunsPerBatch) {
    return Error("at most " + std::to_string(kMaxRunsPerBatch) + " runs");
  }
  std::mutex mutex;
  std::size_t done = 0;
  std::string firstError;
  const auto fail = [&](std::string error) {
    std::lock_guard lock(mutex);
    if (firstError.empty()) firstError = std::move(error);
    return false;
  };
  // Each run's seed follows from its index. An exception in any run (out of memory) reaches the
  // caller after every worker stopped.
  parallelFor(runs, threads, [&](std::size_t i) {
    RunOptions mine = options;
    mine.seed = options.seed + i;
    RunResult result = simulateRun(world, sceneName, mine);
    if (!result.ok()) return fail("run " + std::to_string(i) + ": " + result.errorText());
    if (sink) {
      if (const Status stored = sink(i, result.value()); !stored) return fail(stored.errorText());
    }
    std::lock_guard lock(mutex);
    ++done;
    if (progress && !progress(done, runs)) {
      if (firstError.empty()) firstError = "cancelled";
      return false;
    }
    return true;
  });
  if (!firstError.empty()) return Error(firstError);
  return Status::success();
}

}  // namespace tactile::sim
