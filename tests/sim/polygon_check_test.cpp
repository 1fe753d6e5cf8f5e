// The sweep-line simplicity check against the pair-by-pair one, and the degenerate contacts.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "sim/polygon_check.h"
#include "sim/scene.h"

namespace tactile::sim {
namespace {

// A simple star-shaped polygon: n vertices at increasing angles, random radii, on an integer grid
// (exact arithmetic, and collinear and touching cases occur).
std::vector<Vec2> starPolygon(std::size_t n, std::mt19937& rng, double radius = 1000.0) {
  std::uniform_real_distribution<double> r(0.3 * radius, radius);
  std::vector<Vec2> poly;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    const double d = r(rng);
    poly.emplace_back(std::round(d * std::cos(a)), std::round(d * std::sin(a)));
  }
  // Rounding may repeat a vertex; drop consecutive repeats (the validator rejects those first).
  std::vector<Vec2> out;
  for (const Vec2& p : poly) {
    if (out.empty() || out.back() != p) out.push_back(p);
  }
  while (out.size() > 1 && out.front() == out.back())
    out.pop_back();
  return out;
}

bool consecutiveRepeat(const std::vector<Vec2>& poly) {
  for (std::size_t i = 0; i < poly.size(); ++i) {
    if (poly[i] == poly[(i + 1) % poly.size()]) return true;
  }
  return false;
}

TEST(PolygonCheck, SweepAgreesWithPairByPairOnRandomPolygons) {
  std::mt19937 rng(7);
  int simple = 0;
  int touching = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 4 + rng() % 300;
    std::vector<Vec2> poly = starPolygon(n, rng, trial % 2 == 0 ? 1000.0 : 30.0);
    // Damage some: move a vertex somewhere random, swap two vertices, or repeat one.
    const int kind = static_cast<int>(rng() % 4);
    std::uniform_int_distribution<std::size_t> pick(0, poly.size() - 1);
    if (kind == 1) {
      poly[pick(rng)] = poly[pick(rng)] * 0.5;
    } else if (kind == 2) {
      std::swap(poly[pick(rng)], poly[pick(rng)]);
    } else if (kind == 3) {
      poly[pick(rng)] = poly[pick(rng)];
    }
    poly[0] = Vec2(std::round(poly[0].x()), std::round(poly[0].y()));
    if (poly.size() < 3 || consecutiveRepeat(poly)) continue;
    const bool bruteSimple = !polygonSelfContactBruteForce(poly).has_value();
    const auto sweep = polygonSelfContactSweep(poly);
    ASSERT_EQ(bruteSimple, !sweep.has_value())
        << "trial " << trial << ", " << poly.size() << " vertices";
    if (sweep) {
      EXPECT_LT(sweep->first, sweep->second);
      EXPECT_LT(sweep->second, poly.size());
    }
    (bruteSimple ? simple : touching) += 1;
  }
  // Both outcomes were exercised.
  EXPECT_GT(simple, 50);
  EXPECT_GT(touching, 50);
}

TEST(PolygonCheck, DegenerateContactsAreFoundBySweep) {
  // Square 0..10 with a spike whose tip touches the opposite edge (T contact at (5, 0)), padded
  // with collinear vertices so that the sweep is used.
  auto padded = [](std::vector<Vec2> corners) {
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Vec2 a = corners[i];
      const Vec2 b = corners[(i + 1) % corners.size()];
      for (int k = 0; k < 100; ++k)
        out.push_back(a + (b - a) * (k / 100.0));
    }
    return out;
  };
  const auto tContact = padded({{0, 0}, {10, 0}, {10, 10}, {6, 10}, {5, 0.0}, {4, 10}, {0, 10}});
  ASSERT_GT(tContact.size(), kBruteForceEdges);
  EXPECT_TRUE(polygonSelfContactBruteForce(tContact).has_value());
  EXPECT_TRUE(polygonSelfContact(tContact).has_value());
  // A vertex visited twice (a pinch) and an edge running back along its neighbour.
  const auto pinch = padded({{0, 0}, {10, 0}, {5, 5}, {10, 10}, {0, 10}, {5, 5}});
  EXPECT_TRUE(polygonSelfContact(pinch).has_value());
  std::vector<Vec2> fold = padded({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  fold.insert(fold.begin() + 50, Vec2(1, 0));  // runs back from (5, 0) over the bottom edge
  EXPECT_TRUE(polygonSelfContact(fold).has_value());
  // The padded square itself is simple.
  EXPECT_FALSE(polygonSelfContact(padded({{0, 0}, {10, 0}, {10, 10}, {0, 10}})).has_value());
}

TEST(PolygonCheck, LargeSimplePolygonValidatesAndACrossingIsNamed) {
  std::mt19937 rng(3);
  std::vector<Vec2> poly = starPolygon(100000, rng, 1.0e6);
  ASSERT_FALSE(polygonSelfContact(poly).has_value());
  Scene scene;
  scene.name = "big";
  scene.bounds = {-2.0e6, -2.0e6, 2.0e6, 2.0e6};
  scene.obstacles.push_back({poly});
  scene.start = {1.5e6, 1.5e6, 0.0};
  scene.goal = Vec2(-1.5e6, -1.5e6);
  EXPECT_TRUE(validateSceneGeometry(scene).ok()) << validateSceneGeometry(scene).errorText();
  // Vertex 50,000 pulled to the far side crosses the polygon.
  scene.obstacles[0].polygon[50000] = Vec2(1.9e6, 1.0);
  const Status bad = validateSceneGeometry(scene);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.errorText().find("self-intersecting polygon"), std::string::npos)
      << bad.errorText();
}

TEST(SceneName, OneRuleForSceneNames) {
  EXPECT_EQ(sceneNameProblem("room 1 (copy) – Küche"), "");
  EXPECT_NE(sceneNameProblem("line\nbreak"), "");
  EXPECT_NE(sceneNameProblem("tab\there"), "");
  EXPECT_NE(sceneNameProblem("a,b"), "");
  EXPECT_NE(sceneNameProblem(""), "");
  EXPECT_NE(sceneNameProblem(std::string(201, 'a')), "");
  EXPECT_EQ(sceneNameProblem(std::string(200, 'a')), "");
  EXPECT_NE(sceneNameProblem("caf\xe9"), "");
  EXPECT_NE(sceneNameProblem("\xed\xa0\x80"), "");  // a surrogate
  EXPECT_NE(sceneNameProblem("\xc0\xaf"), "");      // overlong
  const std::string text =
      "{\"name\": \"two\\nlines\", \"bounds\": [0, 0, 1000, 1000], \"obstacles\": [], "
      "\"start\": {\"x\": 100, \"y\": 100, \"theta\": 0}, \"goal\": {\"x\": 900, \"y\": 900}}";
  const Result<Scene> parsed = parseSceneJson(text, "my.json");
  ASSERT_FALSE(parsed.ok());
  EXPECT_NE(parsed.errorText().find("my.json"), std::string::npos) << parsed.errorText();
  EXPECT_NE(parsed.errorText().find("control character"), std::string::npos) << parsed.errorText();
}

}  // namespace
}  // namespace tactile::sim
