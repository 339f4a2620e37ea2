#pragma once

// Closed intervals of doubles that enclose an exact value: every operation rounds to nearest
// (the only mode WebAssembly has) and then steps each end one double outwards, which encloses
// the exact result of the operation on any values inside the operands (a correctly rounded
// result is within half an ulp of the exact one, so the neighbour double lies beyond it). The
// assembly layer's filters: a sign read from an interval that excludes 0 is the exact sign of
// the value enclosed; an interval holding 0 decides nothing (the exact path then does).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "exact_number.hpp"

namespace momentlab::assembly_detail {

/// The next double above x (x not NaN); +inf stays. (Its bits stepped by one: memcpy, as
/// WebAssembly's libc++ has no std::bit_cast.)
[[nodiscard]] inline double next_up(double x) {
    if (x == std::numeric_limits<double>::infinity()) return x;
    if (x == 0.0) return std::numeric_limits<double>::denorm_min();
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    bits = x > 0.0 ? bits + 1 : bits - 1;
    std::memcpy(&x, &bits, sizeof bits);
    return x;
}
/// The next double below x.
[[nodiscard]] inline double next_down(double x) { return -next_up(-x); }

struct Interval {
    double lo = 0.0, hi = 0.0;

    Interval() = default;
    /// The point x (a double is exact).
    explicit Interval(double x) : lo(x), hi(x) {}
    Interval(double l, double h) : lo(l), hi(h) {}

    /// Strictly positive / strictly negative: the sign of every value inside, exactly.
    [[nodiscard]] bool positive() const { return lo > 0.0; }
    [[nodiscard]] bool negative() const { return hi < 0.0; }
    [[nodiscard]] bool nonnegative() const { return lo >= 0.0; }
    [[nodiscard]] bool nonpositive() const { return hi <= 0.0; }
    /// 0 is inside (or the interval is not finite): no sign can be read.
    [[nodiscard]] bool holds_zero() const { return !(lo > 0.0 || hi < 0.0); }
    [[nodiscard]] double mid() const { return lo * 0.5 + hi * 0.5; }
};

/// A scene's number enclosed (a decimal as typed): its correct rounding, and the doubles on
/// either side of it unless it is exact (the value lies within half an ulp of its rounding).
[[nodiscard]] inline Interval enclose(const momentlab::Rational& x) {
    const double d = x.to_double();
    if (x.is_double()) return Interval(d);
    return {next_down(d), next_up(d)};
}

/// The rational x enclosed: its rounding, widened by one double on each side unless exact.
[[nodiscard]] inline Interval enclose(const Rational& x) {
    const double d = approximate(x);
    if (is_double(x)) return Interval(d);
    // approximate() is within a few ulps: four steps out on each side.
    double lo = d, hi = d;
    for (int i = 0; i < 4; ++i) {
        lo = next_down(lo);
        hi = next_up(hi);
    }
    return {lo, hi};
}

// An exact zero stays exact (structural zeros keep their sign: none).
[[nodiscard]] inline bool is_exact_zero(const Interval& a) { return a.lo == 0.0 && a.hi == 0.0; }
[[nodiscard]] inline bool is_point(const Interval& a) { return a.lo == a.hi; }

// Error-free transformations (Knuth's two-sum, Dekker's two-product with Veltkamp's split):
// the rounding error of a sum or a product of two doubles, exactly, so that a result that is
// itself a double stays a point (integer and dyadic scenes keep their exact zeros and ties).
[[nodiscard]] inline double two_sum_error(double a, double b, double s) {
    const double bb = s - a;
    return (a - (s - bb)) + (b - bb);
}
[[nodiscard]] inline bool exact_product(double a, double b, double p) {
    // Valid away from overflow and underflow of the split and of the error term.
    const double m = std::max(std::abs(a), std::abs(b));
    if (!(std::abs(p) > 0x1p-900) || !(m < 0x1p+990) || !std::isfinite(p)) return false;
    const auto split = [](double x, double& hi, double& lo) {
        const double c = 134217729.0 * x;  // 2^27 + 1
        hi = c - (c - x);
        lo = x - hi;
    };
    double ah = 0, al = 0, bh = 0, bl = 0;
    split(a, ah, al);
    split(b, bh, bl);
    const double error = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    return error == 0.0;
}

[[nodiscard]] inline Interval operator+(const Interval& a, const Interval& b) {
    if (is_exact_zero(a)) return b;
    if (is_exact_zero(b)) return a;
    if (is_point(a) && is_point(b)) {
        const double sum = a.lo + b.lo;
        if (std::isfinite(sum) && two_sum_error(a.lo, b.lo, sum) == 0.0) return Interval(sum);
    }
    return {next_down(a.lo + b.lo), next_up(a.hi + b.hi)};
}
[[nodiscard]] inline Interval operator-(const Interval& a, const Interval& b) {
    if (is_exact_zero(b)) return a;
    if (is_exact_zero(a)) return {-b.hi, -b.lo};
    if (is_point(a) && is_point(b)) {
        const double d = a.lo - b.lo;
        if (std::isfinite(d) && two_sum_error(a.lo, -b.lo, d) == 0.0) return Interval(d);
    }
    return {next_down(a.lo - b.hi), next_up(a.hi - b.lo)};
}
[[nodiscard]] inline Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
[[nodiscard]] inline Interval operator*(const Interval& a, const Interval& b) {
    if (is_exact_zero(a) || is_exact_zero(b)) return Interval(0.0);
    if (is_point(a) && is_point(b)) {
        const double p = a.lo * b.lo;
        if (exact_product(a.lo, b.lo, p)) return Interval(p);
    }
    const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
    const double lo = std::min(std::min(p1, p2), std::min(p3, p4));
    const double hi = std::max(std::max(p1, p2), std::max(p3, p4));
    if (std::isnan(lo) || std::isnan(hi)) {  // 0 * inf: nothing known
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    }
    return {next_down(lo), next_up(hi)};
}
/// a / b for b not holding 0 (otherwise the whole line).
[[nodiscard]] inline Interval operator/(const Interval& a, const Interval& b) {
    if (b.holds_zero()) {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    }
    if (is_exact_zero(a)) return Interval(0.0);
    if (is_point(a) && is_point(b)) {
        const double q = a.lo / b.lo;
        if (q * b.lo == a.lo && exact_product(q, b.lo, a.lo)) return Interval(q);
    }
    const double p1 = a.lo / b.lo, p2 = a.lo / b.hi, p3 = a.hi / b.lo, p4 = a.hi / b.hi;
    const double lo = std::min(std::min(p1, p2), std::min(p3, p4));
    const double hi = std::max(std::max(p1, p2), std::max(p3, p4));
    if (std::isnan(lo) || std::isnan(hi)) {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    }
    return {next_down(lo), next_up(hi)};
}
inline Interval& operator+=(Interval& a, const Interval& b) { return a = a + b; }
inline Interval& operator-=(Interval& a, const Interval& b) { return a = a - b; }

}  // namespace momentlab::assembly_detail
