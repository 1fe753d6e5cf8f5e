// Database verbs: import, export-run, autolabel, db check, db create, bench storage (the `runs` and
// `labels` verbs are in cli_catalog.cpp).
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "app/cli/cli_common.h"
#include "app/cli/cli_mcap.h"
#include "run/json_text.h"
#include "run/run_csv.h"
#include "sim/scene_source.h"
#include "storage/run_database.h"
#include "storage/synthetic_run.h"
#include "workspace/run_inputs.h"

namespace tactile::cli {
namespace {

namespace fs = std::filesystem;
using storage::ImportStatus;
using storage::OpenMode;
using storage::RunDatabase;

std::unique_ptr<RunDatabase> openDatabase(const std::string& path, OpenMode mode) {
  auto db = RunDatabase::open(path, mode);
  if (!db) {
    // Every open error names the file (Error::file); the CLI prints "DB: message".
    const Error& error = db.error();
    throw std::runtime_error(error.file.empty() ? storage::shownAddress(path) + ": " + error.message
                                                : error.text());
  }
  if (!db.value()->migrationBackup().empty()) {
    printWarning("migrated '" + path + "' to the current schema; the old file was copied to " +
                 db.value()->migrationBackup().string());
  }
  return std::move(db.value());
}

// "DB: message" for an error of the database at `dbPath`: SQLite errors already name it
// (Error::file), others (e.g. "no run named ...") get it here; errors about another file (an
// output file) keep theirs.
std::string databaseError(const std::string& dbPath, const Error& error) {
  return error.file.empty() ? storage::shownAddress(dbPath) + ": " + error.message : error.text();
}

}  // namespace

std::unique_ptr<RunDatabase> openDatabaseForRead(const std::string& path) {
  return openDatabase(path, OpenMode::ReadOnly);
}
std::string databaseFromEnvironment() {
  const char* db = std::getenv("TACTILE_DB");
  return db == nullptr ? std::string() : std::string(db);
}

std::unique_ptr<RunDatabase> openDatabaseForWrite(const std::string& path) {
  return openDatabase(path, OpenMode::ReadWrite);
}
std::unique_ptr<RunDatabase> openDatabaseOrCreate(const std::string& path) {
  return openDatabase(path, OpenMode::Create);
}

namespace {

void printJson(const nlohmann::json& doc) {
  std::printf("%s\n", dumpJson(doc).c_str());
}

// ---- import ----------------------------------------------------------------------------------

struct ImportArgs {
  std::string db;
  std::vector<std::string> files;
  std::string name;
  std::string prefix;
  unsigned threads = 0;
  std::string mapping;
  bool json = false;
};

int runImport(const ImportArgs& a) {
  // MCAP files (an export of this program, or a ROS 2 bag with --mapping): cli_mcap.cpp.
  const auto mcapFiles = std::count_if(a.files.begin(), a.files.end(), isMcapPath);
  if (mcapFiles > 0) {
    if (static_cast<std::size_t>(mcapFiles) != a.files.size()) {
      throw UsageError("give MCAP files and run files in separate imports");
    }
    if (!a.prefix.empty()) throw UsageError("--prefix applies to run files, not MCAP files");
    return runMcapImport(a.db, a.files, a.mapping, a.name, a.json);
  }
  if (!a.mapping.empty()) throw UsageError("--mapping applies to MCAP files (*.mcap) only");
  // A folder given with --name holding several files: each fails ("only for a single file").
  if (!a.name.empty() && a.files.size() != 1) {
    throw UsageError("--name needs exactly one file, got " + std::to_string(a.files.size()));
  }
  if (!a.name.empty() && !a.prefix.empty()) throw UsageError("give --name or --prefix, not both");
  if (!a.name.empty()) requireValidName(a.name, "--name", "run");
  if (!a.prefix.empty()) requireValidName(a.prefix, "--prefix", "run");
  auto db = openDatabaseOrCreate(a.db);
  storage::ImportOptions options;
  options.name = a.name;
  options.namePrefix = a.prefix;
  options.threads = a.threads;
  options.sceneResolver = sim::proceduralSceneJson;
  const auto t0 = std::chrono::steady_clock::now();
  auto imported = workspace::importRunInputs(*db, {a.files.begin(), a.files.end()}, options);
  if (!imported) throw std::runtime_error(imported.errorText());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const std::string& warning : imported->warnings)
    printWarning(warning);
  const std::vector<storage::ImportOutcome>& outcomes = imported->outcomes;
  nlohmann::json runs = nlohmann::json::array();
  nlohmann::json skipped = nlohmann::json::array();
  nlohmann::json failed = nlohmann::json::array();
  std::int64_t steps = 0;
  for (const auto& outcome : outcomes) {
    for (const std::string& warning : outcome.warnings)
      printWarning(warning);
    switch (outcome.status) {
      case ImportStatus::Imported:
        steps += outcome.steps;
        runs.push_back({{"name", outcome.runName},
                        {"id", outcome.runId},
                        {"steps", outcome.steps},
                        {"file", outcome.file}});
        if (!a.json) {
          std::printf("imported %s as run '%s' (id %lld, %lld steps)\n", outcome.file.c_str(),
                      outcome.runName.c_str(), static_cast<long long>(outcome.runId),
                      static_cast<long long>(outcome.steps));
        }
        break;
      case ImportStatus::Skipped:
        skipped.push_back({{"file", outcome.file},
                           {"name", outcome.runName},
                           {"id", outcome.runId},
                           {"message", outcome.message}});
        if (!a.json) std::printf("skipped %s\n", outcome.message.c_str());
        break;
      case ImportStatus::Failed:
        failed.push_back({{"file", outcome.file}, {"message", outcome.message}});
        printError(outcome.message);
        break;
    }
  }
  if (a.json) {
    printJson({{"runs", runs},
               {"skipped", skipped},
               {"failed", failed},
               {"steps", steps},
               {"seconds", seconds}});
  } else if (outcomes.size() > 1) {
    std::printf("%zu imported, %zu skipped, %zu failed; %lld steps in %.3f s\n", runs.size(),
                skipped.size(), failed.size(), static_cast<long long>(steps), seconds);
  }
  return failed.empty() ? kExitOk : kExitFailure;
}

// ---- export-run ------------------------------------------------------------------------------

int runExport(const std::string& dbPath, const std::string& runName, const std::string& out,
              const std::string& format, const std::vector<std::string>& sets,
              const std::string& model, bool json) {
  if (format != "csv" && format != "mcap" && !format.empty()) {
    throw UsageError("--format must be csv or mcap, got '" + format + "'");
  }
  if (format == "mcap" || (format.empty() && isMcapPath(out))) {
    return runMcapExport(dbPath, runName, out, sets, model, json);
  }
  if (!sets.empty() || !model.empty()) {
    throw UsageError("--sets and --model apply to --format mcap only");
  }
  auto db = openDatabaseForRead(dbPath);
  auto run = db->runs().find(runName);
  if (!run) throw std::runtime_error(databaseError(dbPath, run.error()));
  const auto status = db->runs().exportRun(run->id, out);
  // SQLite errors name the database (Error::file), write errors the output file.
  if (!status) throw std::runtime_error(status.errorText());
  if (json) {
    printJson({{"run", run->name}, {"id", run->id}, {"steps", run->stepCount}, {"out", out}});
  }
  return kExitOk;
}

// ---- autolabel -------------------------------------------------------------------------------

int runAutolabel(const std::string& dbPath, const std::string& runName, bool all,
                 const std::string& set, bool json) {
  if (all == !runName.empty()) throw UsageError("give exactly one of --run NAME or --all");
  requireValidName(set, "--set", "label set");
  auto db = openDatabaseOrCreate(dbPath);
  std::vector<storage::RunInfo> runs;
  if (all) {
    auto listed = db->runs().list();
    if (!listed) throw std::runtime_error(databaseError(dbPath, listed.error()));
    runs = std::move(listed.value());
  } else {
    auto run = db->runs().find(runName);
    if (!run) throw std::runtime_error(databaseError(dbPath, run.error()));
    runs.push_back(std::move(run.value()));
  }
  nlohmann::json labelled = nlohmann::json::array();
  int failures = 0;
  std::vector<std::string> printed;
  for (const auto& run : runs) {
    if (all && !run.hasTruth) {
      printWarning("run '" + run.name + "' has no truth columns; not labelled");
      continue;
    }
    auto count = db->labels().autolabel(run.id, set);
    if (!count) {
      // One line per distinct error: a failure of the database (not of this run) would otherwise
      // repeat for every run.
      const std::string message = databaseError(dbPath, count.error());
      if (std::find(printed.begin(), printed.end(), message) == printed.end()) {
        printError(message);
        printed.push_back(message);
      }
      ++failures;
      continue;
    }
    labelled.push_back({{"run", run.name}, {"segments", count.value()}});
    if (!json) {
      std::printf("labelled run '%s': %lld segments in set '%s'\n", run.name.c_str(),
                  static_cast<long long>(count.value()), set.c_str());
    }
  }
  if (json) printJson({{"set", set}, {"runs", labelled}});
  if (failures > 0) return kExitFailure;
  if (labelled.empty()) {
    printError(runs.empty() ? "the database holds no runs" : "no run has truth columns");
    return kExitFailure;
  }
  return kExitOk;
}

// ---- db check --------------------------------------------------------------------------------

int runCheck(const std::string& dbPath, bool json) {
  auto db = openDatabaseForRead(dbPath);
  const storage::IntegrityReport report = db->check();
  if (json) {
    // Every count; the first cases of each kind (storage::kIntegrityCasesKept).
    nlohmann::json kinds = nlohmann::json::array();
    for (const storage::IntegrityProblemKind& kind : report.kinds) {
      kinds.push_back({{"kind", kind.kind},
                       {"count", kind.count},
                       {"cases", kind.cases},
                       {"more", kind.count - static_cast<std::int64_t>(kind.cases.size())}});
    }
    printJson({{"ok", report.ok},
               {"schema_version", report.schemaVersion},
               {"runs", report.runs},
               {"steps", report.steps},
               {"label_sets", report.labelSets},
               {"problem_kinds", kinds},
               {"problems", report.problems}});
  } else {
    // A summary per kind: the count, the first cases, then "and N more" (a damaged table can
    // have thousands of rows of one kind).
    for (const storage::IntegrityProblemKind& kind : report.kinds) {
      printError(dbPath + ": " + std::to_string(kind.count) + " problem" +
                 (kind.count == 1 ? "" : "s") + " of kind '" + kind.kind + "'");
      for (const std::string& text : kind.cases)
        printError(dbPath + ":   " + text);
      const std::int64_t more = kind.count - static_cast<std::int64_t>(kind.cases.size());
      if (more > 0) printError(dbPath + ":   and " + std::to_string(more) + " more");
    }
    std::printf("%s: %s, schema version %d, %lld runs, %lld steps, %lld label sets\n",
                dbPath.c_str(), report.ok ? "ok" : "DAMAGED", report.schemaVersion,
                static_cast<long long>(report.runs), static_cast<long long>(report.steps),
                static_cast<long long>(report.labelSets));
  }
  return report.ok ? kExitOk : kExitFailure;
}

// ---- db create -------------------------------------------------------------------------------

// Makes a new, empty database (or an empty file into one); an existing Tactile database is left
// as it is (migrated when older). Anything else is refused unchanged.
int runCreate(const std::string& dbPath, bool json) {
  auto db = openDatabaseOrCreate(dbPath);
  const std::string shown = db->path().string();
  const storage::IntegrityReport report = db->check();
  if (json) {
    printJson({{"db", shown},
               {"created", db->created()},
               {"schema_version", report.schemaVersion},
               {"runs", report.runs}});
  } else if (!db->created()) {
    std::printf("%s: already a Tactile database (schema version %d, %lld runs); left as it is\n",
                shown.c_str(), report.schemaVersion, static_cast<long long>(report.runs));
  } else {
    std::printf("created %s (schema version %d)\n", shown.c_str(), report.schemaVersion);
  }
  return kExitOk;
}

// ---- db copy -----------------------------------------------------------------------------------

int runCopy(const std::string& from, const std::string& to, const std::vector<std::string>& runs,
            const std::vector<std::string>& sets, bool json) {
  if (storage::shownAddress(from) == storage::shownAddress(to)) {
    throw UsageError("--from and --to name the same database");
  }
  auto source = openDatabaseForRead(from);
  auto target = openDatabaseOrCreate(to);
  storage::CopyOptions options;
  options.runs = splitNames(runs);
  options.sets = splitNames(sets);
  const auto started = std::chrono::steady_clock::now();
  auto report = target->copyFrom(*source, options);
  if (!report) throw std::runtime_error(report.errorText());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  for (const std::string& warning : report->warnings)
    printWarning(warning);
  if (json) {
    printJson({{"from", source->path().string()},
               {"to", target->path().string()},
               {"runs_copied", report->runsCopied},
               {"runs_present", report->runsPresent},
               {"steps_copied", report->stepsCopied},
               {"label_sets_created", report->setsCreated},
               {"segments_copied", report->segmentsCopied},
               {"segments_without_run", report->segmentsWithoutRun},
               {"label_revisions_copied", report->revisionsCopied},
               {"models_copied", report->modelsCopied},
               {"sweeps_copied", report->sweepsCopied},
               {"seconds", seconds}});
  } else {
    std::printf(
        "%lld runs copied (%lld steps), %lld already there; %lld label segments copied (%lld "
        "history entries), %lld models, %lld sweeps; %.3f s\n",
        static_cast<long long>(report->runsCopied), static_cast<long long>(report->stepsCopied),
        static_cast<long long>(report->runsPresent), static_cast<long long>(report->segmentsCopied),
        static_cast<long long>(report->revisionsCopied),
        static_cast<long long>(report->modelsCopied), static_cast<long long>(report->sweepsCopied),
        seconds);
    if (report->segmentsWithoutRun > 0) {
      printWarning(std::to_string(report->segmentsWithoutRun) +
                   " label segments not copied: their runs are not in the target (copy the runs "
                   "too)");
    }
  }
  return kExitOk;
}

// ---- bench storage ---------------------------------------------------------------------------

struct BenchArgs {
  std::int64_t steps = 1000000;
  int files = 8;
  std::int64_t bigSteps = 1000000;
  int repeats = 15;
  std::string dir;
  std::string server;  // also import into this database (a PostgreSQL address)
  bool keep = false;
  bool compare = true;
  bool json = false;
};

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n == 0 ? 0.0 : (n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]));
}

// CPU seconds (user + system) of this process, or of its finished children.
double cpuSeconds(int who) {
  rusage usage{};
  getrusage(who, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Times the sqlite3 shell's `.import --csv` of the same files (metadata lines skipped) into a plain
// table with the same journal settings; < 0 when the shell is not available or fails.
double timeSqliteShellImport(const std::vector<fs::path>& files, const fs::path& dbPath,
                             std::size_t metadataLines, double& cpuOut) {
  if (std::system("command -v sqlite3 > /dev/null 2>&1") != 0) return -1.0;
  const fs::path script = dbPath.string() + ".sql";
  {
    std::ofstream out(script);
    out << "PRAGMA page_size = 16384;\nPRAGMA journal_mode = WAL;\nPRAGMA synchronous = NORMAL;\n"
        << "PRAGMA cache_size = -262144;\n";
    for (const fs::path& file : files) {
      out << ".import --csv --skip " << metadataLines << " '" << file.string() << "' steps\n";
    }
  }
  const std::string command =
      "sqlite3 '" + dbPath.string() + "' < '" + script.string() + "' > /dev/null";
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = cpuSeconds(RUSAGE_CHILDREN);
  const int rc = std::system(command.c_str());
  const double seconds = secondsSince(t0);
  cpuOut = cpuSeconds(RUSAGE_CHILDREN) - cpu0;
  return rc == 0 ? seconds : -1.0;
}

// The server figures of `bench storage --server`: the same imports into a PostgreSQL database,
// the big run copied into it from the file, and what the workbench reads to open that run.
void benchServer(const BenchArgs& a, const std::vector<fs::path>& files, const fs::path& big,
                 RunDatabase& file, nlohmann::json& result) {
  auto server = openDatabaseOrCreate(a.server);
  if (!server->onServer()) throw UsageError("--server must be a PostgreSQL address");
  auto runs = server->runs().list();
  if (!runs) throw std::runtime_error(runs.errorText());
  if (!runs->empty()) {
    throw UsageError(
        "--server must name a database without runs (the benchmark deletes what it "
        "imports)");
  }
  const auto timed = [](auto&& fn) {
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    return secondsSince(t0);
  };
  const double cpu0 = cpuSeconds(RUSAGE_SELF);
  const double many = timed([&] {
    for (const auto& outcome : server->runs().importFiles(files)) {
      if (outcome.status != ImportStatus::Imported) throw std::runtime_error(outcome.message);
    }
  });
  result["server_import_seconds"] = many;
  result["server_import_cpu_seconds"] = cpuSeconds(RUSAGE_SELF) - cpu0;
  result["server_import_steps_per_second"] = static_cast<double>(a.steps) / many;
  const double single = timed([&] {
    const auto outcomes = server->runs().importFiles({big});
    if (outcomes[0].status != ImportStatus::Imported) throw std::runtime_error(outcomes[0].message);
  });
  result["server_single_file_import_seconds"] = single;
  result["server_single_file_steps_per_second"] = static_cast<double>(a.bigSteps) / single;
  if (Status gone = server->runs().remove({"big"}); !gone)
    throw std::runtime_error(gone.errorText());
  storage::CopyOptions only;
  only.runs = {"big"};
  only.models = false;
  only.sweeps = false;
  const double copy = timed([&] {
    auto copied = server->copyFrom(file, only);
    if (!copied) throw std::runtime_error(copied.errorText());
  });
  result["server_copy_big_run_seconds"] = copy;
  const auto run = server->runs().find("big");
  if (!run) throw std::runtime_error(run.errorText());
  // What the workbench reads to paint a run first: the track, a summary, the cursor's step.
  const auto check = [](bool ok) {
    if (!ok) throw std::runtime_error("reading the run from the server failed");
  };
  const double track = timed([&] { check(server->runs().loadTrack(run->id).ok()); });
  const double summary =
      timed([&] { check(server->runs().loadSummary(run->id, 0, -1, 2000).ok()); });
  const double window = timed([&] { check(server->runs().loadWindow(run->id, 0, 1).ok()); });
  result["server_open_run_reads_seconds"] = track + summary + window;
  result["server_open_track_seconds"] = track;
  result["server_open_summary_seconds"] = summary;
  std::vector<double> cursorMs;
  std::mt19937_64 rng(5);
  for (int r = 0; r < a.repeats; ++r) {
    const std::int64_t step = std::uniform_int_distribution<std::int64_t>(0, a.bigSteps - 1)(rng);
    const auto t0 = std::chrono::steady_clock::now();
    if (!server->runs().loadWindow(run->id, step, 1)) throw std::runtime_error("window failed");
    cursorMs.push_back(1e3 * secondsSince(t0));
  }
  result["server_cursor_step_ms_median"] = median(cursorMs);
  if (!a.keep) {
    std::vector<std::string> names;
    const auto stored = server->runs().list();
    if (!stored) throw std::runtime_error(stored.errorText());
    for (const auto& info : stored.value())
      names.push_back(info.name);
    if (Status gone = names.empty() ? Status::success() : server->runs().remove(names); !gone) {
      throw std::runtime_error(gone.errorText());
    }
  }
}

int runBenchStorage(const BenchArgs& a) {
  if (a.steps < a.files || a.files < 1) throw UsageError("--steps must be at least --files >= 1");
  if (a.bigSteps < 20000) throw UsageError("--big-steps must be at least 20000");
  fs::path dir = a.dir.empty() ? fs::temp_directory_path() /
                                     ("tactile-bench-storage-" + std::to_string(::getpid()))
                               : fs::path(a.dir);
  std::error_code ec;
  const bool ownDir = !fs::exists(dir, ec);
  fs::create_directories(dir);
  nlohmann::json result = {{"steps", a.steps}, {"files", a.files}, {"big_steps", a.bigSteps}};

  // 1. Many files: parallel parsing, one writer.
  std::vector<fs::path> files;
  for (int f = 0; f < a.files; ++f) {
    const std::int64_t n = a.steps / a.files + (f < a.steps % a.files ? 1 : 0);
    files.push_back(dir / ("bench-" + std::to_string(f) + ".csv"));
    const Status written =
        writeRunCsv(storage::makeSyntheticRun(static_cast<std::size_t>(n), 100 + f), files.back());
    if (!written) throw std::runtime_error(written.errorText());
  }
  std::uintmax_t bytes = 0;
  for (const auto& file : files)
    bytes += fs::file_size(file);
  const std::size_t metadataLines =
      storage::makeSyntheticRun(1, 1).metadata.size();  // metadata lines before the header
  const fs::path dbPath = dir / "bench.db";
  for (const char* suffix : {"", "-wal", "-shm"})
    fs::remove(dbPath.string() + suffix);
  double importSeconds = 0.0;
  double importCpu = 0.0;
  {
    auto db = openDatabaseOrCreate(dbPath.string());
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = cpuSeconds(RUSAGE_SELF);
    const auto outcomes = db->runs().importFiles(files);
    importSeconds = secondsSince(t0);
    importCpu = cpuSeconds(RUSAGE_SELF) - cpu0;
    for (const auto& outcome : outcomes) {
      if (outcome.status != ImportStatus::Imported) throw std::runtime_error(outcome.message);
    }
  }
  result["import_seconds"] = importSeconds;
  result["import_steps_per_second"] = static_cast<double>(a.steps) / importSeconds;
  result["csv_megabytes"] = static_cast<double>(bytes) / 1e6;
  result["import_cpu_seconds"] = importCpu;
  // What two cores would give if this process had them to itself (parsing runs on both).
  result["import_steps_per_second_2_idle_cores"] =
      static_cast<double>(a.steps) / std::max(importCpu / 2.0, 1e-9);
  if (a.compare) {
    const fs::path shellDb = dir / "sqlite3-shell.db";
    for (const char* suffix : {"", "-wal", "-shm"})
      fs::remove(shellDb.string() + suffix);
    double shellCpu = 0.0;
    const double shellSeconds = timeSqliteShellImport(files, shellDb, metadataLines, shellCpu);
    if (shellSeconds > 0) {
      result["sqlite3_shell_import_seconds"] = shellSeconds;
      result["sqlite3_shell_cpu_seconds"] = shellCpu;
      result["sqlite3_shell_steps_per_second"] = static_cast<double>(a.steps) / shellSeconds;
      result["speedup_vs_sqlite3_shell"] = shellSeconds / importSeconds;
    }
    for (const char* suffix : {"", "-wal", "-shm", ".sql"})
      fs::remove(shellDb.string() + suffix);
  }

  // 2. One big run: single-file import, then windows and summaries.
  const fs::path big = dir / "big.csv";
  {
    const Status written =
        writeRunCsv(storage::makeSyntheticRun(static_cast<std::size_t>(a.bigSteps), 7), big);
    if (!written) throw std::runtime_error(written.errorText());
  }
  auto db = openDatabaseOrCreate(dbPath.string());
  {
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = cpuSeconds(RUSAGE_SELF);
    const auto outcomes = db->runs().importFiles({big});
    const double seconds = secondsSince(t0);
    result["single_file_cpu_seconds"] = cpuSeconds(RUSAGE_SELF) - cpu0;
    if (outcomes[0].status != ImportStatus::Imported) throw std::runtime_error(outcomes[0].message);
    result["single_file_import_seconds"] = seconds;
    result["single_file_steps_per_second"] = static_cast<double>(a.bigSteps) / seconds;
  }
  const auto run = db->runs().find("big");
  if (!run) throw std::runtime_error(run.errorText());
  std::mt19937_64 rng(3);
  std::vector<double> windowMs;
  std::vector<double> summaryMs;
  for (int r = 0; r < a.repeats; ++r) {
    const std::int64_t first =
        std::uniform_int_distribution<std::int64_t>(0, a.bigSteps - 10000)(rng);
    auto t0 = std::chrono::steady_clock::now();
    auto window = db->runs().loadWindow(run->id, first, 10000);
    windowMs.push_back(1e3 * secondsSince(t0));
    if (!window || window->data.stepCount() != 10000) throw std::runtime_error("window failed");
    t0 = std::chrono::steady_clock::now();
    auto summary = db->runs().loadSummary(run->id, 0, -1, 2000);
    summaryMs.push_back(1e3 * secondsSince(t0));
    if (!summary || summary->buckets.empty()) throw std::runtime_error("summary failed");
  }
  result["window_10000_ms_median"] = median(windowMs);
  result["summary_2000_buckets_ms_median"] = median(summaryMs);
  {
    const auto t0 = std::chrono::steady_clock::now();
    auto whole = db->runs().load(run->id);
    result["load_whole_run_seconds"] = secondsSince(t0);
    if (!whole) throw std::runtime_error(whole.errorText());
  }
  if (!a.server.empty()) benchServer(a, files, big, *db, result);
  db.reset();
  if (!a.keep) {
    // Only what this benchmark wrote; a folder given by the user stays.
    for (const auto& file : files)
      fs::remove(file, ec);
    fs::remove(big, ec);
    for (const char* suffix : {"", "-wal", "-shm"})
      fs::remove(dbPath.string() + suffix, ec);
    if (ownDir) fs::remove(dir, ec);
  }

  if (a.json) {
    printJson(result);
  } else {
    std::printf(
        "import, %d files, %lld steps (%.1f MB CSV): %.3f s wall = %.0f steps/s; %.3f s CPU "
        "(%.0f steps/s on 2 idle cores)\n",
        a.files, static_cast<long long>(a.steps), result["csv_megabytes"].get<double>(),
        importSeconds, result["import_steps_per_second"].get<double>(), importCpu,
        result["import_steps_per_second_2_idle_cores"].get<double>());
    if (result.contains("sqlite3_shell_import_seconds")) {
      std::printf(
          "sqlite3 shell .import of the same files: %.3f s wall = %.0f steps/s, %.3f s CPU "
          "(ours %.2fx faster in wall time)\n",
          result["sqlite3_shell_import_seconds"].get<double>(),
          result["sqlite3_shell_steps_per_second"].get<double>(),
          result["sqlite3_shell_cpu_seconds"].get<double>(),
          result["speedup_vs_sqlite3_shell"].get<double>());
    }
    if (result.contains("server_import_seconds")) {
      std::printf(
          "server: import, %d files: %.3f s = %.0f steps/s; 1 file: %.0f steps/s; copy of the "
          "big run from the file: %.3f s; reads to open it: %.3f s; one cursor step: %.2f ms\n",
          a.files, result["server_import_seconds"].get<double>(),
          result["server_import_steps_per_second"].get<double>(),
          result["server_single_file_steps_per_second"].get<double>(),
          result["server_copy_big_run_seconds"].get<double>(),
          result["server_open_run_reads_seconds"].get<double>(),
          result["server_cursor_step_ms_median"].get<double>());
    }
    std::printf("import, 1 file, %lld steps: %.3f s wall = %.0f steps/s, %.3f s CPU\n",
                static_cast<long long>(a.bigSteps),
                result["single_file_import_seconds"].get<double>(),
                result["single_file_steps_per_second"].get<double>(),
                result["single_file_cpu_seconds"].get<double>());
    std::printf("window of 10000 steps: %.2f ms (median of %d)\n", median(windowMs), a.repeats);
    std::printf("summary of the whole run, 2000 buckets: %.2f ms (median of %d)\n",
                median(summaryMs), a.repeats);
    std::printf("whole run load: %.3f s\n", result["load_whole_run_seconds"].get<double>());
  }
  return kExitOk;
}

}  // namespace

void registerStorageVerbs(CLI::App& app, CLI::App& bench) {
  {
    auto args = std::make_shared<ImportArgs>();
    CLI::App* cmd = app.add_subcommand("import", "Import run CSV files into a database");
    cmd->add_option("--db", args->db,
                    "Database: a file (created when absent) or a PostgreSQL address")
        ->envname("TACTILE_DB")
        ->required();
    cmd->add_option("files", args->files,
                    "Run files, or folders of *.csv run files (A B; a path is never split at a "
                    "comma). A name already stored with other content fails that file only")
        ->required();
    cmd->add_option("--name", args->name, "Run name (one file only; default: the file's stem)");
    cmd->add_option("--prefix", args->prefix,
                    "Name runs P_<stem> (e.g. --prefix room1: room1_run_0000), so batches with "
                    "the same file names import side by side");
    cmd->add_option("--threads", args->threads, "Parser threads (default: one per core)");
    cmd->add_option("--mapping", args->mapping,
                    "Mapping file (JSON) for a ROS 2 bag (*.mcap): its tactile, pose, command "
                    "and blocked topics (docs/interop.md); an MCAP export of tactile needs none");
    cmd->add_flag("--json", args->json, R"(Print {"runs":[{"name","id","steps"}],...})");
    setAction(cmd, [args] { return runImport(*args); });
  }
  {
    auto db = std::make_shared<std::string>();
    auto run = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    auto format = std::make_shared<std::string>();
    auto sets = std::make_shared<std::vector<std::string>>();
    auto model = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand(
        "export-run", "Export a stored run to a run CSV file, or to MCAP for Foxglove/Lichtblick");
    cmd->add_option("--db", *db, "Database: a file or a PostgreSQL address")
        ->envname("TACTILE_DB")
        ->required();
    cmd->add_option("--run", *run, "Run name")->required();
    cmd->add_option("--out", *out, "Output file (written atomically)")->required();
    cmd->add_option("--format", *format,
                    "csv (a run file) or mcap (docs/interop.md); default: mcap for an --out "
                    "ending in .mcap, else csv");
    cmd->add_option("--sets", *sets, "MCAP: label sets to add, each on /labels/SET (A B or A,B)");
    cmd->add_option("--model", *model, "MCAP: a stored model whose online decisions to add");
    cmd->add_flag("--json", *json, R"(Print {"run","id","steps","out"})");
    setAction(cmd, [db, run, out, format, sets, model, json] {
      return runExport(*db, *run, *out, *format, *sets, *model, *json);
    });
  }
  {
    struct AutoArgs {
      std::string db, run, set;
      bool all = false;
      bool json = false;
    };
    auto args = std::make_shared<AutoArgs>();
    CLI::App* cmd = app.add_subcommand(
        "autolabel", "Turn runs' truth columns into a label set (NoContact ranges included)");
    cmd->add_option("--db", args->db, "Database: a file or a PostgreSQL address")
        ->envname("TACTILE_DB")
        ->required();
    cmd->add_option("--run", args->run, "Run name");
    cmd->add_flag("--all", args->all, "Every run with truth columns");
    cmd->add_option("--set", args->set, "Label set name (created when absent)")->required();
    cmd->add_flag("--json", args->json, "Print a JSON summary");
    setAction(cmd, [args] {
      return runAutolabel(args->db, args->run, args->all, args->set, args->json);
    });
  }
  {
    CLI::App* dbCmd = app.add_subcommand("db", "Database maintenance");
    dbCmd->require_subcommand(1, 1);
    auto path = std::make_shared<std::string>();
    auto json = std::make_shared<bool>(false);
    CLI::App* check = dbCmd->add_subcommand(
        "check", "Check a database's integrity and schema version (opened read-only)");
    check->add_option("--db", *path, "Database: a file or a PostgreSQL address")
        ->envname("TACTILE_DB")
        ->required();
    check->add_flag("--json", *json, "Print a JSON report");
    setAction(check, [path, json] { return runCheck(*path, *json); });
    auto createPath = std::make_shared<std::string>();
    auto createJson = std::make_shared<bool>(false);
    CLI::App* create = dbCmd->add_subcommand(
        "create", "Create an empty database (the verbs that read a database never create one)");
    create
        ->add_option("--db", *createPath,
                     "Database to create: a file, or a PostgreSQL address (an empty database)")
        ->envname("TACTILE_DB")
        ->required();
    create->add_flag("--json", *createJson, "Print a JSON summary");
    setAction(create, [createPath, createJson] { return runCreate(*createPath, *createJson); });
    struct CopyArgs {
      std::string from, to;
      std::vector<std::string> runs, sets;
      bool json = false;
    };
    auto copyArgs = std::make_shared<CopyArgs>();
    CLI::App* copy = dbCmd->add_subcommand(
        "copy",
        "Copy runs, label sets, models and sweeps between two databases (files or PostgreSQL "
        "servers, either way); a second copy adds nothing");
    copy->add_option("--from", copyArgs->from, "Source database (opened read-only)")->required();
    copy->add_option("--to", copyArgs->to, "Target database (created when absent)")->required();
    copy->add_option("--runs", copyArgs->runs, "Only these runs (names, comma-separated)");
    copy->add_option("--sets", copyArgs->sets, "Only these label sets (names, comma-separated)");
    copy->add_flag("--json", copyArgs->json, "Print a JSON summary");
    setAction(copy, [copyArgs] {
      return runCopy(copyArgs->from, copyArgs->to, copyArgs->runs, copyArgs->sets, copyArgs->json);
    });
    struct GrantArgs {
      std::string db, role, right;
      bool json = false;
    };
    auto grantArgs = std::make_shared<GrantArgs>();
    CLI::App* grant = dbCmd->add_subcommand(
        "grant",
        "Give a PostgreSQL login role (made when absent) one right on a server database: "
        "annotator (edit labels), researcher (also keep models and sweeps) or admin (also "
        "import, rename and delete runs)");
    grant->add_option("--db", grantArgs->db, "A PostgreSQL address (as a role that may grant)")
        ->envname("TACTILE_DB")
        ->required();
    grant->add_option("--role", grantArgs->role, "The login role (user name)")->required();
    grant->add_option("--as", grantArgs->right, "annotator, researcher or admin")
        ->required()
        ->check(CLI::IsMember({"annotator", "researcher", "admin"}));
    grant->add_flag("--json", grantArgs->json, R"(Print {"role","right"})");
    setAction(grant, [grantArgs] {
      if (!storage::isServerAddress(grantArgs->db)) {
        throw UsageError("--db: roles belong to a PostgreSQL server; give its address");
      }
      auto db = openDatabaseForWrite(grantArgs->db);
      if (const Status s = db->grant(grantArgs->role, grantArgs->right); !s) {
        throw std::runtime_error(s.errorText());
      }
      if (grantArgs->json) {
        printJson({{"role", grantArgs->role}, {"right", grantArgs->right}});
      } else {
        std::printf("%s may now work as %s\n", grantArgs->role.c_str(), grantArgs->right.c_str());
      }
      return kExitOk;
    });
  }
  {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = bench.add_subcommand(
        "storage", "Import speed (against the sqlite3 shell), window and summary loading");
    cmd->add_option("--steps", args->steps, "Steps over all files of the many-file import");
    cmd->add_option("--files", args->files, "Files of the many-file import");
    cmd->add_option("--big-steps", args->bigSteps, "Steps of the big run for windows/summaries");
    cmd->add_option("--repeats", args->repeats, "Window and summary loads to take the median of");
    cmd->add_option("--dir", args->dir, "Work folder (default: a new temporary folder)");
    cmd->add_option("--server", args->server,
                    "Also import into this PostgreSQL database (an address; it must hold no "
                    "runs), copy the big run into it and read it back, timed beside the file");
    cmd->add_flag("--keep", args->keep, "Keep the generated files and database");
    cmd->add_flag("!--no-compare", args->compare, "Skip the sqlite3 shell comparison");
    cmd->add_flag("--json", args->json, "Print the figures as JSON");
    setAction(cmd, [args] { return runBenchStorage(*args); });
  }
}

}  // namespace tactile::cli
