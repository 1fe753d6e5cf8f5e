// The one reader and writer of run files (CSV, version 1; DESIGN.md section 4). Everything that
// reads or writes runs goes through here.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>

#include "sim/progress.h"
#include "sim/run.h"

namespace tactile {

// Where and why a run file was rejected. `line` is the 1-based physical line; `column` the header
// name and `columnPosition` its 1-based position when the error belongs to a column (0 otherwise).
struct RunCsvError {
  std::string file;
  std::size_t line = 0;
  std::string column;
  std::size_t columnPosition = 0;
  std::string message;  // what was expected and what was found

  // "FILE:LINE: column 'n3' (position 10): expected ..."
  std::string toString() const;
};

// Either a complete run or an error; never a half-read run.
class RunCsvResult {
 public:
  RunCsvResult(RunData run) : value_(std::move(run)) {}
  RunCsvResult(RunCsvError error) : value_(std::move(error)) {}

  bool ok() const { return std::holds_alternative<RunData>(value_); }
  explicit operator bool() const { return ok(); }
  RunData& run() { return std::get<RunData>(value_); }
  const RunData& run() const { return std::get<RunData>(value_); }
  const RunCsvError& error() const { return std::get<RunCsvError>(value_); }

 private:
  std::variant<RunData, RunCsvError> value_;
};

// Parses run-file text. `fileName` is used in error messages only. `progress` is called with
// bytes parsed and total bytes; returning false cancels (the result is then an error).
RunCsvResult parseRunCsv(std::string_view text, std::string_view fileName,
                         const ProgressFn& progress = {});

// Reads and parses a file.
RunCsvResult readRunCsv(const std::filesystem::path& path, const ProgressFn& progress = {});

// Formats a run as file text: metadata lines, the header in canonical column order (truth and x_
// columns when present), then one line per step. Doubles use the shortest text that reads back
// bit for bit.
std::string formatRunCsv(const RunData& run);

// Writes atomically: to a temporary file beside `path`, then renamed over it, so a failure never
// leaves a partial file. Returns an empty string on success, otherwise the reason.
std::string writeRunCsv(const RunData& run, const std::filesystem::path& path);

// Reads a whole file into memory; returns false and sets `error` on failure.
bool readFileText(const std::filesystem::path& path, std::string& text, std::string& error);

// Writes text atomically (temporary file, then rename). Returns an empty string on success.
std::string writeFileAtomically(const std::filesystem::path& path, std::string_view text);

}  // namespace tactile
