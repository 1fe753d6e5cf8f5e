// Checks on a database file and its write-ahead log made before SQLite opens them, read with plain
// file calls so that nothing is created, locked or written
// (docs/storage.md#a-leftover-write-ahead-log).
//
// SQLite applies any `-wal` file whose frames are internally consistent, whatever database file
// lies beside it: a backup copied over a database whose log still holds commits, or another
// database's log put beside it, is silently merged into the file at the next close. These checks
// decide whether a log continues this very file (SQLite's WAL format, sections 4.1-4.3 of its file
// format page: header, salts, cumulative checksums, commit frames).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace tactile::storage::db {

// What the database's `-wal` holds and whether it belongs to the file.
struct WalState {
  enum class Kind {
    None,      // no log, an empty one, or one without a committed frame: nothing would be applied
    Live,      // another connection has the database open: the log is in use and belongs
    Belongs,   // a leftover log (a killed process) whose page 1 continues this file's page 1
    Foreign,   // a leftover log that was written on another state of the file: never apply it
    Unproven,  // a leftover log without a page-1 frame: only a read through it can tell
  };
  Kind kind = Kind::None;
  std::string reason;             // for Foreign: what does not match
  std::int64_t commitFrames = 0;  // committed frames in the log's current generation (0 for Live)
};

// Every Tactile database carries a random identity on page 1: a view in the schema, whose text
// SQLite keeps on page 1 (the schema table's root), so that another database's log is told from
// this one's even when their change counters agree. Made by the first writing open.
inline constexpr std::string_view kIdentityViewPrefix = "CREATE VIEW tactile_identity AS SELECT '";
inline constexpr std::size_t kIdentityHexDigits = 32;

// Reads `database`-wal (and `database`'s page 1): see WalState. Never blocks on a FIFO.
WalState inspectWal(const std::filesystem::path& database);

// Committed frames in the log's current generation (0 without a log); reads the -wal file alone,
// so it may be called while a connection of this process has the database open (SQLite holds no
// locks on the -wal file itself). inspectWal returns Live at once in that case: it would open the
// database and its -shm, and closing those descriptors would drop the connection's POSIX locks.
std::int64_t walCommitFrames(const std::filesystem::path& database);

// Removes the database's -shm index when no process has it open (after a read-only connection of
// this process made it and closed); true when it was removed.
bool removeUnusedIndex(const std::filesystem::path& database);

// The one-line message for a log that does not belong (names the log and what to do).
std::string foreignWalMessage(const std::filesystem::path& database, const std::string& reason);

// A database file shorter than its header's page count (a copy cut short): the problem in words,
// or nothing. Only meaningful when no log holds committed frames (a checkpoint in progress may
// have written page 1 before the pages after the old end).
std::optional<std::string> truncationProblem(const std::filesystem::path& database);

// Whether `path` names something other than a regular file (a FIFO, a device, a socket, a folder);
// the words for it ("a FIFO"), or nothing for a regular file or a name that does not exist.
std::optional<std::string> notRegularFile(const std::filesystem::path& path);

}  // namespace tactile::storage::db
