// Simulator verbs: simulate, bench sim (navigate lives in cli_nav.cpp).

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/cli_common.h"
#include "base/file_text.h"
#include "base/text_rules.h"
#include "run/builtin_scenes.h"
#include "run/json_text.h"
#include "run/run_csv.h"
#include "sim/recorder.h"
#include "sim/scene_source.h"
#include "sim/training_plan.h"
#include "sim/truth_stats.h"

namespace tactile::cli {
namespace {

using namespace tactile::sim;

struct SimulateArgs {
  std::string scene;
  std::string plan;
  std::string commands;  // a run file whose commands are replayed
  std::string driver = "wall-follow";
  std::string followSide;  // "left", "right"; empty: drawn from the seed
  std::int64_t steps = 5000;
  std::uint64_t seed = 1;
  std::string out;
  std::string outDir;
  std::string prefix = "run";  // batch files are PREFIX_0000.csv, ...
  std::int64_t runs = 1;
  unsigned threads = 0;
  double dt = 0.1;
  bool json = false;
  bool quiet = false;
};

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Loads the scene or throws (UsageError for what the user typed wrong).
std::shared_ptr<const World> loadWorld(const std::string& spec) {
  if (auto problem = sceneSpecError(spec)) throw UsageError(*problem);
  Result<Scene> loaded = loadScene(spec);
  if (!loaded) throw std::runtime_error(loaded.errorText());
  return std::make_shared<const World>(std::move(loaded.value()));
}

std::string sceneLabel(const std::string& spec, const World& world) {
  // Files are recorded by their scene name; built-ins and random specs by what was typed.
  if (spec.starts_with("random:") || builtinSceneJson(spec)) return spec;
  return world.scene().name;
}

// Steps of each class per group: {"F":{"NoContact":n,...},...}.
nlohmann::json classStepsJson(const TruthStats& stats) {
  nlohmann::json out = nlohmann::json::object();
  for (const GroupInfo& info : kSensorGroups) {
    nlohmann::json row = nlohmann::json::object();
    for (int c = 0; c < kContactClassCount; ++c) {
      row[std::string(contactClassName(static_cast<ContactClass>(c)))] =
          stats.classSteps[static_cast<std::size_t>(groupIndex(info.group))]
                          [static_cast<std::size_t>(c)];
    }
    out[std::string(info.shortName)] = row;
  }
  return out;
}

nlohmann::json truthQualityJson(const TruthStats& stats) {
  nlohmann::json changes = nlohmann::json::object();
  for (const GroupInfo& info : kSensorGroups)
    changes[std::string(info.shortName)] = stats.changesPer100ContactSteps(info.group);
  return {{"changes_per_100_contact_steps", changes},
          {"blocked_steps", stats.blockedSteps},
          {"blocked_without_readings", stats.blockedWithoutReadings}};
}

// The class table printed after a simulation: steps per group and class, and the flicker.
std::string classTable(const TruthStats& stats) {
  std::ostringstream o;
  o << "truth steps per group:\n  group";
  for (int c = 0; c < kContactClassCount; ++c) {
    o << ' ' << std::setw(12) << contactClassName(static_cast<ContactClass>(c));
  }
  o << "  changes/100\n";
  for (const GroupInfo& info : kSensorGroups) {
    o << "  " << std::setw(5) << info.shortName;
    for (int c = 0; c < kContactClassCount; ++c) {
      o << ' ' << std::setw(12)
        << stats.classSteps[static_cast<std::size_t>(groupIndex(info.group))]
                           [static_cast<std::size_t>(c)];
    }
    o << "  " << std::fixed << std::setprecision(2) << std::setw(11)
      << stats.changesPer100ContactSteps(info.group) << '\n';
  }
  o << "blocked steps: " << stats.blockedSteps
    << ", without any reading: " << stats.blockedWithoutReadings << '\n';
  return o.str();
}

// `simulate --plan training`: run i of the recipe for every i < runs, one after another (the runs
// are short); generated scenes are written beside their runs as P_0000.scene.json.
int runPlan(const SimulateArgs& a) {
  if (a.plan != "training") throw UsageError("--plan must be training, got " + quotedInput(a.plan));
  if (a.outDir.empty()) throw UsageError("--plan needs --out-dir");
  if (!a.scene.empty()) throw UsageError("give --scene or --plan, not both");
  if (a.runs <= 0 || static_cast<std::uint64_t>(a.runs) > kMaxRunsPerBatch) {
    throw UsageError("--runs must be between 1 and " + std::to_string(kMaxRunsPerBatch));
  }
  std::error_code ec;
  std::filesystem::create_directories(a.outDir, ec);
  if (ec) throw std::runtime_error(a.outDir + ": cannot create directory: " + ec.message());
  const auto t0 = std::chrono::steady_clock::now();
  const auto runs = static_cast<std::size_t>(a.runs);
  const int width = std::max<int>(4, static_cast<int>(std::to_string(runs - 1).size()));
  TruthStats stats;
  std::size_t totalSteps = 0;
  std::map<std::string, int> kinds;
  nlohmann::json runList = nlohmann::json::array();
  ProgressLine planLine("simulate", "runs");
  for (std::size_t i = 0; i < runs; ++i) {
    PlannedRun planned = planTrainingRun(a.seed, i);
    std::string number = std::to_string(i);
    if (number.size() < static_cast<std::size_t>(width))
      number.insert(0, static_cast<std::size_t>(width) - number.size(), '0');
    const std::string stem = a.prefix + "_" + number;
    const std::filesystem::path dir(a.outDir);
    std::string label = planned.sceneName;
    if (label.empty()) {
      // Stored with the run: the import reads a relative scene path beside the run file.
      label = stem + ".scene.json";
      planned.scene.name = label;
      const Status written = writeFileAtomically(dir / label, sceneToJson(planned.scene));
      if (!written) throw std::runtime_error(written.errorText());
    }
    auto world = std::make_shared<const World>(std::move(planned.scene));
    RunResult result = simulateRunWith(world, label, *planned.driver, planned.options);
    if (!result.ok()) {
      throw std::runtime_error("run " + std::to_string(i) + " (" + planned.kind +
                               "): " + result.errorText());
    }
    RunData& run = result->run;
    run.setMeta("plan", "training " + std::to_string(a.seed) + " " + std::to_string(i) + " " +
                            planned.kind);
    // A scripted run has no navigation goal: it neither reaches nor misses one.
    if (planned.sceneName.empty()) run.setMeta("outcome", "unknown");
    const std::filesystem::path file = dir / (stem + ".csv");
    const Status written = writeRunCsv(run, file);
    if (!written) throw std::runtime_error(written.errorText());
    stats.add(run);
    totalSteps += run.stepCount();
    ++kinds[planned.kind];
    runList.push_back({{"file", file.string()},
                       {"kind", planned.kind},
                       {"scene", label},
                       {"steps", run.stepCount()},
                       {"outcome", *run.meta("outcome")}});
    if (!a.quiet) planLine.show(i + 1, runs);
  }
  const double seconds = secondsSince(t0);
  if (a.json) {
    nlohmann::json j;
    j["plan"] = a.plan;
    j["seed"] = a.seed;
    j["runs"] = runList;
    j["steps"] = totalSteps;
    j["seconds"] = seconds;
    j["class_steps"] = classStepsJson(stats);
    j["truth"] = truthQualityJson(stats);
    std::printf("%s\n", dumpJson(j).c_str());
  } else {
    std::ostringstream o;
    for (const auto& [k, v] : kinds)
      o << " " << k << "=" << v;
    std::printf(
        "simulated %zu planned run(s), %zu steps in %.3f s; kinds:%s\nwrote %zu files to %s\n",
        runs, totalSteps, seconds, o.str().c_str(), runs, a.outDir.c_str());
    std::printf("%s", classTable(stats).c_str());
  }
  return kExitOk;
}

// `simulate --commands RUN.csv`: the run file's (v, omega) commands, one a step, from its start
// pose to its goal (from its metadata; the scene's where absent), through the same run loop as
// every other run. The run ends at the goal or after the last command (outcome timeout).
int runReplay(const SimulateArgs& a) {
  if (a.out.empty() || !a.outDir.empty() || a.runs != 1) {
    throw UsageError("--commands records one run: give --out FILE (not --out-dir or --runs)");
  }
  checkNumberOption("--dt", a.dt, 0.0, RangeEnd::Open, 1.0, RangeEnd::Closed);
  RunCsvResult source = readRunCsv(a.commands);
  if (!source) throw std::runtime_error(source.errorText());
  const RunData& commands = source.value();
  std::shared_ptr<const World> world = loadWorld(a.scene);
  const std::string label = sceneLabel(a.scene, *world);
  Scene scene = world->scene();
  if (const auto start = commands.start()) scene.start = *start;
  if (const auto goal = commands.goal()) scene.goal = Vec2(goal->first, goal->second);
  world = std::make_shared<const World>(std::move(scene));
  std::vector<ScriptDriver::Leg> legs;
  legs.reserve(commands.stepCount());
  for (std::size_t k = 0; k < commands.stepCount(); ++k)
    legs.push_back({Command{commands.v[k], commands.omega[k]}, 1});
  ScriptDriver driver(std::move(legs));
  RunOptions options;
  options.maxSteps = commands.stepCount();
  options.seed = a.seed;
  options.config.dtSeconds = a.dt;
  const auto t0 = std::chrono::steady_clock::now();
  RunResult result = simulateRunWith(world, label, driver, options);
  if (!result.ok()) throw std::runtime_error(a.commands + ": " + result.errorText());
  const Status written = writeRunCsv(result->run, a.out);
  if (!written) throw std::runtime_error(written.errorText());
  const double seconds = secondsSince(t0);
  const std::string outcome(runOutcomeName(result->outcome));
  if (a.json) {
    nlohmann::json j;
    j["scene"] = label;
    j["commands"] = a.commands;
    j["steps"] = result->run.stepCount();
    j["outcome"] = outcome;
    j["seconds"] = seconds;
    j["files"] = {a.out};
    std::printf("%s\n", dumpJson(j).c_str());
  } else {
    std::printf("replayed %zu of %zu command(s) of %s in %.3f s; outcome %s\nwrote %s\n",
                result->run.stepCount(), commands.stepCount(), a.commands.c_str(), seconds,
                outcome.c_str(), a.out.c_str());
  }
  return kExitOk;
}

int runSimulate(const SimulateArgs& a) {
  if (!a.prefix.empty()) requireValidName(a.prefix, "--prefix", "run");
  std::optional<FollowSide> side;
  if (!a.followSide.empty()) {
    side = parseFollowSide(a.followSide);
    if (!side)
      throw UsageError("--follow-side must be left or right, got " + quotedInput(a.followSide));
    if (!a.commands.empty() || !a.plan.empty())
      throw UsageError(
          "--follow-side goes with --driver wall-follow or bug, not with --commands "
          "or --plan");
    if (a.driver != "wall-follow" && a.driver != "bug")
      throw UsageError("--follow-side needs --driver wall-follow or bug (the " + a.driver +
                       " driver follows no wall)");
  }
  if (!a.commands.empty()) {
    if (!a.plan.empty()) throw UsageError("give --commands or --plan, not both");
    if (a.scene.empty()) throw UsageError("--commands needs --scene");
    return runReplay(a);
  }
  if (!a.plan.empty()) return runPlan(a);
  if (a.scene.empty()) throw UsageError("give --scene (or --plan training)");
  if (a.steps <= 0) throw UsageError("--steps must be at least 1, got " + std::to_string(a.steps));
  if (static_cast<std::uint64_t>(a.steps) > kMaxStepsPerRun) {
    throw UsageError("--steps must be at most " + std::to_string(kMaxStepsPerRun) + ", got " +
                     std::to_string(a.steps));
  }
  if (a.runs <= 0 || static_cast<std::uint64_t>(a.runs) > kMaxRunsPerBatch) {
    throw UsageError("--runs must be between 1 and " + std::to_string(kMaxRunsPerBatch));
  }
  checkNumberOption("--dt", a.dt, 0.0, RangeEnd::Open, 1.0, RangeEnd::Closed);
  if (a.driver != "wall-follow" && a.driver != "random" && a.driver != "bug") {
    throw UsageError("--driver must be wall-follow, bug or random, got " + quotedInput(a.driver));
  }
  const bool batch = !a.outDir.empty();
  if (batch == !a.out.empty()) throw UsageError("give exactly one of --out FILE or --out-dir DIR");
  if (!batch && a.runs != 1) throw UsageError("--runs needs --out-dir");
  if (!batch && a.prefix != "run") throw UsageError("--prefix needs --out-dir");
  if (a.prefix.empty() || a.prefix.find_first_of("/\\,\r\n") != std::string::npos ||
      a.prefix == "." || a.prefix == "..") {
    throw UsageError("--prefix must be a non-empty file-name part without '/', '\\' or ',', got " +
                     quotedInput(a.prefix));
  }

  std::shared_ptr<const World> world = loadWorld(a.scene);
  std::string label = sceneLabel(a.scene, *world);
  if (!a.scene.starts_with("random:") && !builtinSceneJson(a.scene)) {
    // A scene from a file is written beside its runs as STEM.scene.json and the runs name that
    // file, so that import stores them with their walls (and a file whose scene is called like a
    // built-in one keeps its own geometry).
    const std::filesystem::path dir =
        batch ? std::filesystem::path(a.outDir) : std::filesystem::path(a.out).parent_path();
    const std::string stem = batch ? a.prefix : std::filesystem::path(a.out).stem().string();
    label = stem + ".scene.json";
    if (std::string problem = sceneNameProblem(label); !problem.empty()) {
      throw UsageError("the scene file written beside the runs would be named '" + label +
                       "': " + problem);
    }
    std::error_code ec;
    if (batch) std::filesystem::create_directories(dir, ec);
    const Status written = writeFileAtomically(dir / label, sceneToJson(world->scene()));
    if (!written) throw std::runtime_error(written.errorText());
  }
  RunOptions options;
  options.maxSteps = static_cast<std::size_t>(a.steps);
  options.seed = a.seed;
  options.driver = a.driver;
  options.followSide = side;
  options.config.dtSeconds = a.dt;

  const auto t0 = std::chrono::steady_clock::now();
  std::size_t totalSteps = 0;
  std::map<std::string, int> outcomes;
  std::vector<std::string> files;
  TruthStats stats;
  if (!batch) {
    ProgressFn progress;
    if (!a.quiet) {
      progress = [line = ProgressLine("simulate", "steps")](std::size_t done,
                                                            std::size_t total) mutable {
        line.show(done, total);
        return true;
      };
    }
    RunResult result = simulateRun(world, label, options, progress);
    if (!result.ok()) throw std::runtime_error(result.errorText());
    const Status written = writeRunCsv(result->run, a.out);
    if (!written) throw std::runtime_error(written.errorText());
    totalSteps = result->run.stepCount();
    stats.add(result->run);
    ++outcomes[std::string(runOutcomeName(result->outcome))];
    files.push_back(a.out);
  } else {
    std::error_code ec;
    std::filesystem::create_directories(a.outDir, ec);
    if (ec) throw std::runtime_error(a.outDir + ": cannot create directory: " + ec.message());
    const std::size_t runs = static_cast<std::size_t>(a.runs);
    const int width = std::max<int>(4, static_cast<int>(std::to_string(runs - 1).size()));
    std::mutex mutex;
    files.resize(runs);
    std::vector<std::string> outcomeOf(runs);
    std::vector<std::size_t> stepsOf(runs, 0);
    const RunSink sink = [&](std::size_t i, SimulatedRun& r) -> Status {
      char number[32];
      std::snprintf(number, sizeof number, "_%0*zu.csv", width, i);
      const std::filesystem::path path = std::filesystem::path(a.outDir) / (a.prefix + number);
      const Status written = writeRunCsv(r.run, path);
      if (!written) return written;
      TruthStats mine;
      mine.add(r.run);
      std::lock_guard lock(mutex);
      stats.merge(mine);
      files[i] = path.string();
      outcomeOf[i] = std::string(runOutcomeName(r.outcome));
      stepsOf[i] = r.run.stepCount();
      return Status::success();
    };
    ProgressLine line("simulate", "runs");
    const ProgressFn progress = [&](std::size_t done, std::size_t total) {
      if (!a.quiet) line.show(done, total);
      return true;
    };
    const Status batch = simulateBatch(world, label, options, runs, a.threads, sink, progress);
    if (!batch) throw std::runtime_error(batch.errorText());
    for (std::size_t i = 0; i < runs; ++i) {
      totalSteps += stepsOf[i];
      ++outcomes[outcomeOf[i]];
    }
  }
  const double seconds = secondsSince(t0);
  const double rate = seconds > 0.0 ? static_cast<double>(totalSteps) / seconds : 0.0;
  if (a.json) {
    nlohmann::json j;
    j["scene"] = label;
    j["driver"] = a.driver;
    if (side) j["follow_side"] = std::string(followSideName(*side));
    j["runs"] = a.runs;
    j["steps"] = totalSteps;
    j["outcomes"] = outcomes;
    j["seconds"] = seconds;
    j["steps_per_second"] = rate;
    j["files"] = files;
    j["class_steps"] = classStepsJson(stats);
    j["truth"] = truthQualityJson(stats);
    std::printf("%s\n", dumpJson(j).c_str());
  } else {
    std::ostringstream o;
    for (const auto& [k, v] : outcomes)
      o << " " << k << "=" << v;
    std::printf("simulated %lld run(s), %zu steps in %.3f s (%.0f steps/s); outcomes:%s\n",
                static_cast<long long>(a.runs), totalSteps, seconds, rate, o.str().c_str());
    if (!batch)
      std::printf("wrote %s\n", a.out.c_str());
    else
      std::printf("wrote %lld files to %s\n", static_cast<long long>(a.runs), a.outDir.c_str());
    if (!a.quiet) std::printf("%s", classTable(stats).c_str());
  }
  return kExitOk;
}

struct BenchArgs {
  std::vector<std::size_t> counts{10, 100, 1000, 10000};
  std::int64_t steps = 20000;
  std::int64_t bruteSteps = 1000;
  int repeats = 3;
  bool json = false;
};

struct Measurement {
  double stepsPerSecond = 0.0;
  double contactFraction = 0.0;  // steps with any truth other than NoContact
};

// Median steps/s of `repeats` timed runs of `steps` steps (random driver, seed 1, recorded to
// memory, no stop at the goal).
Measurement measure(const std::shared_ptr<const World>& world, std::size_t steps, bool useIndex,
                    int repeats) {
  std::vector<double> rates;
  Measurement m;
  for (int r = 0; r < repeats; ++r) {
    RunOptions options;
    options.maxSteps = steps;
    options.seed = 1;
    options.driver = "random";
    options.stopAtGoal = false;
    options.config.useIndex = useIndex;
    const auto t0 = std::chrono::steady_clock::now();
    RunResult result = simulateRun(world, "bench", options);
    const double s = secondsSince(t0);
    if (!result.ok()) throw std::runtime_error(result.errorText());
    rates.push_back(static_cast<double>(result->run.stepCount()) / s);
    std::size_t touching = 0;
    for (std::size_t k = 0; k < result->run.stepCount(); ++k) {
      for (const GroupInfo& g : kSensorGroups) {
        if (result->run.truthAt(k, g.group) != ContactClass::NoContact) {
          ++touching;
          break;
        }
      }
    }
    m.contactFraction =
        static_cast<double>(touching) / static_cast<double>(result->run.stepCount());
  }
  std::sort(rates.begin(), rates.end());
  m.stepsPerSecond = rates[rates.size() / 2];
  return m;
}

int runBench(const BenchArgs& a) {
  if (a.steps <= 0 || static_cast<std::uint64_t>(a.steps) > kMaxStepsPerRun) {
    throw UsageError("--steps must be between 1 and " + std::to_string(kMaxStepsPerRun));
  }
  if (a.bruteSteps < 0 || a.bruteSteps > a.steps) {
    throw UsageError("--brute-steps must be between 0 and --steps");
  }
  if (a.repeats <= 0) throw UsageError("--repeats must be at least 1");
  for (std::size_t n : a.counts) {
    if (n > kMaxProceduralObstacles) {
      throw UsageError("obstacle counts must be at most " +
                       std::to_string(kMaxProceduralObstacles));
    }
  }
  nlohmann::json rows = nlohmann::json::array();
  if (!a.json) {
    std::printf("%-16s %9s %8s %8s %12s %14s %10s\n", "scene", "obstacles", "edges", "contact",
                "steps/s", "brute steps/s", "step time");
  }
  double first = 0.0;
  std::vector<std::string> scenes{"room1"};
  for (std::size_t n : a.counts)
    scenes.push_back("random:" + std::to_string(n) + ":1");
  for (const std::string& spec : scenes) {
    std::shared_ptr<const World> world = loadWorld(spec);
    const Measurement m = measure(world, static_cast<std::size_t>(a.steps), true, a.repeats);
    const double brute =
        a.bruteSteps > 0
            ? measure(world, static_cast<std::size_t>(a.bruteSteps), false, 1).stepsPerSecond
            : 0.0;
    const bool procedural = spec.starts_with("random:");
    if (procedural && first == 0.0) first = m.stepsPerSecond;
    // Step time relative to the smallest procedural scene.
    const double ratio = procedural ? first / m.stepsPerSecond : 0.0;
    const std::size_t obstacles = world->scene().obstacles.size();
    const std::size_t edges = world->edges().size();
    if (a.json) {
      rows.push_back({{"scene", spec},
                      {"obstacles", obstacles},
                      {"edges", edges},
                      {"contact_fraction", m.contactFraction},
                      {"steps_per_second", m.stepsPerSecond},
                      {"brute_force_steps_per_second", brute},
                      {"step_time_vs_smallest", ratio}});
    } else {
      char ratioText[32] = "";
      if (procedural) std::snprintf(ratioText, sizeof ratioText, "%.2fx", ratio);
      std::printf("%-16s %9zu %8zu %7.0f%% %12.0f %14.0f %10s\n", spec.c_str(), obstacles, edges,
                  100.0 * m.contactFraction, m.stepsPerSecond, brute, ratioText);
      std::fflush(stdout);
    }
  }
  if (a.json) {
    nlohmann::json j;
    j["benchmark"] = "sim";
    j["driver"] = "random";
    j["steps"] = a.steps;
    j["brute_steps"] = a.bruteSteps;
    j["repeats"] = a.repeats;
    j["rows"] = rows;
    std::printf("%s\n", dumpJson(j).c_str());
  }
  return kExitOk;
}

}  // namespace

void registerSimVerbs(CLI::App& app, CLI::App& bench) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* sim =
      app.add_subcommand("simulate", "Drive the simulated robot through a scene and record runs");
  sim->add_option("--scene", args->scene,
                  "Built-in scene name, scene JSON file, random:N:SEED (procedural) or "
                  "random:office:SEED (generated office map)");
  CLI::Option* plan =
      sim->add_option("--plan", args->plan,
                      "training: N runs from the standard training recipe (needs --out-dir; scenes "
                      "and drivers come from the recipe, docs/sim.md#training-corpus; without "
                      "--runs, the recipe's documented " +
                          std::to_string(kTrainingPlanRuns) + " runs)");
  CLI::Option* driver =
      sim->add_option("--driver", args->driver,
                      "wall-follow (Bug-2 explorer), bug (Bug-2, side per obstacle) or random");
  sim->add_option("--follow-side", args->followSide,
                  "left or right: the wall followers (wall-follow, bug) keep the wall on this side "
                  "(default: drawn from the seed; bug: the side it takes first at each obstacle)");
  sim->add_option("--commands", args->commands,
                  "Replay the v, omega commands of this run file, one a step, from its start "
                  "pose to its goal (one run, --out; docs/cli.md#simulate)");
  CLI::Option* steps =
      sim->add_option("--steps", args->steps, "Maximum steps per run (1..1000000)");
  sim->add_option("--seed", args->seed, "Seed; run i of a batch uses SEED+i");
  CLI::Option* out = sim->add_option("--out", args->out, "Output run file (single run)");
  sim->add_option("--out-dir", args->outDir, "Output directory (batch: run_0000.csv, ...)");
  sim->add_option("--prefix", args->prefix,
                  "Batch file names P_0000.csv, ... (default run); imported, the runs are named "
                  "by these stems, so batches with different prefixes never clash");
  CLI::Option* runs =
      sim->add_option("--runs", args->runs, "Number of runs in a batch (needs --out-dir)");
  CLI::Option* threads =
      sim->add_option("--threads", args->threads, "Worker threads for a batch (0 = all cores)");
  CLI::Option* dt = sim->add_option("--dt", args->dt, "Step length in seconds");
  sim->add_flag("--json", args->json, "Print one JSON summary object on stdout");
  sim->add_flag("--quiet", args->quiet, "No progress on stderr");
  // The recipe chooses each run's driver, length and step, and runs them one after another: these
  // options would be ignored with it, so they are refused.
  for (CLI::Option* o : {driver, steps, out, threads, dt})
    plan->excludes(o);
  setAction(sim, [args, runs] {
    if (!args->plan.empty() && runs->count() == 0) args->runs = kTrainingPlanRuns;
    return runSimulate(*args);
  });

  registerNavigateVerb(app);  // cli_nav.cpp

  auto bargs = std::make_shared<BenchArgs>();
  CLI::App* b = bench.add_subcommand("sim", "Simulator steps per second against obstacle count");
  b->add_option("--counts", bargs->counts, "Obstacle counts of the procedural scenes");
  b->add_option("--steps", bargs->steps, "Steps per timed run");
  b->add_option("--brute-steps", bargs->bruteSteps, "Steps for the brute-force figure (0: skip)");
  b->add_option("--repeats", bargs->repeats, "Timed runs per scene (median reported)");
  b->add_flag("--json", bargs->json, "Print one JSON object on stdout");
  setAction(b, [bargs] { return runBench(*bargs); });
}

}  // namespace tactile::cli
