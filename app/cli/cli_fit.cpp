// Feature-table verbs: fit, bench learn.
#include "app/cli/cli_common.h"

namespace tactile::cli {

void registerFitVerbs(CLI::App& app, CLI::App& bench) {
  addPlannedVerb(app, "fit", "Train and test a classifier on feature-table CSV files");
  addPlannedVerb(bench, "learn", "Fit time against error over model orders and forms");
}

}  // namespace tactile::cli
