#include "sim/polygon_check.h"

#include <algorithm>
#include <numeric>
#include <set>

namespace tactile::sim {
namespace {

bool lexLess(const Vec2& a, const Vec2& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

bool adjacent(std::size_t i, std::size_t j, std::size_t n) {
  return (i + 1) % n == j || (j + 1) % n == i;
}

EdgePair ordered(std::size_t i, std::size_t j) {
  return {std::min(i, j), std::max(i, j)};
}

// Adjacent edges (a, shared) and (shared, b) fold back onto each other when a and b lie on the same
// ray from the shared vertex.
bool foldsBack(const Vec2& a, const Vec2& shared, const Vec2& b) {
  const Vec2 u = a - shared;
  const Vec2 w = b - shared;
  return cross2(u, w) == 0.0 && u.dot(w) > 0.0;
}

std::optional<EdgePair> firstFold(const std::vector<Vec2>& poly) {
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (foldsBack(poly[i], poly[j], poly[(j + 1) % n])) return ordered(i, j);
  }
  return std::nullopt;
}

}  // namespace

std::optional<EdgePair> polygonSelfContactBruteForce(const std::vector<Vec2>& poly) {
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec2& c = poly[j];
      const Vec2& d = poly[(j + 1) % n];
      bool bad = false;
      if (j == i + 1) {
        bad = foldsBack(a, b, d);
      } else if (i == 0 && j == n - 1) {
        bad = foldsBack(b, a, c);
      } else {
        bad = segmentsIntersect(a, b, c, d);
      }
      if (bad) return EdgePair{i, j};
    }
  }
  return std::nullopt;
}

// Shamos and Hoey's sweep: the edges the vertical sweep line crosses are kept ordered from bottom
// to top; an edge is tested only against its neighbours when it enters, and its two neighbours
// against each other when it leaves. If any two edges touch, some touching pair becomes adjacent
// in that order before the sweep passes their first common point, so O(n) tests in O(n log n)
// time find it. The order of two edges is decided where the later one starts (no sweep position
// is needed), which is consistent as long as no edges cross, and the sweep stops at the first
// contact. Degenerate contacts are caught first: a vertex repeated anywhere (found by sorting)
// and adjacent edges folding back.
std::optional<EdgePair> polygonSelfContactSweep(const std::vector<Vec2>& poly) {
  const std::size_t n = poly.size();
  if (auto fold = firstFold(poly)) return fold;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return lexLess(poly[a], poly[b]) || (poly[a] == poly[b] && a < b);
  });
  // A vertex that occurs twice: the edges leaving the two occurrences touch there.
  for (std::size_t k = 1; k < n; ++k) {
    if (poly[order[k]] == poly[order[k - 1]]) return ordered(order[k - 1], order[k]);
  }
  // Edge e runs from vertex e to vertex e + 1; left/right are its lexicographic ends.
  const auto left = [&](std::size_t e) -> const Vec2& {
    const Vec2& a = poly[e];
    const Vec2& b = poly[(e + 1) % n];
    return lexLess(a, b) ? a : b;
  };
  const auto right = [&](std::size_t e) -> const Vec2& {
    const Vec2& a = poly[e];
    const Vec2& b = poly[(e + 1) % n];
    return lexLess(a, b) ? b : a;
  };
  // e1 below e2 (both crossed by the sweep line, not crossing each other).
  const auto below = [&](std::size_t e1, std::size_t e2) {
    if (e1 == e2) return false;
    const Vec2& l1 = left(e1);
    const Vec2& l2 = left(e2);
    if (l1 == l2) {
      const int o = orientation(l1, right(e1), right(e2));
      return o != 0 ? o > 0 : e1 < e2;
    }
    if (lexLess(l1, l2)) {
      int o = orientation(l1, right(e1), l2);
      if (o == 0) o = orientation(l1, right(e1), right(e2));
      return o != 0 ? o > 0 : e1 < e2;
    }
    int o = orientation(l2, right(e2), l1);
    if (o == 0) o = orientation(l2, right(e2), right(e1));
    return o != 0 ? o < 0 : e1 < e2;
  };
  std::set<std::size_t, decltype(below)> line(below);
  std::vector<std::set<std::size_t, decltype(below)>::iterator> where(n, line.end());
  const auto touching = [&](std::size_t e1, std::size_t e2) {
    if (adjacent(e1, e2, n)) return false;
    return segmentsIntersect(poly[e1], poly[(e1 + 1) % n], poly[e2], poly[(e2 + 1) % n]);
  };
  for (std::size_t v : order) {
    const std::size_t edges[2] = {(v + n - 1) % n, v};  // the edges ending and starting at v
    // Edges whose right end is v leave first, then those whose left end is v enter.
    for (std::size_t e : edges) {
      if (&right(e) != &poly[v] || where[e] == line.end()) continue;
      auto it = where[e];
      if (it != line.begin()) {
        auto next = std::next(it);
        if (next != line.end() && touching(*std::prev(it), *next)) {
          return ordered(*std::prev(it), *next);
        }
      }
      line.erase(it);
      where[e] = line.end();
    }
    for (std::size_t e : edges) {
      if (&left(e) != &poly[v]) continue;
      auto [it, inserted] = line.insert(e);
      if (!inserted) return ordered(e, *it);
      where[e] = it;
      if (it != line.begin() && touching(e, *std::prev(it))) return ordered(e, *std::prev(it));
      auto next = std::next(it);
      if (next != line.end() && touching(e, *next)) return ordered(e, *next);
    }
  }
  return std::nullopt;
}

std::optional<EdgePair> polygonSelfContact(const std::vector<Vec2>& poly) {
  return poly.size() <= kBruteForceEdges ? polygonSelfContactBruteForce(poly)
                                         : polygonSelfContactSweep(poly);
}

}  // namespace tactile::sim
