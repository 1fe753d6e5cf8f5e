// Small RAII pieces over the SQLite C API, in the spirit of Mixxx's src/util/db: a connection that
// owns its handle, a prepared statement that resets itself and reports its own failure with the
// SQL text, and a movable, non-copyable transaction guard that rolls back unless committed.
//
// These wrappers throw DbError; the public storage API (run_database.h) catches it at its boundary
// and turns it into a result with a message, so callers never see an exception.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

struct sqlite3;
struct sqlite3_stmt;

namespace tactile::storage::db {

// A failed SQLite call: the message names the operation, SQLite's own text and the SQL when known;
// `file` is the database file as it was given to Connection::open (empty when not known), so that
// every error can name the database it is about.
struct DbError : std::runtime_error {
  using std::runtime_error::runtime_error;
  DbError(std::string file_, const std::string& message)
      : std::runtime_error(message), file(std::move(file_)) {}
  std::string file;
};

// How a connection opens its file.
enum class Access {
  ReadWrite,  // read and write (with `create`, the file is made when absent)
  ReadOnly,   // SQLITE_OPEN_READONLY: never writes the database; WAL needs a -shm file
  // Read-only and `immutable=1`: no locks and no -shm/-wal files at all, for a database in a
  // folder this process cannot write (docs/storage.md#opening). A -wal file's content is not seen.
  Immutable,
};

// One open database handle. Move-only; closes on destruction.
class Connection {
 public:
  Connection() = default;
  // Opens (and with `create`, creates) a database file; ":memory:" opens a private in-memory one.
  // `readOnly` opens without write access. Throws DbError (naming `path`).
  static Connection open(const std::filesystem::path& path, bool create, bool readOnly = false);
  static Connection open(const std::filesystem::path& path, bool create, Access access);

  Connection(Connection&& other) noexcept;
  Connection& operator=(Connection&& other) noexcept;
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;
  ~Connection();

  sqlite3* handle() const { return db_; }
  bool isOpen() const { return db_ != nullptr; }

  // Runs one or more statements without results. Throws DbError naming `sql`.
  void exec(std::string_view sql);
  // Runs a statement that yields one integer (e.g. "PRAGMA user_version"). Throws DbError.
  std::int64_t queryInt(std::string_view sql);
  std::int64_t lastInsertRowId() const;
  int changes() const;
  std::string errorMessage() const;
  // The database file as given to open() (":memory:" for a private in-memory one).
  const std::string& file() const;
  // From now on every Transaction on this connection also writes page 1 when it commits, by
  // setting the application id to `applicationId` again (its value must be the file's), so that
  // a log left behind by a killed process can be matched to the file it continues
  // (file_guard.h). The statement is prepared once. Throws DbError.
  void stampPageOneOnCommit(std::int64_t applicationId);
  // Runs that statement when it is set (Transaction::commit). Throws DbError.
  void stampPageOne();

 private:
  Connection(sqlite3* db, std::string file) : db_(db), file_(std::move(file)) {}
  void close() noexcept;
  sqlite3* db_ = nullptr;
  std::string file_;
  sqlite3_stmt* stamp_ = nullptr;  // PRAGMA application_id = ..., see stampPageOneOnCommit
};

// A prepared statement. Bind indices are 1-based, column indices 0-based (as in SQLite). step()
// returns true while a row is available. Binding after a step resets the statement first (the
// other bindings stay), so a statement is reused by binding and stepping again.
class Statement {
 public:
  Statement() = default;
  Statement(Connection& connection, std::string_view sql);  // throws DbError
  Statement(Statement&& other) noexcept;
  Statement& operator=(Statement&& other) noexcept;
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  ~Statement();

  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, double value);
  // Text and blobs are bound without copying (SQLITE_STATIC): the memory must stay valid until the
  // statement is stepped to completion or reset.
  Statement& bind(int index, std::string_view text);
  Statement& bindBlob(int index, const void* data, std::size_t bytes);
  Statement& bindNull(int index);

  // Advances; true when a row is available, false when done. Throws DbError on failure.
  bool step();
  // Steps a statement expected to produce no rows, then resets it.
  void run();
  void reset();  // ready to step again; bindings stay

  std::int64_t columnInt(int column) const;
  double columnDouble(int column) const;
  std::string columnText(int column) const;
  std::string_view columnTextView(int column) const;  // valid until the next step/reset
  const void* columnBlob(int column) const;           // valid until the next step/reset
  std::size_t columnBytes(int column) const;
  bool columnIsNull(int column) const;

  sqlite3_stmt* handle() const { return stmt_; }

 private:
  void prepareBind();
  void check(int rc, const char* what) const;
  sqlite3_stmt* stmt_ = nullptr;
  sqlite3* db_ = nullptr;
  bool stepped_ = false;
};

// A transaction guard: BEGIN IMMEDIATE on construction (the write lock is taken up front so a
// writer never fails half-way on a lock upgrade), ROLLBACK on destruction unless commit() ran.
// Movable so that a function can hand an open transaction to its caller; not copyable.
class Transaction {
 public:
  explicit Transaction(Connection& connection);  // throws DbError
  Transaction(Transaction&& other) noexcept;
  Transaction& operator=(Transaction&&) = delete;
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  ~Transaction();

  void commit();  // throws DbError; afterwards the guard is inactive
  void rollback() noexcept;
  bool active() const { return connection_ != nullptr; }

 private:
  Connection* connection_ = nullptr;
};

// Whether a connection of this process has `path` open (the same file, by device and inode).
bool isOpenInThisProcess(const std::filesystem::path& path);

// Copies a whole database (any journal mode) into `target` with the online backup API.
// Throws DbError.
void backupTo(Connection& source, const std::filesystem::path& target);

}  // namespace tactile::storage::db
