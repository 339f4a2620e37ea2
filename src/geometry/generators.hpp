#pragma once

// What every construction algorithm of cone(generators) shares about its generators, which are
// stored doubles (Vec3, the predicates of core/predicates.hpp) or exact vectors (ExactVector,
// core/exact.hpp): the same exact predicates on both, the exact constructions the algorithms
// make of them, and the floating-point hints (orders and guesses) that only steer the running
// time. Private to the geometry layer.

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>

#include "momentlab/core/exact.hpp"
#include "momentlab/core/predicates.hpp"
#include "momentlab/core/vec.hpp"

// Private to the geometry layer: hidden from the shared library's interface.
namespace momentlab {
namespace [[gnu::visibility("hidden")]] geometry_detail {

inline ExactVector in(const Vec3& v) { return ExactVector::input(v); }
inline const ExactVector& in(const ExactVector& v) { return v; }

// Rounded values, for floating-point hints only (orders and guesses; never a decision). Both are
// finite, and a constructed vector's value may be scaled by a power of two: every use is
// invariant under positive scaling of each vector.
inline const Vec3& approx(const Vec3& v) { return v; }
inline const Vec3& approx(const ExactVector& v) { return v.value(); }

// Powers of two that bring the coordinates of the generators to comparable sizes, for the
// floating-point hints (pivot guesses, sort keys), which are taken on D v instead of v. The
// wrenches of a scene 2^40 long have torques 2^40 times their forces: on v itself they all
// round to nearly one direction and the keys are noise (every comparison then exact); on D v
// their angles are as clear as in the scene of length 1. D is a positive diagonal matrix, so
// det(D p, D u, D v) = det(D) det(p, u, v) has the sign of det(p, u, v): only the hints change,
// never an exact order. The identity (nothing changes) unless, for some coordinate, no
// generator has it above 2^-16 of its largest.
template <class G>
Vec3 balance(std::span<const G> g) {
    constexpr double kSmall = 0x1p-16;
    int seen = 0;  // bit i: some generator has coordinate i above kSmall of its largest
    for (const G& v : g) {
        const Vec3 a = approx(v).cwiseAbs();
        const double m = kSmall * a.maxCoeff();
        for (int i = 0; i < 3; ++i) {
            if (a[i] > m) seen |= 1 << i;
        }
        if (seen == 7) return Vec3::Ones();
    }
    Vec3 top = Vec3::Zero();  // coordinate i's largest share of its generator's largest
    for (const G& v : g) {
        const Vec3 a = approx(v).cwiseAbs();
        const double m = a.maxCoeff();
        if (m > 0) top = top.cwiseMax(a / m);
    }
    // A small coordinate is scaled to just below its generator's largest (so no hint overflows
    // where the generators themselves are finite), by at most 2^1000.
    Vec3 d = Vec3::Ones();
    for (int i = 0; i < 3; ++i) {
        if (top[i] > 0 && top[i] <= kSmall) d[i] = std::ldexp(1.0, std::min(-std::ilogb(top[i]) - 1, 1000));
    }
    return d;
}

// The hint of v: D v.
template <class G>
Vec3 hint(const G& v, const Vec3& d) {
    return approx(v).cwiseProduct(d);
}

// The exact coordinates of a generator.
inline Exact3 exact_coordinates(const Vec3& v) { return exact(v); }
inline Exact3 exact_coordinates(const ExactVector& v) { return v.exact(); }

// a x e_k, exactly: its coordinates are +-a_i or 0.
inline ExactVector axis_cross(const Vec3& a, int k) { return in(a.cross(Vec3::Unit(k))); }
inline ExactVector axis_cross(const ExactVector& a, int k) { return ExactVector::cross(a, in(Vec3::Unit(k)), 1); }

// Two vectors spanning the orthogonal complement of a != 0, exactly: e_k x a for two axes k
// other than the one where a is largest.
template <class G>
std::pair<ExactVector, ExactVector> exact_complement(const G& a) {
    int k = 0;
    for (int i = 1; i < 3; ++i) {
        if (std::fabs(approx(a)[i]) > std::fabs(approx(a)[k])) k = i;
    }
    // e_z x a = (-a.y, a.x, 0), e_x x a = (0, -a.z, a.y), e_y x a = (a.z, 0, -a.x).
    const auto along = [&](int axis) { return axis_cross(a, axis).negated(); };
    if (k == 0) return {along(2), along(1)};
    if (k == 1) return {along(2), along(0)};
    return {along(0), along(1)};
}

// The index k of a non-zero coordinate of u x v (exactly), preferring the largest.
template <class G>
int nonzero_cross_axis(const G& u, const G& v) {
    const Vec3 c = approx(u).cross(approx(v));
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int a, int b) { return std::fabs(c[a]) > std::fabs(c[b]); });
    for (int k : order) {
        if (minor_sign(u, v, (k + 1) % 3, (k + 2) % 3) != Sign::Zero) return k;
    }
    assert(false && "nonzero_cross_axis: parallel vectors");
    return 2;
}

// sign((u x v)[k])
template <class G>
Sign cross_component_sign(const G& u, const G& v, int k) {
    return minor_sign(u, v, (k + 1) % 3, (k + 2) % 3);
}

// A vector h with h . r1 = 0 and h . r2 > 0, exact: +-(r1 x e_k) for an axis k with
// (r1 x r2)[k] != 0, since (r1 x e_k) . r2 = -(r1 x r2)[k].
template <class G>
ExactVector exact_normal_towards(const G& r1, const G& r2, int k) {
    const ExactVector h = axis_cross(r1, k);
    return cross_component_sign(r1, r2, k) == Sign::Positive ? h.negated() : h;
}

// An exact vector's approximation, kept beside it where it meets many determinants (doubles need
// none). Its default has an infinite error bound: the exact path, never a wrong filter.
struct NoRounding {};
template <class G>
using RoundingOf = std::conditional_t<std::is_same_v<G, ExactVector>, ExactVector::Approximation, NoRounding>;
template <class G>
RoundingOf<G> unrounded() {
    if constexpr (std::is_same_v<G, ExactVector>) {
        return {Vec3::Zero(), Vec3::Constant(std::numeric_limits<double>::infinity())};
    } else {
        return {};
    }
}
template <class G>
RoundingOf<G> rounding(const G& v) {
    if constexpr (std::is_same_v<G, ExactVector>) {
        return v.approximation();
    } else {
        (void)v;
        return {};
    }
}
// det(a, b, c) with their approximations given.
template <class G>
Sign det_rounded(const G& a, const G& b, const G& c, const RoundingOf<G>& ra, const RoundingOf<G>& rb,
                 const RoundingOf<G>& rc) {
    if constexpr (std::is_same_v<G, ExactVector>) {
        return det_sign(a, b, c, ra, rb, rc);
    } else {
        return det_sign(a, b, c);
    }
}

}  // namespace geometry_detail
}  // namespace momentlab
