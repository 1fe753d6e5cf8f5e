#include "nav/touch_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>

namespace tactile::nav {
namespace {

constexpr double kSqrt2 = 1.4142135623730951;

}  // namespace

TouchMap::TouchMap(const sim::Vec2& start, const sim::Vec2& goal, TouchMapConfig config)
    : cfg_(config) {
  if (!(cfg_.cellUnits > 0.0)) cfg_.cellUnits = 20.0;
  if (!(cfg_.growUnits >= 0.0)) cfg_.growUnits = 0.0;
  if (!(cfg_.marginUnits >= 0.0)) cfg_.marginUnits = 0.0;
  if (!(cfg_.nearUnits >= 0.0)) cfg_.nearUnits = 0.0;
  if (!(cfg_.nearCost >= 1.0)) cfg_.nearCost = 1.0;
  const double xmin = std::min(start.x(), goal.x()) - cfg_.marginUnits;
  const double ymin = std::min(start.y(), goal.y()) - cfg_.marginUnits;
  const double xmax = std::max(start.x(), goal.x()) + cfg_.marginUnits;
  const double ymax = std::max(start.y(), goal.y()) + cfg_.marginUnits;
  x0_ = xmin;
  y0_ = ymin;
  cols_ = std::max(1, static_cast<int>(std::ceil((xmax - xmin) / cfg_.cellUnits)));
  rows_ = std::max(1, static_cast<int>(std::ceil((ymax - ymin) / cfg_.cellUnits)));
  const std::size_t n = static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_);
  touched_.assign(n, 0);
  closedBy_.assign(n, 0);
  nearBy_.assign(n, 0);
  cost_.assign(n, 0.0);
  parent_.assign(n, -1);
  seen_.assign(n, 0);
  const int reach = static_cast<int>(std::floor(cfg_.growUnits / cfg_.cellUnits));
  for (int dr = -reach; dr <= reach; ++dr)
    for (int dc = -reach; dc <= reach; ++dc)
      if (std::hypot(dc, dr) * cfg_.cellUnits <= cfg_.growUnits + 1e-9) disc_.emplace_back(dc, dr);
  const int nearReach = static_cast<int>(std::floor(cfg_.nearUnits / cfg_.cellUnits));
  for (int dr = -nearReach; dr <= nearReach; ++dr)
    for (int dc = -nearReach; dc <= nearReach; ++dc)
      if (std::hypot(dc, dr) * cfg_.cellUnits <= cfg_.nearUnits + 1e-9)
        nearDisc_.emplace_back(dc, dr);
}

bool TouchMap::cellOf(const sim::Vec2& p, int& col, int& row) const {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return false;
  const double c = std::floor((p.x() - x0_) / cfg_.cellUnits);
  const double r = std::floor((p.y() - y0_) / cfg_.cellUnits);
  if (c < 0.0 || r < 0.0 || c >= cols_ || r >= rows_) return false;
  col = static_cast<int>(c);
  row = static_cast<int>(r);
  return true;
}

sim::Vec2 TouchMap::centre(int col, int row) const {
  return {x0_ + (col + 0.5) * cfg_.cellUnits, y0_ + (row + 0.5) * cfg_.cellUnits};
}

bool TouchMap::openCell(int col, int row) const {
  return col >= 0 && row >= 0 && col < cols_ && row < rows_ && closedBy_[index(col, row)] == 0;
}

void TouchMap::grow(int col, int row, int delta) {
  for (const auto& [dc, dr] : disc_) {
    const int c = col + dc;
    const int r = row + dr;
    if (c < 0 || r < 0 || c >= cols_ || r >= rows_) continue;
    auto& n = closedBy_[index(c, r)];
    n = static_cast<std::uint16_t>(n + delta);
  }
  for (const auto& [dc, dr] : nearDisc_) {
    const int c = col + dc;
    const int r = row + dr;
    if (c < 0 || r < 0 || c >= cols_ || r >= rows_) continue;
    auto& n = nearBy_[index(c, r)];
    n = static_cast<std::uint16_t>(n + delta);
  }
}

bool TouchMap::near(const sim::Vec2& point) const {
  int c = 0;
  int r = 0;
  return !cellOf(point, c, r) || nearBy_[index(c, r)] != 0;
}

bool TouchMap::mark(const sim::Vec2& point) {
  int c = 0;
  int r = 0;
  if (!cellOf(point, c, r) || touched_[index(c, r)]) return false;
  touched_[index(c, r)] = 1;
  grow(c, r, +1);
  ++touchedCount_;
  ++revision_;
  return true;
}

int TouchMap::clear(const sim::Vec2& point, double radius) {
  int c0 = 0;
  int r0 = 0;
  if (empty() || !std::isfinite(radius) || radius < 0.0) return 0;
  if (!cellOf(point, c0, r0)) return 0;
  const int reach = static_cast<int>(std::ceil(radius / cfg_.cellUnits)) + 1;
  int cleared = 0;
  for (int r = std::max(0, r0 - reach); r <= std::min(rows_ - 1, r0 + reach); ++r) {
    for (int c = std::max(0, c0 - reach); c <= std::min(cols_ - 1, c0 + reach); ++c) {
      if (!touched_[index(c, r)] || (centre(c, r) - point).norm() > radius) continue;
      touched_[index(c, r)] = 0;
      grow(c, r, -1);
      --touchedCount_;
      ++cleared;
    }
  }
  if (cleared > 0) ++revision_;
  return cleared;
}

bool TouchMap::touched(const sim::Vec2& point) const {
  int c = 0;
  int r = 0;
  return cellOf(point, c, r) && touched_[index(c, r)] != 0;
}

bool TouchMap::closed(const sim::Vec2& point) const {
  int c = 0;
  int r = 0;
  return !cellOf(point, c, r) || closedBy_[index(c, r)] != 0;
}

std::optional<int> TouchMap::snap(const sim::Vec2& p, double snapUnits) const {
  int c0 = 0;
  int r0 = 0;
  if (!cellOf(p, c0, r0)) return std::nullopt;
  if (openCell(c0, r0)) return index(c0, r0);
  // The nearest open cell reached from the point through closed cells without crossing a touched
  // one (four-connected, breadth first, then the nearest of the first ring that has open cells):
  // a thin wall touched on one face must not put the start on its far side.
  const int reach = static_cast<int>(std::ceil(snapUnits / cfg_.cellUnits));
  std::vector<int> ring{index(c0, r0)};
  std::vector<int> visited{index(c0, r0)};
  const auto wasVisited = [&](int i) {
    return std::find(visited.begin(), visited.end(), i) != visited.end();
  };
  for (int depth = 0; depth < reach && !ring.empty(); ++depth) {
    std::vector<int> next;
    std::optional<int> best;
    double bestD = std::numeric_limits<double>::infinity();
    for (int cell : ring) {
      const int c = cell % cols_;
      const int r = cell / cols_;
      static constexpr std::array<std::array<int, 2>, 4> kSteps{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
      for (const auto& s : kSteps) {
        const int nc = c + s[0];
        const int nr = r + s[1];
        if (nc < 0 || nr < 0 || nc >= cols_ || nr >= rows_) continue;
        const int n = index(nc, nr);
        if (touched_[n] || wasVisited(n)) continue;
        visited.push_back(n);
        if (openCell(nc, nr)) {
          const double d = (centre(nc, nr) - p).norm();
          if (d <= snapUnits && (d < bestD || (d == bestD && n < *best))) {
            bestD = d;
            best = n;
          }
        } else {
          next.push_back(n);
        }
      }
    }
    if (best) return best;
    ring = std::move(next);
  }
  return std::nullopt;
}

std::optional<TouchPlan> TouchMap::plan(const sim::Vec2& from, const sim::Vec2& to,
                                        double snapUnits, bool* snapFailed) const {
  if (snapFailed) *snapFailed = false;
  if (empty()) return std::nullopt;
  const auto a = snap(from, snapUnits);
  const auto b = snap(to, snapUnits);
  if (!a || !b) {
    if (snapFailed) *snapFailed = true;
    return std::nullopt;
  }
  if (++stamp_ == 0) {  // wrapped: forget every old mark
    std::fill(seen_.begin(), seen_.end(), 0u);
    stamp_ = 1;
  }
  const std::uint32_t open = stamp_;
  const int bc = *b % cols_;
  const int br = *b / cols_;
  const auto h = [&](int c, int r) {
    const double dx = std::abs(c - bc);
    const double dy = std::abs(r - br);
    return (std::max(dx, dy) - std::min(dx, dy) + kSqrt2 * std::min(dx, dy)) * cfg_.cellUnits;
  };
  // seen_ == stamp_: reached this search (cost_ valid); cost_ < 0 marks a closed (expanded) cell
  // by storing -(cost + 1).
  using Entry = std::pair<double, int>;  // (f, cell); ties by the lower cell index
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  seen_[*a] = open;
  cost_[*a] = 0.0;
  parent_[*a] = -1;
  queue.emplace(h(*a % cols_, *a / cols_), *a);
  bool found = false;
  while (!queue.empty()) {
    const auto [f, cell] = queue.top();
    queue.pop();
    const int c = cell % cols_;
    const int r = cell / cols_;
    if (f > cost_[cell] + h(c, r) + 1e-9) continue;  // a stale entry
    if (cell == *b) {
      found = true;
      break;
    }
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        if (dc == 0 && dr == 0) continue;
        const int nc = c + dc;
        const int nr = r + dr;
        if (!openCell(nc, nr)) continue;
        if (dc != 0 && dr != 0 && (!openCell(c + dc, r) || !openCell(c, r + dr))) continue;
        const int n = index(nc, nr);
        const double g = cost_[cell] + (dc != 0 && dr != 0 ? kSqrt2 : 1.0) * cfg_.cellUnits *
                                           (nearBy_[n] != 0 ? cfg_.nearCost : 1.0);
        if (seen_[n] != open || g + 1e-9 < cost_[n]) {
          seen_[n] = open;
          cost_[n] = g;
          parent_[n] = cell;
          queue.emplace(g + h(nc, nr), n);
        }
      }
    }
  }
  if (!found) return std::nullopt;
  TouchPlan p;
  p.lengthUnits = cost_[*b];
  for (int cell = *b; cell >= 0; cell = parent_[cell])
    p.points.push_back(centre(cell % cols_, cell / cols_));
  std::reverse(p.points.begin(), p.points.end());
  if (p.points.size() == 1) p.points.push_back(p.points.front());
  return p;
}

bool TouchMap::lineOpen(const sim::Vec2& a, const sim::Vec2& b) const {
  const double len = (b - a).norm();
  const int n = std::max(1, static_cast<int>(std::ceil(len / (0.5 * cfg_.cellUnits))));
  // A robot beside a wall stands on closed cells: the line may start on them, but once it has
  // reached an open cell it must stay on open ones.
  bool out = false;
  for (int i = 1; i <= n; ++i) {
    const sim::Vec2 p = a + (b - a) * (static_cast<double>(i) / n);
    int col = 0;
    int row = 0;
    const bool c = !cellOf(p, col, row) || closedBy_[index(col, row)] != 0;
    if (!c) out = true;
    if (c && out) return false;
  }
  return out;
}

sim::Vec2 TouchMap::lookAhead(const TouchPlan& plan, const sim::Vec2& from,
                              double reachUnits) const {
  if (plan.points.empty()) return from;
  if (plan.points.size() == 1) return plan.points.front();
  // At least kMinAheadUnits along the plan (or its end), so the heading does not jitter between
  // neighbouring cells where nothing is in clear sight.
  constexpr double kMinAheadUnits = 40.0;
  sim::Vec2 best = plan.points.back();
  double along = 0.0;
  for (std::size_t i = 1; i < plan.points.size(); ++i) {
    along += (plan.points[i] - plan.points[i - 1]).norm();
    if (along >= kMinAheadUnits) {
      best = plan.points[i];
      break;
    }
  }
  along = 0.0;
  for (std::size_t i = 1; i < plan.points.size(); ++i) {
    along += (plan.points[i] - plan.points[i - 1]).norm();
    if (along > reachUnits) break;
    if (along > kMinAheadUnits && lineOpen(from, plan.points[i])) best = plan.points[i];
  }
  return best;
}

}  // namespace tactile::nav
