#pragma once

/// \file
/// How far an applied wrench is from changing its answer (docs/design.md, "Margins"): the
/// distance from the wrench to the boundary of each E_i that holds it, and to the nearest E_j
/// that does not. Distances are Euclidean after scaling wrenches to (fx, fy, tau_r / L): tau_r
/// the torque about a reference point r, L a characteristic length, so that a margin is a force
/// and does not change when the scene is moved or its units of length change. Rounded values:
/// which modes hold the wrench is decided exactly by query; the margins measure, they do not
/// decide. Every wrench, generator and facet is taken to torques about the reference exactly and
/// rounded once there, so a margin is the same, to rounding, for a scene moved anywhere (about a
/// reference that moves exactly with it: the centre of mass, or a given point); no tolerance
/// chooses the nearest face.

#include <optional>
#include <span>
#include <vector>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// The scaling of wrench space: torques about `reference`, divided by `length`.
struct WrenchMetric {
    Vec2 reference = Vec2::Zero();
    double length = 1.0;

    /// (fx, fy, (tau - r x f) / length) for a wrench (fx, fy, tau) with tau about the origin
    /// (tau - r x f exact, then rounded).
    [[nodiscard]] Vec3 scaled(const Vec3& w) const;
};

/// The reference (default: the body's centre of mass, else the contacts' centroid) and the
/// largest distance of a contact from it (1 when there is none). Closure's quality uses the same.
[[nodiscard]] WrenchMetric default_metric(const Scene& scene, std::optional<Vec2> reference = std::nullopt);

/// The distance from w to the closed cone c in the metric (0 when c holds w).
[[nodiscard]] double distance_to(const Cone& c, const Vec3& w, const WrenchMetric& metric);

/// For w in the closed cone c: the distance to its boundary (0 on it, and whenever c is not
/// full-dimensional; infinite for R^3).
[[nodiscard]] double distance_to_boundary(const Cone& c, const Vec3& w, const WrenchMetric& metric);

/// The margins of one question: for each mode that holds the wrench (query's order), how far
/// the wrench may move before it leaves that mode's set; and how far it is from the nearest set
/// of a mode that does not hold it (none when every mode holds it).
struct QueryMargins {
    std::vector<double> inside;
    std::optional<double> to_other;
};

/// The margins of the wrench e whose answer is `modes` (indices into `analysis`, as query gives).
[[nodiscard]] QueryMargins query_margins(std::span<const ModeForces> analysis, const std::vector<std::size_t>& modes,
                                         const Vec3& e, const WrenchMetric& metric);

/// The margins of a wrench whose answer is computed here (exactly, by each mode's own set).
[[nodiscard]] QueryMargins margins_of(std::span<const ModeForces> analysis, const Vec3& e, const WrenchMetric& metric);
/// The same for an exactly known wrench (a plan's action, whose torque a double would round).
[[nodiscard]] QueryMargins margins_of(std::span<const ModeForces> analysis, const Exact3& e, const WrenchMetric& metric);

}  // namespace momentlab
