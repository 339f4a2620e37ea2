#pragma once

#include <optional>
#include <span>
#include <vector>

#include "momentlab/geometry/cone.hpp"

namespace momentlab {

/// How rank-3 constructions were decided (per thread), for tests and benchmarks.
struct ConePathStats {
    long by_chart = 0;   ///< pointed, found as a hull in the chart d . x = 1 (pointed_by_chart)
    long by_pivot = 0;   ///< decided from the angular order around a pivot (O(n log n))
    long retries = 0;    ///< extra pivot analyses (face retries, second guesses)
    long dual_clip = 0;  ///< fell back to the exact dual clip (O(n m))
    long cuts = 0;       ///< cones cut by a half-space along their facet cycle (ConeBuilder::cut, O(m))
};

/// Builds the minimal double description of cone(generators) (private to the geometry layer).
struct ConeBuilder {
    static Cone build(std::span<const Vec3> generators);
    static Cone build(std::span<const ExactVector> generators);
    /// The cone of these lists, moved in (each must already be minimal).
    static Cone assemble(std::vector<ExactVector>&& rays, std::vector<ExactVector>&& lineality,
                         std::vector<ExactVector>&& facets, std::vector<ExactVector>&& equations,
                         Incidence&& facet_rays, Representation exact = Representation::Generators);
    static ConePathStats& stats();
    /// Whether pointed cones of up to 128 generators may be found in a chart (per thread;
    /// true). Tests and benchmarks set it to false to compare with the pivot path.
    static bool& use_chart();
    /// f n {h . x >= 0} for a pointed full-dimensional f, found by cutting f's cycle of facets
    /// in O(m) for m facets: the facets, their order and incidence that the cone of all the
    /// half-spaces has, with f's own rays where they stay (the same rays up to a positive
    /// factor); empty when f is another kind of cone or the cut leaves less than a
    /// full-dimensional cone (cone_cut.cpp).
    static std::optional<Cone> cut(const Cone& f, const ExactVector& h);
};

}  // namespace momentlab
