#pragma once

/// \file
/// Assemblies: several movable rigid bodies touching each other and fixed obstacles at point
/// contacts with Coulomb friction (docs/assemblies.md). Bodies are numbered 1..N in the order
/// given and 0 is the fixed world (the convention of Lynch and Park's Modern Robotics, ch. 12); a
/// contact names its pair (a, b), its normal points into body a, and body b receives the opposite
/// force. A one-body scene is the assembly with N = 1 and every contact (1, 0).

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "momentlab/mechanics/find_contacts.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// A movable body of an assembly: mass (> 0), centre of mass, inertia about the centre of mass
/// (needed only for the contact modes: equilibrium and tilt are statics), outline (optional).
struct AssemblyBody {
    std::string name;
    double mass = 1.0;
    Vec2 com = Vec2::Zero();
    /// The inertia about the centre of mass, when given.
    std::optional<double> inertia;
    /// When given instead, the inertia is exactly mass * radius_of_gyration^2.
    std::optional<double> radius_of_gyration;
    Polygon polygon;
    /// The exact values of mass, com, inertia (0 when not given) and radius of gyration when
    /// some are not the doubles above (a decimal as typed), the doubles being their correct
    /// roundings; none when the doubles are exact (as Body::exact).
    std::shared_ptr<const BodyValues> exact = nullptr;
    /// The exact values in force: `exact` while the doubles are still its roundings, else none
    /// (then the doubles are the exact values).
    [[nodiscard]] const BodyValues* exact_values() const;
};

/// A point contact of body `a` (1..N) with body `b` (0: the world, or 1..N other than a): the
/// contact's normal points into a; a receives the contact force, b its opposite.
struct AssemblyContact {
    std::size_t a = 1;
    std::size_t b = 0;
    Contact contact;
};

/// Bodies, contacts and fixed obstacles, as an immutable value.
struct Assembly {
    std::vector<AssemblyBody> bodies;
    std::vector<AssemblyContact> contacts;
    std::vector<Polygon> obstacles;
    /// How far apart polygons may be and still touch (scene files' "contact_distance"), when given.
    std::optional<double> contact_distance;
    /// The polygons' vertices as typed, the bodies' (empty for a body without one) then the
    /// obstacles', when some are not doubles (0.1 is 1/10): overlap is then decided on them
    /// (scaled_polygons), while the doubles above are still their roundings.
    std::shared_ptr<const std::vector<std::vector<Rational2>>> exact_polygons = nullptr;
    /// exact_polygons while the polygons' doubles are still their roundings, else none.
    [[nodiscard]] const std::vector<std::vector<Rational2>>* exact_polygons_in_force() const;
};

/// The one-body scene as an assembly: body 1 (the scene's body), every contact (1, 0), the same
/// obstacles. Throws std::invalid_argument when the scene has no body.
[[nodiscard]] Assembly assembly_of(const Scene& scene);

/// The contacts where the bodies' polygons touch the obstacles and each other, in this order: for
/// each body a = 1..N, its contacts with the obstacles (b = 0), then with each earlier body
/// b = 1..a-1, each pair's contacts as find_contacts gives them (the normal into a; a stack listed
/// from the bottom up has its normals pointing up). Bodies without a polygon touch nothing.
/// Throws std::invalid_argument as find_contacts does. When `origins` is given, it receives
/// where each contact was found (ContactOrigin: the vertex of body a's polygon or of the other's,
/// `obstacle` the obstacle's index when b = 0), one per contact.
[[nodiscard]] std::vector<AssemblyContact> find_assembly_contacts(const std::vector<AssemblyBody>& bodies,
                                                                  const std::vector<Polygon>& obstacles,
                                                                  const ContactFinding& options = {},
                                                                  std::vector<ContactOrigin>* origins = nullptr);
namespace detail {
/// find_assembly_contacts on scaled outlines (scaled_polygons of the bodies' n, then the
/// obstacles'), the options as given (distances scaled as find_contacts_of_simple does), every
/// outline simple and no two overlapping (check_assembly).
[[nodiscard]] std::vector<AssemblyContact> find_assembly_contacts_of_simple(const ScaledPolygons& scaled, std::size_t n,
                                                                            const ContactFinding& options,
                                                                            std::vector<ContactOrigin>* origins);
}  // namespace detail

/// Checks an assembly: at least one body; each body's mass finite and > 0, its centre of mass
/// finite, its inertia or radius of gyration (at most one of them) finite and > 0, its polygon
/// simple; each contact's pair in range (a in 1..N, b in 0..N) and not a body with itself, its
/// point, normal and friction as Contact::make requires; no two body polygons, and no body
/// polygon and obstacle, overlapping (touching is fine). Throws InputError (std::invalid_argument)
/// naming the field as a JSON path ("$.contacts[2].bodies"), the first problem found.
void check_assembly(const Assembly& assembly);

}  // namespace momentlab
