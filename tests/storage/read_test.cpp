#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include <sqlite3.h>

#include "run/run_csv.h"
#include "storage/run_codec.h"
#include "storage_test_util.h"

namespace tactile::storage {
namespace {

using test::makeRun;

class ReadTest : public ::testing::TestWithParam<test::Backend> {
 protected:
  void SetUp() override {
    const std::string address = test::databaseAddress(GetParam(), dir_, "read.db");
    if (address.empty()) GTEST_SKIP() << "no PostgreSQL test server (the tests start one in ctest)";
    db_ = test::openDb(address);
    ASSERT_NE(db_, nullptr);
    run_ = makeRun(20000, true, 5, 37);
    const auto outcome = db_->runs().importRun(run_, "long");
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
    auto summary = db_->runs().loadSummary(runId_, first, last, buckets);
    ASSERT_TRUE(summary.ok()) << summary.errorText();
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

  test::TempDir dir_;
  std::unique_ptr<RunDatabase> db_;
  RunData run_;
  std::int64_t runId_ = 0;
};

TEST_P(ReadTest, WindowEqualsTheSliceOfTheRun) {
  auto window = db_->runs().loadWindow(runId_, 1234, 500);
  ASSERT_TRUE(window.ok()) << window.errorText();
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

TEST_P(ReadTest, WindowIsClippedAtTheEnd) {
  auto window = db_->runs().loadWindow(runId_, 19990, 100);
  ASSERT_TRUE(window.ok());
  EXPECT_EQ(window->data.stepCount(), 10u);
  EXPECT_EQ(window->data.x.back(), run_.x.back());
}

TEST_P(ReadTest, WindowBeyondTheEndIsEmpty) {
  auto window = db_->runs().loadWindow(runId_, 50000, 100);
  ASSERT_TRUE(window.ok());
  EXPECT_EQ(window->data.stepCount(), 0u);
}

TEST_P(ReadTest, WindowOfUnknownRunFails) {
  EXPECT_FALSE(db_->runs().loadWindow(999, 0, 10).ok());
}

TEST_P(ReadTest, WholeRunSummaryUsesBlocksAndIsExact) {
  auto summary = db_->runs().loadSummary(runId_, 0, -1, 100);
  ASSERT_TRUE(summary.ok());
  EXPECT_GT(summary->blockSteps, 1);
  expectSummary(0, -1, 100);
}

TEST_P(ReadTest, NarrowRangeSummaryComesFromSteps) {
  auto summary = db_->runs().loadSummary(runId_, 100, 180, 40);
  ASSERT_TRUE(summary.ok());
  EXPECT_EQ(summary->blockSteps, 1);
  expectSummary(100, 180, 40);
}

TEST_P(ReadTest, MoreBucketsThanStepsGivesOneStepEach) {
  auto summary = db_->runs().loadSummary(runId_, 10, 14, 100);
  ASSERT_TRUE(summary.ok());
  ASSERT_EQ(summary->buckets.size(), 5u);
  for (std::size_t b = 0; b < 5; ++b)
    EXPECT_EQ(summary->buckets[b].firstStep, 10 + int(b));
  expectSummary(10, 14, 100);
}

TEST_P(ReadTest, RaggedRangesAtManyBucketCountsAreExact) {
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

TEST_P(ReadTest, SummaryNeedsABucket) {
  EXPECT_FALSE(db_->runs().loadSummary(runId_, 0, -1, 0).ok());
}

TEST_P(ReadTest, SummaryOfEmptyRangeHasNoBuckets) {
  auto summary = db_->runs().loadSummary(runId_, 30000, -1, 10);
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

// Summaries built from parts of any length (as the import's chunks are) equal the whole-run ones.
TEST(RunCodec, SummaryFromPartsEqualsTheWholeRun) {
  const RunData run = makeRun(20000, false, 8);
  const SummaryBlocks whole = computeSummaryBlocks(run.sensors.data(), run.stepCount());
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    SummaryBuilder builder;
    std::size_t at = 0;
    while (at < run.stepCount()) {
      const std::size_t n = std::min<std::size_t>(run.stepCount() - at, 1 + rng() % 3000);
      builder.merge(summarizeSteps(run.stepSensors(at), at, n));
      at += n;
    }
    EXPECT_EQ(std::move(builder).finish(), whole) << "trial " << trial;
  }
  SummaryBuilder gap;
  gap.merge(summarizeSteps(run.stepSensors(0), 0, 10));
  EXPECT_THROW(gap.merge(summarizeSteps(run.stepSensors(11), 11, 10)), std::logic_error);
}

TEST(RunCodec, PackedTruthRoundTripsAndRejectsBadCodes) {
  std::array<ContactClass, kGroupCount> classes{};
  std::array<ContactClass, kGroupCount> back{};
  for (int trial = 0; trial < 500; ++trial) {
    for (int g = 0; g < kGroupCount; ++g)
      classes[g] = static_cast<ContactClass>((trial * 7 + g * 3 + trial / 5) % kContactClassCount);
    const std::int64_t packed = packTruth(classes.data());
    ASSERT_TRUE(unpackTruth(packed, back.data()));
    EXPECT_EQ(back, classes);
  }
  classes.fill(ContactClass::DeadPath);
  EXPECT_EQ(packTruth(classes.data()), 0b100100100100100100100100);
  EXPECT_FALSE(unpackTruth(5, back.data()));                      // code 5 in group F
  EXPECT_FALSE(unpackTruth(std::int64_t{7} << 21, back.data()));  // code 7 in group FRC
  EXPECT_FALSE(unpackTruth(std::int64_t{1} << 24, back.data()));  // a ninth group
  EXPECT_FALSE(unpackTruth(-1, back.data()));
  EXPECT_TRUE(unpackTruth(0, back.data()));
  EXPECT_EQ(back[3], ContactClass::NoContact);
}

// Encodes and decodes `values`; returns the blob size.
std::size_t roundTrip(const std::vector<double>& values) {
  std::vector<unsigned char> blob(maxEncodedValueBytes(values.size()));
  const std::size_t bytes = encodeValues(values.data(), values.size(), blob.data());
  EXPECT_LE(bytes, 8 * values.size());
  std::vector<double> back(values.size(), 123.0);
  EXPECT_TRUE(decodeValues(blob.data(), bytes, values.size(), back.data()));
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back[i]), std::bit_cast<std::uint64_t>(values[i]))
        << "value " << i;
  }
  return bytes;
}

TEST(RunCodec, AllZeroValuesTakeOnlyTheBitmap) {
  EXPECT_EQ(roundTrip(std::vector<double>(kValuesPerStep, 0.0)), 11u);
  EXPECT_EQ(roundTrip(std::vector<double>(kSummaryValues, 0.0)), 22u);
}

TEST(RunCodec, SparseValuesKeepNegativeZeroDenormalsAndExtremes) {
  std::vector<double> values(kValuesPerStep, 0.0);
  values[0] = -0.0;
  values[7] = std::numeric_limits<double>::denorm_min();
  values[8] = -std::numeric_limits<double>::max();
  values[87] = 0.1;
  EXPECT_EQ(roundTrip(values), 11u + 4 * 8);
}

TEST(RunCodec, FullRowsStayDense) {
  std::vector<double> values(kValuesPerStep);
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = 1.0 + static_cast<double>(i);
  EXPECT_EQ(roundTrip(values), 8u * kValuesPerStep);
  // 86 set values: the sparse layout (11 + 688 bytes) is shorter and used.
  values[3] = 0.0;
  values[40] = 0.0;
  EXPECT_EQ(roundTrip(values), 11u + 86 * 8);
  // 87 set values: sparse would need 707 bytes, more than dense.
  values[40] = 2.5;
  EXPECT_EQ(roundTrip(values), 8u * kValuesPerStep);
}

TEST(RunCodec, RandomRowsRoundTripBitExactly) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 2000; ++trial) {
    const std::size_t count = 1 + rng() % 200;
    std::vector<double> values(count);
    const double density = static_cast<double>(rng() % 101) / 100.0;
    for (double& v : values) {
      const std::uint64_t bits = rng();
      v = static_cast<double>(rng() % 1000) / 1000.0 < density ? std::bit_cast<double>(bits) : 0.0;
      if (std::isnan(v)) v = -0.0;
    }
    roundTrip(values);
  }
}

TEST(RunCodec, MalformedValueBlobsAreRejected) {
  std::vector<double> out(kValuesPerStep);
  std::vector<unsigned char> blob(11, 0);
  blob[0] = 0b101;  // two values set, but no value bytes follow
  EXPECT_FALSE(decodeValues(blob.data(), blob.size(), kValuesPerStep, out.data()));
  blob.resize(11 + 16, 0);
  EXPECT_TRUE(decodeValues(blob.data(), blob.size(), kValuesPerStep, out.data()));
  EXPECT_FALSE(decodeValues(blob.data(), blob.size() - 1, kValuesPerStep, out.data()));
  EXPECT_FALSE(decodeValues(blob.data(), 5, kValuesPerStep, out.data()));
  EXPECT_FALSE(decodeValues(blob.data(), 0, kValuesPerStep, out.data()));
  // A bit past the last value of a list whose length is not a multiple of 8.
  std::vector<unsigned char> small{0b1000'0000};
  std::vector<double> five(5);
  EXPECT_FALSE(decodeValues(small.data(), small.size(), 5, five.data()));
  // The dense length is always dense, whatever its first bytes say.
  std::vector<unsigned char> dense(8 * kValuesPerStep, 0);
  dense[8] = 0x3F;
  EXPECT_TRUE(decodeValues(dense.data(), dense.size(), kValuesPerStep, out.data()));
}

}  // namespace
}  // namespace tactile::storage

namespace tactile::storage {
namespace {

TEST_P(ReadTest, TrackEqualsTheRunsColumnsWithoutSensors) {
  const auto track = db_->runs().loadTrack(runId_);
  ASSERT_TRUE(track.ok()) << track.errorText();
  EXPECT_EQ(track->x, run_.x);
  EXPECT_EQ(track->y, run_.y);
  EXPECT_EQ(track->theta, run_.theta);
  EXPECT_EQ(track->v, run_.v);
  EXPECT_EQ(track->omega, run_.omega);
  EXPECT_EQ(track->blocked, run_.blocked);
  EXPECT_EQ(track->truth, run_.truth);
  EXPECT_FALSE(db_->runs().loadTrack(runId_ + 100).ok());
}

TEST_P(ReadTest, TrackOfARunWithoutTruthHasNoTruth) {
  const auto outcome = db_->runs().importRun(makeRun(50, false), "plain");
  ASSERT_EQ(outcome.status, ImportStatus::Imported) << outcome.message;
  const auto track = db_->runs().loadTrack(outcome.runId);
  ASSERT_TRUE(track.ok()) << track.errorText();
  EXPECT_EQ(track->stepCount(), 50u);
  EXPECT_FALSE(track->hasTruth());
}

// Regression: a read that failed on a malformed row (after stepping onto it) left its statement on
// the row, so the connection kept a read transaction open and never saw what another connection
// wrote afterwards.
TEST(ReadSnapshot, AFailedReadDoesNotPinTheConnectionToAnOldSnapshot) {
  test::TempDir dir;
  const auto path = dir.path() / "two.db";
  auto a = test::openDb(path.string());
  ASSERT_NE(a, nullptr);
  const auto outcome = a->runs().importRun(makeRun(10, false), "broken");
  ASSERT_EQ(outcome.status, ImportStatus::Imported);
  {
    sqlite3* raw = nullptr;
    ASSERT_EQ(sqlite3_open(path.string().c_str(), &raw), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(raw, "UPDATE runs SET metadata = x'01'", nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(raw);
  }
  // Read-only: a writable open refuses the damaged database (docs/storage.md#checksums).
  auto opened = RunDatabase::open(path, OpenMode::ReadOnly);
  ASSERT_TRUE(opened.ok()) << opened.errorText();
  auto& b = opened.value();
  EXPECT_FALSE(b->runs().loadWindow(outcome.runId, 0, 5).ok());  // malformed metadata
  ASSERT_TRUE(a->labels().create("new").ok());                   // written by the other connection
  EXPECT_TRUE(b->labels().find("new").ok());                     // and seen at once
}

INSTANTIATE_TEST_SUITE_P(Backends, ReadTest,
                         ::testing::Values(test::Backend::Sqlite, test::Backend::Postgres),
                         test::backendName);

}  // namespace
}  // namespace tactile::storage
