#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run/builtin_scenes.h"
#include "sim/scene.h"
#include "sim/scene_source.h"

namespace tactile::sim {
namespace {

std::string sceneText(const std::string& obstacles, const std::string& start = "200, 500, 0",
                      const std::string& goal = "900, 500") {
  std::string s =
      "{\"name\": \"t\", \"bounds\": [0, 0, 1000, 1000], \"obstacles\": [" + obstacles + "], ";
  const auto comma1 = start.find(',');
  const auto comma2 = start.rfind(',');
  s += "\"start\": {\"x\": " + start.substr(0, comma1) +
       ", \"y\": " + start.substr(comma1 + 1, comma2 - comma1 - 1) +
       ", \"theta\": " + start.substr(comma2 + 1) + "}, ";
  const auto c = goal.find(',');
  s += "\"goal\": {\"x\": " + goal.substr(0, c) + ", \"y\": " + goal.substr(c + 1) + "}}";
  return s;
}

TEST(SceneJson, ParsesAValidScene) {
  Result<Scene> r =
      parseSceneJson(sceneText("{\"polygon\": [[500,500],[600,500],[600,600]]}"), "f");
  ASSERT_TRUE(r.ok()) << r.errorText();
  EXPECT_EQ(r->name, "t");
  ASSERT_EQ(r->obstacles.size(), 1u);
  EXPECT_EQ(r->obstacles[0].polygon[1], Vec2(600, 500));
  EXPECT_DOUBLE_EQ(r->goal.x(), 900.0);
  EXPECT_DOUBLE_EQ(r->start.y, 500.0);
}

TEST(SceneJson, InvalidJsonNamesTheSource) {
  Result<Scene> r = parseSceneJson("{\"name\": ", "bad.json");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("bad.json"), std::string::npos);
  EXPECT_NE(r.errorText().find("not valid JSON"), std::string::npos);
}

TEST(SceneJson, MissingKeyIsNamed) {
  Result<Scene> r =
      parseSceneJson("{\"name\": \"x\", \"bounds\": [0,0,1,1], \"obstacles\": []}", "f");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("missing \"start\""), std::string::npos) << r.errorText();
}

TEST(SceneJson, NonNumericVertexNamesObstacleAndVertex) {
  Result<Scene> r = parseSceneJson(
      sceneText("{\"polygon\": [[1,1],[5,1],[5,5]]}, {\"polygon\": [[1,1],[\"a\",1],[5,5]]}"), "f");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("obstacle 1 vertex 1"), std::string::npos) << r.errorText();
}

TEST(SceneJson, VertexOutsideBoundsNamesObstacleAndVertex) {
  Result<Scene> r =
      parseSceneJson(sceneText("{\"polygon\": [[500,500],[600,500],[1600,600]]}"), "f");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("obstacle 0 vertex 2"), std::string::npos) << r.errorText();
  EXPECT_NE(r.errorText().find("outside the bounds"), std::string::npos) << r.errorText();
}

TEST(SceneJson, SelfIntersectingPolygonNamesTheEdges) {
  // A bow tie: edge 0-1 crosses edge 2-3.
  Result<Scene> r =
      parseSceneJson(sceneText("{\"polygon\": [[500,500],[600,600],[600,500],[500,600]]}"), "f");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(
      r.errorText().find("obstacle 0: edge from vertex 0 to vertex 1 crosses edge from vertex 2 "
                         "to vertex 3"),
      std::string::npos)
      << r.errorText();
}

TEST(SceneJson, RepeatedVertexIsNamed) {
  Result<Scene> r =
      parseSceneJson(sceneText("{\"polygon\": [[500,500],[600,500],[600,500],[600,600]]}"), "f");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("obstacle 0 vertex 1: repeats"), std::string::npos) << r.errorText();
}

TEST(SceneJson, TwoVerticesAreNotAPolygon) {
  Result<Scene> r = parseSceneJson(sceneText("{\"polygon\": [[500,500],[600,500]]}"), "f");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("at least 3 vertices"), std::string::npos) << r.errorText();
}

TEST(SceneJson, ZeroAreaPolygonIsRejected) {
  Result<Scene> r =
      parseSceneJson(sceneText("{\"polygon\": [[500,500],[600,500],[700,500]]}"), "f");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("obstacle 0"), std::string::npos) << r.errorText();
}

TEST(SceneJson, GoalOutsideBoundsIsRejected) {
  Result<Scene> r = parseSceneJson(sceneText("", "200, 500, 0", "1200, 500"), "f");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("goal"), std::string::npos) << r.errorText();
}

TEST(SceneJson, GoalInsideObstacleIsRejected) {
  Result<Scene> r = parseSceneJson(
      sceneText("{\"polygon\": [[800,400],[950,400],[950,600],[800,600]]}", "200, 500, 0"), "f");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("goal: lies inside obstacle 0"), std::string::npos) << r.errorText();
}

TEST(SceneJson, BoundsMustBeOrdered) {
  Result<Scene> r = parseSceneJson(
      "{\"name\":\"x\",\"bounds\":[10,0,0,10],\"obstacles\":[],\"start\":{\"x\":1,\"y\":1,"
      "\"theta\":0},\"goal\":{\"x\":2,\"y\":2}}",
      "f");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("bounds"), std::string::npos) << r.errorText();
}

TEST(SceneSource, StartPoseInObstacleIsAFileError) {
  Scene s;
  s.name = "x";
  s.bounds = {0, 0, 1000, 1000};
  s.obstacles.push_back(Obstacle{{Vec2(250, 450), Vec2(300, 450), Vec2(300, 550), Vec2(250, 550)}});
  s.start = {200, 500, 0};
  s.goal = Vec2(900, 500);
  EXPECT_NE(checkStartPose(s).errorText().find("overlaps"), std::string::npos);
  s.start = {200, 500, 3.14159};
  s.obstacles[0] = Obstacle{{Vec2(600, 450), Vec2(700, 450), Vec2(700, 550), Vec2(600, 550)}};
  EXPECT_TRUE(checkStartPose(s).ok());
}

TEST(SceneSource, StartTooCloseToTheBoundsIsRejected) {
  Scene s;
  s.name = "x";
  s.bounds = {0, 0, 1000, 1000};
  s.start = {10, 500, 0};  // the back overhangs the wall at x = 0
  s.goal = Vec2(900, 500);
  EXPECT_FALSE(checkStartPose(s).ok());
}

TEST(SceneSource, UnknownNameIsAUsageError) {
  Result<Scene> r = loadScene("no-such-scene");
  ASSERT_FALSE(r.ok());
  ASSERT_TRUE(sceneSpecError("no-such-scene").has_value());
  EXPECT_NE(sceneSpecError("no-such-scene")->find("practice"), std::string::npos);
  EXPECT_NE(r.errorText().find("practice"), std::string::npos) << r.errorText();
}

TEST(SceneSource, MissingFileIsNotAUsageError) {
  Result<Scene> r = loadScene("/nonexistent/dir/scene.json");
  ASSERT_FALSE(r.ok());
  EXPECT_FALSE(sceneSpecError("/nonexistent/dir/scene.json").has_value());
  EXPECT_EQ(r.error().file, "/nonexistent/dir/scene.json");
  EXPECT_NE(r.errorText().find("/nonexistent/dir/scene.json"), std::string::npos);
}

TEST(SceneSource, MalformedRandomSpecIsAUsageError) {
  for (const char* spec : {"random:", "random:10", "random:x:1", "random:-5:1", "random:10:-1",
                           "random:10001:1", "random:10:1:2"}) {
    Result<Scene> r = loadScene(spec);
    EXPECT_FALSE(r.ok()) << spec;
    EXPECT_TRUE(sceneSpecError(spec).has_value()) << spec;
  }
}

TEST(SceneSource, EveryBuiltinSceneLoads) {
  const std::vector<std::string> names = builtinSceneNames();
  for (const char* required : {"practice", "room1", "room2", "room3", "chapter5"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
  }
  for (const std::string& name : names) {
    Result<Scene> r = loadScene(name);
    EXPECT_TRUE(r.ok()) << name << ": " << r.errorText();
  }
}

TEST(Procedural, HasTheRequestedObstacleCountAndIsValid) {
  for (std::size_t n : {0u, 1u, 10u, 500u}) {
    const Scene s = generateProceduralScene(n, 3);
    EXPECT_EQ(s.obstacles.size(), n);
    EXPECT_TRUE(validateSceneGeometry(s).ok()) << n;
    EXPECT_TRUE(checkStartPose(s).ok()) << n;
  }
}

TEST(Procedural, DensityIsConstant) {
  const Scene a = generateProceduralScene(100, 1);
  const Scene b = generateProceduralScene(10000, 1);
  const auto density = [](const Scene& s) {
    const double area = (s.bounds.xmax - s.bounds.xmin) * (s.bounds.ymax - s.bounds.ymin);
    return static_cast<double>(s.obstacles.size()) / area;
  };
  EXPECT_NEAR(density(a) / density(b), 1.0, 0.25);
}

TEST(Procedural, SameSeedSameSceneOtherSeedOtherScene) {
  EXPECT_EQ(sceneToJson(generateProceduralScene(50, 9)),
            sceneToJson(generateProceduralScene(50, 9)));
  EXPECT_NE(sceneToJson(generateProceduralScene(50, 9)),
            sceneToJson(generateProceduralScene(50, 10)));
}

TEST(Procedural, JsonRoundTripIsExact) {
  const Scene s = generateProceduralScene(30, 4);
  Result<Scene> r = parseSceneJson(sceneToJson(s), "roundtrip");
  ASSERT_TRUE(r.ok()) << r.errorText();
  EXPECT_EQ(sceneToJson(r.value()), sceneToJson(s));
}

// Regression: 1e400 in a scene threw out of the reader without the file's name.
TEST(SceneHostile, NumberOverflowNamesFileAndLine) {
  const std::string text =
      "{\"name\": \"s\",\n \"bounds\": [0, 0, 1e400, 100],\n \"obstacles\": [],\n"
      " \"start\": {\"x\": 1, \"y\": 1, \"theta\": 0},\n \"goal\": {\"x\": 2, \"y\": 2}}\n";
  const auto r = parseSceneJson(text, "big.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().file, "big.json");
  EXPECT_EQ(r.error().line, 2u) << r.errorText();
  EXPECT_NE(r.errorText().find("overflow"), std::string::npos) << r.errorText();
}

// A scene text with one obstacle per line, the start on its own line, for line numbers.
std::string sceneLines(const std::vector<std::string>& obstacles, const std::string& start) {
  std::string s = "{\"name\": \"t\",\n \"bounds\": [0, 0, 1000, 1000],\n \"obstacles\": [\n";
  for (std::size_t i = 0; i < obstacles.size(); ++i)
    s += "  {\"polygon\": " + obstacles[i] + (i + 1 < obstacles.size() ? "},\n" : "}\n");
  s += " ],\n \"start\": " + start + ",\n \"goal\": {\"x\": 900, \"y\": 500}}\n";
  return s;
}

Result<Scene> loadSceneText(const std::string& text, const std::string& name) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() /
      ("tactile_scene_test_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path) << text;
  Result<Scene> r = loadScene(path.string());
  std::filesystem::remove(path);
  return r;
}

// Regression: a start wholly inside a solid box touched none of its edges and was accepted; the
// robot then drove inside the box with domes pressed while truth said NoContact.
TEST(SceneSource, StartInsideAnObstacleIsRefusedNamingItAndItsLine) {
  const std::string box = "[[50, 50], [700, 50], [700, 950], [50, 950]]";
  const std::string small = "[[800, 800], [850, 800], [850, 850]]";
  const std::string text = sceneLines({small, box}, "{\"x\": 200, \"y\": 500, \"theta\": 0}");
  const Result<Scene> r = loadSceneText(text, "inside.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 7u) << r.errorText();  // the line of "start"
  EXPECT_NE(r.errorText().find("inside obstacle 1 (line 5)"), std::string::npos) << r.errorText();
  EXPECT_NE(r.errorText().find("inside.json:7: start:"), std::string::npos) << r.errorText();

  // The edge-overlap case names the obstacle too.
  const std::string post = "[[250, 450], [300, 450], [300, 550], [250, 550]]";
  const Result<Scene> o =
      loadSceneText(sceneLines({small, post}, "{\"x\": 200, \"y\": 500, \"theta\": 0}"), "o.json");
  ASSERT_FALSE(o.ok());
  EXPECT_NE(o.errorText().find("overlaps obstacle 1 (line 5)"), std::string::npos) << o.errorText();
  // And the walls are named as such.
  const Result<Scene> w =
      loadSceneText(sceneLines({small}, "{\"x\": 10, \"y\": 500, \"theta\": 0}"), "w.json");
  ASSERT_FALSE(w.ok());
  EXPECT_NE(w.errorText().find("overlaps the bounds"), std::string::npos) << w.errorText();
  // The same scene with the robot beside the box loads.
  EXPECT_TRUE(
      loadSceneText(sceneLines({small, box}, "{\"x\": 800, \"y\": 500, \"theta\": 0}"), "ok.json")
          .ok());
}

// Regression: bounds of +-1.7e308 were accepted (the width overflowed to infinity).
TEST(SceneHostile, CoordinatesBeyondTheDocumentedRangeAreRefusedAtTheirLine) {
  const std::string text =
      "{\"name\": \"s\",\n \"bounds\": [-1.7e308, -1.7e308,\n 1.7e308, 1.7e308],\n"
      " \"obstacles\": [],\n \"start\": {\"x\": 1, \"y\": 1, \"theta\": 0},\n"
      " \"goal\": {\"x\": 2, \"y\": 2}}\n";
  const auto r = parseSceneJson(text, "huge.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 2u) << r.errorText();
  EXPECT_NE(r.errorText().find("bounds[0]"), std::string::npos) << r.errorText();
  EXPECT_NE(r.errorText().find("within +-10000000"), std::string::npos) << r.errorText();
  const std::string vertex =
      "{\"name\": \"s\",\n \"bounds\": [0, 0, 100, 100],\n \"obstacles\": [\n"
      "  {\"polygon\": [[1, 1], [2, 1],\n [2, 2e9]]}],\n \"start\": {\"x\": 50, \"y\": 50, "
      "\"theta\": 0},\n"
      " \"goal\": {\"x\": 60, \"y\": 60}}\n";
  const auto v = parseSceneJson(vertex, "v.json");
  ASSERT_FALSE(v.ok());
  EXPECT_EQ(v.error().line, 5u) << v.errorText();
  EXPECT_NE(v.errorText().find("obstacle 0 vertex 2 y"), std::string::npos) << v.errorText();
  // The limit itself is in range; so is every coordinate of a scene built in memory.
  Scene s;
  s.name = "s";
  s.bounds = {-kMaxSceneCoordinate, -kMaxSceneCoordinate, kMaxSceneCoordinate, kMaxSceneCoordinate};
  s.start = {0, 0, 0};
  s.goal = Vec2(1000, 0);
  EXPECT_TRUE(validateSceneGeometry(s).ok());
  s.bounds.xmax = 1.7e308;
  EXPECT_FALSE(validateSceneGeometry(s).ok());
}

// A scene that is not the product's own: the error says where.
TEST(SceneHostile, SchemaErrorsNameTheLine) {
  const std::string text =
      "{\"name\": \"s\",\n \"bounds\": [0, 0, 100, 100],\n \"obstacles\": [],\n"
      " \"start\": {\"x\": 1, \"y\": \"one\", \"theta\": 0},\n \"goal\": {\"x\": 2, \"y\": 2}}\n";
  const auto r = parseSceneJson(text, "s.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errorText(), "s.json:4: start.y must be a number");
}

}  // namespace
}  // namespace tactile::sim
