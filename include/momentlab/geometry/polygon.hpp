#pragma once

/// \file
/// Checks on the polygons of bodies and obstacles (exact, with the orientation predicate).

#include <span>
#include <string>
#include <vector>
#include <utility>
#include <cstddef>

#include "momentlab/core/sign.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// The exact orientation of the triangle a, b, c: positive when counter-clockwise.
[[nodiscard]] Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c);

/// Why `polygon` is not a simple polygon, or "" when it is one. Either orientation is
/// accepted. Problems found: fewer than three vertices, a non-finite coordinate, two
/// consecutive vertices equal, two edges meeting other than at the vertex they share
/// (crossing, touching, or an edge folding back along the previous one, which includes a
/// polygon of zero area). Exact; O(n log n) in the number of vertices (a sweep line).
[[nodiscard]] std::string polygon_problem(std::span<const Vec2> polygon);

/// True when the simple polygon's vertices run counter-clockwise (exact: the turn at its
/// leftmost, then lowest, vertex, where a simple polygon cannot be straight).
[[nodiscard]] bool is_counter_clockwise(std::span<const Vec2> polygon);

/// True when p lies in the closed polygon: inside or on its boundary (exact winding number).
[[nodiscard]] bool in_closed_polygon(std::span<const Vec2> polygon, const Vec2& p);

/// True when the point p is within `distance` of the closed segment ab, exactly (squared
/// distances compared in exact arithmetic, after a float filter with a wide margin).
[[nodiscard]] bool within_distance_of_segment(const Vec2& p, const Vec2& a, const Vec2& b, double distance);

/// True when p is within `distance` of some edge of the polygon (exactly).
[[nodiscard]] bool within_distance_of_boundary(std::span<const Vec2> polygon, const Vec2& p, double distance);

/// True when the interiors of two simple polygons meet, as far as these tell: two edges cross
/// properly, a vertex, an edge midpoint or the vertex centroid of one lies strictly inside
/// the other (the tests are exact for the points tested; for messages, e.g. "the body overlaps
/// obstacle 2" instead of "touches no obstacle").
[[nodiscard]] bool polygons_overlap(std::span<const Vec2> a, std::span<const Vec2> b);

/// The distance from p to the boundary of the polygon (floating point: for messages only).
[[nodiscard]] double distance_to_boundary(std::span<const Vec2> polygon, const Vec2& p);

/// The edges of a polygon that may lie within `distance` of a point: a uniform grid over the
/// polygon's box, each edge entered in the cells near it (the boxes, grown by the distance and a
/// rounding margin, of pieces of the edge no longer than a cell). A superset of the edges within
/// the distance: the exact test (within_distance_of_segment) decides. About 4 m cells for m
/// edges, about as long as the mean edge: a polygon of total length L costs O(m + L / h) to index
/// and a query O(1 + the edges entered in its cell), for outlines whose edges do not crowd into
/// a few cells (docs/benchmarks.md, Polygons).
class EdgeGrid {
public:
    /// Throws std::invalid_argument for no vertices, a non-finite vertex or a distance that is
    /// negative or not finite.
    EdgeGrid(std::span<const Vec2> polygon, double distance);
    /// The edges (edge k runs from vertex k to k + 1) entered in the cell of q, increasing; none
    /// when q lies beyond the polygon's box grown by the distance.
    [[nodiscard]] std::span<const std::size_t> near(const Vec2& q) const;

private:
    [[nodiscard]] std::pair<std::size_t, std::size_t> index(const Vec2& q) const;
    Vec2 lo_ = Vec2::Zero(), hi_ = Vec2::Zero();
    double margin_ = 0.0, cell_ = 1.0;
    std::size_t nx_ = 1, ny_ = 1;
    std::vector<std::size_t> start_;
    std::vector<std::size_t> edges_;
};

}  // namespace momentlab
