#include "storage/db.h"

namespace tactile::storage::db {

std::int64_t Connection::queryInt(std::string_view sql) {
  Statement statement(*this, sql);
  if (!statement.step()) throw DbError(file(), "no result (in: " + std::string(sql) + ")");
  const std::int64_t value = statement.columnInt(0);
  statement.reset();
  return value;
}

std::int64_t Statement::runReturningId() {
  if (!step()) throw DbError("an insert returned no id");
  const std::int64_t id = columnInt(0);
  reset();
  return id;
}

void Transaction::commit() {
  if (connection_ == nullptr) throw DbError("commit of an inactive transaction");
  connection_->backend().commit();
  connection_ = nullptr;
}

}  // namespace tactile::storage::db
