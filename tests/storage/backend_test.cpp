// The storage API on both backends (SQLite files and a PostgreSQL server), and copies between them.
#include <gtest/gtest.h>

#include <bit>

#include "run/run_csv.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::Backend;
using test::makeRun;
using test::TempDir;

bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

class BackendTest : public ::testing::TestWithParam<Backend> {
 protected:
  void SetUp() override {
    address_ = test::databaseAddress(GetParam(), dir_, "backend.db");
    if (address_.empty())
      GTEST_SKIP() << "no PostgreSQL test server (the tests start one in ctest)";
    db_ = test::openDb(address_);
    ASSERT_NE(db_, nullptr);
  }

  TempDir dir_;
  std::string address_;
  std::unique_ptr<RunDatabase> db_;
};

TEST_P(BackendTest, ARunReadsBackValueForValueWindowTrackAndExport) {
  const RunData run = makeRun(3000, true, 11);
  const ImportOutcome outcome = db_->runs().importRun(run, "alpha");
  ASSERT_EQ(outcome.status, ImportStatus::Imported) << outcome.message;
  auto loaded = db_->runs().load(outcome.runId);
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  test::expectSameRun(run, loaded.value());
  auto window = db_->runs().loadWindow(outcome.runId, 1234, 10);
  ASSERT_TRUE(window.ok()) << window.errorText();
  ASSERT_EQ(window->data.stepCount(), 10U);
  EXPECT_TRUE(sameBits(window->data.x[3], run.x[1237]));
  auto track = db_->runs().loadTrack(outcome.runId);
  ASSERT_TRUE(track.ok()) << track.errorText();
  ASSERT_EQ(track->stepCount(), 3000U);
  EXPECT_TRUE(sameBits(track->omega[2999], run.omega[2999]));
  ASSERT_TRUE(db_->runs().exportRun(outcome.runId, dir_ / "alpha.csv").ok());
  EXPECT_EQ(test::readBytes(dir_ / "alpha.csv"), formatRunCsv(run));
  const IntegrityReport check = db_->check();
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems[0]);
  EXPECT_EQ(check.steps, 3000);
  EXPECT_EQ(check.runs, 1);
}

TEST_P(BackendTest, AnInMemoryRunOfManyBlocksPassesTheCheckAndIsStoredOnce) {
  // importRun's blocks, row and block checksums are made beside the writer; `db check` verifies
  // every one. The same run again, under another name, is found once its steps are written and
  // rolled back.
  const RunData run = makeRun(40000, true, 12);
  const ImportOutcome outcome = db_->runs().importRun(run, "many");
  ASSERT_EQ(outcome.status, ImportStatus::Imported) << outcome.message;
  const ImportOutcome again = db_->runs().importRun(run, "many-again");
  EXPECT_EQ(again.status, ImportStatus::Skipped) << again.message;
  EXPECT_EQ(again.runId, outcome.runId);
  EXPECT_EQ(db_->runs().list()->size(), 1U);
  const IntegrityReport check = db_->check();
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems[0]);
  EXPECT_EQ(check.steps, 40000);
  auto loaded = db_->runs().load(outcome.runId);
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  test::expectSameRun(run, loaded.value());
}

TEST_P(BackendTest, TheSameFileTwiceIsStoredOnce) {
  const RunData run = makeRun(50, false, 3);
  const std::string text = formatRunCsv(run);
  EXPECT_EQ(db_->runs().importText(text, "a.csv").status, ImportStatus::Imported);
  const ImportOutcome again = db_->runs().importText(text, "b.csv");
  EXPECT_EQ(again.status, ImportStatus::Skipped) << again.message;
  EXPECT_EQ(db_->runs().list()->size(), 1U);
}

TEST_P(BackendTest, AFailedImportLeavesNothing) {
  ImportOptions options;
  options.failAfterSteps = 700;
  const ImportOutcome failed =
      db_->runs().importText(formatRunCsv(makeRun(1000, true, 4)), "cut.csv", options);
  EXPECT_EQ(failed.status, ImportStatus::Failed);
  EXPECT_TRUE(db_->runs().list()->empty());
  const IntegrityReport check = db_->check();
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems[0]);
  EXPECT_EQ(check.steps, 0);
}

TEST_P(BackendTest, ModelsAndSweepsKeepTheirText) {
  ASSERT_TRUE(db_->models().add("m1", R"({"a":1})", "{}", R"({"rate":0.5})").ok());
  EXPECT_FALSE(db_->models().add("m1", "{}", "{}", "{}").ok());
  EXPECT_EQ(db_->models().load("m1").value(), R"({"a":1})");
  auto sweep = db_->sweeps().create("s1", R"({"state":"running"})");
  ASSERT_TRUE(sweep.ok()) << sweep.errorText();
  ASSERT_TRUE(db_->sweeps().addCell(sweep.value(), R"({"order":2})", R"({"rate":0.9})").ok());
  auto cells = db_->sweeps().cells(sweep.value());
  ASSERT_TRUE(cells.ok());
  ASSERT_EQ(cells->size(), 1U);
  EXPECT_EQ(cells->front().metricsJson, R"({"rate":0.9})");
}

// Workers take the most expensive job first (a long fit left for the end keeps one worker busy
// alone while the others wait); jobs of equal cost go in grid order; a lease that ran out is
// taken over.
TEST_P(BackendTest, SweepJobsAreClaimedMostExpensiveFirst) {
  auto sweep = db_->sweeps().plan("s", "{}", {1, 1, 2, 1}, {5.0, 40.0, 5.0, 12.0});
  ASSERT_TRUE(sweep.ok()) << sweep.errorText();
  std::vector<std::int64_t> order;
  for (int i = 0; i < 4; ++i) {
    auto claim = db_->sweeps().claim(sweep.value(), "w", 100.0, 10.0);
    ASSERT_TRUE(claim.ok()) << claim.errorText();
    ASSERT_TRUE(claim.value().has_value());
    order.push_back(claim.value()->job);
  }
  EXPECT_EQ(order, (std::vector<std::int64_t>{1, 3, 0, 2}));
  auto none = db_->sweeps().claim(sweep.value(), "v", 105.0, 10.0);
  ASSERT_TRUE(none.ok()) << none.errorText();
  EXPECT_FALSE(none.value().has_value());
  // Past the leases, the most expensive running job is taken over first.
  auto takeOver = db_->sweeps().claim(sweep.value(), "v", 111.0, 10.0);
  ASSERT_TRUE(takeOver.ok()) << takeOver.errorText();
  ASSERT_TRUE(takeOver.value().has_value());
  EXPECT_EQ(takeOver.value()->job, 1);
  EXPECT_EQ(takeOver.value()->attempts, 2);
  EXPECT_FALSE(db_->sweeps().plan("t", "{}", {1, 1}, {1.0}).ok()) << "one cost per job";
}

TEST_P(BackendTest, RenameKeepsTheRowChecksumAndTheCatalogSortsByteWise) {
  ASSERT_EQ(db_->runs().importRun(makeRun(40, false, 5), "b_run").status, ImportStatus::Imported);
  ASSERT_EQ(db_->runs().importRun(makeRun(40, false, 6), "B_run").status, ImportStatus::Imported);
  ASSERT_EQ(db_->runs().importRun(makeRun(40, false, 7), "a_run").status, ImportStatus::Imported);
  ASSERT_TRUE(db_->runs().rename("a_run", "Z_run").ok());
  auto runs = db_->runs().list();
  ASSERT_TRUE(runs.ok());
  std::vector<std::string> names;
  for (const RunInfo& r : runs.value())
    names.push_back(r.name);
  EXPECT_EQ(names, (std::vector<std::string>{"B_run", "Z_run", "b_run"}));
  const IntegrityReport check = db_->check();
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems[0]);
}

TEST_P(BackendTest, DeletingARunTakesItsStepsSummariesAndLabelsWithIt) {
  const auto a = db_->runs().importRun(makeRun(500, true, 8), "a");
  const auto b = db_->runs().importRun(makeRun(300, true, 9), "b");
  ASSERT_TRUE(db_->labels().autolabel(a.runId, "truth").ok());
  ASSERT_TRUE(db_->runs().remove(a.runId).ok());
  ASSERT_TRUE(db_->runs().remove({"b"}).ok());
  const IntegrityReport check = db_->check();
  EXPECT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems[0]);
  EXPECT_EQ(check.runs, 0);
  EXPECT_EQ(check.steps, 0);
  auto sets = db_->labels().catalog();
  ASSERT_TRUE(sets.ok());
  ASSERT_EQ(sets->size(), 1U);
  EXPECT_TRUE(sets->front().runs.empty());
}

// A whole-run read that meets a damaged row part way through (on a server the rows are streamed)
// fails with the damage named, and the session goes on answering: the same read of another run,
// the run list, and on a server a write.
TEST_P(BackendTest, AReadStoppedByADamagedRowLeavesTheSessionUsable) {
  const auto bad = db_->runs().importRun(makeRun(5000, true, 21), "bad");
  const auto good = db_->runs().importRun(makeRun(4000, true, 22), "good");
  ASSERT_EQ(bad.status, ImportStatus::Imported);
  ASSERT_EQ(good.status, ImportStatus::Imported);
  const std::string damage =
      "UPDATE steps SET x = x + 1 WHERE run_id = " + std::to_string(bad.runId) + " AND step = 2500";
  if (GetParam() == Backend::Sqlite) {
    db_.reset();
    test::sqliteExec(address_, damage);
    // A damaged file is opened for reading only (docs/storage.md#checksums).
    auto reopened = RunDatabase::open(address_, OpenMode::ReadOnly);
    ASSERT_TRUE(reopened.ok()) << reopened.errorText();
    db_ = std::move(reopened.value());
  } else {
    test::serverExec(address_, damage);
  }
  for (int round = 0; round < 2; ++round) {
    auto track = db_->runs().loadTrack(bad.runId);
    ASSERT_FALSE(track.ok());
    EXPECT_NE(track.errorText().find("step 2500"), std::string::npos) << track.errorText();
    auto whole = db_->runs().load(bad.runId);
    ASSERT_FALSE(whole.ok());
    auto other = db_->runs().loadTrack(good.runId);
    ASSERT_TRUE(other.ok()) << other.errorText();
    EXPECT_EQ(other->stepCount(), 4000U);
    auto runs = db_->runs().list();
    ASSERT_TRUE(runs.ok()) << runs.errorText();
    EXPECT_EQ(runs->size(), 2U);
  }
  if (GetParam() == Backend::Postgres) {
    EXPECT_TRUE(db_->runs().rename("good", "still_good").ok());
  }
  const IntegrityReport check = db_->check();
  EXPECT_FALSE(check.ok);
}

INSTANTIATE_TEST_SUITE_P(Backends, BackendTest,
                         ::testing::Values(Backend::Sqlite, Backend::Postgres), test::backendName);

// ---- copies ------------------------------------------------------------------------------------

class CopyTest : public ::testing::TestWithParam<std::pair<Backend, Backend>> {
 protected:
  void SetUp() override {
    const auto [from, to] = GetParam();
    fromAddress_ = test::databaseAddress(from, dir_, "from.db");
    toAddress_ = test::databaseAddress(to, dir_, "to.db");
    if (fromAddress_.empty() || toAddress_.empty()) {
      GTEST_SKIP() << "no PostgreSQL test server (the tests start one in ctest)";
    }
    from_ = test::openDb(fromAddress_);
    to_ = test::openDb(toAddress_);
    ASSERT_NE(from_, nullptr);
    ASSERT_NE(to_, nullptr);
  }

  TempDir dir_;
  std::string fromAddress_, toAddress_;
  std::unique_ptr<RunDatabase> from_, to_;
};

TEST_P(CopyTest, RunsLabelsModelsAndSweepsArriveAndASecondCopyAddsNothing) {
  const RunData one = makeRun(2500, true, 21);
  const RunData two = makeRun(700, false, 22);
  const auto a = from_->runs().importRun(one, "one");
  const auto b = from_->runs().importRun(two, "two");
  ASSERT_EQ(a.status, ImportStatus::Imported);
  ASSERT_EQ(b.status, ImportStatus::Imported);
  ASSERT_TRUE(from_->labels().autolabel(a.runId, "truth").ok());
  auto set = from_->labels().create("mine", "ann");
  ASSERT_TRUE(set.ok());
  LabelSegment segment;
  segment.runId = b.runId;
  segment.group = SensorGroup::Right;
  segment.firstStep = 10;
  segment.lastStep = 90;
  segment.cls = ContactClass::Wall;
  segment.annotator = "ann";
  ASSERT_TRUE(from_->labels().addSegment(set.value(), segment).ok());
  ASSERT_TRUE(from_->models().add("model", R"({"m":1})", "{}", "{}").ok());
  auto sweep = from_->sweeps().create("sweep", "{}");
  ASSERT_TRUE(from_->sweeps().addCell(sweep.value(), "{}", R"({"r":1})").ok());

  auto report = to_->copyFrom(*from_);
  ASSERT_TRUE(report.ok()) << report.errorText();
  EXPECT_EQ(report->runsCopied, 2);
  EXPECT_EQ(report->stepsCopied, 3200);
  EXPECT_GT(report->segmentsCopied, 8);
  EXPECT_EQ(report->modelsCopied, 1);
  EXPECT_EQ(report->sweepsCopied, 1);

  // The copy exports byte for byte as the source does, labels included.
  for (const char* name : {"one", "two"}) {
    const auto source = from_->runs().find(name);
    const auto copied = to_->runs().find(name);
    ASSERT_TRUE(copied.ok()) << copied.errorText();
    EXPECT_EQ(copied->checksum, source->checksum);
    ASSERT_TRUE(from_->runs().exportRun(source->id, dir_ / "s.csv").ok());
    ASSERT_TRUE(to_->runs().exportRun(copied->id, dir_ / "c.csv").ok());
    EXPECT_EQ(test::readBytes(dir_ / "s.csv"), test::readBytes(dir_ / "c.csv")) << name;
  }
  for (const char* setName : {"truth", "mine"}) {
    ASSERT_TRUE(from_->labels().exportFile(setName, dir_ / "s.labels.csv").ok());
    ASSERT_TRUE(to_->labels().exportFile(setName, dir_ / "c.labels.csv").ok());
    EXPECT_EQ(test::readBytes(dir_ / "s.labels.csv"), test::readBytes(dir_ / "c.labels.csv"))
        << setName;
  }
  EXPECT_EQ(to_->models().load("model").value(), R"({"m":1})");
  EXPECT_TRUE(to_->check().ok);
  // The history travels with the labels: the same edits, annotators and times, in order.
  EXPECT_EQ(report->revisionsCopied, kGroupCount + 1);
  {
    const auto theirs = from_->labels().history(set.value(), b.runId).value();
    const auto copiedSet = to_->labels().find("mine");
    const auto ours = to_->labels().history(copiedSet->id, to_->runs().find("two")->id).value();
    ASSERT_EQ(ours.size(), theirs.size());
    ASSERT_EQ(ours.size(), 1U);
    EXPECT_EQ(ours[0].annotator, "ann");
    EXPECT_EQ(ours[0].time, theirs[0].time);
    EXPECT_EQ(ours[0].cls, ContactClass::Wall);
    EXPECT_EQ(ours[0].firstStep, 10);
  }

  auto again = to_->copyFrom(*from_);
  ASSERT_TRUE(again.ok()) << again.errorText();
  EXPECT_EQ(again->runsCopied, 0);
  EXPECT_EQ(again->runsPresent, 2);
  EXPECT_EQ(again->segmentsCopied, 0);
  EXPECT_EQ(again->revisionsCopied, 0);
  EXPECT_EQ(again->modelsCopied, 0);
  EXPECT_EQ(again->sweepsCopied, 0);
  EXPECT_EQ(to_->sweeps().list()->size(), 1U);
}

TEST_P(CopyTest, ARunOfTheSameNameWithOtherContentStopsTheCopy) {
  ASSERT_EQ(from_->runs().importRun(makeRun(30, false, 1), "same").status, ImportStatus::Imported);
  ASSERT_EQ(to_->runs().importRun(makeRun(30, false, 2), "same").status, ImportStatus::Imported);
  auto report = to_->copyFrom(*from_);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.errorText().find("other content"), std::string::npos) << report.errorText();
}

TEST_P(CopyTest, OnlyTheNamedRunsAndAnUnknownNameCopiesNothing) {
  ASSERT_EQ(from_->runs().importRun(makeRun(30, false, 1), "r1").status, ImportStatus::Imported);
  ASSERT_EQ(from_->runs().importRun(makeRun(30, false, 2), "r2").status, ImportStatus::Imported);
  CopyOptions options;
  options.runs = {"r2", "nope"};
  EXPECT_FALSE(to_->copyFrom(*from_, options).ok());
  EXPECT_TRUE(to_->runs().list()->empty());
  options.runs = {"r2"};
  auto report = to_->copyFrom(*from_, options);
  ASSERT_TRUE(report.ok()) << report.errorText();
  ASSERT_EQ(to_->runs().list()->size(), 1U);
  EXPECT_EQ(to_->runs().list()->front().name, "r2");
}

std::string copyName(const ::testing::TestParamInfo<std::pair<Backend, Backend>>& info) {
  const auto name = [](Backend b) { return b == Backend::Sqlite ? "Sqlite" : "Postgres"; };
  return std::string(name(info.param.first)) + "To" + name(info.param.second);
}

INSTANTIATE_TEST_SUITE_P(Backends, CopyTest,
                         ::testing::Values(std::pair{Backend::Sqlite, Backend::Postgres},
                                           std::pair{Backend::Postgres, Backend::Sqlite},
                                           std::pair{Backend::Postgres, Backend::Postgres}),
                         copyName);

// ---- the server's own cases -------------------------------------------------------------------

TEST(ServerDatabase, AnEmptyDatabaseIsOnlyMadeByACreatingOpen) {
  const std::string address = test::freshServerSchema();
  if (address.empty()) GTEST_SKIP() << "no PostgreSQL test server";
  auto refused = RunDatabase::open(address, OpenMode::ReadWrite);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.errorText().find("tactile db create"), std::string::npos)
      << refused.errorText();
  auto made = RunDatabase::open(address, OpenMode::Create);
  ASSERT_TRUE(made.ok()) << made.errorText();
  EXPECT_TRUE(made.value()->created());
  EXPECT_TRUE(made.value()->onServer());
  auto again = RunDatabase::open(address, OpenMode::Create);
  ASSERT_TRUE(again.ok());
  EXPECT_FALSE(again.value()->created());
}

TEST(ServerDatabase, ADatabaseOfAnotherApplicationIsRefusedAndLeftAlone) {
  const std::string address = test::freshServerSchema();
  if (address.empty()) GTEST_SKIP() << "no PostgreSQL test server";
  const std::string schema = address.substr(address.rfind("%3D") + 3);
  test::serverExec(test::testServerAddress(), "CREATE TABLE " + schema + ".invoices(id int)");
  auto refused = RunDatabase::open(address, OpenMode::Create);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.errorText().find("not a Tactile database"), std::string::npos)
      << refused.errorText();
}

TEST(ServerDatabase, AReadOnlyOpenCannotWrite) {
  const std::string address = test::freshServerSchema();
  if (address.empty()) GTEST_SKIP() << "no PostgreSQL test server";
  ASSERT_TRUE(RunDatabase::open(address, OpenMode::Create).ok());
  auto db = RunDatabase::open(address, OpenMode::ReadOnly);
  ASSERT_TRUE(db.ok()) << db.errorText();
  EXPECT_FALSE(db.value()->labels().create("x").ok());
  EXPECT_TRUE(db.value()->labels().list()->empty());
}

TEST(ServerDatabase, AWrongAddressSaysSoInOneLineWithoutThePassword) {
  const std::string server = test::testServerAddress();
  if (server.empty()) GTEST_SKIP() << "no PostgreSQL test server";
  const std::string host = server.substr(server.find("host="));
  auto missing =
      RunDatabase::open("postgresql://someone:s3cret@/no_such_db?" + host, OpenMode::ReadWrite);
  ASSERT_FALSE(missing.ok());
  const std::string text = missing.errorText();
  EXPECT_EQ(text.find("s3cret"), std::string::npos) << text;
  EXPECT_EQ(text.find('\n'), std::string::npos) << text;
  EXPECT_NE(text.find("***"), std::string::npos) << text;
}

TEST(ServerAddress, AddressesAndFilesAreTold) {
  EXPECT_TRUE(isServerAddress("postgresql://lab@db.example.org/corpus"));
  EXPECT_TRUE(isServerAddress("postgres:///corpus?host=/run/postgresql"));
  EXPECT_TRUE(isServerAddress("host=/run/postgresql dbname=corpus"));
  EXPECT_TRUE(isServerAddress("service=lab"));
  EXPECT_FALSE(isServerAddress("runs.db"));
  EXPECT_FALSE(isServerAddress("/data/a=b.db"));
  EXPECT_FALSE(isServerAddress("data/host=x.db"));
  EXPECT_EQ(shownAddress("postgresql://ann:pw@host:5432/db"), "postgresql://ann:***@host:5432/db");
  EXPECT_EQ(shownAddress("postgresql://ann@host/db?password=pw&sslmode=require"),
            "postgresql://ann@host/db?password=***&sslmode=require");
  EXPECT_EQ(shownAddress("host=h password='a b' dbname=d"), "host=h password=*** dbname=d");
  EXPECT_EQ(shownAddress("runs.db"), "runs.db");
}

}  // namespace
}  // namespace tactile::storage
