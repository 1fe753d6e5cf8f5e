// What the user names to import: run files and folders. A folder stands for the *.csv files
// directly in it (sorted by name, not recursive). `tactile import` and the workbench (its Import
// Runs menu and drag and drop) both import through importRunInputs, so both import the same files
// the same way.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/progress.h"
#include "storage/run_database.h"

namespace tactile::workspace {

struct RunInputs {
  std::vector<std::filesystem::path> files;
  // One line per folder that holds no .csv file ("FOLDER: no .csv files in this folder").
  std::vector<std::string> warnings;
};

// Files as given (whatever their extension; the import reports what it cannot read), folders
// replaced by their .csv files. Fails only when a folder cannot be listed.
Result<RunInputs> expandRunInputs(const std::vector<std::filesystem::path>& inputs);

struct RunImport {
  std::vector<std::string> warnings;             // expandRunInputs's, one per empty folder
  std::vector<storage::ImportOutcome> outcomes;  // one per file, in order
};

// The import of run files and folders: the inputs expanded as above, then every file imported into
// `db` (each file one transaction; `options.sceneResolver` finds the scenes the runs name, which
// the callers take from the simulator). `progress` counts files and may cancel between them.
// Fails only when a folder cannot be listed; a file that cannot be imported is a failed outcome.
Result<RunImport> importRunInputs(storage::RunDatabase& db,
                                  const std::vector<std::filesystem::path>& inputs,
                                  const storage::ImportOptions& options,
                                  const ProgressFn& progress = {});

}  // namespace tactile::workspace
