#include "run/sensor_layout.h"

namespace tactile {

std::optional<SensorGroup> parseSensorGroup(std::string_view name) {
  for (const GroupInfo& info : kSensorGroups) {
    if (info.shortName == name || info.longName == name) return info.group;
  }
  return std::nullopt;
}

}  // namespace tactile
