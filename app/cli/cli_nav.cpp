// The navigator's verb: navigate (seeded runs on one scene, or the office-map benchmark).
#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "analysis/model_file.h"
#include "app/cli/cli_common.h"
#include "base/file_text.h"
#include "base/parallel.h"
#include "base/text_rules.h"
#include "nav/benchmark.h"
#include "nav/navigate.h"
#include "run/builtin_scenes.h"
#include "run/json_text.h"
#include "run/run_csv.h"
#include "sim/scene_source.h"
#include "storage/run_database.h"
#include "workspace/workspace.h"

namespace tactile::cli {
namespace {

using nlohmann::json;

struct NavigateArgs {
  std::string scene;
  std::string model;
  std::string db;
  std::string status = "model";
  std::string seeds = "1";
  std::int64_t maxSteps = 6000;
  std::string outDir;
  unsigned threads = 0;
  std::int64_t benchmark = -1;  // -1: not given
  std::uint64_t seed = 1;
  bool json = false;
  bool quiet = false;
  bool touchMap = false;
  bool wallFollow = false;
};

// "A-B", "A" or "A,B,C" (each part a number or a range); at most 100,000 seeds.
std::vector<std::uint64_t> parseSeeds(const std::string& text) {
  std::vector<std::uint64_t> out;
  const auto number = [&](std::string_view part) {
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    if (ec != std::errc() || end != part.data() + part.size() || part.empty())
      throw UsageError("--seeds: " + quotedInput(part) + " is not a seed (use A-B or A,B,C)");
    return v;
  };
  std::string_view rest = text;
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view part = rest.substr(0, comma);
    const std::size_t dash = part.find('-');
    if (dash == std::string_view::npos) {
      out.push_back(number(part));
    } else {
      const std::uint64_t a = number(part.substr(0, dash));
      const std::uint64_t b = number(part.substr(dash + 1));
      if (b < a) throw UsageError("--seeds: range " + std::string(part) + " runs backwards");
      if (b - a >= 100'000) throw UsageError("--seeds: at most 100000 seeds");
      for (std::uint64_t s = a; s <= b; ++s)
        out.push_back(s);
    }
    if (out.size() > 100'000) throw UsageError("--seeds: at most 100000 seeds");
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  return out;
}

// A model without some groups leaves the navigator blind there (it reads them as no contact all
// run long): said before the run starts.
std::shared_ptr<const analysis::ModelBundle> warnOfMissingGroups(
    const std::string& model, std::shared_ptr<const analysis::ModelBundle> bundle) {
  std::string missing;
  for (const GroupInfo& g : kSensorGroups)
    if (bundle->find(g.group) == nullptr)
      missing += (missing.empty() ? "" : ", ") + std::string(g.shortName);
  if (!missing.empty())
    printWarning("model " + model + " has no model for " + missing +
                 ": the navigator reads those groups as no contact all run long");
  return bundle;
}

std::shared_ptr<const analysis::ModelBundle> loadModelsUnchecked(const NavigateArgs& a) {
  if (a.model.empty())
    throw UsageError(a.benchmark != -1
                         ? "--benchmark needs --model FILE (or a stored NAME with --db): it "
                           "runs the models beside the truth and the bumper"
                         : "--status model needs --model FILE (or a stored NAME with --db)");
  if (!a.db.empty()) {
    workspace::Workspace ws(openDatabaseForRead(a.db));
    auto m = ws.loadModel(a.model);
    if (!m) throw std::runtime_error(a.db + ": " + m.errorText());
    return std::make_shared<const analysis::ModelBundle>(std::move(m.value()));
  }
  auto m = analysis::readModelFile(a.model);
  if (!m) throw std::runtime_error(m.errorText());
  return std::make_shared<const analysis::ModelBundle>(std::move(m.value()));
}

std::shared_ptr<const analysis::ModelBundle> loadModels(const NavigateArgs& a) {
  return warnOfMissingGroups(a.model, loadModelsUnchecked(a));
}

int runBenchmark(const NavigateArgs& a) {
  if (!a.scene.empty()) throw UsageError("give --scene or --benchmark, not both");
  if (a.benchmark < 1 || a.benchmark > 100'000)
    throw UsageError("--benchmark must be between 1 and 100000 maps");
  if (a.seed > std::numeric_limits<std::uint64_t>::max() / 2)
    throw UsageError("--seed must be below 2^63");
  nav::BenchmarkOptions options;
  options.maps = static_cast<std::size_t>(a.benchmark);
  options.seed = a.seed;
  options.maxSteps = static_cast<std::size_t>(a.maxSteps);
  options.threads = a.threads;
  options.touchMap = a.touchMap;
  options.planDrive = !a.wallFollow;
  options.models = loadModels(a);
  if (!a.outDir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(a.outDir, ec);
    if (ec) throw std::runtime_error(a.outDir + ": cannot create directory: " + ec.message());
    options.outDir = a.outDir;
  }
  ProgressFn progress;
  if (!a.quiet) {
    progress = [line = ProgressLine("navigate", "runs")](std::size_t done,
                                                         std::size_t total) mutable {
      line.show(done, total);
      return true;
    };
  }
  auto result = nav::runMapBenchmark(options, progress);
  if (!result) throw std::runtime_error(result.errorText());
  const nav::BenchmarkResult& r = result.value();
  if (a.json) {
    json j;
    j["maps"] = r.maps;
    j["seed"] = a.seed;
    j["max_steps"] = a.maxSteps;
    j["unreachable_maps"] = r.mapsWithoutPath;
    for (const nav::SourceSummary& s : r.sources) {
      json runs = json::array();
      for (const nav::MapRun& m : s.mapRuns) {
        json strategies = json::object();
        for (nav::Strategy st : nav::kStrategies)
          strategies[std::string(nav::strategyKey(st))] =
              m.strategySteps[static_cast<std::size_t>(st)];
        runs.push_back({{"map_seed", m.mapSeed},
                        {"outcome", std::string(runOutcomeName(m.outcome))},
                        {"steps", m.steps},
                        {"budget", m.budget},
                        {"path_ratio", m.pathRatio},
                        {"blocked_steps", m.blockedSteps},
                        {"check_contact_starts", m.checkContactStarts},
                        {"closest_goal_distance", m.closestGoalUnits},
                        {"final_goal_distance", m.finalGoalUnits},
                        {"strategy_steps", strategies}});
      }
      j[std::string(nav::statusSourceName(s.source))] = {
          {"runs", s.runs},
          {"success_rate", s.successRate},
          {"median_path_ratio", s.medianPathRatio},
          {"p90_path_ratio", s.p90PathRatio},
          {"median_steps", s.medianSteps},
          {"outcomes",
           {{"success", s.successes}, {"unreachable", s.unreachable}, {"timeout", s.timeouts}}},
          {"seconds", s.seconds},
          {"map_runs", std::move(runs)}};
    }
    j["seconds"] = r.seconds;
    std::printf("%s\n", dumpJson(j).c_str());
  } else {
    std::printf("%zu generated maps (seed %llu), %lld steps at most per run\n", r.maps,
                static_cast<unsigned long long>(a.seed), static_cast<long long>(a.maxSteps));
    std::printf("%-8s %8s %10s %12s %10s %12s %10s\n", "status", "success", "unreachable",
                "path/A* med", "p90", "median steps", "run time");
    for (const nav::SourceSummary& s : r.sources) {
      std::printf("%-8s %7.1f%% %10zu %12.2f %10.2f %12.0f %9.1fs\n",
                  std::string(nav::statusSourceName(s.source)).c_str(), 100.0 * s.successRate,
                  s.unreachable, s.medianPathRatio, s.p90PathRatio, s.medianSteps, s.seconds);
    }
    std::printf("total %.1f s\n", r.seconds);
  }
  return kExitOk;
}

int runNavigate(const NavigateArgs& a) {
  if (a.maxSteps < 1 || static_cast<std::uint64_t>(a.maxSteps) > 1'000'000)
    throw UsageError("--max-steps must be between 1 and 1000000");
  const auto source = nav::parseStatusSource(a.status);
  if (!source)
    throw UsageError("--status must be model, truth or bumper, got " + quotedInput(a.status));
  if (a.benchmark != -1) return runBenchmark(a);
  if (a.scene.empty()) throw UsageError("give --scene (or --benchmark N)");
  if (auto problem = sim::sceneSpecError(a.scene)) throw UsageError(*problem);
  const std::vector<std::uint64_t> seeds = parseSeeds(a.seeds);
  nav::NavigatorConfig config;
  config.source = *source;
  config.touchMap = a.touchMap;
  config.planDrive = !a.wallFollow;
  if (*source == nav::StatusSource::Model) config.models = loadModels(a);
  Result<sim::Scene> loaded = sim::loadScene(a.scene);
  if (!loaded) throw std::runtime_error(loaded.errorText());
  const bool builtin = a.scene.starts_with("random:") || builtinSceneJson(a.scene).has_value();
  std::string label = builtin ? a.scene : loaded->name;
  std::filesystem::path dir(a.outDir);
  if (!a.outDir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error(a.outDir + ": cannot create directory: " + ec.message());
    if (!builtin) {
      // The run names its scene by a file beside it, so an import finds it.
      label = std::filesystem::path(a.scene).filename().string();
      const Status written = writeFileAtomically(dir / label, sim::sceneToJson(loaded.value()));
      if (!written) throw std::runtime_error(written.errorText());
    }
  }
  auto world = std::make_shared<const sim::World>(std::move(loaded.value()));

  struct Row {
    nav::NavigateResult result;
    std::string error;
    std::string file;
  };
  std::vector<Row> rows(seeds.size());
  std::size_t done = 0;  // under `mutex`
  ProgressLine line("navigate", "runs");
  std::mutex mutex;
  const auto t0 = std::chrono::steady_clock::now();
  // Run i starts from seeds[i]; an exception in any run (out of memory) reaches the caller after
  // every worker stopped.
  parallelFor(seeds.size(), a.threads, [&](std::size_t i) {
    nav::NavigateOptions options;
    options.maxSteps = static_cast<std::size_t>(a.maxSteps);
    options.seed = seeds[i];
    const Pose2d start = nav::drawStart(world, seeds[i]);
    auto r =
        nav::navigate(world, label, start, world->scene().goal, config, options, !a.outDir.empty());
    Row& row = rows[i];
    if (!r) {
      row.error = "seed " + std::to_string(seeds[i]) + ": " + r.errorText();
    } else {
      row.result = std::move(r.value());
      if (!a.outDir.empty()) {
        char name[64];
        std::snprintf(name, sizeof name, "navigate_%s_%04llu.csv", a.status.c_str(),
                      static_cast<unsigned long long>(seeds[i]));
        row.file = (dir / name).string();
        const Status written = writeRunCsv(row.result.run, row.file);
        if (!written) row.error = written.errorText();
        row.result.run = RunData();  // written: free the memory
      }
    }
    if (!a.quiet) {
      std::lock_guard lock(mutex);
      line.show(++done, seeds.size());
    }
  });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const Row& row : rows)
    if (!row.error.empty()) throw std::runtime_error(row.error);

  std::size_t successes = 0;
  for (const Row& row : rows)
    successes += row.result.outcome == RunOutcome::Success ? 1 : 0;
  const double rate = static_cast<double>(successes) / static_cast<double>(rows.size());
  if (a.json) {
    json runs = json::array();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const nav::NavigateResult& r = rows[i].result;
      json one{{"seed", seeds[i]},
               {"outcome", runOutcomeName(r.outcome)},
               {"steps", r.steps},
               {"path_length", r.pathLengthUnits},
               {"blocked_steps", r.blockedSteps}};
      if (!rows[i].file.empty()) one["file"] = rows[i].file;
      runs.push_back(std::move(one));
    }
    json j{{"scene", label},
           {"status", a.status},
           {"success_rate", rate},
           {"runs", runs},
           {"seconds", seconds}};
    std::printf("%s\n", dumpJson(j).c_str());
  } else {
    std::printf("%6s  %-11s %7s %12s %8s\n", "seed", "outcome", "steps", "path length", "blocked");
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const nav::NavigateResult& r = rows[i].result;
      std::printf("%6llu  %-11s %7zu %12.1f %8zu\n", static_cast<unsigned long long>(seeds[i]),
                  std::string(runOutcomeName(r.outcome)).c_str(), r.steps, r.pathLengthUnits,
                  r.blockedSteps);
    }
    std::printf("success rate %.1f%% (%zu of %zu) on %s with %s status in %.1f s\n", 100.0 * rate,
                successes, rows.size(), label.c_str(), a.status.c_str(), seconds);
    if (!a.outDir.empty())
      std::printf("wrote %zu run%s to %s\n", rows.size(), rows.size() == 1 ? "" : "s",
                  a.outDir.c_str());
  }
  return kExitOk;
}

}  // namespace

void registerNavigateVerb(CLI::App& app) {
  auto args = std::make_shared<NavigateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "navigate",
      "Navigate a scene by touch: the chapter-5 navigator with trained models, the simulator's "
      "truth or a bumper Bug2; or benchmark all three on generated office maps");
  cmd->add_option("--scene", args->scene, "Built-in scene name, scene JSON file, or random:N:SEED");
  cmd->add_option("--model", args->model,
                  "Model bundle JSON, or a stored model's name with --db (needed by --status "
                  "model and --benchmark)");
  cmd->add_option("--db", args->db,
                  "Database holding the model named by --model (default: TACTILE_DB when "
                  "--model is not a file)");
  CLI::Option* status =
      cmd->add_option("--status", args->status,
                      "Status source: model (trained models, online decision), truth (the "
                      "simulator's ground truth) or bumper (Bug2 with the skin as a bumper)");
  CLI::Option* seeds =
      cmd->add_option("--seeds", args->seeds,
                      "Seeds of the start poses: A-B, A or A,B,C (default 1); 0 is the "
                      "scene's own start, where --benchmark starts a map");
  cmd->add_option(
      "--max-steps", args->maxSteps,
      "Step budget per run (then `timeout`); with --benchmark the least budget of a map, "
      "which gets 20x its A* path's steps at cruise speed when that is more");
  cmd->add_option("--out-dir", args->outDir,
                  "Write each run as navigate_STATUS_SEED.csv here (importable); with --benchmark "
                  "as benchmark_STATUS_MAPSEED.csv");
  cmd->add_option("--threads", args->threads, "Worker threads (0 = all cores)");
  CLI::Option* benchmark =
      cmd->add_option("--benchmark", args->benchmark,
                      "Benchmark the three status sources on N generated office maps");
  cmd->add_option("--seed", args->seed,
                  "--benchmark: map i is random:office:(900000 + SEED + i) (default 1)")
      ->needs(benchmark);
  // The benchmark runs every source from its own starts: a source or start seeds given with it
  // would be ignored, so they are refused.
  status->excludes(benchmark);
  seeds->excludes(benchmark);
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr");
  cmd->add_flag("--touch-map", args->touchMap,
                "With --wall-follow: the thesis strategies also plan on a map of where the robot "
                "touched things (experimental; plan drive always does; see docs/navigation.md)");
  cmd->add_flag("--wall-follow", args->wallFollow,
                "Model and truth sources use the thesis strategies (wall following) instead of "
                "following the touch map's plan (see docs/navigation.md)");
  setAction(cmd, [args] {
    NavigateArgs a = *args;
    // A --model that is not a file names a stored model of TACTILE_DB.
    if (a.db.empty() && !a.model.empty() && !std::filesystem::exists(a.model)) {
      a.db = databaseFromEnvironment();
    }
    return runNavigate(a);
  });
}

}  // namespace tactile::cli
