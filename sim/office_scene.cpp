#include "sim/office_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "sim/clearance_grid.h"

namespace tactile::sim {
namespace {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng_() >> 11) * 0x1.0p-53;
  }
  int integer(int lo, int hi) {  // inclusive
    return lo + static_cast<int>(uniform(0.0, static_cast<double>(hi - lo + 1) - 1e-9));
  }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }

 private:
  std::mt19937_64 rng_;
};

// Axis-aligned box.
struct Box {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  Box grown(double d) const { return {x0 - d, y0 - d, x1 + d, y1 + d}; }
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  double area() const { return width() * height(); }
};

Box boxOf(const std::vector<Vec2>& poly) {
  Box b{poly[0].x(), poly[0].y(), poly[0].x(), poly[0].y()};
  for (const Vec2& p : poly) {
    b.x0 = std::min(b.x0, p.x());
    b.y0 = std::min(b.y0, p.y());
    b.x1 = std::max(b.x1, p.x());
    b.y1 = std::max(b.y1, p.y());
  }
  return b;
}

std::vector<Vec2> boxPolygon(const Box& b) {
  return {Vec2(b.x0, b.y0), Vec2(b.x1, b.y0), Vec2(b.x1, b.y1), Vec2(b.x0, b.y1)};
}

// Distance from p to a polygon (0 inside).
double polygonDistance(const Vec2& p, const std::vector<Vec2>& poly) {
  if (pointInPolygon(p, poly)) return 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < poly.size(); ++i) {
    best = std::min(best, pointSegmentDistance2(p, poly[i], poly[(i + 1) % poly.size()]));
  }
  return std::sqrt(best);
}

// A room's free rectangle between wall faces (or the bounds).
struct Room {
  Box box;
};

// Robot: turning in place sweeps 126 units round the rear axle (131 with the domes).
constexpr double kStartClearance = 150.0;
constexpr double kGoalClearance = 100.0;
// Furniture keeps this far from start and goal.
constexpr double kStartReserve = 220.0;
constexpr double kGoalReserve = 160.0;
// A door stays clear this far in front of and behind the wall, and this far beside the opening.
constexpr double kApproachDepth = 160.0;
constexpr double kApproachSide = 60.0;
// Walls meeting another wall keep this far from its openings.
constexpr double kJunctionClearance = 100.0;
// A door's or gap's edge keeps this far from the ends of its wall.
constexpr double kOpeningEndClearance = 90.0;
// Two pieces of furniture, or furniture and a room face it does not touch, are either flush or
// at least this far apart (a passage the robot can take).
constexpr double kPassage = 130.0;
// Interior walls reach this far into the wall (or bound) they meet, so that the junction is a
// crossing of edges, not two vertices touching.
constexpr double kWallOverlap = 4.0;
// Furniture and bumps against an interior wall reach this far into it.
constexpr double kFaceOverlap = 2.0;

class Generator {
 public:
  Generator(std::uint64_t seed, const OfficeOptions& options)
      : seed_(seed), options_(options), rng_(seed * 0x9E3779B97F4A7C15ull + 0x0FF1CEull) {}

  OfficeScene run() {
    width_ = 10.0 * std::round(rng_.uniform(2200.0, 3400.0) / 10.0);
    height_ = 10.0 * std::round(rng_.uniform(1800.0, 2800.0) / 10.0);
    split(Box{0.0, 0.0, width_, height_}, 0);
    placeBumps();
    placeStartAndGoal();
    for (const Room& room : rooms_)
      furnish(room);
    return assemble();
  }

 private:
  struct Piece {
    std::vector<Vec2> polygon;
    Box box;
  };

  Box bounds() const { return {0.0, 0.0, width_, height_}; }

  // Binary space partition into rooms: a region wider (or taller) than two rooms is split by a
  // wall with a door (and sometimes a narrow gap, sometimes a second door), unless the dice say
  // it is a room already.
  void split(const Box& region, int depth) {
    const double minRoom = options_.minRoomUnits;
    const double thickness = static_cast<double>(rng_.integer(10, 20));
    const bool canX = region.width() >= 2.0 * minRoom + thickness;  // a wall along y at some x
    const bool canY = region.height() >= 2.0 * minRoom + thickness;
    const bool stop = depth >= 2 && region.area() < 2.6e6 && rng_.chance(0.35);
    if ((!canX && !canY) || stop) {
      rooms_.push_back(Room{region});
      return;
    }
    bool vertical;  // the wall runs along y (splits x)
    if (canX && canY) {
      vertical = region.width() >= region.height() ? rng_.chance(0.8) : rng_.chance(0.2);
    } else {
      vertical = canX;
    }
    const double lo = (vertical ? region.x0 : region.y0) + minRoom + 0.5 * thickness;
    const double hi = (vertical ? region.x1 : region.y1) - minRoom - 0.5 * thickness;
    for (int attempt = 0; attempt < 12; ++attempt) {
      const double c = std::round(rng_.uniform(lo, hi));
      Box wall = vertical ? Box{c - 0.5 * thickness, region.y0, c + 0.5 * thickness, region.y1}
                          : Box{region.x0, c - 0.5 * thickness, region.x1, c + 0.5 * thickness};
      bool clear = true;
      for (const Box& o : openingBoxes_) {
        if (wall.grown(kJunctionClearance).overlaps(o)) clear = false;
      }
      if (!clear) continue;
      addWall(wall, vertical);
      if (vertical) {
        split(Box{region.x0, region.y0, wall.x0, region.y1}, depth + 1);
        split(Box{wall.x1, region.y0, region.x1, region.y1}, depth + 1);
      } else {
        split(Box{region.x0, region.y0, region.x1, wall.y0}, depth + 1);
        split(Box{region.x0, wall.y1, region.x1, region.y1}, depth + 1);
      }
      return;
    }
    rooms_.push_back(Room{region});
  }

  // A wall across `wall` (its extent between the faces it meets), cut by its openings.
  void addWall(const Box& wall, bool vertical) {
    const double from = vertical ? wall.y0 : wall.x0;
    const double to = vertical ? wall.y1 : wall.x1;
    const double across = vertical ? 0.5 * (wall.x0 + wall.x1) : 0.5 * (wall.y0 + wall.y1);
    const double thickness = vertical ? wall.width() : wall.height();
    struct Cut {
      double lo, hi;
      OfficeOpening::Kind kind;
    };
    std::vector<Cut> cuts;
    const auto fits = [&](double lo, double hi) {
      if (lo < from + kOpeningEndClearance || hi > to - kOpeningEndClearance) return false;
      for (const Cut& c : cuts) {
        if (lo < c.hi + 120.0 && c.lo - 120.0 < hi) return false;
      }
      return true;
    };
    const auto tryCut = [&](double w, OfficeOpening::Kind kind) {
      for (int attempt = 0; attempt < 12; ++attempt) {
        const double centre = std::round(rng_.uniform(from + 0.5 * w, to - 0.5 * w));
        const double lo = centre - std::round(0.5 * w);
        const double hi = lo + w;
        if (fits(lo, hi)) {
          cuts.push_back({lo, hi, kind});
          return;
        }
      }
    };
    tryCut(std::round(rng_.uniform(options_.doorMinUnits, options_.doorMaxUnits)),
           OfficeOpening::Kind::Door);
    if (rng_.chance(0.55)) {
      tryCut(std::round(rng_.uniform(options_.gapMinUnits, options_.gapMaxUnits)),
             OfficeOpening::Kind::NarrowGap);
    }
    if (to - from > 1400.0 && rng_.chance(0.3)) {
      tryCut(std::round(rng_.uniform(options_.doorMinUnits, options_.doorMaxUnits)),
             OfficeOpening::Kind::Door);
    }
    std::sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) { return a.lo < b.lo; });
    // The solid pieces, the end ones reaching into the faces they meet.
    double at = std::max(0.0, from - kWallOverlap);
    const double limit = std::min(vertical ? height_ : width_, to + kWallOverlap);
    const auto solid = [&](double lo, double hi) {
      if (hi - lo <= 0.0) return;
      const Box piece = vertical ? Box{wall.x0, lo, wall.x1, hi} : Box{lo, wall.y0, hi, wall.y1};
      wallPieces_.push_back(piece);
    };
    for (const Cut& c : cuts) {
      solid(at, c.lo);
      at = c.hi;
      OfficeOpening o;
      o.kind = c.kind;
      o.widthUnits = c.hi - c.lo;
      o.wallThicknessUnits = thickness;
      o.wallAlongX = !vertical;
      const double mid = 0.5 * (c.lo + c.hi);
      o.centre = vertical ? Vec2(across, mid) : Vec2(mid, across);
      openings_.push_back(o);
      openingBoxes_.push_back(vertical ? Box{wall.x0, c.lo, wall.x1, c.hi}
                                       : Box{c.lo, wall.y0, c.hi, wall.y1});
      approach_.push_back(vertical ? Box{wall.x0 - kApproachDepth, c.lo - kApproachSide,
                                         wall.x1 + kApproachDepth, c.hi + kApproachSide}
                                   : Box{c.lo - kApproachSide, wall.y0 - kApproachDepth,
                                         c.hi + kApproachSide, wall.y1 + kApproachDepth});
    }
    solid(at, limit);
  }

  // Whether a box grown by `clearance` meets any wall piece (except `ignore`) or the bounds.
  bool nearWalls(const Box& b, double clearance, const Box* ignore = nullptr) const {
    const Box g = b.grown(clearance);
    for (const Box& w : wallPieces_) {
      if (ignore && &w == ignore) continue;
      if (g.overlaps(w)) return true;
    }
    return false;
  }

  bool inApproach(const Box& b) const {
    return std::any_of(approach_.begin(), approach_.end(),
                       [&](const Box& a) { return a.overlaps(b); });
  }

  // Bumps: small boxes, triangles and half-hexagons on the faces of the walls and of the bounds,
  // clear of the doors and of the walls they do not stand on (no pockets).
  void placeBumps() {
    struct Face {
      double along0, along1;  // extent along the face
      double at;              // coordinate of the face
      bool vertical;          // the face runs along y
      double out;             // +1 or -1: the direction into free space
      const Box* wall;        // the wall piece it belongs to (nullptr for a bound)
    };
    std::vector<Face> faces;
    faces.push_back({0.0, width_, 0.0, false, 1.0, nullptr});
    faces.push_back({0.0, width_, height_, false, -1.0, nullptr});
    faces.push_back({0.0, height_, 0.0, true, 1.0, nullptr});
    faces.push_back({0.0, height_, width_, true, -1.0, nullptr});
    for (const Box& w : wallPieces_) {
      const bool vertical = w.height() > w.width();
      if (vertical) {
        faces.push_back({w.y0, w.y1, w.x0, true, -1.0, &w});
        faces.push_back({w.y0, w.y1, w.x1, true, 1.0, &w});
      } else {
        faces.push_back({w.x0, w.x1, w.y0, false, -1.0, &w});
        faces.push_back({w.x0, w.x1, w.y1, false, 1.0, &w});
      }
    }
    for (const Face& f : faces) {
      const double length = f.along1 - f.along0;
      const int tries = static_cast<int>(length / 700.0 * rng_.uniform(0.0, 2.0) + 0.5);
      for (int t = 0; t < tries; ++t) {
        const int shape = rng_.integer(0, 2);
        const double len = std::round(rng_.uniform(30.0, 120.0));
        const double depth = std::round(rng_.uniform(10.0, 40.0));
        const double mid = std::round(rng_.uniform(f.along0 + 0.5 * len, f.along1 - 0.5 * len));
        const double base = f.at - (f.wall ? f.out * kFaceOverlap : 0.0);
        const double tip = f.at + f.out * depth;
        // Local (along, out) corners, turned into world points.
        std::vector<std::pair<double, double>> local;
        if (shape == 0) {
          local = {{mid - 0.5 * len, base},
                   {mid + 0.5 * len, base},
                   {mid + 0.5 * len, tip},
                   {mid - 0.5 * len, tip}};
        } else if (shape == 1) {
          local = {{mid - 0.5 * len, base}, {mid + 0.5 * len, base}, {mid, tip}};
        } else {
          local = {{mid - 0.5 * len, base},
                   {mid + 0.5 * len, base},
                   {mid + 0.3 * len, tip},
                   {mid - 0.3 * len, tip}};
        }
        Piece p;
        for (const auto& [a, o] : local)
          p.polygon.push_back(f.vertical ? Vec2(o, a) : Vec2(a, o));
        p.box = boxOf(p.polygon);
        if (!insideBounds(p.box)) continue;
        if (inApproach(p.box.grown(20.0))) continue;
        if (nearWalls(p.box, kPassage, f.wall)) continue;
        if (f.wall == nullptr && nearBounds(p.box, kPassage, f)) continue;
        bool clash = false;
        for (const Piece& q : bumps_) {
          if (p.box.grown(kPassage).overlaps(q.box)) clash = true;
        }
        if (clash) continue;
        bumps_.push_back(std::move(p));
      }
    }
  }

  bool insideBounds(const Box& b) const {
    return b.x0 >= 0.0 && b.y0 >= 0.0 && b.x1 <= width_ && b.y1 <= height_;
  }

  // A bump on a bound closer than `d` to one of the other bounds (a pocket in a room's corner).
  template <class Face>
  bool nearBounds(const Box& b, double d, const Face& f) const {
    if (f.vertical) return b.y0 < d || b.y1 > height_ - d;
    return b.x0 < d || b.x1 > width_ - d;
  }

  double clearanceAt(const Vec2& p) const {
    double best = std::min({p.x(), width_ - p.x(), p.y(), height_ - p.y()});
    for (const Box& w : wallPieces_)
      best = std::min(best, polygonDistance(p, boxPolygon(w)));
    for (const Piece& b : bumps_)
      best = std::min(best, polygonDistance(p, b.polygon));
    return best;
  }

  // A point of the room at least `clearance` from walls and bumps.
  Vec2 pointIn(const Room& room, double clearance) {
    const Box inner = room.box.grown(-clearance);
    Vec2 best(0.5 * (room.box.x0 + room.box.x1), 0.5 * (room.box.y0 + room.box.y1));
    for (int attempt = 0; attempt < 60 && inner.width() > 0.0 && inner.height() > 0.0; ++attempt) {
      const Vec2 p(std::round(rng_.uniform(inner.x0, inner.x1)),
                   std::round(rng_.uniform(inner.y0, inner.y1)));
      if (clearanceAt(p) >= clearance) return p;
    }
    return best;
  }

  void placeStartAndGoal() {
    startRoom_ = static_cast<std::size_t>(rng_.integer(0, static_cast<int>(rooms_.size()) - 1));
    goalRoom_ = startRoom_;
    if (rooms_.size() > 1) {
      const auto centre = [](const Room& r) {
        return Vec2(0.5 * (r.box.x0 + r.box.x1), 0.5 * (r.box.y0 + r.box.y1));
      };
      // Half the time the farthest room, otherwise any other.
      if (rng_.chance(0.5)) {
        double far = -1.0;
        for (std::size_t i = 0; i < rooms_.size(); ++i) {
          const double d = (centre(rooms_[i]) - centre(rooms_[startRoom_])).norm();
          if (i != startRoom_ && d > far) {
            far = d;
            goalRoom_ = i;
          }
        }
      } else {
        const int pick = rng_.integer(0, static_cast<int>(rooms_.size()) - 2);
        goalRoom_ = static_cast<std::size_t>(pick) >= startRoom_
                        ? static_cast<std::size_t>(pick) + 1
                        : static_cast<std::size_t>(pick);
      }
    }
    start_ = pointIn(rooms_[startRoom_], kStartClearance);
    startTheta_ = std::round(rng_.uniform(-std::numbers::pi, std::numbers::pi) * 1024.0) / 1024.0;
    goal_ = pointIn(rooms_[goalRoom_], kGoalClearance);
    if (goalRoom_ == startRoom_) {
      // One room: the goal as far from the start as a few draws find.
      for (int attempt = 0; attempt < 8; ++attempt) {
        const Vec2 g = pointIn(rooms_[goalRoom_], kGoalClearance);
        if ((g - start_).norm() > (goal_ - start_).norm()) goal_ = g;
      }
    }
  }

  // A furniture shape centred near the origin, in local coordinates.
  std::vector<Vec2> shape(int kind) {
    const auto R = [&](double lo, double hi) { return std::round(rng_.uniform(lo, hi)); };
    std::vector<Vec2> p;
    switch (kind) {
      case 0: {  // desk, cabinet
        const double w = R(80, 260), h = R(50, 160);
        p = {Vec2(0, 0), Vec2(w, 0), Vec2(w, h), Vec2(0, h)};
        break;
      }
      case 1: {  // L
        const double a = R(150, 300), b = R(150, 300), t = R(50, 100);
        p = {Vec2(0, 0), Vec2(a, 0), Vec2(a, t), Vec2(t, t), Vec2(t, b), Vec2(0, b)};
        break;
      }
      case 2: {  // U
        const double a = R(180, 320), b = R(120, 240), t = R(40, 70);
        p = {Vec2(0, 0),     Vec2(a, 0), Vec2(a, b), Vec2(a - t, b),
             Vec2(a - t, t), Vec2(t, t), Vec2(t, b), Vec2(0, b)};
        break;
      }
      case 3: {  // T
        const double a = R(160, 300), t = R(40, 70), s = R(40, 80), l = R(80, 200);
        p = {Vec2(-0.5 * a, 0),    Vec2(0.5 * a, 0),      Vec2(0.5 * a, t),  Vec2(0.5 * s, t),
             Vec2(0.5 * s, t + l), Vec2(-0.5 * s, t + l), Vec2(-0.5 * s, t), Vec2(-0.5 * a, t)};
        break;
      }
      case 4: {  // convex polygon: triangle, pentagon, hexagon, octagon (a pillar, a round table)
        static constexpr int kSides[4] = {3, 5, 6, 8};
        const int n = kSides[rng_.integer(0, 3)];
        const double r = R(40, 110);
        const double phase = rng_.uniform(0.0, 2.0 * std::numbers::pi);
        for (int i = 0; i < n; ++i) {
          const double a = phase + 2.0 * std::numbers::pi * i / n;
          p.emplace_back(r * std::cos(a), r * std::sin(a));
        }
        break;
      }
      default: {  // thin partition
        const double l = R(150, 400), t = R(8, 15);
        p = {Vec2(0, 0), Vec2(l, 0), Vec2(l, t), Vec2(0, t)};
        break;
      }
    }
    // Centre on the bounding box (whole units, so that quarter turns stay on whole units).
    const Box b = boxOf(p);
    const Vec2 c(std::floor(0.5 * (b.x0 + b.x1)), std::floor(0.5 * (b.y0 + b.y1)));
    for (Vec2& v : p)
      v = Vec2(std::round((v.x() - c.x()) * 1024.0) / 1024.0,
               std::round((v.y() - c.y()) * 1024.0) / 1024.0);
    return p;
  }

  // Turned by a quarter turn `q` times, exactly.
  static std::vector<Vec2> quarterTurn(const std::vector<Vec2>& p, int q) {
    std::vector<Vec2> out;
    for (const Vec2& v : p) {
      switch (q & 3) {
        case 0:
          out.push_back(v);
          break;
        case 1:
          out.emplace_back(-v.y(), v.x());
          break;
        case 2:
          out.emplace_back(-v.x(), -v.y());
          break;
        default:
          out.emplace_back(v.y(), -v.x());
          break;
      }
    }
    return out;
  }

  static std::vector<Vec2> rotate(const std::vector<Vec2>& p, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    std::vector<Vec2> out;
    for (const Vec2& v : p)
      out.emplace_back(c * v.x() - s * v.y(), s * v.x() + c * v.y());
    return out;
  }

  // Whether a candidate piece keeps its distances: inside the room (touching its faces allowed),
  // flush with a face or kPassage from it, kPassage from other furniture and bumps, clear of the
  // doors' approaches and of start and goal.
  bool acceptable(const Piece& p, const Room& room) const {
    const Box& b = p.box;
    const Box& r = room.box;
    const double eps = 1e-9;
    if (b.x0 < r.x0 - kFaceOverlap - eps || b.y0 < r.y0 - kFaceOverlap - eps ||
        b.x1 > r.x1 + kFaceOverlap + eps || b.y1 > r.y1 + kFaceOverlap + eps)
      return false;
    if (!insideBounds(b)) return false;
    const auto spaced = [&](double gap) { return gap <= eps || gap >= kPassage; };
    if (!spaced(b.x0 - r.x0) || !spaced(r.x1 - b.x1) || !spaced(b.y0 - r.y0) ||
        !spaced(r.y1 - b.y1))
      return false;
    if (inApproach(b)) return false;
    for (const Piece& q : furniture_) {
      if (b.grown(kPassage).overlaps(q.box)) return false;
    }
    for (const Piece& q : bumps_) {
      if (b.grown(kPassage).overlaps(q.box)) return false;
    }
    if (polygonDistance(start_, p.polygon) < kStartReserve) return false;
    return polygonDistance(goal_, p.polygon) >= kGoalReserve;
  }

  // Furniture: about one piece per 0.25 M square units of floor, 1..6 a room; half of them
  // against a face (a corner now and then), the rest free-standing and turned any way.
  void furnish(const Room& room) {
    const double area = room.box.area();
    const int count =
        std::clamp(static_cast<int>(std::round(area / 250000.0 * rng_.uniform(0.6, 1.4))), 1, 6);
    for (int n = 0; n < count; ++n) {
      const int kind = rng_.integer(0, 5);
      const std::vector<Vec2> local = shape(kind);
      const bool againstFace = rng_.chance(kind == 4 ? 0.2 : 0.6);
      for (int attempt = 0; attempt < 25; ++attempt) {
        Piece p;
        if (againstFace) {
          const int side = rng_.integer(0, 3);  // 0 bottom, 1 top, 2 left, 3 right
          // A partition stands out from the face; other shapes any way round.
          const int quarter =
              kind == 5 ? (side < 2 ? 1 : 0) + 2 * rng_.integer(0, 1) : rng_.integer(0, 3);
          const std::vector<Vec2> turnedPoly = quarterTurn(local, quarter);
          const Box lb = boxOf(turnedPoly);
          const Box& r = room.box;
          const bool alongX = side < 2;
          const double span = alongX ? lb.width() : lb.height();
          const double lo = alongX ? r.x0 : r.y0;
          const double hi = alongX ? r.x1 : r.y1;
          double pos;  // where the box's low edge along the face goes
          const double roll = rng_.uniform(0.0, 1.0);
          if (roll < 0.15) {
            pos = lo;
          } else if (roll < 0.3) {
            pos = hi - span;
          } else {
            pos = std::round(rng_.uniform(lo + kPassage, hi - kPassage - span));
          }
          const auto overlapAt = [&](double face, bool isLow) {
            const bool bound = isLow ? face <= 0.0 : face >= (alongX ? height_ : width_);
            return bound ? 0.0 : kFaceOverlap;
          };
          Vec2 shift;
          if (side == 0) {
            shift = Vec2(pos - lb.x0, r.y0 - overlapAt(r.y0, true) - lb.y0);
          } else if (side == 1) {
            shift = Vec2(pos - lb.x0, r.y1 + overlapAt(r.y1, false) - lb.y1);
          } else if (side == 2) {
            shift = Vec2(r.x0 - overlapAt(r.x0, true) - lb.x0, pos - lb.y0);
          } else {
            shift = Vec2(r.x1 + overlapAt(r.x1, false) - lb.x1, pos - lb.y0);
          }
          for (const Vec2& v : turnedPoly)
            p.polygon.push_back(v + shift);
        } else {
          const bool square = rng_.chance(0.5);
          const std::vector<Vec2> turnedPoly =
              square ? quarterTurn(local, rng_.integer(0, 3))
                     : rotate(local, rng_.uniform(0.0, 2.0 * std::numbers::pi));
          const Box& r = room.box;
          const Vec2 c(std::round(rng_.uniform(r.x0 + kPassage, r.x1 - kPassage)),
                       std::round(rng_.uniform(r.y0 + kPassage, r.y1 - kPassage)));
          for (const Vec2& v : turnedPoly) {
            const Vec2 w = v + c;
            p.polygon.emplace_back(std::round(w.x() * 1024.0) / 1024.0,
                                   std::round(w.y() * 1024.0) / 1024.0);
          }
        }
        p.box = boxOf(p.polygon);
        if (acceptable(p, room)) {
          furniture_.push_back(std::move(p));
          break;
        }
      }
    }
  }

  OfficeScene assemble() {
    OfficeScene out;
    out.openings = openings_;
    out.rooms = rooms_.size();
    out.bumps = bumps_.size();
    Scene& s = out.scene;
    s.name = "random:office:" + std::to_string(seed_);
    s.bounds = {0.0, 0.0, width_, height_};
    s.start = Pose2d{start_.x(), start_.y(), startTheta_};
    s.goal = goal_;
    for (const Box& w : wallPieces_)
      s.obstacles.push_back(Obstacle{boxPolygon(w)});
    for (const Piece& b : bumps_)
      s.obstacles.push_back(Obstacle{b.polygon});
    const std::size_t fixed = s.obstacles.size();
    for (const Piece& f : furniture_)
      s.obstacles.push_back(Obstacle{f.polygon});
    const double radius = options_.robotHalfWidthUnits + options_.marginUnits;
    // Furniture that cuts start from goal is left out, the last placed first.
    for (;;) {
      const ClearanceGrid grid(s, radius, options_.gridCellUnits);
      out.connected = grid.connected(start_, goal_);
      if (out.connected || s.obstacles.size() == fixed) break;
      s.obstacles.pop_back();
    }
    out.furniture = s.obstacles.size() - fixed;
    return out;
  }

  std::uint64_t seed_;
  OfficeOptions options_;
  Rng rng_;
  double width_ = 0.0;
  double height_ = 0.0;
  std::vector<Room> rooms_;
  std::vector<Box> wallPieces_;
  std::vector<Box> openingBoxes_;
  std::vector<Box> approach_;
  std::vector<OfficeOpening> openings_;
  std::vector<Piece> bumps_;
  std::vector<Piece> furniture_;
  std::size_t startRoom_ = 0;
  std::size_t goalRoom_ = 0;
  Vec2 start_ = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
  double startTheta_ = 0.0;
  Vec2 goal_ = Vec2::Zero();
};

}  // namespace

OfficeScene generateOfficeScene(std::uint64_t seed, const OfficeOptions& options) {
  return Generator(seed, options).run();
}

}  // namespace tactile::sim
