#pragma once

// Error-free transformations of doubles and the expansions built on them (Dekker 1971; Shewchuk
// 1997, "Adaptive precision floating-point arithmetic and fast robust geometric predicates",
// sections 2.3-2.6), private to the core layer. Exact as long as no intermediate overflows or
// underflows: every component of a sum or product of doubles that are zero or in
// [2^-250, 2^250], of degree at most 3, is a non-zero multiple of 2^-906 below 2^753 (each
// double there is a multiple of 2^-302), so those stay exact (`in_expansion_range`).

#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <optional>

#include "momentlab/core/sign.hpp"

namespace momentlab::detail {

// x + y = a + b exactly, with x = fl(a + b) (Knuth's two-sum).
inline void two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    const double b_virtual = x - a;
    const double a_virtual = x - b_virtual;
    y = (a - a_virtual) + (b - b_virtual);
}

// x - y in doubles when the difference is exact (two-sum leaves no error), else nullopt.
inline std::optional<double> exact_difference(double x, double y) {
    double s = 0, error = 0;
    two_sum(x, -y, s, error);
    if (!std::isfinite(s) || error != 0.0) return std::nullopt;
    return s;
}

// a = hi + lo, each with at most 26 significant bits (Dekker's split).
inline void split(double a, double& hi, double& lo) {
    const double c = 134217729.0 * a;  // 2^27 + 1
    hi = c - (c - a);
    lo = a - hi;
}

// x + y = a b exactly, with x = fl(a b) (Dekker's two-product).
inline void two_product(double a, double b, double& x, double& y) {
    x = a * b;
    double a_hi, a_lo, b_hi, b_lo;
    split(a, a_hi, a_lo);
    split(b, b_hi, b_lo);
    const double err1 = x - a_hi * b_hi;
    const double err2 = err1 - a_lo * b_hi;
    const double err3 = err2 - a_hi * b_lo;
    y = a_lo * b_lo - err3;
}

// True when x is zero or its magnitude lies in [2^-250, 2^250] (see the file's comment).
inline bool in_expansion_range(double x) {
    const double a = std::fabs(x);
    return a == 0.0 || (a >= 0x1p-250 && a <= 0x1p250);
}

// An exact number as a non-overlapping sum of at most N doubles in increasing order of
// magnitude, without zeros (Shewchuk's expansions), so that its sign is that of its last
// component. A number type for the predicates written once (core/predicates.hpp): sums and
// products of expansions are expansions, of sizes that add and multiply (doubled for the
// products' error terms).
template <std::size_t N>
class Expansion {
public:
    Expansion() = default;
    explicit Expansion(double x) {
        static_assert(N >= 1);
        if (x != 0.0) parts_[size_++] = x;
    }

    // Adds b exactly (Shewchuk's GROW-EXPANSION with zero elimination).
    void grow(double b) {
        if (b == 0.0) return;
        double q = b;
        std::size_t out = 0;
        for (std::size_t i = 0; i < size_; ++i) {
            double sum, err;
            two_sum(q, parts_[i], sum, err);
            if (err != 0.0) parts_[out++] = err;
            q = sum;
        }
        if (q != 0.0) parts_[out++] = q;
        assert(out <= N);
        size_ = out;
    }

    [[nodiscard]] Sign sign() const {
        return size_ == 0 ? Sign::Zero : (parts_[size_ - 1] > 0 ? Sign::Positive : Sign::Negative);
    }
    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] double operator[](std::size_t i) const { return parts_[i]; }

private:
    std::array<double, N> parts_{};
    std::size_t size_ = 0;
};

template <std::size_t N, std::size_t M>
Expansion<N + M> operator+(const Expansion<N>& a, const Expansion<M>& b) {
    Expansion<N + M> out;
    for (std::size_t i = 0; i < a.size(); ++i) out.grow(a[i]);
    for (std::size_t i = 0; i < b.size(); ++i) out.grow(b[i]);
    return out;
}

template <std::size_t N, std::size_t M>
Expansion<N + M> operator-(const Expansion<N>& a, const Expansion<M>& b) {
    Expansion<N + M> out;
    for (std::size_t i = 0; i < a.size(); ++i) out.grow(a[i]);
    for (std::size_t i = 0; i < b.size(); ++i) out.grow(-b[i]);
    return out;
}

// Every product of components, each an exact pair of doubles, added in.
template <std::size_t N, std::size_t M>
Expansion<2 * N * M> operator*(const Expansion<N>& a, const Expansion<M>& b) {
    Expansion<2 * N * M> out;
    for (std::size_t i = 0; i < a.size(); ++i) {
        for (std::size_t j = 0; j < b.size(); ++j) {
            double x, y;
            two_product(a[i], b[j], x, y);
            out.grow(y);
            out.grow(x);
        }
    }
    return out;
}

}  // namespace momentlab::detail
