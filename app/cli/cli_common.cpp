#include "app/cli/cli_common.h"

#include <cstdio>
#include <exception>
#include <string>

namespace tactile::cli {
namespace {
int gExitCode = kExitOk;
}  // namespace

int lastExitCode() {
  return gExitCode;
}

void printError(std::string_view message) {
  std::fprintf(stderr, "tactile: error: %.*s\n", static_cast<int>(message.size()), message.data());
}

void printWarning(std::string_view message) {
  std::fprintf(stderr, "tactile: warning: %.*s\n", static_cast<int>(message.size()),
               message.data());
}

void setAction(CLI::App* command, std::function<int()> fn) {
  command->callback([fn = std::move(fn)] {
    try {
      gExitCode = fn();
    } catch (const UsageError& e) {
      printError(e.what());
      gExitCode = kExitUsage;
    } catch (const std::exception& e) {
      printError(e.what());
      gExitCode = kExitFailure;
    }
  });
}

CLI::App* addPlannedVerb(CLI::App& parent, const std::string& name,
                         const std::string& description) {
  CLI::App* command = parent.add_subcommand(name, description + " (not built yet)");
  command->allow_extras();
  std::string full = parent.get_name() == "tactile" ? name : parent.get_name() + " " + name;
  setAction(command, [full] {
    printError("'" + full + "' is not built yet in this version of tactile");
    return kExitUsage;
  });
  return command;
}

}  // namespace tactile::cli
