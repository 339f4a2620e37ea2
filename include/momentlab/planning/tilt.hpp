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

}  // namespace momentlab
