// Recorder and run loop: drive a Simulator with a Driver and record every step into a RunData
// (docs/file-formats.md#run-file: metadata, pose, command, blocked, 88 dome values, 8 truth
// columns).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/progress.h"
#include "run/run.h"
#include "sim/driver.h"
#include "sim/simulator.h"

namespace tactile::sim {

inline constexpr std::size_t kMaxStepsPerRun = 1'000'000;  // ~0.7 GB of values per run
inline constexpr std::size_t kMaxRunsPerBatch = 100'000;

// Shortest round-trip text of a double (metadata values).
std::string formatNumber(double value);

// Records steps of a Simulator into a RunData with metadata. Usable step by step (the GUI) or
// through simulateRun.
class Recorder {
 public:
  // Sets format, scene, subject, dt, start, goal, outcome (unknown) and the extra keys.
  Recorder(const Simulator& sim, std::string_view sceneName, std::string_view subject,
           std::size_t reserveSteps = 0);
  // Appends the simulator's current step (after Simulator::step) with the command it was given.
  void record(const Simulator& sim, const Command& command);
  void setMeta(std::string_view key, std::string value) { run_.setMeta(key, std::move(value)); }
  void setOutcome(RunOutcome outcome) {
    run_.setMeta("outcome", std::string(runOutcomeName(outcome)));
  }
  // Extra (x_) columns (docs/file-formats.md): named before the first step; after each record()
  // the caller appends that step's values, one per column, in column order.
  void setExtraColumns(std::vector<std::string> names) { run_.extraColumns = std::move(names); }
  std::vector<std::string>& extraValues() { return run_.extraValues; }
  const RunData& run() const { return run_; }
  // The run, its truth smoothed over the whole run (smoothTruth in sim/truth.h).
  RunData take() {
    smoothTruth(run_.truth, run_.stepCount());
    return std::move(run_);
  }

 private:
  RunData run_;
};

struct RunOptions {
  std::size_t maxSteps = 5000;
  std::uint64_t seed = 1;
  std::string driver = "wall-follow";
  // The wall followers' side (wall-follow, bug); nullopt: drawn from the seed.
  std::optional<FollowSide> followSide;
  SimConfig config;
  // The run succeeds (and stops) when the body centre comes this close to the goal.
  double goalRadiusUnits = 60.0;
  // false: run all maxSteps even past the goal (benchmarks).
  bool stopAtGoal = true;
};

// A recorded run and how it ended.
struct SimulatedRun {
  RunData run;
  RunOutcome outcome = RunOutcome::Unknown;
};
using RunResult = Result<SimulatedRun>;

// One run: success when the goal is reached, gave-up or unreachable as the driver finishes
// (Driver::finished), timeout after maxSteps. Deterministic: the same world, options and binary
// give the same RunData. `progress` gets (steps done, maxSteps) every 1024 steps; returning false
// cancels (error "cancelled").
RunResult simulateRun(std::shared_ptr<const World> world, std::string_view sceneName,
                      const RunOptions& options, const ProgressFn& progress = {});
// Same, with a caller-made driver (e.g. a manual queue or a future navigator).
RunResult simulateRunWith(std::shared_ptr<const World> world, std::string_view sceneName,
                          Driver& driver, const RunOptions& options,
                          const ProgressFn& progress = {});

// The run loop of simulateRunWith one step at a time, for callers that step at their own pace (the
// workbench's simulator window): the same observation, stepping, recording and ending rules, so a
// run stepped here equals simulateRunWith's with the same driver commands.
class RunLoop {
 public:
  // Fails when the scene's start pose is blocked.
  static Result<std::unique_ptr<RunLoop>> start(std::shared_ptr<const World> world,
                                                std::string_view sceneName,
                                                std::string_view subject,
                                                const RunOptions& options);
  // Asks the driver, steps, records. Returns the outcome once the run has ended (goal reached,
  // the driver finished, or maxSteps taken); after that step() does nothing and returns it again.
  std::optional<RunOutcome> step(Driver& driver);
  // Steps one given command (a driver that is asked nothing: manual driving).
  std::optional<RunOutcome> step(const Command& command);
  // Steps a command the caller had from `driver` itself (fed more than observation() holds, e.g.
  // the simulator's truth); the run ends as step(Driver&) ends it, the driver's finished()
  // included.
  std::optional<RunOutcome> step(const Command& command, const Driver& driver);
  // Ends the run now with `outcome` (e.g. the person gave up); no-op once ended.
  void end(RunOutcome outcome);

  bool ended() const { return ended_.has_value(); }
  std::optional<RunOutcome> outcome() const { return ended_; }
  const Simulator& simulator() const { return sim_; }
  const Recorder& recorder() const { return recorder_; }
  Recorder& recorder() { return recorder_; }
  const RunOptions& options() const { return options_; }
  // What the driver sees before the next step.
  const Observation& observation();
  // Distance of the body centre to the goal.
  double goalDistance() const;
  // The run with its outcome set and truth smoothed over the whole run; the loop is spent.
  RunData take();

 private:
  RunLoop(std::shared_ptr<const World> world, std::string_view sceneName, std::string_view subject,
          const RunOptions& options);
  std::optional<RunOutcome> afterStep(const Command& command, const Driver* driver);

  std::shared_ptr<const World> world_;
  RunOptions options_;
  Simulator sim_;
  Recorder recorder_;
  Observation obs_;
  double centreOffset_ = 0.0;
  std::optional<RunOutcome> ended_;
};

// Batch: run i uses seed options.seed + i. Runs are spread over `threads` workers (0 = all
// cores, at most 256); `sink(i, result)` is called from worker threads (once per run, any order)
// and returns an error that stops the batch, or success. `progress` gets (runs done, runs) from
// one thread at a time. Fails with the first error.
using RunSink = std::function<Status(std::size_t index, SimulatedRun& result)>;
Status simulateBatch(std::shared_ptr<const World> world, std::string_view sceneName,
                     const RunOptions& options, std::size_t runs, unsigned threads,
                     const RunSink& sink, const ProgressFn& progress = {});

}  // namespace tactile::sim
