// Whether a polygon is simple (its boundary does not cross or touch itself), in O(n log n) time by
// a sweep line, so scenes with obstacles of a million vertices validate within a second
// (docs/sim.md#scene-validation, docs/bench-sim.md).
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "sim/geometry.h"

namespace tactile::sim {

// Two edges of a polygon that share a point although they may not (edge i runs from vertex i to
// vertex (i + 1) % n), with first < second.
using EdgePair = std::pair<std::size_t, std::size_t>;

// The first problem of `poly` (n >= 3 vertices, no two consecutive vertices equal) as a pair of
// edges, or nullopt when the polygon is simple: non-adjacent edges share no point, adjacent edges
// share only their common vertex (they do not fold back onto each other). Polygons of up to
// kBruteForceEdges edges are checked pair by pair, so the pair reported is the first in edge
// order; larger ones by the sweep, which reports some offending pair.
std::optional<EdgePair> polygonSelfContact(const std::vector<Vec2>& poly);

inline constexpr std::size_t kBruteForceEdges = 256;

// The two strategies on their own, for tests and benchmarks.
std::optional<EdgePair> polygonSelfContactBruteForce(const std::vector<Vec2>& poly);
std::optional<EdgePair> polygonSelfContactSweep(const std::vector<Vec2>& poly);

}  // namespace tactile::sim
