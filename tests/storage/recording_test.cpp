// Runs stored while they are recorded (beginRun, appendSteps, finishRun): readable after every
// append, equal to the same run imported whole once finished.
#include <gtest/gtest.h>

#include "run/run_csv.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;

RunData headerOf(const RunData& run) {
  RunData header;
  header.metadata = run.metadata;
  header.setMeta("outcome", "unknown");
  return header;
}

void expectSameSummary(RunDatabase& db, std::int64_t a, std::int64_t b, std::int64_t first,
                       std::int64_t last, int buckets) {
  auto sa = db.runs().loadSummary(a, first, last, buckets);
  auto sb = db.runs().loadSummary(b, first, last, buckets);
  ASSERT_TRUE(sa.ok()) << sa.errorText();
  ASSERT_TRUE(sb.ok()) << sb.errorText();
  ASSERT_EQ(sa->buckets.size(), sb->buckets.size());
  EXPECT_EQ(sa->blockSteps, sb->blockSteps);
  for (std::size_t i = 0; i < sa->buckets.size(); ++i) {
    EXPECT_EQ(sa->buckets[i].firstStep, sb->buckets[i].firstStep);
    EXPECT_EQ(sa->buckets[i].lastStep, sb->buckets[i].lastStep);
    EXPECT_EQ(sa->buckets[i].min, sb->buckets[i].min) << "bucket " << i;
    EXPECT_EQ(sa->buckets[i].max, sb->buckets[i].max) << "bucket " << i;
  }
}

TEST(Recording, AppendedInUnevenChunksEqualsTheRunImportedWhole) {
  auto db = test::openDb(":memory:");
  ASSERT_NE(db, nullptr);
  RunData run = makeRun(3000, true, 11);
  const ImportOutcome whole = db->runs().importRun(run, "whole");
  ASSERT_EQ(whole.status, ImportStatus::Imported) << whole.message;

  Result<std::int64_t> id = db->runs().beginRun("live", headerOf(run), true);
  ASSERT_TRUE(id.ok()) << id.errorText();
  // Chunk ends that fall inside and on summary blocks of every level (16, 128, 1024, 8192).
  std::size_t stored = 0;
  for (std::size_t end : {1u, 5u, 16u, 17u, 300u, 1024u, 1030u, 2999u, 3000u}) {
    RunData sofar = run.clone();
    sofar.x.resize(end);
    sofar.y.resize(end);
    sofar.theta.resize(end);
    sofar.v.resize(end);
    sofar.omega.resize(end);
    sofar.blocked.resize(end);
    sofar.sensors.resize(end * kValuesPerStep);
    sofar.truth.resize(end * kGroupCount);
    ASSERT_TRUE(db->runs().appendSteps(id.value(), sofar, stored).ok());
    stored = end;
    // Readable at once: the info, a window, and summaries of any width.
    auto info = db->runs().info(id.value());
    ASSERT_TRUE(info.ok());
    EXPECT_EQ(info->stepCount, static_cast<std::int64_t>(end));
    EXPECT_EQ(info->outcome, "unknown");
    auto loaded = db->runs().load(id.value());
    ASSERT_TRUE(loaded.ok()) << loaded.errorText();
    ASSERT_EQ(loaded->stepCount(), end);
    EXPECT_TRUE(test::bitEqual(loaded->sensors, sofar.sensors));
    for (int buckets : {1, 7, 100, 5000}) {
      auto summary = db->runs().loadSummary(id.value(), 0, -1, buckets);
      ASSERT_TRUE(summary.ok()) << summary.errorText() << " at " << end << " steps";
      ASSERT_FALSE(summary->buckets.empty());
      EXPECT_EQ(summary->buckets.back().lastStep, static_cast<std::int64_t>(end) - 1);
    }
  }
  ASSERT_TRUE(db->runs().finishRun(id.value(), run).ok());

  auto a = db->runs().load(id.value());
  auto b = db->runs().load(whole.runId);
  ASSERT_TRUE(a.ok() && b.ok());
  test::expectSameRun(a.value(), b.value());
  auto ia = db->runs().info(id.value());
  auto ib = db->runs().info(whole.runId);
  EXPECT_EQ(ia->checksum, ib->checksum);
  EXPECT_EQ(ia->outcome, "success");
  EXPECT_EQ(ia->subject, "sim");
  for (int buckets : {1, 3, 50, 400, 3000}) {
    expectSameSummary(*db, id.value(), whole.runId, 0, -1, buckets);
    expectSameSummary(*db, id.value(), whole.runId, 17, 2500, buckets);
  }
  EXPECT_TRUE(db->check().ok);
}

TEST(Recording, FinishReplacesTruthThatChangedAndAppendsTheRest) {
  auto db = test::openDb(":memory:");
  RunData run = makeRun(100, true, 3);
  Result<std::int64_t> id = db->runs().beginRun("r", headerOf(run), true);
  ASSERT_TRUE(id.ok());
  ASSERT_TRUE(db->runs().appendSteps(id.value(), run, 0).ok());
  // The final truth differs (smoothed at the end of a run), and 20 steps come only with finish.
  RunData final = makeRun(120, true, 3);
  for (std::size_t i = 0; i < 100 * kGroupCount; i += 3)
    final.truth[i] = ContactClass::Corner;
  // (makeRun draws step by step, so the first 100 steps of `final` equal `run` but for truth.)
  ASSERT_TRUE(db->runs().finishRun(id.value(), final).ok());
  auto loaded = db->runs().load(id.value());
  ASSERT_TRUE(loaded.ok());
  ASSERT_EQ(loaded->stepCount(), 120u);
  EXPECT_EQ(loaded->truth, final.truth);
}

TEST(Recording, RefusesAppendsThatDoNotContinueTheStoredSteps) {
  auto db = test::openDb(":memory:");
  RunData run = makeRun(40, true, 5);
  Result<std::int64_t> id = db->runs().beginRun("r", headerOf(run), true);
  ASSERT_TRUE(id.ok());
  ASSERT_TRUE(db->runs().appendSteps(id.value(), run, 0).ok());
  const Status again = db->runs().appendSteps(id.value(), run, 10);
  ASSERT_FALSE(again.ok());
  EXPECT_NE(again.errorText().find("40 steps stored"), std::string::npos) << again.errorText();
  RunData noTruth = makeRun(50, false, 5);
  EXPECT_FALSE(db->runs().appendSteps(id.value(), noTruth, 40).ok());
  EXPECT_EQ(db->runs().info(id.value())->stepCount, 40);
  // A taken name and a name with a comma are refused.
  EXPECT_FALSE(db->runs().beginRun("r", headerOf(run), true).ok());
  EXPECT_FALSE(db->runs().beginRun("a,b", headerOf(run), true).ok());
  // A begun run without steps is listed and reads as empty.
  Result<std::int64_t> empty = db->runs().beginRun("empty", headerOf(run), true);
  ASSERT_TRUE(empty.ok());
  auto loaded = db->runs().load(empty.value());
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  EXPECT_EQ(loaded->stepCount(), 0u);
}

}  // namespace
}  // namespace tactile::storage
