// The PostgreSQL backend of the database handles (storage/db.h), over libpq: a session on a server
// named by a libpq connection URI (postgresql://user@host:port/db, postgres://...,
// ?host=/socket/dir) or key=value string. Passwords come only through libpq's own means (~/.pgpass,
// PGPASSFILE, PGPASSWORD, service files) or the address itself, and are never put in a message.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "storage/db.h"

namespace tactile::storage::db {

// Whether `address` names a PostgreSQL server rather than a file: a postgresql:// or postgres://
// URI, or a libpq key=value string (docs/team.md#addresses).
bool isServerAddress(std::string_view address);

// The address as shown in messages: any password in it replaced by "***".
std::string redactedAddress(std::string_view address);

// Connects; the server must be PostgreSQL 15 or newer. Throws DbError with one line that names the
// address (without password) and what went wrong.
Connection connectServer(const std::string& address);

// The SQL of `sql` with `?` and `?N` parameters numbered `$N` as PostgreSQL wants them (string
// literals, quoted names and comments left alone); `count` gets the number of parameters.
std::string numberedParameters(std::string_view sql, int& count);

// The server's version as MAJOR.MINOR, e.g. "15.4".
std::string serverVersion(Connection& connection);

}  // namespace tactile::storage::db
