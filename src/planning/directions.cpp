// Directions of forces through a point in a goal's E (planning/directions.hpp).
#include "momentlab/planning/directions.hpp"

#include <algorithm>
#include <cmath>

#include "momentlab/core/predicates.hpp"
#include "momentlab/geometry/angular_order.hpp"
#include "momentlab/geometry/force_sets.hpp"
#include "momentlab/geometry/labels.hpp"
#include "momentlab/planning/unique.hpp"

namespace momentlab {
namespace {

double angle_of(const Vec2& d) { return std::atan2(d.y(), d.x()); }

// The force of a wrench, rounded, with -0 written as 0: atan2 reads (-1, -0) as -pi, which
// would turn an arc ending at pi into one wrapping through it.
Vec2 force_of(const ExactVector& w) { return Vec2(w.value().x() + 0.0, w.value().y() + 0.0); }

// How b lies from a, counter-clockwise, decided exactly: the same direction, less than a
// half-turn, a half-turn, or more; the value is b's angular_half from a.
enum class Turn { Same = 0, Narrow = 1, Half = 2, Wide = 3 };

// The width of the arc counter-clockwise from a to b, from the rounded angles, kept within the
// range its exact turn allows (rounding can swap two nearly equal directions, which would turn
// a sliver into nearly the whole turn, or the reverse).
double arc_width(const Vec2& a, const Vec2& b, Turn turn) {
    if (turn == Turn::Same) return 0.0;
    if (turn == Turn::Half) return M_PI;
    double w = angle_of(b) - angle_of(a);
    if (w < 0.0) w += 2.0 * M_PI;
    if (turn == Turn::Narrow) return w >= M_PI ? 0.0 : w;
    return w <= M_PI ? 2.0 * M_PI : w;
}

// The arc counter-clockwise from a to b (its exact turn given), split at pi; a single direction
// is an arc of width 0; the whole turn is [-pi, pi].
void add_arc(std::vector<AngleInterval>& out, const Vec2& a, const Vec2& b, Turn turn, bool full_turn = false) {
    double from = angle_of(a);
    if (from == M_PI) from = -M_PI;
    const double width = full_turn ? 2.0 * M_PI : arc_width(a, b, turn);
    if (width >= 2.0 * M_PI) {
        out.push_back({-M_PI, M_PI, a, a});
        return;
    }
    const double to = from + width;
    if (to <= M_PI) {
        out.push_back({from, turn == Turn::Same ? from : to, a, b});
        return;
    }
    out.push_back({from, M_PI, a, Vec2(-1.0, 0.0)});  // through pi
    out.push_back({-M_PI, to - 2.0 * M_PI, Vec2(-1.0, 0.0), b});
}

}  // namespace

DirectionPlan plan_directions_through(const Rational2& point, const Cone& goal_applied) {
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
        add_arc(plan.intervals, start, start, Turn::Same, true);
        plan.best = 0.0;
        plan.margin = M_PI;
        return plan;
    }
    if (s.lineality_dimension() == 1) {  // a line of W, and maybe a half-plane of it
        const Vec2 d = force_of(s.lineality()[0]);
        if (s.rays().empty()) {  // two opposite directions
            add_arc(plan.intervals, d, d, Turn::Same);
            add_arc(plan.intervals, -d, -d, Turn::Same);
            plan.best = angle_of(d);
            return plan;
        }
        // The half-plane on the side of its ray: counter-clockwise from d to -d if the ray is
        // to the left of d (exact).
        const bool left = minor_sign(s.lineality()[0], s.rays()[0], 0, 1) == Sign::Positive;
        start = left ? d : Vec2(-d);
        add_arc(plan.intervals, start, -start, Turn::Half);
        width = M_PI;
    } else if (s.rays().size() == 1) {
        start = force_of(s.rays()[0]);
        add_arc(plan.intervals, start, start, Turn::Same);
    } else {  // a wedge of W: two rays, less than pi apart
        Vec2 a = force_of(s.rays()[0]), b = force_of(s.rays()[1]);
        if (minor_sign(s.rays()[0], s.rays()[1], 0, 1) == Sign::Negative) std::swap(a, b);
        start = a;
        add_arc(plan.intervals, a, b, Turn::Narrow);
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

namespace {

// The arcs of a plane (normal nu) as angle intervals, and the widest arc of positive width
// (start angle, width), if any.
std::optional<std::pair<double, double>> add_arcs(std::vector<AngleInterval>& out, const ExactVector& nu,
                                                   const std::vector<WrenchArc>& arcs) {
    std::optional<std::pair<double, double>> widest;
    for (const WrenchArc& arc : arcs) {
        const Vec2 from = force_of(arc.from), to = force_of(arc.to);
        const auto along = [&] { return dot_sign(arc.from, arc.to) == Sign::Positive; };
        const auto turn = static_cast<Turn>(angular_half(det_sign(nu, arc.from, arc.to), along));
        add_arc(out, from, to, turn, arc.whole);
        const double width = arc.whole ? 2.0 * M_PI : arc_width(from, to, turn);
        if (width > 0.0 && (!widest || width > widest->second)) widest = std::pair(angle_of(from), width);
    }
    return widest;
}

}  // namespace

Cone planned_set(const ModeForces& goal, const PlanContext& context) {
    return context.fixed ? reachable_directions(goal.applied, *context.fixed) : goal.applied;
}

std::optional<MagnitudeRange> magnitudes_through(const ModeForces& goal, const PlanContext& context,
                                                const Rational2& point, const Rational2& direction) {
    Dyadic s_u;
    const std::vector<Dyadic> c = clear_denominators(
        Rational3{direction[0], direction[1], point[0] * direction[1] - point[1] * direction[0]}, &s_u);
    std::optional<MagnitudeRange> r = magnitudes(goal.applied, *context.fixed, Exact3{c[0], c[1], c[2]});
    if (!r) return r;
    r->lo = r->lo.scaled_back(s_u, context.fixed_scale);
    if (r->hi) r->hi = r->hi->scaled_back(s_u, context.fixed_scale);
    return r;
}

DirectionPlan plan_directions_through(const Rational2& point, const ModeForces& goal, const PlanContext& context) {
    return plan_directions_through(point, goal, context, planned_set(goal, context));
}

DirectionPlan plan_directions_through(const Rational2& point, const ModeForces& goal, const PlanContext& context,
                                      const Cone& target) {
    DirectionPlan plan = plan_directions_through(point, target);
    if (!plan.feasible()) return plan;
    // A knife edge: no solution inside E_goal (with a fixed wrench: no g + lambda u inside it, which
    // needs a full-dimensional E_goal and a direction inside E_goal + cone(-g)).
    plan.knife_edge = !meets_interior(plan.solutions, target) || (context.fixed && goal.applied.dimension() < 3);
    if (!context.modes.empty() && !context.fixed) {
        // The plane of forces through the point, oriented so that counter-clockwise forces turn
        // positively about its normal (p.y, -p.x, 1).
        const ExactVector normal = moment_functional(point);
        const PlaneSplit split = split_plane(normal, plan.solutions, context.modes, goal);
        plan.uniqueness_known = true;
        const auto widest = add_arcs(plan.unique, normal, split.unique);
        add_arcs(plan.shared, normal, split.shared);
        if (widest) {
            plan.margin = widest->second / 2.0;
            plan.best = std::remainder(widest->first + plan.margin, 2.0 * M_PI);
            plan.best_unique = true;
        }
        if (context.metric && !plan.knife_edge) {  // (a knife edge's margins are 0)
            plan.best_margins =
                margins_of(context.modes, wrench_through(exact(to_double(point)), exact(Vec2(std::cos(plan.best), std::sin(plan.best)))),
                           *context.metric);
        }
    }
    if (plan.knife_edge) plan.margin = 0.0;
    if (plan.best >= M_PI) plan.best -= 2.0 * M_PI;  // [-pi, pi), as the intervals
    if (context.fixed) {
        // A single direction (a knife edge) exactly as found: its rounding may miss E_goal.
        const Cone& s = plan.solutions;
        const bool single = s.lineality_dimension() == 0 && s.rays().size() == 1;
        const Exact3 ray = single ? s.rays()[0].exact() : Exact3{};
        const Rational2 best = single ? Rational2{Rational(ray[0], Dyadic(1.0)), Rational(ray[1], Dyadic(1.0))}
                                      : rational(Vec2(std::cos(plan.best), std::sin(plan.best)));
        plan.best_magnitudes = magnitudes_through(goal, context, point, best);
        plan.magnitudes_known = true;
    }
    return plan;
}

}  // namespace momentlab
