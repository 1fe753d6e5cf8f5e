#include "workspace/run_inputs.h"

#include <algorithm>
#include <system_error>

namespace tactile::workspace {

namespace fs = std::filesystem;

Result<RunInputs> expandRunInputs(const std::vector<fs::path>& inputs) {
  RunInputs out;
  for (const fs::path& input : inputs) {
    std::error_code ec;
    if (!fs::is_directory(input, ec)) {
      out.files.push_back(input);
      continue;
    }
    std::vector<fs::path> inFolder;
    for (fs::directory_iterator it(input, ec), end; !ec && it != end; it.increment(ec)) {
      std::error_code typeError;
      if (it->is_regular_file(typeError) && it->path().extension() == ".csv")
        inFolder.push_back(it->path());
    }
    if (ec) return Error(input.string(), "cannot list folder: " + ec.message());
    std::sort(inFolder.begin(), inFolder.end());
    if (inFolder.empty()) out.warnings.push_back(input.string() + ": no .csv files in this folder");
    out.files.insert(out.files.end(), inFolder.begin(), inFolder.end());
  }
  return out;
}

Result<RunImport> importRunInputs(storage::RunDatabase& db, const std::vector<fs::path>& inputs,
                                  const storage::ImportOptions& options,
                                  const ProgressFn& progress) {
  Result<RunInputs> expanded = expandRunInputs(inputs);
  if (!expanded) return expanded.error();
  RunImport out;
  out.warnings = std::move(expanded->warnings);
  out.outcomes = db.runs().importFiles(expanded->files, options, progress);
  return out;
}

}  // namespace tactile::workspace
