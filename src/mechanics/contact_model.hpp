// The contact model, written once for every path that builds a mode's sets (analyze, the walk of
// query_scene, the one-shot path of query): which wrench generators a contact adds to the
// contact cone T for each letter, with what friction coefficient, and the body's inertia
// matrix, generic over the number type (Dyadic for exact values, certified doubles in the
// one-shot path). docs/design.md, "Per-mode force sets".
#pragma once

#include <array>
#include <cstdint>

#include "momentlab/geometry/force_sets.hpp"
#include "momentlab/mechanics/modes.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab::detail {

/// The four edges of a contact's friction cones, by their direction n + c t (t = (n.y, -n.x)):
/// c = mu, -mu (the static cone), mu_k, -mu_k (the kinetic one). The values are the slots the
/// walk names generators by.
enum class FrictionEdge : std::uint8_t { StaticPlus = 0, StaticMinus = 1, KineticPlus = 2, KineticMinus = 3 };

/// The generators a contact adds to T in a mode (at most two edges).
struct ContactGenerators {
    std::array<FrictionEdge, 2> edges{};
    std::size_t count = 0;
    [[nodiscard]] constexpr const FrictionEdge* begin() const { return edges.data(); }
    [[nodiscard]] constexpr const FrictionEdge* end() const { return edges.data() + count; }
};

/// What a contact adds to the contact cone T of a mode where its letter is `mode_letter` (Mason 1991,
/// section 2.1): nothing when it separates (s); both edges of the static cone when it is fixed (f);
/// when it slides, the one kinetic edge whose friction opposes the sliding (opposing_friction):
/// n - mu_k t for r (sliding along +t), n + mu_k t for l.
[[nodiscard]] constexpr ContactGenerators contact_generators(char mode_letter) {
    const auto mode = static_cast<ContactMode>(mode_letter);
    if (mode == ContactMode::Fixed) return {{FrictionEdge::StaticPlus, FrictionEdge::StaticMinus}, 2};
    const int s = opposing_friction(mode);
    if (s == 0) return {};
    const FrictionEdge kinetic = s > 0 ? FrictionEdge::KineticPlus : FrictionEdge::KineticMinus;
    return {{kinetic, kinetic}, 1};
}

/// The coefficient c of the edge's direction n + c t.
[[nodiscard]] constexpr double tangent_coefficient(const Contact& c, FrictionEdge e) {
    switch (e) {
        case FrictionEdge::StaticPlus: return c.mu;
        case FrictionEdge::StaticMinus: return -c.mu;
        case FrictionEdge::KineticPlus: return c.mu_kinetic;
        default: return -c.mu_kinetic;
    }
}

/// A contact's exact values with their denominators cleared (docs/design.md, "Numbers as
/// typed"): the point P / scale, a positive multiple n of the normal, mu = mu_num / mu_den and
/// mu_k = kinetic_num / kinetic_den, all Dyadic. Every generator of the contact is then a
/// positive multiple of one made of these in Dyadic arithmetic (cleared_wrench).
struct ClearedContact {
    Exact2 point;
    Dyadic scale;
    Exact2 normal;
    Dyadic mu_num, mu_den, kinetic_num, kinetic_den;
};
[[nodiscard]] ClearedContact cleared(const ContactValues& values);

/// The direction of the edge e, times mu's denominator: den n + c num t for the edge's
/// n + c (num / den) t.
[[nodiscard]] Exact2 edge_direction(const ClearedContact& c, FrictionEdge e);

/// scale times the wrench of the force direction d through P / scale: (scale d, P x d).
[[nodiscard]] Exact3 cleared_wrench(const ClearedContact& c, const Exact2& d);

/// The inertia matrix of a body's exact values times a positive number (its denominators cleared).
[[nodiscard]] std::array<Exact3, 3> cleared_inertia(const BodyValues& values);

/// The body's inertia matrix at the world origin (inertia_matrix) from its doubles, each made an N
/// by `number`: I_c the inertia about the centre of mass, or m rho^2 for a radius of gyration
/// rho (exactly).
template <class N, class Number>
[[nodiscard]] std::array<std::array<N, 3>, 3> body_inertia(const Body& body, const Number& number) {
    const N m = number(body.mass), cx = number(body.com.x()), cy = number(body.com.y());
    const N ic = body.radius_of_gyration ? m * number(*body.radius_of_gyration) * number(*body.radius_of_gyration) : number(body.inertia);
    return inertia_matrix(m, cx, cy, ic);
}

}  // namespace momentlab::detail
