// The SQLite backend of the database handles (storage/db.h): sessions on one file, in the spirit of
// Mixxx's src/util/db. What only SQLite has (the raw handle, page 1 written on every commit, the
// online backup, which files this process holds open) is declared here for storage/ alone.
#pragma once

#include <cstdint>
#include <filesystem>

#include "storage/db.h"

struct sqlite3;

namespace tactile::storage::db {

// The SQLite handle of an SQLite connection. Throws DbError for another backend.
sqlite3* sqliteHandle(Connection& connection);

// From now on every Transaction on this connection also writes page 1 when it commits, by setting
// the application id to `applicationId` again (its value must be the file's), so that a log left
// behind by a killed process can be matched to the file it continues (file_guard.h). The statement
// is prepared once. Throws DbError.
void stampPageOneOnCommit(Connection& connection, std::int64_t applicationId);

// Whether a connection of this process has `path` open (the same file, by device and inode).
bool isOpenInThisProcess(const std::filesystem::path& path);

// Copies a whole database (any journal mode) into `target` with the online backup API.
// Throws DbError.
void backupTo(Connection& source, const std::filesystem::path& target);

}  // namespace tactile::storage::db
