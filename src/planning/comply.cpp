#include "momentlab/planning/comply.hpp"

#include "momentlab/planning/push.hpp"

namespace momentlab {

const char* to_string(CentreVerdict v) {
    switch (v) {
        case CentreVerdict::Works: return "works";
        case CentreVerdict::Boundary: return "boundary";
        case CentreVerdict::Fails: return "fails";
    }
    return "?";
}

ComplyPlan plan_comply(const ModeForces& goal, const Vec2& centre) {
    ComplyPlan plan;
    plan.centre = centre;
    // The label of c: whether its moment functional or its negative lies in E_goal's dual cone
    // (the test Labels::at makes, without building the regions).
    const Cone dual = goal.applied.dual();
    const Vec3 moment = moment_functional(centre);
    const bool plus = dual.has(moment), minus = dual.has(Vec3(-moment));
    plan.label = plus && minus ? Label::Both : plus ? Label::Plus : minus ? Label::Minus : Label::None;
    plan.directions = plan_directions_through(centre, goal.applied);
    // W_c ∩ E_goal is exact: {0} exactly when c is strictly inside a labelled region, and it meets
    // the interior of E_goal (the test plan_push makes) exactly when c is unlabelled and E_goal is
    // full-dimensional.
    if (!plan.directions.feasible()) {
        plan.verdict = CentreVerdict::Fails;
    } else if (meets_interior(plan.directions.solutions, goal.applied)) {
        plan.verdict = CentreVerdict::Works;
    } else {
        plan.verdict = CentreVerdict::Boundary;
    }
    return plan;
}

Labels compliance_labels(const ModeForces& goal) { return Labels(goal.applied); }

}  // namespace momentlab
