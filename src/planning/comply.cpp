#include "momentlab/planning/comply.hpp"


namespace momentlab {

const char* to_string(CentreVerdict v) {
    switch (v) {
        case CentreVerdict::Works: return "works";
        case CentreVerdict::Boundary: return "boundary";
        case CentreVerdict::Fails: return "fails";
    }
    return "?";
}

ComplyPlan plan_comply(const ModeForces& goal, const Vec2& centre) { return plan_comply(goal, rational(centre), PlanContext{}); }

ComplyPlan plan_comply(const ModeForces& goal, const Vec2& centre, const PlanContext& context) {
    return plan_comply(goal, rational(centre), context);
}

ComplyPlan plan_comply(const ModeForces& goal, const Rational2& centre, const PlanContext& context) {
    const Cone target = planned_set(goal, context);
    ComplyPlan plan;
    plan.centre = to_double(centre);
    plan.label = moment_label(target, centre);  // without building the regions
    plan.directions = plan_directions_through(centre, goal, context, target);
    // W_c ∩ E_goal is exact: {0} exactly when c is strictly inside a labelled region, and it meets
    // the interior of E_goal (the test plan_push makes) exactly when c is unlabelled and E_goal is
    // full-dimensional.
    if (!plan.directions.feasible()) {
        plan.verdict = CentreVerdict::Fails;
    } else if (!plan.directions.knife_edge) {
        plan.verdict = CentreVerdict::Works;
    } else {
        plan.verdict = CentreVerdict::Boundary;
    }
    return plan;
}

Labels compliance_labels(const ModeForces& goal) { return Labels(goal.applied); }

Labels compliance_labels(const ModeForces& goal, const PlanContext& context) {
    return Labels(planned_set(goal, context));
}

}  // namespace momentlab
