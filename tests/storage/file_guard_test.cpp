// What lies beside or in place of a database before SQLite opens it (storage/file_guard.h,
// docs/storage.md#a-leftover-write-ahead-log): a leftover write-ahead log that continues the file
// is recovered, one written on another state of the file is refused with both files unchanged, a
// file cut short is refused, a FIFO never blocks, and reads leave no files behind.
#include <sqlite3.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>

#include "storage/file_guard.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;
using test::readBytes;
using test::TempDir;
namespace fs = std::filesystem;

void importInto(const fs::path& path, const std::string& name, unsigned seed) {
  auto db = RunDatabase::open(path, OpenMode::Create);
  ASSERT_TRUE(db.ok()) << db.errorText();
  ASSERT_EQ(db.value()->runs().importRun(makeRun(40, true, seed), name).status,
            ImportStatus::Imported);
}

std::size_t runCount(const fs::path& path) {
  auto db = RunDatabase::open(path, OpenMode::ReadOnly);
  EXPECT_TRUE(db.ok()) << db.errorText();
  if (!db.ok()) return 0;
  auto runs = db.value()->runs().list();
  return runs.ok() ? runs->size() : 0;
}

void copyFile(const fs::path& from, const fs::path& to) {
  fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

// A database and the log a killed process left beside it: `sql` (or an import) runs while another
// connection holds a read transaction, so the writer's close cannot checkpoint; both files are then
// copied to `into` and `into`-wal, where nobody has them open.
void leaveLog(const fs::path& source, const fs::path& into, const std::string& sql = {}) {
  sqlite3* reader = nullptr;
  ASSERT_EQ(sqlite3_open_v2(source.c_str(), &reader, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(reader, "BEGIN; SELECT count(*) FROM runs;", nullptr, nullptr, nullptr),
            SQLITE_OK);
  if (sql.empty()) {
    importInto(source, "three", 3);
  } else {
    test::sqliteExec(source, sql);
  }
  ASSERT_GT(fs::file_size(source.string() + "-wal"), 32u) << "the log holds nothing";
  copyFile(source, into);
  copyFile(source.string() + "-wal", into.string() + "-wal");
  sqlite3_exec(reader, "COMMIT", nullptr, nullptr, nullptr);
  sqlite3_close(reader);
}

void expectRefusedUnchanged(const fs::path& path, const std::string& fragment) {
  const std::string before = readBytes(path);
  const std::string logBefore = readBytes(path.string() + "-wal");
  for (OpenMode mode : {OpenMode::Create, OpenMode::ReadWrite, OpenMode::ReadOnly}) {
    auto db = RunDatabase::open(path, mode);
    ASSERT_FALSE(db.ok()) << "opened in mode " << static_cast<int>(mode);
    EXPECT_NE(db.errorText().find(fragment), std::string::npos) << db.errorText();
  }
  EXPECT_TRUE(readBytes(path) == before) << path << " changed";
  EXPECT_TRUE(readBytes(path.string() + "-wal") == logBefore) << "the log changed";
  EXPECT_FALSE(fs::exists(path.string() + "-shm")) << "an index was made for the log";
}

TEST(LeftoverLog, ALogThatContinuesTheFileIsRecovered) {
  TempDir dir;
  const fs::path live = dir / "live.db";
  importInto(live, "one", 1);
  importInto(live, "two", 2);
  leaveLog(live, dir / "crashed.db");
  EXPECT_EQ(db::inspectWal(dir / "crashed.db").kind, db::WalState::Kind::Belongs);
  EXPECT_EQ(runCount(dir / "crashed.db"), 3u) << "the killed writer's commit was lost";
}

// The reported case: a backup restored over a database whose log still holds commits made after
// the backup's state. SQLite would merge that log into the backup and damage it.
TEST(LeftoverLog, ABackupRestoredBesideANewerLogIsRefusedAndLeftAlone) {
  TempDir dir;
  const fs::path live = dir / "live.db";
  importInto(live, "one", 1);
  copyFile(live, dir / "backup.db");
  importInto(live, "two", 2);
  leaveLog(live, dir / "X.db");
  copyFile(dir / "backup.db", dir / "X.db");  // the restore
  const db::WalState state = db::inspectWal(dir / "X.db");
  EXPECT_EQ(state.kind, db::WalState::Kind::Foreign) << state.reason;
  expectRefusedUnchanged(dir / "X.db", (dir / "X.db").string() + "-wal does not belong");
  // What the message says to do works: with the log moved away the backup opens as it was.
  fs::rename(dir / "X.db-wal", dir / "moved.db-wal");
  EXPECT_EQ(runCount(dir / "X.db"), 1u);
}

// Opened through a link, the log that counts is the one beside the file the link leads to (where
// SQLite looks for it).
TEST(LeftoverLog, ALogBesideTheFileALinkLeadsToIsJudged) {
  TempDir dir;
  const fs::path live = dir / "live.db";
  importInto(live, "one", 1);
  copyFile(live, dir / "backup.db");
  importInto(live, "two", 2);
  fs::create_directories(dir / "real");
  leaveLog(live, dir / "real" / "X.db");
  copyFile(dir / "backup.db", dir / "real" / "X.db");
  fs::create_symlink(dir / "real" / "X.db", dir / "link.db");
  auto db = RunDatabase::open(dir / "link.db", OpenMode::ReadOnly);
  ASSERT_FALSE(db.ok()) << "a log that does not belong was applied through a link";
  EXPECT_NE(db.errorText().find("does not belong"), std::string::npos) << db.errorText();
}

TEST(LeftoverLog, AnotherDatabasesLogIsRefused) {
  TempDir dir;
  const fs::path live = dir / "live.db";
  importInto(live, "one", 1);
  leaveLog(live, dir / "crashed.db");
  importInto(dir / "other.db", "different", 9);
  importInto(dir / "other.db", "more", 10);
  copyFile(dir / "crashed.db-wal", dir / "other.db-wal");
  expectRefusedUnchanged(dir / "other.db", "does not belong");
}

TEST(LeftoverLog, EveryCommitCarriesPageOneSoEveryLogCanBeJudged) {
  TempDir dir;
  const fs::path live = dir / "live.db";
  importInto(live, "one", 1);
  sqlite3* reader = nullptr;
  ASSERT_EQ(sqlite3_open(live.c_str(), &reader), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(reader, "BEGIN; SELECT count(*) FROM runs;", nullptr, nullptr, nullptr),
            SQLITE_OK);
  {
    auto db = RunDatabase::open(live, OpenMode::ReadWrite);
    ASSERT_TRUE(db.ok()) << db.errorText();
    // A rename changes one row in place: without page 1 in the commit the log could not be matched.
    ASSERT_TRUE(db.value()->runs().rename("one", "uno").ok());
  }
  copyFile(live, dir / "crashed.db");
  copyFile(live.string() + "-wal", dir / "crashed.db-wal");
  sqlite3_exec(reader, "COMMIT", nullptr, nullptr, nullptr);
  sqlite3_close(reader);
  EXPECT_EQ(db::inspectWal(dir / "crashed.db").kind, db::WalState::Kind::Belongs);
}

// A long session: one connection commits, its log is checkpointed into the file completely (here by
// another connection, as SQLite's automatic checkpoint does every thousand pages), the connection
// goes on committing (the log starts again from its beginning) and the file grows; then it is
// killed (its files copied while it is open). The restarted log's page-1 images carry the very
// change counter the checkpoint put into the file, and the log is still this file's: every
// committed edit is there after the open.
TEST(LeftoverLog, ALogRestartedInALongSessionIsRecovered) {
  TempDir dir;
  const fs::path live = dir / "live.db";
  importInto(live, "one", 1);
  auto db = RunDatabase::open(live, OpenMode::ReadWrite);
  ASSERT_TRUE(db.ok()) << db.errorText();
  ASSERT_TRUE(db.value()->labels().create("long").ok());
  ASSERT_EQ(db.value()->runs().importRun(makeRun(400, true, 2), "two").status,
            ImportStatus::Imported);
  sqlite3* other = nullptr;
  ASSERT_EQ(sqlite3_open(live.c_str(), &other), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(other, "PRAGMA wal_checkpoint(RESTART)", nullptr, nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(other);
  // Commits that grow the file, so that no image in the restarted log equals the file's page 1.
  ASSERT_EQ(db.value()->runs().importRun(makeRun(4000, true, 3), "three").status,
            ImportStatus::Imported);
  const std::string header = readBytes(live.string() + "-wal").substr(0, 16);
  ASSERT_EQ(header.size(), 16u);
  EXPECT_NE(header.substr(12, 4), std::string(4, '\0')) << "the log was never restarted";
  copyFile(live, dir / "crashed.db");
  copyFile(live.string() + "-wal", dir / "crashed.db-wal");
  db.value().reset();

  const db::WalState state = db::inspectWal(dir / "crashed.db");
  EXPECT_EQ(state.kind, db::WalState::Kind::Belongs) << state.reason;
  EXPECT_EQ(runCount(dir / "crashed.db"), 3u) << "the killed session's commits were lost";
}

// A log without any page-1 frame (written by another program) is read through before it is
// trusted: one that continues the file opens.
TEST(LeftoverLog, ALogWithoutPageOneIsReadThroughAndOpensWhenSound) {
  TempDir dir;
  const fs::path live = dir / "live.db";
  importInto(live, "one", 1);
  leaveLog(live, dir / "crashed.db", "UPDATE runs SET subject = 'changed' WHERE name = 'one'");
  EXPECT_EQ(db::inspectWal(dir / "crashed.db").kind, db::WalState::Kind::Unproven);
  auto db = RunDatabase::open(dir / "crashed.db", OpenMode::ReadOnly);
  ASSERT_TRUE(db.ok()) << db.errorText();
  auto run = db.value()->runs().find("one");
  ASSERT_TRUE(run.ok());
  EXPECT_EQ(run->subject, "changed");
}

// The same log beside another database: reading through it finds tables and indexes that no
// longer agree, so it is refused, and the index made for that reading is removed again.
TEST(LeftoverLog, ALogWithoutPageOneBesideAnotherDatabaseIsRefused) {
  TempDir dir;
  const fs::path live = dir / "live.db";
  importInto(live, "one", 1);
  leaveLog(live, dir / "crashed.db", "UPDATE runs SET subject = 'changed' WHERE name = 'one'");
  importInto(dir / "other.db", "first", 5);
  importInto(dir / "other.db", "second", 6);
  copyFile(dir / "crashed.db-wal", dir / "other.db-wal");
  ASSERT_EQ(db::inspectWal(dir / "other.db").kind, db::WalState::Kind::Unproven);
  expectRefusedUnchanged(dir / "other.db", "does not belong");
}

TEST(LeftoverLog, ALogWithoutItsDatabaseIsNeverTurnedIntoOne) {
  TempDir dir;
  const fs::path live = dir / "live.db";
  importInto(live, "one", 1);
  leaveLog(live, dir / "crashed.db");
  copyFile(dir / "crashed.db-wal", dir / "new.db-wal");
  auto db = RunDatabase::open(dir / "new.db", OpenMode::Create);
  ASSERT_FALSE(db.ok());
  EXPECT_NE(db.errorText().find("does not belong"), std::string::npos) << db.errorText();
  EXPECT_FALSE(fs::exists(dir / "new.db"));
}

TEST(LeftoverLog, ALiveLogOfAnotherConnectionIsNotJudged) {
  TempDir dir;
  const fs::path live = dir / "live.db";
  importInto(live, "one", 1);
  auto writer = RunDatabase::open(live, OpenMode::ReadWrite);
  ASSERT_TRUE(writer.ok());
  sqlite3* reader = nullptr;
  ASSERT_EQ(sqlite3_open(live.c_str(), &reader), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(reader, "BEGIN; SELECT count(*) FROM runs;", nullptr, nullptr, nullptr),
            SQLITE_OK);
  ASSERT_EQ(writer.value()->runs().importRun(makeRun(30, true, 4), "four").status,
            ImportStatus::Imported);
  EXPECT_EQ(db::inspectWal(live).kind, db::WalState::Kind::Live);
  auto second = RunDatabase::open(live, OpenMode::ReadWrite);
  EXPECT_TRUE(second.ok()) << second.errorText();
  sqlite3_exec(reader, "COMMIT", nullptr, nullptr, nullptr);
  sqlite3_close(reader);
}

// Closing any descriptor of a file drops every POSIX lock the process holds on it. A second open
// of a database this process already has open must not look at its files: the first
// connection's SQLite locks would vanish, and another process closing the database would take
// itself for the last connection and remove the log the first one still writes into.
TEST(LeftoverLog, ASecondOpenInTheSameProcessKeepsTheFirstConnectionsLocks) {
  TempDir dir;
  const fs::path path = dir / "shared.db";
  importInto(path, "one", 1);
  auto first = RunDatabase::open(path, OpenMode::ReadWrite);
  ASSERT_TRUE(first.ok()) << first.errorText();
  ASSERT_EQ(first.value()->runs().importRun(makeRun(20, true, 20), "two").status,
            ImportStatus::Imported);
  {
    auto second = RunDatabase::open(path, OpenMode::ReadWrite);
    ASSERT_TRUE(second.ok()) << second.errorText();
  }
  // Another process opens, reads and closes it (the sqlite3 shell, as a user might).
  const std::string command =
      "sqlite3 '" + path.string() + "' 'SELECT count(*) FROM runs' > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_TRUE(fs::exists(path.string() + "-wal")) << "the log was removed under a live connection";
  ASSERT_EQ(first.value()->runs().importRun(makeRun(20, true, 21), "three").status,
            ImportStatus::Imported);
  first.value().reset();
  EXPECT_EQ(runCount(path), 3u) << "a commit of the first connection was lost";
}

TEST(ShortFile, ADatabaseCutShortIsRefusedInEveryMode) {
  TempDir dir;
  const fs::path path = dir / "cut.db";
  importInto(path, "one", 1);
  importInto(path, "two", 2);
  for (std::uintmax_t cut : {1u, 4096u, 9000u}) {
    copyFile(path, dir / "short.db");
    fs::resize_file(dir / "short.db", fs::file_size(path) - cut);
    const std::string before = readBytes(dir / "short.db");
    for (OpenMode mode : {OpenMode::Create, OpenMode::ReadWrite, OpenMode::ReadOnly}) {
      auto db = RunDatabase::open(dir / "short.db", mode);
      ASSERT_FALSE(db.ok()) << "cut by " << cut << ", mode " << static_cast<int>(mode);
      EXPECT_NE(db.errorText().find("cut short"), std::string::npos) << db.errorText();
    }
    EXPECT_TRUE(readBytes(dir / "short.db") == before);
  }
  EXPECT_EQ(runCount(path), 2u);
}

TEST(SpecialFiles, AFifoAsTheDatabaseIsRefusedWithoutBlocking) {
  TempDir dir;
  const fs::path fifo = dir / "pipe.db";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::alarm(10);  // a blocking open would hang here; the alarm ends the child instead
    bool allRefused = true;
    for (OpenMode mode : {OpenMode::Create, OpenMode::ReadWrite, OpenMode::ReadOnly}) {
      auto db = RunDatabase::open(fifo, mode);
      allRefused = allRefused && !db.ok() && db.errorText().find("FIFO") != std::string::npos;
    }
    ::_exit(allRefused ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the open blocked on the FIFO";
  EXPECT_EQ(WEXITSTATUS(status), 0) << "a mode opened the FIFO or did not name it";
  struct stat info {};
  ASSERT_EQ(::lstat(fifo.c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode));
}

TEST(ReadOnlyOpen, LeavesNoLogOrIndexBehind) {
  TempDir dir;
  const fs::path path = dir / "r.db";
  importInto(path, "one", 1);
  ASSERT_FALSE(fs::exists(path.string() + "-wal"));
  {
    auto db = RunDatabase::open(path, OpenMode::ReadOnly);
    ASSERT_TRUE(db.ok()) << db.errorText();
    ASSERT_TRUE(db.value()->runs().find("one").ok());
    EXPECT_TRUE(db.value()->check().ok);
  }
  EXPECT_FALSE(fs::exists(path.string() + "-wal"));
  EXPECT_FALSE(fs::exists(path.string() + "-shm"));
}

// Another account reading the owner's database once left -wal and -shm files that account owned,
// after which the owner could no longer write. As root (CI) the reading child drops to nobody.
TEST(ReadOnlyOpen, AnotherAccountsReadNeverLocksTheOwnerOut) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to read as another account";
  TempDir dir;
  const fs::path folder = dir / "shared";
  fs::create_directories(folder);
  fs::permissions(folder, fs::perms::all);  // anyone may create files here
  const fs::path path = folder / "owned.db";
  importInto(path, "one", 1);
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                            fs::perms::others_read);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (::setgid(65534) != 0 || ::setuid(65534) != 0) ::_exit(3);
    auto db = RunDatabase::open(path, OpenMode::ReadOnly);
    if (!db) ::_exit(1);
    ::_exit(db.value()->runs().find("one").ok() && db.value()->check().ok ? 0 : 2);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: open failed, 2: reading failed, 3: cannot drop root";
  EXPECT_FALSE(fs::exists(path.string() + "-wal")) << "the reader left a log";
  EXPECT_FALSE(fs::exists(path.string() + "-shm")) << "the reader left an index";
  importInto(path, "two", 2);  // the owner still writes
  EXPECT_EQ(runCount(path), 2u);
}

}  // namespace
}  // namespace tactile::storage
