#include <gtest/gtest.h>

#include <fstream>

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
  auto added = db->addSegment(1, segment);
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
  auto run = db->findRun("old");
  ASSERT_TRUE(run.ok()) << run.error();
  EXPECT_TRUE(db->createLabelSet("after-migration").ok());
  // The backup still has the old version and the old data.
  db::Connection backup = db::Connection::open(db->migrationBackup(), false);
  EXPECT_EQ(db::schemaVersion(backup), 1);
  EXPECT_EQ(backup.queryInt("SELECT count(*) FROM runs"), 1);
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
  EXPECT_NE(db.error().find("migration to schema version 2"), std::string::npos) << db.error();
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
  EXPECT_NE(db.error().find("newer"), std::string::npos) << db.error();
  EXPECT_NE(db.error().find(std::to_string(db::kSchemaVersion + 5)), std::string::npos);
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
  EXPECT_NE(db.error().find("not a tactile database"), std::string::npos) << db.error();
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
