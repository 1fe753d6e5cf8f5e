// Internal: the state behind RunDatabase, shared by its implementation files.
#pragma once

#include <exception>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/text_rules.h"
#include "storage/run_database.h"
#include "storage/sqlite/sqlite_connection.h"

namespace tactile::storage {

struct RunDatabase::Impl {
  std::filesystem::path path;
  std::filesystem::path backup;
  bool readOnly = false;
  bool created = false;
  db::Connection connection;
  // How a file's connection was opened, so that a whole-run read can open a second one the same
  // way and step part of the run on another thread (run_columns.cpp): unset for a server or
  // ":memory:". The page cache and memory map each connection asks for.
  std::optional<db::Access> fileAccess;
  int cacheKiB = 0;
  std::int64_t mmapBytes = 0;
  // That second connection, opened by the first whole-run read of a long run and kept (its memory
  // map stays in place from one read to the next); closed before `connection` (declared after it).
  db::Connection secondReader;
  // Prepared statements reused across calls, keyed by the address of their SQL literal.
  std::unordered_map<const char*, db::Statement> statements;
  // Public calls running on this connection (one may call another).
  int callDepth = 0;

  // The cached statement for a string literal; ready to bind (reset if it was stepped).
  db::Statement& statement(const char* sql) {
    auto it = statements.find(sql);
    if (it == statements.end()) it = statements.emplace(sql, db::Statement(connection, sql)).first;
    it->second.reset();
    return it->second;
  }
  // The same for a statement that reads a whole run's rows (db::Statement::Streamed): a literal is
  // used one way or the other, never both.
  db::Statement& streamedStatement(const char* sql) {
    auto it = statements.find(sql);
    if (it == statements.end()) {
      it = statements.emplace(sql, db::Statement(connection, sql, db::Statement::Streamed{})).first;
    }
    it->second.reset();
    return it->second;
  }

  std::int64_t runIdByName(std::string_view name);       // throws DbError when absent
  std::int64_t labelSetIdByName(std::string_view name);  // 0 when absent
  std::int64_t ensureLabelSet(const std::string& name);  // inside a caller's transaction
  std::int64_t runStepCount(std::int64_t runId);         // throws when the run is absent
  // After `addedSteps` steps were written, outside any transaction: on a server, refreshes the
  // planner's statistics of the step tables when they grew by a tenth or more (see
  // run_database.cpp). Never throws; does nothing on a file.
  void refreshStepStatistics(std::int64_t addedSteps);
  // Newest-wins insertion inside a caller's transaction; `keepId` != 0 reuses that id.
  std::int64_t insertSegmentNewestWins(std::int64_t setId, const LabelSegment& segment,
                                       std::int64_t keepId);

  // ---- label history (label_history.cpp), inside a caller's write transaction ----
  // The revision the last edit made.
  std::int64_t lastRevision = 0;
  // Throws a conflict (isLabelConflict) when options.expectRevision is set and a later revision
  // of the set on the run (by another annotator with options.othersOnly) changed a step of
  // [firstStep, lastStep] in `group`.
  void checkExpectedRevision(std::int64_t setId, std::int64_t runId, SensorGroup group,
                             std::int64_t firstStep, std::int64_t lastStep,
                             const EditOptions& options);
  // The set's segments of one run and group overlapping [firstStep, lastStep], by first step
  // (label_scope.cpp).
  std::vector<LabelSegment> overlappingSegments(std::int64_t setId, std::int64_t runId,
                                                SensorGroup group, std::int64_t firstStep,
                                                std::int64_t lastStep);
  // The same, clipped to [firstStep, lastStep].
  std::vector<LabelSegment> clippedSegments(std::int64_t setId, std::int64_t runId,
                                            SensorGroup group, std::int64_t firstStep,
                                            std::int64_t lastStep);
  // Stores one revision and returns it (also in lastRevision).
  std::int64_t recordRevision(std::int64_t setId, std::int64_t runId, SensorGroup group,
                              std::int64_t firstStep, std::int64_t lastStep,
                              std::optional<ContactClass> cls, std::string_view action,
                              std::string_view annotator,
                              const std::vector<LabelSegment>& replaced);
};

// A label segment from a row of `SELECT label_segments.id, runs.name, run_id, grp, first_step,
// last_step, class, annotator` (label_scope.cpp). Throws DbError on a malformed row.
LabelSegment labelSegmentFromRow(db::Statement& s);

// Current UTC time as "YYYY-MM-DDTHH:MM:SSZ".
std::string utcNow();

// Resets every cached statement when the outermost public call on the connection ends, so that no
// statement left on a row (a single-row lookup) holds a read transaction open. An open read
// transaction would pin the connection to an old snapshot: it would not see what other
// connections (the CLI, the workbench's import worker) write, and would keep the WAL from being
// checkpointed. A call made inside another leaves the outer call's statements alone.
class ResetStatements {
 public:
  explicit ResetStatements(RunDatabase::Impl& impl) : impl_(impl) { ++impl_.callDepth; }
  ~ResetStatements() {
    if (--impl_.callDepth > 0) return;
    for (auto& [sql, statement] : impl_.statements)
      statement.reset();
    // No public call leaves a transaction open: it would hold locks and an old snapshot. One still
    // open here was abandoned by a failure (nothing of it was committed): it is rolled back.
    if (impl_.connection.isOpen() && impl_.connection.inTransaction()) {
      impl_.connection.backend().rollback();
    }
  }
  ResetStatements(const ResetStatements&) = delete;
  ResetStatements& operator=(const ResetStatements&) = delete;

 private:
  RunDatabase::Impl& impl_;
};

// The name rule (base/text_rules.h) at the storage boundary, so that every way a name enters
// (CLI, GUI, workspace) meets it: throws DbError with the rule's message. `what` is "run",
// "label set", "model", "sweep" or "annotator".
inline void requireName(std::string_view name, std::string_view what) {
  if (Status ok = checkName(name, what); !ok) throw db::DbError(ok.error().message);
}

// Runs one public call: `fn`, with any exception turned into a failed Result / Status (a DbError
// from SQLite names its database in Error::file, docs/storage.md#errors), then the statements
// reset as above.
template <class T, class Fn>
Result<T> guarded(RunDatabase::Impl& impl, Fn&& fn) {
  const ResetStatements reset{impl};
  try {
    return Result<T>(fn());
  } catch (const db::DbError& e) {
    return Result<T>(Error(e.file, e.what()));
  } catch (const std::exception& e) {
    return Result<T>::failure(e.what());
  }
}

template <class Fn>
Status guardedStatus(RunDatabase::Impl& impl, Fn&& fn) {
  const ResetStatements reset{impl};
  try {
    fn();
    return Status::success();
  } catch (const db::DbError& e) {
    return Status(Error(e.file, e.what()));
  } catch (const std::exception& e) {
    return Status::failure(e.what());
  }
}

}  // namespace tactile::storage
