#pragma once

// An independent exact oracle for cones: cddlib (Fukuda) in GMP rational mode. It shares no
// code with momentlab; its inputs are exact rationals (the same doubles converted exactly, or
// quantities built from a scene's raw numbers in reference/exact_scene.hpp).

#include <gmpxx.h>

#include <array>
#include <utility>
#include <vector>

#include "exact_scene.hpp"

namespace momentlab::oracle {

using reference::QVec;

struct OracleCone {
    int dimension = 0;
    int lineality_dimension = 0;
    std::vector<QVec> rays, lineality, facets, equations;
};

/// cone(generators), minimal V and H representations.
OracleCone from_generators(const std::vector<QVec>& generators);
OracleCone from_generators(const std::vector<Vec3>& generators);
/// {x : n . x >= 0 for all normals}, minimal V and H representations.
OracleCone from_halfspaces(const std::vector<QVec>& normals);
OracleCone from_halfspaces(const std::vector<Vec3>& normals);

/// The facets of the convex hull of points (their doubles read as exact rationals): each as
/// (b, a) with b + a . x >= 0 on the hull's side; none when the hull is not full-dimensional.
std::vector<std::pair<mpq_class, QVec>> hull_facets(const std::vector<Vec3>& points);

/// True when the span of `a` equals the span of `b` (exact ranks).
bool same_span(const std::vector<QVec>& a, const std::vector<QVec>& b);

QVec exact(const Vec3& v);
mpq_class dot(const QVec& a, const QVec& b);
int sign(const mpq_class& q);

}  // namespace momentlab::oracle
