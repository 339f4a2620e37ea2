#include "exact_number.hpp"

#include <cassert>
#include <cmath>

namespace momentlab::assembly_detail {

Rational exact_value(double x) {
    assert(std::isfinite(x));
    if (x == 0.0) return Rational(0);
    int e = 0;
    const double m = std::frexp(x, &e);  // x = m 2^e, 0.5 <= |m| < 1
    const auto mantissa = static_cast<std::int64_t>(std::ldexp(m, 53));  // exact: 53 bits
    return times_power_of_two(Rational(Integer(mantissa)), static_cast<std::int64_t>(e) - 53);
}

namespace {

// The dyadic number d exactly: its limbs (least significant first) times 2^binary_exponent.
Rational dyadic_value(const Dyadic& d) {
    Integer m = 0;
    const std::span<const Dyadic::Limb> limbs = d.limbs();
    for (std::size_t i = limbs.size(); i-- > 0;) m = (m << 64) | Integer(limbs[i]);
    if (d.sign() == Sign::Negative) m = -m;
    return times_power_of_two(Rational(m), d.binary_exponent());
}

}  // namespace

Rational exact_value(const momentlab::Rational& x) { return dyadic_value(x.num()) / dyadic_value(x.den()); }

Rational times_power_of_two(const Rational& x, std::int64_t k) {
    if (k == 0 || x == 0) return x;
    Integer p = numerator(x), q = denominator(x);
    if (k > 0) {
        p <<= static_cast<unsigned>(k);
    } else {
        q <<= static_cast<unsigned>(-k);
    }
    return Rational(p, q);  // reduced by the constructor
}

std::int64_t binary_magnitude(const Rational& x) {
    return static_cast<std::int64_t>(msb(abs(numerator(x)))) - static_cast<std::int64_t>(msb(denominator(x)));
}

double approximate(const Rational& x) {
    if (x == 0) return 0.0;
    // Numerator and denominator cut to their leading 64 bits, divided, scaled back: within a few
    // ulps (printing and guidance only).
    const Integer p = abs(numerator(x));
    const Integer& q = denominator(x);
    const auto shift_p = static_cast<std::int64_t>(msb(p)) - 62;
    const auto shift_q = static_cast<std::int64_t>(msb(q)) - 62;
    const Integer pp = shift_p > 0 ? Integer(p >> static_cast<unsigned>(shift_p)) : p;
    const Integer qq = shift_q > 0 ? Integer(q >> static_cast<unsigned>(shift_q)) : q;
    const double value = std::ldexp(pp.convert_to<double>() / qq.convert_to<double>(),
                                    static_cast<int>(std::max<std::int64_t>(shift_p, 0) - std::max<std::int64_t>(shift_q, 0)));
    return x.sign() < 0 ? -value : value;
}

std::string exact_text(const Rational& x) {
    if (denominator(x) == 1) return numerator(x).str();
    return numerator(x).str() + "/" + denominator(x).str();
}

bool is_double(const Rational& x) {
    if (x == 0) return true;
    const Integer& q = denominator(x);
    if ((q & (q - 1)) != 0) return false;  // not a power of two
    const double d = approximate(x);
    return std::isfinite(d) && exact_value(d) == x;
}

}  // namespace momentlab::assembly_detail
