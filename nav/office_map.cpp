#include "nav/office_map.h"

#include <algorithm>
#include <random>

namespace tactile::nav {
namespace {

double unit(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * unit(rng);
}

sim::Obstacle box(double x0, double y0, double x1, double y1) {
  return sim::Obstacle{
      {sim::Vec2(x0, y0), sim::Vec2(x1, y0), sim::Vec2(x1, y1), sim::Vec2(x0, y1)}};
}

constexpr double kWall = 20.0;

}  // namespace

OfficeMap generateOfficeMap(std::uint64_t seed) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull);
  const int cols = 2 + static_cast<int>(rng() % 2);
  const int rows = 2 + static_cast<int>(rng() % 2);
  std::vector<double> xs{0.0};  // wall centre lines; bounds at 0 and the last
  for (int c = 0; c < cols; ++c)
    xs.push_back(xs.back() + uniform(rng, 450.0, 750.0));
  std::vector<double> ys{0.0};
  for (int r = 0; r < rows; ++r)
    ys.push_back(ys.back() + uniform(rng, 450.0, 750.0));
  OfficeMap map;
  sim::Scene& s = map.scene;
  s.name = "office-" + std::to_string(seed);
  s.bounds = {0.0, 0.0, xs.back(), ys.back()};
  const auto roomIndex = [&](int c, int r) { return r * cols + c; };
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      OfficeRoom room;
      room.x0 = xs[c] + (c == 0 ? 0.0 : 0.5 * kWall);
      room.x1 = xs[c + 1] - (c + 1 == cols ? 0.0 : 0.5 * kWall);
      room.y0 = ys[r] + (r == 0 ? 0.0 : 0.5 * kWall);
      room.y1 = ys[r + 1] - (r + 1 == rows ? 0.0 : 0.5 * kWall);
      map.rooms.push_back(room);
    }
  }
  // Doors: a random spanning tree over the room grid (so every room is reachable), then each other
  // shared wall gets a door with probability 0.3.
  const int n = cols * rows;
  std::vector<int> parent(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    parent[static_cast<std::size_t>(i)] = i;
  const auto find = [&](int i) {
    while (parent[static_cast<std::size_t>(i)] != i)
      i = parent[static_cast<std::size_t>(i)];
    return i;
  };
  struct Shared {
    int a, b;
    bool vertical;  // the wall between them runs along y
    bool door = false;
  };
  std::vector<Shared> shared;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      if (c + 1 < cols) shared.push_back({roomIndex(c, r), roomIndex(c + 1, r), true});
      if (r + 1 < rows) shared.push_back({roomIndex(c, r), roomIndex(c, r + 1), false});
    }
  std::shuffle(shared.begin(), shared.end(), rng);
  for (Shared& w : shared) {
    const int ra = find(w.a);
    const int rb = find(w.b);
    if (ra != rb) {
      parent[static_cast<std::size_t>(ra)] = rb;
      w.door = true;
    } else {
      w.door = unit(rng) < 0.3;
    }
  }
  // Walls: each shared wall is one segment between two rooms, split by its door.
  for (const Shared& w : shared) {
    const OfficeRoom& A = map.rooms[static_cast<std::size_t>(w.a)];
    const OfficeRoom& B = map.rooms[static_cast<std::size_t>(w.b)];
    if (w.vertical) {
      const double x = 0.5 * (A.x1 + B.x0);
      const double y0 = A.y0 - (A.y0 > 0.0 ? 0.5 * kWall : 0.0);
      const double y1 = A.y1 + (A.y1 < s.bounds.ymax ? 0.5 * kWall : 0.0);
      if (!w.door) {
        s.obstacles.push_back(box(x - 0.5 * kWall, y0, x + 0.5 * kWall, y1));
        continue;
      }
      const double width = uniform(rng, 130.0, 220.0);
      const double d0 = uniform(rng, A.y0 + 60.0, A.y1 - 60.0 - width);
      s.obstacles.push_back(box(x - 0.5 * kWall, y0, x + 0.5 * kWall, d0));
      s.obstacles.push_back(box(x - 0.5 * kWall, d0 + width, x + 0.5 * kWall, y1));
    } else {
      const double y = 0.5 * (A.y1 + B.y0);
      // Horizontal walls stop at the vertical ones (which run the full room height).
      const double x0 = A.x0;
      const double x1 = A.x1;
      if (!w.door) {
        s.obstacles.push_back(box(x0, y - 0.5 * kWall, x1, y + 0.5 * kWall));
        continue;
      }
      const double width = uniform(rng, 130.0, 220.0);
      const double d0 = uniform(rng, x0 + 60.0, x1 - 60.0 - width);
      s.obstacles.push_back(box(x0, y - 0.5 * kWall, d0, y + 0.5 * kWall));
      s.obstacles.push_back(box(d0 + width, y - 0.5 * kWall, x1, y + 0.5 * kWall));
    }
  }
  // Furniture: boxes well inside the rooms, so a way round them and to every door stays open.
  for (const OfficeRoom& room : map.rooms) {
    const int count = static_cast<int>(rng() % 3);
    for (int k = 0; k < count; ++k) {
      const double w = uniform(rng, 60.0, 180.0);
      const double h = uniform(rng, 60.0, 180.0);
      const double margin = 150.0;
      if (room.x1 - room.x0 < 2 * margin + w || room.y1 - room.y0 < 2 * margin + h) continue;
      const double x = uniform(rng, room.x0 + margin, room.x1 - margin - w);
      const double y = uniform(rng, room.y0 + margin, room.y1 - margin - h);
      bool overlaps = false;
      for (std::size_t o = 0; o < s.obstacles.size() && !overlaps; ++o) {
        for (const sim::Vec2& p : s.obstacles[o].polygon) {
          if (p.x() > x - 120 && p.x() < x + w + 120 && p.y() > y - 120 && p.y() < y + h + 120) {
            overlaps = true;
            break;
          }
        }
      }
      if (!overlaps) s.obstacles.push_back(box(x, y, x + w, y + h));
    }
  }
  const OfficeRoom& first = map.rooms.front();
  s.start = {0.5 * (first.x0 + first.x1), 0.5 * (first.y0 + first.y1), 0.0};
  const OfficeRoom& last = map.rooms.back();
  s.goal = sim::Vec2(0.5 * (last.x0 + last.x1), 0.5 * (last.y0 + last.y1));
  return map;
}

}  // namespace tactile::nav
