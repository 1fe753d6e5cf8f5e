#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <fstream>

#include "base/file_text.h"
#include "run/run_csv.h"
#include "storage/sqlite/sqlite_connection.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;
using test::TempDir;

std::int64_t countRows(const std::filesystem::path& db, const std::string& table) {
  db::Connection c = db::Connection::open(db, false, true);
  return c.queryInt("SELECT count(*) FROM " + table);
}

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(Import, FileRoundTripsBitForBitAndExportsIdenticalText) {
  TempDir dir;
  const RunData original = makeRun(500, true);
  ASSERT_TRUE(writeRunCsv(original, dir / "r1.csv").ok());
  auto db = test::openDb(dir / "runs.db");
  ASSERT_NE(db, nullptr);
  auto outcomes = db->runs().importFiles({dir / "r1.csv"});
  ASSERT_EQ(outcomes.size(), 1u);
  ASSERT_EQ(outcomes[0].status, ImportStatus::Imported) << outcomes[0].message;
  EXPECT_EQ(outcomes[0].runName, "r1");
  EXPECT_EQ(outcomes[0].steps, 500);

  auto loaded = db->runs().load(outcomes[0].runId);
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  test::expectSameRun(original, loaded.value());
  EXPECT_TRUE(std::signbit(loaded->y[0]));  // -0.0 keeps its sign

  ASSERT_TRUE(db->runs().exportRun(outcomes[0].runId, dir / "out.csv").ok());
  const Result<std::string> exported = readFileText(dir / "out.csv");
  const Result<std::string> source = readFileText(dir / "r1.csv");
  ASSERT_TRUE(exported.ok() && source.ok());
  EXPECT_EQ(exported.value(), source.value());

  auto info = db->runs().find("r1");
  ASSERT_TRUE(info.ok());
  EXPECT_EQ(info->stepCount, 500);
  EXPECT_TRUE(info->hasTruth);
  EXPECT_EQ(info->outcome, "success");
  EXPECT_EQ(info->subject, "sim");
  ASSERT_TRUE(info->dtSeconds.has_value());
  EXPECT_DOUBLE_EQ(*info->dtSeconds, 0.1);
}

TEST(Import, ExtraColumnsAndNoTruthRoundTrip) {
  RunData original = makeRun(40, false, 3);
  original.extraColumns = {"x_note", "x_empty"};
  for (std::size_t i = 0; i < original.stepCount(); ++i) {
    original.extraValues.push_back("n" + std::to_string(i));
    original.extraValues.push_back("");
  }
  auto db = test::openDb(":memory:");
  ASSERT_NE(db, nullptr);
  const auto outcome = db->runs().importText(formatRunCsv(original), "extra.csv");
  ASSERT_EQ(outcome.status, ImportStatus::Imported) << outcome.message;
  auto loaded = db->runs().load(outcome.runId);
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  test::expectSameRun(original, loaded.value());
  EXPECT_FALSE(loaded->hasTruth());
}

TEST(Import, BadFileStoresNothingAndNamesTheLine) {
  TempDir dir;
  std::string text = formatRunCsv(makeRun(30, true));
  // Break a sensor value on the 20th line.
  std::size_t pos = 0;
  for (int i = 1; i < 20; ++i)
    pos = text.find('\n', pos) + 1;
  text.replace(text.find(',', pos), 1, ",abc,");
  writeText(dir / "bad.csv", text);
  auto db = test::openDb(dir / "runs.db");
  ASSERT_NE(db, nullptr);
  auto outcomes = db->runs().importFiles({dir / "bad.csv"});
  ASSERT_EQ(outcomes[0].status, ImportStatus::Failed);
  EXPECT_NE(outcomes[0].message.find("bad.csv:20"), std::string::npos) << outcomes[0].message;
  db.reset();
  EXPECT_EQ(countRows(dir / "runs.db", "runs"), 0);
  EXPECT_EQ(countRows(dir / "runs.db", "steps"), 0);
}

TEST(Import, MissingFileIsReported) {
  TempDir dir;
  auto db = test::openDb(":memory:");
  auto outcomes = db->runs().importFiles({dir / "absent.csv"});
  ASSERT_EQ(outcomes[0].status, ImportStatus::Failed);
  EXPECT_NE(outcomes[0].message.find("absent.csv"), std::string::npos);
}

TEST(Import, SameChecksumIsSkippedWithAMessage) {
  TempDir dir;
  ASSERT_TRUE(writeRunCsv(makeRun(20, true), dir / "a.csv").ok());
  std::filesystem::copy_file(dir / "a.csv", dir / "copy-of-a.csv");
  auto db = test::openDb(dir / "runs.db");
  auto first = db->runs().importFiles({dir / "a.csv"});
  ASSERT_EQ(first[0].status, ImportStatus::Imported);
  auto again = db->runs().importFiles({dir / "a.csv", dir / "copy-of-a.csv"});
  for (const auto& outcome : again) {
    EXPECT_EQ(outcome.status, ImportStatus::Skipped);
    EXPECT_EQ(outcome.runId, first[0].runId);
    EXPECT_NE(outcome.message.find("already imported as run 'a'"), std::string::npos)
        << outcome.message;
  }
  EXPECT_EQ(db->runs().list()->size(), 1u);
}

TEST(Import, ExistingNameWithOtherContentFails) {
  auto db = test::openDb(":memory:");
  ASSERT_EQ(db->runs().importText(formatRunCsv(makeRun(5, true, 1)), "dir1/run.csv").status,
            ImportStatus::Imported);
  const auto clash = db->runs().importText(formatRunCsv(makeRun(5, true, 2)), "dir2/run.csv");
  EXPECT_EQ(clash.status, ImportStatus::Failed);
  EXPECT_NE(clash.message.find("already exists"), std::string::npos) << clash.message;
  ImportOptions renamed;
  renamed.name = "run-2";
  EXPECT_EQ(
      db->runs().importText(formatRunCsv(makeRun(5, true, 2)), "dir2/run.csv", renamed).status,
      ImportStatus::Imported);
}

TEST(Import, ManyFilesInParallelKeepInputOrder) {
  TempDir dir;
  std::vector<std::filesystem::path> files;
  for (int i = 0; i < 7; ++i) {
    const auto path = dir / ("run" + std::to_string(i) + ".csv");
    if (i == 3) {
      writeText(path, "# format: tactile-run 1\nstep,x\n");
    } else {
      ASSERT_TRUE(writeRunCsv(makeRun(100 + i, i % 2 == 0, 10 + i), path).ok());
    }
    files.push_back(path);
  }
  auto db = test::openDb(dir / "runs.db");
  ImportOptions options;
  options.threads = 3;
  std::size_t lastDone = 0;
  auto outcomes = db->runs().importFiles(files, options, [&](std::size_t done, std::size_t total) {
    EXPECT_EQ(total, files.size());
    EXPECT_EQ(done, lastDone + 1);
    lastDone = done;
    return true;
  });
  ASSERT_EQ(outcomes.size(), files.size());
  for (int i = 0; i < 7; ++i) {
    EXPECT_EQ(outcomes[i].file, files[i].string());
    EXPECT_EQ(outcomes[i].status, i == 3 ? ImportStatus::Failed : ImportStatus::Imported)
        << outcomes[i].message;
    if (i != 3) {
      EXPECT_EQ(outcomes[i].steps, 100 + i);
    }
  }
  EXPECT_EQ(db->runs().list()->size(), 6u);
  auto run5 = db->runs().find("run5");
  ASSERT_TRUE(run5.ok());
  auto loaded = db->runs().load(run5->id);
  ASSERT_TRUE(loaded.ok());
  test::expectSameRun(makeRun(105, false, 15), loaded.value());
}

// Files cut into many small chunks: a bad row late in a file (after chunks of it were written)
// stores nothing of it and gives the reader's own message; every other file is stored whole; a
// repeated file is skipped; the result does not depend on the thread count.
TEST(Import, ChunkedFilesAreAllOrNothingWithTheReadersMessage) {
  TempDir dir;
  std::vector<std::filesystem::path> files;
  std::vector<std::string> texts;
  for (int i = 0; i < 6; ++i) {
    RunData run = makeRun(i == 2 ? 3000 : 200 + 50 * i, i % 2 == 0, 30 + i);
    if (i == 4) {
      run.extraColumns = {"x_note"};
      for (std::size_t k = 0; k < run.stepCount(); ++k)
        run.extraValues.push_back("k" + std::to_string(k));
    }
    std::string text = formatRunCsv(run);
    if (i == 1) {
      // Break the second-to-last row.
      const std::size_t last = text.rfind('\n', text.size() - 2);
      const std::size_t before = text.rfind('\n', last - 1);
      text.replace(before + 1, 3, "zz,");
    }
    files.push_back(dir / ("f" + std::to_string(i) + ".csv"));
    writeText(files.back(), text);
    texts.push_back(text);
  }
  files.push_back(files[0]);  // the same file again
  const RunCsvResult expectedError = parseRunCsv(texts[1], files[1].string());
  ASSERT_FALSE(expectedError.ok());
  for (unsigned threads : {1u, 2u, 3u}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    auto db = test::openDb(dir / ("t" + std::to_string(threads) + ".db"));
    ImportOptions options;
    options.threads = threads;
    options.chunkBytes = 1500;  // two or three rows a chunk
    const auto outcomes = db->runs().importFiles(files, options);
    ASSERT_EQ(outcomes.size(), files.size());
    EXPECT_EQ(outcomes[1].status, ImportStatus::Failed);
    EXPECT_EQ(outcomes[1].message, expectedError.errorText());
    EXPECT_EQ(outcomes[6].status, ImportStatus::Skipped) << outcomes[6].message;
    EXPECT_EQ(outcomes[6].runId, outcomes[0].runId);
    EXPECT_FALSE(db->runs().find("f1").ok());
    for (int i : {0, 2, 3, 4, 5}) {
      ASSERT_EQ(outcomes[i].status, ImportStatus::Imported) << outcomes[i].message;
      RunCsvResult parsed = parseRunCsv(texts[i], "x.csv");
      ASSERT_TRUE(parsed.ok());
      EXPECT_EQ(outcomes[i].steps, static_cast<std::int64_t>(parsed.value().stepCount()));
      auto loaded = db->runs().load(outcomes[i].runId);
      ASSERT_TRUE(loaded.ok()) << loaded.errorText();
      EXPECT_TRUE(loaded.value() == parsed.value()) << "file " << i;
      auto info = db->runs().info(outcomes[i].runId);
      ASSERT_TRUE(info.ok());
      EXPECT_EQ(info->stepCount, outcomes[i].steps);
      // Summary blocks assembled from the chunks are exact: with ~20-step buckets the summary
      // comes from the 16-step blocks, each compared with the steps it covers.
      const RunData& steps = parsed.value();
      auto summary = db->runs().loadSummary(outcomes[i].runId, 0, -1,
                                            static_cast<int>(steps.stepCount() / 20));
      ASSERT_TRUE(summary.ok()) << summary.errorText();
      EXPECT_EQ(summary->blockSteps, 16);
      for (const SummaryBucket& bucket : summary->buckets) {
        for (int k = 0; k < kValuesPerStep; ++k) {
          double lo = steps.sensors[bucket.firstStep * kValuesPerStep + k];
          double hi = lo;
          for (std::int64_t step = bucket.firstStep; step <= bucket.lastStep; ++step) {
            lo = std::min(lo, steps.sensors[step * kValuesPerStep + k]);
            hi = std::max(hi, steps.sensors[step * kValuesPerStep + k]);
          }
          ASSERT_EQ(bucket.min[k], lo) << "file " << i << " step " << bucket.firstStep;
          ASSERT_EQ(bucket.max[k], hi) << "file " << i << " step " << bucket.firstStep;
        }
      }
    }
    // Importing the same files again reads them but stores nothing new.
    const auto again = db->runs().importFiles(files, options);
    for (int i : {0, 2, 3, 4, 5}) {
      EXPECT_EQ(again[i].status, ImportStatus::Skipped);
      EXPECT_EQ(again[i].steps, outcomes[i].steps);
    }
    EXPECT_EQ(again[1].message, expectedError.errorText());
    EXPECT_EQ(db->check().steps, 200 + 3000 + 350 + 400 + 450);
  }
}

TEST(Import, CancelStopsAfterTheFileBeingWritten) {
  TempDir dir;
  std::vector<std::filesystem::path> files;
  for (int i = 0; i < 5; ++i) {
    files.push_back(dir / ("c" + std::to_string(i) + ".csv"));
    ASSERT_TRUE(writeRunCsv(makeRun(10, false, 100 + i), files.back()).ok());
  }
  auto db = test::openDb(":memory:");
  ImportOptions options;
  options.threads = 2;
  auto outcomes = db->runs().importFiles(files, options,
                                         [](std::size_t done, std::size_t) { return done < 2; });
  ASSERT_EQ(outcomes.size(), 5u);
  EXPECT_EQ(outcomes[1].status, ImportStatus::Imported);
  EXPECT_EQ(outcomes[2].status, ImportStatus::Failed);
  EXPECT_NE(outcomes[4].message.find("cancelled"), std::string::npos);
  EXPECT_EQ(db->runs().list()->size(), 2u);
}

TEST(Import, FailureMidRunRollsBackEverything) {
  TempDir dir;
  auto db = test::openDb(dir / "runs.db");
  ImportOptions failing;
  failing.failAfterSteps = 150;
  const std::string text = formatRunCsv(makeRun(300, true));
  const auto outcome = db->runs().importText(text, "half.csv", failing);
  EXPECT_EQ(outcome.status, ImportStatus::Failed);
  EXPECT_NE(outcome.message.find("injected failure"), std::string::npos);
  for (const char* table : {"runs", "steps", "step_blocks", "scenes"}) {
    db::Connection c = db::Connection::open(dir / "runs.db", false, true);
    EXPECT_EQ(c.queryInt(std::string("SELECT count(*) FROM ") + table), 0) << table;
  }
  // The same file then imports normally (no stale statement or transaction state).
  EXPECT_EQ(db->runs().importText(text, "half.csv").status, ImportStatus::Imported);
}

TEST(Import, BuiltinSceneIsStoredOnce) {
  auto db = test::openDb(":memory:");
  const auto a = db->runs().importText(formatRunCsv(makeRun(5, false, 1)), "a.csv");
  const auto b = db->runs().importText(formatRunCsv(makeRun(5, false, 2)), "b.csv");
  ASSERT_EQ(a.status, ImportStatus::Imported);
  ASSERT_EQ(b.status, ImportStatus::Imported);
  EXPECT_TRUE(a.warnings.empty());
  auto json = db->runs().sceneJson(a.runId);
  ASSERT_TRUE(json.ok());
  ASSERT_TRUE(json->has_value());
  EXPECT_NE(json->value().find("\"practice\""), std::string::npos);
  EXPECT_EQ(db->runs().sceneJson(b.runId).value(), json.value());
  EXPECT_TRUE(db->runs().find("a")->sceneStored);
}

TEST(Import, SceneFileBesideTheRunFile) {
  TempDir dir;
  const std::string sceneText =
      R"({"name":"corridor","bounds":[0,0,10,10],"obstacles":[],"start":{"x":1,"y":1,"theta":0},"goal":{"x":9,"y":9}})";
  writeText(dir / "corridor.json", sceneText);
  RunData run = makeRun(8, false);
  run.setMeta("scene", "corridor.json");
  ASSERT_TRUE(writeRunCsv(run, dir / "c.csv").ok());
  auto db = test::openDb(":memory:");
  auto outcomes = db->runs().importFiles({dir / "c.csv"});
  ASSERT_EQ(outcomes[0].status, ImportStatus::Imported) << outcomes[0].message;
  EXPECT_TRUE(outcomes[0].warnings.empty());
  EXPECT_EQ(db->runs().sceneJson(outcomes[0].runId).value(), sceneText);
}

// Regression: the `scene` value was read as any path (absolute, `..`, /dev/zero, a FIFO). Only a
// plain regular file in the run file's own folder is read; anything else is a warning and the run
// is stored without its scene, at once (a FIFO does not hang, a device is not read).
TEST(Import, SceneValueIsNeverAPathOutsideTheRunFilesFolder) {
  TempDir dir;
  const std::string sceneText =
      R"({"name":"corridor","bounds":[0,0,10,10],"obstacles":[],"start":{"x":1,"y":1,"theta":0},"goal":{"x":9,"y":9}})";
  std::filesystem::create_directories(dir / "runs" / "sub");
  writeText(dir / "outside.json", sceneText);
  writeText(dir / "runs" / "sub" / "inner.json", sceneText);
  ASSERT_EQ(::mkfifo((dir / "runs" / "pipe.json").c_str(), 0600), 0);
  std::filesystem::create_symlink(dir / "outside.json", dir / "runs" / "link.json");
  {
    // Larger than the cap (sparse: no disk used).
    std::ofstream big(dir / "runs" / "big.json");
    big << "{";
  }
  std::filesystem::resize_file(dir / "runs" / "big.json", (std::uint64_t{16} << 20) + 1);
  const std::vector<std::pair<std::string, std::string>> refused = {
      {(dir / "outside.json").string(), "folder part"},
      {"../outside.json", "folder part"},
      {"sub/inner.json", "folder part"},
      {"/dev/zero", "folder part"},
      {"..", "folder part"},
      {"pipe.json", "not a regular file"},
      {"link.json", "symbolic link"},
      {"big.json", "more than the"},
      {"absent.json", "No such file"},
  };
  auto db = test::openDb(":memory:");
  for (std::size_t i = 0; i < refused.size(); ++i) {
    RunData run = makeRun(8, false, static_cast<unsigned>(100 + i));
    run.setMeta("scene", refused[i].first);
    const auto file = dir / "runs" / ("r" + std::to_string(i) + ".csv");
    ASSERT_TRUE(writeRunCsv(run, file).ok());
    const auto outcomes = db->runs().importFiles({file});
    ASSERT_EQ(outcomes[0].status, ImportStatus::Imported) << outcomes[0].message;
    ASSERT_EQ(outcomes[0].warnings.size(), 1u) << refused[i].first;
    EXPECT_NE(outcomes[0].warnings[0].find(refused[i].second), std::string::npos)
        << outcomes[0].warnings[0];
    EXPECT_FALSE(db->runs().sceneJson(outcomes[0].runId)->has_value()) << refused[i].first;
  }
  // The same file beside the run is read.
  writeText(dir / "runs" / "beside.json", sceneText);
  RunData run = makeRun(8, false, 99);
  run.setMeta("scene", "beside.json");
  ASSERT_TRUE(writeRunCsv(run, dir / "runs" / "ok.csv").ok());
  const auto ok = db->runs().importFiles({dir / "runs" / "ok.csv"});
  ASSERT_EQ(ok[0].status, ImportStatus::Imported) << ok[0].message;
  EXPECT_TRUE(ok[0].warnings.empty());
  EXPECT_EQ(db->runs().sceneJson(ok[0].runId).value(), sceneText);
}

TEST(Import, UnresolvableSceneIsAWarningNotAFailure) {
  RunData run = makeRun(8, false);
  run.setMeta("scene", "no-such-scene");
  auto db = test::openDb(":memory:");
  const auto outcome = db->runs().importText(formatRunCsv(run), "/tmp/x/lost.csv");
  ASSERT_EQ(outcome.status, ImportStatus::Imported) << outcome.message;
  ASSERT_EQ(outcome.warnings.size(), 1u);
  EXPECT_NE(outcome.warnings[0].find("no-such-scene"), std::string::npos);
  EXPECT_FALSE(db->runs().sceneJson(outcome.runId)->has_value());
  EXPECT_EQ(db->runs().find("lost")->scene, "no-such-scene");
}

// The caller's resolver supplies scenes storage cannot (procedural ones); it is not asked for
// built-in names, and declining falls back to the file path (here: a warning).
TEST(Import, SceneResolverSuppliesScenesStorageCannotResolve) {
  std::vector<std::string> asked;
  ImportOptions options;
  options.sceneResolver = [&](const std::string& scene) -> std::optional<std::string> {
    asked.push_back(scene);
    if (scene != "random:5:1") return std::nullopt;
    return std::string(R"({"name": "generated", "obstacles": []})");
  };
  auto db = test::openDb(":memory:");
  RunData run = makeRun(8, false, 1);
  run.setMeta("scene", "random:5:1");
  const auto generated = db->runs().importText(formatRunCsv(run), "/tmp/x/gen.csv", options);
  ASSERT_EQ(generated.status, ImportStatus::Imported) << generated.message;
  EXPECT_TRUE(generated.warnings.empty());
  auto json = db->runs().sceneJson(generated.runId);
  ASSERT_TRUE(json.ok() && json->has_value());
  EXPECT_NE(json->value().find("generated"), std::string::npos);

  run = makeRun(8, false, 2);
  run.setMeta("scene", "random:6:1");
  const auto declined = db->runs().importText(formatRunCsv(run), "/tmp/x/declined.csv", options);
  ASSERT_EQ(declined.status, ImportStatus::Imported) << declined.message;
  EXPECT_EQ(declined.warnings.size(), 1u);
  EXPECT_FALSE(db->runs().sceneJson(declined.runId)->has_value());

  run = makeRun(8, false, 3);  // scene "practice", a built-in
  const auto builtin = db->runs().importText(formatRunCsv(run), "/tmp/x/builtin.csv", options);
  ASSERT_EQ(builtin.status, ImportStatus::Imported) << builtin.message;
  EXPECT_TRUE(db->runs().sceneJson(builtin.runId)->has_value());
  EXPECT_EQ(asked, (std::vector<std::string>{"random:5:1", "random:6:1"}));
}

TEST(Import, RecordedRunThenItsExportedFileIsADuplicate) {
  TempDir dir;
  auto db = test::openDb(":memory:");
  const RunData run = makeRun(12, true);
  const auto stored = db->runs().importRun(run, "recorded");
  ASSERT_EQ(stored.status, ImportStatus::Imported) << stored.message;
  ASSERT_TRUE(db->runs().exportRun(stored.runId, dir / "recorded.csv").ok());
  auto again = db->runs().importFiles({dir / "recorded.csv"});
  EXPECT_EQ(again[0].status, ImportStatus::Skipped);
}

// The runs row's file checksum and row checksum, and the step and block rows' checksums, of the
// one run in `db`.
std::string storedRunDigest(const std::filesystem::path& db) {
  db::Connection c = db::Connection::open(db, false, true);
  std::string digest;
  db::Statement run(c, "SELECT checksum, step_count, crc FROM runs");
  while (run.step())
    digest += run.columnText(0) + " " + std::to_string(run.columnInt(1)) + " " +
              std::to_string(run.columnInt(2)) + "\n";
  for (const char* sql : {"SELECT step, crc, length(sensors) FROM steps ORDER BY step",
                          "SELECT level * 1000000 + block, crc, length(minmax) FROM step_blocks "
                          "ORDER BY level, block"}) {
    db::Statement rows(c, sql);
    while (rows.step())
      digest += std::to_string(rows.columnInt(0)) + " " + std::to_string(rows.columnInt(1)) + " " +
                std::to_string(rows.columnInt(2)) + "\n";
  }
  return digest;
}

TEST(Import, InMemoryRunStoredInBlocksIsTheRunItsFileStores) {
  // Several of importRun's blocks (encoded beside the writer), truth and x_ columns: the same
  // rows, checksums and file checksum as the run file's import.
  TempDir dir;
  RunData run = makeRun(40000, true, 3);
  run.extraColumns = {"x_note"};
  for (std::size_t k = 0; k < run.stepCount(); ++k)
    run.extraValues.push_back(k % 3 == 0 ? "" : "n" + std::to_string(k));
  const std::string text = formatRunCsv(run);
  {
    auto db = test::openDb(dir / "memory.db");
    const auto outcome = db->runs().importRun(run, "run");
    ASSERT_EQ(outcome.status, ImportStatus::Imported) << outcome.message;
    EXPECT_EQ(outcome.steps, 40000);
    auto info = db->runs().find("run");
    ASSERT_TRUE(info.ok());
    EXPECT_EQ(info->checksum, checksumHex(text));
  }
  {
    auto db = test::openDb(dir / "file.db");
    ImportOptions options;
    options.name = "run";
    ASSERT_EQ(db->runs().importText(text, "run.csv", options).status, ImportStatus::Imported);
  }
  const std::string digest = storedRunDigest(dir / "memory.db");
  EXPECT_GT(std::count(digest.begin(), digest.end(), '\n'), 1 + 40000);  // and blocks
  EXPECT_EQ(digest, storedRunDigest(dir / "file.db"));
}

TEST(Import, InMemoryRunAlreadyStoredIsSkippedUnderAnyName) {
  // The checksum is taken beside the writer: a run of the same content is found under its own
  // name (before writing) and under another (after writing, then rolled back).
  TempDir dir;
  auto db = test::openDb(dir / "runs.db");
  const RunData run = makeRun(20000, false, 4);
  const auto first = db->runs().importRun(run, "a");
  ASSERT_EQ(first.status, ImportStatus::Imported) << first.message;
  for (const char* name : {"a", "b"}) {
    const auto again = db->runs().importRun(run, name);
    EXPECT_EQ(again.status, ImportStatus::Skipped) << name << ": " << again.message;
    EXPECT_EQ(again.runId, first.runId);
    EXPECT_NE(again.message.find("already imported as run 'a'"), std::string::npos)
        << again.message;
  }
  // Other content under a taken name is refused as before.
  const auto clash = db->runs().importRun(makeRun(30, false, 5), "a");
  EXPECT_EQ(clash.status, ImportStatus::Failed);
  EXPECT_NE(clash.message.find("already exists"), std::string::npos) << clash.message;
  EXPECT_EQ(db->runs().list()->size(), 1u);
  EXPECT_EQ(countRows(dir / "runs.db", "steps"), 20000);
}

TEST(Import, NonFiniteInMemoryRunIsRejected) {
  auto db = test::openDb(":memory:");
  RunData run = makeRun(4, false);
  run.sensors[5] = std::nan("");
  const auto outcome = db->runs().importRun(run, "nan");
  EXPECT_EQ(outcome.status, ImportStatus::Failed);
  EXPECT_NE(outcome.message.find("not finite"), std::string::npos);
  EXPECT_TRUE(db->runs().list()->empty());
}

TEST(Import, InconsistentInMemoryRunIsRejected) {
  auto db = test::openDb(":memory:");
  RunData run = makeRun(4, false);
  run.sensors.pop_back();
  EXPECT_EQ(db->runs().importRun(run, "short").status, ImportStatus::Failed);
}

TEST(Import, DeleteRunRemovesItsRows) {
  TempDir dir;
  auto db = test::openDb(dir / "runs.db");
  const auto outcome = db->runs().importText(formatRunCsv(makeRun(50, true)), "d.csv");
  ASSERT_EQ(outcome.status, ImportStatus::Imported);
  auto set = db->labels().autolabel(outcome.runId, "auto");
  ASSERT_TRUE(set.ok());
  ASSERT_TRUE(db->runs().remove(outcome.runId).ok());
  for (const char* table : {"runs", "steps", "step_blocks", "label_segments"}) {
    db::Connection c = db::Connection::open(dir / "runs.db", false, true);
    EXPECT_EQ(c.queryInt(std::string("SELECT count(*) FROM ") + table), 0) << table;
  }
  EXPECT_FALSE(db->runs().remove(outcome.runId).ok());
}

TEST(Import, ChecksumDependsOnEveryByte) {
  const std::string a = "step,x\n0,1\n";
  std::string b = a;
  b[8] = '2';
  EXPECT_NE(checksumHex(a), checksumHex(b));
  EXPECT_EQ(checksumHex(a), checksumHex(std::string(a)));
  EXPECT_NE(checksumHex(""), checksumHex(std::string(1, '\0')));
  EXPECT_EQ(checksumHex(a).size(), 16u);
}

}  // namespace
}  // namespace tactile::storage
