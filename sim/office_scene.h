// Office-like generated maps (scene spec `random:office:SEED`): a rectangle split into rooms by
// thin interior walls, each wall with a door the robot passes and sometimes a gap too narrow for
// it, bumps on the walls, furniture of varied shapes (desks, L, U and T shapes, polygons, thin
// partitions), a start pose and a goal in different rooms. In the manner of the generated indoor
// maps of McGuire, de Croon and Tuyls (2019). Deterministic for a seed. See docs/sim.md.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/geometry.h"
#include "sim/scene.h"

namespace tactile::sim {

// Scene seeds from here on (of `random:office:SEED` and `random:N:SEED`) are kept for
// benchmarks: the training recipe (sim/training_plan.h) never draws them, so a benchmark that
// scores on them scores on maps no training run has seen.
inline constexpr std::uint64_t kFirstBenchmarkSceneSeed = 900'000;

struct OfficeOptions {
  double minRoomUnits = 600.0;  // smallest side of a room between wall faces
  double doorMinUnits = 120.0;  // doors: the robot with its domes is 92 wide
  double doorMaxUnits = 220.0;
  double gapMinUnits = 60.0;  // gaps the robot cannot pass
  double gapMaxUnits = 90.0;
  // Connectivity: the map inflated by the robot's half-width (with domes) plus a margin, on a grid.
  double robotHalfWidthUnits = 46.0;
  double marginUnits = 4.0;
  double gridCellUnits = 10.0;
};

// An opening in an interior wall, as generated.
struct OfficeOpening {
  enum class Kind { Door, NarrowGap };
  Kind kind = Kind::Door;
  Vec2 centre = Vec2::Zero();
  bool wallAlongX = false;  // the wall runs along x (the opening is crossed in y)
  double widthUnits = 0.0;  // along the wall
  double wallThicknessUnits = 0.0;
};

struct OfficeScene {
  // Obstacles in this order: wall pieces, then the `bumps` bumps, then the `furniture` pieces.
  Scene scene;
  std::vector<OfficeOpening> openings;
  std::size_t rooms = 0;
  std::size_t furniture = 0;  // furniture pieces kept
  std::size_t bumps = 0;
  // Start (rear axle) and goal joined by free cells of the inflated map (ClearanceGrid with
  // radius robotHalfWidth + margin). Furniture that would cut them apart is left out, so this is
  // false only when the walls themselves separate them (never seen).
  bool connected = false;
};

// The office map of `seed`. Its scene is named "random:office:SEED"; vertices are rounded to
// 1/1024 so that sceneToJson reproduces the scene exactly.
OfficeScene generateOfficeScene(std::uint64_t seed, const OfficeOptions& options = {});

}  // namespace tactile::sim
