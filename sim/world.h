// The immutable, shareable part of a simulation: the scene's obstacle edges (and the scene bounds
// as walls), what each vertex looks like from free space, and a uniform-grid spatial index over
// the edges (docs/sim.md#spatial-index) so that a step only looks at edges within reach of the
// robot.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "sim/geometry.h"
#include "sim/scene.h"

namespace tactile::sim {

// One obstacle edge, oriented so that free space lies on its right: obstacle polygons run
// counter-clockwise, the bounds run clockwise.
struct Edge {
  Vec2 a = Vec2::Zero();
  Vec2 b = Vec2::Zero();
  Vec2 dir = Vec2::UnitX();  // unit vector a -> b
  int obstacle = -1;         // index into Scene::obstacles; -1 for the bounds
  int vertexA = 0;           // global vertex ids (see World::vertexKind)
  int vertexB = 0;
};

// How a polygon vertex looks from free space. A vertex whose edges turn by less than
// kFlatVertexDegrees counts as flat (part of a straight wall).
enum class VertexKind : std::uint8_t { Flat, Convex, Concave };
inline constexpr double kFlatVertexDegrees = 20.0;

// Reusable scratch for EdgeIndex::query: a visit stamp per edge, so each edge is reported once
// without clearing a set per query. One per thread.
struct EdgeQueryScratch {
  std::vector<std::uint32_t> seen;
  std::uint32_t stamp = 0;
};

// Uniform grid over the scene bounds; each cell lists the edges whose segment passes through it
// (compressed row storage). A query returns every edge that meets a box, possibly a few more.
class EdgeIndex {
 public:
  EdgeIndex() = default;
  EdgeIndex(const std::vector<Edge>& edges, const SceneBounds& bounds, double cellSizeUnits);

  // Appends to `out` (after clearing it) the ids of all edges that may meet the box [lo, hi].
  void query(const Vec2& lo, const Vec2& hi, std::vector<int>& out,
             EdgeQueryScratch& scratch) const;

  double cellSizeUnits() const { return cell_; }
  int columns() const { return cols_; }
  int rows() const { return rows_; }

 private:
  double x0_ = 0.0;
  double y0_ = 0.0;
  double cell_ = 1.0;
  int cols_ = 0;
  int rows_ = 0;
  std::size_t edgeCount_ = 0;
  std::vector<std::uint32_t> cellStart_;  // cols_ * rows_ + 1 offsets into cellEdges_
  std::vector<int> cellEdges_;
};

class World {
 public:
  // `cellSizeUnits` <= 0 picks a size from the scene (about half a robot width, larger for huge
  // scenes so the grid stays under a few million cells).
  explicit World(Scene scene, double cellSizeUnits = 0.0);

  const Scene& scene() const { return scene_; }
  const std::vector<Edge>& edges() const { return edges_; }
  VertexKind vertexKind(int vertex) const { return vertexKinds_[vertex]; }
  const EdgeIndex& index() const { return index_; }

 private:
  Scene scene_;
  std::vector<Edge> edges_;
  std::vector<VertexKind> vertexKinds_;
  EdgeIndex index_;
};

}  // namespace tactile::sim
