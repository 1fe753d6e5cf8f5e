// Reading runs back: whole, by window, and as min/max summaries built from stored blocks.
#include <algorithm>
#include <cstring>

#include "run/run_csv.h"
#include "storage/database_impl.h"
#include "storage/run_codec.h"
#include "storage/step_checksum.h"

namespace tactile::storage {
namespace {

struct RunHeader {
  std::string name;
  std::int64_t stepCount = 0;
  bool hasTruth = false;
  std::vector<std::pair<std::string, std::string>> metadata;
  std::vector<std::string> extraColumns;
};

// The error for stored data that does not match its checksum (docs/storage.md#checksums).
db::DbError damaged(const RunDatabase::Impl& impl, const std::string& runName, std::int64_t runId,
                    const std::string& what) {
  return db::DbError(impl.path.string(),
                     "run '" + runName + "' (id " + std::to_string(runId) +
                         ") is damaged: " + what +
                         " does not match its checksum; nothing of it is read (`tactile db "
                         "check` lists the damage)");
}

// The steps columns every read selects, in this order, so that each row can be checked.
constexpr const char* kStepColumns =
    "step, x, y, theta, v, omega, blocked, sensors, extra, truth, crc";

// Throws unless the steps row under `s` (kStepColumns) matches its stored checksum.
void verifyStepRow(const RunDatabase::Impl& impl, const db::Statement& s, const RunHeader& header,
                   std::int64_t runId) {
  const StepRow row = stepRowAt(s, runId);
  if (s.columnIsNull(10) || s.columnInt(10) != stepChecksum(row)) {
    throw damaged(impl, header.name, runId, "step " + std::to_string(row.step));
  }
}

RunHeader readHeader(RunDatabase::Impl& impl, std::int64_t runId) {
  db::Statement& s = impl.statement(
      "SELECT step_count, has_truth, metadata, extra_columns, name, crc FROM runs WHERE id = ?");
  s.bind(1, runId);
  if (!s.step()) throw db::DbError("no run with id " + std::to_string(runId));
  RunHeader header;
  header.stepCount = s.columnInt(0);
  header.hasTruth = s.columnInt(1) != 0;
  header.name = s.columnText(4);
  if (s.columnIsNull(5) ||
      s.columnInt(5) != runChecksum(runId, header.name, header.stepCount, header.hasTruth,
                                    s.columnBlob(2), s.columnBytes(2), s.columnBlob(3),
                                    s.columnBytes(3))) {
    throw damaged(impl, header.name, runId, "the run's row (name, step count, metadata)");
  }
  std::vector<std::string> pairs;
  if (!decodeStrings(s.columnBlob(2), s.columnBytes(2), pairs) || pairs.size() % 2 != 0 ||
      !decodeStrings(s.columnBlob(3), s.columnBytes(3), header.extraColumns)) {
    throw db::DbError("malformed metadata of run " + std::to_string(runId));
  }
  for (std::size_t i = 0; i < pairs.size(); i += 2) {
    header.metadata.emplace_back(std::move(pairs[i]), std::move(pairs[i + 1]));
  }
  s.reset();
  return header;
}

// Columns 0-6 of a steps row (step, x, y, theta, v, omega, blocked) into row `row` of `out` (a
// RunData or a RunTrack), after checking that the row is step firstStep + row of n.
template <class Columns>
void readMotion(const db::Statement& s, std::int64_t runId, std::int64_t firstStep, std::size_t row,
                std::size_t n, Columns& out) {
  if (row >= n || s.columnInt(0) != firstStep + static_cast<std::int64_t>(row)) {
    throw db::DbError("run " + std::to_string(runId) + " has a gap or extra row at step " +
                      std::to_string(s.columnInt(0)));
  }
  out.x[row] = s.columnDouble(1);
  out.y[row] = s.columnDouble(2);
  out.theta[row] = s.columnDouble(3);
  out.v[row] = s.columnDouble(4);
  out.omega[row] = s.columnDouble(5);
  out.blocked[row] = static_cast<std::uint8_t>(s.columnInt(6));
}

RunWindow readWindow(RunDatabase::Impl& impl, std::int64_t runId, std::int64_t firstStep,
                     std::int64_t count) {
  RunHeader header = readHeader(impl, runId);
  RunWindow window;
  firstStep = std::clamp<std::int64_t>(firstStep, 0, header.stepCount);
  const std::int64_t end =
      count <= 0 ? firstStep : std::min<std::int64_t>(header.stepCount, firstStep + count);
  const auto n = static_cast<std::size_t>(end - firstStep);
  window.firstStep = firstStep;
  RunData& run = window.data;
  run.metadata = std::move(header.metadata);
  run.extraColumns = std::move(header.extraColumns);
  for (auto* column : {&run.x, &run.y, &run.theta, &run.v, &run.omega})
    column->resize(n);
  run.blocked.resize(n);
  run.sensors.resize(n * kValuesPerStep);
  if (!run.extraColumns.empty()) run.extraValues.reserve(n * run.extraColumns.size());
  if (header.hasTruth) run.truth.resize(n * kGroupCount);

  static const std::string sql = std::string("SELECT ") + kStepColumns +
                                 " FROM steps WHERE run_id = ? AND step >= ? AND step < ? "
                                 "ORDER BY step";
  db::Statement& s = impl.statement(sql.c_str());
  s.bind(1, runId).bind(2, firstStep).bind(3, end);
  std::size_t row = 0;
  while (s.step()) {
    verifyStepRow(impl, s, header, runId);
    readMotion(s, runId, firstStep, row, n, run);
    if (!decodeValues(s.columnBlob(7), static_cast<std::size_t>(s.columnBytes(7)), kValuesPerStep,
                      run.sensors.data() + row * kValuesPerStep)) {
      throw db::DbError("step " + std::to_string(firstStep + static_cast<std::int64_t>(row)) +
                        " of run " + std::to_string(runId) + " has a malformed sensors blob");
    }
    if (!run.extraColumns.empty() &&
        !decodeExtra(s.columnBlob(8), s.columnBytes(8), run.extraColumns.size(), run.extraValues)) {
      throw db::DbError("malformed x_ values at step " + std::to_string(firstStep + row));
    }
    if (header.hasTruth &&
        (s.columnIsNull(9) || !unpackTruth(s.columnInt(9), run.truth.data() + row * kGroupCount))) {
      throw db::DbError("step " + std::to_string(firstStep + static_cast<std::int64_t>(row)) +
                        " of run " + std::to_string(runId) + " has missing or malformed truth");
    }
    ++row;
  }
  if (row != n) {
    throw db::DbError("run " + std::to_string(runId) + " is missing steps from " +
                      std::to_string(firstStep + static_cast<std::int64_t>(row)));
  }

  return window;
}

RunTrack readTrack(RunDatabase::Impl& impl, std::int64_t runId) {
  const RunHeader header = readHeader(impl, runId);
  const auto n = static_cast<std::size_t>(header.stepCount);
  RunTrack track;
  for (auto* column : {&track.x, &track.y, &track.theta, &track.v, &track.omega})
    column->resize(n);
  track.blocked.resize(n);
  if (header.hasTruth) track.truth.resize(n * kGroupCount);
  // The sensors blob is never decoded, only checksummed with the rest of the row
  // (docs/storage.md#checksums); walking the rows bounds the speed (docs/storage.md#reading).
  static const std::string sql =
      std::string("SELECT ") + kStepColumns + " FROM steps WHERE run_id = ? ORDER BY step";
  db::Statement& s = impl.streamedStatement(sql.c_str());
  s.bind(1, runId);
  std::size_t row = 0;
  while (s.step()) {
    verifyStepRow(impl, s, header, runId);
    readMotion(s, runId, 0, row, n, track);
    if (header.hasTruth && (s.columnIsNull(9) ||
                            !unpackTruth(s.columnInt(9), track.truth.data() + row * kGroupCount))) {
      throw db::DbError("step " + std::to_string(row) + " of run " + std::to_string(runId) +
                        " has missing or malformed truth");
    }
    ++row;
  }
  s.reset();
  if (row != n) {
    throw db::DbError("run " + std::to_string(runId) + " is missing steps from " +
                      std::to_string(row));
  }
  return track;
}

// A piece of a summary range: steps [first, last] whose min/max come from one stored block of
// `level` (or, for level -1, from one step).
struct Piece {
  int level;
  std::int64_t index;
  std::int64_t first;
  std::int64_t last;
};

// Covers [first, last] exactly with pieces: single steps and finer blocks at the ragged ends,
// blocks of `top` in the middle (the classic segment-tree decomposition).
std::vector<Piece> decompose(std::int64_t first, std::int64_t last, std::int64_t runSteps,
                             int top) {
  std::vector<Piece> pieces;
  auto size = [](int level) { return level < 0 ? std::int64_t{1} : kSummaryBlockSteps[level]; };
  auto pieceEnd = [&](int level, std::int64_t start) {
    return std::min(start + size(level), runSteps) - 1;
  };
  std::int64_t cur = first;
  // Left ragged end: climb levels until aligned to the top block size.
  for (int level = -1; level < top && cur <= last; ++level) {
    const std::int64_t next = size(level + 1);
    while (cur <= last && cur % next != 0 && pieceEnd(level, cur) <= last) {
      pieces.push_back({level, cur / size(level), cur, pieceEnd(level, cur)});
      cur = pieceEnd(level, cur) + 1;
    }
  }
  // Middle and right end: descend levels.
  for (int level = top; level >= -1 && cur <= last; --level) {
    while (cur <= last && pieceEnd(level, cur) <= last) {
      pieces.push_back({level, cur / size(level), cur, pieceEnd(level, cur)});
      cur = pieceEnd(level, cur) + 1;
    }
  }
  return pieces;
}

RunSummary readSummary(RunDatabase::Impl& impl, std::int64_t runId, std::int64_t firstStep,
                       std::int64_t lastStep, int bucketCount) {
  if (bucketCount <= 0) throw db::DbError("a summary needs at least one bucket");
  const RunHeader header = readHeader(impl, runId);
  const std::int64_t runSteps = header.stepCount;
  RunSummary summary;
  if (lastStep < 0 || lastStep >= runSteps) lastStep = runSteps - 1;
  firstStep = std::max<std::int64_t>(0, firstStep);
  summary.firstStep = firstStep;
  summary.lastStep = lastStep;
  if (firstStep > lastStep) return summary;
  const std::int64_t length = lastStep - firstStep + 1;
  const std::int64_t buckets = std::min<std::int64_t>(bucketCount, length);
  // The coarsest level whose blocks are no wider than a bucket: bucket widths then differ by at
  // most one block from the ideal width, and at most ~2 * buckets blocks are read.
  const std::int64_t ideal = length / buckets;
  int top = -1;
  for (int level = 0; level < static_cast<int>(kSummaryBlockSteps.size()); ++level) {
    if (kSummaryBlockSteps[level] <= ideal) top = level;
  }
  summary.blockSteps = top < 0 ? 1 : kSummaryBlockSteps[top];
  const std::vector<Piece> pieces = decompose(firstStep, lastStep, runSteps, top);

  summary.buckets.resize(static_cast<std::size_t>(buckets));
  std::vector<bool> filled(summary.buckets.size(), false);
  auto merge = [&](const Piece& piece, const double* mins, const double* maxs) {
    const auto b = static_cast<std::size_t>((piece.first - firstStep) * buckets / length);
    SummaryBucket& bucket = summary.buckets[b];
    if (!filled[b]) {
      filled[b] = true;
      bucket.firstStep = piece.first;
      std::copy(mins, mins + kValuesPerStep, bucket.min.begin());
      std::copy(maxs, maxs + kValuesPerStep, bucket.max.begin());
    } else {
      for (int k = 0; k < kValuesPerStep; ++k) {
        bucket.min[k] = std::min(bucket.min[k], mins[k]);
        bucket.max[k] = std::max(bucket.max[k], maxs[k]);
      }
    }
    bucket.lastStep = piece.last;
  };

  // Pieces of one level are contiguous index ranges (at most one on each side of the middle), so
  // a few range queries read them all in step order.
  std::size_t i = 0;
  while (i < pieces.size()) {
    std::size_t j = i;
    while (j + 1 < pieces.size() && pieces[j + 1].level == pieces[i].level)
      ++j;
    const int level = pieces[i].level;
    std::size_t k = i;
    if (level < 0) {
      static const std::string sql = std::string("SELECT ") + kStepColumns +
                                     " FROM steps WHERE run_id = ? AND step >= ? AND step <= ? "
                                     "ORDER BY step";
      db::Statement& s = impl.statement(sql.c_str());
      s.bind(1, runId).bind(2, pieces[i].first).bind(3, pieces[j].last);
      while (s.step() && k <= j) {
        verifyStepRow(impl, s, header, runId);
        double row[kValuesPerStep];
        if (s.columnInt(0) != pieces[k].first ||
            !decodeValues(s.columnBlob(7), static_cast<std::size_t>(s.columnBytes(7)),
                          kValuesPerStep, row)) {
          throw db::DbError("steps of run " + std::to_string(runId) + " are inconsistent");
        }
        merge(pieces[k], row, row);
        ++k;
      }
      s.reset();
    } else {
      db::Statement& s = impl.statement(
          "SELECT block, minmax, crc FROM step_blocks WHERE run_id = ? AND level = ? AND "
          "block >= ? AND block <= ? ORDER BY block");
      s.bind(1, runId).bind(2, level).bind(3, pieces[i].index).bind(4, pieces[j].index);
      double values[kSummaryValues];
      while (s.step() && k <= j) {
        if (s.columnIsNull(2) ||
            s.columnInt(2) !=
                blockChecksum(runId, level, s.columnInt(0), s.columnBlob(1), s.columnBytes(1))) {
          throw damaged(impl, header.name, runId,
                        "summary block " + std::to_string(s.columnInt(0)) + " of level " +
                            std::to_string(level));
        }
        if (s.columnInt(0) != pieces[k].index ||
            !decodeValues(s.columnBlob(1), static_cast<std::size_t>(s.columnBytes(1)),
                          kSummaryValues, values)) {
          throw db::DbError("summary blocks of run " + std::to_string(runId) + " are inconsistent");
        }
        merge(pieces[k], values, values + kValuesPerStep);
        ++k;
      }
      s.reset();
    }
    if (k != j + 1) {
      throw db::DbError("run " + std::to_string(runId) + " is missing stored steps or blocks");
    }
    i = j + 1;
  }
  // Buckets narrower than a piece stay empty; drop them so every bucket holds data.
  std::vector<SummaryBucket> kept;
  kept.reserve(summary.buckets.size());
  for (std::size_t b = 0; b < summary.buckets.size(); ++b) {
    if (filled[b]) kept.push_back(summary.buckets[b]);
  }
  summary.buckets = std::move(kept);
  return summary;
}

}  // namespace

Result<RunWindow> RunStore::loadWindow(std::int64_t runId, std::int64_t firstStep,
                                       std::int64_t count) {
  return guarded<RunWindow>(*impl_, [&] { return readWindow(*impl_, runId, firstStep, count); });
}

Result<RunTrack> RunStore::loadTrack(std::int64_t runId) {
  return guarded<RunTrack>(*impl_, [&] { return readTrack(*impl_, runId); });
}

Result<RunSummary> RunStore::loadSummary(std::int64_t runId, std::int64_t firstStep,
                                         std::int64_t lastStep, int buckets) {
  return guarded<RunSummary>(
      *impl_, [&] { return readSummary(*impl_, runId, firstStep, lastStep, buckets); });
}

Result<std::optional<std::string>> RunStore::sceneJson(std::int64_t runId) {
  return guarded<std::optional<std::string>>(*impl_, [&] {
    db::Statement& s = impl_->statement(
        "SELECT scenes.json FROM runs LEFT JOIN scenes ON scenes.id = runs.scene_id "
        "WHERE runs.id = ?");
    s.bind(1, runId);
    if (!s.step()) throw db::DbError("no run with id " + std::to_string(runId));
    std::optional<std::string> json;
    if (!s.columnIsNull(0)) json = s.columnText(0);
    s.reset();
    return json;
  });
}

Status RunStore::exportRun(std::int64_t runId, const std::filesystem::path& file) {
  const ResetStatements reset{*impl_};
  Result<RunData> run = load(runId);
  if (!run) return run.error();
  return writeRunCsv(run.value(), file);
}

}  // namespace tactile::storage
