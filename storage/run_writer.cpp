// The SQL writer of run import: one prepared run per transaction (see import_pieces.h).
#include <string>

#include "storage/import_pieces.h"

namespace tactile::storage::importing {

// Writes the steps of one chunk as rows of run `runId`; `steps` is the run's next step number and
// is advanced past the chunk. Throws db::DbError (the caller's transaction rolls back).
void writeStepChunk(RunDatabase::Impl& impl, std::int64_t runId, const StepChunk& chunk,
                    bool hasExtra, bool hasTruth, std::int64_t& steps,
                    std::int64_t failAfterSteps) {
  db::Statement& step = impl.statement(
      "INSERT INTO steps(run_id, step, x, y, theta, v, omega, blocked, sensors, extra, truth) "
      "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  step.bind(1, runId);
  if (!hasExtra) step.bindNull(10);
  if (!hasTruth) step.bindNull(11);
  const RunData& rows = chunk.rows;
  const std::size_t n = rows.stepCount();
  if (n > 0 && static_cast<std::int64_t>(chunk.firstStep) != steps) {
    throw db::DbError("steps out of order at step " + std::to_string(chunk.firstStep));
  }
  for (std::size_t i = 0; i < n; ++i, ++steps) {
    if (steps == failAfterSteps) {
      throw db::DbError("injected failure after " + std::to_string(steps) + " steps");
    }
    step.bind(2, steps)
        .bind(3, rows.x[i])
        .bind(4, rows.y[i])
        .bind(5, rows.theta[i])
        .bind(6, rows.v[i])
        .bind(7, rows.omega[i])
        .bind(8, static_cast<std::int64_t>(rows.blocked[i]))
        .bindBlob(9, chunk.sensors.data(i), chunk.sensors.bytes(i));
    if (hasExtra) step.bindBlob(10, chunk.extraBlobs[i].data(), chunk.extraBlobs[i].size());
    if (hasTruth) step.bind(11, chunk.packedTruth[i]);
    step.step();
  }
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
  const RunData& header = head.header;
  try {
    // The steps and block rows reference the run row written in this same transaction, so their
    // per-row foreign-key lookups can be skipped; the pragma only works outside a transaction and
    // is restored on every path.
    struct ForeignKeysOff {
      db::Connection& c;
      explicit ForeignKeysOff(db::Connection& connection) : c(connection) {
        c.exec("PRAGMA foreign_keys = OFF");
      }
      ~ForeignKeysOff() {
        try {
          c.exec("PRAGMA foreign_keys = ON");
        } catch (const std::exception&) {
        }
      }
    } foreignKeysOff(impl.connection);
    // The checksum and name are checked inside the write transaction: another process importing
    // into the same file at the same time may have stored this file or name since this one
    // looked (docs/storage.md#concurrency), and then it is skipped or refused, never a raw
    // UNIQUE-constraint error.
    db::Transaction transaction(impl.connection);
    {
      db::Statement& dup =
          impl.statement("SELECT id, name, step_count FROM runs WHERE checksum = ?");
      dup.bind(1, head.checksum);
      if (dup.step()) {
        outcome.status = ImportStatus::Skipped;
        outcome.runId = dup.columnInt(0);
        outcome.runName = dup.columnText(1);
        outcome.steps = dup.columnInt(2);
        outcome.message = head.file + ": already imported as run '" + outcome.runName +
                          "' (same checksum " + head.checksum + "); skipped";
        dup.reset();
        return outcome;
      }
      dup.reset();
    }
    {
      db::Statement& named = impl.statement("SELECT source_file FROM runs WHERE name = ?");
      named.bind(1, head.name);
      if (named.step()) {
        outcome.message = head.file + ": a run named '" + head.name +
                          "' already exists (imported from " + named.columnText(0) +
                          ", other content); not imported: give this batch a name prefix "
                          "(tactile import --prefix P names runs P_<stem>) or the file "
                          "another name (--name)";
        named.reset();
        return outcome;
      }
      named.reset();
    }

    std::int64_t sceneId = 0;
    if (!head.sceneJson.empty()) {
      impl.statement("INSERT OR IGNORE INTO scenes(name, checksum, json) VALUES(?, ?, ?)")
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
        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, 0, ?, ?, ?, ?)");
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
        .bind(12, now)
        .run();
    const std::int64_t runId = impl.connection.lastInsertRowId();

    const bool hasExtra = !header.extraColumns.empty();
    SummaryBuilder summary;
    std::int64_t steps = 0;
    for (std::size_t c = 0; c < head.chunkCount; ++c) {
      StepChunk chunk = takeChunk(c);
      if (!chunk.error.empty()) {
        outcome.message = std::move(chunk.error);
        return outcome;  // rolls back
      }
      const std::size_t n = chunk.rows.stepCount();
      writeStepChunk(impl, runId, chunk, hasExtra, head.hasTruth, steps, failAfterSteps);
      if (n > 0) summary.merge(chunk.summary);
    }
    if (steps == 0 && !head.noStepsError.empty()) {
      outcome.message = std::move(head.noStepsError);
      return outcome;  // rolls back
    }

    const std::vector<EncodedBlobs> levels = encodeSummaryBlocks(std::move(summary).finish());
    db::Statement& block =
        impl.statement("INSERT INTO step_blocks(run_id, level, block, minmax) VALUES(?, ?, ?, ?)");
    block.bind(1, runId);
    for (std::size_t level = 0; level < levels.size(); ++level) {
      const EncodedBlobs& blobs = levels[level];
      block.bind(2, static_cast<std::int64_t>(level));
      for (std::size_t b = 0; b < blobs.size(); ++b) {
        block.bind(3, static_cast<std::int64_t>(b))
            .bindBlob(4, blobs.data(b), blobs.bytes(b))
            .step();
      }
    }
    block.reset();
    impl.statement("UPDATE runs SET step_count = ? WHERE id = ?")
        .bind(1, steps)
        .bind(2, runId)
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
