#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "run/builtin_scenes.h"
#include "run/contact_class.h"
#include "run/robot_geometry.h"
#include "run/sensor_layout.h"

namespace tactile {
namespace {

TEST(SensorLayout, GroupsCoverAllSensorsContiguouslyInOrder) {
  int next = 0;
  for (const GroupInfo& info : kSensorGroups) {
    EXPECT_EQ(info.firstSensor, next) << info.shortName;
    next += info.sensorCount;
  }
  EXPECT_EQ(next, kSensorCount);
}

TEST(SensorLayout, IndexRangesMatchDesign) {
  EXPECT_EQ(groupOfSensor(0), SensorGroup::Front);
  EXPECT_EQ(groupOfSensor(7), SensorGroup::Front);
  EXPECT_EQ(groupOfSensor(8), SensorGroup::FrontLeftCorner);
  EXPECT_EQ(groupOfSensor(19), SensorGroup::Left);
  EXPECT_EQ(groupOfSensor(21), SensorGroup::RearLeftCorner);
  EXPECT_EQ(groupOfSensor(29), SensorGroup::Back);
  EXPECT_EQ(groupOfSensor(31), SensorGroup::RearRightCorner);
  EXPECT_EQ(groupOfSensor(41), SensorGroup::Right);
  EXPECT_EQ(groupOfSensor(43), SensorGroup::FrontRightCorner);
}

TEST(SensorLayout, ParsesShortAndLongNames) {
  EXPECT_EQ(parseSensorGroup("FLC"), SensorGroup::FrontLeftCorner);
  EXPECT_EQ(parseSensorGroup("right side"), SensorGroup::Right);
  EXPECT_FALSE(parseSensorGroup("flc"));
  EXPECT_FALSE(parseSensorGroup(""));
}

TEST(ContactClassNames, RoundTripExactSpelling) {
  for (int i = 0; i < kContactClassCount; ++i) {
    const auto c = static_cast<ContactClass>(i);
    EXPECT_EQ(parseContactClass(contactClassName(c)), c);
  }
  EXPECT_FALSE(parseContactClass("wall"));
  EXPECT_FALSE(parseContactClass("Leaving Wall"));
}

TEST(RobotGeometry, DomesLieOnTheOutlineWithUnitOutwardNormals) {
  const RobotGeometry g;
  const auto domes = domePlacements(g);
  for (int i = 0; i < kSensorCount; ++i) {
    const DomePlacement& d = domes[i];
    EXPECT_NEAR(std::hypot(d.normal.x, d.normal.y), 1.0, 1e-12) << i;
    EXPECT_GE(d.centre.x, g.backX() - 1e-9) << i;
    EXPECT_LE(d.centre.x, g.frontX() + 1e-9) << i;
    EXPECT_LE(std::abs(d.centre.y), g.halfWidth() + 1e-9) << i;
    // Outward: the normal points away from the body centre.
    const double cx = 0.5 * (g.frontX() + g.backX());
    EXPECT_GT((d.centre.x - cx) * d.normal.x + d.centre.y * d.normal.y, 0.0) << i;
  }
  // Counter-clockwise order: the angle of each dome about the body centre increases.
  const double cx = 0.5 * (g.frontX() + g.backX());
  double previous = -1e9;
  for (int i = 0; i < kSensorCount; ++i) {
    double a = std::atan2(domes[i].centre.y, domes[i].centre.x - cx);
    if (i > 0 && a < previous - 1e-9) a += 2 * M_PI;
    EXPECT_GT(a, previous) << i;
    previous = a;
  }
  // Front domes face +x, left-side domes +y, back -x, right-side -y.
  EXPECT_DOUBLE_EQ(domes[0].normal.x, 1.0);
  EXPECT_LT(domes[0].centre.y, domes[7].centre.y);
  EXPECT_DOUBLE_EQ(domes[15].normal.y, 1.0);
  EXPECT_DOUBLE_EQ(domes[25].normal.x, -1.0);
  EXPECT_DOUBLE_EQ(domes[35].normal.y, -1.0);
}

TEST(RobotGeometry, WidthWithDomesFitsA110GapButNotA90Gap) {
  const RobotGeometry g;
  const double width = g.widthUnits + 2 * g.domeRadiusUnits;
  EXPECT_LT(width, 100.0);
  EXPECT_GT(width, 90.0);
}

TEST(BuiltinScenes, EmbeddedScenesAreListedAndFound) {
  const auto names = builtinSceneNames();
  ASSERT_FALSE(names.empty());
  for (const std::string& name : names) {
    const auto json = builtinSceneJson(name);
    ASSERT_TRUE(json.has_value()) << name;
    EXPECT_NE(json->find("\"obstacles\""), std::string_view::npos) << name;
  }
  EXPECT_FALSE(builtinSceneJson("no-such-scene").has_value());
}

}  // namespace
}  // namespace tactile
