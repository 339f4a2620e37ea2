#pragma once

// The exact numbers of the assembly layer: integers and rationals of any size (Boost.Multiprecision's
// header-only cpp_int and cpp_rational, which compile to WebAssembly: no GMP). Every number of a
// scene enters here, exactly: a double is the dyadic rational it stores (exact_value); a decimal
// read as typed (0.1 = 1/10) enters as the rational it names, and nothing downstream changes.

#include <boost/multiprecision/cpp_int.hpp>
#include <cstdint>
#include <string>

#include "momentlab/core/rational.hpp"
#include "momentlab/core/sign.hpp"

namespace momentlab::assembly_detail {

// Without expression templates: the programs are written once for Interval and Rational, and
// each operation gives a number.
using Integer = boost::multiprecision::number<boost::multiprecision::cpp_int_backend<>, boost::multiprecision::et_off>;
using Rational = boost::multiprecision::number<boost::multiprecision::rational_adaptor<boost::multiprecision::cpp_int_backend<>>,
                                               boost::multiprecision::et_off>;

/// The double x exactly (x finite).
[[nodiscard]] Rational exact_value(double x);
/// A scene's number exactly (a decimal as typed: 0.1 is 1/10).
[[nodiscard]] Rational exact_value(const momentlab::Rational& x);
/// x rounded to a double (for printing and for the floating-point guidance; decides nothing).
[[nodiscard]] double approximate(const Rational& x);
/// The exact sign.
[[nodiscard]] inline Sign sign_of(const Rational& x) { return sign_of_int(x.sign()); }
/// x times 2^k, exactly.
[[nodiscard]] Rational times_power_of_two(const Rational& x, std::int64_t k);
/// floor(log2 |x|) for x != 0 (within one: the difference of the bit lengths of the numerator
/// and the denominator), for choosing scales.
[[nodiscard]] std::int64_t binary_magnitude(const Rational& x);
/// "p/q" or "p" (lowest terms).
[[nodiscard]] std::string exact_text(const Rational& x);
/// True when x is exactly a double.
[[nodiscard]] bool is_double(const Rational& x);

}  // namespace momentlab::assembly_detail
