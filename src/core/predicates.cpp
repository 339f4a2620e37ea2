#include "momentlab/core/predicates.hpp"

#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "error_free.hpp"
#include "momentlab/core/dyadic.hpp"

namespace momentlab {
namespace {

thread_local PredicateStats g_stats;

// Error-free transformations (Dekker 1971; Shewchuk 1997, section 2). They are exact as long
// as no intermediate overflows or underflows, which `in_expansion_range` guarantees.
constexpr double kSplitter = 134217729.0;  // 2^27 + 1

using detail::two_sum;

inline void split(double a, double& hi, double& lo) {
    const double c = kSplitter * a;
    hi = c - (c - a);
    lo = a - hi;
}

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

// A non-overlapping expansion with zero elimination: the exact sum of its components, kept in
// increasing order of magnitude, so the sign of the sum is the sign of the last component.
template <std::size_t N>
class Expansion {
public:
    void add(double b) {
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
    void add_product(double a, double b) {
        double x, y;
        two_product(a, b, x, y);
        add(y);
        add(x);
    }
    void add_product(double a, double b, double c) {
        double x, y;
        two_product(a, b, x, y);
        double x1, x0, y1, y0;
        two_product(x, c, x1, x0);
        two_product(y, c, y1, y0);
        add(y0);
        add(x0);
        add(y1);
        add(x1);
    }
    Sign sign() const { return size_ == 0 ? Sign::Zero : sign_of(parts_[size_ - 1]); }

private:
    std::array<double, N> parts_{};
    std::size_t size_ = 0;
};

// Products of up to three such numbers, and their error terms, neither overflow nor fall
// below the normal range, which keeps every transformation above exact.
inline bool in_expansion_range(double x) {
    const double a = std::fabs(x);
    return a == 0.0 || (a >= 0x1p-250 && a <= 0x1p250);
}

inline bool in_expansion_range(const Vec3& v) {
    return in_expansion_range(v.x()) && in_expansion_range(v.y()) && in_expansion_range(v.z());
}

inline Dyadic d(double x) { return Dyadic(x); }

}  // namespace

PredicateStats& predicate_stats() { return g_stats; }

namespace detail {

Sign dot_sign_exact(const Vec3& a, const Vec3& b) {
    assert(a.allFinite() && b.allFinite());
    if (in_expansion_range(a) && in_expansion_range(b)) {
        ++g_stats.expansion;
        Expansion<6> e;
        e.add_product(a.x(), b.x());
        e.add_product(a.y(), b.y());
        e.add_product(a.z(), b.z());
        return e.sign();
    }
    ++g_stats.dyadic;
    return (d(a.x()) * d(b.x()) + d(a.y()) * d(b.y()) + d(a.z()) * d(b.z())).sign();
}

// The 2x2 minor x1*y2 - x2*y1 with error at most eps|m| + eps^2 (|x1 y2| + |x2 y1|): the
// products are split exactly (Dekker), their leading parts cancel exactly when close
// (Sterbenz), and only the small tails are rounded.
inline double accurate_minor(double x1, double y2, double x2, double y1) {
    double p, pe, q, qe;
    two_product(x1, y2, p, pe);
    two_product(x2, y1, q, qe);
    return (p - q) + (pe - qe);
}

__extension__ typedef __int128 Int128;

// Integers up to 2^40 in magnitude: products of three fit in 120 bits, sums of six in 123.
inline bool small_integer(double x, std::int64_t& out) {
    if (!(std::fabs(x) <= 0x1p40)) return false;
    out = static_cast<std::int64_t>(x);
    return static_cast<double>(out) == x;
}

inline bool small_integers(const Vec3& a, const Vec3& b, const Vec3& c, std::int64_t v[9]) {
    return small_integer(a.x(), v[0]) && small_integer(a.y(), v[1]) && small_integer(a.z(), v[2]) &&
           small_integer(b.x(), v[3]) && small_integer(b.y(), v[4]) && small_integer(b.z(), v[5]) &&
           small_integer(c.x(), v[6]) && small_integer(c.y(), v[7]) && small_integer(c.z(), v[8]);
}

Sign det_sign_exact(const Vec3& a, const Vec3& b, const Vec3& c) {
    assert(a.allFinite() && b.allFinite() && c.allFinite());
    std::int64_t v[9];
    if (small_integers(a, b, c, v)) {
        // Exactly degenerate inputs are often small integers: exact in 128-bit arithmetic.
        const Int128 m0 = static_cast<Int128>(v[4]) * v[8] - static_cast<Int128>(v[5]) * v[7];
        const Int128 m1 = static_cast<Int128>(v[5]) * v[6] - static_cast<Int128>(v[3]) * v[8];
        const Int128 m2 = static_cast<Int128>(v[3]) * v[7] - static_cast<Int128>(v[4]) * v[6];
        const Int128 d = v[0] * m0 + v[1] * m1 + v[2] * m2;
        return d > 0 ? Sign::Positive : (d < 0 ? Sign::Negative : Sign::Zero);
    }
    if (in_expansion_range(a) && in_expansion_range(b) && in_expansion_range(c)) {
        // Second filter: nearly exact minors. For nearly collinear b, c the minors are small
        // and the bound, relative to |a_i m_i| rather than to the permanent, is much tighter.
        // Bound: each minor has error <= eps|m_i| + eps^2 P_i (see accurate_minor; the
        // difference p - q is exact only when p, q are close, otherwise it adds eps|m_i|);
        // the products and the two sums add <= 3 eps sum |a_i m_i| (plus eps^2 terms).
        const double m0 = accurate_minor(b.y(), c.z(), b.z(), c.y());
        const double m1 = accurate_minor(b.z(), c.x(), b.x(), c.z());
        const double m2 = accurate_minor(b.x(), c.y(), b.y(), c.x());
        const double value = a.x() * m0 + a.y() * m1 + a.z() * m2;
        const double s = std::fabs(a.x() * m0) + std::fabs(a.y() * m1) + std::fabs(a.z() * m2);
        const double permanent =
            std::fabs(a.x()) * (std::fabs(b.y() * c.z()) + std::fabs(b.z() * c.y())) +
            std::fabs(a.y()) * (std::fabs(b.z() * c.x()) + std::fabs(b.x() * c.z())) +
            std::fabs(a.z()) * (std::fabs(b.x() * c.y()) + std::fabs(b.y() * c.x()));
        const double eps = 0x1p-53;
        const double bound = 6.0 * eps * s + 4.0 * eps * eps * permanent;
        if (std::fabs(value) > bound && permanent > 0x1p-500) return sign_of(value);
        ++g_stats.expansion;
        Expansion<24> e;
        e.add_product(a.x(), b.y(), c.z());
        e.add_product(-a.x(), b.z(), c.y());
        e.add_product(a.y(), b.z(), c.x());
        e.add_product(-a.y(), b.x(), c.z());
        e.add_product(a.z(), b.x(), c.y());
        e.add_product(-a.z(), b.y(), c.x());
        return e.sign();
    }
    ++g_stats.dyadic;
    const Dyadic ax(a.x()), ay(a.y()), az(a.z());
    const Dyadic bx(b.x()), by(b.y()), bz(b.z());
    const Dyadic cx(c.x()), cy(c.y()), cz(c.z());
    return (ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx)).sign();
}

Sign minor_sign_exact(const Vec3& a, const Vec3& b, int i, int j) {
    assert(a.allFinite() && b.allFinite());
    if (in_expansion_range(a[i]) && in_expansion_range(a[j]) && in_expansion_range(b[i]) &&
        in_expansion_range(b[j])) {
        ++g_stats.expansion;
        Expansion<4> e;
        e.add_product(a[i], b[j]);
        e.add_product(-a[j], b[i]);
        return e.sign();
    }
    ++g_stats.dyadic;
    return (d(a[i]) * d(b[j]) - d(a[j]) * d(b[i])).sign();
}

}  // namespace detail

}  // namespace momentlab
