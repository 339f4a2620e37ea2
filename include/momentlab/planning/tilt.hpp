#pragma once

/// \file
/// Synthesis by tilting (Mason 1991, section 3, Example 1; DESIGN, Synthesis): gravity acts
/// through the centre of mass, so the achievable applied wrenches are the plane W of forces
/// through it (labels: the centre of mass, twice), and the tilts that produce a goal mode i are
/// W ∩ E_i.

#include <vector>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/dynamics.hpp"
#include "momentlab/mechanics/scene.hpp"

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

/// The tilts of the body that produce `goal` (an entry of analyze(scene)). The boundary
/// directions belong to the intervals (E_goal is closed): there the mode is shared with a
/// neighbour. Throws std::invalid_argument if the scene has no body.
[[nodiscard]] DirectionPlan plan_tilt(const Scene& scene, const ModeForces& goal);

}  // namespace momentlab
