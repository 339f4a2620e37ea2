#pragma once

/// \file
/// The exact angular order of directions about an axis (in a plane, or in R^3 seen along a
/// vector), written once for every caller: the cone builders' sorts, the walk of the contact
/// modes, the arcs of the planners (tools/house_checks.sh checks it is written only here).
///
/// A direction v is placed relative to a reference direction r in one of four classes, its
/// half: 0 along r, 1 strictly counter-clockwise from r within a half-turn, 2 along -r, 3 the
/// rest. Inside the open halves 1 and 3 the order is the orientation of the pair. Both are read
/// from exact signs the caller supplies (its own predicates, with its own filters), so the order
/// is exact whenever they are.

#include "momentlab/core/sign.hpp"

namespace momentlab {

/// The half of a direction v about the axis, from side = the orientation of (r, v) (Positive:
/// v is counter-clockwise from r) and, only when side is Zero, along() = whether v points
/// along r rather than against it (called at most once).
template <class Along>
[[nodiscard]] constexpr int angular_half(Sign side, Along along) {
    if (side == Sign::Positive) return 1;
    if (side == Sign::Negative) return 3;
    return along() ? 0 : 2;
}

/// Compares directions u and v in the angular order from r: Negative when u comes first, Zero
/// for the same direction, Positive when after. half_u and half_v are their angular_half;
/// orient() = the orientation of (u, v) about the axis, called only when both lie in one open
/// half.
template <class Orient>
[[nodiscard]] constexpr Sign angular_compare(int half_u, int half_v, Orient orient) {
    if (half_u != half_v) return half_u < half_v ? Sign::Negative : Sign::Positive;
    if (half_u == 0 || half_u == 2) return Sign::Zero;
    return -orient();
}

}  // namespace momentlab
