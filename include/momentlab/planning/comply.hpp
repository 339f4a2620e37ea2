#pragma once

/// \file
/// Synthesis by compliance (Mason 1991, section 3; docs/design.md, Synthesis): a linear spring with a
/// compliance centre c. The spring force acts along the line through c in the direction of the
/// effector's offset, so the achievable applied wrenches are the plane W_c of forces through c,
/// and the offsets that produce a goal mode i are the directions of W_c ∩ E_i: the lines of E_i
/// through c.
///
/// Which centres work at all is read off E_i's moment labels: the forces of E_i through c are
/// the zeros of c's moment functional on E_i. If c lies inside E_i's + region (or - region),
/// every force of E_i has a positive (negative) moment about it and no offset works; on a
/// region's boundary only forces on the boundary of E_i pass through c (a knife edge); at an
/// unlabelled point the line of forces through c cuts the interior of E_i (when E_i is
/// full-dimensional), and an interval of offsets works with a margin.

#include "momentlab/geometry/labels.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/planning/tilt.hpp"

namespace momentlab {

/// How well a compliance centre works for a goal.
enum class CentreVerdict {
    Works,     ///< unlabelled: an interval of offsets, some strictly inside E_goal
    Boundary,  ///< on the boundary of E_goal's + or - region: offsets on the boundary of E_goal only
    Fails,     ///< inside the + or - region: no offset
};

/// "works", "boundary" or "fails".
[[nodiscard]] const char* to_string(CentreVerdict v);

/// The offsets of a spring with compliance centre `centre` that produce `goal`.
struct ComplyPlan {
    Vec2 centre = Vec2::Zero();  ///< (rounded when given exactly)
    Label label = Label::None;  ///< E_goal's label at the centre (exact)
    CentreVerdict verdict = CentreVerdict::Fails;
    DirectionPlan directions;   ///< the offset (force) directions, radians from +x
};

/// The spring directions through `centre` that produce `goal`. The verdict comes from the exact
/// solution cone W_c ∩ E_goal ({0}: fails; meeting the interior of E_goal: works), which agrees
/// with the exact label of the centre: a centre labelled + or - on its region's boundary is a
/// Boundary case (some force of E_goal passes through it).
[[nodiscard]] ComplyPlan plan_comply(const ModeForces& goal, const Vec2& centre);

/// The same told the context (directions.hpp): unique and shared offsets with the modes; with a
/// fixed wrench, the label and verdict are those of the reachable directions E_goal + cone(-g)
/// (fixed_wrench.hpp), and the directions' magnitudes say how hard the spring must push.
[[nodiscard]] ComplyPlan plan_comply(const ModeForces& goal, const Vec2& centre, const PlanContext& context);
/// The same for a centre given exactly (a decimal as typed: 0.1 is 1/10).
[[nodiscard]] ComplyPlan plan_comply(const ModeForces& goal, const Rational2& centre, const PlanContext& context);

/// The labels of E_goal: the compliance centres that work are the points outside both regions
/// (docs/design.md, Synthesis); the regions are drawn and written as for any force set.
[[nodiscard]] Labels compliance_labels(const ModeForces& goal);
/// The same told the context: with a fixed wrench, the labels of E_goal + cone(-g), the directions
/// that give the goal at some magnitude (plan_comply's verdicts follow them).
[[nodiscard]] Labels compliance_labels(const ModeForces& goal, const PlanContext& context);

}  // namespace momentlab
