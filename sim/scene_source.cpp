#include "sim/scene_source.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>

#include "base/file_text.h"
#include "base/text_parse.h"
#include "run/builtin_scenes.h"
#include "run/run_csv.h"
#include "sim/geometry.h"
#include "sim/office_scene.h"
#include "sim/recorder.h"
#include "sim/simulator.h"

namespace tactile::sim {
namespace {

double unit(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

constexpr double kCellUnits = 300.0;

}  // namespace

Scene generateProceduralScene(std::size_t obstacles, std::uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  Scene scene;
  scene.name = "random:" + std::to_string(obstacles) + ":" + std::to_string(seed);
  // Cells: enough for the obstacles plus the cleared cells around start and goal.
  const std::size_t needed = obstacles + 8;
  int rows = std::max(3, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(needed)))));
  int cols = std::max(4, static_cast<int>(std::ceil(static_cast<double>(needed) / rows)));
  while (static_cast<std::size_t>(rows) * cols < needed + 4)
    ++cols;
  const double width = cols * kCellUnits;
  const double height = rows * kCellUnits;
  scene.bounds = {0.0, 0.0, width, height};
  const int midRow = rows / 2;
  const Vec2 start((0.5) * kCellUnits, (midRow + 0.5) * kCellUnits);
  const Vec2 goal((cols - 0.5) * kCellUnits, (midRow + 0.5) * kCellUnits);
  scene.start = Pose2d{start.x() - 35.0, start.y(), 0.0};
  scene.goal = goal;
  const auto reserved = [&](int r, int c) {
    const bool nearStart = c <= 1 && std::abs(r - midRow) <= 1;
    const bool nearGoal = c >= cols - 1 && std::abs(r - midRow) <= 1;
    return nearStart || nearGoal;
  };
  std::vector<std::pair<int, int>> cells;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      if (!reserved(r, c)) cells.emplace_back(r, c);
    }
  }
  // Deterministic shuffle (Fisher-Yates with our own uniform draw), take the first N cells.
  for (std::size_t i = cells.size(); i > 1; --i) {
    const std::size_t j = static_cast<std::size_t>(unit(rng) * i);
    std::swap(cells[i - 1], cells[j]);
  }
  const double margin = 15.0;
  for (std::size_t k = 0; k < obstacles && k < cells.size(); ++k) {
    const auto [r, c] = cells[k];
    const int shape = static_cast<int>(unit(rng) * 4.0);
    const double size = 20.0 + 110.0 * unit(rng);
    const double aspect = 0.4 + 0.6 * unit(rng);
    const double angle = shape == 0 ? 0.0 : 2.0 * std::numbers::pi * unit(rng);
    std::vector<Vec2> local;
    if (shape <= 1) {
      const double hx = 0.5 * size;
      const double hy = 0.5 * size * aspect;
      local = {Vec2(-hx, -hy), Vec2(hx, -hy), Vec2(hx, hy), Vec2(-hx, hy)};
    } else {
      const int sides = shape == 2 ? 3 : 5;
      for (int i = 0; i < sides; ++i) {
        const double a = 2.0 * std::numbers::pi * i / sides;
        local.emplace_back(0.5 * size * std::cos(a), 0.5 * size * std::sin(a));
      }
    }
    // Place the shape inside its cell with a margin, at a random offset.
    const double reach = 0.5 * size * std::sqrt(2.0);
    const double freeSpan = kCellUnits - 2.0 * (reach + margin);
    const double cx = c * kCellUnits + reach + margin + std::max(0.0, freeSpan) * unit(rng);
    const double cy = r * kCellUnits + reach + margin + std::max(0.0, freeSpan) * unit(rng);
    Obstacle o;
    const double ca = std::cos(angle);
    const double sa = std::sin(angle);
    for (const Vec2& p : local) {
      // Rounded to 1/1024 so the JSON form of the scene reproduces it exactly.
      const double x = std::round((cx + ca * p.x() - sa * p.y()) * 1024.0) / 1024.0;
      const double y = std::round((cy + sa * p.x() + ca * p.y()) * 1024.0) / 1024.0;
      o.polygon.emplace_back(x, y);
    }
    scene.obstacles.push_back(std::move(o));
  }
  return scene;
}

namespace {

// "obstacle 3 (line 12)": the obstacle as the scene's errors name it, with its line when read
// from a file.
std::string obstacleName(const Scene& scene, std::size_t i) {
  std::string out = "obstacle " + std::to_string(i);
  if (scene.obstacles[i].line > 0) out += " (line " + std::to_string(scene.obstacles[i].line) + ")";
  return out;
}

// The obstacles whose bounding box comes within `reach` of `p`.
std::vector<std::size_t> obstaclesNear(const Scene& scene, const Vec2& p, double reach) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    const std::vector<Vec2>& poly = scene.obstacles[i].polygon;
    if (poly.empty()) continue;
    Vec2 lo = poly.front();
    Vec2 hi = poly.front();
    for (const Vec2& v : poly) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    if (p.x() >= lo.x() - reach && p.x() <= hi.x() + reach && p.y() >= lo.y() - reach &&
        p.y() <= hi.y() + reach) {
      out.push_back(i);
    }
  }
  return out;
}

}  // namespace

Status checkStartPose(const Scene& scene, const RobotGeometry& geometry) {
  const std::string at = "start: the robot at (" + formatNumber(scene.start.x) + ", " +
                         formatNumber(scene.start.y) + ", " + formatNumber(scene.start.theta) + ")";
  const auto error = [&](const std::string& message) {
    return Error(std::string(), scene.startLine, 0, at + " " + message);
  };
  const Vec2 centre(scene.start.x, scene.start.y);
  // A body wholly inside an obstacle touches none of its edges: the edge test below cannot see it.
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    if (pointInPolygon(centre, scene.obstacles[i].polygon)) {
      return error("stands inside " + obstacleName(scene, i));
    }
  }
  SimConfig config;
  config.geometry = geometry;
  Simulator sim(std::make_shared<const World>(scene), config);
  if (!sim.isBlocked(scene.start)) return Status::success();
  // Which obstacle: each one near the start alone, in a room far larger than the robot.
  const double reach = std::hypot(std::max(std::abs(geometry.frontX()), std::abs(geometry.backX())),
                                  geometry.halfWidth()) +
                       geometry.domeRadiusUnits + 1.0;
  for (std::size_t i : obstaclesNear(scene, centre, reach)) {
    Scene alone;
    alone.name = scene.name;
    alone.obstacles.push_back(scene.obstacles[i]);
    alone.start = scene.start;
    alone.goal = centre;
    Vec2 lo = centre - Vec2::Constant(4.0 * reach);
    Vec2 hi = centre + Vec2::Constant(4.0 * reach);
    for (const Vec2& v : scene.obstacles[i].polygon) {
      lo = lo.cwiseMin(v - Vec2(reach, reach));
      hi = hi.cwiseMax(v + Vec2(reach, reach));
    }
    alone.bounds = {lo.x(), lo.y(), hi.x(), hi.y()};
    Simulator one(std::make_shared<const World>(alone), config);
    if (one.isBlocked(scene.start)) return error("overlaps " + obstacleName(scene, i));
  }
  return error("overlaps the bounds (the walls)");
}

namespace {

// What the user typed names: a procedural scene (with its N and SEED), a built-in scene or a file;
// or why it names no scene at all (a usage problem).
struct SceneSpec {
  std::optional<std::string> usageProblem;
  bool procedural = false;
  bool office = false;
  std::int64_t obstacles = 0;
  std::int64_t seed = 0;
  bool builtin = false;
  bool file = false;
};

SceneSpec classifySpec(std::string_view spec) {
  SceneSpec out;
  if (spec.starts_with("random:office:")) {
    if (!parseInteger(spec.substr(14), out.seed) || out.seed < 0) {
      out.usageProblem = "scene '" + std::string(spec) +
                         "': expected random:office:SEED with an integer SEED >= 0";
    }
    out.office = true;
    return out;
  }
  if (spec.starts_with("random:")) {
    std::string_view rest = spec.substr(7);
    const std::size_t colon = rest.find(':');
    if (colon == std::string_view::npos || !parseInteger(rest.substr(0, colon), out.obstacles) ||
        !parseInteger(rest.substr(colon + 1), out.seed) || out.seed < 0) {
      out.usageProblem = "scene '" + std::string(spec) +
                         "': expected random:N:SEED with integers N >= 0 and SEED >= 0, "
                         "or random:office:SEED";
    } else if (out.obstacles < 0 ||
               static_cast<std::size_t>(out.obstacles) > kMaxProceduralObstacles) {
      out.usageProblem = "scene '" + std::string(spec) + "': N must be between 0 and " +
                         std::to_string(kMaxProceduralObstacles);
    }
    out.procedural = true;
    return out;
  }
  if (builtinSceneJson(spec)) {
    out.builtin = true;
    return out;
  }
  if (spec.find('/') != std::string_view::npos || spec.ends_with(".json") ||
      std::filesystem::exists(std::filesystem::path(std::string(spec)))) {
    out.file = true;
    return out;
  }
  std::string names;
  for (const std::string& n : builtinSceneNames())
    names += (names.empty() ? "" : ", ") + n;
  out.usageProblem = "unknown scene '" + std::string(spec) + "' (built-in scenes: " + names +
                     "; or a .json file, random:N:SEED or random:office:SEED)";
  return out;
}

}  // namespace

std::optional<std::string> sceneSpecError(std::string_view spec) {
  return classifySpec(spec).usageProblem;
}

Result<Scene> loadScene(std::string_view spec, const RobotGeometry& geometry) {
  const SceneSpec kind = classifySpec(spec);
  if (kind.usageProblem) return Error(*kind.usageProblem);
  Result<Scene> result = Error("");
  if (kind.office) {
    Scene office = generateOfficeScene(static_cast<std::uint64_t>(kind.seed)).scene;
    if (Status valid = validateSceneGeometry(office); !valid) {
      return Error(std::string(spec), valid.error().message);
    }
    result = std::move(office);
  } else if (kind.procedural) {
    result = generateProceduralScene(static_cast<std::size_t>(kind.obstacles),
                                     static_cast<std::uint64_t>(kind.seed));
  } else if (kind.builtin) {
    result = parseSceneJson(*builtinSceneJson(spec), spec);
  } else {
    Result<std::string> text = readFileText(std::filesystem::path(std::string(spec)));
    if (!text) return text.error();
    result = parseSceneJson(text.value(), spec);
  }
  if (!result.ok()) return result;
  if (Status start = checkStartPose(result.value(), geometry); !start) {
    return Error(std::string(spec), start.error().line, 0, start.error().message);
  }
  return result;
}

std::optional<std::string> proceduralSceneJson(const std::string& spec) {
  if (!spec.starts_with("random:")) return std::nullopt;
  Result<Scene> generated = loadScene(spec);
  if (!generated.ok()) return std::nullopt;
  return sceneToJson(generated.value());
}

}  // namespace tactile::sim
