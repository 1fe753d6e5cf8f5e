#include "sim/clearance_grid.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace tactile::sim {

ClearanceGrid::ClearanceGrid(const Scene& scene, double radiusUnits, double cellUnits)
    : x0_(scene.bounds.xmin),
      y0_(scene.bounds.ymin),
      cell_(cellUnits > 0.0 ? cellUnits : 1.0),
      radius_(std::max(0.0, radiusUnits)) {
  const SceneBounds& b = scene.bounds;
  cols_ = std::max(1, static_cast<int>(std::ceil((b.xmax - b.xmin) / cell_)));
  rows_ = std::max(1, static_cast<int>(std::ceil((b.ymax - b.ymin) / cell_)));
  free_.assign(static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_), 1);
  // The bounds are walls: a centre closer than the radius to one is occupied; so is a centre
  // beyond them (the last column or row may reach past xmax or ymax).
  for (int r = 0; r < rows_; ++r) {
    for (int c = 0; c < cols_; ++c) {
      const Vec2 p = cellCentre(c, r);
      const double d = std::min({p.x() - b.xmin, b.xmax - p.x(), p.y() - b.ymin, b.ymax - p.y()});
      if (d < radius_) free_[at(c, r)] = 0;
    }
  }
  const double r2 = radius_ * radius_;
  const auto cellRange = [&](double lo, double hi, double origin, int count) {
    const int first = std::max(0, static_cast<int>(std::floor((lo - origin) / cell_ - 0.5)));
    const int last = std::min(count - 1, static_cast<int>(std::ceil((hi - origin) / cell_ - 0.5)));
    return std::pair<int, int>(first, last);
  };
  for (const Obstacle& o : scene.obstacles) {
    const std::size_t n = o.polygon.size();
    if (n == 0) continue;
    Vec2 lo = o.polygon[0];
    Vec2 hi = o.polygon[0];
    for (const Vec2& p : o.polygon) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    // Inside the polygon.
    const auto [c0, c1] = cellRange(lo.x(), hi.x(), x0_, cols_);
    const auto [rr0, rr1] = cellRange(lo.y(), hi.y(), y0_, rows_);
    for (int r = rr0; r <= rr1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        if (free_[at(c, r)] && pointInPolygon(cellCentre(c, r), o.polygon)) free_[at(c, r)] = 0;
      }
    }
    // Within the radius of an edge.
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2& a = o.polygon[i];
      const Vec2& e = o.polygon[(i + 1) % n];
      const Vec2 elo = a.cwiseMin(e).array() - radius_;
      const Vec2 ehi = a.cwiseMax(e).array() + radius_;
      const auto [ec0, ec1] = cellRange(elo.x(), ehi.x(), x0_, cols_);
      const auto [er0, er1] = cellRange(elo.y(), ehi.y(), y0_, rows_);
      for (int r = er0; r <= er1; ++r) {
        for (int c = ec0; c <= ec1; ++c) {
          if (free_[at(c, r)] && pointSegmentDistance2(cellCentre(c, r), a, e) < r2) {
            free_[at(c, r)] = 0;
          }
        }
      }
    }
  }
}

bool ClearanceGrid::free(int column, int row) const {
  if (column < 0 || row < 0 || column >= cols_ || row >= rows_) return false;
  return free_[at(column, row)] != 0;
}

std::optional<std::pair<int, int>> ClearanceGrid::cellOf(const Vec2& p) const {
  const double fx = std::floor((p.x() - x0_) / cell_);
  const double fy = std::floor((p.y() - y0_) / cell_);
  if (!(fx >= 0.0 && fy >= 0.0 && fx < cols_ && fy < rows_)) return std::nullopt;
  return std::pair<int, int>(static_cast<int>(fx), static_cast<int>(fy));
}

Vec2 ClearanceGrid::cellCentre(int column, int row) const {
  return Vec2(x0_ + (column + 0.5) * cell_, y0_ + (row + 0.5) * cell_);
}

std::vector<int> ClearanceGrid::components() const {
  std::vector<int> label(free_.size(), -1);
  int next = 0;
  std::deque<std::pair<int, int>> queue;
  for (int r0 = 0; r0 < rows_; ++r0) {
    for (int c0 = 0; c0 < cols_; ++c0) {
      if (!free_[at(c0, r0)] || label[at(c0, r0)] >= 0) continue;
      label[at(c0, r0)] = next;
      queue.emplace_back(c0, r0);
      while (!queue.empty()) {
        const auto [c, r] = queue.front();
        queue.pop_front();
        constexpr int kDc[4] = {1, -1, 0, 0};
        constexpr int kDr[4] = {0, 0, 1, -1};
        for (int k = 0; k < 4; ++k) {
          const int nc = c + kDc[k];
          const int nr = r + kDr[k];
          if (free(nc, nr) && label[at(nc, nr)] < 0) {
            label[at(nc, nr)] = next;
            queue.emplace_back(nc, nr);
          }
        }
      }
      ++next;
    }
  }
  return label;
}

bool ClearanceGrid::connected(const Vec2& a, const Vec2& b) const {
  const auto ca = cellOf(a);
  const auto cb = cellOf(b);
  if (!ca || !cb || !free(ca->first, ca->second) || !free(cb->first, cb->second)) return false;
  const std::vector<int> label = components();
  return label[at(ca->first, ca->second)] == label[at(cb->first, cb->second)];
}

}  // namespace tactile::sim
