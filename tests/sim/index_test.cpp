#include <gtest/gtest.h>

#include <random>

#include "sim/scene_source.h"
#include "sim_test_util.h"

namespace tactile::sim {
namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1.0p-53);
}

// Every edge that truly meets the query box is reported.
TEST(EdgeIndex, QueryReturnsEveryEdgeMeetingTheBox) {
  const World world(generateProceduralScene(300, 5));
  const auto& edges = world.edges();
  std::mt19937_64 rng(11);
  EdgeQueryScratch scratch;
  std::vector<int> found;
  const SceneBounds& b = world.scene().bounds;
  for (int q = 0; q < 2000; ++q) {
    const Vec2 c(uniform(rng, b.xmin - 100, b.xmax + 100),
                 uniform(rng, b.ymin - 100, b.ymax + 100));
    const Vec2 half(uniform(rng, 0, 200), uniform(rng, 0, 200));
    world.index().query(c - half, c + half, found, scratch);
    std::vector<char> listed(edges.size(), 0);
    for (int id : found) {
      ASSERT_EQ(listed[id], 0) << "edge reported twice";
      listed[id] = 1;
    }
    for (std::size_t id = 0; id < edges.size(); ++id) {
      if (segmentHitsBox(edges[id].a, edges[id].b, c - half, c + half)) {
        ASSERT_TRUE(listed[id]) << "query " << q << " missed edge " << id;
      }
    }
  }
}

void expectSameContact(const PoseContact& a, const PoseContact& b, int q) {
  ASSERT_EQ(a.blocked, b.blocked) << "pose " << q;
  for (int k = 0; k < kSensorCount; ++k) {
    ASSERT_EQ(a.domes[k].normal, b.domes[k].normal) << "pose " << q << " dome " << k;
    ASSERT_EQ(a.domes[k].shear, b.domes[k].shear) << "pose " << q << " dome " << k;
    ASSERT_EQ(a.domes[k].edge, b.domes[k].edge) << "pose " << q << " dome " << k;
    ASSERT_EQ(a.domes[k].vertex, b.domes[k].vertex) << "pose " << q << " dome " << k;
  }
}

// The indexed contact equals the brute-force contact exactly, on poses biased toward contact.
void compareOnRandomPoses(const Scene& scene, int poses, std::uint64_t seed) {
  auto world = std::make_shared<const World>(scene);
  SimConfig indexed;
  SimConfig brute;
  brute.useIndex = false;
  Simulator a(world, indexed);
  Simulator b(world, brute);
  std::mt19937_64 rng(seed);
  const SceneBounds& bounds = scene.bounds;
  int contacts = 0;
  for (int q = 0; q < poses; ++q) {
    Pose2d pose;
    if (q % 2 == 0 && !world->edges().empty()) {
      // Near a random edge point, so that many poses touch something.
      const Edge& e = world->edges()[rng() % world->edges().size()];
      const Vec2 p = e.a + uniform(rng, 0, 1) * (e.b - e.a);
      pose = {p.x() + uniform(rng, -150, 150), p.y() + uniform(rng, -150, 150),
              uniform(rng, -3.2, 3.2)};
    } else {
      pose = {uniform(rng, bounds.xmin, bounds.xmax), uniform(rng, bounds.ymin, bounds.ymax),
              uniform(rng, -3.2, 3.2)};
    }
    const PoseContact ca = a.evaluate(pose);
    const PoseContact cb = b.evaluate(pose);
    expectSameContact(ca, cb, q);
    if (ca.domes[0].edge >= 0 || ca.blocked) ++contacts;
    ASSERT_EQ(a.isBlocked(pose), b.isBlocked(pose)) << "pose " << q;
  }
  EXPECT_GT(contacts, poses / 50) << "too few poses in contact to mean anything";
}

TEST(EdgeIndex, MatchesBruteForceOnProceduralScene) {
  compareOnRandomPoses(generateProceduralScene(400, 2), 5000, 1);
}

TEST(EdgeIndex, MatchesBruteForceInBuiltinRooms) {
  for (const char* name : {"room1", "room2", "room3", "chapter5"}) {
    Result<Scene> r = loadScene(name);
    ASSERT_TRUE(r.ok()) << r.errorText();
    compareOnRandomPoses(r.value(), 2000, 7);
  }
}

// Whole runs: stepping with the index gives the same trajectory and values as brute force.
TEST(EdgeIndex, SteppedRunsMatchBruteForce) {
  auto world = std::make_shared<const World>(generateProceduralScene(60, 8));
  SimConfig brute;
  brute.useIndex = false;
  Simulator a(world, SimConfig{});
  Simulator b(world, brute);
  std::mt19937_64 rng(3);
  for (int k = 0; k < 3000; ++k) {
    const double v = uniform(rng, -30, 80);
    const double w = uniform(rng, -1.5, 1.5);
    a.step(v, w);
    b.step(v, w);
    ASSERT_EQ(a.pose().x, b.pose().x) << k;
    ASSERT_EQ(a.pose().theta, b.pose().theta) << k;
    ASSERT_EQ(a.blocked(), b.blocked()) << k;
    ASSERT_EQ(a.sensors(), b.sensors()) << k;
    ASSERT_EQ(a.truth(), b.truth()) << k;
  }
}

}  // namespace
}  // namespace tactile::sim
