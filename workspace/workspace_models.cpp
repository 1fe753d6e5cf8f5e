// Model files in and out of a workspace, and models trained from sweep cells: the CLI's `models
// export|import` and the workbench's Learn menu call these.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "analysis/model_file.h"
#include "analysis/report.h"
#include "base/text_rules.h"
#include "run/json_text.h"
#include "workspace/workspace.h"

namespace tactile::workspace {

using nlohmann::json;

namespace {

Error failure(std::string message) {
  return Error(std::move(message));
}

}  // namespace

Status Workspace::exportModel(std::string_view name, const std::filesystem::path& out) {
  auto bundle = loadModel(name);
  if (!bundle) return bundle.error();
  // Atomic for a file, a stream for a device or FIFO (base/file_text.h): a failed write leaves
  // no half file.
  return analysis::writeModelBundleFile(out, bundle.value());
}

Result<std::string> Workspace::importModel(const std::filesystem::path& file, std::string name) {
  const Result<analysis::ModelBundle> read = analysis::readModelFile(file);
  if (!read) return read.error();
  // A stem's commas and control characters become '_'; the name rule is checked on storing.
  if (name.empty()) name = nameFromFileStem(file.stem().string());
  // The bundle is stored as read; the stored provenance also says where it came from.
  analysis::ModelBundle marked = read.value();
  for (analysis::GroupModel& m : marked.models)
    m.provenance.importedFrom = file.string();
  auto id = db_->models().add(name, dumpJson(analysis::bundleToJson(read.value())),
                              dumpJson(analysis::bundleProvenanceToJson(marked)),
                              dumpJson(analysis::bundleMetricsToJson(read.value())));
  if (!id) return id.error();
  return name;
}

Result<TrainOutcome> Workspace::trainSweepCell(std::int64_t sweepId, std::size_t cellIndex,
                                               std::string modelName, const ProgressFn& progress,
                                               bool store) {
  auto info = db_->sweeps().info(sweepId);
  if (!info) return info.error();
  auto sweep = loadSweep(sweepId);
  if (!sweep) return sweep.error();
  if (cellIndex >= sweep->cells.size()) {
    return failure("sweep " + std::to_string(sweepId) + " has " +
                   std::to_string(sweep->cells.size()) + " cells; there is no cell " +
                   std::to_string(cellIndex));
  }
  auto parsed = sweepConfigurationOf(info.value());
  if (!parsed) return parsed.error();
  const json& configuration = parsed.value();
  if (!sweep->cells[cellIndex].ok) {
    return failure("cell " + std::to_string(cellIndex) + " of sweep " + std::to_string(sweepId) +
                   " has no model: " + sweep->cells[cellIndex].reason);
  }
  const analysis::SweepCell& cell = sweep->cells[cellIndex].cell;
  TrainRequest request;
  request.labelSet = configuration.value("label_set", std::string());
  if (request.labelSet.empty()) {
    return failure("sweep " + std::to_string(sweepId) +
                   " was not run on a stored label set; train its settings with `tactile train`");
  }
  request.trainRuns = analysis::runNamesOf(configuration.value("train_runs", json::array()));
  request.testRuns = analysis::runNamesOf(configuration.value("test_runs", json::array()));
  request.groups = {cell.group};
  analysis::TrainSettings settings;
  settings.features = cell.features;
  settings.classifier = analysis::cellClassifierOptions(sweep->grid, cell);
  settings.classifier.threads = 0;
  settings.classifier.gmm.threads = 0;
  // The class chain weighs the evidence as the sweep scored it: the default weight of the group
  // and method.
  settings.emissionWeight = analysis::defaultEmissionWeight(cell.group, cell.method);
  // A model's default decision is causal: an offline cell's model decides online by default (its
  // stored scores give every mode).
  settings.decision =
      analysis::isCausal(cell.decision) ? cell.decision : analysis::DecisionMode::Online;
  request.settings = analysis::GroupSettings::same(settings);
  request.minRowsPerGroup = 1;
  if (modelName.empty()) {
    // Short: the settings are in the model's provenance and the sweep's report, not its name.
    const std::string base = "sweep" + std::to_string(sweepId) + "-" +
                             std::string(groupInfo(cell.group).shortName) + "-cell" +
                             std::to_string(cellIndex);
    modelName = base;
    for (int n = 2; db_->models().info(modelName); ++n)
      modelName = base + " (" + std::to_string(n) + ")";
  }
  request.modelName = modelName;
  request.store = store;
  auto outcome = train(request, progress);
  if (!outcome) return outcome.error();
  if (outcome->groups.empty() || !outcome->groups.front().trained) {
    return failure("the cell's model could not be trained: " +
                   (outcome->groups.empty() ? std::string("no group")
                                            : outcome->groups.front().skippedBecause));
  }
  return outcome;
}

}  // namespace tactile::workspace
