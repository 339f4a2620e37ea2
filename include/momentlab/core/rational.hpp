#pragma once

/// \file
/// Exact rational numbers: the value of a decimal as typed (0.1 is 1/10, 2.943 is 2943/1000)
/// or of a fraction given exactly (docs/design.md, "Numbers as typed").
///
/// momentlab decides nothing in rational arithmetic: every decision is the sign of a polynomial
/// homogeneous in each generator, so a generator built from rationals is multiplied by the
/// common denominator of its coordinates (clear_denominators) and the decision runs on Dyadic
/// numbers as for doubles. A Rational is num / den with a Dyadic numerator and an odd positive
/// integer denominator (powers of two live in the numerator): every double is x / 1.

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "momentlab/core/dyadic.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// An exact rational number num / den, den an odd positive integer (1 for every double).
class Rational {
public:
    /// Zero.
    Rational() : den_(1.0) {}
    /// The double x, exactly. Precondition: x is finite.
    explicit Rational(double x) : num_(x), den_(1.0) {}
    /// num / den for a positive integer den (std::invalid_argument otherwise).
    Rational(Dyadic num, const Dyadic& den);
    /// num / den for any den != 0 (either sign, an integer or not; std::invalid_argument for 0).
    static Rational quotient(Dyadic num, Dyadic den);
    /// The exact value of decimal text in JSON's number grammar, a leading '+', ".5" and "5."
    /// also allowed ("0.1" is 1/10, "-2.943e1" is -2943/100); nullopt for other text and for a
    /// non-zero number whose decimal exponent passes +-100000 (0 or infinite as a double).
    static std::optional<Rational> parse(std::string_view text);
    /// True when the text is in parse's grammar (a sign, digits with at most one point, an
    /// exponent), whatever its exponent: every front end's one number grammar (no hex, no
    /// "inf"); parse refuses beyond that only exponents whose number is 0 or infinite as a double.
    static bool is_decimal(std::string_view text);
    /// True when decimal text (as parse reads it) is exactly the finite double `value`, told
    /// without big numbers for up to 38 significant digits ("0.5", "1e3", the exact expansion
    /// "0.299999999813735485076904296875" of a dyadic double), against the double's own exact
    /// digits for longer texts (up to its longest exact expansion); false when it is not. A reader of
    /// doubles skips parse where this holds.
    static bool spells(std::string_view text, double value);

    [[nodiscard]] const Dyadic& num() const { return num_; }
    [[nodiscard]] const Dyadic& den() const { return den_; }
    [[nodiscard]] Sign sign() const { return num_.sign(); }
    [[nodiscard]] bool is_zero() const { return num_.is_zero(); }
    /// True when the value is exactly a finite double.
    [[nodiscard]] bool is_double() const { return den_.is_one() && num_.fits_double(); }
    /// The value correctly rounded to a double (to nearest, ties to even); +-inf beyond the range.
    [[nodiscard]] double to_double() const;

    [[nodiscard]] Rational operator-() const;
    friend Rational operator+(const Rational& a, const Rational& b);
    friend Rational operator-(const Rational& a, const Rational& b);
    friend Rational operator*(const Rational& a, const Rational& b);
    /// a / b for b != 0 (std::invalid_argument for 0).
    friend Rational operator/(const Rational& a, const Rational& b) { return quotient(a.num_ * b.den_, a.den_ * b.num_); }
    /// -1, 0 or +1 as a < b, a == b, a > b (exact).
    friend int compare(const Rational& a, const Rational& b);
    friend bool operator==(const Rational& a, const Rational& b) { return compare(a, b) == 0; }

private:
    Dyadic num_;
    Dyadic den_;
};

using Rational2 = std::array<Rational, 2>;
using Rational3 = std::array<Rational, 3>;

/// The values x_i times their least common denominator D > 0 (or a positive multiple of it when
/// the denominators pass 2^64), exactly: the same direction with Dyadic coordinates. `common`,
/// when given, receives D.
[[nodiscard]] std::vector<Dyadic> clear_denominators(std::span<const Rational> x, Dyadic* common = nullptr);

/// Each coordinate's exact value.
[[nodiscard]] Rational2 rational(const Vec2& v);
[[nodiscard]] Rational3 rational(const Vec3& v);
/// The coordinates correctly rounded.
[[nodiscard]] Vec2 to_double(const Rational2& v);
[[nodiscard]] Vec3 to_double(const Rational3& v);
/// True when every coordinate is exactly a double.
[[nodiscard]] bool is_double(std::span<const Rational> v);

}  // namespace momentlab
