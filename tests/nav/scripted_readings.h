// Scripted sensor readings for the navigator's tests: dome values pressed by hand and the truth
// that goes with them.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <utility>

#include "nav/navigator.h"
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

// Feeds scripted readings to a truth-status navigator (with or without the touch map, or in plan
// drive), one step at a time, from the origin toward `goal`.
class Script {
 public:
  explicit Script(bool touchMap = false, Vec2 goal = Vec2(2000.0, 0.0), bool planDrive = false)
      : goal_(goal) {
    NavigatorConfig config;
    config.source = StatusSource::Truth;
    config.touchMap = touchMap;
    config.planDrive = planDrive;
    auto made = Navigator::create(config);
    EXPECT_TRUE(made.ok());
    nav_ = std::move(made.value());
  }
  Command step(const Values& values, bool blocked = false,
               ContactClass touching = ContactClass::Wall) {
    values_ = values;
    truth_ = truthOf(values, touching);
    Observation o;
    o.step = step_++;
    o.dtSeconds = 0.1;
    o.start = Pose2d{0.0, 0.0, 0.0};
    o.goal = goal_;
    o.blocked = blocked;
    o.values = &values_;
    o.truth = &truth_;
    return nav_->step(o);
  }
  Navigator& nav() { return *nav_; }

 private:
  std::unique_ptr<Navigator> nav_;
  Vec2 goal_;
  Values values_{};
  Truth truth_{};
  std::size_t step_ = 0;
};

}  // namespace tactile::nav::test
