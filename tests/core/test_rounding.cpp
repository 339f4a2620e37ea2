// nearest_double and significant_digits against GMP rationals: the oracle truncates the exact
// quotient (mpq get_d), then picks the nearer of that double and its neighbour away from zero by
// exact comparison (ties to the even significand); digits come from the exact quotient scaled
// by a power of ten and rounded by integer division. Quotients of products of random doubles
// (about 160 bits), exact ties and their neighbours 2^-200 away, and values near the
// subnormal and overflow ends; Dyadic::to_double on numbers of many limbs.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <iostream>
#include <random>
#include <string>

#include "momentlab/core/rounding.hpp"

namespace momentlab {
namespace {

mpq_class rational(const Dyadic& d) {
    mpz_class m = 0;
    const auto limbs = d.limbs();
    for (std::size_t i = limbs.size(); i-- > 0;) {
        m <<= 64;
        m += mpz_class(static_cast<unsigned long>(limbs[i]));
    }
    mpq_class q(m);
    const long e = d.binary_exponent();
    if (e >= 0) {
        mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<unsigned long>(e));
    } else {
        mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<unsigned long>(-e));
    }
    return d.sign() == Sign::Negative ? mpq_class(-q) : q;
}

bool even(double c) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &c, sizeof bits);
    return (bits & 1U) == 0;
}

// The exact x rounded to nearest, ties to even (x within the normal and subnormal range).
double oracle_double(const mpq_class& x) {
    const double t = x.get_d();  // truncated towards zero
    const double away = std::nextafter(t, x > 0 ? INFINITY : -INFINITY);
    if (std::isinf(away)) return t;
    const mpq_class dt = abs(x - mpq_class(t)), da = abs(mpq_class(away) - x);
    if (dt < da) return t;
    if (da < dt) return away;
    return even(t) ? t : away;
}

std::string oracle_digits(const mpq_class& x, int digits) {
    if (x == 0) return "0";
    const mpq_class a = abs(x);
    long e = 0;  // 10^e <= a < 10^(e + 1)
    mpz_class ten = 10;
    auto power = [](long n) {
        mpq_class p = 1;
        for (long i = 0; i < std::labs(n); ++i) p *= 10;
        return n >= 0 ? p : mpq_class(1 / p);
    };
    while (a >= power(e + 1)) ++e;
    while (a < power(e)) --e;
    const mpq_class scaled = a / power(e - digits + 1);
    mpz_class k = scaled.get_num() / scaled.get_den();
    const mpz_class rest2 = 2 * (scaled.get_num() - k * scaled.get_den());
    if (rest2 > scaled.get_den() || (rest2 == scaled.get_den() && k % 2 != 0)) ++k;
    char text[64];
    const double value = std::strtod((k.get_str() + "e" + std::to_string(e - digits + 1)).c_str(), nullptr);
    std::snprintf(text, sizeof text, "%.*g", digits, x < 0 ? -value : value);
    return text;
}

TEST(Rounding, QuotientsAgreeWithRationals) {
    std::mt19937_64 rng(46);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto product = [&](int k, int scale) {
        Dyadic p(1.0);
        for (int i = 0; i < k; ++i) p = p * Dyadic(std::ldexp(unit(rng), static_cast<int>(rng() % (2 * scale + 1)) - scale));
        return p;
    };
    int ties = 0, subnormal = 0, checked = 0;
    for (int i = 0; i < 20000; ++i) {
        Dyadic num = product(1 + static_cast<int>(rng() % 3), i % 5 == 0 ? 300 : 8) + product(2, 8);
        Dyadic den = product(1 + static_cast<int>(rng() % 3), i % 5 == 0 ? 300 : 8);
        if (num.is_zero() || den.is_zero()) continue;
        if (i % 4 == 1) {  // an exact midpoint between two doubles, and 2^-200 either side
            const double c = std::ldexp(unit(rng), static_cast<int>(rng() % 40) - 20);
            const Dyadic mid = (Dyadic(c) + Dyadic(std::nextafter(c, INFINITY))).scaled(-1);
            const Dyadic tiny = Dyadic(1.0).scaled(-200) * Dyadic(static_cast<double>(static_cast<int>(i % 3) - 1));
            num = (mid + tiny) * den;
            ties += i % 3 == 1 ? 1 : 0;
        }
        if (i % 50 == 7) {  // the subnormal range
            num = Dyadic(unit(rng)).scaled(-1060 - static_cast<int>(rng() % 20)) * den + Dyadic(1.0).scaled(-1200);
            ++subnormal;
        }
        const mpq_class x = rational(num) / rational(den);
        ASSERT_EQ(nearest_double(num, den), oracle_double(x)) << i << ": " << num.to_string() << " / " << den.to_string();
        ASSERT_EQ(nearest_double(-num, den), -oracle_double(x)) << i;
        if (std::fabs(oracle_double(x)) >= DBL_MIN && std::fabs(oracle_double(x)) < 1e300) {
            for (const int digits : {6, 10}) {
                ASSERT_EQ(significant_digits(num, den, digits), oracle_digits(x, digits)) << i << " digits " << digits;
            }
        }
        ++checked;
    }
    std::cout << "[Rounding] " << checked << " quotients (" << ties << " exact ties, " << subnormal << " subnormal)\n";
    EXPECT_GE(ties, 1000);
}

// Decimal ties and their neighbours: 1.234565 (an exact tie at 6 digits: to even, 1.23456) and
// 2^-70 either side, whose nearest double is the same.
TEST(Rounding, DigitsAtDecimalMidpoints) {
    const Dyadic million = Dyadic::from_integer(1000000);
    for (const std::int64_t m : {1234565, 2943000'5 / 10, 9999995}) {
        const Dyadic tie = Dyadic::from_integer(m);
        for (const int side : {-1, 0, 1}) {
            const Dyadic num = tie + Dyadic(static_cast<double>(side)).scaled(-70) * million;
            const mpq_class x = rational(num) / rational(million);
            EXPECT_EQ(significant_digits(num, million, 6), oracle_digits(x, 6)) << m << " " << side;
        }
    }
    EXPECT_EQ(significant_digits(Dyadic::from_integer(1234565), million, 6), "1.23456");
    EXPECT_EQ(significant_digits(Dyadic::from_integer(9999995), million, 6), "10");
    EXPECT_EQ(significant_digits(Dyadic::from_integer(2943), Dyadic::from_integer(1000), 6), "2.943");
}

// The ends of the range: the largest double, the midpoint above it (a tie: infinity), and zero
// below half the smallest subnormal.
TEST(Rounding, EndsOfTheRange) {
    const Dyadic one(1.0), top = Dyadic(1.0).scaled(1024);
    EXPECT_EQ(nearest_double(Dyadic(DBL_MAX), one), DBL_MAX);
    const Dyadic above = (Dyadic(DBL_MAX) + top).scaled(-1);
    EXPECT_EQ(nearest_double(above - Dyadic(1.0), one), DBL_MAX);
    EXPECT_TRUE(std::isinf(nearest_double(above, one)));
    EXPECT_EQ(nearest_double(Dyadic(1.0).scaled(-1075), one), 0.0);
    EXPECT_EQ(nearest_double(Dyadic(1.0).scaled(-1075) + Dyadic(1.0).scaled(-1200), one), DBL_TRUE_MIN);
    EXPECT_EQ(nearest_double(Dyadic(3.0).scaled(-1076), one), DBL_TRUE_MIN);  // 1.5 x 2^-1075
}

// Dyadic::to_double rounds once: 1 + 2^-53 + 2^-200 (above the midpoint of 1 and its successor,
// by less than the 64 leading bits show) is the successor; 1 + 2^-53 alone is a tie, to 1.
TEST(Rounding, DyadicToDoubleRoundsOnce) {
    const Dyadic half_ulp = Dyadic(1.0).scaled(-53);
    EXPECT_EQ((Dyadic(1.0) + half_ulp + Dyadic(1.0).scaled(-200)).to_double(), std::nextafter(1.0, 2.0));
    EXPECT_EQ((Dyadic(1.0) + half_ulp).to_double(), 1.0);
    EXPECT_EQ((Dyadic(1.0) + half_ulp - Dyadic(1.0).scaled(-200)).to_double(), 1.0);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        Dyadic x = Dyadic(unit(rng)) * Dyadic(unit(rng)) * Dyadic(unit(rng)) + Dyadic(unit(rng)).scaled(-static_cast<int>(rng() % 300));
        if (i % 10 == 0) x = x.scaled(-1000 - static_cast<int>(rng() % 80));  // subnormal results
        if (x.is_zero()) continue;
        ASSERT_EQ(x.to_double(), oracle_double(rational(x))) << i << ": " << x.to_string();
    }
}

}  // namespace
}  // namespace momentlab
