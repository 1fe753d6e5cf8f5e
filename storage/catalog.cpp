// The catalog: runs and label sets listed, renamed and deleted by name (docs/storage.md#catalog).
// Every change is one transaction; an unknown name is an error naming it that changes nothing.
#include <algorithm>
#include <map>
#include <set>

#include "storage/database_impl.h"
#include "storage/step_checksum.h"

namespace tactile::storage {
namespace {

// Runs `fn`; any exception becomes an Error about the database file.
template <class T, class Fn>
Result<T> aboutDatabase(const std::filesystem::path& db, Fn&& fn) {
  try {
    if constexpr (std::is_void_v<T>) {
      fn();
      return Result<T>::success();
    } else {
      return Result<T>(fn());
    }
  } catch (const std::exception& e) {
    return Error(db.string(), e.what());
  }
}

std::string quotedList(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names)
    out += (out.empty() ? "'" : ", '") + name + "'";
  return out;
}

// Ids of `names` in `table` (distinct, in order); throws naming every unknown one.
std::vector<std::int64_t> idsByName(RunDatabase::Impl& impl, const std::vector<std::string>& names,
                                    const char* sql, const char* what) {
  if (names.empty()) throw db::DbError(std::string("no ") + what + " names given");
  std::vector<std::int64_t> ids;
  std::vector<std::string> unknown;
  for (const std::string& name : names) {
    db::Statement& s = impl.statement(sql);
    s.bind(1, name);
    if (s.step()) {
      const std::int64_t id = s.columnInt(0);
      if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
    } else if (std::find(unknown.begin(), unknown.end(), name) == unknown.end()) {
      unknown.push_back(name);
    }
    s.reset();
  }
  if (!unknown.empty()) {
    throw db::DbError(std::string("no ") + what + (unknown.size() > 1 ? "s" : "") + " named " +
                      quotedList(unknown) + "; nothing deleted");
  }
  return ids;
}

}  // namespace

Result<std::vector<RunCatalogEntry>> RunStore::catalog() {
  const ResetStatements reset{*impl_};
  Result<std::vector<RunInfo>> runs = list();
  if (!runs) return Error(impl_->path.string(), runs.error().message);
  return aboutDatabase<std::vector<RunCatalogEntry>>(impl_->path, [&] {
    std::map<std::int64_t, std::set<std::string>> setsOfRun;
    db::Statement& s = impl_->statement(
        "SELECT DISTINCT label_segments.run_id, label_sets.name FROM label_segments "
        "JOIN label_sets ON label_sets.id = label_segments.set_id");
    while (s.step())
      setsOfRun[s.columnInt(0)].insert(s.columnText(1));
    s.reset();
    std::vector<RunCatalogEntry> out;
    out.reserve(runs->size());
    for (RunInfo& run : runs.value()) {
      RunCatalogEntry entry;
      const auto it = setsOfRun.find(run.id);
      if (it != setsOfRun.end()) entry.labelSets.assign(it->second.begin(), it->second.end());
      entry.run = std::move(run);
      out.push_back(std::move(entry));
    }
    return out;
  });
}

Status RunStore::rename(std::string_view name, const std::string& newName) {
  const ResetStatements reset{*impl_};
  return aboutDatabase<void>(impl_->path, [&] {
    requireName(newName, "run");
    db::Transaction transaction(impl_->connection);
    const std::int64_t id = impl_->runIdByName(name);  // "no run named 'X'"
    db::Statement& taken = impl_->statement("SELECT source_file FROM runs WHERE name = ?");
    taken.bind(1, newName);
    if (taken.step() && newName != name) {
      throw db::DbError("cannot rename run '" + std::string(name) + "': a run named '" + newName +
                        "' already exists (imported from " + taken.columnText(0) + ")");
    }
    taken.reset();
    // The checksum covers the name; a row that did not match before still does not after.
    db::Statement& row = impl_->statement(
        "SELECT name, step_count, has_truth, metadata, extra_columns, crc FROM runs WHERE id = ?");
    row.bind(1, id);
    if (!row.step()) throw db::DbError("no run with id " + std::to_string(id));
    const auto checksumWith = [&](std::string_view runName) {
      return runChecksum(id, runName, row.columnInt(1), row.columnInt(2) != 0, row.columnBlob(3),
                         row.columnBytes(3), row.columnBlob(4), row.columnBytes(4));
    };
    const bool matched =
        !row.columnIsNull(5) && row.columnInt(5) == checksumWith(row.columnTextView(0));
    const std::int64_t after = checksumWith(newName);
    row.reset();
    db::Statement& update = impl_->statement("UPDATE runs SET name = ?, crc = ? WHERE id = ?");
    update.bind(1, newName).bind(3, id);
    if (matched) {
      update.bind(2, after);
    } else {
      update.bindNull(2);
    }
    update.run();
    transaction.commit();
  });
}

Status RunStore::remove(const std::vector<std::string>& names) {
  const ResetStatements reset{*impl_};
  return aboutDatabase<void>(impl_->path, [&] {
    db::Transaction transaction(impl_->connection);
    const std::vector<std::int64_t> ids =
        idsByName(*impl_, names, "SELECT id FROM runs WHERE name = ?", "run");
    for (const std::int64_t id : ids) {
      // The child tables cascade too (foreign keys are on); deleting them by name keeps that
      // true even on a connection where they are not.
      impl_->statement("DELETE FROM label_segments WHERE run_id = ?").bind(1, id).run();
      impl_->statement("DELETE FROM label_revisions WHERE run_id = ?").bind(1, id).run();
      impl_->statement("DELETE FROM assignments WHERE run_id = ?").bind(1, id).run();
      impl_->statement("DELETE FROM step_blocks WHERE run_id = ?").bind(1, id).run();
      impl_->statement("DELETE FROM steps WHERE run_id = ?").bind(1, id).run();
      impl_->statement("DELETE FROM runs WHERE id = ?").bind(1, id).run();
    }
    impl_->connection.exec(
        "DELETE FROM scenes WHERE id NOT IN (SELECT scene_id FROM runs WHERE scene_id IS NOT "
        "NULL)");
    transaction.commit();
  });
}

Result<std::vector<LabelSetCatalogEntry>> LabelStore::catalog() {
  const ResetStatements reset{*impl_};
  Result<std::vector<LabelSetInfo>> sets = list();
  if (!sets) return Error(impl_->path.string(), sets.error().message);
  return aboutDatabase<std::vector<LabelSetCatalogEntry>>(impl_->path, [&] {
    std::map<std::int64_t, std::set<std::string>> runsOfSet;
    db::Statement& s = impl_->statement(
        "SELECT DISTINCT label_segments.set_id, runs.name FROM label_segments "
        "JOIN runs ON runs.id = label_segments.run_id");
    while (s.step())
      runsOfSet[s.columnInt(0)].insert(s.columnText(1));
    s.reset();
    std::vector<LabelSetCatalogEntry> out;
    out.reserve(sets->size());
    for (LabelSetInfo& set : sets.value()) {
      LabelSetCatalogEntry entry;
      const auto it = runsOfSet.find(set.id);
      if (it != runsOfSet.end()) entry.runs.assign(it->second.begin(), it->second.end());
      entry.set = std::move(set);
      out.push_back(std::move(entry));
    }
    return out;
  });
}

Status LabelStore::rename(std::string_view name, const std::string& newName) {
  const ResetStatements reset{*impl_};
  return aboutDatabase<void>(impl_->path, [&] {
    requireName(newName, "label set");
    db::Transaction transaction(impl_->connection);
    const std::int64_t id = impl_->labelSetIdByName(name);
    if (id == 0) throw db::DbError("no label set named '" + std::string(name) + "'");
    const std::int64_t existing = impl_->labelSetIdByName(newName);
    if (existing != 0 && existing != id) {
      throw db::DbError("cannot rename label set '" + std::string(name) + "': a label set named '" +
                        newName + "' already exists");
    }
    impl_->statement("UPDATE label_sets SET name = ? WHERE id = ?")
        .bind(1, newName)
        .bind(2, id)
        .run();
    impl_->statement("UPDATE assignments SET label_set = ? WHERE label_set = ?")
        .bind(1, newName)
        .bind(2, name)
        .run();
    transaction.commit();
  });
}

Status LabelStore::remove(const std::vector<std::string>& names) {
  const ResetStatements reset{*impl_};
  return aboutDatabase<void>(impl_->path, [&] {
    db::Transaction transaction(impl_->connection);
    const std::vector<std::int64_t> ids =
        idsByName(*impl_, names, "SELECT id FROM label_sets WHERE name = ?", "label set");
    for (const std::int64_t id : ids) {
      impl_->statement("DELETE FROM label_segments WHERE set_id = ?").bind(1, id).run();
      impl_->statement("DELETE FROM label_revisions WHERE set_id = ?").bind(1, id).run();
      impl_->statement("DELETE FROM label_sets WHERE id = ?").bind(1, id).run();
    }
    transaction.commit();
  });
}

}  // namespace tactile::storage
