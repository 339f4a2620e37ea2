// Exact quotients rounded once (core/rounding.hpp).
#include "momentlab/core/rounding.hpp"

#include <cassert>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "power_of_two.hpp"

namespace momentlab {
namespace {

Dyadic magnitude(const Dyadic& x) { return x.sign() == Sign::Negative ? -x : x; }

bool even(double c) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &c, sizeof bits);
    return (bits & 1U) == 0;
}

// 10^n, exactly.
Dyadic power_of_ten(std::int64_t n) {
    Dyadic result = Dyadic::from_integer(1), base = Dyadic::from_integer(10);
    for (; n > 0; n >>= 1, base = base * base) {
        if (n & 1) result = result * base;
    }
    return result;
}

// The sign of a / b - m 10^q / 2 for a, b > 0.
int compare_with_decimal(const Dyadic& a, const Dyadic& b, std::int64_t m, std::int64_t q) {
    const Dyadic twice = a.scaled(1), mb = Dyadic::from_integer(m) * b;
    return q < 0 ? compare(twice * power_of_ten(-q), mb) : compare(twice, mb * power_of_ten(q));
}

}  // namespace

double nearest_double(const Dyadic& num, const Dyadic& den) {
    assert(!den.is_zero());
    if (num.is_zero()) return 0.0;
    const bool negative = (num.sign() == Sign::Negative) != (den.sign() == Sign::Negative);
    const Dyadic a = magnitude(num), b = magnitude(den);
    // The quotient lies in [2^(e - 1), 2^(e + 1)).
    const std::int64_t e = a.exponent() - b.exponent();
    double c = 0.0;
    if (e > 1025) {
        c = INFINITY;
    } else if (e >= -1080) {
        c = detail::times_power_of_two(a.to_double_scaled(a.exponent()) / b.to_double_scaled(b.exponent()), e);
    }
    // a / b against m, the midpoint of c and a neighbour: compare(a, m b).
    const auto beyond = [&](const Dyadic& m) { return compare(a, m * b); };
    const Dyadic top = Dyadic(1.0).scaled(1024);  // the neighbour above DBL_MAX, for rounding
    while (true) {
        if (std::isinf(c)) {  // below the midpoint of DBL_MAX and 2^1024: DBL_MAX (a tie: infinity)
            if (beyond((Dyadic(DBL_MAX) + top).scaled(-1)) >= 0) break;
            c = DBL_MAX;
            continue;
        }
        const double up = std::nextafter(c, INFINITY);
        const int above = beyond((Dyadic(c) + (std::isinf(up) ? top : Dyadic(up))).scaled(-1));
        if (above > 0 || (above == 0 && !even(c))) {
            c = up;
            continue;
        }
        if (c > 0.0) {
            const double down = std::nextafter(c, 0.0);
            const int below = beyond((Dyadic(c) + Dyadic(down)).scaled(-1));
            if (below < 0 || (below == 0 && !even(c))) {
                c = down;
                continue;
            }
        }
        break;
    }
    return negative ? -c : c;
}

std::string significant_digits(const Dyadic& num, const Dyadic& den, int digits) {
    assert(digits >= 1 && digits <= 15);
    const double d = nearest_double(num, den);
    if (std::isinf(d)) return d > 0 ? "inf" : "-inf";
    if (num.is_zero()) return "0";
    const Dyadic a = magnitude(num), b = magnitude(den);
    // printf's digits of |d|: K 10^q with K of `digits` digits (d may be 0 for a tiny quotient).
    char text[64];
    std::snprintf(text, sizeof text, "%.*e", digits - 1, std::fabs(d) > 0 ? std::fabs(d) : DBL_TRUE_MIN);
    char* exponent_at = std::strchr(text, 'e');
    std::int64_t k = 0;
    for (const char* p = text; p < exponent_at; ++p) {
        if (*p >= '0' && *p <= '9') k = 10 * k + (*p - '0');
    }
    std::int64_t q = std::strtoll(exponent_at + 1, nullptr, 10) - (digits - 1);
    std::int64_t smallest = 1;  // 10^(digits - 1)
    for (int i = 1; i < digits; ++i) smallest *= 10;
    const std::int64_t largest = 10 * smallest - 1;
    while (true) {
        const int above = compare_with_decimal(a, b, 2 * k + 1, q);
        if (above > 0 || (above == 0 && k % 2 != 0)) {
            if (++k > largest) k = smallest, ++q;
            continue;
        }
        // The decimal below k 10^q: (k - 1) 10^q, or largest 10^(q - 1) when k is the smallest.
        const int below = k == smallest ? compare_with_decimal(a, b, 2 * largest + 1, q - 1)
                                        : compare_with_decimal(a, b, 2 * k - 1, q);
        if (below < 0 || (below == 0 && k % 2 != 0)) {
            if (k == smallest) {
                k = largest, --q;
            } else {
                --k;
            }
            continue;
        }
        break;
    }
    // Written by printf from the double nearest to k 10^q, which has the same digits.
    std::snprintf(text, sizeof text, "%llde%lld", static_cast<long long>(k), static_cast<long long>(q));
    const double decimal = std::strtod(text, nullptr);
    const bool negative = (num.sign() == Sign::Negative) != (den.sign() == Sign::Negative);
    std::snprintf(text, sizeof text, "%.*g", digits, negative ? -decimal : decimal);
    return text;
}

}  // namespace momentlab
