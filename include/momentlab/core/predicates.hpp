#pragma once

/// \file
/// The exact predicates, each written once for any number type, the one filter adaptor that
/// decides them, and their instances on stored doubles.
///
/// A predicate (`Dot`, `Det`, `Minor`) is a polynomial written once as a function object over
/// any number type with +, - and *: doubles (a rounded value), `Approx` (core/approx.hpp: the
/// filter, whose arithmetic computes its own error bound), exact numbers (Dyadic, and for
/// doubles 128-bit integers and Shewchuk's error-free expansions). `filtered_sign` evaluates it
/// on the operands' certified approximations and returns the sign when the bound decides it,
/// else asks the operands' exact stages (`exact_sign`); for doubles those are 128-bit integers
/// (small integers), error-free expansions (Shewchuk 1997, "Adaptive precision floating-point
/// arithmetic and fast robust geometric predicates"; arguments in 2^-250 .. 2^250) and Dyadic
/// numbers (core/dyadic.hpp). No tolerance is involved anywhere (docs/robustness.md).
/// Preconditions: all arguments finite (checked by the callers that take user input; asserted
/// in debug builds).

#include <array>

#include "momentlab/core/approx.hpp"
#include "momentlab/core/sign.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// The exact sign of the double `x`.
constexpr Sign sign_of(double x) {
    return x > 0 ? Sign::Positive : (x < 0 ? Sign::Negative : Sign::Zero);
}

/// a . b, for vectors indexed 0..2 of any number type.
struct Dot {
    template <class A, class B>
    constexpr auto operator()(const A& a, const B& b) const {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
};

/// det[a b c] = a . (b x c), for vectors indexed 0..2 of any number type.
struct Det {
    template <class A, class B, class C>
    constexpr auto operator()(const A& a, const B& b, const C& c) const {
        return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
};

/// The 2x2 minor a[i] b[j] - a[j] b[i], for vectors indexed 0..2 of any number type.
struct Minor {
    int i, j;
    template <class A, class B>
    constexpr auto operator()(const A& a, const B& b) const {
        return a[i] * b[j] - a[j] * b[i];
    }
};

/// Certified approximations of the three coordinates of a vector.
using Approx3 = std::array<Approx, 3>;

/// Stored doubles as the filter reads them: themselves, without error (each coordinate made
/// where a predicate reads it, so a minor reads two of the three).
struct ExactDoubles {
    const Vec3& v;
    [[nodiscard]] Approx operator[](int k) const { return Approx::exact(v[k]); }
};

/// The approximation of stored doubles.
[[nodiscard]] inline ExactDoubles approximate(const Vec3& v) { return {v}; }

/// The sign of p on the operands' approximations, when their bound decides it (true, the sign in
/// `out`); false when only exact arithmetic can. Operands: Approx3, ExactDoubles (anything
/// indexed 0..2 whose numbers are Approx).
/// (Flattened: the predicate and its arithmetic inline into one straight line of code, whose
/// depths the compiler folds into constants.)
template <class Predicate, class... A>
[[nodiscard, gnu::flatten]] inline bool filter_sign(const Predicate& p, Sign& out, const A&... approximations) {
    return certified_sign(p(approximations...), out);
}

/// The one filter adaptor: the exact sign of p on the operands x, decided by their
/// approximations (`approximate(x)`) when the bound decides it, else by the operands' exact
/// stages (`exact_sign(p, x...)`). Operands: Vec3 here; ExactVector and its kin in core/exact.hpp.
template <class Predicate, class... Operands>
[[nodiscard]] inline Sign filtered_sign(const Predicate& p, const Operands&... x) {
    Sign s = Sign::Zero;
    if (filter_sign(p, s, approximate(x)...)) return s;
    return exact_sign(p, x...);
}

/// The exact stages for stored doubles (src/core/predicates.cpp), when the filter cannot decide.
[[nodiscard]] Sign exact_sign(const Dot& p, const Vec3& a, const Vec3& b);
[[nodiscard]] Sign exact_sign(const Det& p, const Vec3& a, const Vec3& b, const Vec3& c);
[[nodiscard]] Sign exact_sign(const Minor& p, const Vec3& a, const Vec3& b);

/// The exact sign of the dot product a . b.
[[nodiscard]] inline Sign dot_sign(const Vec3& a, const Vec3& b) { return filtered_sign(Dot{}, a, b); }

/// The exact sign of det[a b c] = a . (b x c) (the orientation of three vectors from the origin).
[[nodiscard]] inline Sign det_sign(const Vec3& a, const Vec3& b, const Vec3& c) { return filtered_sign(Det{}, a, b, c); }

/// The exact sign of the 2x2 minor a[i]*b[j] - a[j]*b[i].
[[nodiscard]] inline Sign minor_sign(const Vec3& a, const Vec3& b, int i, int j) {
    return filtered_sign(Minor{i, j}, a, b);
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

/// Counters of the calls the filter could not decide (per thread).
struct PredicateStats {
    long expansion = 0;  ///< decided by an error-free expansion
    long dyadic = 0;     ///< decided in Dyadic arithmetic (extreme exponents)
};

/// The counters of the calling thread since the last reset.
[[nodiscard]] PredicateStats& predicate_stats();

}  // namespace momentlab
