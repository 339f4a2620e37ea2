// Rational (core/rational.hpp): decimal text read exactly, correct rounding, cleared
// denominators, against GMP rationals made from the text in the test and against strtod (the C
// library's correctly rounded reading of decimal text).
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "exact_scene.hpp"
#include "momentlab/core/rational.hpp"

namespace momentlab {
namespace {

using reference::Q;
using reference::to_q;

Q to_q(const Rational& r) { return to_q(r.num()) / to_q(r.den()); }

// The decimal's value by GMP: digits / 10^k, times 10^e.
Q decimal_q(bool negative, const std::string& digits, int k, int e) {
    Q out(mpz_class(digits, 10));
    mpz_class ten;
    mpz_ui_pow_ui(ten.get_mpz_t(), 10, static_cast<unsigned long>(k));
    out /= ten;
    mpz_ui_pow_ui(ten.get_mpz_t(), 10, static_cast<unsigned long>(std::abs(e)));
    if (e >= 0) out *= ten; else out /= ten;
    return negative ? Q(-out) : out;
}

TEST(Rational, ParsesDecimalsExactly) {
    EXPECT_EQ(to_q(*Rational::parse("0.1")), Q(1, 10));
    EXPECT_EQ(to_q(*Rational::parse("2.943")), Q(2943, 1000));
    EXPECT_EQ(to_q(*Rational::parse("1e-3")), Q(1, 1000));
    EXPECT_EQ(to_q(*Rational::parse("-4.905E+1")), Q(-981, 20));
    EXPECT_EQ(to_q(*Rational::parse("+0.5")), Q(1, 2));
    EXPECT_TRUE(Rational::parse("0.5")->is_double());
    EXPECT_FALSE(Rational::parse("0.1")->is_double());
    for (const char* bad : {"", "-", ".", "1e", "0x1p3", "inf", "nan", "1.2.3", "1e+", "1 "}) {
        EXPECT_FALSE(Rational::parse(bad).has_value()) << bad;
        EXPECT_FALSE(Rational::is_decimal(bad)) << bad;
    }
    // Zero with any exponent is 0; a non-zero number past +-100000 is not read (0 or infinite as
    // a double), though it is in the grammar.
    for (const char* zero : {"0e99999999", "0e-999999999", "-0.000e2147483647999"}) EXPECT_TRUE(Rational::parse(zero)->is_zero()) << zero;
    for (const char* beyond : {"1e-999999999", "1e999999999"}) {
        EXPECT_FALSE(Rational::parse(beyond).has_value()) << beyond;
        EXPECT_TRUE(Rational::is_decimal(beyond)) << beyond;
    }
    std::mt19937_64 gen(46);
    for (int i = 0; i < 2000; ++i) {
        std::string digits;
        const int n = std::uniform_int_distribution<int>(1, 30)(gen);
        for (int j = 0; j < n; ++j) digits += static_cast<char>('0' + gen() % 10);
        const int k = std::uniform_int_distribution<int>(0, n)(gen), e = std::uniform_int_distribution<int>(-40, 40)(gen);
        const bool negative = gen() % 2 == 0;
        std::string text = (negative ? "-" : "") + digits.substr(0, static_cast<std::size_t>(n - k));
        if (n - k == 0) text += "0";
        if (k > 0) text += "." + digits.substr(static_cast<std::size_t>(n - k));
        text += "e" + std::to_string(e);
        const std::optional<Rational> r = Rational::parse(text);
        ASSERT_TRUE(r) << text;
        ASSERT_EQ(to_q(*r), decimal_q(negative, digits, k, e)) << text;
        // Correctly rounded, as strtod rounds the text.
        ASSERT_EQ(r->to_double(), std::strtod(text.c_str(), nullptr)) << text;
        // The denominator is odd (powers of two live in the numerator).
        ASSERT_TRUE(mpz_odd_p(to_q(r->den()).get_num_mpz_t())) << text;
    }
}

// Rational::spells (the readers' shortcut for text that is exactly a double) against GMP: the
// exact expansions of random doubles (glibc's printf writes them exactly), with trailing zeros,
// exponents and leading zeros, are the doubles; the same texts with a digit changed or appended,
// and random decimals, are not (GMP compares the text's value with the double).
// The exact decimal expansion of a double (glibc's printf writes every digit), without trailing
// zeros or point.
std::string exact_expansion(double d) {
    char buffer[1200];
    std::snprintf(buffer, sizeof buffer, "%.1100f", d);
    std::string text(buffer);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text;
}

TEST(Rational, SpellsExactlyTheDoublesItIsSaidTo) {
    std::mt19937_64 gen(146);
    int spelled = 0, not_spelled = 0;
    const auto check = [&](const std::string& text, double d) {
        const Q exact = to_q(*Rational::parse(text));
        const bool equal = exact == Q(d);
        const bool said = Rational::spells(text, d);
        // true only when equal; every equal text is told (at most 38 significant digits in
        // 128-bit integers, longer ones in Dyadic numbers)
        if (said) ASSERT_TRUE(equal) << text << " " << d;
        if (equal) ASSERT_TRUE(said) << text;
        (said ? spelled : not_spelled)++;
    };
    for (int i = 0; i < 4000; ++i) {
        // A dyadic double with up to 30 bits after the point, or any double of a random magnitude.
        const double d = i % 2 == 0 ? std::ldexp(static_cast<double>(static_cast<std::int64_t>(gen() >> 11)) - 0x1p52, -static_cast<int>(gen() % 31) - 22)
                                    : std::ldexp(std::uniform_real_distribution<double>(-1, 1)(gen), static_cast<int>(gen() % 120) - 60);
        const std::string text = exact_expansion(d);
        check(text, d);
        check(text + "0", d);
        check("00" + text.substr(text[0] == '-' ? 1 : 0), std::fabs(d));
        if (text.find('.') != std::string::npos) {
            std::string changed = text;
            changed.back() = changed.back() == '9' ? '8' : static_cast<char>(changed.back() + 1);
            check(changed, d);
            check(text + "1", d);
            check(text + "e0", d);
            check(text + "e1", d);  // ten times the text: not d
        }
    }
    // The longest exact expansions: the smallest subnormal (751 significant digits) and the
    // largest double (309 digits, no point).
    for (const double d : {0x1p-1074, 0x1.fffffffffffffp1023, -0x1.8p-1070}) {
        const std::string text = exact_expansion(d);
        check(text, d);
        check(text + "1", d);
        check("0" + text.substr(text[0] == '-' ? 1 : 0) + "e-1", std::fabs(d) / 10);  // d / 10 is not a double: false
    }
    // Short dyadic numbers (at most 19 significant digits: the 64-bit path), as users type them.
    for (int i = 0; i < 2000; ++i) {
        const double d = std::ldexp(static_cast<double>(static_cast<std::int64_t>(gen() % (1u << 20)) - (1 << 19)), -static_cast<int>(gen() % 21));
        const std::string text = exact_expansion(d);
        check(text, d);
        check(text + "1", d);
        check(text + "e2", d);
        check(text + "e2", d * 100.0);  // exact when d 100 is a double; GMP tells
    }
    for (const auto& [text, d] : std::vector<std::pair<std::string, double>>{
             {"0.1", 0.1}, {"0.5", 0.5}, {"1e3", 1000.0}, {"-2.5E-1", -0.25}, {"+8", 8.0}, {"0", 0.0}, {"-0.0", 0.0},
             {".5", 0.5}, {"5.", 5.0}, {"0.299999999813735485076904296875", 0x1.3333333p-2}, {"1e-400", 0.0},
             {"100.25", 100.25}, {"1200", 1200.0}, {"120e-1", 12.0}, {"0.000", 0.0}, {"2000.5000", 2000.5}, {"1200.001", 1200.001}}) {
        check(text, d);
    }
    EXPECT_GT(spelled, 4000);
    EXPECT_GT(not_spelled, 4000);
}

TEST(Rational, RoundsRatiosToNearestTiesToEven) {
    // (2^53 + 1) / 1 ties between 2^53 and 2^53 + 2: to even, 2^53.
    const Rational tie(Dyadic::from_integer((std::int64_t{1} << 53) + 1), Dyadic(1.0));
    EXPECT_EQ(tie.to_double(), 0x1p53);
    const Rational tie_up(Dyadic::from_integer((std::int64_t{1} << 53) + 3), Dyadic(1.0));
    EXPECT_EQ(tie_up.to_double(), 0x1p53 + 4.0);
    EXPECT_EQ(Rational(Dyadic(1.0), Dyadic(3.0)).to_double(), 1.0 / 3.0);  // division is correctly rounded
    EXPECT_EQ(Rational(Dyadic(-2.0), Dyadic(7.0)).to_double(), -2.0 / 7.0);
}

TEST(Rational, ClearsDenominatorsToTheSameDirection) {
    std::mt19937_64 gen(7);
    for (int i = 0; i < 500; ++i) {
        std::vector<Rational> x;
        for (int k = 0; k < 3; ++k) {
            const auto num = static_cast<std::int64_t>(gen() % 2001) - 1000;
            const auto den = static_cast<std::int64_t>(gen() % 999) + 1;
            x.emplace_back(Dyadic::from_integer(num), Dyadic::from_integer(den));
        }
        // Huge denominators: the product path.
        if (i % 5 == 0) x.emplace_back(Dyadic::from_integer(1), Dyadic(0x1p80) * Dyadic(3.0) + Dyadic(1.0));
        Dyadic d;
        const std::vector<Dyadic> y = clear_denominators(x, &d);
        ASSERT_GT(to_q(d), 0);
        for (std::size_t k = 0; k < x.size(); ++k) {
            ASSERT_EQ(to_q(y[k]), to_q(x[k]) * to_q(d));
        }
    }
}

// Decimals of many lengths past 64-bit denominators (review-32: 500 vertices took minutes when
// the distinct denominators 5^k were multiplied): the common denominator is the least, 5^K for
// the longest decimal, and each value clears exactly (GMP).
TEST(Rational, DecimalsOfManyLengthsClearToTheirLeastCommonDenominator) {
    std::mt19937_64 gen(11);
    std::vector<Rational> x;
    int longest = 0;
    for (int i = 0; i < 400; ++i) {
        const int digits = 28 + static_cast<int>(gen() % 400);
        longest = std::max(longest, digits);
        std::string text = "0.";
        for (int k = 0; k + 1 < digits; ++k) text += static_cast<char>('0' + gen() % 10);
        text += static_cast<char>('1' + gen() % 9);  // (a last digit that is not 0: exactly `digits` places)
        x.push_back(*Rational::parse(text));
    }
    x.push_back(Rational(0.5));  // a double among them
    Dyadic d;
    const std::vector<Dyadic> y = clear_denominators(x, &d);
    Q five_to_longest = 1;
    for (int k = 0; k < longest; ++k) five_to_longest *= 5;
    EXPECT_EQ(to_q(d), five_to_longest);
    for (std::size_t k = 0; k < x.size(); ++k) ASSERT_EQ(to_q(y[k]), to_q(x[k]) * to_q(d));
}

}  // namespace
}  // namespace momentlab
