// Hand-built scenes for the simulator tests.
#pragma once

#include <memory>
#include <vector>

#include "sim/scene.h"
#include "sim/simulator.h"
#include "sim/world.h"

namespace tactile::sim::test {

inline Obstacle box(double x0, double y0, double x1, double y1) {
  return Obstacle{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}};
}

// An empty 2000 x 2000 room with the robot at (1000, 1000) facing +x, plus `obstacles`.
inline Scene roomWith(std::vector<Obstacle> obstacles, Pose2d start = {1000, 1000, 0}) {
  Scene s;
  s.name = "test";
  s.bounds = {0, 0, 2000, 2000};
  s.obstacles = std::move(obstacles);
  s.start = start;
  s.goal = Vec2(1900, 1900);
  return s;
}

inline SimConfig rawConfig() {
  SimConfig c;
  c.filterTauSeconds = 0.0;  // recorded values equal the raw displacement
  return c;
}

inline std::unique_ptr<Simulator> makeSim(Scene scene, SimConfig config = rawConfig()) {
  return std::make_unique<Simulator>(std::make_shared<const World>(std::move(scene)), config);
}

}  // namespace tactile::sim::test
