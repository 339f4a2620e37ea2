// Tilts (planning/tilt.hpp): the forces through the centre of mass in E_goal.
#include "momentlab/planning/tilt.hpp"

#include <stdexcept>

namespace momentlab {

DirectionPlan plan_tilt(const Scene& scene, const ModeForces& goal) { return plan_tilt(scene, goal, PlanContext{}); }

DirectionPlan plan_tilt(const Scene& scene, const ModeForces& goal, const PlanContext& context) {
    if (!scene.body) throw std::invalid_argument("plan_tilt: the scene has no body");
    return plan_directions_through(scene.body->exact_com(), goal, context);
}

}  // namespace momentlab
