// Hole detection (thesis 4.5): fragments of contact along a side and the gap widths between them.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/hole_detection.h"
#include "tests/analysis/learn_test_data.h"

namespace tactile::analysis {
namespace {

std::array<bool, kSensorCount> contacts(std::initializer_list<int> on) {
  std::array<bool, kSensorCount> c{};
  for (int s : on)
    c[static_cast<std::size_t>(s)] = true;
  return c;
}

TEST(HoleDetection, GapOnLeftSideIsDistanceBetweenBoundingDomes) {
  const auto placements = domePlacements();
  // Left edge domes 10..19 at equal slots of the straight edge (length - 2 corner radii) / 10.
  const RobotGeometry g;
  const double pitch = (g.lengthUnits - 2.0 * g.cornerRadiusUnits) / 10.0;
  const HoleScan scan = scanSide(contacts({10, 11, 12, 16, 17, 18, 19}), 8, 14, placements);
  ASSERT_EQ(scan.fragments.size(), 2u);
  EXPECT_EQ(scan.fragments[0].firstSensor, 10);
  EXPECT_EQ(scan.fragments[0].lastSensor, 12);
  EXPECT_EQ(scan.fragments[1].firstSensor, 16);
  ASSERT_EQ(scan.holes.size(), 1u);
  EXPECT_EQ(scan.holes[0].lastSensorBefore, 12);
  EXPECT_EQ(scan.holes[0].firstSensorAfter, 16);
  EXPECT_NEAR(scan.holes[0].widthUnits, 4.0 * pitch, 1e-9);
  EXPECT_NEAR(scan.holes[0].freeSpanUnits, 2.0 * pitch, 1e-9);  // domes 13..15
  EXPECT_LT(scan.holes[0].freeSpanUnits, scan.holes[0].widthUnits);
}

TEST(HoleDetection, NoContactMeansNoFragments) {
  const HoleScan scan = scanSide(contacts({}), 8, 14, domePlacements());
  EXPECT_TRUE(scan.fragments.empty());
  EXPECT_TRUE(scan.holes.empty());
}

TEST(HoleDetection, OneFragmentMeansNoHole) {
  const HoleScan scan = scanSide(contacts({12, 13, 14}), 8, 14, domePlacements());
  EXPECT_EQ(scan.fragments.size(), 1u);
  EXPECT_TRUE(scan.holes.empty());
}

TEST(HoleDetection, ContactOutsideTheSideIsIgnored) {
  const HoleScan scan = scanSide(contacts({0, 12, 40}), 8, 14, domePlacements());
  ASSERT_EQ(scan.fragments.size(), 1u);
  EXPECT_EQ(scan.fragments[0].firstSensor, 12);
}

TEST(HoleDetection, FrontSideWrapsFromIndex43ToZero) {
  const auto placements = domePlacements();
  // Front side: FRC (42, 43), F (0..7), FLC (8, 9); contact at 43 and at 2 -> one hole.
  const HoleScan scan =
      scanSide(contacts({42, 43, 2, 3}), kSides[0].firstSensor, kSides[0].count, placements);
  ASSERT_EQ(scan.fragments.size(), 2u);
  EXPECT_EQ(scan.fragments[0].firstSensor, 42);
  EXPECT_EQ(scan.fragments[0].lastSensor, 43);
  ASSERT_EQ(scan.holes.size(), 1u);
  const Vec2d a = placements[43].centre, b = placements[2].centre;
  EXPECT_NEAR(scan.holes[0].widthUnits, std::hypot(a.x - b.x, a.y - b.y), 1e-12);
}

TEST(HoleDetection, ThreeFragmentsGiveTwoHoles) {
  const HoleScan scan = scanSide(contacts({32, 35, 36, 41}), 30, 14, domePlacements());
  EXPECT_EQ(scan.fragments.size(), 3u);
  ASSERT_EQ(scan.holes.size(), 2u);
  EXPECT_EQ(scan.holes[1].lastSensorBefore, 36);
  EXPECT_EQ(scan.holes[1].firstSensorAfter, 41);
  EXPECT_EQ(scan.holes[0].freeSpanUnits > 0.0, true);
}

TEST(HoleDetection, ThresholdDecidesContact) {
  RunData run;
  auto values = testdata::zeroStep();
  values[static_cast<std::size_t>(normalOffset(10))] = 0.05;
  values[static_cast<std::size_t>(normalOffset(11))] = 0.5;
  run.appendStep(0, 0, 0, 0, 0, false, values.data(), nullptr);
  EXPECT_TRUE(sensorContacts(run, 0)[10]);
  EXPECT_FALSE(sensorContacts(run, 0, 0.1)[10]);
  EXPECT_TRUE(sensorContacts(run, 0, 0.1)[11]);
}

TEST(HoleDetection, ScanRunGivesOneScanPerStep) {
  RunData run;
  auto values = testdata::zeroStep();
  run.appendStep(0, 0, 0, 0, 0, false, values.data(), nullptr);
  values[static_cast<std::size_t>(normalOffset(10))] = 1.0;
  values[static_cast<std::size_t>(normalOffset(19))] = 1.0;
  run.appendStep(0, 0, 0, 0, 0, false, values.data(), nullptr);
  const std::vector<HoleScan> scans = scanRun(run, kSides[1]);
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_TRUE(scans[0].holes.empty());
  ASSERT_EQ(scans[1].holes.size(), 1u);
  const auto p = domePlacements();
  EXPECT_NEAR(scans[1].holes[0].widthUnits, std::abs(p[10].centre.x - p[19].centre.x), 1e-9);
}

}  // namespace
}  // namespace tactile::analysis
