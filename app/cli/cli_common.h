// Shared plumbing of the `tactile` command line: verb registration, error printing, exit codes.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <string>
#include <string_view>

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
