#include "app/cli/cli_common.h"

#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <utility>

#include "analysis/gmm.h"
#include "base/text_rules.h"
#include "run/json_text.h"

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

namespace {

// A number for a message: shortest round-trip text ("nan", "inf", "1e-320").
std::string optionNumber(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, end) : std::to_string(v);
}

}  // namespace

void checkNumberOption(std::string_view option, double value, double low, RangeEnd lowEnd,
                       double high, RangeEnd highEnd) {
  const bool aboveLow = lowEnd == RangeEnd::Closed ? value >= low : value > low;
  const bool belowHigh =
      std::isinf(high) || (highEnd == RangeEnd::Closed ? value <= high : value < high);
  if (std::isfinite(value) && aboveLow && belowHigh) return;
  std::string range;
  if (std::isinf(high)) {
    range = "a finite number " + std::string(lowEnd == RangeEnd::Closed ? ">= " : "> ") +
            optionNumber(low);
  } else {
    range = "a number in " + std::string(lowEnd == RangeEnd::Closed ? "[" : "(") +
            optionNumber(low) + ", " + optionNumber(high) +
            (highEnd == RangeEnd::Closed ? "]" : ")");
  }
  throw UsageError(std::string(option) + " must be " + range + ", got " + optionNumber(value));
}

void checkOrderOption(std::string_view option, int order) {
  if (order >= 1 && order <= analysis::kMaxModelOrder) return;
  throw UsageError(std::string(option) + " must be between 1 and " +
                   std::to_string(analysis::kMaxModelOrder) + ", got " + std::to_string(order));
}

void checkFloorOption(std::string_view option, double floor) {
  checkNumberOption(option, floor, 0.0, RangeEnd::Closed, HUGE_VAL, RangeEnd::Open);
  if (floor == 0.0 || floor >= analysis::kMinVarianceFloor) return;
  throw UsageError(std::string(option) + " must be 0 (no floor) or at least " +
                   optionNumber(analysis::kMinVarianceFloor) +
                   " (the smallest normal double; a smaller floor is lost to rounding), got " +
                   optionNumber(floor));
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
    } catch (const nlohmann::json::exception& e) {
      // A JSON document of an unexpected shape that no reader caught: plain words, never the
      // library's own text.
      printError("unexpected JSON content: " + plainJsonError(e));
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
