#include <gtest/gtest.h>

#include <fstream>

#include "run/label_file.h"
#include "run/run_csv.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;
using test::TempDir;

struct Range {
  std::int64_t first, last;
  ContactClass cls;
  bool operator==(const Range&) const = default;
};

class LabelsTest : public ::testing::TestWithParam<test::Backend> {
 protected:
  void SetUp() override {
    const std::string address = test::databaseAddress(GetParam(), dir_, "labels.db");
    if (address.empty()) GTEST_SKIP() << "no PostgreSQL test server (the tests start one in ctest)";
    db_ = test::openDb(address);
    ASSERT_NE(db_, nullptr);
    const auto a = db_->runs().importRun(makeRun(200, true, 1), "runA");
    const auto b = db_->runs().importRun(makeRun(100, false, 2), "runB");
    ASSERT_EQ(a.status, ImportStatus::Imported) << a.message;
    ASSERT_EQ(b.status, ImportStatus::Imported) << b.message;
    runA_ = a.runId;
    runB_ = b.runId;
    auto set = db_->labels().create("main", "alice");
    ASSERT_TRUE(set.ok()) << set.errorText();
    set_ = set.value();
  }

  std::int64_t add(std::int64_t first, std::int64_t last, ContactClass cls,
                   SensorGroup group = SensorGroup::Front, std::int64_t run = 0,
                   std::int64_t set = 0) {
    LabelSegment s;
    s.runId = run == 0 ? runA_ : run;
    s.group = group;
    s.firstStep = first;
    s.lastStep = last;
    s.cls = cls;
    auto id = db_->labels().addSegment(set == 0 ? set_ : set, s);
    EXPECT_TRUE(id.ok()) << id.errorText();
    return id.ok() ? id.value() : 0;
  }

  std::vector<Range> ranges(SensorGroup group = SensorGroup::Front, std::int64_t set = 0) {
    std::vector<Range> out;
    const auto all = db_->labels().segments(set == 0 ? set_ : set, runA_);
    for (const LabelSegment& s : all.value()) {
      if (s.group == group) out.push_back({s.firstStep, s.lastStep, s.cls});
    }
    return out;
  }

  TempDir dir_;
  std::unique_ptr<RunDatabase> db_;
  std::int64_t runA_ = 0;
  std::int64_t runB_ = 0;
  std::int64_t set_ = 0;
};

constexpr auto kWall = ContactClass::Wall;
constexpr auto kCorner = ContactClass::Corner;
constexpr auto kNone = ContactClass::NoContact;

TEST_P(LabelsTest, NewerSegmentInsideSplitsTheOlderOne) {
  add(10, 50, kWall);
  add(20, 30, kCorner);
  EXPECT_EQ(ranges(), (std::vector<Range>{{10, 19, kWall}, {20, 30, kCorner}, {31, 50, kWall}}));
}

TEST_P(LabelsTest, NewerSegmentTrimsOverlappedEnds) {
  add(10, 30, kWall);
  add(40, 60, kWall);
  add(25, 45, kCorner);
  EXPECT_EQ(ranges(), (std::vector<Range>{{10, 24, kWall}, {25, 45, kCorner}, {46, 60, kWall}}));
}

TEST_P(LabelsTest, NewerSegmentRemovesCoveredOnes) {
  add(10, 20, kWall);
  add(30, 40, kCorner);
  add(0, 199, kNone);
  EXPECT_EQ(ranges(), (std::vector<Range>{{0, 199, kNone}}));
}

TEST_P(LabelsTest, OtherGroupsRunsAndSetsAreUntouched) {
  add(0, 100, kWall, SensorGroup::Left);
  add(0, 50, kWall, SensorGroup::Front, runB_);
  auto other = db_->labels().create("other");
  ASSERT_TRUE(other.ok());
  add(0, 100, kWall, SensorGroup::Front, 0, other.value());
  add(0, 100, kCorner);
  EXPECT_EQ(ranges(SensorGroup::Left), (std::vector<Range>{{0, 100, kWall}}));
  EXPECT_EQ(ranges(SensorGroup::Front, other.value()), (std::vector<Range>{{0, 100, kWall}}));
  EXPECT_EQ(db_->labels().segments(set_, runB_)->size(), 1u);
}

TEST_P(LabelsTest, SegmentOutsideTheRunIsRejected) {
  LabelSegment s;
  s.runId = runA_;
  s.firstStep = 150;
  s.lastStep = 200;  // runA has steps 0..199
  EXPECT_FALSE(db_->labels().addSegment(set_, s).ok());
  s.firstStep = 20;
  s.lastStep = 10;
  EXPECT_FALSE(db_->labels().addSegment(set_, s).ok());
  EXPECT_TRUE(db_->labels().segments(set_)->empty());
}

TEST_P(LabelsTest, SegmentByRunName) {
  LabelSegment s;
  s.run = "runB";
  s.firstStep = 1;
  s.lastStep = 2;
  ASSERT_TRUE(db_->labels().addSegment(set_, s).ok());
  EXPECT_EQ(db_->labels().segments(set_, runB_)->at(0).run, "runB");
  s.run = "nope";
  EXPECT_FALSE(db_->labels().addSegment(set_, s).ok());
}

TEST_P(LabelsTest, ChangeKeepsTheIdAndWinsOverItsNewRange) {
  const std::int64_t a = add(0, 10, kWall);
  add(20, 30, kWall);
  LabelSegment changed;
  changed.group = SensorGroup::Front;
  changed.firstStep = 5;
  changed.lastStep = 25;
  changed.cls = kCorner;
  ASSERT_TRUE(db_->labels().changeSegment(a, changed).ok());
  EXPECT_EQ(ranges(), (std::vector<Range>{{5, 25, kCorner}, {26, 30, kWall}}));
  bool found = false;
  const auto all = db_->labels().segments(set_);
  for (const auto& s : all.value())
    found = found || (s.id == a && s.firstStep == 5);
  EXPECT_TRUE(found);
}

TEST_P(LabelsTest, RemoveSegment) {
  const std::int64_t a = add(0, 10, kWall);
  ASSERT_TRUE(db_->labels().removeSegment(a).ok());
  EXPECT_TRUE(ranges().empty());
  EXPECT_FALSE(db_->labels().removeSegment(a).ok());
}

TEST_P(LabelsTest, RenameCopyDelete) {
  add(0, 10, kWall);
  ASSERT_TRUE(db_->labels().rename("main", "renamed").ok());
  EXPECT_FALSE(db_->labels().find("main").ok());
  auto copy = db_->labels().copy(set_, "copy");
  ASSERT_TRUE(copy.ok()) << copy.errorText();
  EXPECT_EQ(ranges(SensorGroup::Front, copy.value()), ranges());
  add(5, 6, kCorner);  // editing the original leaves the copy alone
  EXPECT_EQ(ranges(SensorGroup::Front, copy.value()), (std::vector<Range>{{0, 10, kWall}}));
  EXPECT_FALSE(db_->labels().copy(set_, "copy").ok());  // name taken
  EXPECT_FALSE(db_->labels().rename("copy", "renamed").ok());
  ASSERT_TRUE(db_->labels().remove({"renamed"}).ok());
  auto sets = db_->labels().list();
  ASSERT_EQ(sets->size(), 1u);
  EXPECT_EQ(sets->at(0).name, "copy");
  EXPECT_EQ(sets->at(0).segmentCount, 1);
  EXPECT_FALSE(db_->labels().remove({"renamed"}).ok());
}

TEST_P(LabelsTest, DuplicateSetNameIsRejected) {
  EXPECT_FALSE(db_->labels().create("main").ok());
  EXPECT_FALSE(db_->labels().create("").ok());
}

TEST_P(LabelsTest, CsvAndJsonFilesRoundTrip) {
  add(0, 10, kWall);
  add(11, 20, kCorner, SensorGroup::RearRightCorner);
  add(3, 4, kWall, SensorGroup::Back, runB_);
  const auto original = db_->labels().segments(set_).value();
  for (const char* name : {"labels.csv", "labels.json"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(db_->labels().exportFile("main", dir_ / name).ok());
    const std::string target = std::string("from-") + name;
    auto count = db_->labels().importFile(target, dir_ / name);
    ASSERT_TRUE(count.ok()) << count.errorText();
    EXPECT_EQ(count.value(), 3);
    const auto imported = db_->labels().segments(db_->labels().find(target)->id).value();
    ASSERT_EQ(imported.size(), original.size());
    for (std::size_t i = 0; i < original.size(); ++i) {
      EXPECT_EQ(imported[i].run, original[i].run);
      EXPECT_EQ(imported[i].group, original[i].group);
      EXPECT_EQ(imported[i].firstStep, original[i].firstStep);
      EXPECT_EQ(imported[i].lastStep, original[i].lastStep);
      EXPECT_EQ(imported[i].cls, original[i].cls);
    }
  }
}

TEST_P(LabelsTest, BadLabelFileChangesNothingAndNamesTheLine) {
  std::ofstream(dir_ / "bad.csv") << "run,group,first_step,last_step,class\n"
                                     "runA,F,0,10,Wall\n"
                                     "runA,F,11,20,Wal\n";
  auto result = db_->labels().importFile("fresh", dir_ / "bad.csv");
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.errorText().find("bad.csv:3"), std::string::npos) << result.errorText();
  EXPECT_FALSE(db_->labels().find("fresh").ok());
}

TEST_P(LabelsTest, LabelFileWithUnknownRunChangesNothing) {
  std::ofstream(dir_ / "unknown.csv") << "run,group,first_step,last_step,class\n"
                                         "runA,F,0,10,Wall\n"
                                         "ghost,F,0,10,Wall\n";
  auto result = db_->labels().importFile("main", dir_ / "unknown.csv");
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.errorText().find("unknown.csv:3: no run named 'ghost'"), std::string::npos)
      << result.errorText();
  EXPECT_TRUE(db_->labels().segments(set_)->empty());
}

TEST_P(LabelsTest, LaterRowsOfALabelFileWin) {
  std::ofstream(dir_ / "order.csv") << "run,group,first_step,last_step,class,annotator\n"
                                       "runA,F,0,50,Wall,bob\n"
                                       "runA,front,10,20,Corner,carol\n";
  ASSERT_TRUE(db_->labels().importFile("main", dir_ / "order.csv").ok());
  EXPECT_EQ(ranges(), (std::vector<Range>{{0, 9, kWall}, {10, 20, kCorner}, {21, 50, kWall}}));
  EXPECT_EQ(db_->labels().segments(set_)->at(1).annotator, "carol");
}

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST_P(LabelsTest, ExportCarriesEachRunsStepsAndChecksum) {
  add(0, 10, kWall);
  add(3, 4, kWall, SensorGroup::Back, runB_);
  const std::string a = db_->runs().find("runA")->checksum;
  const std::string b = db_->runs().find("runB")->checksum;
  ASSERT_TRUE(db_->labels().exportFile("main", dir_ / "p.csv").ok());
  const std::string csv = readText(dir_ / "p.csv");
  EXPECT_EQ(csv.rfind("# run runA steps 200 checksum " + a + "\n# run runB steps 100 checksum " +
                          b + "\nrun,group,",
                      0),
            0u)
      << csv;
  ASSERT_TRUE(db_->labels().exportFile("main", dir_ / "p.json").ok());
  const auto json = parseLabelJson(readText(dir_ / "p.json"), "p.json");
  ASSERT_TRUE(json.ok()) << json.errorText();
  EXPECT_EQ(json->runs,
            (std::vector<LabelRunProvenance>{{"runA", 200, a, 0}, {"runB", 100, b, 0}}));
}

TEST_P(LabelsTest, LabelsForAnotherRunOfTheSameNameAreRefused) {
  add(0, 10, kWall);
  // The same set exported from a database whose runA is a different recording.
  TempDir other;
  auto elsewhere = test::openDb(other / "other.db");
  ASSERT_EQ(elsewhere->runs().importRun(makeRun(200, true, 99), "runA").status,
            ImportStatus::Imported);
  const std::string theirs = elsewhere->runs().find("runA")->checksum;
  const std::string ours = db_->runs().find("runA")->checksum;
  ASSERT_NE(theirs, ours);
  auto set = elsewhere->labels().create("theirs");
  LabelSegment s;
  s.run = "runA";
  s.firstStep = 0;
  s.lastStep = 50;
  ASSERT_TRUE(elsewhere->labels().addSegment(set.value(), s).ok());
  for (const char* name : {"theirs.csv", "theirs.json"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(elsewhere->labels().exportFile("theirs", other / name).ok());
    const auto result = db_->labels().importFile("main", other / name);
    ASSERT_FALSE(result.ok());
    const std::string text = result.errorText();
    EXPECT_NE(text.find((other / name).string()), std::string::npos) << text;
    EXPECT_NE(text.find("run 'runA'"), std::string::npos) << text;
    EXPECT_NE(text.find(theirs), std::string::npos) << text;
    EXPECT_NE(text.find(ours), std::string::npos) << text;
    EXPECT_EQ(ranges(), (std::vector<Range>{{0, 10, kWall}}));  // nothing changed
  }
}

TEST_P(LabelsTest, ProvenanceWithAnotherStepCountIsRefused) {
  const std::string checksum = db_->runs().find("runA")->checksum;
  std::ofstream(dir_ / "steps.csv") << "# run runA steps 199 checksum " << checksum
                                    << "\nrun,group,first_step,last_step,class\nrunA,F,0,10,Wall\n";
  const auto result = db_->labels().importFile("fresh", dir_ / "steps.csv");
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.errorText().find("steps.csv:1: run 'runA': the label file was made for 199 "
                                    "steps"),
            std::string::npos)
      << result.errorText();
  EXPECT_NE(result.errorText().find("has 200 steps"), std::string::npos) << result.errorText();
  EXPECT_FALSE(db_->labels().find("fresh").ok());
  // The matching provenance line is accepted.
  std::ofstream(dir_ / "good.csv") << "# run runA steps 200 checksum " << checksum
                                   << "\nrun,group,first_step,last_step,class\nrunA,F,0,10,Wall\n";
  EXPECT_TRUE(db_->labels().importFile("fresh", dir_ / "good.csv").ok());
}

TEST_P(LabelsTest, LabelFileSegmentPastTheLastStepIsRefused) {
  std::ofstream(dir_ / "past.csv") << "run,group,first_step,last_step,class\n"
                                      "runB,F,0,10,Wall\n"
                                      "runB,F,90,100,Wall\n";
  const auto result = db_->labels().importFile("fresh", dir_ / "past.csv");
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.errorText().find("past.csv:3: segment 90..100 is not within the run's steps "
                                    "0..99"),
            std::string::npos)
      << result.errorText();
  EXPECT_FALSE(db_->labels().find("fresh").ok());
}

TEST_P(LabelsTest, AutolabelReproducesTheTruthExactly) {
  auto count = db_->labels().autolabel(runA_, "truth");
  ASSERT_TRUE(count.ok()) << count.errorText();
  const RunData run = makeRun(200, true, 1);
  const auto segments = db_->labels().segments(db_->labels().find("truth")->id, runA_).value();
  EXPECT_EQ(static_cast<std::int64_t>(segments.size()), count.value());
  std::vector<int> covered(200 * kGroupCount, 0);
  bool sawNoContact = false;
  for (const LabelSegment& s : segments) {
    sawNoContact = sawNoContact || s.cls == kNone;
    for (std::int64_t step = s.firstStep; step <= s.lastStep; ++step) {
      ASSERT_EQ(run.truthAt(step, s.group), s.cls);
      ++covered[step * kGroupCount + groupIndex(s.group)];
    }
  }
  EXPECT_TRUE(sawNoContact);
  EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }));
  // Autolabelling again replaces rather than duplicates.
  ASSERT_TRUE(db_->labels().autolabel(runA_, "truth").ok());
  EXPECT_EQ(db_->labels().segments(db_->labels().find("truth")->id, runA_)->size(),
            segments.size());
}

TEST_P(LabelsTest, AutolabelWithoutTruthFails) {
  auto count = db_->labels().autolabel(runB_, "truth");
  ASSERT_FALSE(count.ok());
  EXPECT_NE(count.errorText().find("no truth"), std::string::npos);
}

TEST(LabelFiles, BomAndCrlfAreAccepted) {
  auto parsed = parseLabelCsv(
      "\xEF\xBB\xBFrun,group,first_step,last_step,class\r\nr,FLC,1,2,DeadPath\r\n", "l.csv");
  ASSERT_TRUE(parsed.ok()) << parsed.errorText();
  ASSERT_EQ(parsed->records.size(), 1u);
  EXPECT_EQ(parsed->records[0].group, SensorGroup::FrontLeftCorner);
  EXPECT_EQ(parsed->records[0].cls, ContactClass::DeadPath);
}

TEST(LabelFiles, EmptyLineIsAnError) {
  auto parsed = parseLabelCsv("run,group,first_step,last_step,class\n\nr,F,1,2,Wall\n", "l.csv");
  EXPECT_EQ(parsed.errorText().rfind("l.csv:2:", 0), 0u) << parsed.errorText();
}

TEST(LabelFiles, WrongHeaderIsAnError) {
  auto parsed = parseLabelCsv("run,grp,first_step,last_step,class\n", "l.csv");
  EXPECT_EQ(parsed.errorText().rfind("l.csv:1:", 0), 0u) << parsed.errorText();
}

TEST(LabelFiles, EmptyFileIsAnError) {
  EXPECT_FALSE(parseLabelCsv("", "e.csv").ok());
}

TEST(LabelFiles, JsonWithBadFieldNamesTheSegment) {
  auto parsed = parseLabelJson(
      R"({"format":"tactile-labels","version":1,"segments":[{"run":"r","group":"F","first_step":0,"last_step":1,"class":"Wall"},{"run":"r","group":"F","first_step":"x","last_step":1,"class":"Wall"}]})",
      "l.json");
  EXPECT_NE(parsed.errorText().find("segment 2"), std::string::npos) << parsed.errorText();
  EXPECT_FALSE(parsed.ok());
}

INSTANTIATE_TEST_SUITE_P(Backends, LabelsTest,
                         ::testing::Values(test::Backend::Sqlite, test::Backend::Postgres),
                         test::backendName);

}  // namespace
}  // namespace tactile::storage
