#pragma once

/// \file
/// Contacts from geometry: a body polygon touching fixed polygons.

#include <optional>
#include <vector>

#include "momentlab/geometry/polygon.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// Options of find_contacts.
struct ContactFinding {
    /// How close (scene length units) a vertex must be to an edge to touch it. This is the
    /// one tolerance of momentlab, and a modelling choice: real parts do not touch exactly,
    /// and scene files round coordinates. Two contacts whose points and unit normals are both
    /// within it of each other (exactly: the normals as the touched edges' exact directions)
    /// are one.
    double distance = 1e-9;
    /// Friction coefficients given to every contact found.
    double mu = 0.0;
    double mu_kinetic = 0.0;
};

/// The point contacts between `body` and the `obstacles` (polygons in either orientation):
/// every body vertex lying on an obstacle edge (normal: the edge's outward normal) and every
/// obstacle vertex lying on a body edge (normal: into the body), when the neighbouring
/// vertices stay outside the touched edge's line (so a corner resting on a corner touches
/// only the supporting edge; an obstacle vertex at a body vertex is left to the body vertex,
/// which then gets one contact per obstacle edge ending there: corner on corner is degenerate,
/// its non-penetrating motions are not convex, and this over-constrains it).
/// An edge lying along another edge gives two contacts, at the ends of the overlap. "Lying
/// on" is within `options.distance`, decided exactly (within_distance_of_segment). Throws
/// std::invalid_argument for a polygon that is not simple (polygon_problem: fewer than 3
/// vertices, non-finite or repeated vertices, crossing or folded edges), a body overlapping an
/// obstacle (their interiors meet: polygons_overlap, exact, no tolerance) or a negative distance.
/// Each touched polygon's edges are indexed in a grid (docs/benchmarks.md, Polygons): O((n + m)
/// log(n + m)) with the simplicity checks for outlines of n and m vertices whose edges do not
/// crowd into a few cells. When `origins` is given, it receives where each contact was found,
/// one per contact.
[[nodiscard]] std::vector<Contact> find_contacts(const Polygon& body, const std::vector<Polygon>& obstacles,
                                                 const ContactFinding& options = {},
                                                 std::vector<ContactOrigin>* origins = nullptr);

/// Polygons given exactly (decimal vertices as typed: 0.1 is 1/10) times the least common
/// denominator D of their coordinates (the distance times D with them): overlap and contact are
/// unchanged by the scaling, so find_contacts and polygons_overlap on them decide for the
/// decimals. The products as doubles when every one is a double (`doubles`), else as exact
/// points (`exact`: decimals of more than about 16 digits); `exact` is empty exactly when
/// `doubles` is used.
struct ScaledPolygons {
    std::vector<Polygon> doubles;
    std::vector<ExactPolygon> exact;
    Dyadic scale;  ///< D
    /// A distance of the given polygons on the scaled ones: d D, exactly, and its double.
    [[nodiscard]] Dyadic distance(double d) const { return Dyadic(d) * scale; }
    [[nodiscard]] double rounded_distance(double d) const { return distance(d).to_double(); }
};
/// nullopt when every coordinate is a double (nothing to scale).
[[nodiscard]] std::optional<ScaledPolygons> scaled_polygons(const std::vector<std::vector<Rational2>>& exact);

/// A contact find_contacts found, with the numbers as typed: the point the touching vertex
/// `vertex`, the normal the perpendicular of the touched edge from `from` to `to` (exact: a
/// difference of decimals) in the sense of found.normal, scaled so that its larger coordinate
/// is +-1 (docs/formats.md), friction `mu` (static and kinetic). When the three points are
/// doubles and the contacts were not found on scaled polygons, `found` itself (with `mu` when
/// it is not a double).
[[nodiscard]] Contact contact_as_typed(const Contact& found, const Rational2& vertex, const Rational2& from,
                                       const Rational2& to, const Rational& mu, bool scaled);

namespace detail {
/// find_contacts for polygons the caller has already found simple (polygon_problem gave "") and
/// not overlapping (polygons_overlap gave none): reading a scene checks each outline as it reads
/// it, and sweeps it only once. `origins` as find_contacts.
[[nodiscard]] std::vector<Contact> find_contacts_of_simple(const Polygon& body, const std::vector<Polygon>& obstacles,
                                                           const ContactFinding& options,
                                                           std::vector<ContactOrigin>* origins = nullptr);
/// The same on scaled polygons (scaled_polygons: `doubles` or `exact`), the options as given:
/// points compared within options.distance times the scale, unit normals within
/// options.distance (both exactly). The contacts' points are on the scaled polygons (their doubles) and their
/// normals doubles near the exact ones: contact_as_typed gives the values as typed.
[[nodiscard]] std::vector<Contact> find_contacts_of_simple(const Polygon& body, const std::vector<Polygon>& obstacles,
                                                           const ContactFinding& options, const ScaledPolygons& scaled,
                                                           std::vector<ContactOrigin>* origins = nullptr);
[[nodiscard]] std::vector<Contact> find_contacts_of_simple(const ExactPolygon& body, const std::vector<ExactPolygon>& obstacles,
                                                           const ContactFinding& options, const ScaledPolygons& scaled,
                                                           std::vector<ContactOrigin>* origins = nullptr);
}  // namespace detail

}  // namespace momentlab
