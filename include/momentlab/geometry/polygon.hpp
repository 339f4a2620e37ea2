#pragma once

/// \file
/// Checks on the polygons of bodies and obstacles (exact, with the orientation predicate).

#include <optional>
#include <span>
#include <string>
#include <vector>
#include <utility>
#include <cstddef>

#include "momentlab/core/dyadic.hpp"
#include "momentlab/core/sign.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// A vertex with exact coordinates: the decimals of a polygon scaled to integers too long for
/// doubles (more than about 16 digits: scaled_polygons, mechanics/find_contacts.hpp). Each check
/// below that takes doubles takes these too, with the same meaning, exactly.
struct ExactPoint {
    Dyadic x_, y_;
    [[nodiscard]] const Dyadic& x() const { return x_; }
    [[nodiscard]] const Dyadic& y() const { return y_; }
    friend bool operator==(const ExactPoint& a, const ExactPoint& b) { return a.x_ == b.x_ && a.y_ == b.y_; }
};
using ExactPolygon = std::vector<ExactPoint>;

/// The doubles nearest p's coordinates.
[[nodiscard]] inline Vec2 rounded(const ExactPoint& p) { return Vec2(p.x().to_double(), p.y().to_double()); }
[[nodiscard]] inline const Vec2& rounded(const Vec2& p) { return p; }
/// The doubles nearest a polygon's vertices.
[[nodiscard]] std::vector<Vec2> rounded(std::span<const ExactPoint> polygon);

/// The exact orientation of the triangle a, b, c: positive when counter-clockwise.
[[nodiscard]] Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c);
[[nodiscard]] Sign orient2d(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c);

/// Why `polygon` is not a simple polygon, or "" when it is one. Either orientation is
/// accepted. Problems found: fewer than three vertices, a non-finite coordinate, two
/// consecutive vertices equal, two edges meeting other than at the vertex they share
/// (crossing, touching, or an edge folding back along the previous one, which includes a
/// polygon of zero area). Exact; O(n log n) in the number of vertices (a sweep line).
[[nodiscard]] std::string polygon_problem(std::span<const Vec2> polygon);
[[nodiscard]] std::string polygon_problem(std::span<const ExactPoint> polygon);

/// True when the simple polygon's vertices run counter-clockwise (exact: the turn at its
/// leftmost, then lowest, vertex, where a simple polygon cannot be straight).
[[nodiscard]] bool is_counter_clockwise(std::span<const Vec2> polygon);
[[nodiscard]] bool is_counter_clockwise(std::span<const ExactPoint> polygon);

/// True when p lies in the closed polygon: inside or on its boundary (exact winding number).
[[nodiscard]] bool in_closed_polygon(std::span<const Vec2> polygon, const Vec2& p);
[[nodiscard]] bool in_closed_polygon(std::span<const ExactPoint> polygon, const ExactPoint& p);

/// True when the point p is within `distance` of the closed segment ab, exactly (squared
/// distances compared in exact arithmetic, after a float filter with a wide margin).
[[nodiscard]] bool within_distance_of_segment(const Vec2& p, const Vec2& a, const Vec2& b, double distance);
/// The same for an exact distance (its double `rounded_distance` for the filter), and for exact points.
[[nodiscard]] bool within_distance_of_segment(const Vec2& p, const Vec2& a, const Vec2& b, const Dyadic& distance,
                                              double rounded_distance);
[[nodiscard]] bool within_distance_of_segment(const ExactPoint& p, const ExactPoint& a, const ExactPoint& b,
                                              const Dyadic& distance, double rounded_distance);

/// True when p is within `distance` of some edge of the polygon (exactly).
[[nodiscard]] bool within_distance_of_boundary(std::span<const Vec2> polygon, const Vec2& p, double distance);
[[nodiscard]] bool within_distance_of_boundary(std::span<const ExactPoint> polygon, const ExactPoint& p,
                                               const Dyadic& distance, double rounded_distance);

/// A point where the interiors of two simple polygons (either orientation) meet, or none when
/// they do not (they may touch along edges and at vertices). Decided exactly: every edge of
/// each is cut where the other's boundary meets it (orient2d, and exact rational parameters
/// along the edge), and each piece is inside, outside or along the other polygon as the other's
/// boundary passes at the piece's end (src/geometry/polygon_overlap.cpp). The point returned is
/// a double strictly inside both (checked exactly) when the doubles hold one beside the piece
/// found, else a rounded point of that piece (an overlap thinner than the doubles' spacing).
/// Each polygon's edges are indexed in an EdgeGrid: O(n + m + the edge pairs sharing cells).
[[nodiscard]] std::optional<Vec2> polygons_overlap(std::span<const Vec2> a, std::span<const Vec2> b);
/// The same for exact polygons; the point returned is rounded to doubles.
[[nodiscard]] std::optional<Vec2> polygons_overlap(std::span<const ExactPoint> a, std::span<const ExactPoint> b);

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
    /// The grid of exact points' doubles (its margin covers their rounding).
    EdgeGrid(std::span<const ExactPoint> polygon, double distance) : EdgeGrid(rounded(polygon), distance) {}
    /// The edges (edge k runs from vertex k to k + 1) entered in the cell of q, increasing; none
    /// when q lies beyond the polygon's box grown by the distance.
    [[nodiscard]] std::span<const std::size_t> near(const Vec2& q) const;
    /// The edges entered in the cells near the segment ab (a superset of the edges within the
    /// distance of it), increasing, into `out` (cleared first).
    void near_segment(const Vec2& a, const Vec2& b, std::vector<std::size_t>& out) const;

private:
    [[nodiscard]] std::pair<std::size_t, std::size_t> index(const Vec2& q) const;
    Vec2 lo_ = Vec2::Zero(), hi_ = Vec2::Zero();
    double margin_ = 0.0, cell_ = 1.0;
    std::size_t nx_ = 1, ny_ = 1, edge_count_ = 0;
    std::vector<std::size_t> start_;
    std::vector<std::size_t> edges_;
};

}  // namespace momentlab
