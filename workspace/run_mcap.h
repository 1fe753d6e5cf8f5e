// Runs to and from MCAP files (docs/interop.md), as the CLI (`tactile export-run --format mcap`,
// `tactile import FILE.mcap`) and the workbench (File > Export Run > MCAP, an MCAP file dropped
// on the window) both call them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "base/error.h"
#include "mcap/writer.h"
#include "storage/run_database.h"

namespace tactile::workspace {

class Workspace;

struct McapExportRequest {
  std::string run;
  std::vector<std::string> labelSets;  // each on /labels/SET
  std::string model;                   // empty: none; else its online decisions on /decisions/MODEL
  std::filesystem::path out;
  mcap::WriterOptions writer;
  // Called every few thousand steps with the steps written and the run's steps; false cancels
  // (the export then fails with "cancelled" and leaves nothing at `out`).
  std::function<bool(std::size_t done, std::size_t total)> progress;
};

struct McapExportReport {
  std::string run;
  std::int64_t steps = 0;
  std::uint64_t bytes = 0;
  std::vector<std::string> topics;
  std::vector<std::string> warnings;
};

// Writes the run (with the sets' labels, the model's decisions and the scene's walls) to
// request.out atomically, streamed (the file is never whole in memory); nothing is left there on
// failure or when cancelled.
Result<McapExportReport> exportRunMcap(Workspace& workspace, const McapExportRequest& request);

struct McapImportRequest {
  std::filesystem::path file;
  // A mapping file for a ROS 2 bag; none for an MCAP export of this program.
  std::optional<std::filesystem::path> mapping;
  // The mapping's text itself (the workbench's mapping dialog); used when `mapping` is not set.
  std::optional<std::string> mappingText;
  std::string name;  // empty: the file's stem
  storage::SceneResolver sceneResolver;
};

// Imports the MCAP file as one run, in one transaction: the run is stored whole or not at all.
// An export of this program goes through the run-file reader (so it is checked by the same
// rules and stored exactly as the run it was exported from); a ROS 2 bag needs a mapping.
storage::ImportOutcome importMcap(storage::RunStore runs, const McapImportRequest& request);

// True when the file is an MCAP export of this program (it imports without a mapping).
bool isRunMcapFile(const std::filesystem::path& file);

}  // namespace tactile::workspace
