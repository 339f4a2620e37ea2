// Rank 3, general: the dual cone D = {h : h . g >= 0 for all g} as a spherical polygon, cut
// from the simplicial cone of three independent generators. The polygon is a cyclic list of
// constraints c_0 .. c_{m-1}; its vertex i is c_i x c_{i+1}; it always lies in an open
// hemisphere (inside the initial simplicial cone), so these vertices are never antipodal.
#include <cassert>
#include <cstddef>
#include <numeric>
#include <random>
#include <span>
#include <vector>

#include "cone_parts.hpp"

// Private to the geometry layer: hidden from the shared library's interface.
namespace momentlab {
namespace [[gnu::visibility("hidden")]] geometry_detail {

template <class G>
Parts build_by_dual_clip(std::span<const G> g, std::size_t i0, std::size_t i1, std::size_t i2, bool facets) {
    std::vector<int> poly;
    if (det_sign(g[i0], g[i1], g[i2]) == Sign::Positive) {
        poly = {static_cast<int>(i0), static_cast<int>(i1), static_cast<int>(i2)};
    } else {
        poly = {static_cast<int>(i0), static_cast<int>(i2), static_cast<int>(i1)};
    }
    auto gen = [&](int i) -> const G& { return g[static_cast<std::size_t>(i)]; };
    std::vector<std::size_t> order(g.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    // A fixed-seed shuffle with our own mapping (std distributions differ between libraries)
    // keeps the expected size of the intermediate polygons small.
    std::mt19937_64 rng(0x6d6f6d656e746c61ULL);
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng() % i]);
    std::vector<Sign> side;
    std::vector<int> next;
    for (std::size_t idx : order) {
        if (idx == i0 || idx == i1 || idx == i2) continue;
        const G& h = g[idx];
        const std::size_t m = poly.size();
        side.resize(m);
        bool any_out = false, any_in = false;
        for (std::size_t i = 0; i < m; ++i) {
            side[i] = det_sign(gen(poly[i]), gen(poly[(i + 1) % m]), h);
            if (side[i] == Sign::Negative) any_out = true; else any_in = true;
        }
        if (!any_out) {
            // h along a constraint c_i of the polygon (a generator given again) is zero at both
            // vertices of c_i; of such generators the one given first stands for them, as in
            // the chart and around a pivot, whichever the shuffle met first.
            for (std::size_t i = 0; i < m; ++i) {
                if (side[i] == Sign::Zero && side[(i + m - 1) % m] == Sign::Zero && static_cast<int>(idx) < poly[i] &&
                    parallel(gen(poly[i]), h) && dot_sign(gen(poly[i]), h) == Sign::Positive) {
                    poly[i] = static_cast<int>(idx);
                    break;
                }
            }
            continue;
        }
        if (!any_in) return Parts{{}, {in(Vec3::UnitX()), in(Vec3::UnitY()), in(Vec3::UnitZ())}, {}, {}, {}, {}};
        // The vertices strictly outside form one cyclic run j .. k.
        std::size_t j = 0;
        while (!(side[j] == Sign::Negative && side[(j + m - 1) % m] != Sign::Negative)) ++j;
        std::size_t k = j;
        while (side[(k + 1) % m] == Sign::Negative) k = (k + 1) % m;
        next.clear();
        for (std::size_t t = (k + 1) % m;; t = (t + 1) % m) {
            next.push_back(poly[t]);
            if (t == j) break;
        }
        next.push_back(static_cast<int>(idx));
        poly.swap(next);
    }
    // Distinct vertices: vertex i equals vertex i+1 iff c_i, c_{i+1}, c_{i+2} are dependent.
    const std::size_t m = poly.size();
    std::vector<std::size_t> edges;  // indices t of constraints whose edge has positive length
    for (std::size_t t = 0; t < m; ++t) {
        if (det_sign(gen(poly[(t + m - 1) % m]), gen(poly[t]), gen(poly[(t + 1) % m])) != Sign::Zero) {
            edges.push_back(t);
        }
    }
    Parts parts;
    if (edges.empty()) {  // the dual is a ray: a half-space
        const G& c0 = gen(poly[0]);
        std::size_t t = 1;
        while (parallel(c0, gen(poly[t]))) ++t;
        const ExactVector normal = ExactVector::cross(c0, gen(poly[1]), 1);
        const G* off = nullptr;
        for (const G& v : g) {
            if (normal.dot_sign(v) == Sign::Positive) {
                off = &v;
                break;
            }
        }
        assert(off != nullptr);
        parts.rays = {in(*off)};
        parts.lineality = {in(c0), in(gen(poly[t]))};
        parts.facets = {normal};
        parts.facet_rays.add_row({});
        return parts;
    }
    // The vertex at the end of edge t is c_t x c_{t+1}.
    auto vertex_after = [&](std::size_t t) {
        return ExactVector::cross(gen(poly[t]), gen(poly[(t + 1) % m]), 1);
    };
    if (edges.size() == 2) {  // the dual is a 2-D wedge: C is a wedge times a line
        const G& line = gen(poly[edges[0]]);
        parts.lineality = {in(line)};
        for (std::size_t s = 0; s < 2; ++s) {
            const std::size_t t = edges[s];
            const ExactVector facet = vertex_after(t);
            // A constraint through this vertex that is not on the line.
            const G& c1 = gen(poly[(t + 1) % m]);
            const G& ray = parallel(c1, line) ? gen(poly[t]) : c1;
            parts.facets.push_back(facet);
            parts.rays.push_back(in(ray));
            parts.facet_rays.add_row({static_cast<int>(s)});
        }
        return parts;
    }
    std::vector<int> cycle;
    for (std::size_t t : edges) cycle.push_back(poly[t]);
    pointed_from_cycle(g, cycle, facets, parts);  // parts is still empty here
    return parts;
}

template Parts build_by_dual_clip<Vec3>(std::span<const Vec3>, std::size_t, std::size_t, std::size_t, bool);
template Parts build_by_dual_clip<ExactVector>(std::span<const ExactVector>, std::size_t, std::size_t, std::size_t, bool);

}  // namespace geometry_detail
}  // namespace momentlab
