// Scenes (docs/file-formats.md#scene): bounds, polygonal obstacles, a start pose and a goal, loaded
// from JSON and validated, with errors that name the obstacle and the vertex.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/error.h"
#include "run/run.h"
#include "sim/geometry.h"

namespace tactile::sim {

struct SceneBounds {
  double xmin = 0.0;
  double ymin = 0.0;
  double xmax = 0.0;
  double ymax = 0.0;
};

struct Obstacle {
  std::vector<Vec2> polygon;  // closed implicitly (last vertex joins the first), any orientation
  std::size_t line = 0;       // where it is in the scene's JSON text (1-based), 0 when not read
};

struct Scene {
  std::string name;
  SceneBounds bounds;
  std::vector<Obstacle> obstacles;
  Pose2d start;
  Vec2 goal = Vec2::Zero();
  std::size_t startLine = 0;  // the line of "start" in the scene's JSON text, 0 when not read
};

// Scene coordinates (bounds, vertices, start and goal) lie within +-kMaxSceneCoordinate, so widths,
// heights and distances stay finite and exact enough; theta within +-kMaxSceneAngle radians.
inline constexpr double kMaxSceneCoordinate = 1e7;
inline constexpr double kMaxSceneAngle = 1e3;

// Parses scene JSON. `sourceName` (file or scene name) prefixes every error message, with the line
// of the element at fault. Checks the schema, the coordinate range and the polygons
// (validateSceneGeometry) but not the robot at the start pose (that needs the robot: see
// checkStartPose in sim/scene_source.h). Records the lines of the obstacles and the start.
Result<Scene> parseSceneJson(std::string_view text, std::string_view sourceName);

// Polygon and pose checks that need no robot: every coordinate within +-kMaxSceneCoordinate and
// theta within +-kMaxSceneAngle; bounds non-empty; every obstacle has at least three
// finite vertices inside the bounds, no two consecutive vertices equal, non-zero area, and no two
// non-adjacent edges that touch (not self-intersecting); start and goal inside the bounds; goal
// not inside an obstacle. Fails with the first problem, e.g.
// "obstacle 3: edge from vertex 1 to vertex 2 crosses edge from vertex 4 to vertex 5".
Status validateSceneGeometry(const Scene& scene);

// Scene names follow the product's one name rule (docs/file-formats.md#scene): non-empty, at most
// kMaxSceneNameBytes bytes of well-formed UTF-8, no control character (so no line break), no
// comma. Returns the problem, or "" for a good name. parseSceneJson applies it to "name".
inline constexpr std::size_t kMaxSceneNameBytes = 200;
std::string sceneNameProblem(std::string_view name);

// Scene as JSON text (the format parseSceneJson reads).
std::string sceneToJson(const Scene& scene);

}  // namespace tactile::sim
