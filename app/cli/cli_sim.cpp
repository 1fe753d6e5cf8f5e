// Simulator verbs: simulate, navigate, bench sim.
#include "app/cli/cli_common.h"

namespace tactile::cli {

void registerSimVerbs(CLI::App& app, CLI::App& bench) {
  addPlannedVerb(app, "simulate", "Drive the simulated robot through a scene and record runs");
  addPlannedVerb(app, "navigate", "Navigate a scene by touch with trained models");
  addPlannedVerb(bench, "sim", "Simulator steps per second against obstacle count");
}

}  // namespace tactile::cli
