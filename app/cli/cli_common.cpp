#include "app/cli/cli_common.h"

#include <unistd.h>

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <utility>

#include "base/text_rules.h"

namespace tactile::cli {
namespace {
#include "run/json_text.h"
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

void requireValidName(const std::string& value, std::string_view option, std::string_view what) {
  if (Status ok = checkName(value, what); !ok) {
    throw UsageError(std::string(option) + ": " + ok.error().message);
  }
}

std::vector<std::string> splitNames(const std::vector<std::string>& given) {
  std::vector<std::string> names;
  for (const std::string& item : given) {
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = item.find(',', start);
      names.push_back(item.substr(start, comma == std::string::npos ? comma : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return names;
}

void setAction(CLI::App* command, std::function<int()> fn) {
  command->callback([fn = std::move(fn)] {
    try {
      gExitCode = fn();
    } catch (const UsageError& e) {
      printError(e.what());
      gExitCode = kExitUsage;
    } catch (const std::bad_alloc&) {
      printError("out of memory: the input is too large for this machine's memory");
      gExitCode = kExitFailure;
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

ProgressLine::ProgressLine(std::string verb, std::string unit)
    : verb_(std::move(verb)), unit_(std::move(unit)), terminal_(isatty(2) != 0) {}

void ProgressLine::show(std::size_t done, std::size_t total) {
  // Workers may report out of order: the count only goes up.
  if (total == 0 || (shown_ != kNone && done <= shown_)) return;
  shown_ = done;
  if (terminal_) {
    std::fprintf(stderr, "\r%s: %zu/%zu %s", verb_.c_str(), done, total, unit_.c_str());
    if (done >= total) std::fputc('\n', stderr);
    return;
  }
  const std::size_t tenth = done * 10 / total;
  if (done < total && tenth == lastTenth_) return;
  lastTenth_ = tenth;
  std::fprintf(stderr, "%s: %zu/%zu %s\n", verb_.c_str(), done, total, unit_.c_str());
}

}  // namespace tactile::cli
    } catch (const nlohmann::json::exception& e) {
      // A JSON document of an unexpected shape that no reader caught: plain words, never the
      // library's own text.
      printError("unexpected JSON content: " + plainJsonError(e));
      gExitCode = kExitFailure;
