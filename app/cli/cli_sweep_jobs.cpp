// Sweeps planned for workers (docs/cluster.md): `tactile sweep plan` stores a sweep with every job
// pending, `sweep work` claims and computes jobs, `sweep status` says where it stands, `sweep
// submit` starts workers as a Slurm job array, `sweeps export` writes the sweep as SWEEP.json.
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "analysis/sweep.h"
#include "app/cli/cli_common.h"
#include "app/cli/cli_sweep.h"
#include "base/file_text.h"
#include "run/json_text.h"
#include "storage/run_database.h"
#include "workspace/workspace.h"

namespace tactile::cli {
namespace {

using nlohmann::json;

std::unique_ptr<workspace::Workspace> workspaceOf(const std::string& db, bool create) {
  if (db.empty()) throw UsageError("give --db DB (a file or a postgresql:// address)");
  return std::make_unique<workspace::Workspace>(create ? openDatabaseOrCreate(db)
                                                       : openDatabaseForRead(db));
}

double unixNow() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// ---- plan

struct PlanArgs {
  std::string db;
  workspace::SweepRequestText request;
  bool json = false;
};

int runPlan(const PlanArgs& a) {
  workspace::SweepRequestText text = a.request;
  text.testRuns = splitNames(text.testRuns);
  const workspace::SweepRequest request =
      sweepRequestOrUsage(text, workspace::SweepSource::Database);
  auto ws = workspaceOf(a.db, true);
  auto planned = ws->planSweep(request);
  if (!planned) throw std::runtime_error(a.db + ": " + planned.errorText());
  if (a.json) {
    std::cout << dumpJson(json{{"sweep", planned->sweepId},
                               {"cells", planned->cells},
                               {"jobs", planned->jobs}})
              << "\n";
  } else {
    std::printf(
        "sweep %lld planned: %zu cells in %zu jobs, all pending; start workers with\n"
        "  %s\nor submit them to Slurm with\n  %s\n",
        static_cast<long long>(planned->sweepId), planned->cells, planned->jobs,
        workspace::sweepWorkCommand(a.db, planned->sweepId).c_str(),
        workspace::sweepSubmitCommand(a.db, planned->sweepId, 4).c_str());
  }
  return kExitOk;
}

// ---- work

struct WorkArgs {
  std::string db;
  std::int64_t sweep = 0;
  int threads = 1;
  std::size_t maxCells = 0;
  std::string worker;
  double lease = 120.0;
  std::string data;
  bool progress = false;
  bool json = false;
};

int runWork(const WorkArgs& a) {
  if (a.sweep <= 0) throw UsageError("give --sweep ID (see tactile sweeps list)");
  if (a.threads < 0) throw UsageError("--threads must be 0 (all cores) or more");
  checkNumberOption("--lease", a.lease, 0.0, RangeEnd::Open, HUGE_VAL, RangeEnd::Open);
  auto ws = workspaceOf(a.db, true);
  workspace::WorkOptions options;
  options.threads = a.threads;
  options.maxCells = a.maxCells;
  options.worker = a.worker;
  options.leaseSeconds = a.lease;
  options.data = a.data;
  ProgressFn progress;
  if (a.progress) {
    progress = [line = ProgressLine("sweep work", "cells")](std::size_t done,
                                                            std::size_t total) mutable {
      line.show(done, total);
      return true;
    };
  }
  auto report = ws->workSweep(a.sweep, options, {}, progress);
  if (!report) throw std::runtime_error(a.db + ": " + report.errorText());
  if (a.json) {
    std::cout << dumpJson(json{{"sweep", a.sweep},
                               {"jobs", report->jobs},
                               {"cells", report->cells},
                               {"failed", report->failed},
                               {"overtaken", report->overtaken},
                               {"extract_s", report->extractSeconds},
                               {"claim_store_s", report->claimStoreSeconds},
                               {"wall_s", report->seconds}})
              << "\n";
  } else {
    std::printf("sweep %lld: this worker stored %zu cells (%zu jobs) in %.2f s%s\n",
                static_cast<long long>(a.sweep), report->cells, report->jobs, report->seconds,
                report->failed > 0 ? "; some jobs failed (tactile sweep status)" : "");
  }
  return report->failed > 0 ? kExitFailure : kExitOk;
}

// ---- status

struct StatusArgs {
  std::string db;
  std::int64_t sweep = 0;
  bool json = false;
};

int runStatus(const StatusArgs& a) {
  if (a.sweep <= 0) throw UsageError("give --sweep ID (see tactile sweeps list)");
  auto ws = workspaceOf(a.db, false);
  auto status = ws->sweepStatus(a.sweep);
  if (!status) throw std::runtime_error(a.db + ": " + status.errorText());
  const double now = unixNow();
  if (a.json) {
    std::cout << dumpJson(workspace::sweepStatusJson(status.value(), now)) << "\n";
    return kExitOk;
  }
  const workspace::SweepStatus& s = status.value();
  std::printf("sweep %lld (%s): %s; %zu cells: %zu done, %zu running, %zu pending, %zu failed\n",
              static_cast<long long>(s.sweepId), s.name.c_str(), s.state.c_str(), s.cells, s.done,
              s.running, s.pending, s.failed);
  for (const storage::SweepClaim& c : s.runningClaims) {
    std::printf("  job %lld (%lld cells): %s, lease %s %.0f s\n", static_cast<long long>(c.job),
                static_cast<long long>(c.cells), c.worker.c_str(),
                c.leaseUntil < now ? "ran out" : "left", std::abs(c.leaseUntil - now));
  }
  for (const storage::SweepClaim& c : s.failedClaims) {
    std::printf("  job %lld failed on %s: %s\n", static_cast<long long>(c.job), c.worker.c_str(),
                c.error.c_str());
  }
  if (s.secondsLeft) std::printf("  about %.0f s left\n", *s.secondsLeft);
  return kExitOk;
}

// ---- submit

struct SubmitArgs {
  std::string db;
  std::int64_t sweep = 0;
  int workers = 1;
  int threads = 1;
  std::string partition;
  std::string time;
  std::vector<std::string> sbatchArgs;
  std::string script;
  std::string logs;
  double lease = 120.0;
  bool dryRun = false;
  bool json = false;
};

std::string thisProgram() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("tactile") : self.string();
}

// The job-array script: each task runs one `tactile sweep work`. With an SQLite database the
// task first copies the runs and labels it reads to node-local disk ($TMPDIR) and reads them
// from there; only the claims and the results go to the database file.
std::string jobScript(const SubmitArgs& a, const workspace::SweepRequest& request, bool sqlite) {
  std::string s = "#!/bin/bash\n";
  s += "#SBATCH --job-name=tactile-sweep-" + std::to_string(a.sweep) + "\n";
  s += "#SBATCH --cpus-per-task=" + std::to_string(a.threads) + "\n";
  s += "#SBATCH --output=" + a.logs + "/tactile-sweep-" + std::to_string(a.sweep) + "-%A_%a.out\n";
  if (!a.partition.empty()) s += "#SBATCH --partition=" + a.partition + "\n";
  if (!a.time.empty()) s += "#SBATCH --time=" + a.time + "\n";
  for (const std::string& extra : a.sbatchArgs)
    s += "#SBATCH " + extra + "\n";
  s += "# Submitted with: sbatch --array=0-" + std::to_string(a.workers - 1) + " THIS_SCRIPT\n";
  s += "set -euo pipefail\n";
  s += "TACTILE=" + workspace::shellQuoted(thisProgram()) + "\n";
  s += "DB=" + workspace::shellQuoted(a.db) + "\n";
  s += "WORKER=\"${SLURM_ARRAY_JOB_ID:-0}_${SLURM_ARRAY_TASK_ID:-0}@$(hostname -s)\"\n";
  std::string data;
  if (sqlite) {
    std::string runs;
    for (const auto* list : {&request.trainRuns, &request.testRuns})
      for (const std::string& r : *list)
        runs += (runs.empty() ? "" : ",") + r;
    s += "# Never SQLite over a network share: the runs and labels are read from a copy on\n"
         "# node-local disk.\n";
    s += "SNAPSHOT_DIR=$(mktemp -d \"${TMPDIR:-/tmp}/tactile-sweep-XXXXXX\")\n";
    s += "trap 'rm -rf \"$SNAPSHOT_DIR\"' EXIT\n";
    s += "\"$TACTILE\" db copy --from \"$DB\" --to \"$SNAPSHOT_DIR/data.db\" --runs " +
         workspace::shellQuoted(runs) + " --sets " + workspace::shellQuoted(request.labelSet) +
         " > /dev/null\n";
    data = " --data \"$SNAPSHOT_DIR/data.db\"";
  }
  char lease[32];
  std::snprintf(lease, sizeof lease, "%g", a.lease);
  // With a snapshot the shell stays to remove it afterwards (exec would skip the trap).
  s += std::string(sqlite ? "" : "exec ") + "\"$TACTILE\" sweep work --db \"$DB\" --sweep " +
       std::to_string(a.sweep) + " --threads " + std::to_string(a.threads) +
       " --worker \"$WORKER\" --lease " + lease + data + "\n";
  return s;
}

int runSubmit(const SubmitArgs& a) {
  if (a.sweep <= 0) throw UsageError("give --sweep ID (see tactile sweeps list)");
  if (a.workers < 1) throw UsageError("--workers must be at least 1");
  if (a.threads < 1) throw UsageError("--threads must be at least 1");
  checkNumberOption("--lease", a.lease, 0.0, RangeEnd::Open, HUGE_VAL, RangeEnd::Open);
  auto ws = workspaceOf(a.db, false);
  auto request = ws->plannedRequest(a.sweep);
  if (!request) throw std::runtime_error(a.db + ": " + request.errorText());
  auto status = ws->sweepStatus(a.sweep);
  if (!status) throw std::runtime_error(a.db + ": " + status.errorText());
  if (!status->planned) {
    throw std::runtime_error(a.db + ": sweep " + std::to_string(a.sweep) +
                             " was run in one process, not planned for workers");
  }
  const bool sqlite = !storage::isServerAddress(a.db);
  SubmitArgs args = a;
  if (sqlite) args.db = std::filesystem::absolute(a.db).string();
  if (args.logs.empty()) args.logs = std::filesystem::current_path().string();
  const std::string script =
      args.script.empty() ? "tactile-sweep-" + std::to_string(a.sweep) + ".sbatch" : args.script;
  const std::string text = jobScript(args, request.value(), sqlite);
  if (Status written = writeFileAtomically(script, text); !written)
    throw std::runtime_error(written.errorText());
  std::error_code ec;
  std::filesystem::permissions(script, std::filesystem::perms::owner_exec,
                               std::filesystem::perm_options::add, ec);
  const std::string array = "--array=0-" + std::to_string(a.workers - 1);
  std::string jobId;
  if (!a.dryRun) {
    const std::string command = "sbatch --parsable " + array + " " + workspace::shellQuoted(script);
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) throw std::runtime_error("cannot run sbatch");
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr)
      jobId += buffer;
    const int rc = pclose(pipe);
    while (!jobId.empty() && (jobId.back() == '\n' || jobId.back() == '\r'))
      jobId.pop_back();
    if (rc != 0 || jobId.empty()) {
      throw std::runtime_error("sbatch " + array + " " + script + " failed (exit " +
                               std::to_string(WIFEXITED(rc) ? WEXITSTATUS(rc) : rc) +
                               "); the script is left in " + script);
    }
    // --parsable prints "JOBID" or "JOBID;CLUSTER".
    jobId = jobId.substr(0, jobId.find(';'));
  }
  if (a.json) {
    std::cout << dumpJson(json{{"sweep", a.sweep},
                               {"script", script},
                               {"workers", a.workers},
                               {"array", array},
                               {"job", a.dryRun ? json(nullptr) : json(jobId)}})
              << "\n";
  } else if (a.dryRun) {
    std::printf("wrote %s; submit it with: sbatch %s %s\n", script.c_str(), array.c_str(),
                script.c_str());
  } else {
    std::printf(
        "submitted job %s: %d workers of sweep %lld (script %s); follow it with\n"
        "  tactile sweep status --db %s --sweep %lld\n",
        jobId.c_str(), a.workers, static_cast<long long>(a.sweep), script.c_str(),
        storage::shownAddress(a.db).c_str(), static_cast<long long>(a.sweep));
  }
  return kExitOk;
}

// ---- export

struct ExportArgs {
  std::string db;
  std::int64_t sweep = 0;
  std::string out;
  bool json = false;
};

int runExport(const ExportArgs& a) {
  if (a.sweep <= 0) throw UsageError("give --sweep ID (see tactile sweeps list)");
  if (a.out.empty()) throw UsageError("give --out SWEEP.json");
  auto ws = workspaceOf(a.db, false);
  auto sweep = ws->loadSweep(a.sweep);
  if (!sweep) throw std::runtime_error(a.db + ": " + sweep.errorText());
  const std::string text = dumpJson(analysis::sweepToJson(sweep.value()), 1) + "\n";
  if (a.out == "-") {
    std::fwrite(text.data(), 1, text.size(), stdout);
  } else if (Status written = writeFileAtomically(a.out, text); !written) {
    throw std::runtime_error(written.errorText());
  }
  if (a.json && a.out != "-") {
    std::cout << dumpJson(json{{"sweep", a.sweep}, {"cells", sweep->cells.size()}, {"out", a.out}})
              << "\n";
  }
  return kExitOk;
}

void addDbOption(CLI::App* cmd, std::string& db) {
  cmd->add_option("--db", db, "Database (a file or a postgresql:// address; default TACTILE_DB)");
}

}  // namespace

void registerSweepJobVerbs(CLI::App& sweep) {
  {
    auto args = std::make_shared<PlanArgs>();
    CLI::App* cmd = sweep.add_subcommand(
        "plan",
        "Store a sweep with every cell pending, for `tactile sweep work` processes on any "
        "machines (docs/cluster.md)");
    addDbOption(cmd, args->db);
    addSweepRequestOptions(cmd, args->request);
    cmd->add_flag("--json", args->json, R"(Print {"sweep": ID, "cells": N, "jobs": J})");
    setAction(cmd, [args] {
      PlanArgs a = *args;
      if (a.db.empty()) a.db = databaseFromEnvironment();
      return runPlan(a);
    });
  }
  {
    auto args = std::make_shared<WorkArgs>();
    CLI::App* cmd = sweep.add_subcommand(
        "work",
        "Claim pending cells of a planned sweep one job at a time, compute and store them, until "
        "none is left (a claim whose worker died is taken over when its lease runs out)");
    addDbOption(cmd, args->db);
    cmd->add_option("--sweep", args->sweep, "Sweep id (tactile sweep plan)")->required();
    cmd->add_option("--threads", args->threads, "Jobs computed at once (0 = all cores)")
        ->capture_default_str();
    cmd->add_option("--max-cells", args->maxCells,
                    "Stop after storing at least this many cells (0: until none is left)")
        ->capture_default_str();
    cmd->add_option("--worker", args->worker, "Name the claims carry (default HOST:PID)");
    cmd->add_option("--lease", args->lease,
                    "Seconds a claim stays this worker's without renewal (renewed while it "
                    "computes)")
        ->capture_default_str();
    cmd->add_option("--data", args->data,
                    "Read the runs and labels from this read-only copy (an SQLite file on "
                    "node-local disk) instead of --db");
    cmd->add_flag("--progress", args->progress, "Print progress on stderr");
    cmd->add_flag("--json", args->json, "Print a JSON summary");
    setAction(cmd, [args] {
      WorkArgs a = *args;
      if (a.db.empty()) a.db = databaseFromEnvironment();
      return runWork(a);
    });
  }
  {
    auto args = std::make_shared<StatusArgs>();
    CLI::App* cmd = sweep.add_subcommand(
        "status",
        "Where a planned sweep stands: cells done, running (worker and lease), pending, failed "
        "(with the error), and the time left");
    addDbOption(cmd, args->db);
    cmd->add_option("--sweep", args->sweep, "Sweep id")->required();
    cmd->add_flag("--json", args->json,
                  R"(Print {"done","pending","running","failed","running_jobs",...})");
    setAction(cmd, [args] {
      StatusArgs a = *args;
      if (a.db.empty()) a.db = databaseFromEnvironment();
      return runStatus(a);
    });
  }
  {
    auto args = std::make_shared<SubmitArgs>();
    CLI::App* cmd = sweep.add_subcommand(
        "submit",
        "Write a Slurm job-array script whose tasks each run `tactile sweep work`, and submit it "
        "with sbatch --array=0-(N-1) (docs/cluster.md)");
    addDbOption(cmd, args->db);
    cmd->add_option("--sweep", args->sweep, "Sweep id (tactile sweep plan)")->required();
    cmd->add_option("--workers", args->workers, "Array tasks")->required();
    cmd->add_option("--threads", args->threads, "Threads (CPUs) per task")->capture_default_str();
    cmd->add_option("--partition", args->partition, "Slurm partition");
    cmd->add_option("--time", args->time, "Slurm time limit per task (e.g. 2:00:00)");
    cmd->add_option("--sbatch-arg", args->sbatchArgs,
                    "Another #SBATCH line for the script (repeatable), e.g. --sbatch-arg=--mem=4G")
        ->allow_extra_args(false);
    cmd->add_option("--script", args->script,
                    "Where the script goes (default tactile-sweep-ID.sbatch here)");
    cmd->add_option("--logs", args->logs, "Folder of the tasks' output (default here)");
    cmd->add_option("--lease", args->lease, "The workers' lease, seconds")->capture_default_str();
    cmd->add_flag("--dry-run", args->dryRun, "Write the script, do not submit it");
    cmd->add_flag("--json", args->json, R"(Print {"sweep","script","workers","array","job"})");
    setAction(cmd, [args] {
      SubmitArgs a = *args;
      if (a.db.empty()) a.db = databaseFromEnvironment();
      return runSubmit(a);
    });
  }
}

void registerSweepExportVerb(CLI::App& sweeps) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* cmd = sweeps.add_subcommand(
      "export", "Write a stored sweep as SWEEP.json (what `tactile sweep ... --out` writes)");
  addDbOption(cmd, args->db);
  cmd->add_option("--sweep", args->sweep, "Sweep id")->required();
  cmd->add_option("--out", args->out, "SWEEP.json to write (- for stdout)")->required();
  cmd->add_flag("--json", args->json, R"(Print {"sweep","cells","out"})");
  setAction(cmd, [args] {
    ExportArgs a = *args;
    if (a.db.empty()) a.db = databaseFromEnvironment();
    return runExport(a);
  });
}

}  // namespace tactile::cli
