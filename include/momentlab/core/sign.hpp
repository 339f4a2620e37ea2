#pragma once

/// \file
/// The result type of every exact predicate in momentlab.

namespace momentlab {

/// The exact sign of a real number computed from stored doubles (docs/design.md, Robustness).
enum class Sign : int { Negative = -1, Zero = 0, Positive = 1 };

/// The sign of -x when x has sign `s`.
constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }

/// The sign of a product of two numbers with signs `a` and `b`.
constexpr Sign operator*(Sign a, Sign b) {
    return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}

/// -1, 0 or +1.
constexpr int to_int(Sign s) { return static_cast<int>(s); }

/// The sign of an integer.
constexpr Sign sign_of_int(int x) {
    return x > 0 ? Sign::Positive : (x < 0 ? Sign::Negative : Sign::Zero);
}

}  // namespace momentlab
