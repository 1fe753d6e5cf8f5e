#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <vector>

#include "storage/run_codec.h"
#include "storage/schema.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::TempDir;

TEST(Schema, NewDatabaseGetsNewestVersionWalAndForeignKeys) {
  TempDir dir;
  const auto path = dir / "new.db";
  {
    auto db = test::openDb(path);
    ASSERT_NE(db, nullptr);
    EXPECT_TRUE(db->migrationBackup().empty());
    EXPECT_EQ(db->check().schemaVersion, db::kSchemaVersion);
  }
  db::Connection c = db::Connection::open(path, false);
  EXPECT_EQ(db::schemaVersion(c), db::kSchemaVersion);
  db::Statement mode(c, "PRAGMA journal_mode");
  ASSERT_TRUE(mode.step());
  EXPECT_EQ(mode.columnText(0), "wal");
  EXPECT_EQ(c.queryInt("PRAGMA application_id"), db::kApplicationId);
}

TEST(Schema, ForeignKeysAreEnforced) {
  auto db = test::openDb(":memory:");
  ASSERT_NE(db, nullptr);
  LabelSegment segment;
  segment.runId = 42;  // no such run
  auto added = db->labels().addSegment(1, segment);
  EXPECT_FALSE(added.ok());
}

TEST(Schema, OlderDatabaseIsBackedUpAndMigrated) {
  TempDir dir;
  const auto path = dir / "old.db";
  {
    db::Connection c = db::Connection::open(path, true);
    c.exec("PRAGMA journal_mode = WAL");
    const auto report = db::migrate(c, path, 1);
    EXPECT_EQ(report.toVersion, 1);
    c.exec(
        "INSERT INTO runs(name, source_file, checksum, outcome, step_count, has_truth, metadata, "
        "extra_columns, imported_at) VALUES('old', 'old.csv', 'abc', 'unknown', 0, 0, X'', "
        "X'', 'then')");
  }
  auto db = test::openDb(path);
  ASSERT_NE(db, nullptr);
  EXPECT_EQ(db->check().schemaVersion, db::kSchemaVersion);
  ASSERT_FALSE(db->migrationBackup().empty());
  EXPECT_TRUE(std::filesystem::exists(db->migrationBackup()));
  EXPECT_EQ(db->migrationBackup().filename(), "old.db.v1.bak");
  // Data survived and the new tables work.
  auto run = db->runs().find("old");
  ASSERT_TRUE(run.ok()) << run.errorText();
  EXPECT_TRUE(db->labels().create("after-migration").ok());
  // The backup still has the old version and the old data.
  db::Connection backup = db::Connection::open(db->migrationBackup(), false);
  EXPECT_EQ(db::schemaVersion(backup), 1);
  EXPECT_EQ(backup.queryInt("SELECT count(*) FROM runs"), 1);
}

// Writes `run` the way schema version 3 stored it: dense sensors and minmax blobs, truth as
// run-length rows in truth_segments.
void insertVersion3Run(db::Connection& c, const RunData& run) {
  c.exec("BEGIN");
  std::vector<std::string> pairs;
  for (const auto& [key, value] : run.metadata) {
    pairs.push_back(key);
    pairs.push_back(value);
  }
  const std::string metadata = encodeExtra(pairs.data(), pairs.size());
  db::Statement(c,
                "INSERT INTO runs(id, name, source_file, checksum, outcome, dt, step_count, "
                "has_truth, metadata, extra_columns, imported_at) "
                "VALUES(1, 'old', 'old.csv', 'abc', 'success', 0.1, ?, 1, ?, X'', 'then')")
      .bind(1, static_cast<std::int64_t>(run.stepCount()))
      .bindBlob(2, metadata.data(), metadata.size())
      .run();
  db::Statement step(c,
                     "INSERT INTO steps(run_id, step, x, y, theta, v, omega, blocked, sensors) "
                     "VALUES(1, ?, ?, ?, ?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < run.stepCount(); ++i) {
    step.bind(1, static_cast<std::int64_t>(i))
        .bind(2, run.x[i])
        .bind(3, run.y[i])
        .bind(4, run.theta[i])
        .bind(5, run.v[i])
        .bind(6, run.omega[i])
        .bind(7, static_cast<std::int64_t>(run.blocked[i]))
        .bindBlob(8, run.stepSensors(i), kValuesPerStep * sizeof(double))
        .run();
  }
  db::Statement truth(c,
                      "INSERT INTO truth_segments(run_id, grp, first_step, last_step, class) "
                      "VALUES(1, ?, ?, ?, ?)");
  for (const TruthSegment& segment : truthSegments(run)) {
    truth.bind(1, groupInfo(segment.group).shortName)
        .bind(2, segment.firstStep)
        .bind(3, segment.lastStep)
        .bind(4, contactClassName(segment.cls))
        .run();
  }
  db::Statement block(c,
                      "INSERT INTO step_blocks(run_id, level, block, minmax) VALUES(1, ?, ?, ?)");
  const SummaryBlocks levels = computeSummaryBlocks(run.sensors.data(), run.stepCount());
  for (std::size_t level = 0; level < levels.size(); ++level) {
    for (std::size_t b = 0; b < levels[level].size() / kSummaryValues; ++b) {
      block.bind(1, static_cast<std::int64_t>(level))
          .bind(2, static_cast<std::int64_t>(b))
          .bindBlob(3, levels[level].data() + b * kSummaryValues, kSummaryValues * sizeof(double))
          .run();
    }
  }
  c.exec("COMMIT");
}

// A version 3 file reads back unchanged after the migration: dense blobs, and truth moved from
// segments into the steps.
TEST(Schema, Version3RunReadsBackAfterMigration) {
  TempDir dir;
  const auto path = dir / "v3.db";
  // Truth segments of 1 to 40 steps, different per group, as simulated runs have.
  RunData run = test::makeRun(3000, true, 9);
  std::mt19937 rng(3);
  for (int g = 0; g < kGroupCount; ++g) {
    auto cls = ContactClass::NoContact;
    for (std::size_t i = 0; i < run.stepCount(); ++i) {
      if (rng() % 13 == 0) cls = static_cast<ContactClass>(rng() % kContactClassCount);
      run.truth[i * kGroupCount + static_cast<std::size_t>(g)] = cls;
    }
  }
  {
    db::Connection c = db::Connection::open(path, true);
    c.exec("PRAGMA journal_mode = WAL");
    db::migrate(c, path, 3);
    insertVersion3Run(c, run);
  }
  auto db = test::openDb(path);
  ASSERT_NE(db, nullptr);
  EXPECT_EQ(db->migrationBackup().filename(), "v3.db.v3.bak");
  auto loaded = db->runs().load(1);
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  test::expectSameRun(loaded.value(), run);
  auto window = db->runs().loadWindow(1, 1234, 500);
  ASSERT_TRUE(window.ok()) << window.errorText();
  for (std::size_t i = 0; i < 500 * kGroupCount; ++i) {
    ASSERT_EQ(window->data.truth[i], run.truth[1234 * kGroupCount + i]) << i;
  }
  // Summaries from the dense blocks equal those of the same run imported now.
  auto fresh = test::openDb(":memory:");
  ASSERT_EQ(fresh->runs().importRun(run, "new").status, ImportStatus::Imported);
  auto oldSummary = db->runs().loadSummary(1, 0, -1, 100);
  auto newSummary = fresh->runs().loadSummary(1, 0, -1, 100);
  ASSERT_TRUE(oldSummary.ok() && newSummary.ok());
  ASSERT_EQ(oldSummary->buckets.size(), newSummary->buckets.size());
  for (std::size_t b = 0; b < newSummary->buckets.size(); ++b) {
    EXPECT_EQ(oldSummary->buckets[b].min, newSummary->buckets[b].min);
    EXPECT_EQ(oldSummary->buckets[b].max, newSummary->buckets[b].max);
  }
  // Autolabel gives the truth segments, and the step_truth view spells the classes out.
  auto written = db->labels().autolabel(1, "truth");
  ASSERT_TRUE(written.ok()) << written.errorText();
  EXPECT_EQ(static_cast<std::size_t>(written.value()), truthSegments(run).size());
  db.reset();
  db::Connection c = db::Connection::open(path, false);
  db::Statement view(c, "SELECT FLC FROM step_truth WHERE run_id = 1 AND step = 77");
  ASSERT_TRUE(view.step());
  EXPECT_EQ(view.columnText(0), contactClassName(run.truthAt(77, SensorGroup::FrontLeftCorner)));
  EXPECT_EQ(c.queryInt("SELECT count(*) FROM sqlite_schema WHERE name = 'truth_segments'"), 0);
}

// New files store mostly-zero rows sparsely: far fewer bytes than 88 float64 per step.
TEST(Schema, MostlyZeroSensorRowsAreStoredSparsely) {
  TempDir dir;
  const auto path = dir / "sparse.db";
  RunData run = test::makeRun(500, false, 4);
  std::fill(run.sensors.begin(), run.sensors.begin() + 100 * kValuesPerStep, 0.0);
  {
    auto db = test::openDb(path);
    ASSERT_NE(db, nullptr);
    ASSERT_EQ(db->runs().importRun(run, "sparse").status, ImportStatus::Imported);
    auto loaded = db->runs().load(1);
    ASSERT_TRUE(loaded.ok()) << loaded.errorText();
    test::expectSameRun(loaded.value(), run);
  }
  db::Connection c = db::Connection::open(path, false);
  EXPECT_EQ(c.queryInt("SELECT max(length(sensors)) FROM steps WHERE step < 100"), 11);
  // makeRun touches about a fifth of the domes: well under the dense 704 bytes.
  EXPECT_LT(c.queryInt("SELECT avg(length(sensors)) FROM steps WHERE step >= 100"), 300);
}

TEST(Schema, FailedMigrationLeavesVersionUnchanged) {
  TempDir dir;
  const auto path = dir / "broken.db";
  {
    db::Connection c = db::Connection::open(path, true);
    db::migrate(c, path, 1);
    // A table that migration 2 wants to create: the migration must fail as a whole.
    c.exec("CREATE TABLE label_sets(x)");
  }
  auto db = RunDatabase::open(path);
  ASSERT_FALSE(db.ok());
  EXPECT_NE(db.errorText().find("migration to schema version 2"), std::string::npos)
      << db.errorText();
  db::Connection c = db::Connection::open(path, false);
  EXPECT_EQ(db::schemaVersion(c), 1);
}

TEST(Schema, NewerDatabaseIsAClearError) {
  TempDir dir;
  const auto path = dir / "newer.db";
  {
    db::Connection c = db::Connection::open(path, true);
    db::migrate(c, path);
    c.exec("PRAGMA user_version = " + std::to_string(db::kSchemaVersion + 5));
  }
  auto db = RunDatabase::open(path);
  ASSERT_FALSE(db.ok());
  EXPECT_NE(db.errorText().find("newer"), std::string::npos) << db.errorText();
  EXPECT_NE(db.errorText().find(std::to_string(db::kSchemaVersion + 5)), std::string::npos);
}

TEST(Schema, ForeignSqliteFileIsRefused) {
  TempDir dir;
  const auto path = dir / "other.db";
  {
    db::Connection c = db::Connection::open(path, true);
    c.exec("CREATE TABLE something(a, b)");
  }
  auto db = RunDatabase::open(path);
  ASSERT_FALSE(db.ok());
  EXPECT_NE(db.errorText().find("not a Tactile database"), std::string::npos) << db.errorText();
}

TEST(Schema, MissingFileWithoutCreateIsAnError) {
  TempDir dir;
  OpenOptions options;
  options.create = false;
  auto db = RunDatabase::open(dir / "absent.db", options);
  EXPECT_FALSE(db.ok());
  EXPECT_FALSE(std::filesystem::exists(dir / "absent.db"));
}

TEST(Schema, BackupNamesDoNotOverwrite) {
  TempDir dir;
  const auto first = db::backupPath(dir / "x.db", 2);
  EXPECT_EQ(first.filename(), "x.db.v2.bak");
  std::ofstream(first) << "taken";
  EXPECT_EQ(db::backupPath(dir / "x.db", 2).filename(), "x.db.v2-1.bak");
}

}  // namespace
}  // namespace tactile::storage
