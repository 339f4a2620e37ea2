#pragma once

// The double description that the construction algorithms of cone(generators) fill (Parts),
// the cycle of a pointed cone turned into it (pointed_from_cycle, shared by the chart, the
// pivot and the dual clip), and the algorithms' entry points, each in its own file:
//   pointed_by_chart    cone_chart.cpp      a pointed cone of up to 128 generators, as a hull in
//                                           a chart (Andrew's monotone chain)
//   build_planar        cone_planar.cpp     rank 2: the angular order inside the plane
//   build_spatial       cone_pivot.cpp      rank 3: the angular order around a pivot (Graham's
//                                           scan), falling back to build_by_dual_clip
//   build_by_dual_clip  cone_dual_clip.cpp  rank 3, any: the dual cut out as a spherical polygon
//   parts_of            cone_build.cpp      the driver: chart, rank, then the cases above
// Each is instantiated for Vec3 and ExactVector generators (non-zero). Private to the geometry
// layer.

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "generators.hpp"
#include "momentlab/geometry/cone.hpp"

// Private to the geometry layer: hidden from the shared library's interface.
namespace momentlab {
namespace [[gnu::visibility("hidden")]] geometry_detail {

// The minimal double description of a cone as the algorithms fill it, each list minimal
// (ConeBuilder::assemble makes the Cone of it).
struct Parts {
    std::vector<ExactVector> rays, lineality, facets, equations;
    Incidence facet_rays;
    // Built without facets (cone_holds), a pointed full-dimensional cone is only this: its
    // extreme rays in counter-clockwise order, as indices into the generators (facet i is
    // rays i x i+1).
    std::vector<int> cycle;
};

// Fills `parts` (empty) in place: a small cone's cost is mostly its own representation, and
// moving four vectors and an incidence from one Parts to another was a tenth of it. The cycle
// (counter-clockwise, any start) is read from the extreme generator given first on, and round:
// the same representation whichever path (chart, pivot, dual clip) found the cycle.
template <class G>
void pointed_from_cycle(std::span<const G> g, std::span<const int> cycle, bool facets, Parts& parts) {
    const std::size_t k = cycle.size();
    const auto first = static_cast<std::size_t>(std::min_element(cycle.begin(), cycle.end()) - cycle.begin());
    const auto index = [&](std::size_t i) {  // the i-th generator of the cycle from `first`
        const std::size_t j = first + i;
        return cycle[j < k ? j : j - k];
    };
    const auto at = [&](std::size_t i) -> const G& { return g[static_cast<std::size_t>(index(i))]; };
    if (!facets) {  // the cycle is all cone_holds needs
        parts.cycle.reserve(k);
        for (std::size_t i = 0; i < k; ++i) parts.cycle.push_back(index(i));
        return;
    }
    parts.rays.reserve(k);
    parts.facets.reserve(k);
    for (std::size_t i = 0; i < k; ++i) {
        const G& a = at(i);
        const G& b = at(i + 1 < k ? i + 1 : 0);
        parts.rays.emplace_back(a);  // made in place
        if constexpr (std::is_same_v<G, Vec3>) {
            parts.facets.emplace_back(a, b, 1);
        } else {
            parts.facets.push_back(ExactVector::cross(a, b, 1));
        }
    }
    parts.facet_rays = Incidence::cyclic(k);
}

// A pointed cone of up to kChartLimit generators in `parts` (empty) as a hull in a chart, or
// false with `parts` untouched (cone_chart.cpp).
template <class G>
bool pointed_by_chart(std::span<const G> g, bool facets, Parts& parts);

// Rank 2: the generators span the plane of a and b (cone_planar.cpp).
template <class G>
Parts build_planar(std::span<const G> g, const G& a, const G& b);

// Rank 3: g[ia], g[ib], g[ic] are independent (cone_pivot.cpp).
template <class G>
Parts build_spatial(std::span<const G> g, std::size_t ia, std::size_t ib, std::size_t ic, bool facets);

// Rank 3, any cone: g[i0], g[i1], g[i2] are independent (cone_dual_clip.cpp).
template <class G>
Parts build_by_dual_clip(std::span<const G> g, std::size_t i0, std::size_t i1, std::size_t i2, bool facets);

// The parts of cone(g) for nonzero generators g (at least one); without a pointed
// full-dimensional cone's facets (and rays) when `facets` is false: its cycle only.
// (Filled in place, as pointed_from_cycle fills it.)
template <class G>
void parts_of(std::span<const G> g, bool facets, Parts& parts);

}  // namespace geometry_detail
}  // namespace momentlab
