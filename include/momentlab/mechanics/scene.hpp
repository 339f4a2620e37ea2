#pragma once

/// \file
/// The planar contact problem as an immutable value: a rigid body touching fixed polygons at
/// point contacts with Coulomb friction (docs/design.md, Conventions).

#include <optional>
#include <string>
#include <vector>

#include "momentlab/core/exact.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// A point contact. `normal` points into the moving body and is used exactly as written: any
/// positive length (every condition is homogeneous in it, so nothing is rounded to unit
/// length); the tangent is t = (n.y, -n.x); `mu` is the static and `mu_kinetic` the kinetic
/// friction coefficient.
struct Contact {
    Vec2 point = Vec2::Zero();
    Vec2 normal = Vec2(0.0, 1.0);
    double mu = 0.0;
    double mu_kinetic = 0.0;
    std::string name;

    /// A contact with mu_kinetic defaulting to mu. Throws std::invalid_argument for a zero or
    /// non-finite normal, a non-finite point or a negative friction coefficient.
    static Contact make(const Vec2& point, const Vec2& normal, double mu,
                        std::optional<double> mu_kinetic = std::nullopt, std::string name = {});

    /// t = (n.y, -n.x).
    [[nodiscard]] Vec2 tangent() const { return Vec2(normal.y(), -normal.x()); }
    /// N = (n, p x n), exact: N . xi is the normal velocity of the body point at the contact
    /// (times |n|).
    [[nodiscard]] ExactVector normal_wrench() const;
    /// T = (t, p x t), exact: T . xi is its tangential velocity (times |n|).
    [[nodiscard]] ExactVector tangent_wrench() const;
};

/// A simple polygon given by its vertices, in either orientation (geometry/polygon.hpp checks).
using Polygon = std::vector<Vec2>;

/// Where find_contacts found a contact: vertex `vertex` of one polygon on edge `edge` (from
/// vertex `edge` to the next) of the other, indices as the polygons were given; the vertex is
/// the body's (on obstacle `obstacle`) when `body_vertex`, else obstacle `obstacle`'s (on the
/// body).
struct ContactOrigin {
    bool body_vertex = true;
    std::size_t obstacle = 0;
    std::size_t vertex = 0;
    std::size_t edge = 0;
};

/// The moving body: mass, centre of mass, inertia about the centre of mass, optional outline.
struct Body {
    double mass = 1.0;
    Vec2 com = Vec2::Zero();
    /// The inertia about the centre of mass (rounded when given as a radius of gyration).
    double inertia = 1.0;
    Polygon polygon;
    /// When set, the inertia is exactly mass * radius_of_gyration^2 (`inertia` is its rounding).
    std::optional<double> radius_of_gyration = std::nullopt;
};

/// The planar inertia at the world origin, exactly: M = [[m, 0, -m c.y], [0, m, m c.x],
/// [-m c.y, m c.x, I_c + m |c|^2]], so that the total wrench is M times the acceleration twist.
[[nodiscard]] ExactMatrix inertia_at_origin(const Body& body);

/// A body (optional for purely kinematic questions), its contacts and the fixed obstacles.
struct Scene {
    std::optional<Body> body;
    std::vector<Contact> contacts;
    std::vector<Polygon> obstacles;
    /// How far from the body's outline a contact may lie (scene files' "contact_distance"), when
    /// the scene gave it; to_json writes it back so that the scene reads again.
    std::optional<double> contact_distance;
    /// One per contact when the contacts were found from the polygons (find_contacts), else empty.
    std::vector<ContactOrigin> origins;
};

}  // namespace momentlab
