// One sweep request, checked once, and the one way a sweep job runs: a session over the selected
// data (analysis::SweepSession), whose fit jobs a process runs on its threads or workers claim one
// at a time from a database (docs/cluster.md).
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <set>
#include <thread>
#include <utility>

#include "analysis/report.h"
#include "base/parallel.h"
#include "base/text_rules.h"
#include "run/json_text.h"
#include "workspace/workspace.h"

namespace tactile::workspace {

using nlohmann::json;

namespace {

Error failure(std::string message) {
  return Error(std::move(message));
}

double unixNow() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string defaultWorkerName() {
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
  return std::string(host[0] != '\0' ? host : "worker") + ":" + std::to_string(getpid());
}

template <typename T, typename Parse>
Result<std::vector<T>> parseNames(const std::vector<std::string>& names, Parse parse,
                                  const std::string& what) {
  std::vector<T> out;
  for (const std::string& n : names) {
    const auto v = parse(n);
    if (!v) return failure("unknown " + what + " " + quotedInput(n));
    out.push_back(*v);
  }
  return out;
}

// The configuration a database keeps beside a sweep's cells: the sweep's header (grid, data
// summary, times) with the request's data selection and the sweep's state.
json sweepConfiguration(const analysis::SweepResult& header, const SweepRequest& request,
                        const json& trainRuns, const json& testRuns, const std::string& state) {
  json configuration = analysis::sweepHeaderToJson(header);
  configuration["label_set"] = request.labelSet;
  configuration["train_runs"] = trainRuns;
  configuration["test_runs"] = testRuns;
  configuration["split"] = splitModeName(request.split);
  configuration["state"] = state;
  configuration["program_version"] = programVersion();
  return configuration;
}

}  // namespace

Status checkSweepRequest(const SweepRequest& request, SweepSource source) {
  if (Status grid = analysis::checkSweepGrid(request.grid); !grid) return grid;
  const bool byScene = request.split == SplitMode::ByScene;
  if (request.split == SplitMode::LeaveOneRunOut)
    return Status::failure("a sweep splits by run (training and test runs) or by scene");
  if (byScene && !request.testRuns.empty()) {
    return Status::failure(
        "a by-scene sweep scores every scene of the training runs in turn; give no test runs");
  }
  if (request.trainRuns.empty()) return Status::failure("a sweep needs training runs");
  if (source == SweepSource::Database) {
    if (request.labelSet.empty()) return Status::failure("a sweep needs a label set");
    if (!byScene && request.testRuns.empty())
      return Status::failure("a sweep needs test runs, or the by-scene split");
    if (!request.labelsFile.empty())
      return Status::failure("a label file is for run files; stored runs take a label set");
  } else {
    if (!request.labelSet.empty() || !request.name.empty())
      return Status::failure("a label set and a sweep name are for stored runs");
    if (!(request.holdout > 0.0 && request.holdout < 1.0))
      return Status::failure("the held-out share must be between 0 and 1 (both excluded)");
  }
  for (const std::string& t : request.testRuns) {
    if (std::find(request.trainRuns.begin(), request.trainRuns.end(), t) !=
        request.trainRuns.end()) {
      return Status::failure("run '" + t + "' is given both for training and for testing");
    }
  }
  if (!request.name.empty()) {
    if (Status ok = checkName(request.name, "sweep"); !ok) return ok;
  }
  if (request.threads < 0) return Status::failure("threads must be 0 (all cores) or more");
  return Status::success();
}

Result<SweepRequest> parseSweepRequest(const SweepRequestText& t, SweepSource source) {
  SweepRequest r;
  r.labelSet = t.labelSet;
  r.trainRuns = t.trainRuns;
  r.testRuns = t.testRuns;
  r.labelsFile = t.labelsFile;
  r.holdout = t.holdout;
  r.name = t.name;
  r.threads = t.threads;
  const auto split = parseSplitMode(t.split);
  if (!split || *split == SplitMode::LeaveOneRunOut)
    return failure("unknown split " + quotedInput(t.split) + " for a sweep (by-run, by-scene)");
  r.split = *split;
  analysis::SweepGrid& g = r.grid;
  auto groups =
      parseNames<SensorGroup>(t.groups, parseSensorGroup, "group (F, FLC, L, RLC, B, RRC, R, FRC)");
  if (!groups) return groups.error();
  g.groups = groups.value();
  auto methods = parseNames<analysis::ClassifierMethod>(t.methods, analysis::parseClassifierMethod,
                                                        "method (gmm, gaussian, gbt)");
  if (!methods) return methods.error();
  g.methods = methods.value();
  auto forms = parseNames<analysis::CovarianceForm>(t.covariances, analysis::parseCovarianceForm,
                                                    "covariance form");
  if (!forms) return forms.error();
  g.forms = forms.value();
  auto features =
      parseNames<analysis::FeatureKind>(t.features, analysis::parseFeatureKind, "feature kind");
  if (!features) return features.error();
  g.features = features.value();
  auto decisions = parseNames<analysis::DecisionMode>(t.decisions, analysis::parseDecisionMode,
                                                      "decision (step, online, offline)");
  if (!decisions) return decisions.error();
  g.decisions = decisions.value();
  const auto reg = analysis::parseRegularization(t.reg);
  if (!reg) return failure("unknown regularization " + quotedInput(t.reg) + " (floor, add)");
  const auto init = analysis::parseGmmInit(t.init);
  if (!init)
    return failure("unknown initialisation " + quotedInput(t.init) +
                   " (kmeans++, random-from-data)");
  g.orders = t.orders;
  g.varianceFloors = t.floors;
  g.treeCounts = t.trees;
  g.depths = t.depths;
  g.learningRates = t.learningRates;
  g.minChildWeights = t.minChildWeights;
  g.seeds = t.seeds;
  g.regularization = *reg;
  g.init = *init;
  g.restarts = t.restarts;
  g.maxIterations = t.maxIterations;
  g.tolerance = t.tolerance;
  if (Status ok = checkSweepRequest(r, source); !ok) return ok.error();
  return r;
}

Result<std::unique_ptr<analysis::SweepSession>> makeSweepSession(const SweepRequest& request,
                                                                 const SweepData& data) {
  try {
    if (request.split == SplitMode::ByScene) {
      const std::set<std::string> scenes(data.sceneOfTrain.begin(), data.sceneOfTrain.end());
      if (scenes.size() < 2) {
        return failure("a by-scene sweep needs runs of at least two scenes, found " +
                       std::to_string(scenes.size()));
      }
      return std::make_unique<analysis::SweepSession>(data.train, data.sceneOfTrain, request.grid);
    }
    return std::make_unique<analysis::SweepSession>(data.train, data.test, request.grid);
  } catch (const std::bad_alloc&) {
    return failure("out of memory while extracting the sweep's data");
  } catch (const std::exception& e) {
    return failure(e.what());
  }
}

json sweepStatusJson(const SweepStatus& status, double now) {
  json running = json::array();
  for (const storage::SweepClaim& c : status.runningClaims) {
    running.push_back({{"job", c.job},
                       {"cells", c.cells},
                       {"worker", c.worker},
                       {"attempt", c.attempts},
                       {"lease_s", c.leaseUntil - now},
                       {"lease_expired", c.leaseUntil < now}});
  }
  json failed = json::array();
  for (const storage::SweepClaim& c : status.failedClaims)
    failed.push_back(
        {{"job", c.job}, {"cells", c.cells}, {"worker", c.worker}, {"error", c.error}});
  return json{{"sweep", status.sweepId},
              {"name", status.name},
              {"state", status.state},
              {"planned", status.planned},
              {"cells", status.cells},
              {"done", status.done},
              {"pending", status.pending},
              {"running", status.running},
              {"failed", status.failed},
              {"running_jobs", std::move(running)},
              {"failed_jobs", std::move(failed)},
              {"seconds_left", status.secondsLeft ? json(*status.secondsLeft) : json(nullptr)}};
}

std::string shellQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

namespace {

// The database as a command names it: quoted only where the shell needs it.
std::string databaseWord(const std::string& database) {
  const std::string shown = storage::isServerAddress(database)
                                ? storage::shownAddress(database)
                                : std::filesystem::absolute(database).lexically_normal().string();
  const bool plain = !shown.empty() && std::all_of(shown.begin(), shown.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 ||
           std::string_view("_-./:@=+,%").find(c) != std::string_view::npos;
  });
  return plain ? shown : shellQuoted(shown);
}

}  // namespace

std::string sweepWorkCommand(const std::string& database, std::int64_t sweepId) {
  return "tactile sweep work --db " + databaseWord(database) + " --sweep " +
         std::to_string(sweepId) + " --threads 1";
}

std::string sweepSubmitCommand(const std::string& database, std::int64_t sweepId, int workers) {
  return "tactile sweep submit --db " + databaseWord(database) + " --sweep " +
         std::to_string(sweepId) + " --workers " + std::to_string(workers);
}

Result<PlannedSweep> Workspace::planSweep(const SweepRequest& request) {
  if (Status ok = checkSweepRequest(request, SweepSource::Database); !ok) return ok.error();
  auto set = db_->labels().find(request.labelSet);
  if (!set) return set.error();
  std::vector<storage::RunInfo> train, test;
  for (const auto& [names, infos] :
       {std::pair{&request.trainRuns, &train}, std::pair{&request.testRuns, &test}}) {
    for (const std::string& name : *names) {
      auto info = db_->runs().find(name);
      if (!info) return info.error();
      infos->push_back(info.value());
    }
  }
  if (request.split == SplitMode::ByScene) {
    std::set<std::string> scenes;
    for (const storage::RunInfo& r : train)
      scenes.insert(r.scene.empty() ? r.name : r.scene);
    if (scenes.size() < 2) {
      return failure("a by-scene sweep needs runs of at least two scenes, found " +
                     std::to_string(scenes.size()));
    }
  }
  const std::vector<analysis::SweepCell> cells = analysis::expandGrid(request.grid);
  const std::vector<std::vector<std::size_t>> jobs = analysis::fitJobs(cells);
  // Each job's cost in the grid's cost model, from its group's labelled contact rows, so that the
  // workers take the most expensive jobs first (the result does not depend on the order).
  auto trainRows = labelledContactSteps(request.labelSet, request.trainRuns);
  if (!trainRows) return trainRows.error();
  auto testRows = labelledContactSteps(request.labelSet, request.testRuns);
  if (!testRows) return testRows.error();
  std::vector<std::int64_t> cellsPerJob;
  std::vector<double> costPerJob;
  for (const auto& job : jobs) {
    cellsPerJob.push_back(static_cast<std::int64_t>(job.size()));
    const analysis::SweepCell& cell = cells[job.front()];
    const auto g = static_cast<std::size_t>(groupIndex(cell.group));
    costPerJob.push_back(analysis::sweepCellUnits(cell, trainRows.value()[g], testRows.value()[g]));
  }
  analysis::SweepResult header;
  header.grid = request.grid;
  const json configuration =
      sweepConfiguration(header, request, runsJson(train), runsJson(test), "planned");
  const std::string name =
      request.name.empty() ? defaultSweepName(request.labelSet, request.grid) : request.name;
  auto id = db_->sweeps().plan(name, dumpJson(configuration), cellsPerJob, costPerJob);
  if (!id) return id.error();
  return PlannedSweep{id.value(), cells.size(), jobs.size()};
}

Result<json> Workspace::sweepConfigurationOf(const storage::SweepInfo& info) {
  try {
    return json::parse(info.configurationJson);
  } catch (const json::exception& e) {
    return failure("sweep " + std::to_string(info.id) +
                   ": stored JSON is malformed: " + plainJsonError(e));
  }
}

Result<SweepRequest> Workspace::plannedRequest(std::int64_t sweepId, json* configurationOut) {
  auto info = db_->sweeps().info(sweepId);
  if (!info) return info.error();
  auto parsed = sweepConfigurationOf(info.value());
  if (!parsed) return parsed.error();
  json& configuration = parsed.value();
  SweepRequest request;
  auto grid = analysis::sweepGridFromJson(configuration.value("grid", json()));
  if (!grid) return failure("sweep " + std::to_string(sweepId) + ": " + grid.errorText());
  request.grid = grid.value();
  request.labelSet = configuration.value("label_set", std::string());
  request.trainRuns = analysis::runNamesOf(configuration.value("train_runs", json::array()));
  request.testRuns = analysis::runNamesOf(configuration.value("test_runs", json::array()));
  const auto split = parseSplitMode(configuration.value("split", std::string("by-run")));
  request.split = split.value_or(SplitMode::ByRun);
  request.name = info->name;
  if (configurationOut != nullptr) *configurationOut = std::move(configuration);
  return request;
}

Result<WorkReport> Workspace::workSweep(
    std::int64_t sweepId, const WorkOptions& options,
    const std::function<void(const analysis::SweepCellResult&)>& onCell,
    const ProgressFn& progress) {
  const auto started = std::chrono::steady_clock::now();
  json configuration;
  auto request = plannedRequest(sweepId, &configuration);
  if (!request) return request.error();
  auto claims = db_->sweeps().claims(sweepId);
  if (!claims) return claims.error();
  if (claims->empty()) {
    return failure("sweep " + std::to_string(sweepId) +
                   " was run in one process, not planned for workers (tactile sweep plan)");
  }
  if (!(options.leaseSeconds > 0.0)) return failure("the lease must be longer than 0 seconds");
  std::size_t totalCells = 0, doneCells = 0;
  bool open = false;
  for (const storage::SweepClaim& c : claims.value()) {
    totalCells += static_cast<std::size_t>(c.cells);
    if (c.state == "done") doneCells += static_cast<std::size_t>(c.cells);
    open = open || c.state == "pending" || c.state == "running";
  }
  WorkReport report;
  if (!open) return report;

  // The data: from a read-only copy when given (an SQLite snapshot on node-local disk).
  std::unique_ptr<Workspace> snapshot;
  Workspace* source = this;
  if (!options.data.empty()) {
    auto opened = Workspace::open(options.data, storage::OpenOptions{storage::OpenMode::ReadOnly});
    if (!opened) return opened.error();
    snapshot = std::move(opened.value());
    source = snapshot.get();
  }
  auto set = source->db_->labels().find(request->labelSet);
  if (!set) return set.error();
  auto train = source->loadLabelled(set->id, request->trainRuns);
  if (!train) return train.error();
  auto test = source->loadLabelled(set->id, request->testRuns);
  if (!test) return test.error();
  SweepData data;
  data.train = train->labelled;
  data.test = test->labelled;
  for (const storage::RunInfo& r : train->infos)
    data.sceneOfTrain.push_back(r.scene.empty() ? r.name : r.scene);
  auto session = makeSweepSession(request.value(), data);
  if (!session) return session.error();
  const analysis::SweepSession& s = *session.value();
  report.extractSeconds = s.extractSeconds();

  const std::string workerBase = options.worker.empty() ? defaultWorkerName() : options.worker;
  const unsigned threads =
      workerThreadCount(static_cast<unsigned>(std::max(options.threads, 0)), s.jobs().size());
  // One connection for every thread: claiming and storing take milliseconds, a fit seconds.
  std::mutex dbMutex;
  std::atomic<bool> stop{false};
  std::optional<Error> firstError;
  const auto noteError = [&](const Error& e) {
    if (!firstError) firstError = e;
    stop = true;
  };
  // The caller's progress (under dbMutex once the threads run): false stops the work; an
  // exception from it (out of memory in the caller's handler) stops it with that error.
  const auto goOn = [&]() -> bool {
    if (!progress) return true;
    try {
      return progress(doneCells, totalCells);
    } catch (const std::bad_alloc&) {
      noteError(failure("out of memory"));
    } catch (const std::exception& e) {
      noteError(failure(e.what()));
    }
    return false;
  };
  if (!goOn()) stop = true;

  parallelFor(threads, threads, [&](std::size_t t) {
    const std::string worker = threads > 1 ? workerBase + "/" + std::to_string(t + 1) : workerBase;
    while (!stop.load()) {
      std::optional<storage::SweepClaim> claim;
      double wait = 0.0;
      {
        std::lock_guard lock(dbMutex);
        if (options.maxCells > 0 && report.cells >= options.maxCells) return;
        const auto claimStart = std::chrono::steady_clock::now();
        auto claimed = db_->sweeps().claim(sweepId, worker, unixNow(), options.leaseSeconds);
        report.claimStoreSeconds += secondsSince(claimStart);
        if (!claimed) {
          noteError(claimed.error());
          return;
        }
        if (claimed.value()) {
          claim = claimed.value();
        } else {
          // Nothing pending: done unless another process still holds a claim, which this one
          // takes over should that process die (its lease runs out).
          auto all = db_->sweeps().claims(sweepId);
          if (!all) {
            noteError(all.error());
            return;
          }
          const double now = unixNow();
          for (const storage::SweepClaim& c : all.value()) {
            // This process's own claims end with its threads.
            if (c.state != "running" || c.worker.rfind(workerBase, 0) == 0) continue;
            // Looked at again soon: the other process usually finishes long before its lease
            // runs out, and this one should then return at once, not seconds later.
            const double left = std::clamp(c.leaseUntil - now, 0.05, 0.25);
            wait = wait == 0.0 ? left : std::min(wait, left);
          }
          if (wait == 0.0) return;  // nothing left
        }
      }
      if (!claim) {
        std::this_thread::sleep_for(std::chrono::duration<double>(wait));
        continue;
      }
      const std::int64_t job = claim->job;
      if (job < 0 || static_cast<std::size_t>(job) >= s.jobs().size() ||
          static_cast<std::int64_t>(s.jobs()[static_cast<std::size_t>(job)].size()) !=
              claim->cells) {
        std::lock_guard lock(dbMutex);
        (void)db_->sweeps().fail(sweepId, job, worker, "the plan does not match the sweep's grid");
        ++report.failed;
        continue;
      }
      const auto jobStart = std::chrono::steady_clock::now();
      double renewed = unixNow();
      bool lost = false;
      // After every EM iteration: stop when asked, and keep the lease while the fit runs.
      const ProgressFn keepGoing = [&](std::size_t, std::size_t) {
        if (stop.load()) return false;
        const double now = unixNow();
        if (now - renewed < options.leaseSeconds / 4) return true;
        std::lock_guard lock(dbMutex);
        renewed = now;
        auto held = db_->sweeps().renew(sweepId, job, worker, now + options.leaseSeconds);
        if (held && !held.value()) lost = true;  // taken over: another worker computes it
        if (!goOn()) stop = true;
        return !lost && !stop.load();
      };
      std::optional<std::vector<analysis::SweepCellResult>> results;
      std::string error;
      try {
        results = s.runJob(static_cast<std::size_t>(job), keepGoing);
      } catch (const std::bad_alloc&) {
        error = "out of memory";
      } catch (const std::exception& e) {
        error = e.what();
      }
      std::lock_guard lock(dbMutex);
      if (!error.empty()) {
        (void)db_->sweeps().fail(sweepId, job, worker, error);
        ++report.failed;
        continue;
      }
      if (!results) {
        if (lost) {
          ++report.overtaken;
        } else {
          (void)db_->sweeps().release(sweepId, job, worker);  // stopped: pending again
        }
        continue;
      }
      std::vector<std::pair<std::string, std::string>> cells;
      for (const analysis::SweepCellResult& c : *results) {
        cells.emplace_back(dumpJson(analysis::sweepCellSettingsToJson(c.cell)),
                           dumpJson(analysis::sweepCellToJson(c)));
      }
      const double seconds = secondsSince(jobStart);
      const auto storeStart = std::chrono::steady_clock::now();
      auto stored = db_->sweeps().complete(sweepId, job, worker, seconds, cells);
      report.claimStoreSeconds += secondsSince(storeStart);
      if (!stored) {
        noteError(stored.error());
        return;
      }
      if (!stored.value()) {
        ++report.overtaken;
        continue;
      }
      ++report.jobs;
      report.cells += results->size();
      doneCells += results->size();
      for (const analysis::SweepCellResult& c : *results)
        if (onCell) onCell(c);
      if (!goOn()) stop = true;
    }
  });
  report.cancelled = stop.load() && !firstError;
  report.seconds = secondsSince(started);
  if (firstError) return firstError.value();

  // The last worker out records the sweep's final state and data summary (any worker computes
  // the same summary from the same data).
  auto after = sweepStatus(sweepId);
  if (after && after->pending == 0 && after->running == 0) {
    analysis::SweepResult header;
    header.grid = request->grid;
    header.data = s.data();
    header.extractSeconds = s.extractSeconds();
    header.threads = static_cast<int>(threads);
    header.wallSeconds = report.seconds;
    json final = sweepConfiguration(
        header, request.value(), configuration.value("train_runs", json::array()),
        configuration.value("test_runs", json::array()), after->failed > 0 ? "failed" : "finished");
    if (after->failed > 0) {
      final["error"] = after->failedClaims.front().error;
    }
    if (Status st = db_->sweeps().update(sweepId, dumpJson(final)); !st) return st.error();
  } else {
    const std::string state = report.cancelled ? "cancelled" : "running";
    if (configuration.value("state", std::string()) != state) {
      configuration["state"] = state;
      configuration["cancelled"] = report.cancelled;
      (void)db_->sweeps().update(sweepId, dumpJson(configuration));  // best effort
    }
  }
  return report;
}

Result<SweepStatus> Workspace::sweepStatus(std::int64_t sweepId) {
  auto info = db_->sweeps().info(sweepId);
  if (!info) return info.error();
  auto claims = db_->sweeps().claims(sweepId);
  if (!claims) return claims.error();
  SweepStatus status;
  status.sweepId = sweepId;
  status.name = info->name;
  try {
    status.state = json::parse(info->configurationJson).value("state", std::string());
  } catch (const json::exception&) {
    status.state.clear();
  }
  if (claims->empty()) {
    // Run in one process before sweeps were planned: its stored cells are all there is.
    status.planned = false;
    status.cells = static_cast<std::size_t>(info->cellCount);
    status.done = status.cells;
    return status;
  }
  const double now = unixNow();
  std::size_t doneJobs = 0, openJobs = 0;
  double doneSeconds = 0.0;
  std::set<std::string> workers;
  for (const storage::SweepClaim& c : claims.value()) {
    const auto n = static_cast<std::size_t>(c.cells);
    status.cells += n;
    if (c.state == "done") {
      status.done += n;
      ++doneJobs;
      doneSeconds += c.seconds;
    } else if (c.state == "pending") {
      status.pending += n;
      ++openJobs;
    } else if (c.state == "running") {
      status.running += n;
      ++openJobs;
      status.runningClaims.push_back(c);
      if (c.leaseUntil >= now) workers.insert(c.worker);
    } else {
      status.failed += n;
      status.failedClaims.push_back(c);
    }
  }
  if (openJobs == 0) {
    status.secondsLeft = 0.0;
  } else if (doneJobs > 0 && !workers.empty()) {
    status.secondsLeft = doneSeconds / static_cast<double>(doneJobs) *
                         static_cast<double>(openJobs) / static_cast<double>(workers.size());
  }
  if (status.state == "planned" && (status.done > 0 || status.running > 0))
    status.state = "running";
  return status;
}

Result<SweepOutcome> Workspace::sweep(
    const SweepRequest& request,
    const std::function<void(const analysis::SweepCellResult&)>& onCell,
    const ProgressFn& progress) {
  auto planned = planSweep(request);
  if (!planned) return planned.error();
  WorkOptions options;
  options.threads = request.threads;
  auto work = workSweep(planned->sweepId, options, onCell, progress);
  if (!work) {
    // A sweep that stops on an error is marked failed, never left "running".
    json configuration;
    if (plannedRequest(planned->sweepId, &configuration)) {
      configuration["state"] = "failed";
      configuration["error"] = work.errorText();
      (void)db_->sweeps().update(planned->sweepId, dumpJson(configuration));  // best effort
    }
    return failure("sweep " + std::to_string(planned->sweepId) + ": " + work.errorText());
  }
  if (work->failed > 0) {
    // The other jobs ran and are stored; the sweep is marked failed with the first job's error.
    auto status = sweepStatus(planned->sweepId);
    const std::string error = status && !status->failedClaims.empty()
                                  ? status->failedClaims.front().error
                                  : std::string("a job failed");
    return failure("sweep " + std::to_string(planned->sweepId) + ": " + error);
  }
  auto result = loadSweep(planned->sweepId);
  if (!result) return result.error();
  SweepOutcome outcome;
  outcome.sweepId = planned->sweepId;
  outcome.result = std::move(result.value());
  outcome.result.cancelled = work->cancelled;
  outcome.result.threads = static_cast<int>(
      workerThreadCount(static_cast<unsigned>(std::max(request.threads, 0)), planned->jobs));
  outcome.result.wallSeconds = work->seconds;
  outcome.result.extractSeconds = work->extractSeconds;
  return outcome;
}

}  // namespace tactile::workspace
