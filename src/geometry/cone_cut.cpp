// A pointed full-dimensional cone cut by a half-space (cone_build.hpp, ConeBuilder::cut): what
// intersection(f, half-space) builds, without sorting f's facets again.
//
// intersection(f, g) is the dual of cone(f's facets, h) (cone.cpp). For a pointed
// full-dimensional f, that cone's extreme rays are the facets of f whose facet keeps a 2-D
// piece in {h . x >= 0} (a ray of it with h . r > 0), and h itself when some ray of f has
// h . r < 0: they follow f's facets around, h in the place of the facets cut away. So one
// exact sign per ray of f gives the cycle, and the cone is assembled as
// Cone::from_generators assembles a cycle it found: starting at the generator given first,
// facet t = c_t x c_t+1. Those facets are f's own rays wherever two facets of f stay
// neighbours: there the cut keeps f's ray itself (the same ray, up to a positive factor, that
// the cone of all half-spaces constructs), so the cut of a cone of 10^5 rays makes no new exact
// vector but the two where h cuts, and no exact arithmetic for the others.
#include <algorithm>
#include <cstdlib>
#include <vector>

#include "cone_build.hpp"

namespace momentlab {

std::optional<Cone> ConeBuilder::cut(const Cone& f, const ExactVector& h) {
    const std::vector<ExactVector>& rays = f.rays();
    const std::vector<ExactVector>& facets = f.facets();
    const std::size_t m = facets.size();
    if (f.dimension() != 3 || !f.is_pointed() || m < 3 || rays.size() != m) return std::nullopt;
    // The cycle of facets: facet t lies on two rays, each ray on two facets.
    std::vector<std::array<int, 2>> on_ray(m, {-1, -1});
    for (std::size_t t = 0; t < m; ++t) {
        const std::span<const int> row = f.facet_rays().row(t);
        if (row.size() != 2) return std::nullopt;
        for (int r : row) {
            auto& slot = on_ray[static_cast<std::size_t>(r)];
            (slot[0] < 0 ? slot[0] : slot[1]) = static_cast<int>(t);
        }
    }
    std::vector<int> order{0};         // facets in cyclic order
    std::vector<int> between;          // between[i]: the ray shared by order[i] and order[i + 1]
    order.reserve(m);
    between.reserve(m);
    int ray = f.facet_rays().row(0)[1];
    for (std::size_t i = 0; i < m; ++i) {
        const auto& pair = on_ray[static_cast<std::size_t>(ray)];
        if (pair[1] < 0) return std::nullopt;
        const int next = pair[0] == order.back() ? pair[1] : pair[0];
        between.push_back(ray);
        if (i + 1 == m) {
            if (next != order.front()) return std::nullopt;
            break;
        }
        order.push_back(next);
        const std::span<const int> row = f.facet_rays().row(static_cast<std::size_t>(next));
        ray = row[0] == ray ? row[1] : row[0];
    }
    if (order.size() != m) return std::nullopt;
    // Counter-clockwise as generators (det of three consecutive > 0), as from_generators orders them.
    const Sign turn = det_sign(facets[static_cast<std::size_t>(order[0])], facets[static_cast<std::size_t>(order[1])],
                               facets[static_cast<std::size_t>(order[2])]);
    if (turn == Sign::Zero) return std::nullopt;
    if (turn == Sign::Negative) {
        // order[0], order[m-1], ..., order[1]; the ray between order[i] and order[i+1] is between[i].
        std::reverse(order.begin() + 1, order.end());
        std::vector<int> reversed(m);
        for (std::size_t i = 0; i < m; ++i) reversed[i] = between[(2 * m - 1 - i) % m];
        between.swap(reversed);
    }
    // Which side of h each ray lies on.
    std::vector<Sign> side(m);
    bool any_in = false, any_out = false;
    for (std::size_t r = 0; r < m; ++r) {
        side[r] = h.dot_sign(rays[r]);
        any_in = any_in || side[r] == Sign::Positive;
        any_out = any_out || side[r] == Sign::Negative;
    }
    if (!any_in) return std::nullopt;
    // h parallel to a facet g (h = c g) would tie with g in the cycle; but c < 0 leaves no ray
    // inside (returned above) and c > 0 none outside, where h joins no cycle and the cut is f
    // (labels' K of a set with a pure moment has the facet s = 0).
    // The cycle of the cut cone's facets: index t < m is facets[t], m is h.
    const auto side_of = [&](int r) { return side[static_cast<std::size_t>(r)]; };
    const auto kept = [&](std::size_t i) {  // facet order[i] keeps a 2-D piece (all, when h cuts nothing)
        const int before = between[(i + m - 1) % m], after = between[i];
        return !any_out || side_of(before) == Sign::Positive || side_of(after) == Sign::Positive;
    };
    std::vector<int> cycle;
    std::vector<int> shared;  // shared[k]: f's ray between cycle[k] and cycle[k + 1], or -1
    std::size_t cuts = 0;
    for (std::size_t i = 0; i < m; ++i) {
        if (!kept(i)) continue;
        cycle.push_back(order[i]);
        const bool next_kept = kept((i + 1) % m);
        if (any_out && (!next_kept || side_of(between[i]) == Sign::Negative)) {
            shared.push_back(-1);
            cycle.push_back(static_cast<int>(m));
            shared.push_back(-1);
            ++cuts;
        } else {
            shared.push_back(between[i]);
        }
    }
    if (cuts != (any_out ? 1u : 0u) || cycle.size() < 3) return std::nullopt;
    // Start at the generator given first (the lowest index), as from_generators does.
    const std::size_t start = static_cast<std::size_t>(std::min_element(cycle.begin(), cycle.end()) - cycle.begin());
    std::rotate(cycle.begin(), cycle.begin() + static_cast<std::ptrdiff_t>(start), cycle.end());
    std::rotate(shared.begin(), shared.begin() + static_cast<std::ptrdiff_t>(start), shared.end());
    const auto normal = [&](int c) -> const ExactVector& { return c == static_cast<int>(m) ? h : facets[static_cast<std::size_t>(c)]; };
    const std::size_t k = cycle.size();
    if (det_sign(normal(cycle[0]), normal(cycle[1]), normal(cycle[2])) != Sign::Positive) return std::nullopt;
    // The cone of the cycle (generators: the normals), as pointed_from_cycle assembles it; its dual
    // is the cut.
    std::vector<ExactVector> generators, edges;
    generators.reserve(k);
    edges.reserve(k);
    for (std::size_t t = 0; t < k; ++t) {
        const ExactVector& a = normal(cycle[t]);
        const ExactVector& b = normal(cycle[(t + 1) % k]);
        generators.push_back(a);
        const int r = shared[t];
        // Where two facets of f stay neighbours the ray between them is f's own (a x b is a
        // positive multiple of it: both lie on the two planes, in the pointed cut); only the
        // rays where h crosses the cycle are constructed.
        edges.push_back(r >= 0 ? rays[static_cast<std::size_t>(r)] : ExactVector::cross(a, b, 1));
    }
    ++stats().cuts;
    // (Assembled as that cone's dual directly: Cone::dual would copy every vector once more.)
    Incidence dual_incidence = Incidence::cyclic(k).transposed(k);
    return assemble(std::move(edges), {}, std::move(generators), {}, std::move(dual_incidence), Representation::Halfspaces);
}

}  // namespace momentlab
