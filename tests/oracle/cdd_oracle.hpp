#pragma once

// An independent exact oracle for cones: cddlib (Fukuda) in GMP rational mode. It shares no
// code with momentlab; its inputs are the same doubles, converted exactly to rationals.

#include <gmpxx.h>

#include <array>
#include <vector>

#include "momentlab/core/vec.hpp"

namespace momentlab::oracle {

using QVec = std::array<mpq_class, 3>;

struct OracleCone {
    int dimension = 0;
    int lineality_dimension = 0;
    std::vector<QVec> rays, lineality, facets, equations;
};

/// cone(generators), minimal V and H representations.
OracleCone from_generators(const std::vector<Vec3>& generators);
/// {x : n . x >= 0 for all normals}, minimal V and H representations.
OracleCone from_halfspaces(const std::vector<Vec3>& normals);

QVec exact(const Vec3& v);
mpq_class dot(const QVec& a, const QVec& b);
int sign(const mpq_class& q);

}  // namespace momentlab::oracle
