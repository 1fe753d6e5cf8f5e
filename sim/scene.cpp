#include "sim/scene.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "base/text_rules.h"
#include "run/json_text.h"
#include "sim/polygon_check.h"

namespace tactile::sim {
namespace {

using nlohmann::json;

struct SchemaError {
  std::string message;
};

double number(const json& j, const std::string& what) {
  if (!j.is_number()) throw SchemaError{what + " must be a number"};
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw SchemaError{what + " must be finite"};
  return v;
}

const json& member(const json& obj, const char* key, const std::string& where) {
  auto it = obj.find(key);
  if (it == obj.end()) throw SchemaError{where + "missing \"" + key + "\""};
  return *it;
}

std::string obstacleLabel(std::size_t i) {
  return "obstacle " + std::to_string(i);
}

std::string validatePolygon(const std::vector<Vec2>& poly, std::size_t index,
                            const SceneBounds& b) {
  const std::string label = obstacleLabel(index);
  const std::size_t n = poly.size();
  if (n < 3) {
    return label + ": a polygon needs at least 3 vertices, found " + std::to_string(n);
  }
  for (std::size_t v = 0; v < n; ++v) {
    const Vec2& p = poly[v];
    if (p.x() < b.xmin || p.x() > b.xmax || p.y() < b.ymin || p.y() > b.ymax) {
      return label + " vertex " + std::to_string(v) + ": (" + std::to_string(p.x()) + ", " +
             std::to_string(p.y()) + ") lies outside the bounds";
    }
    if (poly[v] == poly[(v + 1) % n]) {
      return label + " vertex " + std::to_string(v) + ": repeats the next vertex (" +
             std::to_string((v + 1) % n) + ")";
    }
  }
  // Non-adjacent edges must not touch; adjacent edges may only share their common vertex.
  if (const std::optional<EdgePair> contact = polygonSelfContact(poly)) {
    const auto [i, j] = *contact;
    return label + ": edge from vertex " + std::to_string(i) + " to vertex " +
           std::to_string((i + 1) % n) + " crosses edge from vertex " + std::to_string(j) +
           " to vertex " + std::to_string((j + 1) % n) + " (self-intersecting polygon)";
  }
  double area2 = 0.0;
  for (std::size_t v = 0; v < n; ++v)
    area2 += cross2(poly[v], poly[(v + 1) % n]);
  if (area2 == 0.0) return label + ": the polygon has zero area";
  return {};
}

}  // namespace

std::string sceneNameProblem(std::string_view name) {
  // Scenes follow the one name rule of runs, label sets, models, sweeps and annotators.
  if (std::optional<std::string> problem = nameProblem(name)) return "a scene name " + *problem;
  return {};
}

namespace {

// The first geometry problem, or "".
std::string geometryProblem(const Scene& scene) {
  const SceneBounds& b = scene.bounds;
  if (!(b.xmin < b.xmax) || !(b.ymin < b.ymax)) {
    return "bounds: need xmin < xmax and ymin < ymax";
  }
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    std::string error = validatePolygon(scene.obstacles[i].polygon, i, b);
    if (!error.empty()) return error;
  }
  const auto inside = [&](double x, double y) {
    return x > b.xmin && x < b.xmax && y > b.ymin && y < b.ymax;
  };
  if (!inside(scene.start.x, scene.start.y)) return "start: (x, y) lies outside the bounds";
  if (!inside(scene.goal.x(), scene.goal.y())) return "goal: (x, y) lies outside the bounds";
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    if (pointInPolygon(scene.goal, scene.obstacles[i].polygon)) {
      return "goal: lies inside " + obstacleLabel(i);
    }
  }
  return {};
}

}  // namespace

Status validateSceneGeometry(const Scene& scene) {
  if (std::string problem = geometryProblem(scene); !problem.empty()) return Error(problem);
  return Status::success();
}

Result<Scene> parseSceneJson(std::string_view text, std::string_view sourceName) {
  const std::string source(sourceName);
  Result<json> parsed = parseJsonText(text, sourceName);
  if (!parsed) {
    Error error = parsed.error();
    error.message = "not valid JSON: " + error.message;
    return error;
  }
  const json& doc = parsed.value();
  Scene scene;
  try {
    if (!doc.is_object()) throw SchemaError{"the scene must be a JSON object"};
    const json& name = member(doc, "name", "");
    if (!name.is_string()) throw SchemaError{"\"name\" must be a string"};
    scene.name = name.get<std::string>();
    if (std::string problem = sceneNameProblem(scene.name); !problem.empty()) {
      throw SchemaError{"\"name\": " + problem};
    }
    const json& bounds = member(doc, "bounds", "");
    if (!bounds.is_array() || bounds.size() != 4) {
      throw SchemaError{"\"bounds\" must be [xmin, ymin, xmax, ymax]"};
    }
    scene.bounds = {number(bounds[0], "bounds[0]"), number(bounds[1], "bounds[1]"),
                    number(bounds[2], "bounds[2]"), number(bounds[3], "bounds[3]")};
    const json& obstacles = member(doc, "obstacles", "");
    if (!obstacles.is_array()) throw SchemaError{"\"obstacles\" must be an array"};
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      const std::string label = obstacleLabel(i);
      const json& o = obstacles[i];
      if (!o.is_object()) throw SchemaError{label + ": must be an object with a \"polygon\""};
      const json& poly = member(o, "polygon", label + ": ");
      if (!poly.is_array()) throw SchemaError{label + ": \"polygon\" must be an array of [x, y]"};
      Obstacle obstacle;
      for (std::size_t v = 0; v < poly.size(); ++v) {
        const std::string where = label + " vertex " + std::to_string(v);
        if (!poly[v].is_array() || poly[v].size() != 2) {
          throw SchemaError{where + ": must be [x, y]"};
        }
        obstacle.polygon.emplace_back(number(poly[v][0], where + " x"),
                                      number(poly[v][1], where + " y"));
      }
      scene.obstacles.push_back(std::move(obstacle));
    }
    const json& start = member(doc, "start", "");
    if (!start.is_object()) throw SchemaError{"\"start\" must be {\"x\", \"y\", \"theta\"}"};
    scene.start.x = number(member(start, "x", "start: "), "start.x");
    scene.start.y = number(member(start, "y", "start: "), "start.y");
    scene.start.theta = number(member(start, "theta", "start: "), "start.theta");
    const json& goal = member(doc, "goal", "");
    if (!goal.is_object()) throw SchemaError{"\"goal\" must be {\"x\", \"y\"}"};
    scene.goal = Vec2(number(member(goal, "x", "goal: "), "goal.x"),
                      number(member(goal, "y", "goal: "), "goal.y"));
  } catch (const SchemaError& e) {
    return Error(source, e.message);
  }
  if (Status valid = validateSceneGeometry(scene); !valid) {
    return Error(source, valid.error().message);
  }
  return scene;
}

std::string sceneToJson(const Scene& scene) {
  json doc;
  doc["name"] = scene.name;
  doc["bounds"] = {scene.bounds.xmin, scene.bounds.ymin, scene.bounds.xmax, scene.bounds.ymax};
  json obstacles = json::array();
  for (const Obstacle& o : scene.obstacles) {
    json poly = json::array();
    for (const Vec2& p : o.polygon)
      poly.push_back({p.x(), p.y()});
    obstacles.push_back({{"polygon", poly}});
  }
  doc["obstacles"] = obstacles;
  doc["start"] = {{"x", scene.start.x}, {"y", scene.start.y}, {"theta", scene.start.theta}};
  doc["goal"] = {{"x", scene.goal.x()}, {"y", scene.goal.y()}};
  return dumpJson(doc, 1) + "\n";
}

}  // namespace tactile::sim
