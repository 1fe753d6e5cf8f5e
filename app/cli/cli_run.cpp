// Run-file verbs: bench io.
#include "app/cli/cli_common.h"

namespace tactile::cli {

void registerRunVerbs(CLI::App& /*app*/, CLI::App& bench) {
  addPlannedVerb(bench, "io", "Run-file reading and writing speed");
}

}  // namespace tactile::cli
