// `tactile`: the headless twin of the workbench. Its contract: docs/cli.md.
#include <csignal>
#include <cstdio>
#include <exception>

#include "app/cli/cli_common.h"
#include "app/cli/cli_mcap.h"
#include "base/file_text.h"

namespace tactile::cli {
void registerCatalogVerbs(CLI::App& app);    // cli_catalog.cpp
void registerWorkspaceVerbs(CLI::App& app);  // cli_workspace.cpp
}  // namespace tactile::cli

int main(int argc, char** argv) {
  using namespace tactile::cli;
  // A file-size limit (ulimit -f) makes a write fail with EFBIG, which every writer reports and
  // cleans up after, instead of killing the process half-way with SIGXFSZ.
  std::signal(SIGXFSZ, SIG_IGN);
  // No output of a command replaces one of its inputs (docs/cli.md#output-files).
  tactile::guardInputFiles(true);
  CLI::App app{
      "tactile: simulate, import, label, train and evaluate tactile-navigation runs.\n"
      "Run 'tactile VERB --help' for the options of a verb."};
  app.name("tactile");
  app.require_subcommand(1, 1);
  app.fallthrough(false);

  CLI::App* bench = app.add_subcommand("bench", "Measure the speed of the core pieces");
  bench->require_subcommand(1, 1);

  registerRunVerbs(app, *bench);
  registerSimVerbs(app, *bench);
  registerLearnVerbs(app, *bench);
  registerFitVerbs(app, *bench);
  registerStorageVerbs(app, *bench);
  registerCatalogVerbs(app);
  registerWorkspaceVerbs(app);
  registerMcapVerbs(app, *bench);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    printError(e.what());
    std::fputs("Run 'tactile --help' or 'tactile VERB --help' for usage.\n", stderr);
    return kExitUsage;
  }
  return lastExitCode();
}
