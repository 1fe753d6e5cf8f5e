// Where scenes come from: built-in names, JSON files, and the seeded procedural generator
// `random:N:SEED`; plus the robot-dependent start-pose check.
#pragma once

#include <cstdint>
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

// The start pose check of a scene: "" or why the robot cannot stand there (body or a dome
// compressed past 5 overlapping an obstacle or the bounds).
std::string checkStartPose(const Scene& scene, const RobotGeometry& geometry = {});

// Resolves what the user typed: "random:N:SEED", a built-in scene name, or a path to a JSON file
// (anything containing '/' or ending in ".json"). Validates everything, the start pose included.
// Unknown names and malformed random specs are usage errors; unreadable or invalid files are not.
SceneResult loadScene(std::string_view spec, const RobotGeometry& geometry = {});

}  // namespace tactile::sim
