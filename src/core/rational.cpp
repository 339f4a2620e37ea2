#include "momentlab/core/rational.hpp"
#include "momentlab/core/rounding.hpp"
#include "decimal_limbs.hpp"
#include "powers_of_five.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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

// The finite double |x| != 0 as N 10^exponent with N an integer not divisible by 10, N in
// base-10^9 limbs, least significant first. With x = M 2^k (M odd), N is M 5^-k and the
// exponent k for k < 0 (M 5^-k is odd and not a multiple of 5 times 2: no trailing zero), and
// M 2^k without its trailing zeros for k >= 0; at most 767 digits, built by multiplying by
// 5^13 or 2^30 at a time (a limb times either, plus a carry, stays below 2^64).
struct DecimalLimbs {
    static constexpr std::uint64_t kBase = 1000000000;
    std::array<std::uint32_t, 90> limbs;
    std::size_t size = 0;
    std::int64_t exponent = 0;

    explicit DecimalLimbs(double x) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &x, sizeof bits);
        const auto biased = static_cast<int>((bits >> 52) & 0x7ff);
        std::uint64_t m = bits & ((std::uint64_t{1} << 52) - 1);
        if (biased != 0) m |= std::uint64_t{1} << 52;
        std::int64_t k = (biased != 0 ? biased : 1) - 1075;
        const int twos = std::countr_zero(m);
        m >>= twos;
        k += twos;
        for (; m != 0; m /= kBase) limbs[size++] = static_cast<std::uint32_t>(m % kBase);
        for (std::int64_t left = k >= 0 ? k : -k; left > 0;) {
            const std::int64_t step = std::min<std::int64_t>(left, k >= 0 ? 30 : 13);
            times(k >= 0 ? std::uint64_t{1} << step : detail::kPowersOfFive[static_cast<std::size_t>(step)]);
            left -= step;
        }
        exponent = k >= 0 ? 0 : k;
        if (k > 0) {  // an integer: its trailing zeros go to the exponent
            std::size_t zero_limbs = 0;
            while (limbs[zero_limbs] == 0) ++zero_limbs;
            std::copy(limbs.begin() + static_cast<std::ptrdiff_t>(zero_limbs), limbs.begin() + static_cast<std::ptrdiff_t>(size), limbs.begin());
            size -= zero_limbs;
            exponent += 9 * static_cast<std::int64_t>(zero_limbs);
            while (limbs[0] % 10 == 0) {
                std::uint64_t remainder = 0;
                for (std::size_t i = size; i-- > 0;) {
                    const std::uint64_t v = remainder * kBase + limbs[i];
                    limbs[i] = static_cast<std::uint32_t>(v / 10);
                    remainder = v % 10;
                }
                if (limbs[size - 1] == 0) --size;
                ++exponent;
            }
        }
    }
    // The number of decimal digits of N.
    [[nodiscard]] std::size_t digits() const {
        std::size_t n = 9 * (size - 1);
        for (std::uint32_t top = limbs[size - 1]; top != 0; top /= 10) ++n;
        return n;
    }

private:
    void times(std::uint64_t factor) {
        std::uint64_t carry = 0;
        for (std::size_t i = 0; i < size; ++i) {
            const std::uint64_t product = limbs[i] * factor + carry;
            limbs[i] = static_cast<std::uint32_t>(product % kBase);
            carry = product / kBase;
        }
        for (; carry != 0; carry /= kBase) limbs[size++] = static_cast<std::uint32_t>(carry % kBase);
    }
};

// k when the odd positive integer d is 5^k (log2 5^k = 2.3219... k: d's bit length tells k to
// within one), else none.
std::optional<std::int64_t> five_power(const Dyadic& d) {
    if (d.is_one()) return 0;
    if (d.sign() != Sign::Positive || d.binary_exponent() != 0) return std::nullopt;
    const double estimate = static_cast<double>(d.exponent()) / std::log2(5.0);
    for (std::int64_t k = std::max<std::int64_t>(1, static_cast<std::int64_t>(estimate)); k <= static_cast<std::int64_t>(estimate) + 1; ++k) {
        if (power(Dyadic::from_integer(5), k) == d) return k;
    }
    return std::nullopt;
}

// The odd integer x as a 64-bit word, when it is one.
std::optional<std::uint64_t> word(const Dyadic& x) {
    const auto limbs = x.limbs();
    if (x.binary_exponent() != 0 || limbs.size() != 1) return std::nullopt;
    return limbs[0];
}

Dyadic of_word(std::uint64_t odd) { return Dyadic::from_limbs(Sign::Positive, std::span<const Dyadic::Limb>(&odd, 1), 0); }

}  // namespace

Rational Rational::quotient(Dyadic num, Dyadic den) {
    if (den.is_zero()) throw std::invalid_argument("Rational::quotient: division by zero");
    if (den.sign() == Sign::Negative) num = -num, den = -den;
    const std::int64_t twos = den.binary_exponent();  // den = an odd integer times 2^twos
    return Rational(num.scaled(-twos), den.scaled(-twos));
}

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
    __extension__ typedef unsigned __int128 U;
    if (!std::isfinite(value)) return false;
    const char* p = text.data();
    const char* const end = p + text.size();
    bool negative = false;
    if (p < end && (*p == '-' || *p == '+')) negative = *p++ == '-';
    const auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
    // The text is [int].[frac][e exp]: first the spans, then the significant digits D (at most
    // 38: below 10^38 < 2^127) without leading or trailing zeros, and the exponent e: D 10^e.
    const char* const int_begin = p;
    while (p < end && is_digit(*p)) ++p;
    const char* const int_end = p;
    const char* frac_begin = p;
    const char* frac_end = p;
    if (p < end && *p == '.') {
        frac_begin = ++p;
        while (p < end && is_digit(*p)) ++p;
        frac_end = p;
    }
    if (int_begin == int_end && frac_begin == frac_end) return false;  // no digit
    std::int64_t e = 0;
    if (p < end && (*p == 'e' || *p == 'E')) {
        ++p;
        bool minus = false;
        if (p < end && (*p == '-' || *p == '+')) minus = *p++ == '-';
        if (p == end) return false;
        std::int64_t x = 0;
        for (; p < end && is_digit(*p); ++p) {
            if (x > 100000) return false;
            x = x * 10 + (*p - '0');
        }
        e = minus ? -x : x;
    }
    if (p != end) return false;
    // Leading zeros of the integer part, trailing zeros of the fraction; with no integer digits
    // left, the fraction's leading zeros too, and with no fraction digits, the integer's trailing
    // zeros (each moving e).
    const char* a = int_begin;
    while (a < int_end && *a == '0') ++a;
    const char* f = frac_end;
    while (f > frac_begin && f[-1] == '0') --f;
    e -= f - frac_begin;
    const char* b = int_end;
    const char* c = frac_begin;
    if (a == int_end) {
        while (c < f && *c == '0') ++c;
    }
    if (c == f) {
        while (b > a && b[-1] == '0') --b;
        e += int_end - b;
    }
    if ((b - a) + (f - c) > 38) {
        // Longer: against the double's own exact digits. A double's exact text has at most 767
        // significant digits; beyond, the text is not one.
        // Compared limb by limb, without writing the double's digits.
        if ((b - a) + (f - c) > 800 || value == 0.0 || (value < 0.0) != negative) return false;
        const DecimalLimbs exact(value);
        const auto whole = static_cast<std::size_t>(b - a);
        const std::size_t length = whole + static_cast<std::size_t>(f - c);
        if (exact.exponent != e || exact.digits() != length) return false;
        char text_digits[800];
        std::memcpy(text_digits, a, whole);
        std::memcpy(text_digits + whole, c, length - whole);
        std::array<std::uint32_t, 90> limbs;
        const std::size_t size = detail::limbs_of_digits(text_digits, length, limbs.data());
        return size == exact.size && std::equal(limbs.begin(), limbs.begin() + static_cast<std::ptrdiff_t>(size), exact.limbs.begin());
    }
    U digits = 0;
    std::uint64_t chunk = 0;  // fewer than 19 digits, folded into D when full
    int in_chunk = 0;
    std::uint64_t scale = 1;
    const auto add = [&](const char* from, const char* to) {
        for (; from < to; ++from) {
            chunk = chunk * 10 + static_cast<unsigned>(*from - '0');
            scale *= 10;
            if (++in_chunk == 19) digits = digits * scale + chunk, chunk = 0, in_chunk = 0, scale = 1;
        }
    };
    add(a, b);
    add(c, f);
    digits = digits * scale + chunk;
    if (digits == 0) return value == 0.0;
    if (value == 0.0 || (value < 0.0) != negative) return false;
    // value = M 2^k with M odd; the text is D_odd 2^(t + e) 5^e with D = D_odd 2^t.
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);  // (std::bit_cast: not in the WebAssembly build's library)
    const auto biased = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t big_m = bits & ((std::uint64_t{1} << 52) - 1);  // (subnormal: no hidden bit)
    if (biased != 0) big_m |= std::uint64_t{1} << 52;
    int k = (biased != 0 ? biased : 1) - 1075;
    const int m_twos = std::countr_zero(big_m);
    big_m >>= m_twos;
    k += m_twos;
    const auto low = static_cast<std::uint64_t>(digits);
    const int t = low != 0 ? std::countr_zero(low) : 64 + std::countr_zero(static_cast<std::uint64_t>(digits >> 64));
    digits >>= t;
    if (static_cast<std::int64_t>(t) + e != k) return false;
    // D_odd 5^e = M: for e >= 0, D_odd 5^e reaches M; for e < 0, M 5^-e reaches D_odd (in steps
    // of at most 5^27 < 2^63, each checked against its target first: nothing overflows).
    const std::int64_t fives = e >= 0 ? e : -e;
    if ((digits >> 64) == 0) {  // (most texts: 64-bit products, checked for overflow)
        std::uint64_t small = e >= 0 ? static_cast<std::uint64_t>(digits) : big_m;
        const std::uint64_t target = e >= 0 ? big_m : static_cast<std::uint64_t>(digits);
        for (std::int64_t left = fives; left > 0; left -= 27) {
            const std::uint64_t five = detail::kPowersOfFive[static_cast<std::size_t>(std::min<std::int64_t>(left, 27))];
            if (__builtin_mul_overflow(small, five, &small) || small > target) return false;
        }
        return small == target;
    }
    U small = e >= 0 ? digits : U(big_m);
    const U target = e >= 0 ? U(big_m) : digits;
    for (std::int64_t left = fives; left > 0; left -= 27) {
        const U five = detail::kPowersOfFive[static_cast<std::size_t>(std::min<std::int64_t>(left, 27))];
        if (small > target / five) return false;  // (then small 5^j > target)
        small *= five;
    }
    return small == target;
}

bool Rational::is_decimal(std::string_view text) {
    std::size_t at = 0;
    const auto digits = [&] {
        const std::size_t from = at;
        while (at < text.size() && text[at] >= '0' && text[at] <= '9') ++at;
        return at - from;
    };
    if (at < text.size() && (text[at] == '-' || text[at] == '+')) ++at;
    std::size_t mantissa = digits();
    if (at < text.size() && text[at] == '.') ++at, mantissa += digits();
    if (mantissa == 0) return false;
    if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
        ++at;
        if (at < text.size() && (text[at] == '-' || text[at] == '+')) ++at;
        if (digits() == 0) return false;
    }
    return at == text.size();
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
            // (held past 10^15, beyond any text's count of digits: the sum below keeps its sign
            // and passes the bound; 0e99999999 is 0)
            if (e < 1000000000000000) e = e * 10 + (text[at] - '0');
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
        const auto five_power = static_cast<std::int64_t>(detail::kPowersOfFive[static_cast<std::size_t>(exponent > 0 ? exponent : fives)]);
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
    // Decimals' denominators are powers of 5 (the odd part of 10^k): their least common multiple
    // is the largest, 5^K, and x = n / 5^k clears to n 5^(K - k).
    std::vector<std::int64_t> fives;
    fives.reserve(x.size());
    const Dyadic* last = nullptr;  // (runs of one denominator told once)
    for (const Rational& r : x) {
        if (last != nullptr && *last == r.den()) {
            fives.push_back(fives.back());
            continue;
        }
        const std::optional<std::int64_t> k = five_power(r.den());
        if (!k) break;
        fives.push_back(*k);
        last = &r.den();
    }
    if (fives.size() == x.size()) {
        const std::int64_t most = fives.empty() ? 0 : *std::max_element(fives.begin(), fives.end());
        std::vector<std::optional<Dyadic>> powers(static_cast<std::size_t>(most) + 1);
        const auto power_of_five = [&](std::int64_t k) -> const Dyadic& {
            std::optional<Dyadic>& p = powers[static_cast<std::size_t>(k)];
            if (!p) p = power(Dyadic::from_integer(5), k);
            return *p;
        };
        for (std::size_t i = 0; i < x.size(); ++i) out.push_back(x[i].num() * power_of_five(most - fives[i]));
        if (common) *common = power_of_five(most);
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
