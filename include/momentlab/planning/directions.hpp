#pragma once

/// \file
/// What the planners share (Mason 1991, section 3): intervals of force directions, and the
/// forces through one point that lie in a goal's set of applied wrenches (the tilts of
/// planning/tilt.hpp, the spring directions of planning/comply.hpp).

#include <vector>

#include "momentlab/core/vec.hpp"
#include "momentlab/geometry/cone.hpp"

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
    double best = 0.0;
    double margin = 0.0;
    [[nodiscard]] bool feasible() const { return !intervals.empty(); }
};

/// The directions of the forces through `point` that lie in `goal_applied` (an E_i). The
/// boundary directions belong to the intervals (E_i is closed).
[[nodiscard]] DirectionPlan plan_directions_through(const Vec2& point, const Cone& goal_applied);

/// Force directions counter-clockwise from `from` to `to` (radians from +x, from in [-pi, pi),
/// to - from in [0, 2 pi)).
struct DirectionRange {
    double from = 0.0;
    double to = 0.0;
};

}  // namespace momentlab
