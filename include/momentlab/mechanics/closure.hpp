#pragma once

/// \file
/// Grasp closure (Lynch and Park, Modern Robotics, ch. 12; docs/design.md, "Closure"): whether
/// the contacts can resist every applied wrench. First-order form closure: the wrenches of the
/// contact normals N_j = (n_j, p_j x n_j) positively span R^3 (frictionless contacts). Force
/// closure: the contacts' friction cones (each with its own static mu) positively span R^3.
/// Both are decided exactly, as a cone being the whole space.

#include <optional>

#include "momentlab/core/exact.hpp"
#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// One closure test and its certificate.
struct ClosureTest {
    bool holds = false;
    /// The contact wrenches: the cone of the normals' wrenches (form) or the sum of the friction
    /// cones (force).
    Cone wrenches;
    /// When it fails, a non-zero w with w . c >= 0 for every contact wrench c, exact: the
    /// applied wrench w cannot be resisted (-w is no contact wrench), and for form closure the
    /// twist with the same coordinates moves no contact into its obstacle (to first order).
    std::optional<ExactVector> unresisted;
    /// When it holds: the radius of the largest ball about 0 inside the convex hull of the
    /// contacts' unit wrenches (form: the unit normals; force: the unit friction-cone edges),
    /// each (u, ((p - reference) x u) / length); rounded, in (0, 1]. The hull's facets are chosen
    /// exactly on the rounded unit wrenches, so the quality is 0 only when the ball is thinner
    /// than their rounding (a relative 1e-16).
    double quality = 0.0;
};

/// Where torques are taken and how they are scaled in the quality metric.
struct ClosureOptions {
    /// Default: the body's centre of mass, else the centroid of the contact points.
    std::optional<Vec2> reference;
    /// A characteristic length (> 0); default: the largest distance of a contact from the
    /// reference (1 when every contact is at the reference).
    std::optional<double> length;
};

/// What the quality measures, in words (the CLI and the JSON view say it).
inline constexpr const char* kClosureQualityMetric =
    "radius of the largest ball about 0 inside the convex hull of the contacts' unit wrenches (fx, fy, tau / length), "
    "tau about the reference point";

/// Form and force closure of a scene's contacts (the body is optional).
struct Closure {
    ClosureTest form;
    ClosureTest force;
    Vec2 reference = Vec2::Zero();
    double length = 1.0;
};

/// Both closure tests. O(n log n) for the decisions; the quality measure enumerates the hull's
/// facets from the k = n (form) or 2n (force) unit wrenches in O(k^4). Throws
/// std::invalid_argument for a scene without contacts or a non-finite or non-positive length.
[[nodiscard]] Closure closure(const Scene& scene, const ClosureOptions& options = {});

}  // namespace momentlab
