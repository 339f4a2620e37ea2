// Directions of forces through a point in a goal's E (planning/directions.hpp).
#include "momentlab/planning/directions.hpp"

#include <algorithm>
#include <cmath>

#include "momentlab/core/predicates.hpp"
#include "momentlab/geometry/force_sets.hpp"

namespace momentlab {
namespace {

double angle_of(const Vec2& d) { return std::atan2(d.y(), d.x()); }

// The force of a wrench, rounded, with -0 written as 0: atan2 reads (-1, -0) as -pi, which
// would turn an arc ending at pi into one wrapping through it.
Vec2 force_of(const ExactVector& w) { return Vec2(w.value().x() + 0.0, w.value().y() + 0.0); }

// The arc counter-clockwise from a to b, split at pi; a == b is the one direction a (an arc
// of width 0, not the full turn).
void add_arc(std::vector<AngleInterval>& out, const Vec2& a, const Vec2& b, bool full_turn = false) {
    double from = angle_of(a), to = angle_of(b);
    if (from == M_PI) from = -M_PI;
    if (full_turn) {
        out.push_back({-M_PI, M_PI, a, a});
        return;
    }
    if (a == b) {
        out.push_back({from, from, a, b});
        return;
    }
    if (to < from) {  // through pi
        out.push_back({from, M_PI, a, Vec2(-1.0, 0.0)});
        out.push_back({-M_PI, to, Vec2(-1.0, 0.0), b});
        return;
    }
    out.push_back({from, to, a, b});
}

}  // namespace

DirectionPlan plan_directions_through(const Vec2& point, const Cone& goal_applied) {
    DirectionPlan plan;
    plan.actions = forces_through_point(point);
    plan.solutions = intersection(plan.actions, goal_applied);
    const Cone& s = plan.solutions;
    // W holds no pure moment, so every non-zero wrench of W ∩ E has a force: a direction.
    if (s.is_zero()) return plan;
    double width = 0.0;
    Vec2 start = Vec2::Zero();
    if (s.lineality_dimension() == 2) {
        start = force_of(s.lineality()[0]);
        add_arc(plan.intervals, start, start, true);
        plan.best = 0.0;
        plan.margin = M_PI;
        return plan;
    }
    if (s.lineality_dimension() == 1) {  // a line of W, and maybe a half-plane of it
        const Vec2 d = force_of(s.lineality()[0]);
        if (s.rays().empty()) {  // two opposite directions
            add_arc(plan.intervals, d, d);
            add_arc(plan.intervals, -d, -d);
            plan.best = angle_of(d);
            return plan;
        }
        // The half-plane on the side of its ray: counter-clockwise from d to -d if the ray is
        // to the left of d (exact).
        const bool left = minor_sign(s.lineality()[0], s.rays()[0], 0, 1) == Sign::Positive;
        start = left ? d : Vec2(-d);
        add_arc(plan.intervals, start, -start);
        width = M_PI;
    } else if (s.rays().size() == 1) {
        start = force_of(s.rays()[0]);
        add_arc(plan.intervals, start, start);
    } else {  // a wedge of W: two rays, less than pi apart
        Vec2 a = force_of(s.rays()[0]), b = force_of(s.rays()[1]);
        if (minor_sign(s.rays()[0], s.rays()[1], 0, 1) == Sign::Negative) std::swap(a, b);
        start = a;
        add_arc(plan.intervals, a, b);
        // The width from the intervals' own angles (atan2 of each end), so that the best
        // direction lies inside them: acos of the ends' dot product loses half the digits for
        // nearly equal directions (a width of 2e-16 came out as 2e-8).
        width = 0.0;
        for (const AngleInterval& i : plan.intervals) width += i.to - i.from;
    }
    plan.margin = width / 2.0;
    plan.best = std::remainder(angle_of(start) + plan.margin, 2.0 * M_PI);
    return plan;
}

}  // namespace momentlab
