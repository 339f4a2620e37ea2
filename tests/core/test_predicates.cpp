// The filter's number type (Approx) and the exact predicates against GMP rationals computed
// independently in the test.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>

#include "random_inputs.hpp"
#include "momentlab/core/approx.hpp"
#include "momentlab/core/predicates.hpp"

namespace momentlab {
namespace {

int exact_det(const Vec3& a, const Vec3& b, const Vec3& c) {
    auto q = [](double x) { return mpq_class(x); };
    const mpq_class d = q(a.x()) * (q(b.y()) * q(c.z()) - q(b.z()) * q(c.y())) -
                        q(a.y()) * (q(b.x()) * q(c.z()) - q(b.z()) * q(c.x())) +
                        q(a.z()) * (q(b.x()) * q(c.y()) - q(b.y()) * q(c.x()));
    return sgn(d);
}

int exact_dot(const Vec3& a, const Vec3& b) {
    const mpq_class d = mpq_class(a.x()) * b.x() + mpq_class(a.y()) * b.y() + mpq_class(a.z()) * b.z();
    return sgn(d);
}

// Random vectors at a random scale 2^k, k in [-lo, hi].
Vec3 scaled(testing::Random& r, int lo, int hi) {
    return std::ldexp(1.0, r.integer(-lo, hi)) * r.vec3(1.0);
}

// ---------------------------------------------------------------------------------------------
// Approx: the bound its arithmetic computes holds.

// A number as the filter sees it (Approx) beside the exact rational it stands for.
struct Pair {
    Approx a;
    mpq_class x;
};

Pair operator+(const Pair& p, const Pair& q) { return {p.a + q.a, p.x + q.x}; }
Pair operator-(const Pair& p, const Pair& q) { return {p.a - q.a, p.x - q.x}; }
Pair operator*(const Pair& p, const Pair& q) { return {p.a * q.a, p.x * q.x}; }

// The certified bound as the filter computes it, in doubles: fl(error_factor(depth) magnitude).
mpq_class certified_bound(const Approx& a) { return mpq_class(error_factor(a.depth) * a.magnitude); }

// The smallest double >= |q| (for a bound on an error known exactly).
double rounded_up(const mpq_class& q) {
    double d = mpq_class(abs(q)).get_d();  // (GMP truncates)
    if (mpq_class(d) < abs(q)) d = std::nextafter(d, std::numeric_limits<double>::infinity());
    return d;
}

// A decimal k / 10^n that is not a double, with its nearest-or-next double and that double's
// exact error (as issue 46's numbers read as typed will be): Approx::within.
Pair decimal(testing::Random& r) {
    mpz_class ten_n = 1;
    for (int n = r.integer(17, 18); n > 0; --n) ten_n *= 10;
    mpz_class k = r.integer(1, 999999999);
    k = k * 1000000000 + r.integer(0, 999999999);  // up to 18 digits: x up to 10
    const mpq_class x(r.integer(0, 1) ? mpz_class(k) : mpz_class(-k), ten_n);
    const double d = x.get_d();
    return {Approx::within(d, rounded_up(x - mpq_class(d))), x};
}

// A double at a random scale: from far below 1 (products then fall below the normal range) to
// far above.
Pair exact_double(testing::Random& r) {
    const int kind = r.integer(0, 3);
    const double d = kind == 0 ? std::ldexp(r.uniform(-1, 1), r.integer(-560, -500))
                   : kind == 1 ? std::ldexp(r.uniform(-1, 1), r.integer(-300, 300))
                               : r.uniform(-1, 1);
    return {Approx::exact(d), mpq_class(d)};
}

// A value known to within a given error, the exact value at the edge of it (the worst case).
Pair at_the_edge(testing::Random& r) {
    const double d = std::ldexp(r.uniform(-1, 1), r.integer(-8, 8));
    const double error = std::ldexp(std::fabs(d), -r.integer(20, 52));
    return {Approx::within(d, error), mpq_class(d) + (r.integer(0, 1) ? mpq_class(error) : mpq_class(-error))};
}

Pair random_expression(testing::Random& r, int depth) {
    const int op = depth == 0 ? 4 : r.integer(0, 5);
    if (op >= 4) {
        const int leaf = r.integer(0, 2);
        return leaf == 0 ? exact_double(r) : leaf == 1 ? decimal(r) : at_the_edge(r);
    }
    const Pair a = random_expression(r, depth - 1);
    // A second operand close to the first in half the sums: cancellation.
    const double near_one = 1 + 0x1p-50 * r.integer(-4, 4);
    const Pair b = op < 2 && r.integer(0, 1) ? a * Pair{Approx::exact(near_one), mpq_class(near_one)} : random_expression(r, depth - 1);
    return op == 0 ? a - b : op == 1 ? a + b : a * b;
}

// |x - value| <= fl(error_factor(depth) * magnitude) against GMP on random expressions of up to
// five levels over exact doubles (some small enough that products fall below the normal range),
// decimals that are not doubles, and values at the edge of a stated error; a certified sign is
// the exact sign. Fails when u is taken as 2^-60, when a product's underflow term is 0, when a
// product's depth is the larger of its operands' (not their sum), or when within() understates
// the error.
TEST(Approx, BoundHoldsOnRandomExpressions) {
    testing::Random r(43);
    int underflowed = 0, certified = 0;
    for (int i = 0; i < 200000; ++i) {
        const Pair e = random_expression(r, r.integer(1, 5));
        if (!std::isfinite(e.a.value) || !std::isfinite(e.a.magnitude)) continue;
        ASSERT_LE(abs(e.x - mpq_class(e.a.value)), certified_bound(e.a)) << i << ": depth " << e.a.depth;
        Sign s = Sign::Zero;
        if (certified_sign(e.a, s)) {
            ASSERT_EQ(to_int(s), sgn(e.x)) << i;
            ++certified;
        }
        underflowed += e.a.magnitude < 0x1p-1000 && e.x != mpq_class(e.a.value);
    }
    EXPECT_GT(underflowed, 1000);
    EXPECT_GT(certified, 100000);
}

// The depth the arithmetic counts for each predicate is the number of roundings on its longest
// path, read off the formulas: a . b is three products then two sums (3); a 2x2 minor is two
// products and a difference (2); det[a b c] is products, differences, products by a's
// coordinates and two sums (5); an input known within an error counts 4 (Approx::within), once
// per factor: 2 * 4 + 3, 2 * 4 + 2 and 3 * 4 + 5.
TEST(Approx, DepthCountsTheRoundings) {
    const Approx3 x{Approx::exact(1), Approx::exact(2), Approx::exact(3)};
    const Approx3 y{Approx::within(1, 0), Approx::within(2, 0), Approx::within(3, 0)};
    EXPECT_EQ(Dot{}(x, x).depth, 3);
    EXPECT_EQ((Minor{0, 1}(x, x).depth), 2);
    EXPECT_EQ(Det{}(x, x, x).depth, 5);
    EXPECT_EQ(Dot{}(y, y).depth, 11);
    EXPECT_EQ((Minor{0, 1}(y, y).depth), 10);
    EXPECT_EQ(Det{}(y, y, y).depth, 17);
    EXPECT_EQ(Det{}(x, y, x).depth, 9);
    // The magnitude is the permanent (the formula with every term made positive), here exact.
    const Approx3 a{Approx::exact(1), Approx::exact(-2), Approx::exact(3)}, b{Approx::exact(-4), Approx::exact(5), Approx::exact(6)};
    EXPECT_EQ(Dot{}(a, b).value, 1 * -4 + -2 * 5 + 3 * 6);
    EXPECT_NEAR(Dot{}(a, b).magnitude, 4 + 10 + 18, 1e-300);
}

// Vectors of decimals that are not doubles (issue 46: 0.1 read as 1/10), each coordinate's
// approximation the double next to it with its exact error: determinants, dot products and
// minors exactly zero (c = a + b, b = (a_y, -a_x, 0) s) and moved off zero by 1 to 4 units of
// 10^-k, k from 14 to 19 (within a few ulps of the degeneracy), or by 2^30 units. Every sign the
// filter certifies is GMP's; it certifies none of the zeros and most of the signs 2^30 units away. Fails when within()
// understates the error (2^45 for 2^51) or counts its depth as 1.
TEST(Approx, DecimalsNearDegeneracyAreDecidedRightly) {
    testing::Random r(46);
    int decided_far = 0, far = 0, decided_zero = 0;
    for (int i = 0; i < 30000; ++i) {
        std::array<Pair, 3> a, b, c;
        for (std::size_t k = 0; k < 3; ++k) {
            a[k] = decimal(r);
            b[k] = decimal(r);
        }
        const int kind = i % 3;
        const int units = r.integer(0, 1) ? r.integer(1, 4) : 1 << 30;
        mpz_class ten = 1;
        for (int n = r.integer(14, 19); n > 0; --n) ten *= 10;
        const mpq_class nudge = i % 4 == 0 ? mpq_class(0) : mpq_class(r.integer(0, 1) ? units : -units, ten);
        if (kind == 1) {  // b orthogonal to a, then nudged
            b = {Pair{}, Pair{}, Pair{}};
            const mpq_class s(r.integer(1, 99), 7);
            const std::array<mpq_class, 3> exact{a[1].x * s + nudge, -a[0].x * s, mpq_class(0)};
            for (std::size_t k = 0; k < 3; ++k) {
                const double d = exact[k].get_d();
                b[k] = {Approx::within(d, rounded_up(exact[k] - mpq_class(d))), exact[k]};
            }
        }
        for (std::size_t k = 0; k < 3; ++k) {  // c = a + b, nudged
            const mpq_class exact = a[k].x + b[k].x + (k == 0 ? nudge : mpq_class(0));
            const double d = exact.get_d();
            c[k] = {Approx::within(d, rounded_up(exact - mpq_class(d))), exact};
        }
        // (Evaluated on Pair: the filter's Approx and GMP's exact value at once.)
        Pair value;
        if (kind == 0) {
            value = Det{}(a, b, c);
        } else if (kind == 1) {
            value = Dot{}(a, b);
        } else {  // a against c - b = a + nudge e_0: the minor is -a_y nudge
            std::array<Pair, 3> d;
            for (std::size_t k = 0; k < 3; ++k) d[k] = c[k] - b[k];
            value = Minor{0, 1}(a, d);
        }
        Sign s = Sign::Zero;
        const bool decided = certified_sign(value.a, s);
        const int expected = sgn(value.x);
        if (decided) ASSERT_EQ(to_int(s), expected) << i << " kind " << kind;
        if (expected == 0) decided_zero += decided;
        if (units == 1 << 30 && nudge != 0) {
            ++far;
            decided_far += decided;
        }
    }
    EXPECT_EQ(decided_zero, 0);
    EXPECT_GT(decided_far, far / 2);
}

TEST(Predicates, DeterminantSignIsExactOnNearlyCoplanarTriples) {
    testing::Random r(1);
    predicate_stats() = {};
    int zero = 0;
    for (int i = 0; i < 100000; ++i) {
        const Vec3 a = scaled(r, 40, 40), b = scaled(r, 40, 40);
        // c is a rounded combination of a and b: the exact determinant is tiny or zero.
        Vec3 c = r.uniform(-2, 2) * a + r.uniform(-2, 2) * b;
        if (i % 3 == 0) c = a + b;
        if (i % 5 == 0) c = Vec3(std::nextafter(c.x(), 1e300), c.y(), c.z());
        const int expected = exact_det(a, b, c);
        zero += expected == 0;
        ASSERT_EQ(to_int(det_sign(a, b, c)), expected) << i;
    }
    EXPECT_GT(zero, 1000);  // exact zeros do occur and are recognised
    EXPECT_GT(predicate_stats().expansion, 10000);
}

TEST(Predicates, DeterminantSignIsExactAtExtremeExponents) {
    testing::Random r(2);
    for (int i = 0; i < 20000; ++i) {
        const Vec3 a = scaled(r, 1000, 1000), b = scaled(r, 1000, 1000);
        const Vec3 c = i % 2 ? a + b : scaled(r, 1000, 1000);
        ASSERT_EQ(to_int(det_sign(a, b, c)), exact_det(a, b, c)) << i;
    }
    const Vec3 tiny(0x1p-1070, 0, 0), huge(0, 0x1p1000, 0), mid(0, 0, 1);
    EXPECT_EQ(det_sign(tiny, huge, mid), Sign::Positive);
    EXPECT_EQ(det_sign(huge, tiny, mid), Sign::Negative);
}

// Each coordinate at its own scale, from denormal to 2^1000, some zero: the inline filter
// must not trust a product that fell below the normal range (fuzz_cone found one).
Vec3 mixed(testing::Random& r) {
    Vec3 v;
    for (int k = 0; k < 3; ++k) {
        const int kind = r.integer(0, 5);
        v[k] = kind == 0 ? 0.0 : kind == 1 ? r.uniform(-1, 1) * 0x1p-1040 : std::ldexp(r.uniform(-1, 1), r.integer(-1000, 1000));
    }
    return v;
}

TEST(Predicates, DeterminantSignIsExactWithMixedExponentsAndDenormals) {
    testing::Random r(4);
    int zero = 0;
    for (int i = 0; i < 100000; ++i) {
        const Vec3 a = mixed(r), b = mixed(r);
        const Vec3 c = i % 3 == 0 ? a : (i % 3 == 1 ? b : mixed(r));
        const int expected = exact_det(a, b, c);
        zero += expected == 0;
        ASSERT_EQ(to_int(det_sign(a, b, c)), expected) << i << ": " << a.transpose() << " | " << b.transpose() << " | " << c.transpose();
        ASSERT_EQ(to_int(det_sign(c, a, b)), expected) << i;
        ASSERT_EQ(to_int(dot_sign(a, c)), exact_dot(a, c)) << i;
    }
    EXPECT_GT(zero, 60000);
    // The case fuzz_cone found: a repeated vector, so the determinant is exactly zero.
    const Vec3 g0(1.000000000014552, 0.0, 2.27e-322), g1(2.635549485807631e-82, -3.152794309511059e+231, 3.1e-322);
    EXPECT_EQ(det_sign(g1, g0, g1), Sign::Zero);
}

TEST(Predicates, DotSignIsExact) {
    testing::Random r(3);
    for (int i = 0; i < 100000; ++i) {
        const Vec3 a = scaled(r, 600, 600);
        Vec3 b = scaled(r, 600, 600);
        if (i % 2) {  // make a . b nearly zero: b orthogonalised in floating point
            b = b - (a.dot(b) / a.squaredNorm()) * a;
        }
        if (!a.allFinite() || !b.allFinite()) continue;
        ASSERT_EQ(to_int(dot_sign(a, b)), exact_dot(a, b)) << i;
    }
}

// Consecutive points of a circle of 10^6 (seen as generators (cos t, sin t, 1)), rounded: the sign
// of each triple's determinant against GMP. Those determinants, near 1e-16 and below the filter's bound,
// are decided by the filter on the accurate cross product of the last two (src/core/predicates.cpp),
// not by expansions: fails without that stage (all 20,000 then take expansions).
TEST(Predicates, NearlyCollinearTriplesAreDecidedBeforeTheExpansions) {
    predicate_stats() = {};
    const int n = 1000000;
    int undecided_by_the_filter = 0;
    for (int i = 0; i < 20000; ++i) {
        const auto point = [&](int k) {
            const double t = 6.283185307179586 * static_cast<double>(k) / n;
            return Vec3(std::cos(t), std::sin(t), 1.0);
        };
        const Vec3 a = point(50 * i), b = point(50 * i + 1), c = point(50 * i + 2);
        Sign s = Sign::Zero;
        undecided_by_the_filter += !filter_sign(Det{}, s, approximate(a), approximate(b), approximate(c));
        ASSERT_EQ(to_int(det_sign(a, b, c)), exact_det(a, b, c)) << i;
    }
    EXPECT_GT(undecided_by_the_filter, 15000);  // (the first filter decides few of them)
    EXPECT_LT(predicate_stats().expansion, 200);
}

// Nearly parallel pairs (b a rounded multiple of a, some moved by an ulp) at every scale: each
// 2x2 minor against GMP.
TEST(Predicates, MinorSignIsExactNearParallel) {
    testing::Random r(5);
    int zero = 0;
    for (int i = 0; i < 100000; ++i) {
        const Vec3 a = scaled(r, 600, 600);
        Vec3 b = std::ldexp(r.uniform(-2, 2), r.integer(-300, 300)) * a;
        if (i % 3 == 0) {
            const int t = r.integer(0, 2);
            b[t] = std::nextafter(b[t], 1e300);
        }
        if (i % 5 == 0) b = std::ldexp(1.0, r.integer(-300, 300)) * a;  // exactly parallel
        if (!b.allFinite()) continue;
        const int k = r.integer(0, 2), l = (k + r.integer(1, 2)) % 3;
        const mpq_class m = mpq_class(a[k]) * mpq_class(b[l]) - mpq_class(a[l]) * mpq_class(b[k]);
        zero += sgn(m) == 0;
        ASSERT_EQ(to_int(minor_sign(a, b, k, l)), sgn(m)) << i;
    }
    EXPECT_GT(zero, 10000);
}

// Integers beyond the 128-bit stage's 2^40 (up to 2^52), exactly and nearly coplanar: the
// expansions decide them. Fails when that stage takes integers up to 2^52 (products overflow).
TEST(Predicates, LargeIntegersAreExact) {
    testing::Random r(6);
    int zero = 0;
    for (int i = 0; i < 20000; ++i) {
        const auto big = [&] { return std::ldexp(std::floor(r.uniform(-1, 1) * 0x1p20), r.integer(20, 31)) + r.integer(-99, 99); };
        const Vec3 a(big(), big(), big()), b(big(), big(), big());
        Vec3 c = a + b;  // (exact: below 2^53)
        if (i % 2) c.z() += r.integer(-2, 2);
        const int expected = exact_det(a, b, c);
        zero += expected == 0;
        ASSERT_EQ(to_int(det_sign(a, b, c)), expected) << i;
    }
    EXPECT_GT(zero, 10000);
}

// Exactly and nearly coplanar triples whose coordinates lie near the ends of the expansions'
// range (2^-250 .. 2^250) and beyond them: decided by expansions inside, by Dyadic numbers
// outside. Fails when the expansions take coordinates down to 2^-400 (their error terms
// underflow).
TEST(Predicates, ExpansionsStayExactAtTheEndsOfTheirRange) {
    testing::Random r(7);
    predicate_stats() = {};
    for (int i = 0; i < 20000; ++i) {
        const int e = i % 2 ? r.integer(-400, -240) : r.integer(240, 330);
        const Vec3 a = std::ldexp(1.0, e) * r.vec3(1), b = std::ldexp(1.0, e + r.integer(-5, 5)) * r.vec3(1);
        Vec3 c = r.uniform(-2, 2) * a + b;
        if (i % 3 == 0) c = a + b;
        ASSERT_EQ(to_int(det_sign(a, b, c)), exact_det(a, b, c)) << i;
    }
    EXPECT_GT(predicate_stats().expansion, 1000);
    EXPECT_GT(predicate_stats().dyadic, 1000);
}

TEST(Predicates, ParallelIsExact) {
    const Vec3 a(3, 5, 7);
    EXPECT_TRUE(parallel(a, 0.25 * a));
    EXPECT_TRUE(parallel(a, -2.0 * a));
    EXPECT_TRUE(parallel(a, Vec3::Zero()));
    EXPECT_FALSE(parallel(a, Vec3(3, 5, std::nextafter(7.0, 8.0))));
    EXPECT_EQ(cross2_sign(Vec2(1e-300, 1), Vec2(1, 1e300)), Sign::Positive);  // 1 - 1 would round
    EXPECT_EQ(cross2_sign(Vec2(0.1, 0.3), Vec2(0.1, 0.3)), Sign::Zero);
}

}  // namespace
}  // namespace momentlab
