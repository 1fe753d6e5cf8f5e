#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "sim/run_csv.h"
#include "storage/run_codec.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;

class ReadTest : public ::testing::Test {
 protected:
  void SetUp() override {
    db_ = test::openDb(":memory:");
    ASSERT_NE(db_, nullptr);
    run_ = makeRun(20000, true, 5, 37);
    const auto outcome = db_->importRun(run_, "long");
    ASSERT_EQ(outcome.status, ImportStatus::Imported) << outcome.message;
    runId_ = outcome.runId;
  }

  // Brute-force min/max over steps [first, last].
  void expectBucket(const SummaryBucket& bucket) {
    for (int k = 0; k < kValuesPerStep; ++k) {
      double lo = run_.sensors[bucket.firstStep * kValuesPerStep + k];
      double hi = lo;
      for (std::int64_t s = bucket.firstStep; s <= bucket.lastStep; ++s) {
        lo = std::min(lo, run_.sensors[s * kValuesPerStep + k]);
        hi = std::max(hi, run_.sensors[s * kValuesPerStep + k]);
      }
      ASSERT_EQ(bucket.min[k], lo)
          << "value " << k << " steps " << bucket.firstStep << ".." << bucket.lastStep;
      ASSERT_EQ(bucket.max[k], hi) << "value " << k;
    }
  }

  void expectSummary(std::int64_t first, std::int64_t last, int buckets) {
    auto summary = db_->loadSummary(runId_, first, last, buckets);
    ASSERT_TRUE(summary.ok()) << summary.error();
    const std::int64_t clippedLast = last < 0 ? 19999 : std::min<std::int64_t>(last, 19999);
    ASSERT_FALSE(summary->buckets.empty());
    ASSERT_LE(summary->buckets.size(), static_cast<std::size_t>(buckets));
    EXPECT_EQ(summary->buckets.front().firstStep, first);
    EXPECT_EQ(summary->buckets.back().lastStep, clippedLast);
    const double ideal = double(clippedLast - first + 1) / buckets;
    for (std::size_t b = 0; b < summary->buckets.size(); ++b) {
      const SummaryBucket& bucket = summary->buckets[b];
      if (b > 0) {
        ASSERT_EQ(bucket.firstStep, summary->buckets[b - 1].lastStep + 1);
      }
      ASSERT_LE(bucket.firstStep, bucket.lastStep);
      // Bucket widths stay near the ideal width (one block either way).
      EXPECT_LE(bucket.lastStep - bucket.firstStep + 1,
                static_cast<std::int64_t>(ideal) + 1 + 2 * summary->blockSteps);
      expectBucket(bucket);
    }
  }

  std::unique_ptr<RunDatabase> db_;
  RunData run_;
  std::int64_t runId_ = 0;
};

TEST_F(ReadTest, WindowEqualsTheSliceOfTheRun) {
  auto window = db_->loadWindow(runId_, 1234, 500);
  ASSERT_TRUE(window.ok()) << window.error();
  EXPECT_EQ(window->firstStep, 1234);
  const RunData& w = window->data;
  ASSERT_EQ(w.stepCount(), 500u);
  EXPECT_EQ(w.metadata, run_.metadata);
  for (std::size_t i = 0; i < 500; ++i) {
    ASSERT_EQ(w.x[i], run_.x[1234 + i]);
    ASSERT_EQ(w.omega[i], run_.omega[1234 + i]);
    ASSERT_EQ(w.blocked[i], run_.blocked[1234 + i]);
    for (int k = 0; k < kValuesPerStep; ++k) {
      ASSERT_EQ(w.stepSensors(i)[k], run_.stepSensors(1234 + i)[k]);
    }
    for (const GroupInfo& g : kSensorGroups) {
      ASSERT_EQ(w.truthAt(i, g.group), run_.truthAt(1234 + i, g.group));
    }
  }
}

TEST_F(ReadTest, WindowIsClippedAtTheEnd) {
  auto window = db_->loadWindow(runId_, 19990, 100);
  ASSERT_TRUE(window.ok());
  EXPECT_EQ(window->data.stepCount(), 10u);
  EXPECT_EQ(window->data.x.back(), run_.x.back());
}

TEST_F(ReadTest, WindowBeyondTheEndIsEmpty) {
  auto window = db_->loadWindow(runId_, 50000, 100);
  ASSERT_TRUE(window.ok());
  EXPECT_EQ(window->data.stepCount(), 0u);
}

TEST_F(ReadTest, WindowOfUnknownRunFails) {
  EXPECT_FALSE(db_->loadWindow(999, 0, 10).ok());
}

TEST_F(ReadTest, WholeRunSummaryUsesBlocksAndIsExact) {
  auto summary = db_->loadSummary(runId_, 0, -1, 100);
  ASSERT_TRUE(summary.ok());
  EXPECT_GT(summary->blockSteps, 1);
  expectSummary(0, -1, 100);
}

TEST_F(ReadTest, NarrowRangeSummaryComesFromSteps) {
  auto summary = db_->loadSummary(runId_, 100, 180, 40);
  ASSERT_TRUE(summary.ok());
  EXPECT_EQ(summary->blockSteps, 1);
  expectSummary(100, 180, 40);
}

TEST_F(ReadTest, MoreBucketsThanStepsGivesOneStepEach) {
  auto summary = db_->loadSummary(runId_, 10, 14, 100);
  ASSERT_TRUE(summary.ok());
  ASSERT_EQ(summary->buckets.size(), 5u);
  for (std::size_t b = 0; b < 5; ++b)
    EXPECT_EQ(summary->buckets[b].firstStep, 10 + int(b));
  expectSummary(10, 14, 100);
}

TEST_F(ReadTest, RaggedRangesAtManyBucketCountsAreExact) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 25; ++trial) {
    const std::int64_t first = std::uniform_int_distribution<std::int64_t>(0, 15000)(rng);
    const std::int64_t last = std::uniform_int_distribution<std::int64_t>(first, 19999)(rng);
    const int buckets = std::uniform_int_distribution<int>(1, 300)(rng);
    SCOPED_TRACE(std::to_string(first) + ".." + std::to_string(last) + " / " +
                 std::to_string(buckets));
    expectSummary(first, last, buckets);
    if (HasFatalFailure()) return;
  }
}

TEST_F(ReadTest, SummaryNeedsABucket) {
  EXPECT_FALSE(db_->loadSummary(runId_, 0, -1, 0).ok());
}

TEST_F(ReadTest, SummaryOfEmptyRangeHasNoBuckets) {
  auto summary = db_->loadSummary(runId_, 30000, -1, 10);
  ASSERT_TRUE(summary.ok());
  EXPECT_TRUE(summary->buckets.empty());
}

TEST(RunCodec, TruthSegmentsAreMaximalAndCoverEveryStep) {
  const RunData run = makeRun(100, true, 1, 9);
  const auto segments = truthSegments(run);
  std::vector<int> covered(100 * kGroupCount, 0);
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const TruthSegment& s = segments[i];
    for (std::int64_t step = s.firstStep; step <= s.lastStep; ++step) {
      EXPECT_EQ(run.truthAt(step, s.group), s.cls);
      ++covered[step * kGroupCount + groupIndex(s.group)];
    }
    if (i > 0 && segments[i - 1].group == s.group) {
      EXPECT_NE(segments[i - 1].cls, s.cls);
    }
  }
  EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }));
}

TEST(RunCodec, NoTruthGivesNoSegments) {
  EXPECT_TRUE(truthSegments(makeRun(10, false)).empty());
}

TEST(RunCodec, ExtraValuesRoundTripAndRejectTruncation) {
  const std::vector<std::string> values{"a", "", std::string("x\0y", 3)};
  const std::string blob = encodeExtra(values.data(), values.size());
  std::vector<std::string> out;
  ASSERT_TRUE(decodeExtra(blob.data(), blob.size(), values.size(), out));
  EXPECT_EQ(out, values);
  out.clear();
  EXPECT_FALSE(decodeExtra(blob.data(), blob.size() - 1, values.size(), out));
}

}  // namespace
}  // namespace tactile::storage
