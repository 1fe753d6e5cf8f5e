#include "storage/sqlite_db.h"

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

}  // namespace

// ---------------------------------------------------------------------------------------------
// Connection

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
  return Connection(db, path.string());
}

Connection::Connection(Connection&& other) noexcept
    : db_(std::exchange(other.db_, nullptr)),
      file_(std::move(other.file_)),
      stamp_(std::exchange(other.stamp_, nullptr)) {}

Connection& Connection::operator=(Connection&& other) noexcept {
  if (this != &other) {
    close();
    db_ = std::exchange(other.db_, nullptr);
    file_ = std::move(other.file_);
    stamp_ = std::exchange(other.stamp_, nullptr);
  }
  return *this;
}

Connection::~Connection() {
  close();
}

void Connection::close() noexcept {
  if (db_ == nullptr) return;
  sqlite3_finalize(stamp_);
  stamp_ = nullptr;
  {
    std::lock_guard lock(gFilesMutex);
    openFiles().erase(db_);
  }
  sqlite3_close_v2(db_);
  db_ = nullptr;
}

const std::string& Connection::file() const {
  return file_;
}

void Connection::stampPageOneOnCommit(std::int64_t applicationId) {
  sqlite3_finalize(stamp_);
  stamp_ = nullptr;
  const std::string sql = "PRAGMA application_id = " + std::to_string(applicationId);
  if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &stamp_, nullptr) != SQLITE_OK) {
    fail(db_, "cannot prepare statement", sql);
  }
}

void Connection::stampPageOne() {
  if (stamp_ == nullptr) return;
  const int rc = sqlite3_step(stamp_);
  sqlite3_reset(stamp_);
  if (rc != SQLITE_DONE && rc != SQLITE_ROW) fail(db_, "cannot write the file's header");
}

void Connection::exec(std::string_view sql) {
  const std::string text(sql);
  char* error = nullptr;
  if (sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    std::string message = error != nullptr ? error : sqlite3_errmsg(db_);
    sqlite3_free(error);
    throw DbError(file_, message + " (in: " + text.substr(0, 200) + ")");
  }
}

std::int64_t Connection::queryInt(std::string_view sql) {
  Statement statement(*this, sql);
  if (!statement.step()) throw DbError(file_, "no result (in: " + std::string(sql) + ")");
  return statement.columnInt(0);
}

std::int64_t Connection::lastInsertRowId() const {
  return sqlite3_last_insert_rowid(db_);
}
int Connection::changes() const {
  return sqlite3_changes(db_);
}
std::string Connection::errorMessage() const {
  return sqlite3_errmsg(db_);
}

// ---------------------------------------------------------------------------------------------
// Statement

Statement::Statement(Connection& connection, std::string_view sql) : db_(connection.handle()) {
  if (sqlite3_prepare_v3(db_, sql.data(), static_cast<int>(sql.size()), SQLITE_PREPARE_PERSISTENT,
                         &stmt_, nullptr) != SQLITE_OK) {
    fail(db_, "cannot prepare statement", sql);
  }
}

Statement::Statement(Statement&& other) noexcept
    : stmt_(std::exchange(other.stmt_, nullptr)),
      db_(std::exchange(other.db_, nullptr)),
      stepped_(other.stepped_) {}

Statement& Statement::operator=(Statement&& other) noexcept {
  if (this != &other) {
    sqlite3_finalize(stmt_);
    stmt_ = std::exchange(other.stmt_, nullptr);
    db_ = std::exchange(other.db_, nullptr);
    stepped_ = other.stepped_;
  }
  return *this;
}

Statement::~Statement() {
  sqlite3_finalize(stmt_);
}

void Statement::prepareBind() {
  if (stepped_) {
    sqlite3_reset(stmt_);
    stepped_ = false;
  }
}

void Statement::check(int rc, const char* what) const {
  if (rc != SQLITE_OK) fail(db_, what, sqlite3_sql(stmt_));
}

Statement& Statement::bind(int index, std::int64_t value) {
  prepareBind();
  check(sqlite3_bind_int64(stmt_, index, value), "cannot bind integer");
  return *this;
}

Statement& Statement::bind(int index, double value) {
  prepareBind();
  check(sqlite3_bind_double(stmt_, index, value), "cannot bind number");
  return *this;
}

Statement& Statement::bind(int index, std::string_view text) {
  prepareBind();
  check(sqlite3_bind_text(stmt_, index, text.data(), static_cast<int>(text.size()), SQLITE_STATIC),
        "cannot bind text");
  return *this;
}

Statement& Statement::bindBlob(int index, const void* data, std::size_t bytes) {
  // A zero-length blob with a null pointer would bind NULL; give SQLite a valid pointer.
  static const char kEmpty = 0;
  prepareBind();
  check(sqlite3_bind_blob(stmt_, index, bytes == 0 ? &kEmpty : data, static_cast<int>(bytes),
                          SQLITE_STATIC),
        "cannot bind blob");
  return *this;
}

Statement& Statement::bindNull(int index) {
  prepareBind();
  check(sqlite3_bind_null(stmt_, index), "cannot bind null");
  return *this;
}

bool Statement::step() {
  stepped_ = true;
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  const std::string message = std::string("statement failed: ") + sqlite3_errmsg(db_) +
                              " (in: " + std::string(sqlite3_sql(stmt_)).substr(0, 200) + ")";
  sqlite3_reset(stmt_);
  throw DbError(fileOf(db_), message);
}

void Statement::run() {
  step();
  sqlite3_reset(stmt_);
  stepped_ = false;
}

void Statement::reset() {
  sqlite3_reset(stmt_);
  stepped_ = false;
}

std::int64_t Statement::columnInt(int column) const {
  return sqlite3_column_int64(stmt_, column);
}
double Statement::columnDouble(int column) const {
  return sqlite3_column_double(stmt_, column);
}

std::string Statement::columnText(int column) const {
  return std::string(columnTextView(column));
}

std::string_view Statement::columnTextView(int column) const {
  const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, column));
  if (text == nullptr) return {};
  return {text, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column))};
}

const void* Statement::columnBlob(int column) const {
  return sqlite3_column_blob(stmt_, column);
}

std::size_t Statement::columnBytes(int column) const {
  return static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column));
}

bool Statement::columnIsNull(int column) const {
  return sqlite3_column_type(stmt_, column) == SQLITE_NULL;
}

// ---------------------------------------------------------------------------------------------
// Transaction

Transaction::Transaction(Connection& connection) : connection_(&connection) {
  connection.exec("BEGIN IMMEDIATE");
}

Transaction::Transaction(Transaction&& other) noexcept
    : connection_(std::exchange(other.connection_, nullptr)) {}

Transaction::~Transaction() {
  rollback();
}

void Transaction::commit() {
  if (connection_ == nullptr) throw DbError("commit of an inactive transaction");
  // Every commit carries page 1 (the file's header, with its change counter) into the write-ahead
  // log where the connection asks for it (Connection::stampPageOneOnCommit).
  connection_->stampPageOne();
  connection_->exec("COMMIT");
  connection_ = nullptr;
}

void Transaction::rollback() noexcept {
  if (connection_ == nullptr) return;
  // Statements still pending would make ROLLBACK fail in old SQLite versions; ours are reset.
  sqlite3_exec(connection_->handle(), "ROLLBACK", nullptr, nullptr, nullptr);
  connection_ = nullptr;
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
      sqlite3_backup_init(destination.handle(), "main", source.handle(), "main");
  if (backup == nullptr) fail(destination.handle(), "cannot start backup to " + target.string());
  const int rc = sqlite3_backup_step(backup, -1);
  sqlite3_backup_finish(backup);
  if (rc != SQLITE_DONE) {
    throw DbError(source.file(),
                  "backup to '" + target.string() + "' failed: " + sqlite3_errstr(rc));
  }
}

}  // namespace tactile::storage::db
