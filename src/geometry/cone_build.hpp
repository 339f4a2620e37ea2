#pragma once

#include <span>

#include "momentlab/geometry/cone.hpp"

namespace momentlab {

/// How rank-3 constructions were decided (per thread), for tests and benchmarks.
struct ConePathStats {
    long by_pivot = 0;   ///< decided from the angular order around a pivot (O(n log n))
    long retries = 0;    ///< extra pivot analyses (face retries, second guesses)
    long dual_clip = 0;  ///< fell back to the exact dual clip (O(n m))
};

/// Builds the minimal double description of cone(generators) (private to the geometry layer).
struct ConeBuilder {
    static Cone build(std::span<const Vec3> generators);
    static ConePathStats& stats();
};

}  // namespace momentlab
