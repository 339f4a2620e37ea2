#pragma once

/// \file
/// Builders of the force sets of the paper (Mason 1991, Figure 1) as wrench cones.
/// Wrenches are (fx, fy, tau) with tau about the world origin (DESIGN, Conventions).

#include <array>

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

/// The Coulomb friction cone of a point contact (Figure 1c): forces n + s t with |s| <= mu,
/// t = (n.y, -n.x), acting at `point`; `normal` points into the body and need not be unit.
/// The edges n +- mu t are rounded when mu * n is not representable (docs/robustness.md).
/// Throws std::invalid_argument for a zero normal or mu < 0.
[[nodiscard]] Cone friction_cone(const Vec2& point, const Vec2& normal, double mu);

/// The two edges of the Coulomb cone at a contact, as wrenches: {n + mu t, n - mu t} acting at
/// `point`, t = (n.y, -n.x). Friction opposing sliding along +t is the second edge (with the
/// kinetic mu), along -t the first. No argument checks (see friction_cone).
[[nodiscard]] inline std::array<Vec3, 2> friction_cone_edges(const Vec2& point, const Vec2& normal, double mu) {
    const Vec2 t(normal.y(), -normal.x());
    return {wrench_at(point, normal + mu * t), wrench_at(point, normal - mu * t)};
}

/// Pure moments: positive (sign > 0), negative (sign < 0) or both (sign == 0).
[[nodiscard]] Cone pure_moments(int sign);

}  // namespace momentlab
