// The catalog (storage/catalog.cpp): runs and label sets listed, renamed and deleted by name, each
// change one transaction; import name prefixes and name clashes within one batch.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <map>
#include <tuple>

#include "run/run_csv.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;
using test::TempDir;

// A second, plain SQLite connection on the same file: counts rows and installs triggers that make
// a statement fail (failure injection).
class RawDb {
 public:
  explicit RawDb(const std::filesystem::path& path) {
    EXPECT_EQ(sqlite3_open(path.string().c_str(), &db_), SQLITE_OK);
    sqlite3_busy_timeout(db_, 5000);
  }
  ~RawDb() { sqlite3_close(db_); }
  std::int64_t count(const std::string& sql) {
    sqlite3_stmt* s = nullptr;
    EXPECT_EQ(sqlite3_prepare_v2(db_, sql.c_str(), -1, &s, nullptr), SQLITE_OK) << sql;
    std::int64_t n = -1;
    if (sqlite3_step(s) == SQLITE_ROW) n = sqlite3_column_int64(s, 0);
    sqlite3_finalize(s);
    return n;
  }
  void exec(const std::string& sql) {
    char* error = nullptr;
    EXPECT_EQ(sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error), SQLITE_OK)
        << (error ? error : "");
    sqlite3_free(error);
  }

 private:
  sqlite3* db_ = nullptr;
};

class CatalogTest : public ::testing::Test {
 protected:
  void SetUp() override {
    db_ = test::openDb(dir_ / "catalog.db");
    ASSERT_NE(db_, nullptr);
    for (const auto& [name, steps, seed] :
         {std::tuple{"runA", 200, 1}, std::tuple{"runB", 100, 2}, std::tuple{"runC", 50, 3}}) {
      const auto outcome = db_->runs().importRun(makeRun(steps, true, seed), name);
      ASSERT_EQ(outcome.status, ImportStatus::Imported) << outcome.message;
      ids_[name] = outcome.runId;
    }
    label("s1", "runA", 0, 10);
    label("s2", "runA", 5, 20);
    label("s2", "runB", 0, 99);
  }

  void label(const std::string& set, const std::string& run, std::int64_t first,
             std::int64_t last) {
    auto setInfo = db_->labels().find(set);
    std::int64_t setId = setInfo.ok() ? setInfo->id : 0;
    if (setId == 0) {
      auto created = db_->labels().create(set, "ann-" + set);
      ASSERT_TRUE(created.ok()) << created.errorText();
      setId = created.value();
    }
    LabelSegment s;
    s.run = run;
    s.firstStep = first;
    s.lastStep = last;
    s.cls = ContactClass::Wall;
    ASSERT_TRUE(db_->labels().addSegment(setId, s).ok());
  }

  // Rows of the run in every table that holds per-run rows.
  std::int64_t rowsOf(RawDb& raw, std::int64_t runId) {
    const std::string id = std::to_string(runId);
    return raw.count("SELECT count(*) FROM runs WHERE id = " + id) +
           raw.count("SELECT count(*) FROM steps WHERE run_id = " + id) +
           raw.count("SELECT count(*) FROM step_blocks WHERE run_id = " + id) +
           raw.count("SELECT count(*) FROM label_segments WHERE run_id = " + id);
  }

  TempDir dir_;
  std::unique_ptr<RunDatabase> db_;
  std::map<std::string, std::int64_t> ids_;
};

TEST_F(CatalogTest, RunsListedWithTheirLabelSets) {
  auto runs = db_->runs().catalog();
  ASSERT_TRUE(runs.ok()) << runs.errorText();
  ASSERT_EQ(runs->size(), 3u);
  EXPECT_EQ(runs->at(0).run.name, "runA");
  EXPECT_EQ(runs->at(0).run.stepCount, 200);
  EXPECT_EQ(runs->at(0).labelSets, (std::vector<std::string>{"s1", "s2"}));
  EXPECT_EQ(runs->at(1).run.name, "runB");
  EXPECT_EQ(runs->at(1).labelSets, (std::vector<std::string>{"s2"}));
  EXPECT_EQ(runs->at(2).run.name, "runC");
  EXPECT_TRUE(runs->at(2).labelSets.empty());
}

TEST_F(CatalogTest, LabelSetsListedWithTheRunsTheyCover) {
  auto sets = db_->labels().catalog();
  ASSERT_TRUE(sets.ok()) << sets.errorText();
  ASSERT_EQ(sets->size(), 2u);
  EXPECT_EQ(sets->at(0).set.name, "s1");
  EXPECT_EQ(sets->at(0).set.annotator, "ann-s1");
  EXPECT_EQ(sets->at(0).set.segmentCount, 1);
  EXPECT_EQ(sets->at(0).runs, (std::vector<std::string>{"runA"}));
  EXPECT_EQ(sets->at(1).set.segmentCount, 2);
  EXPECT_EQ(sets->at(1).runs, (std::vector<std::string>{"runA", "runB"}));
}

TEST_F(CatalogTest, RenameRunKeepsItsStepsAndLabels) {
  ASSERT_TRUE(db_->runs().rename("runA", "room1_runA").ok());
  EXPECT_FALSE(db_->runs().find("runA").ok());
  auto renamed = db_->runs().find("room1_runA");
  ASSERT_TRUE(renamed.ok());
  EXPECT_EQ(renamed->id, ids_["runA"]);
  EXPECT_EQ(renamed->stepCount, 200);
  EXPECT_EQ(db_->labels().catalog()->at(0).runs, (std::vector<std::string>{"room1_runA"}));
}

TEST_F(CatalogTest, RenameRunToATakenOrBadNameChangesNothing) {
  const auto taken = db_->runs().rename("runA", "runB");
  ASSERT_FALSE(taken.ok());
  EXPECT_NE(taken.errorText().find("'runB' already exists"), std::string::npos)
      << taken.errorText();
  EXPECT_EQ(taken.error().file, (dir_ / "catalog.db").string());
  const auto unknown = db_->runs().rename("ghost", "x");
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.errorText().find("no run named 'ghost'"), std::string::npos);
  EXPECT_FALSE(db_->runs().rename("runA", "a,b").ok());
  EXPECT_FALSE(db_->runs().rename("runA", "").ok());
  EXPECT_EQ(db_->runs().find("runA")->id, ids_["runA"]);
  EXPECT_EQ(db_->runs().find("runB")->id, ids_["runB"]);
}

TEST_F(CatalogTest, DeleteRunsCascadesToStepsSummariesAndLabels) {
  RawDb raw(dir_ / "catalog.db");
  ASSERT_GT(
      raw.count("SELECT count(*) FROM step_blocks WHERE run_id = " + std::to_string(ids_["runA"])),
      0);
  const std::int64_t keptRows = rowsOf(raw, ids_["runC"]);
  ASSERT_TRUE(db_->runs().remove({"runA", "runB"}).ok());
  EXPECT_EQ(rowsOf(raw, ids_["runA"]), 0);
  EXPECT_EQ(rowsOf(raw, ids_["runB"]), 0);
  EXPECT_EQ(rowsOf(raw, ids_["runC"]), keptRows);
  EXPECT_EQ(raw.count("SELECT count(*) FROM label_segments"), 0);
  // The sets stay (empty); the scene stays while runC uses it, and goes with the last run.
  EXPECT_EQ(db_->labels().catalog()->size(), 2u);
  EXPECT_EQ(raw.count("SELECT count(*) FROM scenes"), 1);
  ASSERT_TRUE(db_->runs().remove({"runC"}).ok());
  EXPECT_EQ(raw.count("SELECT count(*) FROM scenes"), 0);
  EXPECT_EQ(raw.count("SELECT count(*) FROM steps"), 0);
  EXPECT_TRUE(db_->check().ok);
}

TEST_F(CatalogTest, DeleteWithAnUnknownNameDeletesNothing) {
  const auto status = db_->runs().remove({"runA", "ghost", "runB"});
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.errorText().find("no run named 'ghost'; nothing deleted"), std::string::npos)
      << status.errorText();
  EXPECT_EQ(db_->runs().catalog()->size(), 3u);
  EXPECT_EQ(db_->runs().load(ids_["runA"])->stepCount(), 200u);
}

TEST_F(CatalogTest, FailureMidDeleteLeavesEverything) {
  RawDb raw(dir_ / "catalog.db");
  const std::int64_t rowsA = rowsOf(raw, ids_["runA"]);
  const std::int64_t rowsB = rowsOf(raw, ids_["runB"]);
  // runA is deleted completely, then deleting runB's row fails.
  raw.exec(
      "CREATE TRIGGER fail_on_b BEFORE DELETE ON runs WHEN old.name = 'runB' "
      "BEGIN SELECT RAISE(ABORT, 'injected failure'); END");
  const auto status = db_->runs().remove({"runA", "runB"});
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.errorText().find("injected failure"), std::string::npos) << status.errorText();
  EXPECT_EQ(rowsOf(raw, ids_["runA"]), rowsA);
  EXPECT_EQ(rowsOf(raw, ids_["runB"]), rowsB);
  EXPECT_EQ(db_->runs().catalog()->at(0).labelSets, (std::vector<std::string>{"s1", "s2"}));
  raw.exec("DROP TRIGGER fail_on_b");
  EXPECT_TRUE(db_->runs().remove({"runA", "runB"}).ok());
}

TEST_F(CatalogTest, RenameAndDeleteLabelSetsByName) {
  ASSERT_TRUE(db_->labels().rename("s1", "mine").ok());
  EXPECT_FALSE(db_->labels().find("s1").ok());
  EXPECT_EQ(db_->labels().find("mine")->segmentCount, 1);
  const auto taken = db_->labels().rename("mine", "s2");
  ASSERT_FALSE(taken.ok());
  EXPECT_NE(taken.errorText().find("'s2' already exists"), std::string::npos);
  EXPECT_FALSE(db_->labels().rename("ghost", "x").ok());

  const auto unknown = db_->labels().remove({"mine", "ghost"});
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.errorText().find("no label set named 'ghost'"), std::string::npos);
  EXPECT_TRUE(db_->labels().find("mine").ok());

  RawDb raw(dir_ / "catalog.db");
  raw.exec(
      "CREATE TRIGGER fail_on_s2 BEFORE DELETE ON label_sets WHEN old.name = 's2' "
      "BEGIN SELECT RAISE(ABORT, 'injected failure'); END");
  EXPECT_FALSE(db_->labels().remove({"mine", "s2"}).ok());
  EXPECT_EQ(raw.count("SELECT count(*) FROM label_segments"), 3);
  EXPECT_TRUE(db_->labels().find("mine").ok());
  raw.exec("DROP TRIGGER fail_on_s2");

  ASSERT_TRUE(db_->labels().remove({"mine", "s2"}).ok());
  EXPECT_TRUE(db_->labels().catalog()->empty());
  EXPECT_EQ(raw.count("SELECT count(*) FROM label_segments"), 0);
  EXPECT_TRUE(db_->runs().catalog()->at(0).labelSets.empty());
}

// ---- import names -----------------------------------------------------------------------------

TEST(CatalogImport, PrefixNamesRunsPrefixUnderscoreStem) {
  TempDir dir;
  std::filesystem::create_directories(dir / "room1");
  ASSERT_TRUE(writeRunCsv(makeRun(30, true, 1), dir / "room1/run_0000.csv").ok());
  auto db = test::openDb(dir / "p.db");
  ImportOptions options;
  options.namePrefix = "room1";
  const auto outcomes = db->runs().importFiles({dir / "room1/run_0000.csv"}, options);
  ASSERT_EQ(outcomes[0].status, ImportStatus::Imported) << outcomes[0].message;
  EXPECT_EQ(outcomes[0].runName, "room1_run_0000");
  EXPECT_TRUE(db->runs().find("room1_run_0000").ok());
}

TEST(CatalogImport, NameClashInOneBatchFailsThatFileOnlyAndNamesBothFiles) {
  TempDir dir;
  for (const char* folder : {"room1", "chapter5"})
    std::filesystem::create_directories(dir / folder);
  ASSERT_TRUE(writeRunCsv(makeRun(30, true, 1), dir / "room1/run_0000.csv").ok());
  ASSERT_TRUE(writeRunCsv(makeRun(40, true, 2), dir / "chapter5/run_0000.csv").ok());
  ASSERT_TRUE(writeRunCsv(makeRun(50, true, 3), dir / "chapter5/run_0001.csv").ok());
  auto db = test::openDb(dir / "c.db");
  const auto outcomes = db->runs().importFiles(
      {dir / "room1/run_0000.csv", dir / "chapter5/run_0000.csv", dir / "chapter5/run_0001.csv"});
  ASSERT_EQ(outcomes.size(), 3u);
  EXPECT_EQ(outcomes[0].status, ImportStatus::Imported);
  EXPECT_EQ(outcomes[1].status, ImportStatus::Failed);
  EXPECT_EQ(outcomes[2].status, ImportStatus::Imported) << outcomes[2].message;
  const std::string& message = outcomes[1].message;
  EXPECT_NE(message.find((dir / "chapter5/run_0000.csv").string()), std::string::npos) << message;
  EXPECT_NE(message.find((dir / "room1/run_0000.csv").string()), std::string::npos) << message;
  EXPECT_NE(message.find("--prefix"), std::string::npos) << message;
  EXPECT_EQ(db->runs().find("run_0000")->stepCount, 30);
}

}  // namespace
}  // namespace tactile::storage
