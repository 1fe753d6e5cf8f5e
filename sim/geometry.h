// Small 2-D geometry kernels shared by the scene validator, the spatial index and the contact
// model. Points are Eigen vectors; every function is total (no NaN for degenerate input).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace tactile::sim {

using Vec2 = Eigen::Vector2d;

inline double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Parameter t in [0, 1] of the point of segment [a, b] closest to p:
//   t = clamp(((p - a) . (b - a)) / |b - a|^2, 0, 1); a zero-length segment gives t = 0.
inline double closestParameter(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 <= 0.0) return 0.0;
  return std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
}

// Squared distance from p to segment [a, b].
inline double pointSegmentDistance2(const Vec2& p, const Vec2& a, const Vec2& b) {
  const double t = closestParameter(p, a, b);
  return (p - (a + t * (b - a))).squaredNorm();
}

// Orientation sign of (a, b, c): +1 counter-clockwise, -1 clockwise, 0 collinear (exact).
inline int orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double v = cross2(b - a, c - a);
  return (v > 0.0) - (v < 0.0);
}

inline bool onSegmentCollinear(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

// Whether closed segments [a, b] and [c, d] share at least one point (touching counts).
inline bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && onSegmentCollinear(a, b, c)) return true;
  if (o2 == 0 && onSegmentCollinear(a, b, d)) return true;
  if (o3 == 0 && onSegmentCollinear(c, d, a)) return true;
  if (o4 == 0 && onSegmentCollinear(c, d, b)) return true;
  return false;
}

// Squared distance from p to the axis-aligned box [lo, hi] (0 inside).
inline double pointBoxDistance2(const Vec2& p, const Vec2& lo, const Vec2& hi) {
  const double dx = std::max({lo.x() - p.x(), 0.0, p.x() - hi.x()});
  const double dy = std::max({lo.y() - p.y(), 0.0, p.y() - hi.y()});
  return dx * dx + dy * dy;
}

// Whether segment [a, b] meets the closed box [lo, hi] (Liang-Barsky clipping).
inline bool segmentHitsBox(const Vec2& a, const Vec2& b, const Vec2& lo, const Vec2& hi) {
  double t0 = 0.0;
  double t1 = 1.0;
  const Vec2 d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - lo.x(), hi.x() - a.x(), a.y() - lo.y(), hi.y() - a.y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
    } else {
      const double r = q[i] / p[i];
      if (p[i] < 0.0) {
        t0 = std::max(t0, r);
      } else {
        t1 = std::min(t1, r);
      }
      if (t0 > t1) return false;
    }
  }
  return true;
}

// Squared distance between segment [a, b] and the box [lo, hi]: 0 when they meet, otherwise the
// smallest of the endpoint-to-box and box-corner-to-segment distances.
inline double segmentBoxDistance2(const Vec2& a, const Vec2& b, const Vec2& lo, const Vec2& hi) {
  if (segmentHitsBox(a, b, lo, hi)) return 0.0;
  double best = std::min(pointBoxDistance2(a, lo, hi), pointBoxDistance2(b, lo, hi));
  best = std::min(best, pointSegmentDistance2(lo, a, b));
  best = std::min(best, pointSegmentDistance2(hi, a, b));
  best = std::min(best, pointSegmentDistance2(Vec2(lo.x(), hi.y()), a, b));
  best = std::min(best, pointSegmentDistance2(Vec2(hi.x(), lo.y()), a, b));
  return best;
}

// Even-odd point-in-polygon test (points on the boundary may go either way).
template <class Points>
bool pointInPolygon(const Vec2& p, const Points& poly) {
  bool inside = false;
  const std::size_t n = poly.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

}  // namespace tactile::sim
