#pragma once

/// \file
/// Checks on the polygons of bodies and obstacles (exact, with the orientation predicate).

#include <span>
#include <string>

#include "momentlab/core/sign.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// The exact orientation of the triangle a, b, c: positive when counter-clockwise.
[[nodiscard]] Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c);

/// Why `polygon` is not a simple polygon, or "" when it is one. Either orientation is
/// accepted. Problems found: fewer than three vertices, a non-finite coordinate, two
/// consecutive vertices equal, two edges meeting other than at the vertex they share
/// (crossing, touching, or an edge folding back along the previous one, which includes a
/// polygon of zero area). Exact; O(n^2) in the number of vertices.
[[nodiscard]] std::string polygon_problem(std::span<const Vec2> polygon);

/// The distance from p to the boundary of the polygon (floating point: for messages and
/// modelling checks, never for combinatorial decisions).
[[nodiscard]] double distance_to_boundary(std::span<const Vec2> polygon, const Vec2& p);

}  // namespace momentlab
