// Exact predicates against GMP rationals computed independently in the test.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>

#include "random_inputs.hpp"
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
