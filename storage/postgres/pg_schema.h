// The Tactile schema on a PostgreSQL server: the same tables, columns and meaning as in an SQLite
// file (storage/schema.h), in PostgreSQL's types, created in the session's current schema
// (normally `public`). A table `tactile_meta` holds the identity that SQLite keeps in the file's
// header: the application id and the schema version.
#pragma once

#include <string>

#include "storage/db.h"

namespace tactile::storage::db {

// What the current schema of the database holds.
struct ServerContent {
  bool tactile = false;     // tactile_meta with our application id
  int version = 0;          // its schema version (tactile only)
  std::int64_t tables = 0;  // tables of any kind in the current schema
};
ServerContent inspectServer(Connection& connection);

// Makes the schema in a database whose current schema holds no table, in one transaction; a
// database holding another application's tables is refused (DbError) and left unchanged. Several
// processes creating it at once: one creates, the others find it made.
void createServerSchema(Connection& connection);

// The three rights of a team (docs/team.md#roles): group roles tactile_annotator (read everything,
// edit labels and assignments), tactile_researcher (also models and sweeps) and tactile_admin
// (everything: import, rename and delete runs), each holding the one before. grantRole makes them
// when absent, grants them on the current schema's tables, makes `role` (a login role) when
// absent and gives it exactly `right` ("annotator", "researcher" or "admin"), in one transaction.
void grantRole(Connection& connection, const std::string& role, const std::string& right);

// What the session's user may do in the current schema.
struct ServerRights {
  bool editLabels = false;
  bool keepModels = false;
  bool manageRuns = false;
};
ServerRights serverRights(Connection& connection);

}  // namespace tactile::storage::db
