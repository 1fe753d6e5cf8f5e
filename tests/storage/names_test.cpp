// The one name rule (base/text_rules.h) at the database boundary: every stored name of a run,
// label set, model, sweep or annotator follows it, whoever calls (CLI, workbench, workspace).
// Regression: import names, label sets, models and sweeps took commas, line breaks and bytes that
// are not UTF-8, which later broke list options, label files and every --json writer.
#include <gtest/gtest.h>

#include "base/text_rules.h"
#include "run/run_csv.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;
using test::TempDir;

const std::vector<std::string>& badNames() {
  static const std::vector<std::string> names = {
      "a,b", "a\nb", "tab\there", "caf\xE9", std::string(201, 'n'), "", "c1\xC2\x85"};
  return names;
}

TEST(NameRuleInStorage, RunsImportedUnderABadNameAreRefused) {
  auto db = test::openDb(":memory:");
  const RunData run = makeRun(20, true);
  for (const std::string& name : badNames()) {
    const ImportOutcome outcome = db->runs().importRun(run, name, "f.csv");
    EXPECT_EQ(outcome.status, ImportStatus::Failed) << name;
    if (!name.empty()) {
      EXPECT_NE(outcome.message.find("run name"), std::string::npos) << outcome.message;
    }
  }
  EXPECT_TRUE(db->runs().list()->empty());
  EXPECT_EQ(db->runs().importRun(run, "Müller 1", "f.csv").status, ImportStatus::Imported);
}

TEST(NameRuleInStorage, FileStemsBecomeValidNamesOrFailThatFileOnly) {
  TempDir dir;
  std::filesystem::create_directories(dir / "dir,x");
  ASSERT_TRUE(writeRunCsv(makeRun(20, true, 1), dir / "dir,x/run,one.csv").ok());
  ASSERT_TRUE(writeRunCsv(makeRun(21, true, 2), dir / "dir,x/line\nbreak.csv").ok());
  ASSERT_TRUE(writeRunCsv(makeRun(22, true, 3), dir / "dir,x/caf\xE9.csv").ok());
  auto db = test::openDb(dir / "n.db");
  const auto outcomes = db->runs().importFiles(
      {dir / "dir,x/run,one.csv", dir / "dir,x/line\nbreak.csv", dir / "dir,x/caf\xE9.csv"}, {});
  ASSERT_EQ(outcomes.size(), 3u);
  EXPECT_EQ(outcomes[0].status, ImportStatus::Imported) << outcomes[0].message;
  EXPECT_EQ(outcomes[0].runName, "run_one");
  EXPECT_EQ(outcomes[1].status, ImportStatus::Imported) << outcomes[1].message;
  EXPECT_EQ(outcomes[1].runName, "line_break");
  EXPECT_EQ(outcomes[2].status, ImportStatus::Failed);
  EXPECT_NE(outcomes[2].message.find("not valid UTF-8"), std::string::npos) << outcomes[2].message;
  EXPECT_NE(outcomes[2].message.find("--name"), std::string::npos) << outcomes[2].message;
  // A prefix joins the cleaned stem; a bad prefix makes a bad name.
  ImportOptions prefixed;
  prefixed.namePrefix = "p";
  ASSERT_TRUE(writeRunCsv(makeRun(23, true, 4), dir / "x,y.csv").ok());
  EXPECT_EQ(db->runs().importFiles({dir / "x,y.csv"}, prefixed)[0].runName, "p_x_y");
  prefixed.namePrefix = "p\r";
  ASSERT_TRUE(writeRunCsv(makeRun(24, true, 5), dir / "z.csv").ok());
  EXPECT_EQ(db->runs().importFiles({dir / "z.csv"}, prefixed)[0].status, ImportStatus::Failed);
}

TEST(NameRuleInStorage, LabelSetsModelsSweepsAndAnnotatorsAreChecked) {
  auto db = test::openDb(":memory:");
  ASSERT_EQ(db->runs().importRun(makeRun(30, true), "r", "r.csv").status, ImportStatus::Imported);
  auto set = db->labels().create("good", "ann");
  ASSERT_TRUE(set.ok()) << set.errorText();
  for (const std::string& name : badNames()) {
    SCOPED_TRACE(shownText(name));
    EXPECT_FALSE(db->labels().create(name, "").ok());
    EXPECT_FALSE(db->labels().rename("good", name).ok());
    EXPECT_FALSE(db->runs().rename("r", name).ok());
    EXPECT_FALSE(db->models().add(name, "{}", "{}", "{}").ok());
    EXPECT_FALSE(db->sweeps().create(name, "{}").ok());
    if (!name.empty()) {
      EXPECT_FALSE(db->labels().create("other", name).ok());
      LabelSegment s;
      s.run = "r";
      s.firstStep = 0;
      s.lastStep = 3;
      s.cls = ContactClass::Wall;
      s.annotator = name;
      EXPECT_FALSE(db->labels().addSegment(set.value(), s).ok());
    }
  }
  EXPECT_EQ(db->labels().list()->size(), 1u);
  EXPECT_EQ(db->runs().find("r")->name, "r");
  EXPECT_TRUE(db->models().add("m ok", "{}", "{}", "{}").ok());
}

}  // namespace
}  // namespace tactile::storage
