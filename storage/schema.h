// The database schema and its versioned migrations (PRAGMA user_version), in the spirit of
// Mixxx's SchemaManager: an ordered list of migrations, each taking the schema from version N-1 to
// N; opening runs the missing ones in one transaction after a backup copy of the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "storage/sqlite/sqlite_connection.h"

namespace tactile::storage::db {

// The schema version this program writes. A database with a higher user_version was written by
// a newer program and is refused rather than misread.
inline constexpr int kSchemaVersion = 7;

// PRAGMA application_id of tactile databases ("TACT"), so that another program's SQLite file is
// recognised and refused instead of being "migrated".
inline constexpr int kApplicationId = 0x54414354;

struct Migration {
  int version;  // the schema version after this migration
  std::string_view description;
  std::string_view sql;
};

// All migrations, in version order (version 1 creates the first schema).
std::span<const Migration> migrations();

struct MigrationReport {
  int fromVersion = 0;
  int toVersion = 0;
  std::filesystem::path backupPath;  // empty when no backup was needed (new or current database)
};

// The database's user_version.
int schemaVersion(Connection& connection);

// What identifies a Tactile database, read in one statement (one snapshot: another process may
// be creating the schema at the same moment, and separate reads could mix before and after).
struct Identity {
  std::int64_t applicationId = 0;
  int version = 0;           // PRAGMA user_version
  std::int64_t objects = 0;  // rows of sqlite_schema
};
Identity readIdentity(Connection& connection);

// Why migrating this database from its user_version to `targetVersion` would fail, found by
// running the migrations on a copy of its schema (no rows) in memory; nullopt when it would work
// or nothing needs doing. Reads only. A damaged user_version (tables of another version) shows
// here.
std::optional<std::string> migrationProblem(Connection& connection,
                                            int targetVersion = kSchemaVersion);

// Brings the database to `targetVersion` (the newest by default; lower targets exist for tests
// that need an old database). A database newer than kSchemaVersion, or one that belongs to
// another application, is an error. An existing database with older data is first copied to
// `backupPath(dbPath, version)`; then all missing migrations run in one transaction, so a failure
// leaves the file as it was. Throws DbError with a clear message.
MigrationReport migrate(Connection& connection, const std::filesystem::path& dbPath,
                        int targetVersion = kSchemaVersion);

// "<db>.v<version>.bak", or with a numeric suffix when that file already exists.
std::filesystem::path backupPath(const std::filesystem::path& dbPath, int version);

}  // namespace tactile::storage::db
