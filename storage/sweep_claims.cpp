// Sweeps planned for workers: one claim row per fit job, claimed under a lease, completed with
// its cells in one transaction (docs/cluster.md).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "storage/database_impl.h"

namespace tactile::storage {

namespace {

SweepClaim claimFromRow(db::Statement& s) {
  SweepClaim c;
  c.job = s.columnInt(0);
  c.cells = s.columnInt(1);
  c.state = s.columnText(2);
  c.worker = s.columnText(3);
  c.leaseUntil = s.columnDouble(4);
  c.attempts = s.columnInt(5);
  c.error = s.columnText(6);
  c.seconds = s.columnDouble(7);
  c.finishedAt = s.columnText(8);
  return c;
}

}  // namespace

Result<std::int64_t> SweepStore::plan(const std::string& name, const std::string& configurationJson,
                                      const std::vector<std::int64_t>& cellsPerJob,
                                      const std::vector<double>& costPerJob) {
  return guarded<std::int64_t>(*impl_, [&] {
    requireName(name, "sweep");
    if (!costPerJob.empty() && costPerJob.size() != cellsPerJob.size())
      throw db::DbError("a sweep's plan needs one cost per job");
    db::Transaction transaction(impl_->connection);
    const std::int64_t id =
        impl_
            ->statement(
                "INSERT INTO sweeps(name, configuration, created_at) VALUES(?, ?, ?) RETURNING id")
            .bind(1, name)
            .bind(2, configurationJson)
            .bind(3, utcNow())
            .runReturningId();
    db::RowWriter rows(impl_->connection, "sweep_claims", "sweep_id, job, cells, cost, state", 5);
    for (std::size_t job = 0; job < cellsPerJob.size(); ++job) {
      rows.bind(1, id).bind(2, static_cast<std::int64_t>(job)).bind(3, cellsPerJob[job]);
      rows.bind(4, costPerJob.empty() ? 0.0 : costPerJob[job]);
      rows.bindText(5, "pending");
      rows.add();
    }
    rows.finish();
    transaction.commit();
    return id;
  });
}

Result<std::optional<SweepClaim>> SweepStore::claim(std::int64_t sweepId, const std::string& worker,
                                                    double now, double leaseSeconds) {
  return guarded<std::optional<SweepClaim>>(*impl_, [&]() -> std::optional<SweepClaim> {
    db::Transaction transaction(impl_->connection, db::Transaction::RowLocking{});
    // A job whose workers all died in it is not handed out again.
    const std::string lost = "its worker stopped mid-job " + std::to_string(kSweepClaimAttempts) +
                             " times (killed, or out of memory?)";
    impl_
        ->statement(
            "UPDATE sweep_claims SET state = 'failed', error = ? WHERE sweep_id = ? AND "
            "state = 'running' AND lease_until < ? AND attempts >= ?")
        .bind(1, lost)
        .bind(2, sweepId)
        .bind(3, now)
        .bind(4, kSweepClaimAttempts)
        .run();
    // The most expensive job first. PostgreSQL: the row is locked until commit and skipped by the
    // other workers meanwhile.
    db::Statement& pick = impl_->statement(
        impl_->connection.isSqlite()
            ? "SELECT job FROM sweep_claims WHERE sweep_id = ? AND (state = 'pending' OR "
              "(state = 'running' AND lease_until < ?)) ORDER BY cost DESC, job LIMIT 1"
            : "SELECT job FROM sweep_claims WHERE sweep_id = ? AND (state = 'pending' OR "
              "(state = 'running' AND lease_until < ?)) ORDER BY cost DESC, job LIMIT 1 "
              "FOR UPDATE SKIP LOCKED");
    pick.bind(1, sweepId).bind(2, now);
    if (!pick.step()) {
      pick.reset();
      transaction.commit();
      return std::nullopt;
    }
    const std::int64_t job = pick.columnInt(0);
    pick.reset();
    db::Statement& take = impl_->statement(
        "UPDATE sweep_claims SET state = 'running', worker = ?, lease_until = ?, "
        "attempts = attempts + 1, error = '' WHERE sweep_id = ? AND job = ? RETURNING job, "
        "cells, state, worker, lease_until, attempts, error, seconds, finished_at");
    take.bind(1, worker).bind(2, now + leaseSeconds).bind(3, sweepId).bind(4, job);
    if (!take.step()) throw db::DbError("claim of job " + std::to_string(job) + " was lost");
    SweepClaim claimed = claimFromRow(take);
    take.reset();
    transaction.commit();
    return claimed;
  });
}

Result<bool> SweepStore::renew(std::int64_t sweepId, std::int64_t job, const std::string& worker,
                               double leaseUntil) {
  return guarded<bool>(*impl_, [&] {
    db::Transaction transaction(impl_->connection, db::Transaction::RowLocking{});
    impl_
        ->statement(
            "UPDATE sweep_claims SET lease_until = ? WHERE sweep_id = ? AND job = ? AND "
            "worker = ? AND state = 'running'")
        .bind(1, leaseUntil)
        .bind(2, sweepId)
        .bind(3, job)
        .bind(4, worker)
        .run();
    const bool held = impl_->connection.changes() > 0;
    transaction.commit();
    return held;
  });
}

Result<bool> SweepStore::complete(std::int64_t sweepId, std::int64_t job, const std::string& worker,
                                  double seconds,
                                  const std::vector<std::pair<std::string, std::string>>& cells) {
  return guarded<bool>(*impl_, [&] {
    db::Transaction transaction(impl_->connection, db::Transaction::RowLocking{});
    // The row lock (PostgreSQL) or the write lock (SQLite) makes a second completion wait for the
    // first and then find the job done.
    impl_
        ->statement(
            "UPDATE sweep_claims SET state = 'done', worker = ?, seconds = ?, finished_at = ?, "
            "error = '' WHERE sweep_id = ? AND job = ? AND state IN ('pending', 'running')")
        .bind(1, worker)
        .bind(2, seconds)
        .bind(3, utcNow())
        .bind(4, sweepId)
        .bind(5, job)
        .run();
    if (impl_->connection.changes() == 0) {
      transaction.rollback();
      return false;
    }
    db::Statement& insert = impl_->statement(
        "INSERT INTO sweep_cells(sweep_id, configuration, metrics) VALUES(?, ?, ?)");
    for (const auto& [settings, metrics] : cells)
      insert.bind(1, sweepId).bind(2, settings).bind(3, metrics).run();
    transaction.commit();
    return true;
  });
}

Status SweepStore::fail(std::int64_t sweepId, std::int64_t job, const std::string& worker,
                        const std::string& error) {
  return guardedStatus(*impl_, [&] {
    db::Transaction transaction(impl_->connection, db::Transaction::RowLocking{});
    impl_
        ->statement(
            "UPDATE sweep_claims SET state = 'failed', error = ?, finished_at = ? WHERE "
            "sweep_id = ? AND job = ? AND worker = ? AND state = 'running'")
        .bind(1, error)
        .bind(2, utcNow())
        .bind(3, sweepId)
        .bind(4, job)
        .bind(5, worker)
        .run();
    transaction.commit();
  });
}

Status SweepStore::release(std::int64_t sweepId, std::int64_t job, const std::string& worker) {
  return guardedStatus(*impl_, [&] {
    db::Transaction transaction(impl_->connection, db::Transaction::RowLocking{});
    impl_
        ->statement(
            "UPDATE sweep_claims SET state = 'pending', lease_until = 0, "
            "attempts = attempts - 1 WHERE sweep_id = ? AND job = ? AND worker = ? AND "
            "state = 'running'")
        .bind(1, sweepId)
        .bind(2, job)
        .bind(3, worker)
        .run();
    transaction.commit();
  });
}

Result<std::vector<SweepClaim>> SweepStore::claims(std::int64_t sweepId) {
  return guarded<std::vector<SweepClaim>>(*impl_, [&] {
    std::vector<SweepClaim> out;
    db::Statement& s = impl_->statement(
        "SELECT job, cells, state, worker, lease_until, attempts, error, seconds, finished_at "
        "FROM sweep_claims WHERE sweep_id = ? ORDER BY job");
    s.bind(1, sweepId);
    while (s.step())
      out.push_back(claimFromRow(s));
    s.reset();
    return out;
  });
}

}  // namespace tactile::storage
