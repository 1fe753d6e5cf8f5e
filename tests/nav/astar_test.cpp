// The A* reference of the map benchmark on hand-made maps.
#include <gtest/gtest.h>

#include <cmath>

#include "nav/astar.h"
#include "nav/benchmark.h"
#include "sim/recorder.h"

namespace tactile::nav {
namespace {

using sim::Vec2;

sim::Obstacle box(double x0, double y0, double x1, double y1) {
  return sim::Obstacle{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}};
}

sim::World worldOf(std::vector<sim::Obstacle> obstacles) {
  sim::Scene s;
  s.name = "grid";
  s.bounds = {0, 0, 1000, 1000};
  s.obstacles = std::move(obstacles);
  return sim::World(std::move(s));
}

constexpr double kInflate = 46.0;  // half the robot's width with its domes

TEST(AStar, EmptyMapGivesTheStraightAndDiagonalDistances) {
  const sim::World w = worldOf({});
  const GridMap g = inflatedGrid(w, 10.0, kInflate);
  EXPECT_NEAR(*shortestPathUnits(g, Vec2(105, 105), Vec2(905, 105)), 800.0, 1e-9);
  EXPECT_NEAR(*shortestPathUnits(g, Vec2(105, 105), Vec2(505, 505)), 400.0 * std::sqrt(2.0), 1e-9);
  // Octile: 300 straight plus 100 diagonal.
  EXPECT_NEAR(*shortestPathUnits(g, Vec2(105, 105), Vec2(505, 205)), 300.0 + 100.0 * std::sqrt(2.0),
              1e-9);
  // The bounds are grown too: the cell at 20 from the edge is blocked.
  EXPECT_TRUE(g.isBlocked(2, 50));
  EXPECT_FALSE(g.isBlocked(5, 50));
}

TEST(AStar, GoesRoundAWallThroughTheOnlyOpening) {
  // A wall from the bottom to y = 800: the way round is the 200-wide opening at the top.
  const sim::World w = worldOf({box(480, 0, 520, 800)});
  const GridMap g = inflatedGrid(w, 10.0, kInflate);
  const auto d = shortestPathUnits(g, Vec2(200, 500), Vec2(800, 500));
  ASSERT_TRUE(d);
  // The shortest polyline round the grown wall's corners (434, 846) and (566, 846), and at most
  // the octile grid's 8.3% over any straight stretch.
  const double exact = 2.0 * std::hypot(234.0, 346.0) + 132.0;
  EXPECT_GE(*d, exact - 10.0);
  EXPECT_LE(*d, exact * 1.083 + 10.0);
}

TEST(AStar, NarrowGapIsClosedAndAWideOneOpen) {
  // A wall across the map with one gap: 90 wide is not passable for the robot, 120 wide is.
  const auto across = [](double y0, double y1) {
    return std::vector<sim::Obstacle>{box(480, 0, 520, y0), box(480, y1, 520, 1000)};
  };
  const sim::World narrow = worldOf(across(455, 545));
  const sim::World wide = worldOf(across(440, 560));
  EXPECT_FALSE(
      shortestPathUnits(inflatedGrid(narrow, 5.0, kInflate), Vec2(200, 500), Vec2(800, 500)));
  const auto d =
      shortestPathUnits(inflatedGrid(wide, 5.0, kInflate), Vec2(200, 500), Vec2(800, 500));
  ASSERT_TRUE(d);
  EXPECT_NEAR(*d, 600.0, 1e-9);
}

TEST(AStar, EnclosedGoalHasNoPath) {
  const sim::World w = worldOf({box(600, 600, 900, 620), box(600, 880, 900, 900),
                                box(600, 620, 620, 880), box(880, 620, 900, 880)});
  const GridMap g = inflatedGrid(w, 10.0, kInflate);
  EXPECT_FALSE(shortestPathUnits(g, Vec2(200, 200), Vec2(750, 750)));
  // A start inside an obstacle's grown margin snaps to the nearest free cell.
  EXPECT_TRUE(shortestPathUnits(g, Vec2(30, 200), Vec2(200, 200)));
}

// A map's step budget: kBudgetPerAStarPath times the A* path's steps at cruise, never below the
// floor, never above a run's maximum; a degenerate length or speed leaves the floor.
TEST(MapBenchmark, StepBudgetScalesWithTheAStarPath) {
  EXPECT_EQ(mapStepBudget(1000.0, 5.0, 6000), 6000u);  // 4000 < floor
  EXPECT_EQ(mapStepBudget(3000.0, 5.0, 6000), static_cast<std::size_t>(kBudgetPerAStarPath * 600));
  EXPECT_EQ(mapStepBudget(3001.0, 5.0, 1),
            static_cast<std::size_t>(std::ceil(kBudgetPerAStarPath * 3001.0 / 5.0)));
  EXPECT_EQ(mapStepBudget(1e12, 5.0, 1), sim::kMaxStepsPerRun);
  EXPECT_EQ(mapStepBudget(std::nan(""), 5.0, 6000), 6000u);
  EXPECT_EQ(mapStepBudget(3000.0, 0.0, 6000), 6000u);
  EXPECT_EQ(mapStepBudget(3000.0, 5.0, 2'000'000), sim::kMaxStepsPerRun);
}

}  // namespace
}  // namespace tactile::nav
