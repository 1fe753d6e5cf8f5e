#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "sim/clearance_grid.h"
#include "sim/office_scene.h"
#include "sim/scene.h"
#include "sim/scene_source.h"
#include "sim_test_util.h"

namespace tactile::sim {
namespace {

using test::box;
using test::roomWith;

constexpr int kSeeds = 200;

// FNV-1a over the text: a stable fingerprint (std::hash differs between standard libraries).
std::uint64_t fingerprint(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

// Every edge of the scene, the bounds included.
std::vector<std::pair<Vec2, Vec2>> edgesOf(const Scene& s) {
  std::vector<std::pair<Vec2, Vec2>> out;
  const SceneBounds& b = s.bounds;
  const Vec2 c[4] = {Vec2(b.xmin, b.ymin), Vec2(b.xmax, b.ymin), Vec2(b.xmax, b.ymax),
                     Vec2(b.xmin, b.ymax)};
  for (int i = 0; i < 4; ++i)
    out.emplace_back(c[i], c[(i + 1) % 4]);
  for (const Obstacle& o : s.obstacles) {
    for (std::size_t i = 0; i < o.polygon.size(); ++i)
      out.emplace_back(o.polygon[i], o.polygon[(i + 1) % o.polygon.size()]);
  }
  return out;
}

bool anyEdgeHits(const Scene& s, const Vec2& lo, const Vec2& hi) {
  for (const auto& [a, b] : edgesOf(s)) {
    if (segmentHitsBox(a, b, lo, hi)) return true;
  }
  return false;
}

// Distance from p to the nearest obstacle edge or bound.
double clearance(const Scene& s, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : edgesOf(s))
    best = std::min(best, std::sqrt(pointSegmentDistance2(p, a, b)));
  return best;
}

// The box round an opening: `along` either side of its centre along the wall, `across` either
// side of the wall's middle.
std::pair<Vec2, Vec2> openingBox(const OfficeOpening& o, double along, double across) {
  const Vec2 half = o.wallAlongX ? Vec2(along, across) : Vec2(across, along);
  return {o.centre - half, o.centre + half};
}

bool concave(const std::vector<Vec2>& poly) {
  int pos = 0, neg = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % poly.size()];
    const Vec2& c = poly[(i + 2) % poly.size()];
    const double z = cross2(b - a, c - b);
    pos += z > 0.0;
    neg += z < 0.0;
  }
  return pos > 0 && neg > 0;
}

TEST(OfficeScene, SameSeedGivesTheSameJsonOtherSeedsDiffer) {
  std::set<std::string> seen;
  for (std::uint64_t seed : {0ull, 1ull, 2ull, 77ull, 900000ull}) {
    const std::string a = sceneToJson(generateOfficeScene(seed).scene);
    const std::string b = sceneToJson(generateOfficeScene(seed).scene);
    EXPECT_EQ(a, b) << seed;
    seen.insert(a);
  }
  EXPECT_EQ(seen.size(), 5u);
}

TEST(OfficeScene, JsonReproducesTheSceneExactly) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Scene s = generateOfficeScene(seed).scene;
    Result<Scene> back = parseSceneJson(sceneToJson(s), "office");
    ASSERT_TRUE(back.ok()) << back.errorText();
    ASSERT_EQ(back->obstacles.size(), s.obstacles.size());
    for (std::size_t i = 0; i < s.obstacles.size(); ++i)
      EXPECT_EQ(back->obstacles[i].polygon, s.obstacles[i].polygon) << seed << " " << i;
    EXPECT_EQ(sceneToJson(back.value()), sceneToJson(s));
  }
}

TEST(OfficeScene, TwoHundredSeedsAreValidConnectedAndStartInFreeSpace) {
  const OfficeOptions options;
  const double radius = options.robotHalfWidthUnits + options.marginUnits;
  for (int seed = 0; seed < kSeeds; ++seed) {
    const OfficeScene office = generateOfficeScene(static_cast<std::uint64_t>(seed));
    const Scene& s = office.scene;
    ASSERT_TRUE(validateSceneGeometry(s).ok())
        << seed << ": " << validateSceneGeometry(s).error().message;
    ASSERT_TRUE(checkStartPose(s).ok()) << seed;
    EXPECT_TRUE(office.connected) << seed;
    const Vec2 start(s.start.x, s.start.y);
    // The robot can turn in place at the start (its outline reaches 131 units with the domes).
    EXPECT_GE(clearance(s, start), 131.0) << seed;
    EXPECT_GE(clearance(s, s.goal), 60.0) << seed;
    for (const Obstacle& o : s.obstacles) {
      EXPECT_FALSE(pointInPolygon(start, o.polygon)) << seed;
      EXPECT_FALSE(pointInPolygon(s.goal, o.polygon)) << seed;
    }
    // Connected on an independent grid of the inflated map.
    const ClearanceGrid grid(s, radius, 10.0);
    EXPECT_TRUE(grid.connected(start, s.goal)) << seed;
    EXPECT_GE(office.rooms, 2u) << seed;
  }
}

TEST(OfficeScene, DoorsArePassableAndNarrowGapsAreNot) {
  int doors = 0, gaps = 0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    const OfficeScene office = generateOfficeScene(static_cast<std::uint64_t>(seed));
    const Scene& s = office.scene;
    for (const OfficeOpening& o : office.openings) {
      const double t = 0.5 * o.wallThicknessUnits;
      if (o.kind == OfficeOpening::Kind::Door) {
        ++doors;
        EXPECT_GE(o.widthUnits, 110.0);
        // A corridor 110 wide through the door, reaching 150 units either side of the wall, is
        // free of every edge.
        const auto [lo, hi] = openingBox(o, 55.0, t + 150.0);
        EXPECT_FALSE(anyEdgeHits(s, lo, hi))
            << "seed " << seed << " door at " << o.centre.x() << ", " << o.centre.y();
      } else {
        ++gaps;
        EXPECT_GE(o.widthUnits, 60.0);
        EXPECT_LE(o.widthUnits, 90.0);
        // The wall's ends lie within 46 units (half the robot with its domes) of the gap's centre:
        // the robot does not fit.
        const auto [lo, hi] = openingBox(o, 46.0, t - 1.0);
        EXPECT_TRUE(anyEdgeHits(s, lo, hi)) << "seed " << seed;
        // But it is a real gap: nothing fills it.
        const auto [glo, ghi] = openingBox(o, 0.5 * o.widthUnits - 1.0, t + 60.0);
        EXPECT_FALSE(anyEdgeHits(s, glo, ghi)) << "seed " << seed;
      }
    }
  }
  EXPECT_GE(doors, kSeeds);
  EXPECT_GE(gaps, kSeeds / 2);
}

TEST(OfficeScene, FurnitureHasVariedShapes) {
  int lShapes = 0, eightConcave = 0, convexPolygons = 0, thin = 0, turned = 0, bumps = 0;
  for (int seed = 0; seed < 50; ++seed) {
    const OfficeScene office = generateOfficeScene(static_cast<std::uint64_t>(seed));
    bumps += static_cast<int>(office.bumps);
    const auto& obstacles = office.scene.obstacles;
    ASSERT_GE(obstacles.size(), office.furniture);
    // Furniture comes last.
    for (std::size_t i = obstacles.size() - office.furniture; i < obstacles.size(); ++i) {
      const auto& p = obstacles[i].polygon;
      if (p.size() == 6 && concave(p)) ++lShapes;
      if (p.size() == 8 && concave(p)) ++eightConcave;  // U and T shapes
      if (!concave(p) && p.size() >= 3 && p.size() != 4) ++convexPolygons;
      int axisAligned = 0;
      for (std::size_t k = 0; k < p.size(); ++k) {
        const Vec2 d = p[(k + 1) % p.size()] - p[k];
        axisAligned += d.x() == 0.0 || d.y() == 0.0;
      }
      if (axisAligned == 0 && p.size() == 4) ++turned;
      if (p.size() == 4 && axisAligned == 4) {
        const double w = std::abs(p[2].x() - p[0].x());
        const double h = std::abs(p[2].y() - p[0].y());
        if (std::min(w, h) <= 15.0 && std::max(w, h) >= 150.0) ++thin;
      }
    }
  }
  EXPECT_GE(lShapes, 10);
  EXPECT_GE(eightConcave, 10);
  EXPECT_GE(convexPolygons, 10);
  EXPECT_GE(thin, 10);
  EXPECT_GE(turned, 5);
  EXPECT_GE(bumps, 100);
}

TEST(OfficeScene, SpecLoadsAndImportsTheSameScene) {
  Result<Scene> loaded = loadScene("random:office:42");
  ASSERT_TRUE(loaded.ok()) << loaded.errorText();
  EXPECT_EQ(loaded->name, "random:office:42");
  EXPECT_EQ(sceneToJson(loaded.value()), sceneToJson(generateOfficeScene(42).scene));
  const std::optional<std::string> json = proceduralSceneJson("random:office:42");
  ASSERT_TRUE(json.has_value());
  EXPECT_EQ(*json, sceneToJson(loaded.value()));
  for (const char* spec : {"random:office:", "random:office:x", "random:office:-1",
                           "random:office:1:2", "random:offices:1"}) {
    EXPECT_TRUE(sceneSpecError(spec).has_value()) << spec;
    EXPECT_FALSE(loadScene(spec).ok()) << spec;
  }
}

TEST(OfficeScene, CountedRandomScenesAreUnchanged) {
  // Runs recorded earlier name `random:N:SEED` in their metadata and are imported again by
  // generating the scene: its geometry must never change. Fingerprints of the JSON as generated
  // before the office generator was added.
  EXPECT_EQ(fingerprint(sceneToJson(generateProceduralScene(40, 7))), 6046219608642372047ull);
  EXPECT_EQ(fingerprint(sceneToJson(generateProceduralScene(80, 11))), 8314399039106604736ull);
}

TEST(ClearanceGrid, GapsWiderThanTheInflatedRobotConnect) {
  // A wall across the room at x 1000..1020 with one gap; the robot on the left, goal on the right.
  const auto wallWithGap = [](double gap) {
    return roomWith({box(1000, 0, 1020, 1000 - gap / 2), box(1000, 1000 + gap / 2, 1020, 2000)},
                    Pose2d{500, 1000, 0});
  };
  const Vec2 left(500, 1000), right(1500, 1000);
  EXPECT_TRUE(ClearanceGrid(wallWithGap(120), 50.0, 10.0).connected(left, right));
  EXPECT_FALSE(ClearanceGrid(wallWithGap(90), 50.0, 10.0).connected(left, right));
  EXPECT_TRUE(ClearanceGrid(wallWithGap(90), 40.0, 10.0).connected(left, right));
}

TEST(ClearanceGrid, EnclosedGoalIsNotConnectedAndOccupiedCellsAreNot) {
  Scene s = roomWith({box(1400, 1400, 1800, 1420), box(1400, 1780, 1800, 1800),
                      box(1400, 1400, 1420, 1800), box(1780, 1400, 1800, 1800)});
  const ClearanceGrid grid(s, 50.0, 10.0);
  EXPECT_FALSE(grid.connected(Vec2(500, 500), Vec2(1600, 1600)));
  EXPECT_TRUE(grid.connected(Vec2(500, 500), Vec2(1000, 1900 - 60)));
  // Inside a wall, near the bounds, outside the bounds.
  EXPECT_FALSE(grid.connected(Vec2(500, 500), Vec2(1410, 1600)));
  EXPECT_FALSE(grid.connected(Vec2(500, 500), Vec2(20, 500)));
  EXPECT_FALSE(grid.connected(Vec2(500, 500), Vec2(-5, 500)));
  const std::vector<int> labels = grid.components();
  std::set<int> distinct(labels.begin(), labels.end());
  distinct.erase(-1);
  EXPECT_EQ(distinct.size(), 2u);
}

}  // namespace
}  // namespace tactile::sim
