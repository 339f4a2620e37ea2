#pragma once

/// \file
/// Exact geometric predicates on stored doubles.
///
/// Each predicate returns the exact sign of a polynomial in its (finite) arguments. A
/// floating-point evaluation with a forward error bound answers most calls; when the bound
/// cannot decide, an error-free expansion (Shewchuk 1997, "Adaptive precision floating-point
/// arithmetic and fast robust geometric predicates") computes the exact value, and arguments
/// with extreme exponents (outside 2^-250 .. 2^250) go to GMP rationals. No tolerance is
/// involved anywhere. Preconditions: all arguments finite (checked by the callers that take
/// user input; asserted here in debug builds).

#include "momentlab/core/sign.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// The exact sign of the double `x`.
constexpr Sign sign_of(double x) {
    return x > 0 ? Sign::Positive : (x < 0 ? Sign::Negative : Sign::Zero);
}

/// The exact sign of the dot product a . b.
[[nodiscard]] Sign dot_sign(const Vec3& a, const Vec3& b);

/// The exact sign of det[a b c] = a . (b x c) (the orientation of three vectors from the origin).
[[nodiscard]] Sign det_sign(const Vec3& a, const Vec3& b, const Vec3& c);

/// The exact sign of the 2x2 minor a[i]*b[j] - a[j]*b[i].
[[nodiscard]] Sign minor_sign(const Vec3& a, const Vec3& b, int i, int j);

/// The exact sign of the planar cross product a.x*b.y - a.y*b.x.
[[nodiscard]] Sign cross2_sign(const Vec2& a, const Vec2& b);

/// True when a and b are exactly parallel (a x b = 0), including when either is zero.
[[nodiscard]] bool parallel(const Vec3& a, const Vec3& b);

/// True when every coordinate of v is exactly zero.
[[nodiscard]] inline bool is_zero(const Vec3& v) {
    return v.x() == 0.0 && v.y() == 0.0 && v.z() == 0.0;
}

/// Counters of how predicates were decided, for benchmarks and tests (per thread).
struct PredicateStats {
    long filtered = 0;   ///< decided by the floating-point filter
    long expansion = 0;  ///< decided by an error-free expansion
    long gmp = 0;        ///< decided by GMP rationals (extreme exponents)
};

/// The counters of the calling thread since the last reset.
[[nodiscard]] PredicateStats& predicate_stats();

}  // namespace momentlab
