// Opening, run listing, integrity check, models and sweeps. Import, reading and labels live in
// run_import.cpp, run_read.cpp and labels.cpp.
#include "storage/run_database.h"

#include <sqlite3.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <iterator>
#include <random>
#include <thread>

#include "base/file_text.h"
#include "storage/database_impl.h"
#include "storage/file_guard.h"
#include "storage/postgres/pg_connection.h"
#include "storage/postgres/pg_schema.h"
#include "storage/schema.h"
#include "storage/step_checksum.h"

namespace tactile::storage {

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm parts{};
  gmtime_r(&now, &parts);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
  return text;
}

RunDatabase::RunDatabase(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
RunDatabase::~RunDatabase() {
  if (impl_ == nullptr) return;
  impl_->statements.clear();  // finalize before the connection closes
}

const std::filesystem::path& RunDatabase::path() const {
  return impl_->path;
}
const std::filesystem::path& RunDatabase::migrationBackup() const {
  return impl_->backup;
}

namespace {

// What the file's first bytes say, read without SQLite so that nothing is created or written
// (docs/storage.md#opening; the header layout is SQLite's file format, section 1.3).
enum class FileKind { Absent, Empty, NotSqlite, Foreign, NoSchema, Tactile, Unknown };

struct Probe {
  FileKind kind = FileKind::Unknown;
  std::uint32_t applicationId = 0;
  std::uint32_t userVersion = 0;
};

std::uint32_t bigEndian32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
         std::uint32_t{p[3]};
}

Probe probeFile(const std::filesystem::path& path) {
  Probe probe;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    probe.kind = FileKind::Absent;
    return probe;
  }
  if (std::filesystem::is_directory(path, ec)) {
    probe.kind = FileKind::NotSqlite;
    return probe;
  }
  // A write-ahead log with content may hold a newer page 1 (header); then only SQLite can tell.
  // Looked at before and after reading the header, as another process may be checkpointing.
  const auto walHasContent = [&] {
    std::error_code walError;
    const auto walBytes = std::filesystem::file_size(path.string() + "-wal", walError);
    return !walError && walBytes > 0;
  };
  const bool walBefore = walHasContent();
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) return probe;  // unreadable: SQLite reports why
  unsigned char header[100] = {};
  const std::size_t got = std::fread(header, 1, sizeof header, file);
  std::fclose(file);
  if (got == 0) {
    probe.kind = FileKind::Empty;
    return probe;
  }
  static constexpr char kMagic[] = "SQLite format 3";  // 16 bytes with its NUL
  if (got < sizeof header || std::memcmp(header, kMagic, sizeof kMagic) != 0) {
    probe.kind = FileKind::NotSqlite;
    return probe;
  }
  if (walBefore || walHasContent()) return probe;
  probe.applicationId = bigEndian32(header + 68);
  const std::uint32_t userVersion = bigEndian32(header + 60);
  const std::uint32_t schemaCookie = bigEndian32(header + 40);
  // The application id is the identity: every Tactile database has carried it since its first
  // schema (set in the migration's transaction, with user_version). Only a blank SQLite file (no
  // id, no version, no schema) may become one; anything else belongs to someone else.
  probe.userVersion = userVersion;
  if (probe.applicationId == static_cast<std::uint32_t>(db::kApplicationId)) {
    probe.kind = FileKind::Tactile;
  } else if (probe.applicationId == 0 && userVersion == 0 && schemaCookie == 0) {
    probe.kind = FileKind::NoSchema;
  } else {
    probe.kind = FileKind::Foreign;
  }
  return probe;
}

std::string hex32(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08x", value);
  return text;
}

// One line for an SQLite file that is not ours (docs/storage.md#opening).
std::string foreignMessage(std::uint32_t applicationId, std::uint32_t userVersion) {
  if (applicationId != 0) {
    return "an SQLite database of another application (application_id " + hex32(applicationId) +
           "), not a Tactile database; left unchanged";
  }
  if (userVersion != 0) {
    return "an SQLite database without the Tactile application id (user_version " +
           std::to_string(userVersion) + "), not a Tactile database; left unchanged";
  }
  return "holds tables but no Tactile application id; not a Tactile database; left unchanged";
}

// The same identity checks through SQLite, before anything is written (for files whose -wal holds
// content the header above could not judge). Throws DbError naming the file.
void checkIdentity(db::Connection& c, const std::string& name, bool mayInitialise) {
  const db::Identity identity = db::readIdentity(c);
  const auto applicationId = identity.applicationId;
  const auto version = identity.version;
  const auto objects = identity.objects;
  if (applicationId != db::kApplicationId && (applicationId != 0 || version != 0 || objects != 0)) {
    throw db::DbError(name, foreignMessage(static_cast<std::uint32_t>(applicationId),
                                           static_cast<std::uint32_t>(version)));
  }
  if (applicationId == 0 && !mayInitialise) {
    throw db::DbError(name,
                      "an SQLite database without the Tactile schema; not a Tactile "
                      "database (only a creating verb such as `tactile db create` makes one)");
  }
}

// PRAGMA journal_mode = WAL, retried while another process holds the lock: the switch of a new
// file needs an exclusive lock, and SQLite returns SQLITE_BUSY at once instead of calling the busy
// handler when several processes create one file together (docs/storage.md#concurrency).
std::string switchToWal(db::Connection& c, const std::string& name) {
  using namespace std::chrono_literals;
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (true) {
    sqlite3_stmt* statement = nullptr;
    int rc = sqlite3_prepare_v2(db::sqliteHandle(c), "PRAGMA journal_mode = WAL", -1, &statement,
                                nullptr);
    std::string journal;
    if (rc == SQLITE_OK) {
      rc = sqlite3_step(statement);
      if (rc == SQLITE_ROW) {
        const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(statement, 0));
        journal = text != nullptr ? text : "";
        rc = SQLITE_OK;
      }
    }
    sqlite3_finalize(statement);
    if (rc == SQLITE_OK) return journal;
    const int primary = rc & 0xff;
    if ((primary != SQLITE_BUSY && primary != SQLITE_LOCKED) ||
        std::chrono::steady_clock::now() > deadline) {
      throw db::DbError(name, std::string("cannot switch to WAL: ") + sqlite3_errstr(rc));
    }
    std::this_thread::sleep_for(5ms);
  }
}

}  // namespace

namespace {

// A creating open that failed (a full disk, a file-size limit) removes the file it made, so no
// 0-byte "database" stays behind; only while the file is still empty and no write-ahead log holds
// anything (so a database another process created at the same moment is never touched).
void removeFailedCreation(const std::filesystem::path& path) {
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  if (ec || bytes != 0) return;
  const auto walBytes = std::filesystem::file_size(path.string() + "-wal", ec);
  if (!ec && walBytes != 0) return;
  for (const char* suffix : {"-wal", "-shm", "-journal"}) {
    std::filesystem::remove(path.string() + suffix, ec);
  }
  std::filesystem::remove(path, ec);
}

// Gives a database without one its random identity on page 1 (db::kIdentityViewPrefix).
void stampIdentity(db::Connection& c) {
  constexpr const char* kCount =
      "SELECT count(*) FROM sqlite_schema WHERE name = 'tactile_identity'";
  if (c.queryInt(kCount) != 0) return;
  std::random_device random;
  std::string id;
  while (id.size() < db::kIdentityHexDigits) {
    char part[9];
    std::snprintf(part, sizeof part, "%08x", static_cast<unsigned>(random()));
    id += part;
  }
  db::Transaction transaction(c);
  if (c.queryInt(kCount) != 0) return;  // another process made it meanwhile
  c.exec(std::string(db::kIdentityViewPrefix) + id + "' AS id");
  transaction.commit();
}

// Refuses, before SQLite opens anything, a write-ahead log that does not belong to the file and a
// file cut short (docs/storage.md#a-leftover-write-ahead-log); both are left as they are.
Status guardFiles(const std::filesystem::path& path, const std::string& name) {
  const db::WalState wal = db::inspectWal(path);
  switch (wal.kind) {
    case db::WalState::Kind::Foreign:
      return Error(name, db::foreignWalMessage(path, wal.reason));
    case db::WalState::Kind::Unproven: {
      // No page-1 frame to compare (a log written by another program): read the database through
      // the log, without writing either, and refuse it when that reading finds damage.
      // The index SQLite makes for that read is removed again when it was not there before.
      std::error_code ec;
      const bool hadIndex = std::filesystem::exists(name + "-shm", ec);
      std::string first;
      {
        db::Connection c;
        try {
          c = db::Connection::open(path, false, db::Access::ReadOnly);
        } catch (const db::DbError&) {
          return Status::success();  // cannot read it here; the open that follows says why
        }
        try {
          db::Statement s(c, "PRAGMA integrity_check(1)");
          if (s.step()) first = s.columnText(0);
        } catch (const db::DbError& e) {
          first = e.what();
        }
      }
      if (!hadIndex) db::removeUnusedIndex(path);
      if (first != "ok") {
        return Error(name, db::foreignWalMessage(
                               path, "reading the database through it finds damage: " + first));
      }
      return Status::success();
    }
    case db::WalState::Kind::None:
      if (const auto cut = db::truncationProblem(path)) return Error(name, *cut);
      return Status::success();
    case db::WalState::Kind::Live:
    case db::WalState::Kind::Belongs:
      return Status::success();
  }
  return Status::success();
}

}  // namespace

Result<std::unique_ptr<RunDatabase>> RunDatabase::open(const std::filesystem::path& path,
                                                       OpenMode mode) {
  OpenOptions options;
  options.mode = mode;
  return open(path, options);
}

Result<std::unique_ptr<RunDatabase>> RunDatabase::open(const std::filesystem::path& path,
                                                       const OpenOptions& options) {
  using R = Result<std::unique_ptr<RunDatabase>>;
  const std::string name = path.string();
  OpenMode mode = options.mode;
  if (mode == OpenMode::Create && !options.create) mode = OpenMode::ReadWrite;
  if (db::isServerAddress(name)) return openServer(name, mode);
  const bool inMemoryPath = path.empty() || path == ":memory:";
  std::error_code absentError;
  const bool wasAbsent = mode == OpenMode::Create && !inMemoryPath &&
                         !std::filesystem::exists(path, absentError) && !absentError;
  R result = openFile(path, options, mode, name);
  if (!result.ok() && wasAbsent) removeFailedCreation(path);
  return result;
}

Result<std::unique_ptr<RunDatabase>> RunDatabase::openFile(const std::filesystem::path& path,
                                                           const OpenOptions& options,
                                                           OpenMode mode, const std::string& name) {
  using R = Result<std::unique_ptr<RunDatabase>>;
  try {
    const bool inMemory = path.empty() || path == ":memory:";
    auto impl = std::make_unique<Impl>();
    impl->path = inMemory ? std::filesystem::path(":memory:") : path;
    impl->readOnly = mode == OpenMode::ReadOnly && !inMemory;
    impl->cacheKiB = options.cacheKiB;
    impl->mmapBytes = options.mmapBytes;
    if (!inMemory) {
      if (const auto what = db::notRegularFile(path)) {
        return R(Error(name, "is " + *what + ", not a database file; left unchanged"));
      }
      // SQLite keeps the log beside the file a link leads to; so are the checks below.
      std::error_code linkError;
      std::filesystem::path real = std::filesystem::canonical(path, linkError);
      if (linkError) real = path;
      if (const auto what = db::notRegularFile(real.string() + "-wal")) {
        return R(Error(name, "its write-ahead log " + real.string() + "-wal is " + *what +
                                 ", not a file; left unchanged"));
      }
      // Opening and closing any descriptor of a file drops every POSIX lock this process holds on
      // it, SQLite's among them: while a connection of this process has the database open, the
      // files are not looked at here (that connection proved them) and SQLite alone decides.
      const bool openHere = db::isOpenInThisProcess(path);
      if (!openHere) {
        if (Status guarded = guardFiles(real, name); !guarded) return R(guarded.error());
      }
      noteInputFile(path);
      const Probe probe = openHere ? Probe{} : probeFile(path);
      switch (probe.kind) {
        case FileKind::Absent:
          if (mode != OpenMode::Create) return R(Error(name, "no such database"));
          break;
        case FileKind::Empty:
          if (mode != OpenMode::Create) {
            return R(Error(name,
                           "empty file, not a Tactile database (only a creating verb such "
                           "as `tactile db create` makes one)"));
          }
          break;
        case FileKind::NotSqlite:
          return R(Error(name, "not a Tactile database (not an SQLite file); left unchanged"));
        case FileKind::Foreign:
          return R(Error(name, foreignMessage(probe.applicationId, probe.userVersion)));
        case FileKind::NoSchema:  // maybe being created this moment: SQLite's snapshot decides
        case FileKind::Tactile:
        case FileKind::Unknown:
          break;
      }
    }
    if (impl->readOnly) {
      // A read leaves no files behind (docs/storage.md#read-only-opening). Where this account may
      // write the file, a read-write connection that SQL may not write (query_only) reads it: as
      // the last connection it removes the -wal and -shm files at close, as every writer does.
      // Where it may not, a database without -wal and -shm is read as it is (immutable), so another
      // account's read never leaves files the owner cannot write.
      const std::filesystem::path folder =
          path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
      const bool mayWrite =
          ::access(path.c_str(), W_OK) == 0 && ::access(folder.c_str(), W_OK | X_OK) == 0;
      std::error_code existsError;
      const bool logFiles = std::filesystem::exists(name + "-wal", existsError) ||
                            std::filesystem::exists(name + "-shm", existsError);
      impl->fileAccess = mayWrite ? db::Access::ReadWrite
                                  : (logFiles ? db::Access::ReadOnly : db::Access::Immutable);
      impl->connection = db::Connection::open(impl->path, false, *impl->fileAccess);
      if (mayWrite) impl->connection.exec("PRAGMA query_only = ON");
      try {
        checkIdentity(impl->connection, name, false);
      } catch (const db::DbError& e) {
        if (mayWrite) throw;
        // SQLITE_READONLY_CANTINIT and friends: WAL needs a -shm file this process cannot make
        // (read-only folder). Without a -wal holding changes, `immutable` reads the file as it is.
        const int code = sqlite3_extended_errcode(db::sqliteHandle(impl->connection));
        if ((code & 0xff) != SQLITE_READONLY && (code & 0xff) != SQLITE_CANTOPEN) throw;
        std::error_code ec;
        const auto walBytes = std::filesystem::file_size(name + "-wal", ec);
        if (!ec && walBytes > 0) {
          return R(Error(name,
                         "cannot be read without write access to its folder: its "
                         "write-ahead log " +
                             name + "-wal holds changes (" + e.what() + ")"));
        }
        impl->fileAccess = db::Access::Immutable;
        impl->connection = db::Connection::open(impl->path, false, *impl->fileAccess);
        checkIdentity(impl->connection, name, false);
      }
      db::Connection& c = impl->connection;
      registerChecksumFunctions(c);
      c.exec("PRAGMA foreign_keys = ON");
      c.exec("PRAGMA temp_store = MEMORY");
      c.exec("PRAGMA cache_size = -" + std::to_string(options.cacheKiB));
      c.exec("PRAGMA mmap_size = " + std::to_string(options.mmapBytes));
      const int version = db::schemaVersion(c);
      if (version > db::kSchemaVersion) {
        return R(Error(name, "schema version " + std::to_string(version) + ", newer than version " +
                                 std::to_string(db::kSchemaVersion) +
                                 " that this program understands; use a newer tactile"));
      }
      if (version < db::kSchemaVersion) {
        // Advise the migrating verb only when the migration would work.
        if (auto problem = db::migrationProblem(c)) {
          return R(Error(name, "schema version " + std::to_string(version) + ", but " + *problem +
                                   "; the file is damaged"));
        }
        return R(Error(name, "schema version " + std::to_string(version) +
                                 ", older than this program's " +
                                 std::to_string(db::kSchemaVersion) +
                                 "; it is not migrated when opened read-only (`tactile db create "
                                 "--db` on it migrates it, keeping a backup)"));
      }
      return R(std::unique_ptr<RunDatabase>(new RunDatabase(std::move(impl))));
    }
    impl->connection = db::Connection::open(impl->path, mode == OpenMode::Create);
    if (!inMemory) impl->fileAccess = db::Access::ReadWrite;
    db::Connection& c = impl->connection;
    if (!inMemory) checkIdentity(c, name, mode == OpenMode::Create);
    const bool fresh = c.queryInt("PRAGMA user_version") == 0 &&
                       c.queryInt("SELECT count(*) FROM sqlite_schema") == 0;
    impl->created = fresh && !inMemory;
    if (fresh) {
      // Step rows are 60-200 bytes (sparse sensors; ~800 at most), within the 1/20 of a page
      // that SQLite advises for WITHOUT ROWID tables; block rows (at most ~1.4 KB) are few. The
      // size is a trade-off measured on imports: every small file's commit writes its dirty pages
      // to the WAL, so 64 KiB pages made 20,000 files of 50 steps import 1.45x slower than 16 KiB
      // ones (8 KiB: 1.8x), while one 1,000,000-step file imported fastest with 16 KiB pages (8 KiB
      // cost ~10% more CPU). Must precede WAL.
      c.exec("PRAGMA page_size = 16384");
    }
    if (!inMemory) {
      const std::string journal = switchToWal(c, name);
      if (journal != "wal") {
        return R(Error(name, "cannot switch to WAL (journal mode " + journal + ")"));
      }
    }
    c.exec("PRAGMA synchronous = NORMAL");
    c.exec("PRAGMA foreign_keys = ON");
    c.exec("PRAGMA temp_store = MEMORY");
    c.exec("PRAGMA cache_size = -" + std::to_string(options.cacheKiB));
    c.exec("PRAGMA mmap_size = " + std::to_string(options.mmapBytes));
    const db::MigrationReport report = db::migrate(c, impl->path);
    impl->backup = report.backupPath;
    if (!inMemory) {
      stampIdentity(c);
      // From here on the file is a Tactile database: every commit writes page 1 (file_guard.h).
      db::stampPageOneOnCommit(c, db::kApplicationId);
    }
    std::unique_ptr<RunDatabase> database(new RunDatabase(std::move(impl)));
    if (options.refuseDamaged && !inMemory) {
      const IntegrityReport check = database->check();
      if (!check.ok) {
        std::int64_t count = 0;
        for (const IntegrityProblemKind& kind : check.kinds)
          count += kind.count;
        return R(Error(name, "damaged (`tactile db check` finds " + std::to_string(count) +
                                 (count == 1 ? " problem" : " problems") +
                                 (check.problems.empty() ? "" : ", first: " + check.problems[0]) +
                                 "); nothing is written into it"));
      }
    }
    return R(std::move(database));
  } catch (const db::DbError& e) {
    return R(Error(e.file.empty() ? name : e.file, e.what()));
  } catch (const std::exception& e) {
    return R(Error(name, e.what()));
  }
}

Result<std::unique_ptr<RunDatabase>> RunDatabase::openServer(const std::string& address,
                                                             OpenMode mode) {
  using R = Result<std::unique_ptr<RunDatabase>>;
  const std::string shown = db::redactedAddress(address);
  try {
    auto impl = std::make_unique<Impl>();
    impl->path = shown;
    impl->readOnly = mode == OpenMode::ReadOnly;
    impl->connection = db::connectServer(address);
    db::Connection& c = impl->connection;
    db::ServerContent content = db::inspectServer(c);
    if (!content.tactile) {
      if (content.tables != 0) {
        return R(
            Error(shown, "holds " + std::to_string(content.tables) +
                             (content.tables == 1 ? " table" : " tables") +
                             " but no Tactile schema; not a Tactile database; left unchanged"));
      }
      if (mode != OpenMode::Create) {
        return R(Error(shown,
                       "an empty database without the Tactile schema (`tactile db create --db "
                       "ADDRESS` makes it)"));
      }
      db::createServerSchema(c);
      content = db::inspectServer(c);
      impl->created = true;
    }
    if (content.version > db::kSchemaVersion) {
      return R(Error(shown, "schema version " + std::to_string(content.version) +
                                ", newer than version " + std::to_string(db::kSchemaVersion) +
                                " that this program understands; use a newer tactile"));
    }
    if (content.version < db::kSchemaVersion && content.version >= 5 && mode == OpenMode::Create &&
        !impl->readOnly) {
      db::createServerSchema(c);  // migrates, under the same lock as a creation
      content = db::inspectServer(c);
    }
    if (content.version < db::kSchemaVersion) {
      return R(Error(shown, "schema version " + std::to_string(content.version) +
                                ", older than this program's " +
                                std::to_string(db::kSchemaVersion) +
                                "; `tactile db create --db ADDRESS` migrates it"));
    }
    // A read-only open never writes, whatever the account may do on the server.
    if (impl->readOnly) c.exec("SET default_transaction_read_only = on");
    return R(std::unique_ptr<RunDatabase>(new RunDatabase(std::move(impl))));
  } catch (const db::DbError& e) {
    return R(Error(e.file.empty() ? shown : e.file, e.what()));
  } catch (const std::exception& e) {
    return R(Error(shown, e.what()));
  }
}

RunDatabase::Rights RunDatabase::rights() {
  Rights rights;
  if (impl_->readOnly) return {false, false, false};
  if (!onServer()) return rights;
  const ResetStatements reset{*impl_};
  try {
    const db::ServerRights server = db::serverRights(impl_->connection);
    rights.editLabels = server.editLabels;
    rights.keepModels = server.keepModels;
    rights.manageRuns = server.manageRuns;
  } catch (const std::exception&) {
    return {false, false, false};
  }
  return rights;
}

Status RunDatabase::grant(const std::string& role, const std::string& right) {
  if (!onServer()) {
    return Error(impl_->path.string(),
                 "roles belong to a PostgreSQL server; a file is guarded by its file permissions");
  }
  return guardedStatus(*impl_, [&] { db::grantRole(impl_->connection, role, right); });
}

RunStore RunDatabase::runs() {
  return RunStore(*impl_);
}
LabelStore RunDatabase::labels() {
  return LabelStore(*impl_);
}
ModelStore RunDatabase::models() {
  return ModelStore(*impl_);
}
SweepStore RunDatabase::sweeps() {
  return SweepStore(*impl_);
}

bool RunDatabase::created() const {
  return impl_->created;
}
bool RunDatabase::onServer() const {
  return !impl_->connection.isSqlite();
}

bool isServerAddress(std::string_view address) {
  return db::isServerAddress(address);
}
std::string shownAddress(std::string_view address) {
  return db::isServerAddress(address) ? db::redactedAddress(address) : std::string(address);
}

bool RunDatabase::readOnly() const {
  return impl_->readOnly;
}

// ---- runs ----------------------------------------------------------------------------------

namespace {

constexpr const char* kRunColumns =
    "SELECT id, name, source_file, checksum, scene, scene_id IS NOT NULL, subject, outcome, dt, "
    "step_count, has_truth, imported_at FROM runs ";

RunInfo readRunInfo(const db::Statement& s) {
  RunInfo info;
  info.id = s.columnInt(0);
  info.name = s.columnText(1);
  info.sourceFile = s.columnText(2);
  info.checksum = s.columnText(3);
  info.scene = s.columnText(4);
  info.sceneStored = s.columnInt(5) != 0;
  info.subject = s.columnText(6);
  info.outcome = s.columnText(7);
  if (!s.columnIsNull(8)) info.dtSeconds = s.columnDouble(8);
  info.stepCount = s.columnInt(9);
  info.hasTruth = s.columnInt(10) != 0;
  info.importedAt = s.columnText(11);
  return info;
}

}  // namespace

Result<std::vector<RunInfo>> RunStore::list() {
  return guarded<std::vector<RunInfo>>(*impl_, [&] {
    static const std::string sql = std::string(kRunColumns) + "ORDER BY name";
    db::Statement& s = impl_->statement(sql.c_str());
    std::vector<RunInfo> runs;
    while (s.step())
      runs.push_back(readRunInfo(s));
    return runs;
  });
}

Result<RunInfo> RunStore::find(std::string_view name) {
  return guarded<RunInfo>(*impl_, [&] {
    static const std::string sql = std::string(kRunColumns) + "WHERE name = ?";
    db::Statement& s = impl_->statement(sql.c_str());
    s.bind(1, name);
    if (!s.step()) throw db::DbError("no run named '" + std::string(name) + "'");
    RunInfo info = readRunInfo(s);
    s.reset();
    return info;
  });
}

Result<RunInfo> RunStore::info(std::int64_t runId) {
  return guarded<RunInfo>(*impl_, [&] {
    static const std::string sql = std::string(kRunColumns) + "WHERE id = ?";
    db::Statement& s = impl_->statement(sql.c_str());
    s.bind(1, runId);
    if (!s.step()) throw db::DbError("no run with id " + std::to_string(runId));
    RunInfo info = readRunInfo(s);
    s.reset();
    return info;
  });
}

Status RunStore::remove(std::int64_t runId) {
  return guardedStatus(*impl_, [&] {
    db::Transaction transaction(impl_->connection);
    // The child rows by name too: a server's step rows have no cascading foreign key.
    impl_->statement("DELETE FROM label_segments WHERE run_id = ?").bind(1, runId).run();
    impl_->statement("DELETE FROM label_revisions WHERE run_id = ?").bind(1, runId).run();
    impl_->statement("DELETE FROM assignments WHERE run_id = ?").bind(1, runId).run();
    impl_->statement("DELETE FROM step_blocks WHERE run_id = ?").bind(1, runId).run();
    impl_->statement("DELETE FROM steps WHERE run_id = ?").bind(1, runId).run();
    db::Statement& s = impl_->statement("DELETE FROM runs WHERE id = ?");
    s.bind(1, runId).run();
    if (impl_->connection.changes() == 0) {
      throw db::DbError("no run with id " + std::to_string(runId));
    }
    transaction.commit();
  });
}

std::int64_t RunDatabase::Impl::runIdByName(std::string_view name) {
  db::Statement& s = statement("SELECT id FROM runs WHERE name = ?");
  s.bind(1, name);
  if (!s.step()) throw db::DbError("no run named '" + std::string(name) + "'");
  const std::int64_t id = s.columnInt(0);
  s.reset();
  return id;
}

std::int64_t RunDatabase::Impl::runStepCount(std::int64_t runId) {
  db::Statement& s = statement("SELECT step_count FROM runs WHERE id = ?");
  s.bind(1, runId);
  if (!s.step()) throw db::DbError("no run with id " + std::to_string(runId));
  const std::int64_t count = s.columnInt(0);
  s.reset();
  return count;
}

// A server plans a read of one run's steps from its statistics of the table. Right after a bulk
// load it has none (or those of a far smaller table), believes a run holds a few thousand rows, and
// reads a million-step run by a bitmap scan and an on-disk sort: three times slower than walking
// the primary key. PostgreSQL's own advice after a bulk load is ANALYZE; only run_id matters to
// these plans, and the schema keeps its sample small (docs/team.md#setting-up-a-server), so it
// costs tens of milliseconds. It runs only when the tables grew by a tenth or more, so that many
// small imports into a large corpus do not each pay for it; autovacuum does the rest. A role that
// does not own the tables gets a notice, not an error, and the plan simply stays as it was.
void RunDatabase::Impl::refreshStepStatistics(std::int64_t addedSteps) {
  if (connection.isSqlite() || addedSteps <= 0 || connection.inTransaction()) return;
  try {
    double known = -1.0;
    {
      db::Statement s(connection, "SELECT reltuples FROM pg_class WHERE oid = 'steps'::regclass");
      if (s.step() && !s.columnIsNull(0)) known = s.columnDouble(0);
    }
    if (known >= 0.0 && static_cast<double>(addedSteps) * 10.0 < known) return;
    connection.exec("ANALYZE steps (run_id), step_blocks (run_id)");
  } catch (const std::exception&) {
    // Only a plan's speed is at stake; the data written is already committed.
  }
}

// ---- check ---------------------------------------------------------------------------------

namespace {

// Counts a problem under its kind and keeps its text while the kind has fewer than
// kIntegrityCasesKept.
void addProblem(IntegrityReport& report, const std::string& kind, const std::string& text) {
  auto it = std::find_if(report.kinds.begin(), report.kinds.end(),
                         [&](const IntegrityProblemKind& k) { return k.kind == kind; });
  if (it == report.kinds.end()) {
    report.kinds.push_back({kind, 0, {}});
    it = std::prev(report.kinds.end());
  }
  ++it->count;
  if (it->cases.size() < kIntegrityCasesKept) {
    it->cases.push_back(text);
    report.problems.push_back(kind + ": " + text);
  }
}

// Every run, steps and summary block row against its checksum (docs/storage.md#checksums), each
// row read and its checksum computed here: a server has no checksum functions of its own.
void checkChecksumsRowByRow(db::Connection& c, IntegrityReport& report) {
  const auto runName = [](const db::Statement& s) {
    return s.columnIsNull(0) ? std::string("(missing run)") : "'" + s.columnText(0) + "'";
  };
  const auto differs = [](const db::Statement& s, int column, std::int64_t want) {
    return s.columnIsNull(column) || s.columnInt(column) != want;
  };
  {
    db::Statement s(c,
                    "SELECT name, id, step_count, has_truth, metadata, extra_columns, crc "
                    "FROM runs ORDER BY id");
    while (s.step()) {
      const std::int64_t want =
          runChecksum(s.columnInt(1), s.columnTextView(0), s.columnInt(2), s.columnInt(3) != 0,
                      s.columnBlob(4), s.columnBytes(4), s.columnBlob(5), s.columnBytes(5));
      if (differs(s, 6, want)) {
        addProblem(report, "checksum",
                   "run " + runName(s) + " (id " + std::to_string(s.columnInt(1)) +
                       "): its row (name, step count, metadata) does not match its checksum");
      }
    }
  }
  {
    // Run by run, so that no result holds more than one run's rows.
    std::vector<std::pair<std::int64_t, std::string>> runs;
    {
      db::Statement ids(c, "SELECT DISTINCT run_id FROM steps ORDER BY run_id");
      while (ids.step())
        runs.emplace_back(ids.columnInt(0), std::string());
    }
    db::Statement names(c, "SELECT name FROM runs WHERE id = ?");
    db::Statement s(c,
                    "SELECT step, x, y, theta, v, omega, blocked, sensors, extra, truth, crc "
                    "FROM steps WHERE run_id = ? ORDER BY step",
                    db::Statement::Streamed{});
    db::Statement blocks(c,
                         "SELECT level, block, minmax, crc FROM step_blocks WHERE run_id = ? "
                         "ORDER BY level, block");
    for (auto& [runId, name] : runs) {
      names.bind(1, runId);
      name = names.step() ? "'" + names.columnText(0) + "'" : std::string("(missing run)");
      names.reset();
      s.bind(1, runId);
      while (s.step()) {
        const StepRow row = stepRowAt(s, runId);
        if (differs(s, 10, stepChecksum(row))) {
          addProblem(report, "checksum",
                     "run " + name + " (id " + std::to_string(runId) + ") step " +
                         std::to_string(row.step) + ": stored data does not match its checksum");
        }
      }
      s.reset();
    }
    db::Statement blockRuns(c, "SELECT DISTINCT run_id FROM step_blocks ORDER BY run_id");
    std::vector<std::int64_t> blockRunIds;
    while (blockRuns.step())
      blockRunIds.push_back(blockRuns.columnInt(0));
    for (const std::int64_t runId : blockRunIds) {
      names.bind(1, runId);
      const std::string name =
          names.step() ? "'" + names.columnText(0) + "'" : std::string("(missing run)");
      names.reset();
      blocks.bind(1, runId);
      while (blocks.step()) {
        const std::int64_t want = blockChecksum(runId, blocks.columnInt(0), blocks.columnInt(1),
                                                blocks.columnBlob(2), blocks.columnBytes(2));
        if (differs(blocks, 3, want)) {
          addProblem(report, "checksum",
                     "run " + name + " (id " + std::to_string(runId) + ") summary block " +
                         std::to_string(blocks.columnInt(1)) + " of level " +
                         std::to_string(blocks.columnInt(0)) + ": does not match its checksum");
        }
      }
      blocks.reset();
    }
  }
}

// Every run, steps and summary block row against its checksum (docs/storage.md#checksums).
void checkChecksums(db::Connection& c, IntegrityReport& report) {
  if (!c.isSqlite()) {
    checkChecksumsRowByRow(c, report);
    return;
  }
  const auto runName = [](const db::Statement& s) {
    return s.columnIsNull(0) ? std::string("(missing run)") : "'" + s.columnText(0) + "'";
  };
  {
    db::Statement s(c,
                    "SELECT name, id FROM runs WHERE crc IS NOT "
                    "tactile_run_crc(id, name, step_count, has_truth, metadata, extra_columns)");
    while (s.step()) {
      addProblem(report, "checksum",
                 "run " + runName(s) + " (id " + std::to_string(s.columnInt(1)) +
                     "): its row (name, step count, metadata) does not match its checksum");
    }
  }
  {
    db::Statement s(c,
                    "SELECT runs.name, steps.run_id, steps.step FROM steps LEFT JOIN runs ON "
                    "runs.id = steps.run_id WHERE steps.crc IS NOT tactile_step_crc(steps.run_id, "
                    "steps.step, steps.x, steps.y, steps.theta, steps.v, steps.omega, "
                    "steps.blocked, steps.sensors, steps.extra, steps.truth)");
    while (s.step()) {
      addProblem(report, "checksum",
                 "run " + runName(s) + " (id " + std::to_string(s.columnInt(1)) + ") step " +
                     std::to_string(s.columnInt(2)) + ": stored data does not match its checksum");
    }
  }
  {
    db::Statement s(c,
                    "SELECT runs.name, b.run_id, b.level, b.block FROM step_blocks AS b LEFT JOIN "
                    "runs ON runs.id = b.run_id WHERE b.crc IS NOT tactile_block_crc(b.run_id, "
                    "b.level, b.block, b.minmax)");
    while (s.step()) {
      addProblem(report, "checksum",
                 "run " + runName(s) + " (id " + std::to_string(s.columnInt(1)) +
                     ") summary block " + std::to_string(s.columnInt(3)) + " of level " +
                     std::to_string(s.columnInt(2)) + ": does not match its checksum");
    }
  }
}

}  // namespace

IntegrityReport RunDatabase::check() {
  const ResetStatements reset{*impl_};
  IntegrityReport report;
  try {
    db::Connection& c = impl_->connection;
    // Every count and checksum is read from one snapshot: another process importing at the same
    // time must not make the runs' step counts and the steps table look inconsistent.
    struct Snapshot {
      db::Connection& c;
      explicit Snapshot(db::Connection& connection) : c(connection) { c.backend().beginSnapshot(); }
      ~Snapshot() { c.backend().endSnapshot(); }
    } snapshot(c);
    report.schemaVersion = c.isSqlite() ? db::schemaVersion(c) : db::inspectServer(c).version;
    // A file cut short since it was opened: pages past its end read as zeros, which neither
    // SQLite's checks nor the row checksums see in every table. Read through SQLite and stat
    // alone (a descriptor opened and closed here would drop this connection's locks); without
    // committed frames in the log, SQLite's page count is the file's.
    if (c.isSqlite() && !impl_->path.empty() && impl_->path != ":memory:" &&
        db::walCommitFrames(impl_->path) == 0) {
      std::error_code ec;
      const auto bytes = std::filesystem::file_size(impl_->path, ec);
      const std::int64_t pageSize = c.queryInt("PRAGMA page_size");
      const std::int64_t pages = c.queryInt("PRAGMA page_count");
      if (!ec && static_cast<std::int64_t>(bytes) < pages * pageSize) {
        addProblem(report, "file size",
                   "cut short: " + std::to_string(pages) + " pages of " + std::to_string(pageSize) +
                       " bytes, the file holds " + std::to_string(bytes) +
                       "; restore it from a backup");
      }
    }
    // A server checks its pages and foreign keys itself; a file is checked here.
    if (c.isSqlite()) {
      db::Statement s(c, "PRAGMA integrity_check");
      while (s.step()) {
        std::string line = s.columnText(0);
        if (line != "ok") addProblem(report, "integrity", line);
      }
    }
    if (c.isSqlite()) {
      db::Statement s(c, "PRAGMA foreign_key_check");
      while (s.step()) {
        const std::string table = s.columnText(0);
        const std::string parent = s.columnText(2);
        // WITHOUT ROWID tables (steps, step_blocks) report no rowid.
        const std::string row =
            s.columnIsNull(1) ? "a row of table " + table
                              : "row " + std::to_string(s.columnInt(1)) + " of table " + table;
        addProblem(report, "foreign key " + table + " -> " + parent,
                   row + " refers to a missing " + parent + " row");
      }
    }
    report.runs = c.queryInt("SELECT count(*) FROM runs");
    report.steps = c.queryInt("SELECT CAST(coalesce(sum(step_count), 0) AS BIGINT) FROM runs");
    report.labelSets = c.queryInt("SELECT count(*) FROM label_sets");
    const std::int64_t storedSteps = c.queryInt("SELECT count(*) FROM steps");
    if (storedSteps != report.steps) {
      addProblem(report, "step count",
                 "runs declare " + std::to_string(report.steps) +
                     " steps but the steps table holds " + std::to_string(storedSteps));
    }
    if (report.schemaVersion >= 5) checkChecksums(c, report);
    report.ok = report.kinds.empty() && report.schemaVersion == db::kSchemaVersion;
  } catch (const db::DbError& e) {
    report.ok = false;
    addProblem(report, "error", e.what());
  } catch (const std::exception& e) {
    report.ok = false;
    addProblem(report, "error", e.what());
  }
  return report;
}

// ---- models and sweeps -----------------------------------------------------------------------

Result<std::string> ModelStore::load(const std::string& name) {
  return guarded<std::string>(*impl_, [&] {
    db::Statement& s = impl_->statement("SELECT json FROM models WHERE name = ?");
    s.bind(1, name);
    if (!s.step()) throw db::DbError("no model named '" + name + "'");
    std::string json = s.columnText(0);
    s.reset();
    return json;
  });
}

}  // namespace tactile::storage
