// The command line's own logic, tested without running the program: which label run each run file
// gets (matchLabelRuns) and the option checks every verb shares.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli/cli_common.h"
#include "app/cli/cli_labels.h"
#include "base/file_text.h"
#include "storage/run_database.h"

namespace tactile::cli {
namespace {

namespace fs = std::filesystem;

RunData runOfSteps(std::size_t steps) {
  RunData run;
  run.reserve(steps, false);
  const std::array<double, kValuesPerStep> values{};
  for (std::size_t i = 0; i < steps; ++i)
    run.appendStep(static_cast<double>(i), 0.0, 0.0, 0.0, 0.0, false, values.data(), nullptr);
  return run;
}

// Run files that exist (the provenance check reads their bytes), each with its step count.
class MatchLabelRuns : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("tactile_cli_match_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "a");
    fs::create_directories(dir_ / "b");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Adds a run of `steps` steps read from `relative` (written with `bytes`).
  void add(const std::string& relative, std::size_t steps, const std::string& bytes) {
    const fs::path path = dir_ / relative;
    ASSERT_TRUE(writeFileAtomically(path, bytes));
    loaded_.runs.push_back(runOfSteps(steps));
    loaded_.paths.push_back(path.string());
  }
  static LabelRecord record(const std::string& run) {
    LabelRecord r;
    r.run = run;
    return r;
  }

  fs::path dir_;
  LoadedRuns loaded_;
};

TEST_F(MatchLabelRuns, ARunFileMatchesByPathFileNameOrStem) {
  add("a/one.csv", 3, "one");
  add("a/two.csv", 3, "two");
  add("a/three.csv", 3, "three");
  LabelFile file;
  file.records = {record((dir_ / "a/one.csv").string()), record("two.csv"), record("three")};
  const std::vector<std::string> names = matchLabelRuns(loaded_, "labels.csv", file);
  EXPECT_EQ(names, (std::vector<std::string>{(dir_ / "a/one.csv").string(), "two.csv", "three"}));
}

TEST_F(MatchLabelRuns, AFileThatNoLabelRunNamesGetsNothing) {
  add("a/one.csv", 3, "one");
  add("a/other.csv", 3, "other");
  LabelFile file;
  file.records = {record("one"), record("missing")};
  EXPECT_EQ(matchLabelRuns(loaded_, "labels.csv", file), (std::vector<std::string>{"one", ""}));
}

TEST_F(MatchLabelRuns, TwoFilesOfOneNameWithoutProvenanceAreAnError) {
  add("a/run.csv", 3, "first");
  add("b/run.csv", 3, "second");
  LabelFile file;
  file.records = {record("run")};
  try {
    matchLabelRuns(loaded_, "labels.csv", file);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("labels.csv: label run 'run' matches"), std::string::npos) << message;
    EXPECT_NE(message.find("provenance"), std::string::npos) << message;
  }
}

// The provenance's checksum tells two runs of one name apart.
TEST_F(MatchLabelRuns, ProvenancePicksTheFileWithItsStepsAndChecksum) {
  add("a/run.csv", 3, "first");
  add("b/run.csv", 3, "second");
  LabelFile file;
  file.records = {record("run")};
  file.runs = {{"run", 3, storage::checksumHex("second"), 1}};
  EXPECT_EQ(matchLabelRuns(loaded_, "labels.csv", file), (std::vector<std::string>{"", "run"}));
}

TEST_F(MatchLabelRuns, AFileOfTheRightNameButOtherContentIsAnError) {
  add("a/run.csv", 4, "changed");
  LabelFile file;
  file.records = {record("run")};
  file.runs = {{"run", 3, storage::checksumHex("original"), 2}};
  try {
    matchLabelRuns(loaded_, "labels.csv", file);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("labels.csv:2: label run 'run' was made for 3 steps"), std::string::npos)
        << message;
    EXPECT_NE(message.find("has 4 steps"), std::string::npos) << message;
  }
}

TEST_F(MatchLabelRuns, OneFileMatchingTwoLabelRunsIsAnError) {
  add("a/run.csv", 3, "run");
  LabelFile file;
  file.records = {record("run"), record("run.csv")};
  EXPECT_THROW(matchLabelRuns(loaded_, "labels.csv", file), std::runtime_error);
}

TEST(SplitNames, SplitsAtCommasAndKeepsOrder) {
  EXPECT_EQ(splitNames({"a,b", "c"}), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(splitNames({"F"}), (std::vector<std::string>{"F"}));
  EXPECT_TRUE(splitNames({}).empty());
}

TEST(CheckNumberOption, RefusesNaNInfinityAndOutOfRange) {
  EXPECT_NO_THROW(checkNumberOption("--holdout", 0.5, 0.0, RangeEnd::Open, 1.0, RangeEnd::Open));
  EXPECT_THROW(checkNumberOption("--holdout", 0.0, 0.0, RangeEnd::Open, 1.0, RangeEnd::Open),
               UsageError);
  EXPECT_NO_THROW(
      checkNumberOption("--holdout", 0.0, 0.0, RangeEnd::Closed, 1.0, RangeEnd::Closed));
  EXPECT_THROW(
      checkNumberOption("--holdout", std::nan(""), 0.0, RangeEnd::Closed, 1.0, RangeEnd::Closed),
      UsageError);
  EXPECT_THROW(checkNumberOption("--x", HUGE_VAL, 0.0, RangeEnd::Closed, HUGE_VAL, RangeEnd::Open),
               UsageError);
  try {
    checkNumberOption("--holdout", 2.0, 0.0, RangeEnd::Open, 1.0, RangeEnd::Open);
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--holdout"), std::string::npos) << e.what();
  }
}

TEST(RequireValidName, NamesTheOptionOfABadName) {
  EXPECT_NO_THROW(requireValidName("run_1", "--name", "run"));
  try {
    requireValidName("a,b", "--name", "run");
    ADD_FAILURE() << "no error";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--name", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace tactile::cli
