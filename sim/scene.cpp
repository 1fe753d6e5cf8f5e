#include "sim/scene.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>

#include "base/text_rules.h"
#include "run/json_text.h"
#include "sim/polygon_check.h"

namespace tactile::sim {
namespace {

using nlohmann::json;

// Shortest round-trip text of a number ("1e+07" is written "10000000", "1.7e308" as is).
std::string formatShortest(double v) {
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, end) : std::to_string(v);
}

// A problem and the JSON pointer of the element it is about ("" for the whole document).
struct SchemaError {
  std::string message;
  std::string pointer;
};

// A limit as written in the docs ("10000000", not "1e+07").
std::string limitText(double limit) {
  char buffer[64];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, limit, std::chars_format::fixed);
  return ec == std::errc() ? std::string(buffer, end) : formatShortest(limit);
}

// "within +-10000000" for messages.
std::string coordinateRange() {
  return "within +-" + limitText(kMaxSceneCoordinate);
}

double number(const json& j, const std::string& what, const std::string& pointer,
              double limit = kMaxSceneCoordinate) {
  if (!j.is_number()) throw SchemaError{what + " must be a number", pointer};
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw SchemaError{what + " must be finite", pointer};
  if (!(std::abs(v) <= limit)) {
    throw SchemaError{
        what + " is " + formatShortest(v) + ": scene values lie within +-" + limitText(limit),
        pointer};
  }
  return v;
}

const json& member(const json& obj, const char* key, const std::string& where,
                   const std::string& pointer) {
  auto it = obj.find(key);
  if (it == obj.end()) throw SchemaError{where + "missing \"" + key + "\"", pointer};
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

// Whether every coordinate is finite and within +-kMaxSceneCoordinate (theta within
// +-kMaxSceneAngle); the first one that is not, as a problem, or an empty message.
SchemaError rangeProblem(const Scene& scene) {
  const auto out = [](double v, double limit) { return !(std::abs(v) <= limit); };
  const SceneBounds& b = scene.bounds;
  for (double v : {b.xmin, b.ymin, b.xmax, b.ymax}) {
    if (out(v, kMaxSceneCoordinate)) {
      return {"bounds: " + formatShortest(v) + " is not " + coordinateRange(), "/bounds"};
    }
  }
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    const std::vector<Vec2>& poly = scene.obstacles[i].polygon;
    for (std::size_t v = 0; v < poly.size(); ++v) {
      if (out(poly[v].x(), kMaxSceneCoordinate) || out(poly[v].y(), kMaxSceneCoordinate)) {
        return {obstacleLabel(i) + " vertex " + std::to_string(v) + ": not " + coordinateRange(),
                "/obstacles/" + std::to_string(i) + "/polygon/" + std::to_string(v)};
      }
    }
  }
  if (out(scene.start.x, kMaxSceneCoordinate) || out(scene.start.y, kMaxSceneCoordinate) ||
      out(scene.start.theta, kMaxSceneAngle)) {
    return {"start: (x, y) not " + coordinateRange() + " or theta not within +-" +
                limitText(kMaxSceneAngle),
            "/start"};
  }
  if (out(scene.goal.x(), kMaxSceneCoordinate) || out(scene.goal.y(), kMaxSceneCoordinate)) {
    return {"goal: (x, y) not " + coordinateRange(), "/goal"};
  }
  return {};
}

// The first geometry problem, or one with an empty message.
SchemaError geometryProblem(const Scene& scene) {
  if (SchemaError range = rangeProblem(scene); !range.message.empty()) return range;
  const SceneBounds& b = scene.bounds;
  if (!(b.xmin < b.xmax) || !(b.ymin < b.ymax)) {
    return {"bounds: need xmin < xmax and ymin < ymax", "/bounds"};
  }
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    std::string error = validatePolygon(scene.obstacles[i].polygon, i, b);
    if (!error.empty()) return {error, "/obstacles/" + std::to_string(i)};
  }
  const auto inside = [&](double x, double y) {
    return x > b.xmin && x < b.xmax && y > b.ymin && y < b.ymax;
  };
  if (!inside(scene.start.x, scene.start.y)) {
    return {"start: (x, y) lies outside the bounds", "/start"};
  }
  if (!inside(scene.goal.x(), scene.goal.y())) {
    return {"goal: (x, y) lies outside the bounds", "/goal"};
  }
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    if (pointInPolygon(scene.goal, scene.obstacles[i].polygon)) {
      return {"goal: lies inside " + obstacleLabel(i), "/goal"};
    }
  }
  return {};
}

}  // namespace

Status validateSceneGeometry(const Scene& scene) {
  if (SchemaError problem = geometryProblem(scene); !problem.message.empty()) {
    return Error(problem.message);
  }
  return Status::success();
}

Result<Scene> parseSceneJson(std::string_view text, std::string_view sourceName) {
  const std::string source(sourceName);
  JsonLines lines;
  Result<json> parsed = parseJsonText(text, sourceName, &lines);
  if (!parsed) {
    Error error = parsed.error();
    error.message = "not valid JSON: " + error.message;
    return error;
  }
  const json& doc = parsed.value();
  Scene scene;
  // An error at the line of the element it is about (or of the nearest enclosing one).
  const auto located = [&](const SchemaError& e) {
    std::string pointer = e.pointer;
    while (!pointer.empty() && lines.lineOf(pointer) == 0)
      pointer.erase(pointer.rfind('/'));
    return Error(source, std::max<std::size_t>(lines.lineOf(pointer), 1), 0, e.message);
  };
  try {
    if (!doc.is_object()) throw SchemaError{"the scene must be a JSON object", ""};
    const json& name = member(doc, "name", "", "");
    if (!name.is_string()) throw SchemaError{"\"name\" must be a string", "/name"};
    scene.name = name.get<std::string>();
    if (std::string problem = sceneNameProblem(scene.name); !problem.empty()) {
      throw SchemaError{"\"name\": " + problem, "/name"};
    }
    const json& bounds = member(doc, "bounds", "", "");
    if (!bounds.is_array() || bounds.size() != 4) {
      throw SchemaError{"\"bounds\" must be [xmin, ymin, xmax, ymax]", "/bounds"};
    }
    scene.bounds = {
        number(bounds[0], "bounds[0]", "/bounds/0"), number(bounds[1], "bounds[1]", "/bounds/1"),
        number(bounds[2], "bounds[2]", "/bounds/2"), number(bounds[3], "bounds[3]", "/bounds/3")};
    const json& obstacles = member(doc, "obstacles", "", "");
    if (!obstacles.is_array()) throw SchemaError{"\"obstacles\" must be an array", "/obstacles"};
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      const std::string label = obstacleLabel(i);
      const std::string pointer = "/obstacles/" + std::to_string(i);
      const json& o = obstacles[i];
      if (!o.is_object()) {
        throw SchemaError{label + ": must be an object with a \"polygon\"", pointer};
      }
      const json& poly = member(o, "polygon", label + ": ", pointer);
      if (!poly.is_array()) {
        throw SchemaError{label + ": \"polygon\" must be an array of [x, y]", pointer + "/polygon"};
      }
      Obstacle obstacle;
      obstacle.line = lines.lineOf(pointer);
      for (std::size_t v = 0; v < poly.size(); ++v) {
        const std::string where = label + " vertex " + std::to_string(v);
        const std::string at = pointer + "/polygon/" + std::to_string(v);
        if (!poly[v].is_array() || poly[v].size() != 2) {
          throw SchemaError{where + ": must be [x, y]", at};
        }
        obstacle.polygon.emplace_back(number(poly[v][0], where + " x", at + "/0"),
                                      number(poly[v][1], where + " y", at + "/1"));
      }
      scene.obstacles.push_back(std::move(obstacle));
    }
    const json& start = member(doc, "start", "", "");
    if (!start.is_object()) {
      throw SchemaError{"\"start\" must be {\"x\", \"y\", \"theta\"}", "/start"};
    }
    scene.startLine = lines.lineOf("/start");
    scene.start.x = number(member(start, "x", "start: ", "/start"), "start.x", "/start/x");
    scene.start.y = number(member(start, "y", "start: ", "/start"), "start.y", "/start/y");
    scene.start.theta = number(member(start, "theta", "start: ", "/start"), "start.theta",
                               "/start/theta", kMaxSceneAngle);
    const json& goal = member(doc, "goal", "", "");
    if (!goal.is_object()) throw SchemaError{"\"goal\" must be {\"x\", \"y\"}", "/goal"};
    scene.goal = Vec2(number(member(goal, "x", "goal: ", "/goal"), "goal.x", "/goal/x"),
                      number(member(goal, "y", "goal: ", "/goal"), "goal.y", "/goal/y"));
  } catch (const SchemaError& e) {
    return located(e);
  }
  if (SchemaError problem = geometryProblem(scene); !problem.message.empty()) {
    return located(problem);
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
