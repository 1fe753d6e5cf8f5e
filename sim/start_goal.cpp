#include "sim/start_goal.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

#include "sim/geometry.h"
#include "sim/simulator.h"
#include "sim/world.h"

namespace tactile::sim {

Result<Scene> drawStartGoal(const Scene& scene, std::uint64_t seed, const RobotGeometry& geometry) {
  auto world = std::make_shared<const World>(scene);
  SimConfig config;
  config.geometry = geometry;
  Simulator sim(world, config);
  const SceneBounds& b = scene.bounds;
  const double diagonal = std::hypot(b.xmax - b.xmin, b.ymax - b.ymin);
  // Draws are taken from the generator in a fixed order with our own 53-bit uniform (the
  // standard distributions differ between standard libraries), so the result depends on the seed
  // alone.
  std::mt19937_64 rng(seed);
  auto uniform = [&rng](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
  };
  auto goalFree = [&](const Vec2& p) {
    for (const Obstacle& o : scene.obstacles) {
      if (pointInPolygon(p, o.polygon)) return false;
    }
    const double clear2 = kDrawnGoalClearanceUnits * kDrawnGoalClearanceUnits;
    for (const Edge& e : world->edges()) {
      if (pointSegmentDistance2(p, e.a, e.b) < clear2) return false;
    }
    return true;
  };
  for (int attempt = 0; attempt < 20000; ++attempt) {
    const Pose2d start{uniform(b.xmin, b.xmax), uniform(b.ymin, b.ymax),
                       uniform(-std::numbers::pi, std::numbers::pi)};
    const Vec2 goal(uniform(b.xmin, b.xmax), uniform(b.ymin, b.ymax));
    if ((goal - Vec2(start.x, start.y)).norm() < diagonal / 3.0) continue;
    if (!goalFree(goal)) continue;
    // A body wholly inside a large obstacle touches no edge: rule that out by the rear axle.
    bool inside = false;
    for (const Obstacle& o : scene.obstacles)
      inside = inside || pointInPolygon(Vec2(start.x, start.y), o.polygon);
    if (inside) continue;
    const PoseContact contact = sim.evaluate(start);
    if (contact.blocked || !(contact.clearanceUnits >= kDrawnStartClearanceUnits)) continue;
    Scene drawn = scene;
    drawn.start = start;
    drawn.goal = goal;
    return drawn;
  }
  return Error(scene.name + ": no start and goal with room to spare found in 20000 draws");
}

}  // namespace tactile::sim
