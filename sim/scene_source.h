// Where scenes come from: built-in names, JSON files, and the seeded procedural generator
// `random:N:SEED`; plus the robot-dependent start-pose check.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "run/robot_geometry.h"
#include "sim/scene.h"

namespace tactile::sim {

inline constexpr std::size_t kMaxProceduralObstacles = 10'000;

// A cluttered room with `obstacles` convex obstacles (boxes, rotated boxes, triangles, pentagons,
// sizes 20..130) on a jittered grid of 300-unit cells, so density is constant and the room grows
// with the count. Cells near the start (left middle) and the goal (right middle) stay empty, so
// neither is ever blocked. Deterministic for a given (obstacles, seed).
Scene generateProceduralScene(std::size_t obstacles, std::uint64_t seed);

// The start pose check of a scene: fails with why the robot cannot stand there (body or a dome
// compressed past 5 overlapping an obstacle or the bounds).
Status checkStartPose(const Scene& scene, const RobotGeometry& geometry = {});

// Why what the user typed cannot name a scene at all (an unknown name, a malformed
// `random:N:SEED`), or nullopt. A front end reports these as usage errors; loadScene fails on them
// too.
std::optional<std::string> sceneSpecError(std::string_view spec);

// Resolves what the user typed: "random:N:SEED", "random:office:SEED" (generateOfficeScene in
// sim/office_scene.h), a built-in scene name, or a path to a JSON file
// (anything containing '/' or ending in ".json"). Validates everything, the start pose included.
Result<Scene> loadScene(std::string_view spec, const RobotGeometry& geometry = {});

// The JSON of a procedural scene (`random:N:SEED`, `random:office:SEED`), generated again, so that
// an importer can store the scene of a run recorded in one; nullopt for anything else (built-in
// names and files are resolved by storage itself).
std::optional<std::string> proceduralSceneJson(const std::string& spec);

}  // namespace tactile::sim
