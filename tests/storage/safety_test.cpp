// Database safety (docs/storage.md#opening, #errors, #check, #concurrency): open modes, files that
// are not Tactile databases left byte for byte unchanged, errors that name the database, the
// summarised check, and several processes creating and importing into one file at once.
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>

#include "run/run_csv.h"
#include "storage/schema.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;
using test::readBytes;
using test::sqliteExec;
using test::TempDir;
namespace fs = std::filesystem;

void expectNoCompanions(const fs::path& path) {
  for (const char* suffix : {"-wal", "-shm", "-journal"}) {
    EXPECT_FALSE(fs::exists(path.string() + suffix)) << path.string() + suffix << " left behind";
  }
}

TEST(OpenMode, MissingFileIsAnErrorNamingItAndCreatesNothing) {
  TempDir dir;
  const fs::path path = dir / "absent.db";
  for (OpenMode mode : {OpenMode::ReadWrite, OpenMode::ReadOnly}) {
    auto db = RunDatabase::open(path, mode);
    ASSERT_FALSE(db.ok());
    EXPECT_EQ(db.error().file, path.string());
    EXPECT_EQ(db.error().message, "no such database");
  }
  EXPECT_TRUE(fs::is_empty(dir.path())) << "a file was created";
  auto created = RunDatabase::open(path, OpenMode::Create);
  ASSERT_TRUE(created.ok()) << created.errorText();
  EXPECT_TRUE(fs::exists(path));
}

TEST(OpenMode, LegacyCreateFalseMeansReadWrite) {
  TempDir dir;
  OpenOptions options;
  options.create = false;
  EXPECT_FALSE(RunDatabase::open(dir / "absent.db", options).ok());
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(OpenMode, ReadOnlyNeverWrites) {
  TempDir dir;
  const fs::path path = dir / "r.db";
  {
    auto db = RunDatabase::open(path, OpenMode::Create);
    ASSERT_TRUE(db.ok());
    ASSERT_EQ(db.value()->runs().importRun(makeRun(20, true), "one").status,
              ImportStatus::Imported);
  }
  const std::string before = readBytes(path);
  auto db = RunDatabase::open(path, OpenMode::ReadOnly);
  ASSERT_TRUE(db.ok()) << db.errorText();
  EXPECT_TRUE(db.value()->readOnly());
  ASSERT_TRUE(db.value()->runs().find("one").ok());
  auto set = db.value()->labels().create("s");
  ASSERT_FALSE(set.ok());
  EXPECT_EQ(set.error().file, path.string()) << set.errorText();
  EXPECT_NE(set.errorText().find("readonly"), std::string::npos) << set.errorText();
  EXPECT_EQ(db.value()->runs().importRun(makeRun(5, true, 9), "two").status, ImportStatus::Failed);
  EXPECT_TRUE(db.value()->check().ok);
  db.value().reset();
  EXPECT_TRUE(readBytes(path) == before) << path << " changed";
}

// A read-only file in a read-only folder (no -shm can be made there): opened `immutable`. As root
// (CI) file modes do not stop writes, so the reading child drops to user nobody (65534).
TEST(OpenMode, ReadOnlyWorksInAReadOnlyFolder) {
  TempDir dir;
  const fs::path folder = dir / "ro";
  fs::create_directories(folder);
  const fs::path path = folder / "r.db";
  {
    auto db = RunDatabase::open(path, OpenMode::Create);
    ASSERT_TRUE(db.ok());
    ASSERT_EQ(db.value()->runs().importRun(makeRun(25, true), "one").status,
              ImportStatus::Imported);
  }
  expectNoCompanions(path);
  const std::string before = readBytes(path);
  fs::permissions(path, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                              fs::perms::group_exec | fs::perms::others_read |
                              fs::perms::others_exec);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (::getuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(3);
    auto db = RunDatabase::open(path, OpenMode::ReadOnly);
    if (!db) {
      std::fprintf(stderr, "%s\n", db.errorText().c_str());
      ::_exit(1);
    }
    auto run = db.value()->runs().find("one");
    auto data = run ? db.value()->runs().load(run->id) : Result<RunData>(Error("no run"));
    ::_exit(data.ok() && data->stepCount() == 25 && db.value()->check().ok ? 0 : 2);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  fs::permissions(folder, fs::perms::owner_all);
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: open failed, 2: reading failed, 3: cannot drop root";
  EXPECT_TRUE(readBytes(path) == before) << "the read-only database changed";
  expectNoCompanions(path);
}

TEST(OpenMode, ReadOnlyRefusesAnOlderSchemaInsteadOfMigrating) {
  TempDir dir;
  const fs::path path = dir / "v3.db";
  {
    db::Connection c = db::Connection::open(path, true);
    c.exec("PRAGMA journal_mode = WAL");
    db::migrate(c, path, 3);
  }
  const std::string before = readBytes(path);
  auto db = RunDatabase::open(path, OpenMode::ReadOnly);
  ASSERT_FALSE(db.ok());
  EXPECT_EQ(db.error().file, path.string());
  EXPECT_NE(db.error().message.find("older"), std::string::npos) << db.errorText();
  EXPECT_TRUE(readBytes(path) == before) << path << " changed";
}

// Every mode refuses these files before writing anything.
void expectRefusedUnchanged(const fs::path& path, const std::string& expected) {
  const std::string before = readBytes(path);
  for (OpenMode mode : {OpenMode::Create, OpenMode::ReadWrite, OpenMode::ReadOnly}) {
    auto db = RunDatabase::open(path, mode);
    ASSERT_FALSE(db.ok()) << path << " opened in mode " << static_cast<int>(mode);
    EXPECT_EQ(db.error().file, path.string());
    EXPECT_NE(db.error().message.find(expected), std::string::npos) << db.errorText();
    EXPECT_TRUE(readBytes(path) == before)
        << path << " changed (mode " << static_cast<int>(mode) << ")";
    expectNoCompanions(path);
  }
}

TEST(ForeignFile, AnotherProgramsSqliteFileIsLeftByteForByte) {
  TempDir dir;
  const fs::path plain = dir / "plain.db";
  sqliteExec(plain, "CREATE TABLE notes(text); INSERT INTO notes VALUES('keep');");
  expectRefusedUnchanged(plain, "not a Tactile database");

  const fs::path wal = dir / "wal.db";
  sqliteExec(wal, "PRAGMA journal_mode = WAL; CREATE TABLE t(x); INSERT INTO t VALUES(1);");
  expectRefusedUnchanged(wal, "not a Tactile database");

  const fs::path app = dir / "app.db";
  sqliteExec(app, "PRAGMA application_id = 77; CREATE TABLE t(x);");
  expectRefusedUnchanged(app, "another application");
}

// Regression: a file with a user_version but another program's schema (no application id) was
// switched to WAL and got a .v2.bak beside it, with a multi-line SQL error.
TEST(ForeignFile, AUserVersionWithoutTheApplicationIdIsNotOurs) {
  TempDir dir;
  const fs::path versioned = dir / "versioned.db";
  sqliteExec(versioned, "PRAGMA user_version = 2; CREATE TABLE notes(x);");
  expectRefusedUnchanged(versioned, "without the Tactile application id (user_version 2)");
  const fs::path bare = dir / "bare.db";
  sqliteExec(bare, "PRAGMA user_version = 4;");  // the current version, no tables, no id
  expectRefusedUnchanged(bare, "not a Tactile database");
  for (const fs::path& path : {versioned, bare}) {
    for (OpenMode mode : {OpenMode::Create, OpenMode::ReadWrite, OpenMode::ReadOnly}) {
      auto db = RunDatabase::open(path, mode);
      ASSERT_FALSE(db.ok());
      EXPECT_EQ(db.errorText().find('\n'), std::string::npos) << db.errorText();
    }
    for (const auto& entry : fs::directory_iterator(dir.path())) {
      EXPECT_EQ(entry.path().string().find(".bak"), std::string::npos) << entry.path();
    }
  }
}

TEST(ForeignFile, NonSqliteFileIsRefusedNamingIt) {
  TempDir dir;
  const fs::path path = dir / "text.db";
  std::ofstream(path) << "step,x,y\n0,1,2\n";
  expectRefusedUnchanged(path, "not an SQLite file");
}

TEST(ForeignFile, EmptyFileOnlyBecomesADatabaseWhenCreating) {
  TempDir dir;
  const fs::path path = dir / "empty.db";
  std::ofstream(path).close();
  for (OpenMode mode : {OpenMode::ReadWrite, OpenMode::ReadOnly}) {
    auto db = RunDatabase::open(path, mode);
    ASSERT_FALSE(db.ok());
    EXPECT_EQ(db.error().file, path.string());
    EXPECT_NE(db.error().message.find("empty file"), std::string::npos) << db.errorText();
    EXPECT_EQ(fs::file_size(path), 0u);
    expectNoCompanions(path);
  }
  auto db = RunDatabase::open(path, OpenMode::Create);
  ASSERT_TRUE(db.ok()) << db.errorText();
  EXPECT_TRUE(db.value()->check().ok);
}

TEST(Errors, SqliteErrorsNameTheDatabase) {
  TempDir dir;
  const fs::path path = dir / "named.db";
  auto db = RunDatabase::open(path, OpenMode::Create);
  ASSERT_TRUE(db.ok());
  ASSERT_EQ(db.value()->runs().importRun(makeRun(10, true), "one").status, ImportStatus::Imported);
  const auto id = db.value()->runs().find("one")->id;
  sqliteExec(path, "DROP VIEW step_truth; DROP TABLE step_blocks; DROP TABLE steps;");
  auto run = db.value()->runs().load(id);
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.error().file, path.string());
  EXPECT_EQ(run.errorText().rfind(path.string() + ": ", 0), 0u) << run.errorText();
  EXPECT_NE(run.errorText().find("no such table"), std::string::npos) << run.errorText();
}

TEST(Check, ProblemsAreCountedPerKindWithTheFirstTenKept) {
  TempDir dir;
  const fs::path path = dir / "orphans.db";
  {
    auto db = RunDatabase::open(path, OpenMode::Create);
    ASSERT_TRUE(db.ok());
    ASSERT_EQ(db.value()->runs().importRun(makeRun(40, true, 1), "a").status,
              ImportStatus::Imported);
    ASSERT_EQ(db.value()->runs().importRun(makeRun(30, true, 2), "b").status,
              ImportStatus::Imported);
  }
  sqliteExec(path, "DELETE FROM runs WHERE name = 'a'");  // foreign keys off: 40 orphaned steps
  auto db = RunDatabase::open(path, OpenMode::ReadOnly);
  ASSERT_TRUE(db.ok()) << db.errorText();
  const IntegrityReport report = db.value()->check();
  EXPECT_FALSE(report.ok);
  const IntegrityProblemKind* steps = nullptr;
  for (const auto& kind : report.kinds) {
    EXPECT_LE(kind.cases.size(), kIntegrityCasesKept);
    if (kind.kind == "foreign key steps -> runs") steps = &kind;
  }
  ASSERT_NE(steps, nullptr);
  EXPECT_EQ(steps->count, 40);
  EXPECT_EQ(steps->cases.size(), kIntegrityCasesKept);
  EXPECT_LE(report.problems.size(), report.kinds.size() * kIntegrityCasesKept);
}

// Eight processes create one new database and import the same runs into it at once, five rounds:
// every process succeeds, each run is stored once, the others report it as skipped.
TEST(Concurrency, ProcessesCreateMigrateAndImportAtOnce) {
  TempDir dir;
  constexpr int kProcesses = 8;
  constexpr int kRuns = 6;
  std::vector<std::string> texts;
  for (int r = 0; r < kRuns; ++r)
    texts.push_back(formatRunCsv(makeRun(30, true, 100 + r)));
  for (int round = 0; round < 5; ++round) {
    const fs::path path = dir / ("c" + std::to_string(round) + ".db");
    int pipeFds[2];
    ASSERT_EQ(::pipe(pipeFds), 0);
    std::vector<pid_t> children;
    for (int p = 0; p < kProcesses; ++p) {
      const pid_t pid = ::fork();
      ASSERT_GE(pid, 0);
      if (pid == 0) {
        ::close(pipeFds[0]);
        // Child: 0 = every file imported or skipped; 1 = open failed; 2 = an import failed.
        int code = 0;
        auto db = RunDatabase::open(path, OpenMode::Create);
        if (!db) {
          const std::string line = "open: " + db.errorText() + "\n";
          (void)!::write(pipeFds[1], line.data(), line.size());
          ::_exit(1);
        }
        for (int r = 0; r < kRuns; ++r) {
          const auto outcome = db.value()->runs().importText(texts[static_cast<std::size_t>(r)],
                                                             "run_" + std::to_string(r) + ".csv");
          if (outcome.status == ImportStatus::Failed) {
            const std::string line = "import: " + outcome.message + "\n";
            (void)!::write(pipeFds[1], line.data(), line.size());
            code = 2;
          } else if (outcome.status == ImportStatus::Imported) {
            const std::string line = "imported " + outcome.runName + "\n";
            (void)!::write(pipeFds[1], line.data(), line.size());
          }
        }
        db.value().reset();
        ::_exit(code);
      }
      children.push_back(pid);
    }
    ::close(pipeFds[1]);
    std::string output;
    char buffer[4096];
    ssize_t n = 0;
    while ((n = ::read(pipeFds[0], buffer, sizeof buffer)) > 0)
      output.append(buffer, static_cast<std::size_t>(n));
    ::close(pipeFds[0]);
    for (pid_t pid : children) {
      int status = 0;
      ::waitpid(pid, &status, 0);
      EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
          << "round " << round << ": a process failed (status " << status << "):\n"
          << output;
    }
    std::multiset<std::string> imported;
    std::size_t start = 0;
    while (start < output.size()) {
      const std::size_t end = output.find('\n', start);
      const std::string line = output.substr(start, end - start);
      if (line.rfind("imported ", 0) == 0) imported.insert(line.substr(9));
      start = end + 1;
    }
    EXPECT_EQ(imported.size(), static_cast<std::size_t>(kRuns)) << output;
    EXPECT_EQ(std::set<std::string>(imported.begin(), imported.end()).size(), imported.size())
        << "a run was imported twice:\n"
        << output;
    auto db = RunDatabase::open(path, OpenMode::ReadOnly);
    ASSERT_TRUE(db.ok()) << db.errorText();
    EXPECT_EQ(db.value()->runs().list()->size(), static_cast<std::size_t>(kRuns));
    EXPECT_TRUE(db.value()->check().ok);
  }
}

}  // namespace
}  // namespace tactile::storage
