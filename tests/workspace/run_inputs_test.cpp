// Expanding what the user names for import: files pass as given, a folder becomes its .csv files
// sorted by name (not those of sub-folders, not other extensions), an empty folder is a warning;
// and the import that `tactile import` and the workbench share (importRunInputs).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "run/run_csv.h"
#include "tests/analysis/learn_test_data.h"
#include "tests/storage/storage_test_util.h"
#include "workspace/run_inputs.h"

namespace tactile::workspace {
namespace {

namespace fs = std::filesystem;
using storage::test::TempDir;

void touch(const fs::path& p) {
  std::ofstream(p) << "x\n";
}

TEST(RunInputs, FolderBecomesItsCsvFilesSortedFilesPassAsGiven) {
  TempDir dir;
  const fs::path folder = dir / "runs";
  fs::create_directories(folder / "nested");
  touch(folder / "b.csv");
  touch(folder / "a.csv");
  touch(folder / "notes.txt");
  touch(folder / "nested" / "c.csv");
  const fs::path loose = dir / "loose.txt";  // a named file passes whatever its extension
  touch(loose);

  auto expanded = expandRunInputs({loose, folder});
  ASSERT_TRUE(expanded.ok()) << expanded.errorText();
  ASSERT_EQ(expanded->files.size(), 3u);
  EXPECT_EQ(expanded->files[0], loose);
  EXPECT_EQ(expanded->files[1], folder / "a.csv");
  EXPECT_EQ(expanded->files[2], folder / "b.csv");
  EXPECT_TRUE(expanded->warnings.empty());
}

TEST(RunInputs, EmptyFolderIsAWarningAndMissingFilesPassOn) {
  TempDir dir;
  fs::create_directories(dir / "empty");
  auto expanded = expandRunInputs({dir / "empty", dir / "absent.csv"});
  ASSERT_TRUE(expanded.ok());
  ASSERT_EQ(expanded->files.size(), 1u);  // the import reports the missing file itself
  EXPECT_EQ(expanded->files[0], dir / "absent.csv");
  ASSERT_EQ(expanded->warnings.size(), 1u);
  EXPECT_NE(expanded->warnings[0].find("no .csv files"), std::string::npos);
  EXPECT_NE(expanded->warnings[0].find("empty"), std::string::npos);
}

TEST(ImportRunInputs, ImportsAFoldersFilesInOrderWithTheFolderWarnings) {
  TempDir dir;
  fs::create_directories(dir / "runs");
  fs::create_directories(dir / "empty");
  ASSERT_TRUE(writeRunCsv(testdata::makeLabelledRun(40, 1), dir / "runs" / "b.csv").ok());
  ASSERT_TRUE(writeRunCsv(testdata::makeLabelledRun(30, 2), dir / "runs" / "a.csv").ok());
  auto db = storage::RunDatabase::open(dir / "w.db", storage::OpenMode::Create);
  ASSERT_TRUE(db.ok()) << db.errorText();
  storage::ImportOptions options;
  options.namePrefix = "p";
  std::size_t calls = 0;
  auto imported = importRunInputs(*db.value(), {dir / "runs", dir / "empty"}, options,
                                  [&](std::size_t, std::size_t) { return ++calls > 0; });
  ASSERT_TRUE(imported.ok()) << imported.errorText();
  ASSERT_EQ(imported->outcomes.size(), 2u);
  EXPECT_EQ(imported->outcomes[0].runName, "p_a");
  EXPECT_EQ(imported->outcomes[0].steps, 30);
  EXPECT_EQ(imported->outcomes[1].runName, "p_b");
  EXPECT_EQ(imported->outcomes[1].status, storage::ImportStatus::Imported);
  ASSERT_EQ(imported->warnings.size(), 1u);
  EXPECT_NE(imported->warnings[0].find("empty"), std::string::npos);
  EXPECT_GE(calls, 1u);
}

}  // namespace
}  // namespace tactile::workspace
