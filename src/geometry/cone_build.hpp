#pragma once

#include <span>
#include <vector>

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
    static Cone build(std::span<const ExactVector> generators);
    static Cone assemble(std::vector<ExactVector> rays, std::vector<ExactVector> lineality,
                         std::vector<ExactVector> facets, std::vector<ExactVector> equations, Incidence facet_rays);
    static ConePathStats& stats();
};

}  // namespace momentlab
