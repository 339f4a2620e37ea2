#include "momentlab/core/rational.hpp"
#include "momentlab/core/rounding.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace momentlab {
namespace {

constexpr std::int64_t kMaxDecimalExponent = 100000;


// The integer spelled by decimal digits, exactly (18 digits at a time).
Dyadic integer_of(std::string_view digits) {
    Dyadic out;
    for (std::size_t at = 0; at < digits.size(); at += 18) {
        const std::string_view chunk = digits.substr(at, 18);
        std::int64_t value = 0, scale = 1;
        for (const char c : chunk) {
            value = value * 10 + (c - '0');
            scale *= 10;
        }
        out = out * Dyadic::from_integer(scale) + Dyadic::from_integer(value);
    }
    return out;
}

Dyadic power(Dyadic base, std::int64_t k) {
    Dyadic out = Dyadic::from_integer(1);
    for (; k > 0; k >>= 1) {
        if (k & 1) out = out * base;
        if (k > 1) base = base * base;
    }
    return out;
}

// The odd integer x as a 64-bit word, when it is one.
std::optional<std::uint64_t> word(const Dyadic& x) {
    const auto limbs = x.limbs();
    if (x.binary_exponent() != 0 || limbs.size() != 1) return std::nullopt;
    return limbs[0];
}

Dyadic of_word(std::uint64_t odd) { return Dyadic::from_limbs(Sign::Positive, std::span<const Dyadic::Limb>(&odd, 1), 0); }

}  // namespace

Rational::Rational(Dyadic num, const Dyadic& den) {
    if (den.sign() != Sign::Positive || den.binary_exponent() < 0) {
        throw std::invalid_argument("Rational: the denominator must be a positive integer");
    }
    // Its powers of two move to the numerator: the denominator is odd.
    const std::int64_t twos = den.binary_exponent();
    num_ = num.scaled(-twos);
    den_ = den.scaled(-twos);
}

bool Rational::spells(std::string_view text, double value) {
    using U = unsigned __int128;
    if (!std::isfinite(value)) return false;
    std::size_t at = 0;
    bool negative = false;
    if (at < text.size() && (text[at] == '-' || text[at] == '+')) negative = text[at++] == '-';
    // The significant digits as an integer D (at most 38: below 10^38 < 2^127) and the decimal
    // exponent e: the text is D 10^e.
    U digits = 0;
    int count = 0;
    std::int64_t e = 0;
    bool any = false, point = false;
    for (; at < text.size(); ++at) {
        const char c = text[at];
        if (c == '.' && !point) {
            point = true;
            continue;
        }
        if (c < '0' || c > '9') break;
        any = true;
        if (digits == 0 && c == '0') {
            if (point) --e;  // a leading zero after the point
            continue;
        }
        if (++count > 38) return false;
        digits = digits * 10 + static_cast<unsigned>(c - '0');
        if (point) --e;
    }
    if (!any) return false;
    if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
        ++at;
        bool minus = false;
        if (at < text.size() && (text[at] == '-' || text[at] == '+')) minus = text[at++] == '-';
        if (at == text.size()) return false;
        std::int64_t x = 0;
        for (; at < text.size() && text[at] >= '0' && text[at] <= '9'; ++at) {
            if (x > 100000) return false;
            x = x * 10 + (text[at] - '0');
        }
        e += minus ? -x : x;
    }
    if (at != text.size()) return false;
    if (digits == 0) return value == 0.0;
    if (value == 0.0 || (value < 0.0) != negative) return false;
    // value = M 2^b with M odd; the text is D_odd 2^(a + e) 5^e with D = D_odd 2^a.
    int b = 0;
    const double m = std::frexp(std::fabs(value), &b);  // |value| = m 2^b, m in [0.5, 1)
    auto big_m = static_cast<std::uint64_t>(std::ldexp(m, 64));  // exact: m has at most 53 bits
    b -= 64;
    while ((big_m & 1u) == 0) big_m >>= 1, ++b;
    while (digits % 10 == 0) digits /= 10, ++e;
    int a = 0;
    while ((digits & 1u) == 0) digits >>= 1, ++a;
    if (static_cast<std::int64_t>(a) + e != b) return false;
    // D_odd 5^e = M: for e >= 0, M / 5^e = D_odd; for e < 0, D_odd / 5^-e = M.
    U left = digits, right = big_m;
    for (std::int64_t k = 0; k < (e >= 0 ? e : -e); ++k) {
        U& divided = e >= 0 ? right : left;
        if (divided % 5 != 0) return false;
        divided /= 5;
    }
    return left == right;
}

std::optional<Rational> Rational::parse(std::string_view text) {
    std::size_t at = 0;
    bool negative = false;
    if (at < text.size() && (text[at] == '-' || text[at] == '+')) negative = text[at++] == '-';
    std::string digits;
    std::int64_t exponent = 0;
    bool any = false;
    for (; at < text.size() && text[at] >= '0' && text[at] <= '9'; ++at) digits += text[at], any = true;
    if (at < text.size() && text[at] == '.') {
        for (++at; at < text.size() && text[at] >= '0' && text[at] <= '9'; ++at) digits += text[at], --exponent, any = true;
    }
    if (!any) return std::nullopt;
    if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
        ++at;
        bool minus = false;
        if (at < text.size() && (text[at] == '-' || text[at] == '+')) minus = text[at++] == '-';
        if (at == text.size()) return std::nullopt;
        std::int64_t e = 0;
        for (; at < text.size() && text[at] >= '0' && text[at] <= '9'; ++at) {
            if (e > kMaxDecimalExponent) return std::nullopt;
            e = e * 10 + (text[at] - '0');
        }
        exponent += minus ? -e : e;
    }
    if (at != text.size()) return std::nullopt;
    // digits x 10^exponent, without leading or trailing zeros.
    const std::size_t first = digits.find_first_not_of('0');
    if (first == std::string::npos) return Rational();
    digits.erase(0, first);
    while (digits.back() == '0') digits.pop_back(), ++exponent;
    if (exponent > kMaxDecimalExponent || exponent < -kMaxDecimalExponent - static_cast<std::int64_t>(digits.size())) {
        return std::nullopt;
    }
    std::int64_t fives = exponent < 0 ? -exponent : 0;
    // Up to 18 digits and 5^27 (every double's shortest text, most decimals typed): in 64-bit
    // integers. D x 10^e = D 2^e 5^e; for e < 0, each factor 5 of D cancels one of 5^-e.
    if (digits.size() <= 18 && exponent >= -27 && exponent <= 27) {
        std::int64_t d = 0;
        for (const char c : digits) d = d * 10 + (c - '0');
        while (fives > 0 && d % 5 == 0) d /= 5, --fives;
        std::int64_t five_power = 1;
        for (std::int64_t k = 0; k < (exponent > 0 ? exponent : fives); ++k) five_power *= 5;
        Dyadic num = Dyadic::from_integer(negative ? -d : d).scaled(exponent);
        if (exponent > 0) num = num * Dyadic::from_integer(five_power);
        Rational out;
        out.num_ = std::move(num);
        out.den_ = exponent > 0 ? Dyadic(1.0) : Dyadic::from_integer(five_power);
        return out;
    }
    // D x 10^-k = D 2^-k / 5^k; while D is a multiple of 5 (its last digit 5), D / 5 = 2 D / 10
    // takes one 5 from the denominator.
    while (fives > 0 && digits.back() == '5') {
        int carry = 0;
        for (std::size_t i = digits.size(); i-- > 0;) {
            const int d = 2 * (digits[i] - '0') + carry;
            digits[i] = static_cast<char>('0' + d % 10);
            carry = d / 10;
        }
        if (carry) digits.insert(digits.begin(), static_cast<char>('0' + carry));
        digits.pop_back();  // the 0 that 2 x (...5) ends in
        --fives;
    }
    Dyadic num = integer_of(digits).scaled(exponent);  // the 2^exponent of 10^exponent
    if (exponent > 0) num = num * power(Dyadic::from_integer(5), exponent);
    Rational out;
    out.num_ = negative ? -num : num;
    out.den_ = power(Dyadic::from_integer(5), fives);
    return out;
}

bool Rational::is_double() const { return den_ == Dyadic(1.0) && num_.fits_double(); }

double Rational::to_double() const { return nearest_double(num_, den_); }

Rational Rational::operator-() const {
    Rational out = *this;
    out.num_ = -num_;
    return out;
}

Rational operator+(const Rational& a, const Rational& b) {
    Rational out;
    if (a.den_ == b.den_) {
        out.num_ = a.num_ + b.num_;
        out.den_ = a.den_;
    } else {
        out.num_ = a.num_ * b.den_ + b.num_ * a.den_;
        out.den_ = a.den_ * b.den_;
    }
    return out;
}

Rational operator-(const Rational& a, const Rational& b) { return a + (-b); }

Rational operator*(const Rational& a, const Rational& b) {
    Rational out;
    out.num_ = a.num_ * b.num_;
    out.den_ = a.den_ * b.den_;
    return out;
}

int compare(const Rational& a, const Rational& b) {
    if (a.den_ == b.den_) return compare(a.num_, b.num_);
    return compare(a.num_ * b.den_, b.num_ * a.den_);
}

std::vector<Dyadic> clear_denominators(std::span<const Rational> x, Dyadic* common) {
    std::vector<Dyadic> out;
    out.reserve(x.size());
    // The least common multiple in 64 bits when the denominators are words and it fits.
    std::uint64_t lcm = 1;
    bool words = true;
    for (const Rational& r : x) {
        const std::optional<std::uint64_t> d = word(r.den());
        if (!d) {
            words = false;
            break;
        }
        const std::uint64_t step = *d / std::gcd(lcm, *d);
        if (step != 0 && lcm > std::numeric_limits<std::uint64_t>::max() / step) {
            words = false;
            break;
        }
        lcm *= step;
    }
    if (words) {
        for (const Rational& r : x) out.push_back(r.num() * of_word(lcm / *word(r.den())));
        if (common) *common = of_word(lcm);
        return out;
    }
    // Else the product of the distinct denominators.
    std::vector<const Dyadic*> distinct;
    for (const Rational& r : x) {
        bool seen = false;
        for (const Dyadic* d : distinct) seen = seen || *d == r.den();
        if (!seen) distinct.push_back(&r.den());
    }
    for (const Rational& r : x) {
        Dyadic v = r.num();
        for (const Dyadic* d : distinct) {
            if (!(*d == r.den())) v = v * *d;
        }
        out.push_back(std::move(v));
    }
    if (common) {
        Dyadic d = Dyadic::from_integer(1);
        for (const Dyadic* f : distinct) d = d * *f;
        *common = std::move(d);
    }
    return out;
}

Rational2 rational(const Vec2& v) { return {Rational(v.x()), Rational(v.y())}; }

Rational3 rational(const Vec3& v) { return {Rational(v.x()), Rational(v.y()), Rational(v.z())}; }

Vec2 to_double(const Rational2& v) { return Vec2(v[0].to_double(), v[1].to_double()); }

Vec3 to_double(const Rational3& v) { return Vec3(v[0].to_double(), v[1].to_double(), v[2].to_double()); }

bool is_double(std::span<const Rational> v) {
    for (const Rational& r : v) {
        if (!r.is_double()) return false;
    }
    return true;
}

}  // namespace momentlab
