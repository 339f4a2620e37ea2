#pragma once

/// \file
/// Exact values rounded once, for output: to the nearest double and to decimal digits. The
/// values momentlab computes exactly and prints or returns as doubles (a label vertex x / s, the
/// end num / den of a band of push magnitudes, a Dyadic coordinate) go through here, so each is
/// the exact value correctly rounded (to nearest, ties to even), never a floating-point quotient
/// of rounded parts (which is 1-2 units in the last place off now and then).

#include <string>

#include "momentlab/core/dyadic.hpp"

namespace momentlab {

/// num / den rounded to the nearest double, ties to even: an estimate within a few units in the
/// last place, then moved while the exact quotient lies beyond the midpoint with a neighbour
/// (exact comparisons). Infinite from the midpoint above the largest double on, 0 below half the
/// smallest subnormal (with the quotient's sign). Precondition: den != 0.
[[nodiscard]] double nearest_double(const Dyadic& num, const Dyadic& den);

/// num / den correctly rounded to `digits` significant decimal digits (1..15, ties to even),
/// written as printf's "%.<digits>g" writes a double ("2.943", "1e-07", "0"): printf's digits
/// of the nearest double, moved by one unit in the last digit while the exact quotient lies
/// beyond the midpoint with the neighbouring decimal. "inf" or "-inf" beyond the doubles.
/// Precondition: den != 0.
[[nodiscard]] std::string significant_digits(const Dyadic& num, const Dyadic& den, int digits);

}  // namespace momentlab
