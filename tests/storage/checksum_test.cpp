// Checksums of the stored run data (docs/storage.md#checksums): a flipped bit in a database file
// is reported by `check()` and by every read of the damaged run, never read back as another value;
// a damaged database is not written into; older databases get their checksums on migration.
#include <sqlite3.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <csignal>
#include <fstream>
#include <iterator>
#include <random>

#include "run/run_csv.h"
#include "storage/schema.h"
#include "storage/step_checksum.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;
using test::readBytes;
using test::sqliteExec;
using test::TempDir;
namespace fs = std::filesystem;

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// A database of three runs (truth, x_ columns) closed, so everything is in the main file.
fs::path makeDatabase(const TempDir& dir, std::vector<RunData>& runs) {
  const fs::path path = dir / "runs.db";
  auto db = test::openDb(path);
  for (unsigned i = 0; i < 3; ++i) {
    RunData run = makeRun(300 + 100 * i, i != 1, 10 + i);
    if (i == 2) {
      run.extraColumns = {"x_note"};
      for (std::size_t s = 0; s < run.stepCount(); ++s)
        run.extraValues.push_back("n" + std::to_string(s % 5));
    }
    EXPECT_EQ(db->runs().importRun(run, "run" + std::to_string(i)).status, ImportStatus::Imported);
    runs.push_back(std::move(run));
  }
  return path;
}

TEST(Checksums, Crc32KnownAnswer) {
  EXPECT_EQ(crc32(0, "123456789", 9), 0xCBF43926u);
  EXPECT_EQ(crc32(0, "", 0), 0u);
  // Any split gives the same value.
  const std::string text = "The quick brown fox jumps over the lazy dog";
  EXPECT_EQ(crc32(0, text.data(), text.size()), 0x414FA339u);
  EXPECT_EQ(crc32(crc32(0, text.data(), 13), text.data() + 13, text.size() - 13), 0x414FA339u);
}

// Regression: one flipped bit of a stored sensor value passed the check and was exported as
// another number.
TEST(Checksums, AFlippedBitInAStepBlobIsReportedNamingTheRun) {
  TempDir dir;
  std::vector<RunData> runs;
  const fs::path path = makeDatabase(dir, runs);
  // A distinctive stored value of run1: its bytes occur once in the file.
  std::size_t index = 57 * kValuesPerStep;
  while (runs[1].sensors[index] == 0.0)
    ++index;
  ASSERT_LT(index, 58 * kValuesPerStep);
  const double value = runs[1].sensors[index];
  std::string bytes = readBytes(path);
  char pattern[8];
  std::memcpy(pattern, &value, 8);
  const std::size_t at = bytes.find(std::string(pattern, 8));
  ASSERT_NE(at, std::string::npos);
  bytes[at] = static_cast<char>(bytes[at] ^ 0x10);  // a low mantissa bit
  writeBytes(path, bytes);

  auto db = RunDatabase::open(path, OpenMode::ReadOnly);
  ASSERT_TRUE(db.ok()) << db.errorText();
  const IntegrityReport report = db.value()->check();
  EXPECT_FALSE(report.ok);
  ASSERT_FALSE(report.kinds.empty());
  EXPECT_EQ(report.kinds[0].kind, "checksum");
  EXPECT_NE(report.kinds[0].cases[0].find("run 'run1'"), std::string::npos)
      << report.kinds[0].cases[0];
  EXPECT_NE(report.kinds[0].cases[0].find("step 57"), std::string::npos);
  const auto id = db.value()->runs().find("run1")->id;
  auto loaded = db.value()->runs().load(id);
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.errorText().find("run 'run1'"), std::string::npos) << loaded.errorText();
  EXPECT_NE(loaded.errorText().find("damaged"), std::string::npos) << loaded.errorText();
  EXPECT_FALSE(db.value()->runs().loadWindow(id, 50, 20).ok());
  EXPECT_FALSE(db.value()->runs().loadTrack(id).ok());
  EXPECT_TRUE(db.value()->runs().loadWindow(id, 100, 20).ok());  // the rest of the run still reads
  // The other runs are intact.
  auto other = db.value()->runs().load(db.value()->runs().find("run0")->id);
  ASSERT_TRUE(other.ok()) << other.errorText();
  test::expectSameRun(other.value(), runs[0]);
  db.value().reset();

  // No writing verb writes into it: refused, the file unchanged.
  const std::string before = readBytes(path);
  for (OpenMode mode : {OpenMode::ReadWrite, OpenMode::Create}) {
    auto writable = RunDatabase::open(path, mode);
    ASSERT_FALSE(writable.ok());
    EXPECT_NE(writable.errorText().find("damaged"), std::string::npos) << writable.errorText();
    EXPECT_NE(writable.errorText().find("nothing is written"), std::string::npos);
  }
  EXPECT_TRUE(readBytes(path) == before);
}

// Single bit flips anywhere in the file: the database is refused, the check reports damage, or
// every run reads back exactly as imported. Never a silently different value.
TEST(Checksums, RandomBitFlipsNeverReadBackAsOtherValues) {
  TempDir dir;
  std::vector<RunData> runs;
  const fs::path path = makeDatabase(dir, runs);
  const std::string pristine = readBytes(path);
  const fs::path copy = dir / "flipped.db";
  std::mt19937_64 rng(11);
  int reported = 0;
  for (int trial = 0; trial < 150; ++trial) {
    std::string bytes = pristine;
    const std::size_t at = 100 + rng() % (bytes.size() - 100);  // past SQLite's file header
    bytes[at] = static_cast<char>(bytes[at] ^ (1 << (rng() % 8)));
    writeBytes(copy, bytes);
    std::error_code ec;
    for (const char* suffix : {"-wal", "-shm"})
      fs::remove(copy.string() + suffix, ec);
    auto db = RunDatabase::open(copy, OpenMode::ReadOnly);
    if (!db.ok()) {
      ++reported;
      continue;
    }
    const bool checked = db.value()->check().ok;
    bool allSame = true;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      auto info = db.value()->runs().find("run" + std::to_string(i));
      if (!info.ok()) {
        allSame = false;
        continue;
      }
      auto loaded = db.value()->runs().load(info->id);
      if (!loaded.ok()) {
        allSame = false;
        continue;
      }
      // A run that loads is the run that was imported, bit for bit.
      ASSERT_TRUE(loaded.value() == runs[i])
          << "trial " << trial << ": a flip at byte " << at << " changed run" << i
          << " without an error (check " << (checked ? "ok" : "failed") << ")";
    }
    if (checked) {
      EXPECT_TRUE(allSame) << "trial " << trial << ": check ok but a run did not load";
    } else {
      ++reported;
    }
  }
  EXPECT_GT(reported, 0);
}

// A version-4 database (before checksums) opens: the migration computes every checksum, keeps a
// backup, and damage after it is found.
TEST(Checksums, AnOlderDatabaseGetsItsChecksumsOnMigration) {
  TempDir dir;
  std::vector<RunData> runs;
  const fs::path path = makeDatabase(dir, runs);
  sqliteExec(path,
             "ALTER TABLE runs DROP COLUMN crc; ALTER TABLE steps DROP COLUMN crc; "
             "ALTER TABLE step_blocks DROP COLUMN crc; DROP TABLE label_revisions; "
             "DROP TABLE assignments; DROP TABLE sweep_claims; PRAGMA user_version = 4;");
  {
    auto old = RunDatabase::open(path, OpenMode::ReadOnly);
    ASSERT_FALSE(old.ok());  // read-only never migrates
  }
  auto db = RunDatabase::open(path, OpenMode::ReadWrite);
  ASSERT_TRUE(db.ok()) << db.errorText();
  EXPECT_EQ(db.value()->migrationBackup().filename(), "runs.db.v4.bak");
  EXPECT_TRUE(db.value()->check().ok);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    auto loaded = db.value()->runs().load(db.value()->runs().find("run" + std::to_string(i))->id);
    ASSERT_TRUE(loaded.ok()) << loaded.errorText();
    test::expectSameRun(loaded.value(), runs[i]);
  }
  db.value().reset();
  sqliteExec(path, "UPDATE steps SET x = x + 1e-9 WHERE run_id = 1 AND step = 3");
  auto reopened = RunDatabase::open(path, OpenMode::ReadOnly);
  ASSERT_TRUE(reopened.ok());
  const IntegrityReport report = reopened.value()->check();
  EXPECT_FALSE(report.ok);
  ASSERT_FALSE(report.problems.empty());
  EXPECT_NE(report.problems[0].find("step 3"), std::string::npos) << report.problems[0];
}

// Regression: a creating open that failed on a full disk left a 0-byte database behind. The file
// size limit (RLIMIT_FSIZE, SIGXFSZ ignored so writes fail with EFBIG) stands in for the full disk.
TEST(FailedCreation, LeavesNoEmptyDatabaseBehind) {
  TempDir dir;
  const fs::path path = dir / "full.db";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{};
    limit.rlim_cur = limit.rlim_max = 0;
    setrlimit(RLIMIT_FSIZE, &limit);
    auto db = RunDatabase::open(path, OpenMode::Create);
    _exit(db.ok() ? 3 : 0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the creation did not fail";
  EXPECT_FALSE(fs::exists(path)) << "a " << fs::file_size(path) << "-byte file stayed";
  for (const char* suffix : {"-wal", "-shm", "-journal"}) {
    EXPECT_FALSE(fs::exists(path.string() + suffix)) << suffix;
  }
  // An existing empty file given to a creating open that fails stays (it was the user's).
  std::ofstream(path).close();
  const pid_t second = fork();
  ASSERT_GE(second, 0);
  if (second == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{};
    limit.rlim_cur = limit.rlim_max = 0;
    setrlimit(RLIMIT_FSIZE, &limit);
    auto db = RunDatabase::open(path, OpenMode::Create);
    _exit(db.ok() ? 3 : 0);
  }
  ASSERT_EQ(waitpid(second, &status, 0), second);
  EXPECT_TRUE(fs::exists(path));
}

// The checksum of bytes given in pieces of any size equals that of the bytes at once, and a run's
// file-form checksum made in formatted pieces on several threads equals that of its whole text.
TEST(RunningChecksum, PiecesOfAnySizeGiveTheChecksumOfTheWhole) {
  std::mt19937 rng(3);
  for (std::size_t length : {0u, 1u, 7u, 8u, 15u, 16u, 17u, 31u, 33u, 1000u, 4099u}) {
    std::string bytes(length, '\0');
    for (char& c : bytes)
      c = static_cast<char>(rng());
    for (int round = 0; round < 20; ++round) {
      RunningChecksum sum;
      std::size_t at = 0;
      while (at < bytes.size()) {
        const std::size_t piece = std::min<std::size_t>(bytes.size() - at, rng() % 40);
        sum.update(std::string_view(bytes).substr(at, piece));
        at += piece;
      }
      EXPECT_EQ(sum.hex(), checksumHex(bytes)) << length << " bytes, round " << round;
    }
  }
  EXPECT_NE(checksumHex("a"), checksumHex("b"));
  EXPECT_NE(checksumHex(std::string(16, '\0')), checksumHex(std::string(17, '\0')));
}

TEST(RunningChecksum, ARunsFileChecksumInPiecesEqualsThatOfItsText) {
  for (std::size_t steps : {0u, 1u, 8191u, 8192u, 8193u, 40000u}) {
    RunData run = makeRun(steps, steps % 2 == 0, 9);
    if (steps == 8193u) {
      run.extraColumns = {"x_plan", "x_state"};
      for (std::size_t i = 0; i < steps; ++i) {
        run.extraValues.push_back(std::to_string(i));
        run.extraValues.push_back(i % 3 == 0 ? "follow" : "");
      }
    }
    EXPECT_EQ(runFileChecksumHex(run), checksumHex(formatRunCsv(run))) << steps << " steps";
  }
}

}  // namespace
}  // namespace tactile::storage
