// Models and sweeps: listing, storing cell by cell, deleting (docs/storage.md#models-and-sweeps).
#include <set>
#include <string>
#include <vector>

#include "storage/database_impl.h"

namespace tactile::storage {

namespace {

ModelInfo modelFromRow(db::Statement& s) {
  ModelInfo m;
  m.id = s.columnInt(0);
  m.name = s.columnText(1);
  m.createdAt = s.columnText(2);
  m.trainedOnJson = s.columnText(3);
  m.metricsJson = s.columnText(4);
  return m;
}

SweepInfo sweepFromRow(db::Statement& s) {
  SweepInfo w;
  w.id = s.columnInt(0);
  w.name = s.columnText(1);
  w.createdAt = s.columnText(2);
  w.configurationJson = s.columnText(3);
  w.cellCount = s.columnInt(4);
  return w;
}

constexpr const char* kSweepColumns =
    "SELECT id, name, created_at, configuration, "
    "(SELECT count(*) FROM sweep_cells c WHERE c.sweep_id = sweeps.id) FROM sweeps";

}  // namespace

Result<std::vector<ModelInfo>> ModelStore::list() {
  return guarded<std::vector<ModelInfo>>(*impl_, [&] {
    std::vector<ModelInfo> out;
    db::Statement& s = impl_->statement(
        "SELECT id, name, created_at, trained_on, metrics FROM models ORDER BY name");
    while (s.step())
      out.push_back(modelFromRow(s));
    s.reset();
    return out;
  });
}

Result<ModelInfo> ModelStore::info(std::string_view name) {
  return guarded<ModelInfo>(*impl_, [&] {
    db::Statement& s = impl_->statement(
        "SELECT id, name, created_at, trained_on, metrics FROM models WHERE name = ?");
    s.bind(1, name);
    if (!s.step()) throw db::DbError("no model named '" + std::string(name) + "'");
    ModelInfo m = modelFromRow(s);
    s.reset();
    return m;
  });
}

Status ModelStore::remove(const std::vector<std::string>& names) {
  return guardedStatus(*impl_, [&] {
    db::Transaction transaction(impl_->connection);
    db::Statement& s = impl_->statement("DELETE FROM models WHERE name = ?");
    std::set<std::string> done;  // a name given twice is deleted once
    for (const std::string& name : names) {
      if (!done.insert(name).second) continue;
      s.bind(1, name).run();
      if (impl_->connection.changes() == 0) {
        throw db::DbError("no model named '" + name + "'; nothing deleted");
      }
    }
    transaction.commit();
  });
}

Result<std::int64_t> ModelStore::add(const std::string& name, const std::string& json,
                                     const std::string& trainedOnJson,
                                     const std::string& metricsJson) {
  return guarded<std::int64_t>(*impl_, [&] {
    requireName(name, "model");
    db::Transaction transaction(impl_->connection);
    db::Statement& exists = impl_->statement("SELECT 1 FROM models WHERE name = ?");
    exists.bind(1, name);
    const bool taken = exists.step();
    exists.reset();
    if (taken) {
      throw db::DbError("a model named '" + name +
                        "' is already stored; choose another name or delete it first");
    }
    const std::int64_t id = impl_
                                ->statement(
                                    "INSERT INTO models(name, json, trained_on, metrics, "
                                    "created_at) VALUES(?, ?, ?, ?, ?) RETURNING id")
                                .bind(1, name)
                                .bind(2, json)
                                .bind(3, trainedOnJson)
                                .bind(4, metricsJson)
                                .bind(5, utcNow())
                                .runReturningId();
    transaction.commit();
    return id;
  });
}

Result<std::int64_t> SweepStore::create(const std::string& name,
                                        const std::string& configurationJson) {
  return guarded<std::int64_t>(*impl_, [&] {
    requireName(name, "sweep");
    db::Transaction transaction(impl_->connection);
    const std::int64_t id =
        impl_
            ->statement(
                "INSERT INTO sweeps(name, configuration, created_at) VALUES(?, ?, ?) RETURNING id")
            .bind(1, name)
            .bind(2, configurationJson)
            .bind(3, utcNow())
            .runReturningId();
    transaction.commit();
    return id;
  });
}

Result<std::int64_t> SweepStore::addCell(std::int64_t sweepId, const std::string& configurationJson,
                                         const std::string& metricsJson) {
  return guarded<std::int64_t>(*impl_, [&] {
    db::Transaction transaction(impl_->connection);
    const std::int64_t id = impl_
                                ->statement(
                                    "INSERT INTO sweep_cells(sweep_id, configuration, metrics) "
                                    "VALUES(?, ?, ?) RETURNING id")
                                .bind(1, sweepId)
                                .bind(2, configurationJson)
                                .bind(3, metricsJson)
                                .runReturningId();
    transaction.commit();
    return id;
  });
}

Status SweepStore::update(std::int64_t sweepId, const std::string& configurationJson) {
  return guardedStatus(*impl_, [&] {
    db::Transaction transaction(impl_->connection);
    impl_->statement("UPDATE sweeps SET configuration = ? WHERE id = ?")
        .bind(1, configurationJson)
        .bind(2, sweepId)
        .run();
    if (impl_->connection.changes() == 0) {
      throw db::DbError("no sweep with id " + std::to_string(sweepId));
    }
    transaction.commit();
  });
}

Result<std::vector<SweepInfo>> SweepStore::list() {
  return guarded<std::vector<SweepInfo>>(*impl_, [&] {
    static const std::string sql = std::string(kSweepColumns) + " ORDER BY id";
    std::vector<SweepInfo> out;
    db::Statement& s = impl_->statement(sql.c_str());
    while (s.step())
      out.push_back(sweepFromRow(s));
    s.reset();
    return out;
  });
}

Result<SweepInfo> SweepStore::info(std::int64_t sweepId) {
  return guarded<SweepInfo>(*impl_, [&] {
    static const std::string sql = std::string(kSweepColumns) + " WHERE id = ?";
    db::Statement& s = impl_->statement(sql.c_str());
    s.bind(1, sweepId);
    if (!s.step()) throw db::DbError("no sweep with id " + std::to_string(sweepId));
    SweepInfo w = sweepFromRow(s);
    s.reset();
    return w;
  });
}

Result<std::vector<SweepCellRecord>> SweepStore::cells(std::int64_t sweepId) {
  return guarded<std::vector<SweepCellRecord>>(*impl_, [&] {
    std::vector<SweepCellRecord> out;
    db::Statement& s = impl_->statement(
        "SELECT id, configuration, metrics FROM sweep_cells WHERE sweep_id = ? ORDER BY id");
    s.bind(1, sweepId);
    while (s.step())
      out.push_back({s.columnInt(0), s.columnText(1), s.columnText(2)});
    s.reset();
    return out;
  });
}

Status SweepStore::remove(const std::vector<std::int64_t>& sweepIds) {
  return guardedStatus(*impl_, [&] {
    db::Transaction transaction(impl_->connection);
    db::Statement& s = impl_->statement("DELETE FROM sweeps WHERE id = ?");
    std::set<std::int64_t> done;  // an id given twice is deleted once
    for (const std::int64_t id : sweepIds) {
      if (!done.insert(id).second) continue;
      s.bind(1, id).run();
      if (impl_->connection.changes() == 0) {
        throw db::DbError("no sweep with id " + std::to_string(id) + "; nothing deleted");
      }
    }
    transaction.commit();
  });
}

}  // namespace tactile::storage
