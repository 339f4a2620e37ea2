#pragma once

/// \file
/// Exact geometric predicates on stored doubles.
///
/// Each predicate returns the exact sign of a polynomial in its (finite) arguments. A
/// floating-point evaluation with a forward error bound answers most calls; when the bound
/// cannot decide, an error-free expansion (Shewchuk 1997, "Adaptive precision floating-point
/// arithmetic and fast robust geometric predicates") computes the exact value, and arguments
/// with extreme exponents (outside 2^-250 .. 2^250) go to exact Dyadic numbers (core/dyadic.hpp). No tolerance is
/// involved anywhere. Preconditions: all arguments finite (checked by the callers that take
/// user input; asserted here in debug builds).

#include <cmath>

#include "momentlab/core/sign.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// The exact sign of the double `x`.
constexpr Sign sign_of(double x) {
    return x > 0 ? Sign::Positive : (x < 0 ? Sign::Negative : Sign::Zero);
}

namespace detail {
// The exact paths, called when the inline floating-point filter cannot decide.
Sign dot_sign_exact(const Vec3& a, const Vec3& b);
Sign det_sign_exact(const Vec3& a, const Vec3& b, const Vec3& c);
Sign minor_sign_exact(const Vec3& a, const Vec3& b, int i, int j);

// Forward error bound of the straightforward evaluations relative to the sum of absolute
// values of the terms. Shewchuk's orient3d bound (7 + 56 eps) eps covers the 3x3 determinant
// (our inputs are exact, which only helps); dot products and 2x2 minors have smaller bounds and
// use the same constant. The filter is trusted only when the permanent is far above the
// underflow range (so the absolute errors of denormal products of two factors are negligible;
// det_sign adds an absolute term for the third factor) and when nothing overflowed.
inline constexpr double kErrorBound = 8.0 * 0x1p-53;
inline constexpr double kMinPermanent = 0x1p-600;

inline bool filter_decides(double value, double permanent) {
    return std::fabs(value) > kErrorBound * permanent && permanent > kMinPermanent &&
           permanent < 0x1p1000;
}
/// det[a b c] evaluated in doubles, and its permanent (the same sum with every term made
/// positive), which scales the evaluation's error: the floating-point filters' common part.
struct DetTerms {
    double value;
    double permanent;
};
[[nodiscard]] inline DetTerms det_terms(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double m0 = b.y() * c.z(), m1 = b.z() * c.y();
    const double m2 = b.z() * c.x(), m3 = b.x() * c.z();
    const double m4 = b.x() * c.y(), m5 = b.y() * c.x();
    return {a.x() * (m0 - m1) + a.y() * (m2 - m3) + a.z() * (m4 - m5),
            std::fabs(a.x()) * (std::fabs(m0) + std::fabs(m1)) + std::fabs(a.y()) * (std::fabs(m2) + std::fabs(m3)) +
                std::fabs(a.z()) * (std::fabs(m4) + std::fabs(m5))};
}

}  // namespace detail

/// The exact sign of the dot product a . b.
[[nodiscard]] inline Sign dot_sign(const Vec3& a, const Vec3& b) {
    const double p0 = a.x() * b.x(), p1 = a.y() * b.y(), p2 = a.z() * b.z();
    const double value = p0 + p1 + p2;
    if (detail::filter_decides(value, std::fabs(p0) + std::fabs(p1) + std::fabs(p2))) return sign_of(value);
    return detail::dot_sign_exact(a, b);
}

/// The exact sign of det[a b c] = a . (b x c) (the orientation of three vectors from the origin).
[[nodiscard]] inline Sign det_sign(const Vec3& a, const Vec3& b, const Vec3& c) {
    const auto [value, permanent] = detail::det_terms(a, b, c);
    // A product of b and c below the normal range errs by up to 2^-1075 absolutely, and a's
    // coordinates scale that error: the bound needs an absolute term (found by fuzz_cone with
    // coordinates near 1e231 and 1e-322).
    // That term is at most 2^-772 while a's coordinates sum below 2^300, which the filter's
    // slack already covers (kErrorBound is 8 eps where Shewchuk's bound is below 7.1 eps, and
    // the permanent exceeds 2^-600: a margin above 2^-653). It is computed only beyond that,
    // where it is a normal number: a subnormal product stalls the processor for about a hundred
    // cycles, which made every det_sign cost 20-30 ns.
    const double a_sum = std::fabs(a.x()) + std::fabs(a.y()) + std::fabs(a.z());
    if (detail::filter_decides(value, permanent) &&
        (a_sum < 0x1p300 || std::fabs(value) > detail::kErrorBound * permanent + a_sum * 0x1p-1072)) {
        return sign_of(value);
    }
    return detail::det_sign_exact(a, b, c);
}

/// The exact sign of the 2x2 minor a[i]*b[j] - a[j]*b[i].
[[nodiscard]] inline Sign minor_sign(const Vec3& a, const Vec3& b, int i, int j) {
    const double p = a[i] * b[j], q = a[j] * b[i];
    if (detail::filter_decides(p - q, std::fabs(p) + std::fabs(q))) return sign_of(p - q);
    return detail::minor_sign_exact(a, b, i, j);
}

/// The exact sign of the planar cross product a.x*b.y - a.y*b.x.
[[nodiscard]] inline Sign cross2_sign(const Vec2& a, const Vec2& b) {
    return minor_sign(Vec3(a.x(), a.y(), 0.0), Vec3(b.x(), b.y(), 0.0), 0, 1);
}

/// True when a and b are exactly parallel (a x b = 0), including when either is zero.
[[nodiscard]] inline bool parallel(const Vec3& a, const Vec3& b) {
    return minor_sign(a, b, 1, 2) == Sign::Zero && minor_sign(a, b, 2, 0) == Sign::Zero &&
           minor_sign(a, b, 0, 1) == Sign::Zero;
}

/// True when every coordinate of v is exactly zero. (Eigen's isZero() is true for coordinates up
/// to 1e-12 in magnitude: never use it for a decision.)
[[nodiscard]] inline bool is_zero(const Vec3& v) {
    return v.x() == 0.0 && v.y() == 0.0 && v.z() == 0.0;
}
[[nodiscard]] inline bool is_zero(const Vec2& v) { return v.x() == 0.0 && v.y() == 0.0; }

/// Counters of the calls the floating-point filter could not decide (per thread).
struct PredicateStats {
    long expansion = 0;  ///< decided by an error-free expansion
    long dyadic = 0;     ///< decided in Dyadic arithmetic (extreme exponents)
};

/// The counters of the calling thread since the last reset.
[[nodiscard]] PredicateStats& predicate_stats();

}  // namespace momentlab
