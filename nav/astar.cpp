#include "nav/astar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace tactile::nav {
namespace {

constexpr double kSqrt2 = 1.4142135623730951;

}  // namespace

GridMap inflatedGrid(const sim::World& world, double cellUnits, double inflateUnits) {
  GridMap g;
  const sim::SceneBounds& b = world.scene().bounds;
  g.cellUnits = cellUnits;
  g.x0 = b.xmin;
  g.y0 = b.ymin;
  g.cols = std::max(1, static_cast<int>(std::ceil((b.xmax - b.xmin) / cellUnits)));
  g.rows = std::max(1, static_cast<int>(std::ceil((b.ymax - b.ymin) / cellUnits)));
  g.blocked.assign(static_cast<std::size_t>(g.cols) * g.rows, 0);
  std::vector<int> near;
  sim::EdgeQueryScratch scratch;
  const double r2 = inflateUnits * inflateUnits;
  const auto& edges = world.edges();
  const auto& obstacles = world.scene().obstacles;
  for (int row = 0; row < g.rows; ++row) {
    for (int col = 0; col < g.cols; ++col) {
      const sim::Vec2 c(g.x0 + (col + 0.5) * cellUnits, g.y0 + (row + 0.5) * cellUnits);
      bool blocked = c.x() - b.xmin < inflateUnits || b.xmax - c.x() < inflateUnits ||
                     c.y() - b.ymin < inflateUnits || b.ymax - c.y() < inflateUnits;
      if (!blocked) {
        const sim::Vec2 reach(inflateUnits, inflateUnits);
        world.index().query(c - reach, c + reach, near, scratch);
        for (int e : near) {
          if (sim::pointSegmentDistance2(c, edges[e].a, edges[e].b) < r2) {
            blocked = true;
            break;
          }
        }
      }
      if (!blocked) {
        for (const sim::Obstacle& o : obstacles) {
          if (sim::pointInPolygon(c, o.polygon)) {
            blocked = true;
            break;
          }
        }
      }
      g.blocked[static_cast<std::size_t>(row) * g.cols + col] = blocked ? 1 : 0;
    }
  }
  return g;
}

std::optional<double> shortestPathUnits(const GridMap& g, const sim::Vec2& from,
                                        const sim::Vec2& to, double snapUnits) {
  const auto cellOf = [&](const sim::Vec2& p) -> std::optional<std::pair<int, int>> {
    const int c0 = static_cast<int>(std::floor((p.x() - g.x0) / g.cellUnits));
    const int r0 = static_cast<int>(std::floor((p.y() - g.y0) / g.cellUnits));
    if (!g.isBlocked(c0, r0)) return std::make_pair(c0, r0);
    // Nearest free cell within snapUnits (ties: lowest row, then column).
    const int reach = static_cast<int>(std::ceil(snapUnits / g.cellUnits));
    std::optional<std::pair<int, int>> best;
    double bestD = std::numeric_limits<double>::infinity();
    for (int dr = -reach; dr <= reach; ++dr) {
      for (int dc = -reach; dc <= reach; ++dc) {
        if (g.isBlocked(c0 + dc, r0 + dr)) continue;
        const double d = std::hypot(dc, dr) * g.cellUnits;
        if (d <= snapUnits && d < bestD) {
          bestD = d;
          best = std::make_pair(c0 + dc, r0 + dr);
        }
      }
    }
    return best;
  };
  const auto a = cellOf(from);
  const auto b = cellOf(to);
  if (!a || !b) return std::nullopt;
  const auto index = [&](int c, int r) { return static_cast<std::size_t>(r) * g.cols + c; };
  // Octile distance: the exact shortest 8-connected length without obstacles (admissible).
  const auto h = [&](int c, int r) {
    const double dx = std::abs(c - b->first);
    const double dy = std::abs(r - b->second);
    return (std::max(dx, dy) - std::min(dx, dy) + kSqrt2 * std::min(dx, dy)) * g.cellUnits;
  };
  std::vector<double> cost(g.blocked.size(), std::numeric_limits<double>::infinity());
  std::vector<std::uint8_t> closed(g.blocked.size(), 0);
  using Entry = std::pair<double, std::size_t>;  // (f, cell); ties by the lower cell index
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  cost[index(a->first, a->second)] = 0.0;
  open.emplace(h(a->first, a->second), index(a->first, a->second));
  const std::size_t goal = index(b->first, b->second);
  while (!open.empty()) {
    const auto [f, cell] = open.top();
    open.pop();
    if (closed[cell]) continue;
    closed[cell] = 1;
    if (cell == goal) return cost[cell];
    const int c = static_cast<int>(cell % g.cols);
    const int r = static_cast<int>(cell / g.cols);
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        if (dc == 0 && dr == 0) continue;
        const int nc = c + dc;
        const int nr = r + dr;
        if (g.isBlocked(nc, nr)) continue;
        // No corner cutting: both orthogonal neighbours of a diagonal move must be free.
        if (dc != 0 && dr != 0 && (g.isBlocked(c + dc, r) || g.isBlocked(c, r + dr))) continue;
        const std::size_t n = index(nc, nr);
        const double step = (dc != 0 && dr != 0 ? kSqrt2 : 1.0) * g.cellUnits;
        if (cost[cell] + step < cost[n]) {
          cost[n] = cost[cell] + step;
          open.emplace(cost[n] + h(nc, nr), n);
        }
      }
    }
  }
  return std::nullopt;
}

}  // namespace tactile::nav
