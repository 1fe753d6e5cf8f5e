// The label history on both backends: revisions, conflicts between two sessions editing one run,
// change polling, assignments.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "storage/schema.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;
using test::TempDir;

constexpr auto kWall = ContactClass::Wall;
constexpr auto kCorner = ContactClass::Corner;
constexpr auto F = SensorGroup::Front;
constexpr auto L = SensorGroup::Left;

class HistoryTest : public ::testing::TestWithParam<test::Backend> {
 protected:
  void SetUp() override {
    address_ = test::databaseAddress(GetParam(), dir_, "history.db");
    if (address_.empty())
      GTEST_SKIP() << "no PostgreSQL test server (the tests start one in ctest)";
    db_ = test::openDb(address_);
    ASSERT_NE(db_, nullptr);
    const auto a = db_->runs().importRun(makeRun(200, true, 1), "runA");
    ASSERT_EQ(a.status, ImportStatus::Imported) << a.message;
    run_ = a.runId;
    auto set = db_->labels().create("team", "alice");
    ASSERT_TRUE(set.ok()) << set.errorText();
    set_ = set.value();
    other_ = test::openDb(address_);  // a second session, as another annotator's machine
    ASSERT_NE(other_, nullptr);
  }

  static EditOptions as(const std::string& annotator, std::optional<std::int64_t> expect = {}) {
    EditOptions options;
    options.annotator = annotator;
    options.expectRevision = expect;
    return options;
  }

  std::int64_t latest(RunDatabase& db) {
    auto r = db.labels().latestRevision(set_, run_);
    EXPECT_TRUE(r.ok()) << r.errorText();
    return r.ok() ? r.value() : -1;
  }

  std::optional<ContactClass> classAt(SensorGroup group, std::int64_t step) {
    for (const LabelSegment& s : db_->labels().segments(set_, run_).value()) {
      if (s.group == group && s.firstStep <= step && step <= s.lastStep) return s.cls;
    }
    return std::nullopt;
  }

  TempDir dir_;
  std::string address_;
  std::unique_ptr<RunDatabase> db_;
  std::unique_ptr<RunDatabase> other_;
  std::int64_t run_ = 0;
  std::int64_t set_ = 0;
};

TEST_P(HistoryTest, EveryEditIsARevisionWithWhoWhenAndWhatItReplaced) {
  auto r1 = db_->labels().setRange(set_, run_, {F}, 10, 50, kWall, as("alice"));
  ASSERT_TRUE(r1.ok()) << r1.errorText();
  auto r2 = db_->labels().setRange(set_, run_, {F}, 30, 60, kCorner, as("bob"));
  ASSERT_TRUE(r2.ok()) << r2.errorText();
  EXPECT_GT(r2.value(), r1.value());
  EXPECT_EQ(db_->labels().lastRevision(), r2.value());

  auto history = db_->labels().history(set_, run_);
  ASSERT_TRUE(history.ok()) << history.errorText();
  ASSERT_EQ(history->size(), 2u);
  const LabelRevision& first = history->at(0);
  EXPECT_EQ(first.revision, r1.value());
  EXPECT_EQ(first.annotator, "alice");
  EXPECT_EQ(first.action, "set");
  EXPECT_EQ(first.run, "runA");
  EXPECT_EQ(first.group, F);
  EXPECT_EQ(first.firstStep, 10);
  EXPECT_EQ(first.lastStep, 50);
  EXPECT_EQ(first.cls, kWall);
  EXPECT_TRUE(first.replaced.empty());
  EXPECT_EQ(first.time.size(), 20u);  // YYYY-MM-DDTHH:MM:SSZ

  // Bob's edit replaced alice's Wall over 30-50 only, clipped to his range.
  const LabelRevision& second = history->at(1);
  EXPECT_EQ(second.annotator, "bob");
  ASSERT_EQ(second.replaced.size(), 1u);
  EXPECT_EQ(second.replaced[0].firstStep, 30);
  EXPECT_EQ(second.replaced[0].lastStep, 50);
  EXPECT_EQ(second.replaced[0].cls, kWall);
  EXPECT_EQ(second.replaced[0].annotator, "alice");
  // The segment written carries its editor.
  const auto segments = db_->labels().segments(set_, run_).value();
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_EQ(segments[1].annotator, "bob");

  // Only the revisions after a given one.
  auto newer = db_->labels().history(set_, run_, r1.value());
  ASSERT_TRUE(newer.ok());
  ASSERT_EQ(newer->size(), 1u);
  EXPECT_EQ(newer->at(0).revision, r2.value());
  EXPECT_EQ(latest(*db_), r2.value());
}

TEST_P(HistoryTest, EditsOfTwoSessionsOnDifferentStepsBothStand) {
  const std::int64_t base = latest(*db_);
  ASSERT_TRUE(db_->labels().setRange(set_, run_, {F}, 0, 49, kWall, as("alice", base)).ok());
  // Bob read the run before alice's edit; his steps are others: his edit stands.
  auto bob = other_->labels().setRange(set_, run_, {F}, 100, 149, kCorner, as("bob", base));
  ASSERT_TRUE(bob.ok()) << bob.errorText();
  // So does one in another group over the same steps.
  ASSERT_TRUE(other_->labels().setRange(set_, run_, {L}, 0, 49, kCorner, as("bob", base)).ok());
  EXPECT_EQ(classAt(F, 10), kWall);
  EXPECT_EQ(classAt(F, 120), kCorner);
  EXPECT_EQ(classAt(L, 10), kCorner);
  EXPECT_EQ(db_->labels().history(set_, run_).value().size(), 3u);
}

TEST_P(HistoryTest, AnEditOverStepsChangedSinceItsRevisionIsRefusedAndStoresNothing) {
  const std::int64_t base = latest(*db_);
  auto alice = db_->labels().setRange(set_, run_, {F}, 20, 80, kWall, as("alice", base));
  ASSERT_TRUE(alice.ok()) << alice.errorText();
  // Bob still works from `base`: his edit overlaps alice's steps 20-80 in F (and his L is free,
  // but the edit stands or fails as a whole).
  auto bob = other_->labels().setRange(set_, run_, {L, F}, 70, 120, kCorner, as("bob", base));
  ASSERT_FALSE(bob.ok());
  EXPECT_TRUE(isLabelConflict(bob.error())) << bob.errorText();
  EXPECT_NE(bob.error().message.find("alice"), std::string::npos) << bob.errorText();
  EXPECT_NE(bob.error().message.find("70-80"), std::string::npos) << bob.errorText();
  EXPECT_NE(bob.error().message.find("revision " + std::to_string(alice.value())),
            std::string::npos)
      << bob.errorText();
  EXPECT_EQ(classAt(F, 75), kWall);
  EXPECT_EQ(classAt(L, 100), std::nullopt);
  EXPECT_EQ(latest(*db_), alice.value());
  // After reading again, his edit goes through.
  auto again =
      other_->labels().setRange(set_, run_, {L, F}, 70, 120, kCorner, as("bob", latest(*other_)));
  ASSERT_TRUE(again.ok()) << again.errorText();
  EXPECT_EQ(classAt(F, 75), kCorner);
  // Without an expected revision, newest wins as before.
  ASSERT_TRUE(db_->labels().setRange(set_, run_, {F}, 75, 75, kWall, as("alice")).ok());
  EXPECT_EQ(classAt(F, 75), kWall);
}

TEST_P(HistoryTest, SegmentEditsAndUndoAreCheckedAndRecordedToo) {
  LabelSegment s;
  s.runId = run_;
  s.group = F;
  s.firstStep = 10;
  s.lastStep = 20;
  s.cls = kWall;
  const std::int64_t base = latest(*db_);
  auto id = db_->labels().addSegment(set_, s, as("alice", base));
  ASSERT_TRUE(id.ok()) << id.errorText();
  const std::int64_t added = db_->labels().lastRevision();
  // Another session changes it; alice's move based on `added` is then refused.
  LabelSegment wider = s;
  wider.lastStep = 40;
  ASSERT_TRUE(other_->labels().changeSegment(id.value(), wider, as("bob", added)).ok());
  LabelSegment moved = s;
  moved.firstStep = 15;
  const Status refused = db_->labels().changeSegment(id.value(), moved, as("alice", added));
  ASSERT_FALSE(refused.ok());
  EXPECT_TRUE(isLabelConflict(refused.error()));
  EXPECT_NE(refused.error().message.find("bob"), std::string::npos);
  const Status gone = db_->labels().removeSegment(id.value(), as("alice", added));
  EXPECT_TRUE(isLabelConflict(gone.error()));
  EXPECT_EQ(classAt(F, 30), kWall);
  // A removal and a restore (what undo writes) based on the newest revision stand.
  ASSERT_TRUE(db_->labels().removeSegment(id.value(), as("alice", latest(*db_))).ok());
  EXPECT_EQ(classAt(F, 30), std::nullopt);
  EditOptions undo = as("alice", latest(*db_));
  undo.action = "undo";
  wider.annotator = "bob";
  ASSERT_TRUE(db_->labels().replaceSegmentsInRange(set_, run_, F, 10, 40, {wider}, undo).ok());
  EXPECT_EQ(classAt(F, 30), kWall);
  const auto history = db_->labels().history(set_, run_).value();
  ASSERT_EQ(history.size(), 4u);
  EXPECT_EQ(history[0].action, "set");
  EXPECT_EQ(history[1].action, "change");
  EXPECT_EQ(history[1].annotator, "bob");
  EXPECT_EQ(history[2].action, "delete");
  EXPECT_EQ(history[2].cls, std::nullopt);
  ASSERT_EQ(history[2].replaced.size(), 1u);
  EXPECT_EQ(history[2].replaced[0].lastStep, 40);
  EXPECT_EQ(history[3].action, "undo");
  EXPECT_EQ(history[3].cls, kWall);
}

TEST_P(HistoryTest, AnUndoIsCheckedAgainstOthersOnly) {
  auto mine = db_->labels().setRange(set_, run_, {F}, 10, 20, kWall, as("alice"));
  ASSERT_TRUE(mine.ok());
  // Alice's own later edit over the same steps does not stop her undo of the first...
  ASSERT_TRUE(db_->labels().setRange(set_, run_, {F}, 15, 25, kCorner, as("alice")).ok());
  EditOptions undo = as("alice", mine.value());
  undo.othersOnly = true;
  undo.action = "undo";
  EXPECT_TRUE(db_->labels().replaceSegmentsInRange(set_, run_, F, 10, 14, {}, undo).ok());
  // ...but bob's does.
  const std::int64_t before = latest(*db_);
  ASSERT_TRUE(other_->labels().setRange(set_, run_, {F}, 24, 30, kWall, as("bob")).ok());
  undo.expectRevision = before;
  const Status refused = db_->labels().replaceSegmentsInRange(set_, run_, F, 15, 25, {}, undo);
  ASSERT_FALSE(refused.ok());
  EXPECT_TRUE(isLabelConflict(refused.error()));
  EXPECT_EQ(classAt(F, 20), kCorner);
}

TEST_P(HistoryTest, ImportTruthAndCopiesKeepHistory) {
  ASSERT_TRUE(db_->labels().autolabel(run_, "team").ok());
  auto history = db_->labels().history(set_, run_).value();
  ASSERT_EQ(history.size(), static_cast<std::size_t>(kGroupCount));
  EXPECT_EQ(history[0].action, "truth");
  EXPECT_EQ(history[0].annotator, "truth");
  EXPECT_EQ(history[0].lastStep, 199);
  auto copy = db_->labels().copy(set_, "team2");
  ASSERT_TRUE(copy.ok()) << copy.errorText();
  EXPECT_EQ(db_->labels().history(copy.value(), run_).value().size(), history.size());
  // Deleting the set or the run takes its history with it.
  ASSERT_TRUE(db_->labels().remove({"team2"}).ok());
  EXPECT_TRUE(db_->labels().history(copy.value(), run_).value().empty());
  ASSERT_TRUE(db_->runs().remove({"runA"}).ok());
  EXPECT_TRUE(db_->labels().history(set_, run_).value().empty());
}

TEST_P(HistoryTest, AnotherSessionsEditIsSeenByPolling) {
  auto first = db_->labels().pollChanges();  // starts watching
  ASSERT_TRUE(first.ok()) << first.errorText();
  EXPECT_FALSE(first.value());
  if (GetParam() == test::Backend::Sqlite) {
    // Nothing else writes this file: no change.
    EXPECT_FALSE(db_->labels().pollChanges().value());
  }
  ASSERT_TRUE(other_->labels().setRange(set_, run_, {F}, 0, 9, kWall, as("bob")).ok());
  bool seen = false;
  for (int i = 0; i < 40 && !seen; ++i) {  // a notification takes a moment to arrive
    auto polled = db_->labels().pollChanges();
    ASSERT_TRUE(polled.ok()) << polled.errorText();
    seen = polled.value();
    if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_TRUE(seen);
}

TEST_P(HistoryTest, AssignmentsMoveFromTodoToReviewed) {
  ASSERT_TRUE(db_->runs().importRun(makeRun(50, false, 2), "runB").status ==
              ImportStatus::Imported);
  ASSERT_TRUE(
      db_->labels()
          .assign({"runA", "runB"}, std::nullopt, "carol", "team", AssignmentState::Todo, "lead")
          .ok());
  ASSERT_TRUE(db_->labels().assign({"runA"}, L, "dave", "", AssignmentState::Todo, "lead").ok());
  ASSERT_TRUE(db_->labels()
                  .assign({"runA"}, std::nullopt, "carol", "", AssignmentState::Labelled, "carol")
                  .ok());
  auto carol = db_->labels().assignments("carol");
  ASSERT_TRUE(carol.ok()) << carol.errorText();
  ASSERT_EQ(carol->size(), 2u);
  EXPECT_EQ(carol->at(0).run, "runA");
  EXPECT_EQ(carol->at(0).state, AssignmentState::Labelled);
  EXPECT_EQ(carol->at(0).labelSet, "team");  // kept when not given again
  EXPECT_EQ(carol->at(0).updatedBy, "carol");
  EXPECT_EQ(carol->at(1).state, AssignmentState::Todo);
  auto all = db_->labels().assignments();
  ASSERT_EQ(all->size(), 3u);
  EXPECT_EQ(all->at(1).group, L);
  // Renaming the set follows into the assignments; an unknown run changes nothing.
  ASSERT_TRUE(db_->labels().rename("team", "lab").ok());
  EXPECT_EQ(db_->labels().assignments("carol")->at(1).labelSet, "lab");
  EXPECT_FALSE(db_->labels()
                   .assign({"runB", "nope"}, std::nullopt, "erin", "", AssignmentState::Todo, "")
                   .ok());
  EXPECT_TRUE(db_->labels().assignments("erin")->empty());
  EXPECT_FALSE(db_->labels().unassign({"runB"}, std::nullopt, "dave").ok());
  ASSERT_TRUE(db_->labels().unassign({"runA"}, L, "dave").ok());
  EXPECT_EQ(db_->labels().assignments()->size(), 2u);
  EXPECT_EQ(parseAssignmentState("reviewed"), AssignmentState::Reviewed);
  EXPECT_EQ(parseAssignmentState("done"), std::nullopt);
}

INSTANTIATE_TEST_SUITE_P(Backends, HistoryTest,
                         ::testing::Values(test::Backend::Sqlite, test::Backend::Postgres),
                         test::backendName);

}  // namespace
}  // namespace tactile::storage

namespace tactile::storage {
namespace {

// A file of schema 5 (before the history) gets the history tables on opening; its labels stay.
TEST(HistoryMigration, AVersion5FileGainsTheHistory) {
  test::TempDir dir;
  const auto path = dir / "v5.db";
  {
    auto db = test::openDb(path);
    ASSERT_NE(db, nullptr);
    ASSERT_EQ(db->runs().importRun(test::makeRun(30, false, 1), "r").status,
              ImportStatus::Imported);
    auto set = db->labels().create("s", "a");
    ASSERT_TRUE(set.ok());
    LabelSegment seg;
    seg.run = "r";
    seg.group = SensorGroup::Left;
    seg.firstStep = 1;
    seg.lastStep = 5;
    seg.cls = ContactClass::Wall;
    ASSERT_TRUE(db->labels().addSegment(set.value(), seg).ok());
  }
  test::sqliteExec(path,
                   "DROP TABLE sweep_claims; DROP TABLE label_revisions; DROP TABLE assignments; "
                   "PRAGMA user_version = 5;");
  auto db = RunDatabase::open(path, OpenMode::ReadWrite);
  ASSERT_TRUE(db.ok()) << db.errorText();
  EXPECT_EQ(db.value()->migrationBackup().filename(), "v5.db.v5.bak");
  EXPECT_TRUE(db.value()->check().ok);
  const auto set = db.value()->labels().find("s");
  ASSERT_TRUE(set.ok());
  const std::int64_t run = db.value()->runs().find("r")->id;
  EXPECT_EQ(db.value()->labels().segments(set->id, run)->size(), 1u);
  // The history starts at the upgrade.
  EXPECT_TRUE(db.value()->labels().history(set->id, run)->empty());
  EXPECT_TRUE(db.value()
                  ->labels()
                  .setRange(set->id, run, {SensorGroup::Left}, 3, 9, ContactClass::Corner, {})
                  .ok());
  EXPECT_EQ(db.value()->labels().history(set->id, run)->size(), 1u);
}

// A server of schema 5 is refused by a plain open with the command that migrates it, and
// `db create` (an open that may create) migrates it.
TEST(HistoryMigration, AVersion5ServerIsMigratedByCreate) {
  const std::string address = test::freshServerSchema();
  if (address.empty()) GTEST_SKIP() << "no PostgreSQL test server (the tests start one in ctest)";
  {
    auto db = RunDatabase::open(address, OpenMode::Create);
    ASSERT_TRUE(db.ok()) << db.errorText();
    ASSERT_EQ(db.value()->runs().importRun(test::makeRun(30, false, 1), "r").status,
              ImportStatus::Imported);
  }
  test::serverExec(
      address,
      "DROP TABLE sweep_claims; DROP TABLE label_revisions; DROP TABLE assignments; "
      "DROP FUNCTION tactile_notify_labels(); UPDATE tactile_meta SET value = '5' WHERE key = "
      "'schema_version'");
  auto refused = RunDatabase::open(address, OpenMode::ReadWrite);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.errorText().find("tactile db create"), std::string::npos)
      << refused.errorText();
  auto migrated = RunDatabase::open(address, OpenMode::Create);
  ASSERT_TRUE(migrated.ok()) << migrated.errorText();
  EXPECT_TRUE(migrated.value()->check().ok);
  EXPECT_EQ(migrated.value()->check().schemaVersion, db::kSchemaVersion);
  auto set = migrated.value()->labels().create("s", "a");
  ASSERT_TRUE(set.ok());
  const std::int64_t run = migrated.value()->runs().find("r")->id;
  EXPECT_TRUE(migrated.value()
                  ->labels()
                  .setRange(set.value(), run, {SensorGroup::Front}, 0, 4, ContactClass::Wall, {})
                  .ok());
  EXPECT_EQ(migrated.value()->labels().history(set.value(), run)->size(), 1u);
}

// A file of schema 6 (before sweeps were planned for workers) gets the claims table on its first
// writing open, with a backup of the file as it was; its sweeps stay.
TEST(SweepClaimsMigration, AVersion6FileGainsTheClaimsWithABackup) {
  test::TempDir dir;
  const auto path = dir / "v6.db";
  {
    auto db = test::openDb(path);
    ASSERT_NE(db, nullptr);
    auto sweep = db->sweeps().create("old", R"({"state":"finished"})");
    ASSERT_TRUE(sweep.ok()) << sweep.errorText();
    ASSERT_TRUE(db->sweeps().addCell(sweep.value(), R"({"order":2})", R"({"rate":0.5})").ok());
  }
  test::sqliteExec(path, "DROP TABLE sweep_claims; PRAGMA user_version = 6;");
  {
    // A read-only open leaves the file as it is and says what migrates it.
    auto readOnly = RunDatabase::open(path, OpenMode::ReadOnly);
    ASSERT_FALSE(readOnly.ok());
    EXPECT_NE(readOnly.errorText().find("schema version 6, older than this program's 7"),
              std::string::npos)
        << readOnly.errorText();
    EXPECT_FALSE(std::filesystem::exists(dir / "v6.db.v6.bak"));
  }
  auto db = RunDatabase::open(path, OpenMode::ReadWrite);
  ASSERT_TRUE(db.ok()) << db.errorText();
  EXPECT_EQ(db.value()->migrationBackup().filename(), "v6.db.v6.bak");
  EXPECT_TRUE(std::filesystem::exists(db.value()->migrationBackup()));
  EXPECT_TRUE(db.value()->check().ok);
  EXPECT_EQ(db.value()->check().schemaVersion, db::kSchemaVersion);
  auto sweeps = db.value()->sweeps().list();
  ASSERT_TRUE(sweeps.ok());
  ASSERT_EQ(sweeps->size(), 1u);
  EXPECT_EQ(sweeps->front().cellCount, 1);
  // The old sweep was not planned: it has no claims. A new plan has one per job.
  EXPECT_TRUE(db.value()->sweeps().claims(sweeps->front().id)->empty());
  auto planned = db.value()->sweeps().plan("new", "{}", {2, 1});
  ASSERT_TRUE(planned.ok()) << planned.errorText();
  auto claim = db.value()->sweeps().claim(planned.value(), "w", 100.0, 10.0);
  ASSERT_TRUE(claim.ok()) << claim.errorText();
  ASSERT_TRUE(claim.value().has_value());
  EXPECT_EQ(claim.value()->state, "running");
  EXPECT_EQ(db.value()->sweeps().claims(planned.value())->size(), 2u);
}

// A server of schema 6 is refused by a plain open with the command that migrates it, and
// `db create` migrates it.
TEST(SweepClaimsMigration, AVersion6ServerIsMigratedByCreate) {
  const std::string address = test::freshServerSchema();
  if (address.empty()) GTEST_SKIP() << "no PostgreSQL test server (the tests start one in ctest)";
  std::int64_t oldSweep = 0;
  {
    auto db = RunDatabase::open(address, OpenMode::Create);
    ASSERT_TRUE(db.ok()) << db.errorText();
    auto sweep = db.value()->sweeps().create("old", R"({"state":"finished"})");
    ASSERT_TRUE(sweep.ok()) << sweep.errorText();
    oldSweep = sweep.value();
  }
  test::serverExec(address,
                   "DROP TABLE sweep_claims; UPDATE tactile_meta SET value = '6' WHERE key = "
                   "'schema_version'");
  auto refused = RunDatabase::open(address, OpenMode::ReadWrite);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.errorText().find("`tactile db create --db ADDRESS` migrates it"),
            std::string::npos)
      << refused.errorText();
  auto migrated = RunDatabase::open(address, OpenMode::Create);
  ASSERT_TRUE(migrated.ok()) << migrated.errorText();
  EXPECT_TRUE(migrated.value()->check().ok);
  EXPECT_EQ(migrated.value()->check().schemaVersion, db::kSchemaVersion);
  EXPECT_TRUE(migrated.value()->sweeps().claims(oldSweep)->empty());
  auto planned = migrated.value()->sweeps().plan("new", "{}", {1, 1, 1});
  ASSERT_TRUE(planned.ok()) << planned.errorText();
  auto claim = migrated.value()->sweeps().claim(planned.value(), "w", 100.0, 10.0);
  ASSERT_TRUE(claim.ok()) << claim.errorText();
  ASSERT_TRUE(claim.value().has_value());
  EXPECT_EQ(migrated.value()->sweeps().claims(planned.value())->size(), 3u);
}

}  // namespace
}  // namespace tactile::storage
