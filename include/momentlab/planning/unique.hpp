#pragma once

/// \file
/// Where a planned action gives the goal mode and nothing else (docs/planning.md, "Unique and
/// shared"). Mason's sets E_i overlap: a wrench in E_goal may lie in another mode's E_j as well
/// (jamming, or a neighbouring mode on a shared boundary), and then the goal is one possible
/// answer, not the answer. Given the solutions S = W ∩ E_goal of a plan and every mode's E, these
/// functions split S into the part where the goal is unique (in no other E_j) and the part where
/// it is shared. Exact: the pieces' ends are exact rays of the cones W ∩ E_j, ordered by exact
/// orientation tests.

#include <optional>
#include <span>
#include <vector>

#include "momentlab/core/exact.hpp"
#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/analysis.hpp"

namespace momentlab {

/// An arc of the directions of a plane of wrenches, counter-clockwise about the plane's normal
/// from `from` to `to` (exact rays; equal for a single direction), or (`whole`) the whole turn
/// from `from` round to it again. A split's arcs are closures: a run of directions that covers
/// the whole turn but one direction, held by another arc of the split, is the whole turn from
/// that direction.
struct WrenchArc {
    ExactVector from;
    ExactVector to;
    bool whole = false;
};

/// The solutions of a plan split by whether another mode's set holds them too. `unique` and
/// `shared` are closures: an arc of `unique` ends where the goal becomes shared (or ends).
struct PlaneSplit {
    std::vector<WrenchArc> unique;
    std::vector<WrenchArc> shared;
};

/// For cones s (the solutions, in E_goal) lying in the plane with normal `normal`, the arcs of s
/// where no mode of `modes` other than `goal` holds the wrench, and those where one does.
/// Every cone W ∩ E_j is computed exactly; O(m k log(m k)) for m modes and k arc ends per mode.
[[nodiscard]] PlaneSplit split_plane(const ExactVector& normal, const Cone& s, std::span<const ModeForces> modes,
                                     const ModeForces& goal);

/// Whether a cone of solutions s (in E_goal, any dimension) has a part of its own dimension
/// where the goal is the only mode, and wrenches that another mode holds too.
struct Uniqueness {
    bool unique = false;
    bool shared = false;
    /// An exact wrench in the relative interior of a unique part (when there is one).
    std::optional<ExactVector> representative;
    /// The unique parts, closed, as convex cones of s's dimension (each narrower than a half-turn
    /// in a plane): where the goal is the only mode, up to their boundaries.
    std::vector<Cone> parts;
};

/// Uniqueness of the solutions s against every other mode of `modes`. Exact. In three dimensions
/// the unique part is s minus each full-dimensional E_j, cut into convex cones along E_j's facets.
[[nodiscard]] Uniqueness uniqueness(const Cone& s, std::span<const ModeForces> modes, const ModeForces& goal);

/// A vector in the relative interior of an arc (exact): the sum of its ends when it is narrower
/// than a half-turn, the quarter turn from `from` at a half-turn, minus the sum when wider, and
/// -`from` for the whole turn (the direction farthest from where it starts).
[[nodiscard]] ExactVector arc_middle(const ExactVector& normal, const WrenchArc& arc);

}  // namespace momentlab
