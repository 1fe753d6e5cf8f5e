// Feature vectors, the NoContact rule, label files and labelled data sets.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/features.h"
#include "tests/analysis/learn_test_data.h"

namespace tactile::analysis {
namespace {

// A one-step run whose right-side group (sensors 32..41) has n = 1 + i/10 and s = -(i/10).
RunData oneStepRun() {
  RunData run;
  auto values = testdata::zeroStep();
  for (int i = 0; i < 10; ++i) {
    values[static_cast<std::size_t>(normalOffset(32 + i))] = 1.0 + i / 10.0;
    values[static_cast<std::size_t>(shearOffset(32 + i))] = -(i / 10.0);
  }
  run.appendStep(0, 0, 0, 0, 0, false, values.data(), nullptr);
  return run;
}

TEST(Features, KindNamesRoundTrip) {
  for (FeatureKind k : kFeatureKinds) {
    ASSERT_TRUE(parseFeatureKind(featureKindName(k)).has_value());
    EXPECT_EQ(*parseFeatureKind(featureKindName(k)), k);
  }
  EXPECT_EQ(featureKindName(FeatureKind::NormalShearTouch), "normal+shear+touch");
  EXPECT_FALSE(parseFeatureKind("Normal").has_value());
  EXPECT_FALSE(parseFeatureKind("").has_value());
}

TEST(Features, DimensionPerGroupAndKind) {
  for (const GroupInfo& info : kSensorGroups) {
    EXPECT_EQ(featureDimension(info.group, FeatureKind::Normal), info.sensorCount);
    EXPECT_EQ(featureDimension(info.group, FeatureKind::Magnitude), info.sensorCount);
    EXPECT_EQ(featureDimension(info.group, FeatureKind::NormalShear), 2 * info.sensorCount);
    EXPECT_EQ(featureDimension(info.group, FeatureKind::NormalShearTouch),
              2 * info.sensorCount + 3);
    EXPECT_EQ(featureDimension(info.group, FeatureKind::Neighbours),
              featureDimension(info.group, FeatureKind::Context) + 4);
  }
}

// Every group's neighbours are the groups beside it round the body, counter-clockwise first, and
// each group is the neighbour of both of its neighbours.
TEST(Features, NeighbourGroupsAreTheGroupsBesideIt) {
  const auto f = neighbourGroups(SensorGroup::Front);
  EXPECT_EQ(f[0], SensorGroup::FrontLeftCorner);
  EXPECT_EQ(f[1], SensorGroup::FrontRightCorner);
  const auto l = neighbourGroups(SensorGroup::Left);
  EXPECT_EQ(l[0], SensorGroup::RearLeftCorner);
  EXPECT_EQ(l[1], SensorGroup::FrontLeftCorner);
  const auto frc = neighbourGroups(SensorGroup::FrontRightCorner);
  EXPECT_EQ(frc[0], SensorGroup::Front);
  EXPECT_EQ(frc[1], SensorGroup::Right);
  for (const GroupInfo& info : kSensorGroups) {
    const auto n = neighbourGroups(info.group);
    EXPECT_NE(n[0], n[1]);
    EXPECT_EQ(neighbourGroups(n[0])[1], info.group) << info.shortName;
    EXPECT_EQ(neighbourGroups(n[1])[0], info.group) << info.shortName;
  }
}

// The neighbours kind is the context kind followed by the largest and the mean n value of each
// neighbouring group; shear and groups further away do not count.
TEST(Features, NeighboursAddTheLargestAndMeanNormalOfTheGroupsBeside) {
  RunData run;
  auto values = testdata::zeroStep();
  values[static_cast<std::size_t>(normalOffset(2))] = 1.5;   // front
  values[static_cast<std::size_t>(normalOffset(8))] = 2.0;   // front-left corner
  values[static_cast<std::size_t>(normalOffset(9))] = 4.0;   // front-left corner
  values[static_cast<std::size_t>(shearOffset(42))] = 9.0;   // front-right corner: shear only
  values[static_cast<std::size_t>(normalOffset(43))] = 1.0;  // front-right corner
  values[static_cast<std::size_t>(normalOffset(12))] = 5.0;  // left side: not F's neighbour
  values[static_cast<std::size_t>(normalOffset(21))] = 3.0;  // rear-left corner
  run.appendStep(0, 0, 0, 0, 0, false, values.data(), nullptr);
  run.appendStep(0, 0, 25.0, -0.5, 0, false, values.data(), nullptr);

  const int dc = featureDimension(SensorGroup::Front, FeatureKind::Context);
  std::vector<double> context(static_cast<std::size_t>(dc));
  std::vector<double> f(static_cast<std::size_t>(dc + 4), -1.0);
  groupFeatures(run, 1, SensorGroup::Front, FeatureKind::Context, context.data());
  groupFeatures(run, 1, SensorGroup::Front, FeatureKind::Neighbours, f.data());
  for (int i = 0; i < dc; ++i)
    EXPECT_EQ(f[static_cast<std::size_t>(i)], context[static_cast<std::size_t>(i)]) << i;
  EXPECT_EQ(f[static_cast<std::size_t>(dc)], 4.0);      // FLC largest
  EXPECT_EQ(f[static_cast<std::size_t>(dc + 1)], 3.0);  // FLC mean of 2 and 4
  EXPECT_EQ(f[static_cast<std::size_t>(dc + 2)], 1.0);  // FRC largest
  EXPECT_EQ(f[static_cast<std::size_t>(dc + 3)], 0.5);  // FRC mean of 0 and 1

  // The left side: FLC first, then RLC (sensors 20, 21).
  const int dl = featureDimension(SensorGroup::Left, FeatureKind::Neighbours);
  std::vector<double> g(static_cast<std::size_t>(dl), -1.0);
  groupFeatures(run, 1, SensorGroup::Left, FeatureKind::Neighbours, g.data());
  EXPECT_EQ(g[static_cast<std::size_t>(dl - 4)], 3.0);  // RLC largest
  EXPECT_EQ(g[static_cast<std::size_t>(dl - 3)], 1.5);  // RLC mean
  EXPECT_EQ(g[static_cast<std::size_t>(dl - 2)], 4.0);  // FLC largest
  EXPECT_EQ(g[static_cast<std::size_t>(dl - 1)], 3.0);  // FLC mean

  // Neighbours without contact read 0.
  const int db = featureDimension(SensorGroup::Back, FeatureKind::Neighbours);
  std::vector<double> b(static_cast<std::size_t>(db), -1.0);
  groupFeatures(run, 1, SensorGroup::Back, FeatureKind::Neighbours, b.data());
  EXPECT_EQ(b[static_cast<std::size_t>(db - 4)], 0.0);  // RRC
  EXPECT_EQ(b[static_cast<std::size_t>(db - 3)], 0.0);
  EXPECT_EQ(b[static_cast<std::size_t>(db - 2)], 3.0);  // RLC
  EXPECT_EQ(b[static_cast<std::size_t>(db - 1)], 1.5);
}

TEST(Features, NormalIsTheGroupsNValues) {
  const RunData run = oneStepRun();
  std::vector<double> f(10);
  groupFeatures(run, 0, SensorGroup::Right, FeatureKind::Normal, f.data());
  for (int i = 0; i < 10; ++i)
    EXPECT_EQ(f[static_cast<std::size_t>(i)], run.normal(0, 32 + i));
}

TEST(Features, MagnitudeIsEuclideanNormOfNormalAndShear) {
  const RunData run = oneStepRun();
  std::vector<double> f(10);
  groupFeatures(run, 0, SensorGroup::Right, FeatureKind::Magnitude, f.data());
  for (int i = 0; i < 10; ++i) {
    const double n = run.normal(0, 32 + i), s = run.shear(0, 32 + i);
    EXPECT_NEAR(f[static_cast<std::size_t>(i)], std::sqrt(n * n + s * s), 1e-15);
  }
}

TEST(Features, NormalShearInterleaves) {
  const RunData run = oneStepRun();
  std::vector<double> f(20);
  groupFeatures(run, 0, SensorGroup::Right, FeatureKind::NormalShear, f.data());
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(f[static_cast<std::size_t>(2 * i)], run.normal(0, 32 + i));
    EXPECT_EQ(f[static_cast<std::size_t>(2 * i + 1)], run.shear(0, 32 + i));
  }
}

TEST(Features, TouchFlagsSayWhetherFrontLeftAndRightRead) {
  RunData run;
  auto values = testdata::zeroStep();
  values[static_cast<std::size_t>(normalOffset(3))] = 0.4;       // front
  values[static_cast<std::size_t>(normalOffset(5))] = 0.9;       // front
  values[static_cast<std::size_t>(shearOffset(34))] = 5.0;       // right side shear: not counted
  values[static_cast<std::size_t>(normalOffset(9))] = 7.0;       // front-left corner: not counted
  values[static_cast<std::size_t>(normalOffset(12))] = 1e-9;     // left side, barely
  values[static_cast<std::size_t>(normalOffset(24))] = 9.0;      // back: not counted
  run.appendStep(0, 0, 0, 0, 0, false, values.data(), nullptr);  // right side n all zero

  std::vector<double> f(7, -1.0);
  groupFeatures(run, 0, SensorGroup::FrontLeftCorner, FeatureKind::NormalShearTouch, f.data());
  EXPECT_EQ(f[0], 0.0);  // sensor 8: n, s
  EXPECT_EQ(f[1], 0.0);
  EXPECT_EQ(f[2], 7.0);  // sensor 9: n, s
  EXPECT_EQ(f[3], 0.0);
  EXPECT_EQ(f[4], 1.0);  // front touches
  EXPECT_EQ(f[5], 1.0);  // left side touches, however lightly
  EXPECT_EQ(f[6], 0.0);  // right side: shear alone is not a touch
}

TEST(Features, ZeroGroupIsNoContactByRule) {
  const RunData run = oneStepRun();
  EXPECT_FALSE(groupIsZero(run, 0, SensorGroup::Right));
  for (SensorGroup g : {SensorGroup::Front, SensorGroup::Left, SensorGroup::FrontRightCorner}) {
    EXPECT_TRUE(groupIsZero(run, 0, g));
  }
}

TEST(Features, ShearAloneMakesGroupNonZero) {
  RunData run;
  auto values = testdata::zeroStep();
  values[static_cast<std::size_t>(shearOffset(8))] = 0.25;  // FLC, normal still zero
  run.appendStep(0, 0, 0, 0, 0, false, values.data(), nullptr);
  EXPECT_FALSE(groupIsZero(run, 0, SensorGroup::FrontLeftCorner));
}

TEST(Features, ExtractGroupStepsFlagsZeroRows) {
  const RunData run = testdata::makeLabelledRun(300, 7);
  const GroupSteps gs = extractGroupSteps(run, SensorGroup::Left, FeatureKind::Normal);
  ASSERT_EQ(gs.features.rows(), 300);
  ASSERT_EQ(gs.features.cols(), 10);
  std::size_t zero = 0;
  for (std::size_t t = 0; t < 300; ++t) {
    EXPECT_EQ(gs.isZero[t] != 0, groupIsZero(run, t, SensorGroup::Left));
    if (gs.isZero[t]) {
      ++zero;
      EXPECT_EQ(gs.features.row(static_cast<Eigen::Index>(t)).cwiseAbs().maxCoeff(), 0.0);
    }
  }
  EXPECT_GT(zero, 0u);
  EXPECT_LT(zero, 300u);
}

TEST(Features, DataSetExcludesZeroRowsAndCountsThem) {
  const RunData run = testdata::makeLabelledRun(500, 3);
  std::vector<LabelledRun> runs{{&run, labelsFromTruth(run)}};
  const GroupDataSet ds = buildGroupDataSet(runs, SensorGroup::Right, FeatureKind::Normal);
  std::size_t contact = 0, zero = 0;
  for (std::size_t t = 0; t < run.stepCount(); ++t) {
    (groupIsZero(run, t, SensorGroup::Right) ? zero : contact) += 1;
  }
  EXPECT_EQ(ds.size(), contact);
  EXPECT_EQ(ds.zeroRows, zero);
  // The generator's NoContact episodes are exactly the zero rows.
  EXPECT_EQ(ds.zeroRowsByClass[0], zero);
  EXPECT_EQ(ds.classCounts()[0], 0u);
  for (std::size_t i = 0; i < ds.size(); ++i) {
    EXPECT_EQ(ds.y[i], run.truthAt(ds.step[i], SensorGroup::Right));
    EXPECT_EQ(ds.x(static_cast<Eigen::Index>(i), 0), run.normal(ds.step[i], 32));
  }
}

TEST(Features, AbsentClassesAreNotPresent) {
  const RunData run = testdata::makeLabelledRun(400, 5);
  std::vector<LabelledRun> runs{{&run, labelsFromTruth(run)}};
  // Relabel every contact step of group L as Wall: only Wall is present.
  for (std::size_t t = 0; t < run.stepCount(); ++t) {
    runs[0].labels[t * kGroupCount + groupIndex(SensorGroup::Left)] = ContactClass::Wall;
  }
  const GroupDataSet ds = buildGroupDataSet(runs, SensorGroup::Left, FeatureKind::Normal);
  ASSERT_EQ(ds.classesPresent().size(), 1u);
  EXPECT_EQ(ds.classesPresent()[0], ContactClass::Wall);
  EXPECT_EQ(ds.rowsOf(ContactClass::Corner).rows(), 0);
  EXPECT_EQ(static_cast<std::size_t>(ds.rowsOf(ContactClass::Wall).rows()), ds.size());
}

TEST(Features, UnlabelledStepsAreSkipped) {
  const RunData run = testdata::makeLabelledRun(100, 9);
  std::vector<LabelledRun> runs{
      {&run, std::vector<std::optional<ContactClass>>(run.stepCount() * kGroupCount)}};
  const GroupDataSet ds = buildGroupDataSet(runs, SensorGroup::Front, FeatureKind::Magnitude);
  EXPECT_EQ(ds.size(), 0u);
  EXPECT_EQ(ds.unlabelledRows, 100u);
  EXPECT_EQ(ds.dimension(), 8);
}

TEST(Labels, SegmentsApplyToMatchingRunAndLaterOverride) {
  const RunData run = testdata::makeLabelledRun(10, 1);
  std::vector<LabelRecord> segs{{"a", SensorGroup::Right, 0, 9, ContactClass::Wall, ""},
                                {"b", SensorGroup::Right, 0, 9, ContactClass::Corner, ""},
                                {"a", SensorGroup::Right, 3, 4, ContactClass::LeavingWall, ""}};
  const auto read = labelsFromSegments(run, "a", segs);
  ASSERT_TRUE(read.ok()) << read.errorText();
  const auto& labels = read.value();
  const std::size_t g = groupIndex(SensorGroup::Right);
  EXPECT_EQ(labels[0 * kGroupCount + g], ContactClass::Wall);
  EXPECT_EQ(labels[3 * kGroupCount + g], ContactClass::LeavingWall);
  EXPECT_EQ(labels[5 * kGroupCount + g], ContactClass::Wall);
  EXPECT_FALSE(labels[0 * kGroupCount + groupIndex(SensorGroup::Left)].has_value());
}

TEST(Labels, SegmentPastLastStepIsError) {
  const RunData run = testdata::makeLabelledRun(10, 1);
  std::vector<LabelRecord> segs{{"a", SensorGroup::Right, 5, 10, ContactClass::Wall, ""}};
  const auto labels = labelsFromSegments(run, "a", segs);
  ASSERT_FALSE(labels.ok());
  EXPECT_NE(labels.errorText().find("reaches past its last step 9"), std::string::npos)
      << labels.errorText();
}

}  // namespace
}  // namespace tactile::analysis
