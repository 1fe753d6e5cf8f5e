// The database handles the stores are written against, the same for every backend: a connection
// that owns its session, a prepared statement that resets itself and reports its own failure with
// the SQL text, a transaction guard that rolls back unless committed, and a bulk row writer.
//
// Two backends implement them: SQLite files (storage/sqlite/) and PostgreSQL servers
// (storage/postgres/). Statements are written once in the SQL both understand, with `?` or `?N`
// parameters (the PostgreSQL backend numbers them `$N`). Only storage/ includes this header.
//
// These wrappers throw DbError; the public storage API (run_database.h) catches it at its boundary
// and turns it into a result with a message, so callers never see an exception.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace tactile::storage::db {

// A failed database call: the message names the operation, the backend's own text and the SQL when
// known; `file` is the database (a file path, or a server address without its password) so that
// every error can name the database it is about. `state` is PostgreSQL's SQLSTATE when known.
struct DbError : std::runtime_error {
  using std::runtime_error::runtime_error;
  DbError(std::string file_, const std::string& message, std::string state_ = {})
      : std::runtime_error(message), file(std::move(file_)), state(std::move(state_)) {}
  std::string file;
  std::string state;
};

enum class Engine { Sqlite, Postgres };

// How a connection opens an SQLite file.
enum class Access {
  ReadWrite,  // read and write (with `create`, the file is made when absent)
  ReadOnly,   // SQLITE_OPEN_READONLY: never writes the database; WAL needs a -shm file
  // Read-only and `immutable=1`: no locks and no -shm/-wal files at all, for a database in a
  // folder this process cannot write (docs/storage.md#opening). A -wal file's content is not seen.
  Immutable,
};

// What a backend implements for one prepared statement.
class StatementBackend {
 public:
  virtual ~StatementBackend() = default;
  virtual void bindInt(int index, std::int64_t value) = 0;
  virtual void bindDouble(int index, double value) = 0;
  virtual void bindText(int index, std::string_view text) = 0;
  virtual void bindBlob(int index, const void* data, std::size_t bytes) = 0;
  virtual void bindNull(int index) = 0;
  virtual bool step() = 0;
  virtual void reset() = 0;
  virtual std::int64_t columnInt(int column) const = 0;
  virtual double columnDouble(int column) const = 0;
  virtual std::string_view columnText(int column) const = 0;
  virtual const void* columnBlob(int column) const = 0;
  virtual std::size_t columnBytes(int column) const = 0;
  virtual bool columnIsNull(int column) const = 0;
};

// What a backend implements for a bulk insert into one table (RowWriter).
class RowWriterBackend : public StatementBackend {
 public:
  // Adds the bound row.
  virtual void add() = 0;
  // Sends what is buffered; the rows are in the table (of the open transaction) afterwards.
  virtual void finish() = 0;
};

// What a backend implements for one session.
class ConnectionBackend {
 public:
  virtual ~ConnectionBackend() = default;
  virtual Engine engine() const = 0;
  // The database as named in errors: a file path, or a server address without password.
  virtual const std::string& name() const = 0;
  virtual std::unique_ptr<StatementBackend> prepare(std::string_view sql) = 0;
  // A statement that reads many rows, streamed rather than held whole in memory (PostgreSQL: COPY
  // ... TO STDOUT; its parameters may only be integers). While it is part way through its rows,
  // no other statement may run on the session. SQLite streams every statement.
  virtual std::unique_ptr<StatementBackend> prepareStreamed(std::string_view sql) {
    return prepare(sql);
  }
  virtual std::unique_ptr<RowWriterBackend> rowWriter(std::string_view table,
                                                      std::string_view columns, int count) = 0;
  virtual void exec(std::string_view sql) = 0;
  // A write transaction: BEGIN IMMEDIATE on SQLite; on PostgreSQL BEGIN with the database's writer
  // lock, so that writers queue as they do on an SQLite file.
  virtual void begin() = 0;
  // A write transaction whose statements lock the rows they touch themselves (SELECT ... FOR
  // UPDATE SKIP LOCKED), so that writers on different rows do not queue: PostgreSQL's plain BEGIN;
  // on SQLite the same as begin() (the file has one writer at a time).
  virtual void beginRowLocking() { begin(); }
  virtual void commit() = 0;
  virtual void rollback() noexcept = 0;
  // Rows changed by the newest INSERT, UPDATE or DELETE.
  virtual std::int64_t changes() const = 0;
  // A read of several statements from one snapshot (SQLite: a savepoint's read transaction;
  // PostgreSQL: a read-only REPEATABLE READ transaction), and its end.
  virtual void beginSnapshot() = 0;
  virtual void endSnapshot() noexcept = 0;
  // Whether a transaction is open on the session.
  virtual bool inTransaction() const = 0;
  // Whether another session may have committed a change since the last call: SQLite's
  // data_version (any change to the file); PostgreSQL, a notification on `channel` (the first call
  // starts listening). Never blocks; the first call returns false.
  virtual bool changedSinceLastPoll(std::string_view channel) = 0;
};

// One open database session. Move-only; closes on destruction.
class Connection {
 public:
  Connection() = default;
  explicit Connection(std::unique_ptr<ConnectionBackend> backend) : backend_(std::move(backend)) {}
  // Opens (and with `create`, creates) an SQLite file; ":memory:" opens a private in-memory one
  // (storage/sqlite/sqlite_connection.cpp). Throws DbError naming `path`.
  static Connection open(const std::filesystem::path& path, bool create, bool readOnly = false);
  static Connection open(const std::filesystem::path& path, bool create, Access access);

  bool isOpen() const { return backend_ != nullptr; }
  Engine engine() const { return backend_->engine(); }
  bool isSqlite() const { return backend_->engine() == Engine::Sqlite; }
  ConnectionBackend& backend() { return *backend_; }

  // Runs one or more statements without results. Throws DbError naming `sql`.
  void exec(std::string_view sql) { backend_->exec(sql); }
  // Runs a statement that yields one integer (e.g. "SELECT count(*) FROM runs"). Throws DbError.
  std::int64_t queryInt(std::string_view sql);
  std::int64_t changes() const { return backend_->changes(); }
  bool inTransaction() const { return backend_->inTransaction(); }
  // The database as given when opened (":memory:" for a private in-memory SQLite one).
  const std::string& file() const { return backend_->name(); }

 private:
  std::unique_ptr<ConnectionBackend> backend_;
};

// A prepared statement. Bind indices are 1-based, column indices 0-based (as in SQLite). step()
// returns true while a row is available. Binding after a step resets the statement first (the
// other bindings stay), so a statement is reused by binding and stepping again.
class Statement {
 public:
  Statement() = default;
  Statement(Connection& connection, std::string_view sql)
      : backend_(connection.backend().prepare(sql)) {}
  // A statement over many rows (a whole run's steps), streamed
  // (ConnectionBackend::prepareStreamed).
  struct Streamed {};
  Statement(Connection& connection, std::string_view sql, Streamed)
      : backend_(connection.backend().prepareStreamed(sql)) {}
  Statement(Statement&&) noexcept = default;
  Statement& operator=(Statement&&) noexcept = default;

  Statement& bind(int index, std::int64_t value) {
    prepareBind();
    backend_->bindInt(index, value);
    return *this;
  }
  Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, double value) {
    prepareBind();
    backend_->bindDouble(index, value);
    return *this;
  }
  // Text and blobs are bound without copying where the backend allows: the memory must stay valid
  // until the statement is stepped to completion or reset.
  Statement& bind(int index, std::string_view text) {
    prepareBind();
    backend_->bindText(index, text);
    return *this;
  }
  Statement& bindBlob(int index, const void* data, std::size_t bytes) {
    prepareBind();
    backend_->bindBlob(index, data, bytes);
    return *this;
  }
  Statement& bindNull(int index) {
    prepareBind();
    backend_->bindNull(index);
    return *this;
  }

  // Advances; true when a row is available, false when done. Throws DbError on failure.
  bool step() {
    stepped_ = true;
    return backend_->step();
  }
  // Steps a statement expected to produce no rows (or whose rows are not needed), then resets it.
  void run() {
    step();
    reset();
  }
  void reset() {
    backend_->reset();
    stepped_ = false;
  }
  // Runs an INSERT ... RETURNING id and gives the id. Throws DbError when no row comes back.
  std::int64_t runReturningId();

  std::int64_t columnInt(int column) const { return backend_->columnInt(column); }
  double columnDouble(int column) const { return backend_->columnDouble(column); }
  std::string columnText(int column) const { return std::string(backend_->columnText(column)); }
  // Valid until the next step/reset.
  std::string_view columnTextView(int column) const { return backend_->columnText(column); }
  const void* columnBlob(int column) const { return backend_->columnBlob(column); }
  std::size_t columnBytes(int column) const { return backend_->columnBytes(column); }
  bool columnIsNull(int column) const { return backend_->columnIsNull(column); }

  StatementBackend& backend() { return *backend_; }

 private:
  void prepareBind() {
    if (stepped_) reset();
  }
  std::unique_ptr<StatementBackend> backend_;
  bool stepped_ = false;
};

// Many rows into one table inside a transaction: a prepared INSERT on SQLite, COPY on PostgreSQL.
// Bind a row's columns (1-based, in the order of `columns`), add() it, and finish() before the
// transaction runs any other statement on the connection.
class RowWriter {
 public:
  RowWriter(Connection& connection, std::string_view table, std::string_view columns, int count)
      : backend_(connection.backend().rowWriter(table, columns, count)) {}

  RowWriter& bind(int index, std::int64_t value) {
    backend_->bindInt(index, value);
    return *this;
  }
  RowWriter& bind(int index, double value) {
    backend_->bindDouble(index, value);
    return *this;
  }
  RowWriter& bindText(int index, std::string_view text) {
    backend_->bindText(index, text);
    return *this;
  }
  RowWriter& bindBlob(int index, const void* data, std::size_t bytes) {
    backend_->bindBlob(index, data, bytes);
    return *this;
  }
  RowWriter& bindNull(int index) {
    backend_->bindNull(index);
    return *this;
  }
  void add() { backend_->add(); }
  void finish() { backend_->finish(); }

 private:
  std::unique_ptr<RowWriterBackend> backend_;
};

// A write transaction guard (ConnectionBackend::begin) on construction, ROLLBACK on destruction
// unless commit() ran. Movable so that a function can hand an open transaction to its caller.
class Transaction {
 public:
  explicit Transaction(Connection& connection) : connection_(&connection) {
    connection.backend().begin();
  }
  struct RowLocking {};
  Transaction(Connection& connection, RowLocking) : connection_(&connection) {
    connection.backend().beginRowLocking();
  }
  Transaction(Transaction&& other) noexcept
      : connection_(std::exchange(other.connection_, nullptr)) {}
  Transaction& operator=(Transaction&&) = delete;
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  ~Transaction() { rollback(); }

  void commit();  // throws DbError; afterwards the guard is inactive
  void rollback() noexcept {
    if (connection_ == nullptr) return;
    connection_->backend().rollback();
    connection_ = nullptr;
  }
  bool active() const { return connection_ != nullptr; }

 private:
  Connection* connection_ = nullptr;
};

}  // namespace tactile::storage::db
