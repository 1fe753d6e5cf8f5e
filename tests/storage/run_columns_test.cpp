// Whole-run reads (storage/run_columns.h): a long run of a file is read on two connections, each
// stepping ranges of its steps on its own thread; it reads back bit for bit, also while another
// connection writes, and a damaged row gives the same error as reading the same rows as a window
// (the row-by-row path).
#include <sqlite3.h>

#include <atomic>
#include <thread>

#include "storage/step_checksum.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;
using test::TempDir;
namespace fs = std::filesystem;

// Long enough for the two-thread read (kPipelinedSteps in run_columns.cpp is 50,000), and no
// multiple of the ranges the two connections share (kRangeSteps, 16,384): the last one is short.
constexpr std::size_t kLongRun = 60000;

// A long run with some dense sensor rows (every value non-zero) among the sparse ones.
RunData longRun(bool withTruth, bool withExtra, unsigned seed) {
  RunData run = makeRun(kLongRun, withTruth, seed);
  for (std::size_t t = 5; t < run.stepCount(); t += 997) {
    for (int k = 0; k < kValuesPerStep; ++k)
      run.sensors[t * kValuesPerStep + static_cast<std::size_t>(k)] = 1.0 + k + 1e-3 * t;
  }
  if (withExtra) {
    run.extraColumns = {"x_note", "x_empty"};
    for (std::size_t t = 0; t < run.stepCount(); ++t) {
      run.extraValues.push_back("n" + std::to_string(t % 11));
      run.extraValues.push_back("");
    }
  }
  return run;
}

std::unique_ptr<RunDatabase> openReadOnly(const fs::path& path) {
  auto db = RunDatabase::open(path, OpenMode::ReadOnly);
  EXPECT_TRUE(db.ok()) << (db.ok() ? "" : db.errorText());
  return db.ok() ? std::move(db.value()) : nullptr;
}

// Changes stored rows with SQL that may call the checksum functions (tactile_step_crc).
void exec(const fs::path& path, const std::string& sql) {
  db::Connection c = db::Connection::open(path, false);
  registerChecksumFunctions(c);
  c.exec(sql);
}

TEST(WholeRunRead, LongRunsReadBackBitForBit) {
  TempDir dir;
  auto db = test::openDb(dir / "runs.db");
  ASSERT_NE(db, nullptr);
  for (int variant = 0; variant < 3; ++variant) {
    const RunData run = longRun(variant != 1, variant == 2, 20 + static_cast<unsigned>(variant));
    const std::string name = "long" + std::to_string(variant);
    ASSERT_EQ(db->runs().importRun(run, name).status, ImportStatus::Imported);
    auto loaded = db->runs().load(db->runs().find(name)->id);
    ASSERT_TRUE(loaded.ok()) << loaded.errorText();
    test::expectSameRun(loaded.value(), run);
    EXPECT_EQ(loaded->hasTruth(), variant != 1);
    EXPECT_EQ(loaded->extraValues.size(), variant == 2 ? 2 * kLongRun : 0u);
  }
}

// A long run read through a read-only opening of the file while the writer imports other runs,
// then through the writer's own connection: every read has the run's values bit for bit (each of
// the two connections reads its ranges from a snapshot holding the run as it was imported).
TEST(WholeRunRead, ALongRunReadsBackWhileAnotherConnectionWrites) {
  TempDir dir;
  const fs::path path = dir / "runs.db";
  auto writer = test::openDb(path);
  ASSERT_NE(writer, nullptr);
  const RunData run = longRun(true, true, 31);
  ASSERT_EQ(writer->runs().importRun(run, "long").status, ImportStatus::Imported);
  const std::int64_t id = writer->runs().find("long")->id;
  auto reader = openReadOnly(path);
  ASSERT_NE(reader, nullptr);
  std::atomic<bool> stop{false};
  std::atomic<int> imported{0};
  std::thread imports([&] {
    for (unsigned i = 0; !stop; ++i) {
      if (writer->runs()
              .importRun(makeRun(300, true, 100 + i), "short" + std::to_string(i))
              .status == ImportStatus::Imported) {
        ++imported;
      }
    }
  });
  for (int i = 0; i < 3; ++i) {
    auto loaded = reader->runs().load(id);
    EXPECT_TRUE(loaded.ok()) << loaded.errorText();
    if (loaded.ok()) test::expectSameRun(loaded.value(), run);
  }
  stop = true;
  imports.join();
  EXPECT_GT(imported.load(), 0);
  auto loaded = writer->runs().load(id);
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  test::expectSameRun(loaded.value(), run);
  EXPECT_EQ(loaded->extraValues.size(), 2 * kLongRun);
}

// Each damage, made to step 41234 of a long run: loadRun fails with loadWindow's error for the
// whole run, which names the step.
TEST(WholeRunRead, ADamagedRowOfALongRunGivesTheRowByRowError) {
  struct Damage {
    const char* what;
    const char* sql;  // %R is the run id
    const char* expected;
  };
  const Damage damages[] = {
      {"a changed value", "UPDATE steps SET x = x + 1e-9 WHERE run_id = %R AND step = 41234",
       "step 41234 does not match its checksum"},
      {"a missing row", "DELETE FROM steps WHERE run_id = %R AND step = 41234",
       "gap or extra row at step 41235"},
      {"a NULL checksum", "UPDATE steps SET crc = NULL WHERE run_id = %R AND step = 41234",
       "step 41234 does not match its checksum"},
      {"truth NULL under a matching checksum",
       "UPDATE steps SET truth = NULL, crc = tactile_step_crc(run_id, step, x, y, theta, v, "
       "omega, blocked, sensors, extra, NULL) WHERE run_id = %R AND step = 41234",
       "step 41234 of run %R has missing or malformed truth"},
      {"a malformed sensors blob under a matching checksum",
       "UPDATE steps SET sensors = x'0102', crc = tactile_step_crc(run_id, step, x, y, theta, v, "
       "omega, blocked, x'0102', extra, truth) WHERE run_id = %R AND step = 41234",
       "step 41234 of run %R has a malformed sensors blob"},
      {"too few values for the bitmap under a matching checksum",
       "UPDATE steps SET sensors = x'0100000000000000000000', crc = tactile_step_crc(run_id, "
       "step, x, y, theta, v, omega, blocked, x'0100000000000000000000', extra, truth) WHERE "
       "run_id = %R AND step = 41234",
       "step 41234 of run %R has a malformed sensors blob"},
      {"the last row missing", "DELETE FROM steps WHERE run_id = %R AND step = 59999",
       "is missing steps from 59999"},
  };
  for (const Damage& damage : damages) {
    SCOPED_TRACE(damage.what);
    TempDir dir;
    const fs::path path = dir / "runs.db";
    std::int64_t id = 0;
    {
      auto db = test::openDb(path);
      ASSERT_NE(db, nullptr);
      ASSERT_EQ(db->runs().importRun(longRun(true, false, 7), "long").status,
                ImportStatus::Imported);
      id = db->runs().find("long")->id;
    }
    const auto withId = [&](std::string text) {
      for (std::size_t at = text.find("%R"); at != std::string::npos; at = text.find("%R"))
        text.replace(at, 2, std::to_string(id));
      return text;
    };
    exec(path, withId(damage.sql));
    auto db = openReadOnly(path);
    ASSERT_NE(db, nullptr);
    auto whole = db->runs().load(id);
    ASSERT_FALSE(whole.ok());
    EXPECT_NE(whole.errorText().find(withId(damage.expected)), std::string::npos)
        << whole.errorText();
    auto window = db->runs().loadWindow(id, 0, static_cast<std::int64_t>(kLongRun));
    ASSERT_FALSE(window.ok());
    EXPECT_EQ(whole.errorText(), window.errorText());
  }
}

// A run's x_ values NULL at one step under a matching checksum: the row-by-row error.
TEST(WholeRunRead, MissingExtraValuesOfALongRunAreReported) {
  TempDir dir;
  const fs::path path = dir / "runs.db";
  std::int64_t id = 0;
  {
    auto db = test::openDb(path);
    ASSERT_NE(db, nullptr);
    ASSERT_EQ(db->runs().importRun(longRun(false, true, 9), "long").status, ImportStatus::Imported);
    id = db->runs().find("long")->id;
  }
  exec(path,
       "UPDATE steps SET extra = NULL, crc = tactile_step_crc(run_id, step, x, y, theta, v, "
       "omega, blocked, sensors, NULL, truth) WHERE run_id = " +
           std::to_string(id) + " AND step = 50001");
  auto db = openReadOnly(path);
  ASSERT_NE(db, nullptr);
  auto whole = db->runs().load(id);
  ASSERT_FALSE(whole.ok());
  EXPECT_NE(whole.errorText().find("malformed x_ values at step 50001"), std::string::npos)
      << whole.errorText();
  EXPECT_EQ(whole.errorText(), db->runs().loadWindow(id, 0, 60000).errorText());
}

}  // namespace
}  // namespace tactile::storage
