// The one reader and writer of run files (CSV, version 1; docs/file-formats.md#run-file).
// Everything that reads or writes runs goes through here.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "base/error.h"
#include "base/progress.h"
#include "run/run.h"

namespace tactile {

// Either a complete run or an error, never a half-read run. An error names the file and the
// 1-based physical line; when it belongs to a column, `Error::column` is the column's 1-based
// position and the message starts with its name: "column 'n3' (position 10): expected ...".
using RunCsvResult = Result<RunData>;

// Limits of the readers, so that a hostile header or a flood of metadata lines is refused at once
// instead of being held in memory: at most kMaxRunColumns columns in the header (the 103 columns of
// the format plus `x_` columns) and at most kMaxRunMetadataLines metadata lines. Past either the
// reader fails at the line that goes past it.
inline constexpr std::size_t kMaxRunColumns = 10'000;
inline constexpr std::size_t kMaxRunMetadataLines = 10'000;

// Parses run-file text. `fileName` is used in error messages only. `progress` is called with
// bytes parsed and total bytes; returning false cancels (the result is then an error).
RunCsvResult parseRunCsv(std::string_view text, std::string_view fileName,
                         const ProgressFn& progress = {});

// A run file prepared for parsing on several threads. The metadata and header are read at once;
// the rows are split at line starts into chunks of about `chunkBytes`, which may be parsed
// concurrently and in any order. Joining the parsed chunks gives exactly what parseRunCsv gives,
// the same (first) error included. `text` must outlive the object.
class RunCsvChunks {
 public:
  RunCsvChunks(std::string_view text, std::string_view fileName, std::size_t chunkBytes);
  RunCsvChunks(RunCsvChunks&&) noexcept;
  RunCsvChunks& operator=(RunCsvChunks&&) noexcept;
  ~RunCsvChunks();

  // The metadata or header error, or null; with an error there is nothing to parse.
  const Error* error() const;
  // Metadata and x_ column names, no steps.
  const RunData& header() const;
  bool hasTruth() const;
  // At least one chunk (maybe empty) when the header is valid.
  std::size_t size() const;
  // The step the chunk's first row must carry (the number of lines before it).
  std::size_t firstStep(std::size_t chunk) const;
  std::size_t bytes(std::size_t chunk) const;
  // The chunk's rows (no metadata), or its first error. Safe to call from several threads.
  RunCsvResult parse(std::size_t chunk) const;
  // The error for a file whose chunks held `steps` rows in all, if that is one (no rows).
  std::optional<Error> checkStepCount(std::size_t steps) const;
  // The parsed chunks in order, joined into the run (or the first error in file order).
  RunCsvResult join(std::vector<RunCsvResult> parts) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// parseRunCsv on up to `threads` threads, chunk by chunk; the same result.
RunCsvResult parseRunCsvParallel(std::string_view text, std::string_view fileName, unsigned threads,
                                 std::size_t chunkBytes = std::size_t{4} << 20);

// Reads and parses a file.
RunCsvResult readRunCsv(const std::filesystem::path& path, const ProgressFn& progress = {});

// Formats a run as file text: metadata lines, the header in canonical column order (truth and x_
// columns when present), then one line per step. Doubles use the shortest text that reads back
// bit for bit.
std::string formatRunCsv(const RunData& run);
// The same text in pieces, in order, to `sink` (header first, then blocks of steps formatted on up
// to `threads` threads, 0 for one per core), without ever holding the whole text: for a checksum
// of a run's file form.
void formatRunCsvPieces(const RunData& run, unsigned threads,
                        const std::function<void(std::string_view)>& sink);

// Writes atomically: to a temporary file beside `path`, then renamed over it, so a failure never
// leaves a partial file. An error names the file.
Status writeRunCsv(const RunData& run, const std::filesystem::path& path);

}  // namespace tactile
