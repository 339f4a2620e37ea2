#pragma once

/// \file
/// Synthesis by tilting (Mason 1991, section 3, Example 1; docs/design.md, Synthesis): gravity acts
/// through the centre of mass, so the achievable applied wrenches are the plane W of forces
/// through it (labels: the centre of mass, twice), and the tilts that produce a goal mode i are
/// W ∩ E_i.

#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/planning/directions.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// The tilts of the body that produce `goal` (an entry of analyze(scene)). The boundary
/// directions belong to the intervals (E_goal is closed): there the mode is shared with a
/// neighbour. Throws std::invalid_argument if the scene has no body.
[[nodiscard]] DirectionPlan plan_tilt(const Scene& scene, const ModeForces& goal);

/// The same told the context: with the modes, where the goal is unique; with a fixed wrench g
/// (not gravity itself, which is what the tilt turns: say a constant push), the directions of the
/// force through the centre of mass for which g plus that force, at some magnitude, gives the goal.
[[nodiscard]] DirectionPlan plan_tilt(const Scene& scene, const ModeForces& goal, const PlanContext& context);

}  // namespace momentlab
