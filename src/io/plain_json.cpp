// The plain reader: the JSON that programs write, read in one pass (docs/architecture.md,
// "The JSON reader"); anything else goes to the JSON library (json_read.cpp).
#include "json_read.hpp"
#include "../core/decimal_limbs.hpp"
#include "../core/power_of_two.hpp"
#include "../core/powers_of_five.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <vector>

namespace momentlab::json_read {

namespace {

// A reader of the plain JSON that programs write: ASCII strings without escapes and numbers
// that convert to finite doubles. It reads such a text in one pass over its characters with no
// copies (the library reads a character at a time through its input adapter and copies each
// token: bench/bench_io.cpp), and gives up on anything else, which the library then reads.
class PlainReader {
public:
    PlainReader(std::string_view text, Builder& b) : p_(text.data()), end_(text.data() + text.size()), b_(b) {}

    // Reads the text to the builder; false when the text is not plain JSON.
    bool document() {
        std::vector<bool> arrays;  // the open containers, innermost last: true for an array
        for (;;) {
            skip_space();
            if (p_ == end_) return false;
            if (*p_ == '{' || *p_ == '[') {
                const bool array = *p_++ == '[';
                array ? b_.start_array() : b_.start_object();
                if (next_is(array ? ']' : '}')) {
                    array ? b_.end_array() : b_.end_object();
                } else {
                    arrays.push_back(array);
                    if (!array && !member_key()) return false;
                    continue;  // its first value
                }
            } else if (!scalar()) {
                return false;
            }
            // After a value: a comma and the next value, or the ends of containers.
            for (;;) {
                skip_space();
                if (arrays.empty()) return p_ == end_;
                if (p_ == end_) return false;
                const bool array = arrays.back();
                if (*p_ == ',') {
                    ++p_;
                    if (!array && !member_key()) return false;
                    break;
                }
                if (*p_++ != (array ? ']' : '}')) return false;
                arrays.pop_back();
                array ? b_.end_array() : b_.end_object();
            }
        }
    }

private:
    static bool digit(char c) { return c >= '0' && c <= '9'; }

    void skip_space() {
        while (p_ != end_ && (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t')) ++p_;
    }

    // Whether the text continues with c (after white space); consumes it if so.
    bool next_is(char c) {
        skip_space();
        if (p_ == end_ || *p_ != c) return false;
        ++p_;
        return true;
    }

    // A member's key, then its colon (the key is an event before the colon is read, as the
    // library has it, so that both report a repeated key at the same place).
    bool member_key() {
        skip_space();
        std::string_view key;
        if (p_ == end_ || *p_ != '"' || !string(key)) return false;
        b_.key(key, Builder::Text::Lasting);
        return next_is(':');
    }

    bool scalar() {
        switch (*p_) {
            case '"': {
                std::string_view s;
                if (!string(s)) return false;
                b_.string(s, Builder::Text::Lasting);
                return true;
            }
            case 't': return literal("true") && (b_.boolean(true), true);
            case 'f': return literal("false") && (b_.boolean(false), true);
            case 'n': return literal("null") && (b_.null(), true);
            default: return number();
        }
    }

    // ASCII from the space to DEL between quotes, with no escape.
    bool string(std::string_view& out) {
        const char* start = ++p_;
        for (; p_ != end_; ++p_) {
            const auto c = static_cast<unsigned char>(*p_);
            if (c == '"') {
                out = std::string_view(start, static_cast<std::size_t>(p_++ - start));
                return true;
            }
            if (c < 0x20 || c == '\\' || c >= 0x80) return false;
        }
        return false;
    }

    bool literal(std::string_view word) {
        if (static_cast<std::size_t>(end_ - p_) < word.size() || std::string_view(p_, word.size()) != word) return false;
        p_ += word.size();
        return true;
    }

    // JSON's number grammar, and its value as the library gives it: an integer's (+0 for "-0"),
    // or the nearest double.
    bool number() {
        const char* const start = p_;
        const char* q = p_;
        const bool negative = *q == '-';
        if (negative) ++q;
        if (q == end_ || !digit(*q)) return false;
        // The digits as one integer w while they fit (at most 19), and the decimal exponent:
        // the text is w 10^e.
        std::uint64_t w = 0;
        std::int64_t digits = 0;
        // The digits beyond the 19th are only counted (a run of them skipped at once: the exact
        // expansions of doubles have hundreds).
        const auto take_all = [&] {
            for (; q != end_ && digits < 19 && digit(*q); ++q, ++digits) w = w * 10 + static_cast<std::uint64_t>(*q - '0');
            const char* const rest = q;
            q = end_of_digits(q, end_);
            digits += q - rest;
        };
        const char* const integer_begin = q;
        if (*q == '0') {
            ++q;
        } else {
            take_all();
        }
        const char* const integer_end = q;
        const char* fraction = q;
        std::int64_t e = 0;
        if (q != end_ && *q == '.') {
            fraction = ++q;
            if (digits == 0) {
                while (q != end_ && *q == '0') ++q;  // (leading zeros of 0.00x)
            }
            take_all();
            if (q == fraction) return false;
            e = -(q - fraction);
        }
        const char* const fraction_end = q;
        if (q != end_ && (*q == 'e' || *q == 'E')) {
            ++q;
            const bool minus = q != end_ && *q == '-';
            if (q != end_ && (*q == '+' || *q == '-')) ++q;
            const char* const exponent = q;
            std::int64_t x = 0;
            // (held once past 10^15: beyond any fraction's length, so e keeps its sign and stays
            // far outside the fast path's bounds)
            for (; q != end_ && digit(*q); ++q) x = x < 1000000000000000 ? x * 10 + (*q - '0') : x;
            if (q == exponent) return false;
            e += minus ? -x : x;
        }
        p_ = q;
        const std::string_view text(start, static_cast<std::size_t>(q - start));
        double x = 0.0;
        using S = JsonNumber::Spelling;
        S spelling = digits <= 19 ? spelled(w, e, x) : S::Unknown;
        if (spelling == S::Unknown && e < 0) {
            const std::string_view integer(integer_begin, static_cast<std::size_t>(integer_end - integer_begin));
            spelling = spelled_long(integer, std::string_view(fraction, static_cast<std::size_t>(fraction_end - fraction)), e, x);
        }
        if (spelling == S::Exact) {
            if (negative && !(x == 0.0 && q == integer_end)) x = -x;  // ("-0" is the integer 0)
        } else if (digits <= 19 && w <= (std::uint64_t{1} << 53) && e >= -22 && e <= 22) {
            // w and 10^|e| are doubles: one correctly rounded product or quotient is the nearest
            // double (Clinger, "How to read floating point numbers accurately", PLDI 1990).
            x = e >= 0 ? static_cast<double>(w) * kTens[static_cast<std::size_t>(e)]
                       : static_cast<double>(w) / kTens[static_cast<std::size_t>(-e)];
            if (negative) x = -x;
        } else {
#if defined(__cpp_lib_to_chars)
            const auto [end, error] = std::from_chars(start, q, x);
            if (error != std::errc() || end != q || !std::isfinite(x)) return false;
#else
            return false;  // no exact conversion without a locale: the library reads the text
#endif
        }
        b_.number(x, text, Builder::Text::Lasting, spelling);
        return true;
    }

    static constexpr std::array<double, 23> kTens = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                                      1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                                      1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

    // Whether w 10^e (w < 10^19) is a double, and then that double in x: w 10^e is
    // odd(w) 5^e 2^(e + twos(w)) for e >= 0, and for e < 0, when 5^-e divides w,
    // odd(w / 5^-e) 2^(e + twos(w / 5^-e)) (else it is no dyadic number); a double when the odd
    // factor is below 2^53 (the exponents here are far inside the doubles' range). Unknown for
    // |e| > 27 (then spelled_long, or for e > 27 Rational::spells where it is needed).
    static JsonNumber::Spelling spelled(std::uint64_t w, std::int64_t e, double& x) {
        using S = JsonNumber::Spelling;
        if (w == 0) return x = 0.0, S::Exact;
        if (e < -27 || e > 27) return S::Unknown;
        const std::uint64_t five = detail::kPowersOfFive[static_cast<std::size_t>(e >= 0 ? e : -e)];
        std::uint64_t odd = 0;
        int twos = 0;
        if (e >= 0) {
            twos = std::countr_zero(w);
            if (__builtin_mul_overflow(w >> twos, five, &odd)) return S::Inexact;
            twos += static_cast<int>(e);
        } else {
            if (w % five != 0) return S::Inexact;
            const std::uint64_t m = w / five;
            twos = std::countr_zero(m);
            odd = m >> twos;
            twos += static_cast<int>(e);
        }
        if (odd >= (std::uint64_t{1} << 53)) return S::Inexact;
        // odd 2^twos, exactly (odd < 2^53; 2^twos a normal double: |twos| < 100).
        const std::uint64_t power_bits = static_cast<std::uint64_t>(1023 + twos) << 52;
        double power = 0.0;
        std::memcpy(&power, &power_bits, sizeof power);
        x = static_cast<double>(odd) * power;
        return S::Exact;
    }

    // spelled() for a text of any length whose digits are those of `integer` then `fraction`
    // and whose value is digits 10^e, e < 0: a double when 5^-e divides the digits D and
    // D / 5^-e = odd 2^twos with odd < 2^53 and odd 2^(twos + e) in the doubles' range (then that
    // double in x). D is taken in base-10^9 limbs and divided by 5^13 at a time, each remainder
    // 0 or the text no dyadic number; a double's exact text has at most 767 significant digits.
    // Unknown for a quotient of 128 bits or more (Rational::spells decides those).
    static JsonNumber::Spelling spelled_long(std::string_view integer, std::string_view fraction, std::int64_t e, double& x) {
        using S = JsonNumber::Spelling;
        constexpr std::uint64_t kBase = 1000000000;
        // The significant digits: without leading zeros, and trailing zeros moved to e.
        std::string_view first = integer, second = fraction;
        while (!first.empty() && first.front() == '0') first.remove_prefix(1);
        if (first.empty()) {
            while (!second.empty() && second.front() == '0') second.remove_prefix(1);
        }
        while (!second.empty() && second.back() == '0') second.remove_suffix(1), ++e;
        if (second.empty()) {
            while (!first.empty() && first.back() == '0') first.remove_suffix(1), ++e;
        }
        const std::size_t length = first.size() + second.size();
        if (length == 0) return x = 0.0, S::Exact;
        if (length > 767) return S::Inexact;
        if (e >= 0) return S::Unknown;
        // (one run of digits as it stands in the text unless the point splits it)
        char text[767];
        const char* run = first.empty() ? second.data() : second.empty() ? first.data() : text;
        if (run == text) {
            std::memcpy(text, first.data(), first.size());
            std::memcpy(text + first.size(), second.data(), second.size());
        }
        std::array<std::uint32_t, 86> limbs;  // D, least significant first
        std::size_t size = detail::limbs_of_digits(run, length, limbs.data());
        for (std::int64_t fives = -e; fives > 0;) {
            const std::int64_t step = fives < 13 ? fives : 13;
            const std::uint64_t divisor = detail::kPowersOfFive[static_cast<std::size_t>(step)];
            std::uint64_t remainder = 0;
            for (std::size_t i = size; i-- > 0;) {
                const std::uint64_t current = remainder * kBase + limbs[i];  // < 5^13 10^9 < 2^61
                limbs[i] = static_cast<std::uint32_t>(current / divisor);
                remainder = current % divisor;
            }
            if (remainder != 0) return S::Inexact;
            while (size > 0 && limbs[size - 1] == 0) --size;
            fives -= step;
        }
        __extension__ typedef unsigned __int128 U;
        U quotient = 0;
        constexpr U kRoom = ~U{0} / kBase - 1;  // quotient * 10^9 + a limb stays below 2^128
        for (std::size_t i = size; i-- > 0;) {
            if (quotient > kRoom) return S::Unknown;
            quotient = quotient * kBase + limbs[i];
        }
        const int twos = quotient == 0 ? 0 : (static_cast<std::uint64_t>(quotient) != 0 ? std::countr_zero(static_cast<std::uint64_t>(quotient))
                                                                                       : 64 + std::countr_zero(static_cast<std::uint64_t>(quotient >> 64)));
        const U odd = quotient >> twos;
        if (odd >= (U{1} << 53)) return S::Inexact;
        // odd 2^(twos + e) when it is a double: one exact product when it is a normal double;
        // else ldexp, exact then, and only then giving back odd.
        const std::int64_t power = twos + e;
        if (power < -1200 || power > 1100) return S::Inexact;
        const std::int64_t top = power + static_cast<std::int64_t>(std::bit_width(static_cast<std::uint64_t>(odd))) - 1;
        if (top >= -1022 && top <= 1023) return x = detail::times_power_of_two(static_cast<double>(odd), power), S::Exact;
        x = std::ldexp(static_cast<double>(odd), static_cast<int>(power));
        if (!std::isfinite(x) || std::ldexp(x, static_cast<int>(-power)) != static_cast<double>(odd)) return S::Inexact;
        return S::Exact;
    }

    const char* p_;
    const char* end_;
    Builder& b_;
};

}  // namespace

// Each byte '0'..'9' when its high nibble is 3 and stays 3 with 6 added (a carry into a byte
// comes only from a byte of high nibble F, which fails itself); eight at a time, then one by one.
const char* end_of_digits(const char* p, const char* end) {
    constexpr std::uint64_t kHigh = 0xF0F0F0F0F0F0F0F0, kSix = 0x0606060606060606, kThrees = 0x3333333333333333;
    while (end - p >= 8) {
        std::uint64_t v = 0;
        std::memcpy(&v, p, sizeof v);
        if (((v & kHigh) | (((v + kSix) & kHigh) >> 4)) != kThrees) break;
        p += 8;
    }
    while (p != end && *p >= '0' && *p <= '9') ++p;
    return p;
}

std::optional<Document> read_plain(std::string_view text, const Schema& schema) {
    Builder b(schema, text);
    if (!PlainReader(text, b).document()) return std::nullopt;
    return b.finish();
}

}  // namespace momentlab::json_read
