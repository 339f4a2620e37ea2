#pragma once

/// \file
/// The planar contact problem as an immutable value: a rigid body touching fixed polygons at
/// point contacts with Coulomb friction (docs/design.md, Conventions).

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "momentlab/core/exact.hpp"
#include "momentlab/core/rational.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// A contact's numbers exactly (docs/design.md, "Numbers as typed"), with the doubles they round
/// to (the Contact's own doubles while these are its values).
struct ContactValues {
    Rational2 point, normal;
    Rational mu, mu_kinetic;
    Vec2 point_double = Vec2::Zero(), normal_double = Vec2::Zero();
    double mu_double = 0.0, mu_kinetic_double = 0.0;
};

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
    /// The exact values when some are not the doubles above (a decimal read from text, a
    /// Fraction from Python), the doubles being their correct roundings; none when the doubles
    /// are exact. Every decision reads the exact values (exact_values()).
    std::shared_ptr<const ContactValues> exact = nullptr;

    /// A contact with mu_kinetic defaulting to mu. Throws std::invalid_argument for a zero or
    /// non-finite normal, a non-finite point or a negative friction coefficient.
    static Contact make(const Vec2& point, const Vec2& normal, double mu,
                        std::optional<double> mu_kinetic = std::nullopt, std::string name = {});
    /// The same from exact values: the doubles are their correct roundings, and `exact` keeps
    /// the values when some are not doubles. The same checks, on the exact values.
    static Contact make(const Rational2& point, const Rational2& normal, const Rational& mu,
                        const std::optional<Rational>& mu_kinetic = std::nullopt, std::string name = {});
    /// The same from values whose doubles are already their roundings (a reader's).
    static Contact make(ContactValues values, std::string name = {});

    /// The exact values in force: `exact` while the doubles are still its roundings, else none
    /// (then the doubles are the exact values).
    [[nodiscard]] const ContactValues* exact_values() const;
    /// True when mu_kinetic = mu exactly.
    [[nodiscard]] bool kinetic_is_static() const;

    /// t = (n.y, -n.x).
    [[nodiscard]] Vec2 tangent() const { return Vec2(normal.y(), -normal.x()); }
    /// N = (n, p x n), exact: N . xi is the normal velocity of the body point at the contact
    /// (times |n|).
    [[nodiscard]] ExactVector normal_wrench() const;
    /// T = (t, p x t), exact: T . xi is its tangential velocity (times |n|).
    [[nodiscard]] ExactVector tangent_wrench() const;
    /// The edges of the static friction cone (kinetic: of the kinetic one) as wrenches acting at
    /// the contact: (n + mu t, n - mu t), exactly. For exact values (`exact`), each of these
    /// three is the same vector times a positive number (its denominators cleared).
    [[nodiscard]] std::array<ExactVector, 2> friction_edges(bool kinetic = false) const;
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

/// A body's numbers exactly, with the doubles they round to.
struct BodyValues {
    Rational mass;
    Rational2 com;
    Rational inertia;
    std::optional<Rational> radius_of_gyration;
    /// The outline as typed, when a vertex is not a double (else empty).
    std::vector<Rational2> polygon;
    double mass_double = 0.0, inertia_double = 0.0;
    Vec2 com_double = Vec2::Zero();
    std::optional<double> radius_double;
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
    /// The exact values of mass, com, inertia and radius of gyration when some are not the
    /// doubles above (as Contact::exact); none when the doubles are exact.
    std::shared_ptr<const BodyValues> exact = nullptr;
    /// The exact values in force (as Contact::exact_values).
    [[nodiscard]] const BodyValues* exact_values() const;
    /// The centre of mass exactly (as typed, or the double's own value).
    [[nodiscard]] Rational2 exact_com() const;
    /// The outline's vertices exactly (as typed, or the doubles' own values; O(n)).
    [[nodiscard]] std::vector<Rational2> exact_polygon() const;
};

/// The planar inertia at the world origin of a body of mass m, centre of mass (cx, cy) and
/// inertia ic about it: M = [[m, 0, -m cy], [0, m, m cx], [-m cy, m cx, ic + m (cx^2 + cy^2)]],
/// so that the total wrench is M times the acceleration twist (docs/design.md, "Per-mode force
/// sets"), in the number type N (N{} is 0; Dyadic, Rational, Approx, intervals). The one place
/// the matrix is written (tools/house_checks.sh).
template <class N>
[[nodiscard]] std::array<std::array<N, 3>, 3> inertia_matrix(const N& m, const N& cx, const N& cy, const N& ic) {
    const N mcx = m * cx, mcy = m * cy;
    return {std::array<N, 3>{m, N{}, -mcy}, std::array<N, 3>{N{}, m, mcx}, std::array<N, 3>{-mcy, mcx, ic + mcx * cx + mcy * cy}};
}

/// The planar inertia at the world origin, exactly (inertia_matrix of the body's numbers).
/// For a body with exact values (`exact`), M times a positive number (its denominators
/// cleared): the same cones M A.
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
