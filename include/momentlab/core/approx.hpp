#pragma once

/// \file
/// Certified approximations: the number type of momentlab's filters (docs/robustness.md).
///
/// An `Approx` is a double standing for an exact real number x, with a bound on |x - value|
/// that its own arithmetic computes: the a-priori bound of floating-point error analysis
/// (Higham, "Accuracy and Stability of Numerical Algorithms", 2002, section 3.1),
///     |x - value| <= gamma(depth) * magnitude,   gamma(n) = n u / (1 - n u),  u = 2^-53,
/// where `magnitude` is the same expression evaluated on the magnitudes (every minus a plus)
/// and `depth` the number of roundings (and input errors, counted in units of u) on the
/// longest path. An exact double x is {x, |x|, 0}; an exact value known only to within an error
/// (a rounded Dyadic number, a decimal 0.1 read as 1/10) is `Approx::within(value, error)`.
/// Every predicate is written once, generic over its number type (core/predicates.hpp), and
/// evaluated on `Approx` it is a filter whose error bound is computed by the operations
/// themselves: where the depth is known at compile time the bound is a constant, as in a
/// static filter (CGAL's Static_filters, whose constants come from Static_filter_error).

#include <cmath>

#include "momentlab/core/sign.hpp"

namespace momentlab {

/// The unit roundoff of double arithmetic (round to nearest).
inline constexpr double kUnitRoundoff = 0x1p-53;

/// What a product adds to its magnitude: the absolute error of a product rounded below the
/// normal range is at most 2^-1075, and u * 2^-1020 = 2^-1073 covers it twice over (the value's
/// product and the magnitude's own) wherever it is multiplied afterwards.
inline constexpr double kUnderflowMagnitude = 0x1p-1020;

/// A double `value` standing for an exact x with |x - value| <= gamma(depth) * magnitude
/// (magnitude >= |value|, depth >= 0), plus what underflow adds (kUnderflowMagnitude).
struct Approx {
    double value = 0.0;
    double magnitude = 0.0;
    int depth = 0;

    /// The double x itself (no error).
    static Approx exact(double x) { return {x, std::fabs(x), 0}; }
    /// An x known to lie within `error` of `value` (any finite error >= 0; +inf: unknown). The
    /// error is written as gamma(4) times a magnitude, which costs nothing for errors up to
    /// 4u |value| (a rounded exact number).
    static Approx within(double value, double error) {
        const double a = std::fabs(value), m = error * 0x1p51;  // (exact: a power of two)
        return {value, a >= m ? a : m, kWithinDepth};            // (a NaN error stays NaN: uncertain)
    }
    /// The depth that `within` gives.
    static constexpr int kWithinDepth = 4;
};

[[nodiscard]] constexpr Approx operator-(const Approx& a) { return {-a.value, a.magnitude, a.depth}; }
// A sum of two exact doubles is rounded once relative to itself, fl(a + b) = (a + b)(1 + d) with
// |d| <= u (exact below the normal range), so |x - value| <= u |x| <= gamma(1) |value|: its
// magnitude is |value| (Shewchuk's differences of coordinates, which cancel nothing they hide).
[[nodiscard]] inline Approx operator+(const Approx& a, const Approx& b) {
    const double v = a.value + b.value;
    return {v, a.depth == 0 && b.depth == 0 ? std::fabs(v) : a.magnitude + b.magnitude, (a.depth > b.depth ? a.depth : b.depth) + 1};
}
[[nodiscard]] inline Approx operator-(const Approx& a, const Approx& b) { return a + -b; }
// Input errors multiply: (1 + gamma(m))(1 + gamma(n))(1 + u) <= 1 + gamma(m + n + 1). (The
// product of two exact doubles has the magnitude |value|, one instruction where the depths are
// known at compile time.)
[[nodiscard]] inline Approx operator*(const Approx& a, const Approx& b) {
    const double v = a.value * b.value;
    const double m = a.depth == 0 && b.depth == 0 ? std::fabs(v) : a.magnitude * b.magnitude;
    return {v, m + kUnderflowMagnitude, a.depth + b.depth + 1};
}

/// A bound on gamma(depth) / (1 - u)^(2 depth + 2), which also covers the rounding of the
/// magnitude's own evaluation (at most two roundings per level of depth, each of non-negative
/// numbers and so by a factor 1 - u at worst) and of its product with this factor:
/// n u (1 + 2^-40) for n <= 1024 (the product is exact in doubles).
[[nodiscard]] constexpr double error_factor(int depth) { return depth * kUnitRoundoff * (1 + 0x1p-40); }

/// The certified sign of the exact number `a` stands for: true (and the sign in `out`) when the
/// bound decides it, false when it does not. An overflow anywhere makes the magnitude infinite
/// (each node's |value| is at most its magnitude: rounding is monotone), and a NaN fails every
/// comparison: neither is ever certified. Precondition: depth <= 1024.
[[nodiscard]] inline bool certified_sign(const Approx& a, Sign& out) {
    if (!(std::fabs(a.value) > error_factor(a.depth) * a.magnitude)) return false;
    out = a.value > 0 ? Sign::Positive : Sign::Negative;
    return true;
}

class Dyadic;

/// An exact number as the filters read it: its double, rounded to nearest (relative error at
/// most 2^-53, or 2^-1075 below the normal range), exact when it is one.
[[nodiscard]] Approx approximate(const Dyadic& x);

}  // namespace momentlab
