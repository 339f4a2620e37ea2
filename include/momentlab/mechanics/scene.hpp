#pragma once

/// \file
/// The planar contact problem as an immutable value: a rigid body touching fixed polygons at
/// point contacts with Coulomb friction (DESIGN, Conventions).

#include <optional>
#include <string>
#include <vector>

#include "momentlab/core/vec.hpp"

namespace momentlab {

/// A point contact. `normal` is a unit vector pointing into the moving body; the tangent is
/// t = (n.y, -n.x); `mu` is the static and `mu_kinetic` the kinetic friction coefficient.
struct Contact {
    Vec2 point = Vec2::Zero();
    Vec2 normal = Vec2(0.0, 1.0);
    double mu = 0.0;
    double mu_kinetic = 0.0;
    std::string name;

    /// A contact with the normal scaled to unit length (rounded) and mu_kinetic defaulting to
    /// mu. Throws std::invalid_argument for a zero or non-finite normal, a non-finite point or
    /// a negative friction coefficient.
    static Contact make(const Vec2& point, const Vec2& normal, double mu,
                        std::optional<double> mu_kinetic = std::nullopt, std::string name = {});

    /// t = (n.y, -n.x).
    [[nodiscard]] Vec2 tangent() const { return Vec2(normal.y(), -normal.x()); }
    /// N = (n, p x n): N . xi is the normal velocity of the body point at the contact.
    [[nodiscard]] Vec3 normal_wrench() const { return wrench_at(point, normal); }
    /// T = (t, p x t): T . xi is its tangential velocity.
    [[nodiscard]] Vec3 tangent_wrench() const { return wrench_at(point, tangent()); }
};

/// A simple polygon given by its vertices, in either orientation (geometry/polygon.hpp checks).
using Polygon = std::vector<Vec2>;

/// The moving body: mass, centre of mass, inertia about the centre of mass, optional outline.
struct Body {
    double mass = 1.0;
    Vec2 com = Vec2::Zero();
    double inertia = 1.0;
    Polygon polygon;
};

/// A body (optional for purely kinematic questions), its contacts and the fixed obstacles.
struct Scene {
    std::optional<Body> body;
    std::vector<Contact> contacts;
    std::vector<Polygon> obstacles;
};

}  // namespace momentlab
