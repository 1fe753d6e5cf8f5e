// The 44-dome sensor layout of docs/domain.md#sensors: one table that every part of the product
// uses.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace tactile {

inline constexpr int kSensorCount = 44;
inline constexpr int kGroupCount = 8;
// Values recorded per step: a normal and a shear component for each dome.
inline constexpr int kValuesPerStep = 2 * kSensorCount;
inline constexpr double kMaxNormal = 5.0;  // full compression, scene units
inline constexpr double kMaxShear = 5.0;   // |shear| limit, scene units

// Groups in index order: indices run counter-clockwise from the right end of the front edge.
enum class SensorGroup : std::uint8_t {
  Front,
  FrontLeftCorner,
  Left,
  RearLeftCorner,
  Back,
  RearRightCorner,
  Right,
  FrontRightCorner,
};

struct GroupInfo {
  SensorGroup group;
  std::string_view shortName;  // "F", "FLC", ... as used in file columns and the CLI
  std::string_view longName;   // "front", "front-left corner", ...
  int firstSensor;
  int sensorCount;
};

inline constexpr std::array<GroupInfo, kGroupCount> kSensorGroups{{
    {SensorGroup::Front, "F", "front", 0, 8},
    {SensorGroup::FrontLeftCorner, "FLC", "front-left corner", 8, 2},
    {SensorGroup::Left, "L", "left side", 10, 10},
    {SensorGroup::RearLeftCorner, "RLC", "rear-left corner", 20, 2},
    {SensorGroup::Back, "B", "back", 22, 8},
    {SensorGroup::RearRightCorner, "RRC", "rear-right corner", 30, 2},
    {SensorGroup::Right, "R", "right side", 32, 10},
    {SensorGroup::FrontRightCorner, "FRC", "front-right corner", 42, 2},
}};

constexpr const GroupInfo& groupInfo(SensorGroup g) {
  return kSensorGroups[static_cast<std::size_t>(g)];
}

constexpr int groupIndex(SensorGroup g) {
  return static_cast<int>(g);
}

// The group a sensor index belongs to; index must be in [0, kSensorCount).
constexpr SensorGroup groupOfSensor(int sensor) {
  for (const GroupInfo& info : kSensorGroups) {
    if (sensor < info.firstSensor + info.sensorCount) return info.group;
  }
  return SensorGroup::FrontRightCorner;
}

// Parses a short name ("FLC") or a long name ("front-left corner"); case-sensitive.
std::optional<SensorGroup> parseSensorGroup(std::string_view name);

// Offset of the normal / shear value of a sensor within one step's kValuesPerStep values.
constexpr int normalOffset(int sensor) {
  return 2 * sensor;
}
constexpr int shearOffset(int sensor) {
  return 2 * sensor + 1;
}

}  // namespace tactile
