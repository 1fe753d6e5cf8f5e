// Runs stored while they are recorded: a run row first, then steps appended in chunks, each chunk
// one transaction with its summary blocks and the new step count, then the final metadata, truth
// and checksum. The step rows go through the import's one step writer (writeStepChunk).
#include <algorithm>
#include <string>
#include <vector>

#include "run/run_csv.h"
#include "storage/import_pieces.h"
#include "storage/step_checksum.h"

namespace tactile::storage {

using namespace importing;

namespace {

// A step row read by "SELECT x, y, theta, v, omega, blocked, sensors, extra", with `truth`; valid
// until `s` steps on.
StepRow stepRowWithTruth(const db::Statement& s, std::int64_t runId, std::int64_t step,
                         std::int64_t truth) {
  StepRow row;
  row.runId = runId;
  row.step = step;
  row.x = s.columnDouble(0);
  row.y = s.columnDouble(1);
  row.theta = s.columnDouble(2);
  row.v = s.columnDouble(3);
  row.omega = s.columnDouble(4);
  row.blocked = s.columnInt(5);
  row.sensors = s.columnBlob(6);
  row.sensorBytes = s.columnBytes(6);
  if (!s.columnIsNull(7)) {
    row.extra = s.columnBlob(7);
    row.extraBytes = s.columnBytes(7);
  }
  row.hasTruth = true;
  row.truth = truth;
  return row;
}

// A run's stored state as the recorder needs it.
struct StoredRun {
  std::int64_t steps = 0;
  bool hasTruth = false;
  bool hasExtra = false;
};

StoredRun storedRun(RunDatabase::Impl& impl, std::int64_t runId) {
  db::Statement& s =
      impl.statement("SELECT step_count, has_truth, length(extra_columns) FROM runs WHERE id = ?");
  s.bind(1, runId);
  if (!s.step()) throw db::DbError("no run with id " + std::to_string(runId));
  StoredRun run;
  run.steps = s.columnInt(0);
  run.hasTruth = s.columnInt(1) != 0;
  run.hasExtra = s.columnInt(2) > 0;
  s.reset();
  return run;
}

// Sets the run's step count and recomputes its row checksum from the row as stored.
void updateRunChecksum(RunDatabase::Impl& impl, std::int64_t runId, std::int64_t steps) {
  db::Statement& row =
      impl.statement("SELECT name, has_truth, metadata, extra_columns FROM runs WHERE id = ?");
  row.bind(1, runId);
  if (!row.step()) throw db::DbError("no run with id " + std::to_string(runId));
  const std::int64_t crc =
      runChecksum(runId, row.columnTextView(0), steps, row.columnInt(1) != 0, row.columnBlob(2),
                  row.columnBytes(2), row.columnBlob(3), row.columnBytes(3));
  row.reset();
  impl.statement("UPDATE runs SET step_count = ?, crc = ? WHERE id = ?")
      .bind(1, steps)
      .bind(2, crc)
      .bind(3, runId)
      .run();
}

// The steps [first, end) of `run`, without metadata.
RunData sliceSteps(const RunData& run, std::size_t first, std::size_t end) {
  RunData rows;
  auto copy = [&](const auto& from, auto& to, std::size_t width) {
    to.assign(from.begin() + static_cast<std::ptrdiff_t>(first * width),
              from.begin() + static_cast<std::ptrdiff_t>(end * width));
  };
  copy(run.x, rows.x, 1);
  copy(run.y, rows.y, 1);
  copy(run.theta, rows.theta, 1);
  copy(run.v, rows.v, 1);
  copy(run.omega, rows.omega, 1);
  copy(run.blocked, rows.blocked, 1);
  copy(run.sensors, rows.sensors, kValuesPerStep);
  if (run.hasTruth()) copy(run.truth, rows.truth, kGroupCount);
  rows.extraColumns = run.extraColumns;
  if (!run.extraColumns.empty()) copy(run.extraValues, rows.extraValues, run.extraColumns.size());
  return rows;
}

// Brings the summary blocks of every level up to date with the steps [first, end) of `run` just
// stored: blocks these steps fall in are merged with what the block already held (a block is
// partial while the run grows) and written back, so loadSummary works on the run at any time.
void writeSummaryBlocks(RunDatabase::Impl& impl, std::int64_t runId, const RunData& run,
                        std::size_t first, std::size_t end) {
  db::Statement& read =
      impl.statement("SELECT minmax FROM step_blocks WHERE run_id = ? AND level = ? AND block = ?");
  std::vector<double> values(kSummaryValues);
  std::vector<unsigned char> encoded(maxEncodedValueBytes(kSummaryValues));
  for (std::size_t level = 0; level < kSummaryBlockSteps.size(); ++level) {
    const auto size = static_cast<std::size_t>(kSummaryBlockSteps[level]);
    for (std::size_t block = first / size; block * size < end; ++block) {
      const std::size_t from = std::max(first, block * size);
      const std::size_t to = std::min(end, (block + 1) * size);
      double* mins = values.data();
      double* maxs = values.data() + kValuesPerStep;
      bool filled = false;
      if (from > block * size) {  // the block holds earlier steps
        read.bind(1, runId).bind(2, static_cast<std::int64_t>(level));
        read.bind(3, static_cast<std::int64_t>(block));
        if (read.step()) {
          if (!decodeValues(read.columnBlob(0), static_cast<std::size_t>(read.columnBytes(0)),
                            kSummaryValues, values.data())) {
            throw db::DbError("summary blocks of run " + std::to_string(runId) + " are malformed");
          }
          filled = true;
        }
        read.reset();
      }
      for (std::size_t s = from; s < to; ++s) {
        const double* row = run.stepSensors(s);
        if (!filled) {
          std::copy(row, row + kValuesPerStep, mins);
          std::copy(row, row + kValuesPerStep, maxs);
          filled = true;
          continue;
        }
        for (int k = 0; k < kValuesPerStep; ++k) {
          mins[k] = std::min(mins[k], row[k]);
          maxs[k] = std::max(maxs[k], row[k]);
        }
      }
      const std::size_t bytes = encodeValues(values.data(), kSummaryValues, encoded.data());
      impl.statement(
              "INSERT INTO step_blocks(run_id, level, block, minmax, crc) "
              "VALUES(?, ?, ?, ?, ?) ON CONFLICT(run_id, level, block) DO UPDATE SET "
              "minmax = excluded.minmax, crc = excluded.crc")
          .bind(1, runId)
          .bind(2, static_cast<std::int64_t>(level))
          .bind(3, static_cast<std::int64_t>(block))
          .bindBlob(4, encoded.data(), bytes)
          .bind(5, static_cast<std::int64_t>(blockChecksum(runId, static_cast<std::int64_t>(level),
                                                           static_cast<std::int64_t>(block),
                                                           encoded.data(), bytes)))
          .run();
    }
  }
}

// Appends steps [first, run.stepCount()) inside the caller's transaction.
void appendInside(RunDatabase::Impl& impl, std::int64_t runId, const RunData& run,
                  std::size_t first) {
  const StoredRun stored = storedRun(impl, runId);
  if (static_cast<std::int64_t>(first) != stored.steps) {
    throw db::DbError("run " + std::to_string(runId) + " has " + std::to_string(stored.steps) +
                      " steps stored; cannot append from step " + std::to_string(first));
  }
  const std::size_t end = run.stepCount();
  if (first > end) throw db::DbError("no steps to append from step " + std::to_string(first));
  if (first == end) return;
  if (run.hasTruth() != stored.hasTruth) {
    throw db::DbError(stored.hasTruth ? "the run was begun with truth; these steps have none"
                                      : "the run was begun without truth; these steps have it");
  }
  if (std::string problem = validateRun(run); !problem.empty()) throw db::DbError(problem);
  const StepChunk chunk = encodeChunk(sliceSteps(run, first, end), first, run.extraColumns.size());
  writeStepChunk(impl, runId, chunk, stored.hasTruth);
  const auto steps = static_cast<std::int64_t>(end);
  writeSummaryBlocks(impl, runId, run, first, end);
  updateRunChecksum(impl, runId, steps);
}

}  // namespace

Result<std::int64_t> RunStore::beginRun(const std::string& name, const RunData& header,
                                        bool withTruth, const SceneResolver& sceneResolver) {
  return guarded<std::int64_t>(*impl_, [&] {
    requireName(name, "run");
    FileHead head;
    head.file = name;
    head.name = name;
    head.header.metadata = header.metadata;
    head.header.extraColumns = header.extraColumns;
    head.hasTruth = withTruth;
    describeHead(head, {}, sceneResolver);
    db::Transaction transaction(impl_->connection);
    db::Statement& taken = impl_->statement("SELECT 1 FROM runs WHERE name = ?");
    taken.bind(1, name);
    if (taken.step()) throw db::DbError("a run named '" + name + "' already exists");
    taken.reset();
    std::int64_t sceneId = 0;
    if (!head.sceneJson.empty()) {
      impl_
          ->statement(
              "INSERT INTO scenes(name, checksum, json) VALUES(?, ?, ?) ON CONFLICT DO NOTHING")
          .bind(1, head.sceneName)
          .bind(2, head.sceneChecksum)
          .bind(3, head.sceneJson)
          .run();
      db::Statement& id = impl_->statement("SELECT id FROM scenes WHERE checksum = ?");
      id.bind(1, head.sceneChecksum);
      id.step();
      sceneId = id.columnInt(0);
      id.reset();
    }
    // The checksum is that of the finished run's CSV text; until then it says the run is being
    // recorded (never a 16-hex-digit file checksum, so no import is mistaken for it).
    db::Statement& insert = impl_->statement(
        "INSERT INTO runs(name, source_file, checksum, scene, scene_id, subject, outcome, dt, "
        "step_count, has_truth, metadata, extra_columns, imported_at) "
        "VALUES(?, ?, 'recording', ?, ?, ?, ?, ?, 0, ?, ?, ?, ?) RETURNING id");
    insert.bind(1, name).bind(2, name);
    if (head.sceneValue.empty()) {
      insert.bindNull(3);
    } else {
      insert.bind(3, head.sceneValue);
    }
    if (sceneId != 0) {
      insert.bind(4, sceneId);
    } else {
      insert.bindNull(4);
    }
    if (const std::string* subject = header.meta("subject")) {
      insert.bind(5, *subject);
    } else {
      insert.bindNull(5);
    }
    insert.bind(6, runOutcomeName(header.outcome()));
    if (auto dt = header.dtSeconds()) {
      insert.bind(7, *dt);
    } else {
      insert.bindNull(7);
    }
    insert.bind(8, withTruth ? 1 : 0)
        .bindBlob(9, head.metadataBlob.data(), head.metadataBlob.size())
        .bindBlob(10, head.extraColumnsBlob.data(), head.extraColumnsBlob.size())
        .bind(11, utcNow());
    const std::int64_t runId = insert.runReturningId();
    updateRunChecksum(*impl_, runId, 0);
    transaction.commit();
    return runId;
  });
}

Status RunStore::appendSteps(std::int64_t runId, const RunData& run, std::size_t firstStep) {
  return guardedStatus(*impl_, [&] {
    db::Transaction transaction(impl_->connection);
    appendInside(*impl_, runId, run, firstStep);
    transaction.commit();
  });
}

Status RunStore::finishRun(std::int64_t runId, const RunData& run) {
  return guardedStatus(*impl_, [&] {
    if (std::string problem = validateRun(run); !problem.empty()) throw db::DbError(problem);
    const std::string checksum = checksumHex(formatRunCsv(run));
    db::Transaction transaction(impl_->connection);
    const StoredRun stored = storedRun(*impl_, runId);
    if (stored.steps > static_cast<std::int64_t>(run.stepCount())) {
      throw db::DbError("run " + std::to_string(runId) + " has more steps stored (" +
                        std::to_string(stored.steps) + ") than the run given (" +
                        std::to_string(run.stepCount()) + ")");
    }
    appendInside(*impl_, runId, run, static_cast<std::size_t>(stored.steps));
    if (stored.hasTruth) {
      std::vector<std::pair<std::int64_t, std::int64_t>> changed;
      db::Statement& s =
          impl_->statement("SELECT step, truth FROM steps WHERE run_id = ? ORDER BY step");
      s.bind(1, runId);
      while (s.step()) {
        const std::int64_t step = s.columnInt(0);
        const std::int64_t want =
            packTruth(run.truth.data() + static_cast<std::size_t>(step) * kGroupCount);
        if (s.columnIsNull(1) || s.columnInt(1) != want) changed.emplace_back(step, want);
      }
      s.reset();
      db::Statement& read = impl_->statement(
          "SELECT x, y, theta, v, omega, blocked, sensors, extra FROM steps "
          "WHERE run_id = ? AND step = ?");
      db::Statement& update =
          impl_->statement("UPDATE steps SET truth = ?, crc = ? WHERE run_id = ? AND step = ?");
      for (const auto& [step, packed] : changed) {
        read.bind(1, runId).bind(2, step);
        if (!read.step()) throw db::DbError("step " + std::to_string(step) + " vanished");
        const std::int64_t crc = stepChecksum(stepRowWithTruth(read, runId, step, packed));
        read.reset();
        update.bind(1, packed).bind(2, crc).bind(3, runId).bind(4, step).run();
      }
    }
    std::vector<std::string> pairs;
    for (const auto& [key, value] : run.metadata) {
      pairs.push_back(key);
      pairs.push_back(value);
    }
    const std::string blob = encodeExtra(pairs.data(), pairs.size());
    db::Statement& update = impl_->statement(
        "UPDATE runs SET metadata = ?, outcome = ?, subject = ?, checksum = ? WHERE id = ?");
    update.bindBlob(1, blob.data(), blob.size()).bind(2, runOutcomeName(run.outcome()));
    if (const std::string* subject = run.meta("subject")) {
      update.bind(3, *subject);
    } else {
      update.bindNull(3);
    }
    update.bind(4, checksum).bind(5, runId).run();
    updateRunChecksum(*impl_, runId, static_cast<std::int64_t>(run.stepCount()));
    transaction.commit();
    impl_->refreshStepStatistics(static_cast<std::int64_t>(run.stepCount()));
  });
}

}  // namespace tactile::storage
