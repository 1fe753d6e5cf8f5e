// Database verbs: import, export-run, labels, autolabel, db, bench storage.
#include "app/cli/cli_common.h"

namespace tactile::cli {

void registerStorageVerbs(CLI::App& app, CLI::App& bench) {
  addPlannedVerb(app, "import", "Import run CSV files into a database");
  addPlannedVerb(app, "export-run", "Export a stored run back to a run CSV file");
  addPlannedVerb(app, "labels", "Import or export label sets");
  addPlannedVerb(app, "autolabel", "Turn a run's ground truth into a label set");
  addPlannedVerb(app, "db", "Check a database's integrity and schema version");
  addPlannedVerb(bench, "storage", "Import and window-loading speed of the database");
}

}  // namespace tactile::cli
