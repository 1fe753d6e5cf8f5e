// Learning verbs: train, sweep, report, classify.
#include "app/cli/cli_common.h"

namespace tactile::cli {

void registerLearnVerbs(CLI::App& app, CLI::App& /*bench*/) {
  addPlannedVerb(app, "train", "Train per-group classifiers on labelled runs");
  addPlannedVerb(app, "sweep", "Sweep model order, covariance form and variance floor");
  addPlannedVerb(app, "report", "Confusion matrices and rate tables of a sweep or model");
  addPlannedVerb(app, "classify", "Classify each step and group of a run with a model");
}

}  // namespace tactile::cli
