#include "momentlab/core/predicates.hpp"

#include <gmpxx.h>

#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>

namespace momentlab {
namespace {

thread_local PredicateStats g_stats;

// Error-free transformations (Dekker 1971; Shewchuk 1997, section 2). They are exact as long
// as no intermediate overflows or underflows, which `in_expansion_range` guarantees.
constexpr double kSplitter = 134217729.0;  // 2^27 + 1

inline void two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    const double b_virtual = x - a;
    const double a_virtual = x - b_virtual;
    y = (a - a_virtual) + (b - b_virtual);
}

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

inline Sign sign_of(const mpq_class& q) { return sign_of_int(sgn(q)); }

// Forward error bounds of the straightforward evaluations, relative to the sum of absolute
// values of the terms (the "permanent"). Shewchuk's orient3d bound (7 + 56 eps) eps covers the
// 3x3 determinant (our inputs are exact, which only helps); dot products and 2x2 minors have
// smaller bounds, and we use the same conservative constant. The filter is only trusted when
// the permanent is far from underflow, so absolute errors of denormal products are negligible.
constexpr double kErrorBound = 8.0 * 0x1p-53;
constexpr double kMinPermanent = 0x1p-600;

}  // namespace

PredicateStats& predicate_stats() { return g_stats; }

Sign dot_sign(const Vec3& a, const Vec3& b) {
    assert(a.allFinite() && b.allFinite());
    const double p0 = a.x() * b.x(), p1 = a.y() * b.y(), p2 = a.z() * b.z();
    const double value = p0 + p1 + p2;
    const double permanent = std::fabs(p0) + std::fabs(p1) + std::fabs(p2);
    if (std::fabs(value) > kErrorBound * permanent && permanent > kMinPermanent &&
        std::isfinite(permanent)) {
        ++g_stats.filtered;
        return sign_of(value);
    }
    if (in_expansion_range(a) && in_expansion_range(b)) {
        ++g_stats.expansion;
        Expansion<6> e;
        e.add_product(a.x(), b.x());
        e.add_product(a.y(), b.y());
        e.add_product(a.z(), b.z());
        return e.sign();
    }
    ++g_stats.gmp;
    const mpq_class r = mpq_class(a.x()) * mpq_class(b.x()) + mpq_class(a.y()) * mpq_class(b.y()) +
                        mpq_class(a.z()) * mpq_class(b.z());
    return sign_of(r);
}

Sign det_sign(const Vec3& a, const Vec3& b, const Vec3& c) {
    assert(a.allFinite() && b.allFinite() && c.allFinite());
    const double m0 = b.y() * c.z(), m1 = b.z() * c.y();
    const double m2 = b.z() * c.x(), m3 = b.x() * c.z();
    const double m4 = b.x() * c.y(), m5 = b.y() * c.x();
    const double value = a.x() * (m0 - m1) + a.y() * (m2 - m3) + a.z() * (m4 - m5);
    const double permanent = std::fabs(a.x()) * (std::fabs(m0) + std::fabs(m1)) +
                             std::fabs(a.y()) * (std::fabs(m2) + std::fabs(m3)) +
                             std::fabs(a.z()) * (std::fabs(m4) + std::fabs(m5));
    if (std::fabs(value) > kErrorBound * permanent && permanent > kMinPermanent &&
        std::isfinite(permanent)) {
        ++g_stats.filtered;
        return sign_of(value);
    }
    if (in_expansion_range(a) && in_expansion_range(b) && in_expansion_range(c)) {
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
    ++g_stats.gmp;
    const mpq_class ax(a.x()), ay(a.y()), az(a.z());
    const mpq_class bx(b.x()), by(b.y()), bz(b.z());
    const mpq_class cx(c.x()), cy(c.y()), cz(c.z());
    const mpq_class r = ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
    return sign_of(r);
}

Sign minor_sign(const Vec3& a, const Vec3& b, int i, int j) {
    assert(a.allFinite() && b.allFinite());
    const double p = a[i] * b[j], q = a[j] * b[i];
    const double value = p - q;
    const double permanent = std::fabs(p) + std::fabs(q);
    if (std::fabs(value) > kErrorBound * permanent && permanent > kMinPermanent &&
        std::isfinite(permanent)) {
        ++g_stats.filtered;
        return sign_of(value);
    }
    if (in_expansion_range(a[i]) && in_expansion_range(a[j]) && in_expansion_range(b[i]) &&
        in_expansion_range(b[j])) {
        ++g_stats.expansion;
        Expansion<4> e;
        e.add_product(a[i], b[j]);
        e.add_product(-a[j], b[i]);
        return e.sign();
    }
    ++g_stats.gmp;
    return sign_of(mpq_class(a[i]) * mpq_class(b[j]) - mpq_class(a[j]) * mpq_class(b[i]));
}

Sign cross2_sign(const Vec2& a, const Vec2& b) {
    return minor_sign(Vec3(a.x(), a.y(), 0.0), Vec3(b.x(), b.y(), 0.0), 0, 1);
}

bool parallel(const Vec3& a, const Vec3& b) {
    return minor_sign(a, b, 1, 2) == Sign::Zero && minor_sign(a, b, 2, 0) == Sign::Zero &&
           minor_sign(a, b, 0, 1) == Sign::Zero;
}

}  // namespace momentlab
