// Scripted sensor readings for the navigator's tests: dome values pressed by hand and the truth
// that goes with them.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

#include "nav/navigator.h"
#include "run/contact_class.h"
#include "run/robot_geometry.h"
#include "run/sensor_layout.h"
#include "sim/robot.h"
#include "sim/scene.h"
#include "sim/world.h"

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
  explicit Script(bool touchMap = false, Vec2 goal = Vec2(2000.0, 0.0), bool planDrive = false,
                  double blockedStepShare = NavigatorConfig{}.blockedStepShare)
      : goal_(goal) {
    NavigatorConfig config;
    config.source = StatusSource::Truth;
    config.touchMap = touchMap;
    config.planDrive = planDrive;
    config.blockedStepShare = blockedStepShare;
    auto made = Navigator::create(config);
    EXPECT_TRUE(made.ok());
    nav_ = std::move(made.value());
  }
  Command step(const Values& values, bool blocked = false,
               ContactClass touching = ContactClass::Wall) {
    return step(values, truthOf(values, touching), blocked);
  }
  // A step whose status (the truth source's classes) is given apart from the readings.
  Command step(const Values& values, const Truth& truth, bool blocked = false) {
    values_ = values;
    truth_ = truth;
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

// A rectangle obstacle from (x0, y0) to (x1, y1).
inline sim::Obstacle box(double x0, double y0, double x1, double y1) {
  return sim::Obstacle{
      {sim::Vec2(x0, y0), sim::Vec2(x1, y0), sim::Vec2(x1, y1), sim::Vec2(x0, y1)}};
}

// A test scene of the given size and obstacles with its goal; the start is at (200, height / 2).
inline std::shared_ptr<const sim::World> worldOf(std::vector<sim::Obstacle> obstacles, double width,
                                                 double height, sim::Vec2 goal) {
  sim::Scene s;
  s.name = "test";
  s.bounds = {0, 0, width, height};
  s.obstacles = std::move(obstacles);
  s.start = {200, height / 2, 0};
  s.goal = goal;
  return std::make_shared<const sim::World>(std::move(s));
}

// A 2000 x 1000 scene whose goal (1100, 450) lies inside a closed ring of walls: no way to it.
inline std::shared_ptr<const sim::World> ringWorld() {
  return worldOf({box(950, 250, 1250, 270), box(950, 630, 1250, 650), box(950, 270, 970, 630),
                  box(1230, 270, 1250, 630)},
                 2000, 1000, sim::Vec2(1100, 450));
}

// Where a pressed dome marks: its centre a dome radius out along its normal, in the odometry frame.
inline Vec2 touchPoint(const Pose2d& pose, int sensor) {
  const RobotGeometry g;
  const DomePlacement d = domePlacements(g)[static_cast<std::size_t>(sensor)];
  const Vec2 body(d.centre.x + g.domeRadiusUnits * d.normal.x,
                  d.centre.y + g.domeRadiusUnits * d.normal.y);
  return sim::bodyToWorld(pose, body);
}

}  // namespace tactile::nav::test
