#pragma once

// Exact checks on label regions shared by the tests.

#include <algorithm>
#include <vector>

#include "momentlab/geometry/labels.hpp"

namespace momentlab::testing {

/// True when one of the region's homogeneous vertices is a positive multiple of (x, y, s).
inline bool has_vertex(const Region& r, const Vec3& xys) {
    const ExactVector target = ExactVector::input(xys);
    return std::any_of(r.vertices_h.begin(), r.vertices_h.end(), [&](const ExactVector& v) {
        return parallel(v, target) && dot_sign(v, target) == Sign::Positive;
    });
}

/// True when one of the directions is a positive multiple of d (exactly).
inline bool has_direction(const std::vector<Vec2>& list, const Vec2& d) {
    return std::any_of(list.begin(), list.end(), [&](const Vec2& v) {
        return cross2_sign(v, d) == Sign::Zero && v.dot(d) > 0;
    });
}

}  // namespace momentlab::testing
