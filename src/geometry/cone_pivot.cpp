// Rank 3: cone(generators) from the angular order around a pivot generator p (the quotient
// R^3 / p, exact through det(p, u, v); angular_sort.hpp). A floating-point guess picks p
// (farthest_from, guess_extreme: only the running time depends on it); the largest angular gap
// around p then decides the cone, in O(n log n) (see PivotAnalysis): when p is an extreme ray of
// a pointed cone, Graham's scan around p gives the extreme rays in cyclic order. At most three
// pivots are analysed (build_spatial); when none decides (R^3 not seen, p interior), the exact
// dual clip does (cone_dual_clip.cpp).
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include "angular_sort.hpp"
#include "cone_build.hpp"
#include "cone_parts.hpp"
#include "scratch.hpp"

// Private to the geometry layer: hidden from the shared library's interface.
namespace momentlab {
namespace [[gnu::visibility("hidden")]] geometry_detail {
namespace {

// What the angular order around a pivot p tells:
//  * a gap wider than pi: p is on an edge of the cone. Without -p among the generators p is an
//    extreme ray of a pointed cone (Graham's scan); with it, the cone is span(p) + a wedge.
//  * a gap of exactly pi: p lies inside a 2-face F (the plane of the two boundary groups). With
//    -p the cone is a half-space. Otherwise F, in its plane, is a wedge (retry from its
//    extreme generator a*, a vertex of a pointed cone), a half-plane (retry from a*, which
//    then spans the lineality) or the plane (a half-space).
//  * all gaps below pi: p is interior; with -p the cone is R^3, otherwise undecided.
struct PivotAnalysis {
    std::optional<Parts> parts;  // the cone, when decided
    int retry_pivot = -1;        // a generator worth trying as the pivot next
    bool interior = false;       // p lies in the interior of the cone
};

Parts whole_space_parts() {
    Parts parts;
    parts.lineality = {in(Vec3::UnitX()), in(Vec3::UnitY()), in(Vec3::UnitZ())};
    return parts;
}

// The half-space {x : det(p, b, x) >= 0} with lineality span(p, l) and a generator w off it.
template <class G>
Parts half_space_parts(const G& p, const G& b, const G& l, const G& w) {
    Parts parts;
    parts.rays = {in(w)};
    parts.lineality = {in(p), in(l)};
    parts.facets = {ExactVector::cross(p, b, 1)};
    parts.facet_rays.add_row({});
    return parts;
}

template <class G>
PivotAnalysis analyse_pivot(std::span<const G> g, std::size_t pivot, const G& witness_hint, bool facets, const Vec3& scale) {
    PivotAnalysis out;
    const G& p = g[pivot];
    bool antiparallel = false;
    // Of the generators along p, the one given first stands for them (as in the chart).
    std::size_t p_first = pivot;
    const auto along_p = [&](std::size_t i) {
        if (dot_sign(p, g[i]) == Sign::Negative) {
            antiparallel = true;
        } else if (i < p_first) {
            p_first = i;
        }
    };
    // The reference direction r: the first generator not parallel to p (the rank is 3).
    std::size_t reference = 0;
    for (;; ++reference) {
        if (reference == pivot) continue;  // p itself: parallel, and the test would take the exact path
        if (!parallel(p, g[reference])) break;
        along_p(reference);
    }
    const G& r = g[reference];
    // A witness w with det(p, r, w) != 0 tells r from -r around p.
    const G* witness = &witness_hint;
    Sign witness_side = &witness_hint == &r || &witness_hint == &p ? Sign::Zero : det_sign(p, r, witness_hint);
    for (std::size_t i = 0; witness_side == Sign::Zero && i < g.size(); ++i) {
        if (i == pivot || i == reference) continue;
        witness = &g[i];
        witness_side = det_sign(p, r, g[i]);
    }
    AngularOrder<G> ord{AngularOrder<G>::Mode::Pivot, 0, p, r, *witness, rounding(p)};
    // An orthonormal frame (e1, e2) of the quotient by D p, e1 along D r: hints for the keys.
    const Vec3 ph = hint(p, scale).normalized();
    const Vec3 hr = hint(r, scale);
    const Vec3 e1 = (hr - hr.dot(ph) * ph).normalized();
    const Vec3 e2 = ph.cross(e1);
    Scratch scratch;
    ScratchVector<Item<G>> items(&scratch);
    items.reserve(g.size() - reference);
    // Each generator's half around p from one determinant det(p, r, x); only where it is zero
    // is x tested for being parallel to p (dropped) or told from -r by the witness. (Of exact
    // vectors, the approximations are made once: p's and r's for all x, each x's for this and
    // the determinants of the sort and the scan.)
    // Where x lies nearly in the plane of p and r (|across| below 2^-40 |D x|), the hints'
    // angle is noise: generators nearly in one plane through p (wrenches of forces whose lines
    // nearly meet in a point) would have keys in random order, and the sort would fall back to
    // O(n log n) exact comparisons. There det(p, r, x) is taken exactly as (p x r) . x, with p x r
    // made once: its sign is x's half, and its value, rounded and brought to the frame's scale
    // (across = det(D) det(p, r, x) / (|D p| |D r - (D r . ph) ph|)), the key's ordinate.
    const RoundingOf<G>& p_rounding = ord.pivot_rounding;
    const RoundingOf<G> r_rounding = rounding(r);
    std::optional<Exact3> p_cross_r;
    double to_frame = scale.prod() / (hint(p, scale).norm() * (hr - hr.dot(ph) * ph).norm());
    if (!std::isfinite(to_frame) || !(to_frame > 0)) to_frame = 1.0;  // a hint: any positive factor orders
    for (std::size_t i = reference; i < g.size(); ++i) {
        if (i == pivot) continue;
        int half = 0;
        const RoundingOf<G> x_rounding = i == reference ? r_rounding : rounding(g[i]);
        const Vec3 u = hint(g[i], scale);
        double across = u.dot(e2);
        if (i != reference) {  // r itself: along r, no det(p, r, r)
            Sign s;
            if (across * across > 0x1p-80 * u.squaredNorm()) {
                s = det_rounded(p, r, g[i], p_rounding, r_rounding, x_rounding);
            } else {
                if (!p_cross_r) p_cross_r = cross(exact_coordinates(p), exact_coordinates(r));
                const Dyadic det = dot(*p_cross_r, exact_coordinates(g[i]));
                s = det.sign();
                across = det.to_double() * to_frame;
            }
            if (s != Sign::Zero) {
                half = s == Sign::Positive ? 1 : 3;
            } else if (parallel(p, g[i])) {
                along_p(i);
                continue;
            } else {
                half = det_sign(p, g[i], *witness) == witness_side ? 0 : 2;
            }
        }
        items.push_back({g[i], angle_key(u.dot(e1), across, half), static_cast<int>(i), half, x_rounding});
    }
    // Ties: nearer to p (along the great circle through p) first. In the plane of p and u,
    // u is nearer than v iff u lies inside cone(p, v). The items of a group lie on one half-plane
    // bounded by the line of p, so their products p x v are positive multiples of each other:
    // one axis k where they are non-zero, and their sign there, serve the whole group.
    auto tie_order = [&](const G& first) {
        const int k = nonzero_cross_axis(p, first);
        const Sign pv = cross_component_sign(p, first, k);
        return [k, pv](const G& u, const G& v) {
            const Sign uv = cross_component_sign(u, v, k);
            return uv != Sign::Zero && uv == pv;
        };
    };
    const Groups groups = angular_sort(items, ord, tie_order);
    const std::size_t m = groups.size();
    auto rep_item = [&](std::size_t group) -> const Item<G>& { return items[groups[group % m].first]; };
    auto rep = [&](std::size_t group) -> const G& { return rep_item(group).v; };
    std::size_t wide = m, flat = m;
    for (std::size_t i = 0; i < m; ++i) {
        const int c = m == 1 ? 1 : gap_vs_pi(rep_item(i), rep_item(i + 1), ord);
        if (c > 0) wide = i;
        if (c == 0 && flat == m) flat = i;
    }
    if (wide == m && flat == m) {
        if (antiparallel) {
            out.parts = whole_space_parts();
        } else {
            out.interior = true;
        }
        return out;
    }
    if (wide == m) {
        // The occupied side runs counter-clockwise from group flat + 1 (direction -u) to group
        // flat (u): every generator has det(p, b, x) >= 0. m >= 3 (rank 3), so group
        // flat + 2 lies strictly inside.
        const G& b = rep(flat + 1);
        const G& w = rep(flat + 2);
        const Item<G>& a_far = items[groups[flat].second - 1];
        const Item<G>& b_far = items[groups[(flat + 1) % m].second - 1];
        if (antiparallel) {
            out.parts = half_space_parts(p, b, rep(flat), w);
            return out;
        }
        // Orientation inside the face's plane, seen from w: F = cone(b*, p, a*) is pointed iff
        // turning from b* to a* goes the same way as from b* to p.
        const Sign to_p = det_sign(b_far.v, p, w);
        const Sign to_a = det_sign(b_far.v, a_far.v, w);
        if (to_a == -to_p) {
            out.parts = half_space_parts(p, b, a_far.v, w);
        } else {
            out.retry_pivot = a_far.index;
        }
        return out;
    }
    if (antiparallel) {  // span(p) + the wedge from the group after the gap to the one before
        const G& r1 = rep(wide + 1);
        const G& r2 = rep(wide);
        Parts parts;
        parts.lineality = {in(p)};
        parts.rays = {in(r1), in(r2)};
        parts.facets = {ExactVector::cross(p, r1, 1), ExactVector::cross(p, r2, -1)};
        parts.facet_rays.add_row({0});
        parts.facet_rays.add_row({1});
        out.parts = std::move(parts);
        return out;
    }
    // Graham's scan: p, then the groups from just after the gap to just before it.
    // The stack holds positions in `items` (-1 for p), which the scan visits in order.
    ScratchVector<std::int64_t> stack({-1}, &scratch);
    auto at = [&](std::int64_t k) -> const G& { return k < 0 ? p : items[static_cast<std::size_t>(k)].v; };
    auto rounding_at = [&](std::int64_t k) -> const RoundingOf<G>& {
        return k < 0 ? p_rounding : items[static_cast<std::size_t>(k)].rounding;
    };
    // det(stack[-2], stack[-1], x)
    auto turn_to = [&](const G& x, const RoundingOf<G>& rx) {
        const std::int64_t a = stack[stack.size() - 2], b = stack.back();
        return det_rounded(at(a), at(b), x, rounding_at(a), rounding_at(b), rx);
    };
    // Generators along one ray are next to each other in the scan (one angle, and a tie in the
    // group's order); the one given first stands for them.
    auto push = [&](std::size_t k) {
        const G& x = items[k].v;
        while (stack.size() >= 2) {
            const Sign turn = turn_to(x, items[k].rounding);
            if (turn == Sign::Positive) break;
            const std::int64_t top = stack.back();
            if (turn == Sign::Zero && top >= 0 && parallel(items[static_cast<std::size_t>(top)].v, x) &&
                dot_sign(items[static_cast<std::size_t>(top)].v, x) == Sign::Positive) {
                if (items[k].index < items[static_cast<std::size_t>(top)].index) stack.back() = static_cast<std::int64_t>(k);
                return;
            }
            stack.pop_back();
        }
        stack.push_back(static_cast<std::int64_t>(k));
    };
    for (std::size_t t = 1; t <= m; ++t) {
        const auto [b, e] = groups[(wide + t) % m];
        for (std::size_t i = b; i < e; ++i) push(i);
    }
    while (stack.size() >= 3 && turn_to(p, p_rounding) != Sign::Positive) {
        stack.pop_back();
    }
    assert(stack.size() >= 3);
    ScratchVector<int> hull(&scratch);
    hull.reserve(stack.size());
    for (std::int64_t k : stack) hull.push_back(k < 0 ? static_cast<int>(p_first) : items[static_cast<std::size_t>(k)].index);
    pointed_from_cycle(g, hull, facets, out.parts.emplace());
    return out;
}

// Floating-point guesses of an extreme ray; only the running time depends on them, every
// decision after them is exact. The generator farthest in angle from a direction d: when all
// generators lie within 90 degrees of d it is a vertex of their spherical hull (the angular
// distance from d is convex there), up to rounding.
// Taken on the hints D v (balance).
template <class G>
std::size_t farthest_from(std::span<const G> g, const Vec3& d, const Vec3& scale) {
    std::size_t best = 0;
    double best_cos = std::numeric_limits<double>::infinity();  // d need not be a unit vector
    for (std::size_t i = 0; i < g.size(); ++i) {
        const Vec3 u = hint(g[i], scale);
        const double c = d.dot(u) / u.norm();
        if (c < best_cos) {
            best_cos = c;
            best = i;
        }
    }
    // When every generator lies within about 2^-15 rad of d (the wrenches of a scene 2^40 long,
    // all nearly along the torque axis), the cosines carry too few bits to tell the angles apart
    // (below 2^-27 rad they all round to 1): compare the chords |u/|u| - d/|d|| instead, which
    // keep their precision at small angles. Elsewhere the cosines decide, as they always have
    // (the printed form of a cone can depend on its pivot).
    const double length = d.norm();
    if (!(best_cos > (1 - 0x1p-30) * length) || !std::isfinite(length)) return best;
    const Vec3 unit = d / length;
    double best_chord = -1.0;
    for (std::size_t i = 0; i < g.size(); ++i) {
        const double chord = (hint(g[i], scale).normalized() - unit).squaredNorm();
        if (chord > best_chord) {
            best_chord = chord;
            best = i;
        }
    }
    return best;
}

// The mean direction of the generators is inside the cone; the farthest from it is the guess.
template <class G>
std::size_t guess_extreme(std::span<const G> g, const Vec3& scale) {
    Vec3 mean = Vec3::Zero();
    for (const G& v : g) {
        const Vec3 u = hint(v, scale);
        mean += u / u.norm();
    }
    return farthest_from(g, mean, scale);
}

}  // namespace

template <class G>
Parts build_spatial(std::span<const G> g, std::size_t ia, std::size_t ib, std::size_t ic, bool facets) {
    // At most three analyses: a face retry always ends in a decided case; an interior pivot
    // gets one more guess, the generator most opposite to it.
    // The generator farthest from the mean direction: extreme unless the cone is not pointed (an
    // arbitrary first pivot, interior to a pointed cone, costs a second analysis or the clip).
    const Vec3 scale = balance(g);
    std::size_t pivot = g.size() > 3 ? guess_extreme(g, scale) : ia;
    bool second_guess = false;
    for (int attempt = 0; attempt < 3; ++attempt) {
        if (attempt > 0) ++ConeBuilder::stats().retries;
        PivotAnalysis pa = analyse_pivot(g, pivot, g[ic], facets, scale);
        if (pa.parts) {
            ++ConeBuilder::stats().by_pivot;
            return std::move(*pa.parts);
        }
        if (pa.retry_pivot >= 0) {
            pivot = static_cast<std::size_t>(pa.retry_pivot);
        } else if (pa.interior && !second_guess) {
            second_guess = true;
            pivot = farthest_from(g, hint(g[pivot], scale), scale);
        } else {
            break;
        }
    }
    ++ConeBuilder::stats().dual_clip;
    return build_by_dual_clip(g, ia, ib, ic, facets);
}

template Parts build_spatial<Vec3>(std::span<const Vec3>, std::size_t, std::size_t, std::size_t, bool);
template Parts build_spatial<ExactVector>(std::span<const ExactVector>, std::size_t, std::size_t, std::size_t, bool);

}  // namespace geometry_detail
}  // namespace momentlab
