// The SQL writer of run import: one prepared run per transaction (see import_pieces.h).
#include <string>

#include "storage/import_pieces.h"
#include "storage/step_checksum.h"

namespace tactile::storage::importing {

namespace {

// Binds and writes the chunk's rows to `target`: a cached INSERT statement (SQLite) or a bulk row
// writer (PostgreSQL's COPY); both take the same 1-based columns.
template <class Target, class Emit>
void writeRows(Target& target, Emit emit, std::int64_t runId, const StepChunk& chunk, bool hasTruth,
               std::int64_t failAfterSteps) {
  const bool hasExtra = !chunk.extraBlobs.empty();
  // Checksums taken beside the writer, for this run's id (else taken here).
  const bool checksummed =
      chunk.checksumsRunId == runId && chunk.checksums.size() == chunk.rows.stepCount();
  target.bind(1, runId);
  if (!hasExtra) target.bindNull(10);
  if (!hasTruth) target.bindNull(11);
  const std::size_t n = chunk.rows.stepCount();
  for (std::size_t i = 0; i < n; ++i) {
    const StepRow row = stepRowOf(chunk, i, runId, hasTruth);
    if (row.step == failAfterSteps) {
      throw db::DbError("injected failure after " + std::to_string(row.step) + " steps");
    }
    target.bind(1, runId)
        .bind(2, row.step)
        .bind(3, row.x)
        .bind(4, row.y)
        .bind(5, row.theta)
        .bind(6, row.v)
        .bind(7, row.omega)
        .bind(8, row.blocked)
        .bindBlob(9, row.sensors, row.sensorBytes);
    if (hasExtra) target.bindBlob(10, row.extra, row.extraBytes);
    if (hasTruth) target.bind(11, row.truth);
    target.bind(12,
                static_cast<std::int64_t>(checksummed ? chunk.checksums[i] : stepChecksum(row)));
    emit();
  }
}

constexpr const char* kStepColumns =
    "run_id, step, x, y, theta, v, omega, blocked, sensors, extra, truth, crc";

}  // namespace

StepRow stepRowOf(const StepChunk& chunk, std::size_t i, std::int64_t runId, bool hasTruth) {
  const RunData& rows = chunk.rows;
  StepRow row;
  row.runId = runId;
  row.hasTruth = hasTruth;
  row.step = static_cast<std::int64_t>(chunk.firstStep + i);
  row.x = rows.x[i];
  row.y = rows.y[i];
  row.theta = rows.theta[i];
  row.v = rows.v[i];
  row.omega = rows.omega[i];
  row.blocked = static_cast<std::int64_t>(rows.blocked[i]);
  row.sensors = chunk.sensors.data(i);
  row.sensorBytes = chunk.sensors.bytes(i);
  if (!chunk.extraBlobs.empty()) {
    row.extra = chunk.extraBlobs[i].data();
    row.extraBytes = chunk.extraBlobs[i].size();
  }
  if (hasTruth) row.truth = chunk.packedTruth[i];
  return row;
}

SummaryRows summaryRows(SummaryBlocks summary, std::int64_t runId) {
  SummaryRows rows;
  rows.runId = runId;
  rows.levels = encodeSummaryBlocks(summary);
  rows.checksums.resize(rows.levels.size());
  for (std::size_t level = 0; level < rows.levels.size(); ++level) {
    const EncodedBlobs& blobs = rows.levels[level];
    rows.checksums[level].resize(blobs.size());
    for (std::size_t b = 0; b < blobs.size(); ++b) {
      rows.checksums[level][b] =
          blockChecksum(runId, static_cast<std::int64_t>(level), static_cast<std::int64_t>(b),
                        blobs.data(b), blobs.bytes(b));
    }
  }
  return rows;
}

void checksumSteps(StepChunk& chunk, std::int64_t runId, bool hasTruth) {
  const std::size_t n = chunk.rows.stepCount();
  chunk.checksums.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    chunk.checksums[i] = stepChecksum(stepRowOf(chunk, i, runId, hasTruth));
  chunk.checksumsRunId = runId;
}

void writeStepChunk(RunDatabase::Impl& impl, std::int64_t runId, const StepChunk& chunk,
                    bool hasTruth, std::int64_t failAfterSteps) {
  if (!impl.connection.isSqlite()) {
    db::RowWriter bulk(impl.connection, "steps", kStepColumns, 12);
    writeRows(
        bulk, [&] { bulk.add(); }, runId, chunk, hasTruth, failAfterSteps);
    bulk.finish();
    return;
  }
  db::Statement& step = impl.statement(
      "INSERT INTO steps(run_id, step, x, y, theta, v, omega, blocked, sensors, extra, truth, crc) "
      "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  writeRows(
      step, [&] { step.step(); }, runId, chunk, hasTruth, failAfterSteps);
  step.reset();
}

// Writes one run in its own transaction: the run row, then the steps chunk by chunk as
// `takeChunk(i)` hands them over, then the summary blocks. A chunk with an error, or any failure,
// rolls everything back.
ImportOutcome writeRun(RunDatabase::Impl& impl, FileHead& head,
                       const std::function<StepChunk(std::size_t)>& takeChunk,
                       std::int64_t failAfterSteps) {
  ImportOutcome outcome;
  outcome.file = head.file;
  outcome.runName = head.name;
  outcome.warnings = std::move(head.warnings);
  if (!head.error.empty()) {
    outcome.message = std::move(head.error);
    return outcome;
  }
  if (Status name = checkName(head.name, "run"); !name) {
    outcome.message = head.file + ": " + name.error().message +
                      "; give the run a name with --name (or the file another name)";
    return outcome;
  }
  const RunData& header = head.header;
  try {
    // The steps and block rows reference the run row written in this same transaction, so their
    // per-row foreign-key lookups can be skipped; the pragma only works outside a transaction and
    // is restored on every path.
    // (SQLite only: a PostgreSQL server checks them once per COPY batch anyway.)
    struct ForeignKeysOff {
      db::Connection& c;
      explicit ForeignKeysOff(db::Connection& connection) : c(connection) {
        if (c.isSqlite()) c.exec("PRAGMA foreign_keys = OFF");
      }
      ~ForeignKeysOff() {
        try {
          if (c.isSqlite()) c.exec("PRAGMA foreign_keys = ON");
        } catch (const std::exception&) {
        }
      }
    } foreignKeysOff(impl.connection);
    // The checksum and name are checked inside the write transaction: another process importing
    // into the same file at the same time may have stored this file or name since this one
    // looked (docs/storage.md#concurrency), and then it is skipped or refused, never a raw
    // UNIQUE-constraint error.
    db::Transaction transaction(impl.connection);
    // True (with the outcome filled in) when a run of the same content is stored.
    const auto storedAlready = [&](const std::string& checksum) {
      db::Statement& dup =
          impl.statement("SELECT id, name, step_count FROM runs WHERE checksum = ?");
      dup.bind(1, checksum);
      if (dup.step()) {
        outcome.status = ImportStatus::Skipped;
        outcome.runId = dup.columnInt(0);
        outcome.runName = dup.columnText(1);
        outcome.steps = dup.columnInt(2);
        outcome.message = head.file + ": already imported as run '" + outcome.runName +
                          "' (same checksum " + checksum + "); skipped";
        dup.reset();
        return true;
      }
      dup.reset();
      return false;
    };
    // A checksum computed beside this writer: waited for here. False: it failed (outcome set).
    bool checksumKnown = !head.lateChecksum;
    const auto awaitChecksum = [&] {
      if (checksumKnown) return true;
      std::string error;
      if (!head.lateChecksum(head.checksum, error)) {
        outcome.message = std::move(error);
        return false;
      }
      checksumKnown = true;
      return true;
    };
    if (checksumKnown && storedAlready(head.checksum)) return outcome;
    {
      db::Statement& named = impl.statement("SELECT source_file FROM runs WHERE name = ?");
      named.bind(1, head.name);
      if (named.step()) {
        const std::string sourceFile = named.columnText(0);
        named.reset();
        // The same content under this name is a skip, not a clash (as when checked first).
        if (!awaitChecksum()) return outcome;
        if (storedAlready(head.checksum)) return outcome;
        outcome.message = head.file + ": a run named '" + head.name +
                          "' already exists (imported from " + sourceFile +
                          ", other content); not imported: give this batch a name prefix "
                          "(tactile import --prefix P names runs P_<stem>) or the file "
                          "another name (--name)";
        return outcome;
      }
      named.reset();
    }

    std::int64_t sceneId = 0;
    if (!head.sceneJson.empty()) {
      impl.statement(
              "INSERT INTO scenes(name, checksum, json) VALUES(?, ?, ?) ON CONFLICT DO NOTHING")
          .bind(1, head.sceneName)
          .bind(2, head.sceneChecksum)
          .bind(3, head.sceneJson)
          .run();
      db::Statement& id = impl.statement("SELECT id FROM scenes WHERE checksum = ?");
      id.bind(1, head.sceneChecksum);
      id.step();
      sceneId = id.columnInt(0);
      id.reset();
    }
    const std::string now = utcNow();
    // step_count is set once the steps are in.
    db::Statement& insertRun = impl.statement(
        "INSERT INTO runs(name, source_file, checksum, scene, scene_id, subject, outcome, dt, "
        "step_count, has_truth, metadata, extra_columns, imported_at) "
        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, 0, ?, ?, ?, ?) RETURNING id");
    insertRun.bind(1, head.name).bind(2, head.file).bind(3, head.checksum);
    if (head.sceneValue.empty()) {
      insertRun.bindNull(4);
    } else {
      insertRun.bind(4, head.sceneValue);
    }
    if (sceneId != 0) {
      insertRun.bind(5, sceneId);
    } else {
      insertRun.bindNull(5);
    }
    const std::string* subject = header.meta("subject");
    if (subject != nullptr) {
      insertRun.bind(6, *subject);
    } else {
      insertRun.bindNull(6);
    }
    insertRun.bind(7, runOutcomeName(header.outcome()));
    if (auto dt = header.dtSeconds()) {
      insertRun.bind(8, *dt);
    } else {
      insertRun.bindNull(8);
    }
    insertRun.bind(9, head.hasTruth ? 1 : 0)
        .bindBlob(10, head.metadataBlob.data(), head.metadataBlob.size())
        .bindBlob(11, head.extraColumnsBlob.data(), head.extraColumnsBlob.size())
        .bind(12, now);
    const std::int64_t runId = insertRun.runReturningId();
    if (head.runStarted) head.runStarted(runId);

    SummaryBuilder summary;
    std::optional<SummaryRows> given;  // made beside the writer
    std::int64_t steps = 0;
    for (std::size_t c = 0; c < head.chunkCount; ++c) {
      StepChunk chunk = takeChunk(c);
      if (!chunk.error.empty()) {
        outcome.message = std::move(chunk.error);
        return outcome;  // rolls back
      }
      const std::size_t n = chunk.rows.stepCount();
      if (n > 0 && static_cast<std::int64_t>(chunk.firstStep) != steps) {
        throw db::DbError("steps out of order at step " + std::to_string(chunk.firstStep));
      }
      writeStepChunk(impl, runId, chunk, head.hasTruth, failAfterSteps);
      steps += static_cast<std::int64_t>(n);
      if (chunk.wholeSummary) {
        given = std::move(chunk.wholeSummary);
      } else if (n > 0 && chunk.summary.steps > 0) {
        summary.merge(chunk.summary);
      }
    }
    if (steps == 0 && !head.noStepsError.empty()) {
      outcome.message = std::move(head.noStepsError);
      return outcome;  // rolls back
    }
    if (!checksumKnown) {
      if (!awaitChecksum() || storedAlready(head.checksum)) return outcome;  // rolls back
      impl.statement("UPDATE runs SET checksum = ? WHERE id = ?")
          .bind(1, head.checksum)
          .bind(2, runId)
          .run();
    }

    if (!given || given->runId != runId) given = summaryRows(std::move(summary).finish(), runId);
    const std::vector<EncodedBlobs>& levels = given->levels;
    const auto writeBlocks = [&](auto& block, auto emit) {
      block.bind(1, runId);
      for (std::size_t level = 0; level < levels.size(); ++level) {
        const EncodedBlobs& blobs = levels[level];
        for (std::size_t b = 0; b < blobs.size(); ++b) {
          block.bind(1, runId)
              .bind(2, static_cast<std::int64_t>(level))
              .bind(3, static_cast<std::int64_t>(b))
              .bindBlob(4, blobs.data(b), blobs.bytes(b))
              .bind(5, static_cast<std::int64_t>(given->checksums[level][b]));
          emit();
        }
      }
    };
    if (impl.connection.isSqlite()) {
      db::Statement& block = impl.statement(
          "INSERT INTO step_blocks(run_id, level, block, minmax, crc) VALUES(?, ?, ?, ?, ?)");
      writeBlocks(block, [&] { block.step(); });
      block.reset();
    } else {
      db::RowWriter block(impl.connection, "step_blocks", "run_id, level, block, minmax, crc", 5);
      writeBlocks(block, [&] { block.add(); });
      block.finish();
    }
    impl.statement("UPDATE runs SET step_count = ?, crc = ? WHERE id = ?")
        .bind(1, steps)
        .bind(2, static_cast<std::int64_t>(
                     runChecksum(runId, head.name, steps, head.hasTruth, head.metadataBlob.data(),
                                 head.metadataBlob.size(), head.extraColumnsBlob.data(),
                                 head.extraColumnsBlob.size())))
        .bind(3, runId)
        .run();
    transaction.commit();
    outcome.status = ImportStatus::Imported;
    outcome.runId = runId;
    outcome.steps = steps;
  } catch (const std::exception& e) {
    outcome.status = ImportStatus::Failed;
    outcome.runId = 0;
    // An SQLite failure names the database too (docs/storage.md#errors).
    outcome.message = head.file + ": not stored in " + impl.path.string() + ": " + e.what();
  }
  return outcome;
}

}  // namespace tactile::storage::importing
