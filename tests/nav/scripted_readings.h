// Scripted sensor readings for the navigator's tests: dome values pressed by hand and the truth
// that goes with them.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>

#include "run/contact_class.h"
#include "run/sensor_layout.h"

namespace tactile::nav::test {

using Values = std::array<double, kValuesPerStep>;
using Truth = std::array<ContactClass, kGroupCount>;

// Sets the normal value of the given domes.
inline void press(Values& values, std::initializer_list<int> sensors, double n) {
  for (int s : sensors)
    values[static_cast<std::size_t>(normalOffset(s))] = n;
}

// Truth of a step: the groups with any value touch as `touching`, the rest NoContact.
inline Truth truthOf(const Values& values, ContactClass touching = ContactClass::Wall) {
  Truth t{};
  for (const GroupInfo& info : kSensorGroups) {
    bool any = false;
    for (int d = info.firstSensor; d < info.firstSensor + info.sensorCount; ++d)
      any = any || values[static_cast<std::size_t>(normalOffset(d))] != 0.0;
    t[static_cast<std::size_t>(groupIndex(info.group))] = any ? touching : ContactClass::NoContact;
  }
  return t;
}

}  // namespace tactile::nav::test
