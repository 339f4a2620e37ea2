#pragma once

/// \file
/// What the planners share (Mason 1991, section 3): intervals of force directions, and the
/// forces through one point that lie in a goal's set of applied wrenches (the tilts of
/// planning/tilt.hpp, the spring directions of planning/comply.hpp).

#include <optional>
#include <span>
#include <vector>

#include "momentlab/core/vec.hpp"
#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/margin.hpp"
#include "momentlab/planning/fixed_wrench.hpp"

namespace momentlab {

/// A closed interval of directions, counter-clockwise from `from` to `to`, in radians from +x;
/// `from` is in [-pi, pi) and `from <= to <= pi` (an interval through pi is given as two).
/// The directions `from_direction`, `to_direction` are the exact rays of the solution cone,
/// rounded; the angles are rounded from them.
struct AngleInterval {
    double from = 0.0;
    double to = 0.0;
    Vec2 from_direction = Vec2::Zero();
    Vec2 to_direction = Vec2::Zero();
};

/// What a planner may be told beyond its goal.
struct PlanContext {
    /// Every mode's sets (the analysis the goal belongs to). With them a plan says where the goal
    /// is the only mode and where another mode's set holds the same wrench (planning/unique.hpp),
    /// and picks its best action among the unique ones. Empty: not said.
    std::span<const ModeForces> modes;
    /// A wrench acting whatever the controller does (gravity_wrench, or any): the plan is then for
    /// fixed + lambda u, lambda >= 0 (planning/fixed_wrench.hpp). Uniqueness then depends on the
    /// magnitude too: ask magnitude_bands at the action chosen.
    std::optional<Exact3> fixed;
    /// The fixed wrench is fixed / fixed_scale (> 0): a load typed with decimals, its denominators
    /// cleared (the directions are those of `fixed`; the magnitudes are scaled back).
    Dyadic fixed_scale = Dyadic(1.0);
    /// With the modes (and no fixed wrench): the metric in which a plan gives the margins of its
    /// best action, a unit force (mechanics/margin.hpp, as query --margin).
    std::optional<WrenchMetric> metric;
};

/// The forces through one point that produce a goal mode: tilts (gravity through the centre of
/// mass), or a spring through a compliance centre (comply.hpp).
struct DirectionPlan {
    Cone actions;    ///< W: the forces through the point
    Cone solutions;  ///< W ∩ E_goal
    /// The force directions in W ∩ E_goal: none, one (possibly a single direction), two when
    /// the set wraps through pi, or [-pi, pi] when every direction works.
    std::vector<AngleInterval> intervals;
    /// The direction farthest from every boundary (the middle of the widest arc) and that
    /// distance in radians (0 when the arc is a single direction; pi when every tilt works).
    /// With PlanContext::modes (and no fixed wrench): the best direction is the middle of the
    /// widest arc where the goal is unique (when there is one of positive width), and the margin
    /// the distance to where it stops being unique.
    double best = 0.0;
    double margin = 0.0;
    /// Told the modes (and no fixed wrench): the closures of the directions where the goal is the
    /// only mode and of those where another mode's set holds them too; `intervals` is their union.
    bool uniqueness_known = false;
    /// Every solution lies on the boundary of E_goal (with a fixed wrench: every g + lambda u that
    /// gives the goal does), so no direction has a margin: `margin` is 0.
    bool knife_edge = false;
    std::vector<AngleInterval> unique;
    std::vector<AngleInterval> shared;
    bool best_unique = false;  ///< `best` lies in an arc of `unique`
    /// With a fixed wrench: the magnitudes of the force along `best` that give the goal (none when
    /// only the limit of ever larger forces reaches E_goal, on the boundary of `intervals`).
    std::optional<MagnitudeRange> best_magnitudes;
    bool magnitudes_known = false;  ///< planned with a fixed wrench
    /// With the modes and a metric: the margins of the unit force along `best` (query_margins).
    std::optional<QueryMargins> best_margins;
    [[nodiscard]] bool feasible() const { return !intervals.empty(); }
};

/// The directions of the forces through `point` (exact: a decimal as typed) that lie in
/// `goal_applied` (an E_i). The boundary directions belong to the intervals (E_i is closed).
[[nodiscard]] DirectionPlan plan_directions_through(const Rational2& point, const Cone& goal_applied);

/// The set a plan aims at: E_goal, or with a fixed wrench g the directions that reach it at some
/// magnitude, E_goal + cone(-g) (reachable_directions).
[[nodiscard]] Cone planned_set(const ModeForces& goal, const PlanContext& context);

/// The same for the goal mode, told the context: the directions u of forces through `point` for
/// which fixed + lambda u lies in E_goal for some lambda >= 0 (or its limit), split into unique and
/// shared arcs when the modes are given. Exact as above.
[[nodiscard]] DirectionPlan plan_directions_through(const Rational2& point, const ModeForces& goal, const PlanContext& context);
/// The same with planned_set(goal, context) given, for a caller that needs it too.
[[nodiscard]] DirectionPlan plan_directions_through(const Rational2& point, const ModeForces& goal, const PlanContext& context,
                                                    const Cone& planned);

/// The magnitudes lambda >= 0 of the force through `point` along `direction` (both exact) for
/// which the context's fixed wrench plus lambda times it lies in E_goal (magnitudes, with the
/// context's fixed_scale and the force's denominators scaled back). Precondition: context.fixed.
[[nodiscard]] std::optional<MagnitudeRange> magnitudes_through(const ModeForces& goal, const PlanContext& context,
                                                               const Rational2& point, const Rational2& direction);

/// Force directions counter-clockwise from `from` to `to` (radians from +x, from in [-pi, pi),
/// to - from in [0, 2 pi)).
struct DirectionRange {
    double from = 0.0;
    double to = 0.0;
};

}  // namespace momentlab
