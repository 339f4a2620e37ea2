// Rank 2: cone(generators) when they span the plane of a and b. The generators are sorted by
// angle inside the plane (angular_sort.hpp: about a coordinate axis across the plane, exact
// 2x2 minors), and the largest angular gap tells the cone: a gap wider than pi leaves a wedge,
// a gap of exactly pi a half-plane, none the whole plane.
#include <cassert>
#include <cstddef>
#include <span>

#include "angular_sort.hpp"
#include "cone_parts.hpp"

// Private to the geometry layer: hidden from the shared library's interface.
namespace momentlab {
namespace [[gnu::visibility("hidden")]] geometry_detail {

template <class G>
Parts build_planar(std::span<const G> g, const G& a, const G& b) {
    Parts parts;
    parts.equations.push_back(ExactVector::cross(a, b, 1));
    AngularOrder<G> ord{AngularOrder<G>::Mode::PlaneAxis, nonzero_cross_axis(a, b), G{}, a, G{}};
    Scratch scratch;
    ScratchVector<Item<G>> items(&scratch);
    items.reserve(g.size());
    // Keys in the coordinate plane across the axis, where the exact orientation is the
    // sign of (u x v)[axis]: the same sense, so the keys increase with the exact order.
    const int ci = (ord.axis + 1) % 3, cj = (ord.axis + 2) % 3;
    const Vec3 d = balance(g);
    const Vec3 x = hint(a, d);
    for (std::size_t i = 0; i < g.size(); ++i) {
        const int half = &g[i] == &a ? 0 : ord.half(g[i]);  // a itself: along a, no exact zero test
        const Vec3 y = hint(g[i], d);
        const double along = x[ci] * y[ci] + x[cj] * y[cj];
        const double across = x[ci] * y[cj] - x[cj] * y[ci];
        items.push_back({g[i], angle_key(along, across, half), static_cast<int>(i), half});
    }
    const Groups groups = angular_sort(items, ord, [](const G&) { return [](const G&, const G&) { return false; }; });
    const std::size_t m = groups.size();
    assert(m >= 2);
    auto rep_item = [&](std::size_t group) -> const Item<G>& { return items[groups[group % m].first]; };
    auto rep = [&](std::size_t group) -> const G& { return rep_item(group).v; };
    std::size_t wide = m, flat = m;
    for (std::size_t i = 0; i < m; ++i) {
        const int c = gap_vs_pi(rep_item(i), rep_item(i + 1), ord);
        if (c > 0) wide = i;
        if (c == 0 && flat == m) flat = i;
    }
    if (wide != m) {  // a wedge from the group after the gap to the group before it
        const G& r1 = rep(wide + 1);
        const G& r2 = rep(wide);
        const int k = ord.axis;
        parts.rays = {in(r1), in(r2)};
        parts.facets = {exact_normal_towards(r1, r2, k), exact_normal_towards(r2, r1, k)};
        parts.facet_rays.add_row({0});
        parts.facet_rays.add_row({1});
        return parts;
    }
    if (flat != m) {  // a half-plane bounded by the line of the two antipodal groups
        assert(m >= 3);
        const G& l = rep(flat);
        const G& off = rep(flat + 2);  // a group strictly inside: neither flat nor flat + 1
        parts.rays = {in(off)};
        parts.lineality = {in(l)};
        parts.facets = {exact_normal_towards(l, off, ord.axis)};
        parts.facet_rays.add_row({});
        return parts;
    }
    parts.lineality = {in(a), in(b)};  // the whole plane
    return parts;
}

template Parts build_planar<Vec3>(std::span<const Vec3>, const Vec3&, const Vec3&);
template Parts build_planar<ExactVector>(std::span<const ExactVector>, const ExactVector&, const ExactVector&);

}  // namespace geometry_detail
}  // namespace momentlab
