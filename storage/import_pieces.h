// Internal to storage: run import in three pieces. Preparing a file (reading, hashing, parsing and
// encoding it chunk by chunk; import_prepare.cpp) runs on worker threads; the SQL writer
// (run_writer.cpp) stores one prepared file per transaction on the calling thread; the scheduler
// (run_import.cpp) hands chunks from the workers to the writer in order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "run/run.h"
#include "run/run_csv.h"
#include "storage/database_impl.h"
#include "storage/run_codec.h"
#include "storage/step_checksum.h"

namespace tactile::storage::importing {

inline constexpr std::size_t kDefaultChunkBytes = std::size_t{4} << 20;
// The largest scene file import reads beside a run (docs/file-formats.md#run-file).
inline constexpr std::uint64_t kMaxSceneFileBytes = std::uint64_t{16} << 20;

// What the writer needs of a file before its steps; made off the writer thread.
struct FileHead {
  std::string file;  // as given, for messages
  std::string name;
  std::string checksum;
  // Instead of `checksum` (then empty): the checksum as it is computed beside the writer, waited
  // for once the steps are written (or when the name is taken). Returns false with `error` set when
  // it could not be computed; the run is then not stored.
  std::function<bool(std::string& checksum, std::string& error)> lateChecksum;
  // Optional: told the run's id once its row is written (the steps' checksums include it).
  std::function<void(std::int64_t runId)> runStarted;
  std::string error;  // non-empty: the file is rejected
  std::vector<std::string> warnings;
  RunData header;  // metadata and x_ column names, no steps
  bool hasTruth = false;
  std::size_t chunkCount = 0;
  std::string noStepsError;  // the reader's error for a file without rows; empty: allowed
  std::string sceneValue;    // the `scene` metadata value
  std::string sceneName;
  std::string sceneJson;  // empty when unresolved
  std::string sceneChecksum;
  std::string metadataBlob;
  std::string extraColumnsBlob;
};

// A whole run's summary blocks, encoded, with each block row's checksum for run `runId`.
struct SummaryRows {
  std::int64_t runId = 0;
  std::vector<EncodedBlobs> levels;
  std::vector<std::vector<std::int32_t>> checksums;  // [level][block]
};
// The rows of `summary` for run `runId`.
SummaryRows summaryRows(SummaryBlocks summary, std::int64_t runId);

// Consecutive steps of a run, parsed and encoded off the writer thread.
struct StepChunk {
  std::string error;  // non-empty: the file is rejected (the reader's message)
  RunData rows;       // no metadata
  std::size_t firstStep = 0;
  EncodedBlobs sensors;                   // one per step
  std::vector<std::int64_t> packedTruth;  // one per step when the run has truth
  std::vector<std::string> extraBlobs;    // one per step when there are x_ columns
  PartialSummary summary;                 // finest-level blocks of these steps
  // Optional: each row's stepChecksum for run `checksumsRunId` (taken off the writer thread);
  // the writer takes them itself when they are missing or for another run id.
  std::vector<std::int32_t> checksums;
  std::int64_t checksumsRunId = 0;
  // Optional, on the last chunk: the whole run's summary rows, made off the writer thread (the
  // chunks' `summary` are then empty).
  std::optional<SummaryRows> wholeSummary;
};

// Rejects runs that cannot be stored faithfully (hand-built ones; the reader checks files).
std::string validateRun(const RunData& run);
// Metadata blobs and the scene, from the header (metadata and x_ names) of a run.
void describeHead(FileHead& head, const std::filesystem::path& baseDir,
                  const SceneResolver& resolver);
StepChunk encodeChunk(RunData rows, std::size_t firstStep, std::size_t extraColumns);
// The steps [first, first + count) of `run`, encoded (only those rows' columns are copied).
StepChunk encodeSteps(const RunData& run, std::size_t first, std::size_t count);
// Never throws: any failure (even out of memory on a worker thread) becomes the chunk's error.
StepChunk parseChunk(const RunCsvChunks& chunks, std::size_t index, const std::string& file);
// The head of a file's text once split into chunks (the header read).
void describeText(FileHead& head, const RunCsvChunks& chunks, const SceneResolver& resolver);
// The given name, else `PREFIX_<stem>` (or the stem without a prefix); docs/storage.md#import.
std::string runName(const ImportOptions& options, const std::filesystem::path& file);
ImportOutcome cancelledOutcome(const std::filesystem::path& file);

// The steps row of the chunk's i-th step in run `runId`, as it is written.
StepRow stepRowOf(const StepChunk& chunk, std::size_t i, std::int64_t runId, bool hasTruth);
// Fills chunk.checksums for run `runId`.
void checksumSteps(StepChunk& chunk, std::int64_t runId, bool hasTruth);

// Writes the steps rows of one chunk of run `runId` (steps chunk.firstStep, ...) with their
// checksums, inside the caller's transaction. Every writer of step rows goes through here, so
// every row carries its checksum (docs/storage.md#checksums). `failAfterSteps` (>= 0) injects a
// failure at that step, for tests.
void writeStepChunk(RunDatabase::Impl& impl, std::int64_t runId, const StepChunk& chunk,
                    bool hasTruth, std::int64_t failAfterSteps = -1);

// The SQL writer: stores one run in its own transaction: the run row, then the steps chunk by
// chunk as `takeChunk(i)` hands them over, then the summary blocks. A chunk with an error, or any
// failure, rolls everything back. With head.lateChecksum the check for a run of the same content
// comes after the steps are written (same outcome: skipped, nothing stored).
ImportOutcome writeRun(RunDatabase::Impl& impl, FileHead& head,
                       const std::function<StepChunk(std::size_t)>& takeChunk,
                       std::int64_t failAfterSteps);

}  // namespace tactile::storage::importing
