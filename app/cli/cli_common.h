// Shared plumbing of the `tactile` command line: verb registration, error printing, exit codes.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace tactile::storage {
class RunDatabase;
}  // namespace tactile::storage

namespace tactile::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// Prints "tactile: error: MESSAGE" on stderr.
// The exit status chosen by the verb that ran.
int lastExitCode();

void printError(std::string_view message);
// Prints "tactile: warning: MESSAGE" on stderr.
void printWarning(std::string_view message);

// Thrown by a verb for a usage problem found after parsing (exit 2).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The name rule (base/text_rules.h) for a name given on the command line: a UsageError naming
// the option ("--name: a run name must ...") when `value` breaks it. `what` is "run", "label set",
// "model", "sweep" or "annotator".
void requireValidName(const std::string& value, std::string_view option, std::string_view what);

// The numeric option checks, one wording for every verb. NaN never passes any of them, nor does
// infinity (no option of the CLI means anything at infinity). Each throws a UsageError naming the
// option and the value given.
enum class RangeEnd { Closed, Open };
// `value` in the range from `low` to `high` (each end included or not; an infinite `high` means no
// upper bound): "--holdout must be a number in (0, 1), got nan".
void checkNumberOption(std::string_view option, double value, double low, RangeEnd lowEnd,
                       double high, RangeEnd highEnd);
// A model order: 1 to analysis::kMaxModelOrder.
void checkOrderOption(std::string_view option, int order);
// A variance floor: 0 (none) or from analysis::kMinVarianceFloor (the smallest normal double) up.
void checkFloorOption(std::string_view option, double floor);

// Names given as `A B` or `A,B` (or both), split at commas: no valid name holds one. Only for
// names; file paths are never split.
std::vector<std::string> splitNames(const std::vector<std::string>& given);

// Progress of a long verb on stderr: "VERB: DONE/TOTAL UNIT". On a terminal one line rewritten in
// place; otherwise (a log file, a pipe) a line at every tenth of the way and at the end, so logs
// stay readable. Not thread-safe: callers from several threads hold a lock.
class ProgressLine {
 public:
  ProgressLine(std::string verb, std::string unit);
  void show(std::size_t done, std::size_t total);

 private:
  std::string verb_;
  std::string unit_;
  bool terminal_;
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t shown_ = kNone;
  std::size_t lastTenth_ = 0;
};

// Makes `fn` the action of a parsed subcommand. Its return value becomes the exit status; a
// UsageError exits 2, any other exception prints `tactile: error:` and exits 1.
void setAction(CLI::App* command, std::function<int()> fn);

// Registers a verb that exists in the contract but is not built yet: it says so and exits 2.
CLI::App* addPlannedVerb(CLI::App& parent, const std::string& name, const std::string& description);

// Opening the database of a verb's --db (defined in cli_storage.cpp; docs/storage.md#opening).
// Each throws std::runtime_error with the text the CLI prints ("DB: no such database" for a
// missing file, "DB: ..." for anything else) and creates no file unless it says so.
//  - openDatabaseForRead: read-only verbs (list, export, report, classify, db check); works on a
//    read-only file in a read-only folder.
//  - openDatabaseForWrite: verbs that change an existing database (rename, delete, ...).
//  - openDatabaseOrCreate: only import, autolabel, labels import, models import, train, sweep and
//    db create; makes the file when absent. Migrations print a warning naming the backup.
// TACTILE_DB, or empty: the database of a verb whose --db is optional and that was given neither
// --db nor the file form's inputs (train, sweep, report, classify, navigate).
std::string databaseFromEnvironment();
std::unique_ptr<storage::RunDatabase> openDatabaseForRead(const std::string& path);
std::unique_ptr<storage::RunDatabase> openDatabaseForWrite(const std::string& path);
std::unique_ptr<storage::RunDatabase> openDatabaseOrCreate(const std::string& path);

// Verb registration, one function per part (each in its own cli_*.cpp file). `bench` is the
// `tactile bench` command; each part adds its own benchmark under it.
void registerRunVerbs(CLI::App& app, CLI::App& bench);
void registerSimVerbs(CLI::App& app, CLI::App& bench);
void registerLearnVerbs(CLI::App& app, CLI::App& bench);
void registerFitVerbs(CLI::App& app, CLI::App& bench);
void registerStorageVerbs(CLI::App& app, CLI::App& bench);
// `navigate` (cli_nav.cpp), registered by registerSimVerbs.
void registerNavigateVerb(CLI::App& app);

}  // namespace tactile::cli
