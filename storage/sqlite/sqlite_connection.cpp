#include "storage/sqlite/sqlite_connection.h"

#include <sqlite3.h>

#include <mutex>
#include <unordered_map>
#include <utility>

namespace tactile::storage::db {
namespace {

// The file each open handle was opened with, so that a failing statement (which knows only its
// handle) can name its database. Touched on open, close and errors only.
std::mutex gFilesMutex;
std::unordered_map<sqlite3*, std::string>& openFiles() {
  static std::unordered_map<sqlite3*, std::string> files;
  return files;
}

std::string fileOf(sqlite3* db) {
  if (db == nullptr) return {};
  std::lock_guard lock(gFilesMutex);
  const auto it = openFiles().find(db);
  return it == openFiles().end() ? std::string() : it->second;
}

[[noreturn]] void fail(sqlite3* db, const std::string& what, std::string_view sql = {}) {
  std::string message = what + ": " + (db != nullptr ? sqlite3_errmsg(db) : "out of memory");
  if (!sql.empty()) message += " (in: " + std::string(sql.substr(0, 200)) + ")";
  throw DbError(fileOf(db), message);
}

// "file:" URI of a path (RFC 3986 escapes for the characters SQLite's URI parser treats
// specially), with `query`.
std::string fileUri(const std::filesystem::path& path, const char* query) {
  std::string uri = "file:";
  for (const char ch : path.string()) {
    if (ch == '%' || ch == '?' || ch == '#') {
      static const char* const kHex = "0123456789ABCDEF";
      uri += '%';
      uri += kHex[(static_cast<unsigned char>(ch) >> 4) & 15];
      uri += kHex[static_cast<unsigned char>(ch) & 15];
    } else {
      uri += ch;
    }
  }
  return uri + "?" + query;
}

// ---------------------------------------------------------------------------------------------
// Statements

class SqliteStatement : public StatementBackend {
 public:
  SqliteStatement(sqlite3* db, std::string_view sql) : db_(db) {
    if (sqlite3_prepare_v3(db_, sql.data(), static_cast<int>(sql.size()), SQLITE_PREPARE_PERSISTENT,
                           &stmt_, nullptr) != SQLITE_OK) {
      fail(db_, "cannot prepare statement", sql);
    }
  }
  ~SqliteStatement() override { sqlite3_finalize(stmt_); }
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;

  void bindInt(int index, std::int64_t value) override {
    check(sqlite3_bind_int64(stmt_, index, value), "cannot bind integer");
  }
  void bindDouble(int index, double value) override {
    check(sqlite3_bind_double(stmt_, index, value), "cannot bind number");
  }
  void bindText(int index, std::string_view text) override {
    check(
        sqlite3_bind_text(stmt_, index, text.data(), static_cast<int>(text.size()), SQLITE_STATIC),
        "cannot bind text");
  }
  void bindBlob(int index, const void* data, std::size_t bytes) override {
    // A zero-length blob with a null pointer would bind NULL; give SQLite a valid pointer.
    static const char kEmpty = 0;
    check(sqlite3_bind_blob(stmt_, index, bytes == 0 ? &kEmpty : data, static_cast<int>(bytes),
                            SQLITE_STATIC),
          "cannot bind blob");
  }
  void bindNull(int index) override { check(sqlite3_bind_null(stmt_, index), "cannot bind null"); }

  bool step() override {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    const std::string message = std::string("statement failed: ") + sqlite3_errmsg(db_) +
                                " (in: " + std::string(sqlite3_sql(stmt_)).substr(0, 200) + ")";
    sqlite3_reset(stmt_);
    throw DbError(fileOf(db_), message);
  }
  void reset() override { sqlite3_reset(stmt_); }

  std::int64_t columnInt(int column) const override { return sqlite3_column_int64(stmt_, column); }
  double columnDouble(int column) const override { return sqlite3_column_double(stmt_, column); }
  std::string_view columnText(int column) const override {
    const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, column));
    if (text == nullptr) return {};
    return {text, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column))};
  }
  const void* columnBlob(int column) const override { return sqlite3_column_blob(stmt_, column); }
  std::size_t columnBytes(int column) const override {
    return static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column));
  }
  bool columnIsNull(int column) const override {
    return sqlite3_column_type(stmt_, column) == SQLITE_NULL;
  }

 protected:
  void check(int rc, const char* what) const {
    if (rc != SQLITE_OK) fail(db_, what, sqlite3_sql(stmt_));
  }
  sqlite3* db_ = nullptr;
  sqlite3_stmt* stmt_ = nullptr;
};

// A bulk insert is a prepared INSERT stepped once per row: SQLite has no faster path.
class SqliteRowWriter : public RowWriterBackend {
 public:
  SqliteRowWriter(sqlite3* db, const std::string& sql) : statement_(db, sql) {}
  void bindInt(int index, std::int64_t value) override { statement_.bindInt(index, value); }
  void bindDouble(int index, double value) override { statement_.bindDouble(index, value); }
  void bindText(int index, std::string_view text) override { statement_.bindText(index, text); }
  void bindBlob(int index, const void* data, std::size_t bytes) override {
    statement_.bindBlob(index, data, bytes);
  }
  void bindNull(int index) override { statement_.bindNull(index); }
  bool step() override { return statement_.step(); }
  void reset() override { statement_.reset(); }
  std::int64_t columnInt(int) const override { return 0; }
  double columnDouble(int) const override { return 0; }
  std::string_view columnText(int) const override { return {}; }
  const void* columnBlob(int) const override { return nullptr; }
  std::size_t columnBytes(int) const override { return 0; }
  bool columnIsNull(int) const override { return true; }
  void add() override {
    statement_.step();
    statement_.reset();
  }
  void finish() override { statement_.reset(); }

 private:
  SqliteStatement statement_;
};

// ---------------------------------------------------------------------------------------------
// Connection

class SqliteConnection : public ConnectionBackend {
 public:
  SqliteConnection(sqlite3* db, std::string file) : db_(db), file_(std::move(file)) {}
  ~SqliteConnection() override {
    sqlite3_finalize(stamp_);
    {
      std::lock_guard lock(gFilesMutex);
      openFiles().erase(db_);
    }
    sqlite3_close_v2(db_);
  }
  SqliteConnection(const SqliteConnection&) = delete;
  SqliteConnection& operator=(const SqliteConnection&) = delete;

  Engine engine() const override { return Engine::Sqlite; }
  const std::string& name() const override { return file_; }
  std::unique_ptr<StatementBackend> prepare(std::string_view sql) override {
    return std::make_unique<SqliteStatement>(db_, sql);
  }
  std::unique_ptr<RowWriterBackend> rowWriter(std::string_view table, std::string_view columns,
                                              int count) override {
    std::string sql =
        "INSERT INTO " + std::string(table) + "(" + std::string(columns) + ") VALUES(";
    for (int i = 0; i < count; ++i)
      sql += i == 0 ? "?" : ", ?";
    return std::make_unique<SqliteRowWriter>(db_, sql + ")");
  }
  void exec(std::string_view sql) override {
    const std::string text(sql);
    char* error = nullptr;
    if (sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
      std::string message = error != nullptr ? error : sqlite3_errmsg(db_);
      sqlite3_free(error);
      throw DbError(file_, message + " (in: " + text.substr(0, 200) + ")");
    }
  }
  void begin() override { exec("BEGIN IMMEDIATE"); }
  void commit() override {
    // Every commit carries page 1 (the file's header, with its change counter) into the
    // write-ahead log where the connection asks for it (stampPageOneOnCommit).
    if (stamp_ != nullptr) {
      const int rc = sqlite3_step(stamp_);
      sqlite3_reset(stamp_);
      if (rc != SQLITE_DONE && rc != SQLITE_ROW) fail(db_, "cannot write the file's header");
    }
    exec("COMMIT");
  }
  void rollback() noexcept override {
    // Statements still pending would make ROLLBACK fail in old SQLite versions; ours are reset.
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
  }
  std::int64_t changes() const override { return sqlite3_changes64(db_); }
  void beginSnapshot() override {
    snapshotOpened_ = sqlite3_get_autocommit(db_) != 0;
    exec("SAVEPOINT tactile_snapshot");
  }
  void endSnapshot() noexcept override {
    if (sqlite3_exec(db_, "RELEASE tactile_snapshot", nullptr, nullptr, nullptr) != SQLITE_OK &&
        snapshotOpened_ && sqlite3_get_autocommit(db_) == 0) {
      // A read of a damaged file can leave the release failing: the snapshot only read.
      sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    }
  }
  bool inTransaction() const override { return sqlite3_get_autocommit(db_) == 0; }
  bool changedSinceLastPoll(std::string_view /*channel*/) override {
    sqlite3_stmt* stmt = nullptr;
    if (sqlite3_prepare_v2(db_, "PRAGMA data_version", -1, &stmt, nullptr) != SQLITE_OK) {
      fail(db_, "cannot prepare statement", "PRAGMA data_version");
    }
    std::int64_t version = dataVersion_;
    if (sqlite3_step(stmt) == SQLITE_ROW) version = sqlite3_column_int64(stmt, 0);
    sqlite3_finalize(stmt);
    const bool changed = dataVersion_ >= 0 && version != dataVersion_;
    dataVersion_ = version;
    return changed;
  }

  sqlite3* handle() const { return db_; }
  void stampOnCommit(std::int64_t applicationId) {
    sqlite3_finalize(stamp_);
    stamp_ = nullptr;
    const std::string sql = "PRAGMA application_id = " + std::to_string(applicationId);
    if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &stamp_, nullptr) != SQLITE_OK) {
      fail(db_, "cannot prepare statement", sql);
    }
  }

 private:
  sqlite3* db_ = nullptr;
  std::string file_;
  sqlite3_stmt* stamp_ = nullptr;  // PRAGMA application_id = ..., see stampPageOneOnCommit
  bool snapshotOpened_ = false;    // beginSnapshot opened the transaction (none was open)
  std::int64_t dataVersion_ = -1;  // PRAGMA data_version at the last poll
};

SqliteConnection& sqliteOf(Connection& connection) {
  if (!connection.isOpen() || connection.engine() != Engine::Sqlite) {
    throw DbError(connection.isOpen() ? connection.file() : std::string(),
                  "an SQLite operation on a connection of another backend");
  }
  return static_cast<SqliteConnection&>(connection.backend());
}

}  // namespace

Connection Connection::open(const std::filesystem::path& path, bool create, bool readOnly) {
  return open(path, create, readOnly ? Access::ReadOnly : Access::ReadWrite);
}

Connection Connection::open(const std::filesystem::path& path, bool create, Access access) {
  // Once per process, before SQLite initialises: no allocation statistics (they take a global
  // mutex on every malloc, ~6% of bulk insert time), and connections that are each used by one
  // thread at a time. Fails harmlessly if someone else initialised SQLite first.
  static const bool configured = [] {
    sqlite3_config(SQLITE_CONFIG_MEMSTATUS, 0);
    sqlite3_config(SQLITE_CONFIG_MULTITHREAD);
    return true;
  }();
  (void)configured;
  const bool readOnly = access != Access::ReadWrite;
  int flags = readOnly ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE;
  if (create && !readOnly) flags |= SQLITE_OPEN_CREATE;
  // Each connection is used from one thread at a time; no SQLite-level mutexes needed.
  flags |= SQLITE_OPEN_NOMUTEX;
  std::string name = path.string();
  if (access == Access::Immutable) {
    flags |= SQLITE_OPEN_URI;
    name = fileUri(path, "mode=ro&immutable=1");
  }
  sqlite3* db = nullptr;
  const int rc = sqlite3_open_v2(name.c_str(), &db, flags, nullptr);
  if (rc != SQLITE_OK) {
    std::string message = std::string("cannot open database: ") +
                          (db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(rc));
    sqlite3_close_v2(db);
    throw DbError(path.string(), message);
  }
  sqlite3_extended_result_codes(db, 1);
  // Writers queue for the write lock (BEGIN IMMEDIATE, checkpoints, journal mode changes) instead
  // of failing at once while another process imports.
  sqlite3_busy_timeout(db, 60000);
  {
    std::lock_guard lock(gFilesMutex);
    openFiles()[db] = path.string();
  }
  return Connection(std::make_unique<SqliteConnection>(db, path.string()));
}

sqlite3* sqliteHandle(Connection& connection) {
  return sqliteOf(connection).handle();
}

void stampPageOneOnCommit(Connection& connection, std::int64_t applicationId) {
  sqliteOf(connection).stampOnCommit(applicationId);
}

// ---------------------------------------------------------------------------------------------

bool isOpenInThisProcess(const std::filesystem::path& path) {
  std::lock_guard lock(gFilesMutex);
  for (const auto& [handle, file] : openFiles()) {
    std::error_code ec;
    if (file != ":memory:" && std::filesystem::equivalent(file, path, ec)) return true;
  }
  return false;
}

void backupTo(Connection& source, const std::filesystem::path& target) {
  Connection destination = Connection::open(target, true);
  sqlite3_backup* backup =
      sqlite3_backup_init(sqliteHandle(destination), "main", sqliteHandle(source), "main");
  if (backup == nullptr) {
    fail(sqliteHandle(destination), "cannot start backup to " + target.string());
  }
  const int rc = sqlite3_backup_step(backup, -1);
  sqlite3_backup_finish(backup);
  if (rc != SQLITE_DONE) {
    throw DbError(source.file(),
                  "backup to '" + target.string() + "' failed: " + sqlite3_errstr(rc));
  }
}

}  // namespace tactile::storage::db
