// What the user names to import: run files and folders. A folder stands for the *.csv files
// directly in it (sorted by name, not recursive). `tactile import` and the workbench (its Import
// Runs menu and drag and drop) both expand their inputs here, so both import the same files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "base/error.h"

namespace tactile::workspace {

struct RunInputs {
  std::vector<std::filesystem::path> files;
  // One line per folder that holds no .csv file ("FOLDER: no .csv files in this folder").
  std::vector<std::string> warnings;
};

// Files as given (whatever their extension; the import reports what it cannot read), folders
// replaced by their .csv files. Fails only when a folder cannot be listed.
Result<RunInputs> expandRunInputs(const std::vector<std::filesystem::path>& inputs);

}  // namespace tactile::workspace
