#include "sim/world.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tactile::sim {
namespace {

// Appends a closed loop of vertices as edges (in the given order) and classifies its vertices.
void addLoop(const std::vector<Vec2>& loop, int obstacle, std::vector<Edge>& edges,
             std::vector<VertexKind>& kinds) {
  const int first = static_cast<int>(kinds.size());
  const int n = static_cast<int>(loop.size());
  for (int i = 0; i < n; ++i) {
    Edge e;
    e.a = loop[i];
    e.b = loop[(i + 1) % n];
    const Vec2 d = e.b - e.a;
    const double length = d.norm();
    e.dir = length > 0.0 ? Vec2(d / length) : Vec2::UnitX();  // unvalidated scenes stay finite
    e.obstacle = obstacle;
    e.vertexA = first + i;
    e.vertexB = first + (i + 1) % n;
    edges.push_back(e);
  }
  const double flat = std::sin(kFlatVertexDegrees * std::numbers::pi / 180.0);
  for (int i = 0; i < n; ++i) {
    const Vec2 in = (loop[i] - loop[(i + n - 1) % n]).normalized();
    const Vec2 out = (loop[(i + 1) % n] - loop[i]).normalized();
    const double turn = cross2(in, out);
    if (in.dot(out) > 0.0 && std::abs(turn) < flat) {
      kinds.push_back(VertexKind::Flat);
    } else {
      // Free space on the right: a left turn makes the vertex stick out into free space.
      kinds.push_back(turn > 0.0 ? VertexKind::Convex : VertexKind::Concave);
    }
  }
}

}  // namespace

EdgeIndex::EdgeIndex(const std::vector<Edge>& edges, const SceneBounds& bounds,
                     double cellSizeUnits)
    : x0_(bounds.xmin), y0_(bounds.ymin), cell_(cellSizeUnits), edgeCount_(edges.size()) {
  cols_ = std::max(1, static_cast<int>(std::ceil((bounds.xmax - bounds.xmin) / cell_)));
  rows_ = std::max(1, static_cast<int>(std::ceil((bounds.ymax - bounds.ymin) / cell_)));
  const std::size_t cells = static_cast<std::size_t>(cols_) * rows_;
  // Two passes: count per cell, then fill.
  std::vector<std::uint32_t> counts(cells + 1, 0);
  const double pad = 1e-9 * cell_;
  auto forEachCell = [&](const Edge& e, auto&& fn) {
    const Vec2 lo = e.a.cwiseMin(e.b);
    const Vec2 hi = e.a.cwiseMax(e.b);
    const int c0 = std::clamp(static_cast<int>(std::floor((lo.x() - x0_) / cell_)), 0, cols_ - 1);
    const int c1 = std::clamp(static_cast<int>(std::floor((hi.x() - x0_) / cell_)), 0, cols_ - 1);
    const int r0 = std::clamp(static_cast<int>(std::floor((lo.y() - y0_) / cell_)), 0, rows_ - 1);
    const int r1 = std::clamp(static_cast<int>(std::floor((hi.y() - y0_) / cell_)), 0, rows_ - 1);
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        const Vec2 clo(x0_ + c * cell_ - pad, y0_ + r * cell_ - pad);
        const Vec2 chi(x0_ + (c + 1) * cell_ + pad, y0_ + (r + 1) * cell_ + pad);
        // Border cells extend to infinity so that nothing outside the grid is lost.
        const Vec2 blo(c == 0 ? -INFINITY : clo.x(), r == 0 ? -INFINITY : clo.y());
        const Vec2 bhi(c == cols_ - 1 ? INFINITY : chi.x(), r == rows_ - 1 ? INFINITY : chi.y());
        if (segmentHitsBox(e.a, e.b, blo, bhi)) fn(static_cast<std::size_t>(r) * cols_ + c);
      }
    }
  };
  for (const Edge& e : edges)
    forEachCell(e, [&](std::size_t cell) { ++counts[cell + 1]; });
  for (std::size_t i = 1; i <= cells; ++i)
    counts[i] += counts[i - 1];
  cellStart_ = counts;
  cellEdges_.resize(counts[cells]);
  std::vector<std::uint32_t> fill(counts.begin(), counts.end() - 1);
  for (std::size_t id = 0; id < edges.size(); ++id) {
    forEachCell(edges[id],
                [&](std::size_t cell) { cellEdges_[fill[cell]++] = static_cast<int>(id); });
  }
}

void EdgeIndex::query(const Vec2& lo, const Vec2& hi, std::vector<int>& out,
                      EdgeQueryScratch& scratch) const {
  out.clear();
  if (cols_ == 0) return;
  if (scratch.seen.size() != edgeCount_) {
    scratch.seen.assign(edgeCount_, 0);
    scratch.stamp = 0;
  }
  if (++scratch.stamp == 0) {
    std::fill(scratch.seen.begin(), scratch.seen.end(), 0);
    scratch.stamp = 1;
  }
  const auto cellOf = [&](double v, double origin, int count) {
    const double f = std::floor((v - origin) / cell_);
    if (!(f >= 0.0)) return 0;  // also catches NaN
    return f >= count - 1 ? count - 1 : static_cast<int>(f);
  };
  const int c0 = cellOf(lo.x(), x0_, cols_);
  const int c1 = cellOf(hi.x(), x0_, cols_);
  const int r0 = cellOf(lo.y(), y0_, rows_);
  const int r1 = cellOf(hi.y(), y0_, rows_);
  const std::uint32_t stamp = scratch.stamp;
  for (int r = r0; r <= r1; ++r) {
    const std::size_t rowBase = static_cast<std::size_t>(r) * cols_;
    for (int c = c0; c <= c1; ++c) {
      const std::size_t cell = rowBase + c;
      for (std::uint32_t k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) {
        const int id = cellEdges_[k];
        if (scratch.seen[id] != stamp) {
          scratch.seen[id] = stamp;
          out.push_back(id);
        }
      }
    }
  }
}

World::World(Scene scene, double cellSizeUnits) : scene_(std::move(scene)) {
  for (std::size_t i = 0; i < scene_.obstacles.size(); ++i) {
    std::vector<Vec2> loop = scene_.obstacles[i].polygon;
    double area2 = 0.0;
    for (std::size_t v = 0; v < loop.size(); ++v)
      area2 += cross2(loop[v], loop[(v + 1) % loop.size()]);
    if (area2 < 0.0) std::reverse(loop.begin(), loop.end());  // counter-clockwise
    addLoop(loop, static_cast<int>(i), edges_, vertexKinds_);
  }
  const SceneBounds& b = scene_.bounds;
  // Clockwise, so that the free space inside the bounds lies on the right of each wall.
  addLoop({Vec2(b.xmin, b.ymin), Vec2(b.xmin, b.ymax), Vec2(b.xmax, b.ymax), Vec2(b.xmax, b.ymin)},
          -1, edges_, vertexKinds_);
  if (cellSizeUnits <= 0.0) {
    cellSizeUnits = 48.0;
    const double area = (b.xmax - b.xmin) * (b.ymax - b.ymin);
    const double maxCells = 4.0e6;
    cellSizeUnits = std::max(cellSizeUnits, std::sqrt(area / maxCells));
  }
  index_ = EdgeIndex(edges_, b, cellSizeUnits);
}

}  // namespace tactile::sim
