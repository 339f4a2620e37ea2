#pragma once

/// \file
/// Builders of the force sets of the paper (Mason 1991, Figure 1) as wrench cones.
/// Wrenches are (fx, fy, tau) with tau about the world origin (docs/design.md, Conventions).

#include <array>
#include <vector>

#include "momentlab/core/rational.hpp"
#include "momentlab/core/vec.hpp"
#include "momentlab/geometry/cone.hpp"

namespace momentlab {

/// The positive multiples of the force `direction` acting through `point` (Figure 1a: a
/// directed line of force). Throws std::invalid_argument for a zero or non-finite direction.
[[nodiscard]] Cone force_ray(const Vec2& point, const Vec2& direction);

/// All forces along the line through `point` with `direction`, both senses.
[[nodiscard]] Cone line_of_force(const Vec2& point, const Vec2& direction);

/// All forces whose line of action passes through `point` (Figure 1b): a plane of wrenches.
[[nodiscard]] Cone forces_through_point(const Vec2& point);

/// The same three sets for an exact point and direction (decimals as typed: 0.1 is 1/10,
/// docs/design.md, "Numbers as typed"): each generator times a positive number, its
/// denominators cleared, so the same cone with Dyadic coordinates; when every value is a double,
/// the builder of doubles (its generators as it makes them). Precondition: the direction is
/// non-zero.
[[nodiscard]] Cone force_ray(const Rational2& point, const Rational2& direction);
[[nodiscard]] Cone line_of_force(const Rational2& point, const Rational2& direction);
[[nodiscard]] Cone forces_through_point(const Rational2& point);

/// The wrench (d, p x d) of the force d acting through p, exact.
[[nodiscard]] ExactVector force_wrench(const Vec2& point, const Vec2& direction);

/// The direction n + c t of a friction edge, t = (n.y, -n.x) (c = +-mu or +-mu_k), in the number
/// type N: Dyadic for exact edges, certified doubles in the one-shot path of query, intervals and
/// rationals in the assembly layer. With `den` (> 0), c = num / den and the direction is scaled
/// by den: den n + num t (so that a decimal mu stays exact in Dyadic arithmetic). The one place
/// the edge is written (tools/house_checks.sh).
template <class N>
[[nodiscard]] std::array<N, 2> friction_direction(const N& nx, const N& ny, const N& c, const N* den = nullptr) {
    if (den == nullptr) return {nx + c * ny, ny - c * nx};
    return {*den * nx + c * ny, *den * ny - c * nx};
}

/// An edge of the Coulomb cone with inward normal n (any length): n + mu t (`left`: the force
/// opposing sliding along -t) or n - mu t, t = (n.y, -n.x); exact.
[[nodiscard]] Exact2 friction_edge(const Exact2& normal, double mu, bool left);
[[nodiscard]] Exact2 friction_edge(const Vec2& normal, double mu, bool left);
/// The same for an exact mu = num / den (a decimal as typed): den n + num t or den n - num t.
[[nodiscard]] Exact2 friction_edge(const Exact2& normal, const Rational& mu, bool left);

/// The Coulomb friction cone of a point contact (Figure 1c): forces n + s t with |s| <= mu,
/// t = (n.y, -n.x), acting at `point`; `normal` points into the body and need not be unit.
/// Exact: the edges n +- mu t and their torques are exact expressions of the doubles given.
/// Throws std::invalid_argument for a zero normal or mu < 0.
[[nodiscard]] Cone friction_cone(const Vec2& point, const Vec2& normal, double mu);

/// The same for an exact point, normal and mu (as typed): with the normal cleared to integers N
/// and mu = a / b, the edges b N +- a t, t = (N.y, -N.x). Preconditions: a non-zero normal, mu >= 0.
[[nodiscard]] Cone friction_cone(const Rational2& point, const Rational2& normal, const Rational& mu);

/// The two edges of the Coulomb cone at a contact, as exact wrenches: {n + mu t, n - mu t}
/// acting at `point`, t = (n.y, -n.x). Friction opposing sliding along +t is the second edge
/// (with the kinetic mu), along -t the first. No argument checks (see friction_cone).
[[nodiscard]] std::array<ExactVector, 2> friction_cone_edges(const Vec2& point, const Vec2& normal, double mu);

/// All forces with direction in cone(directions) (exact, in one open half-plane) whose line
/// of action meets the segment a-b (a == b: passes through a): the directions with every pure
/// moment, cut by the half-spaces of moments about a and b of opposite signs. Built from the
/// directions and the points exactly (rounding the moments p x d of generators would tilt the
/// plane of forces through a vertex off its true position). For a segment the directions must
/// lie in one open side of its line. The ends are exact (a body outline's vertices as typed;
/// rational(v) for a double v).
[[nodiscard]] Cone forces_across(const Rational2& a, const Rational2& b, const std::vector<Exact2>& directions);

/// Pure moments: positive (sign > 0), negative (sign < 0) or both (sign == 0).
[[nodiscard]] Cone pure_moments(int sign);

}  // namespace momentlab
