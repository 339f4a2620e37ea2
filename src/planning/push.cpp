#include "momentlab/planning/push.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "momentlab/core/predicates.hpp"
#include "momentlab/geometry/force_sets.hpp"
#include "momentlab/geometry/polygon.hpp"
#include "momentlab/planning/unique.hpp"

namespace momentlab {
namespace {

Vec2 force_of(const Vec3& w) { return Vec2(w.x(), w.y()); }

bool in_obstacle(const std::vector<Polygon>& obstacles, const Vec2& p) {
    return std::any_of(obstacles.begin(), obstacles.end(), [&](const Polygon& o) { return in_closed_polygon(o, p); });
}

// The parts of the segment a-b (parameters s in [0, 1]) that a point finger can touch: the
// closures of the maximal runs of points lying in no closed obstacle. The breakpoints (where
// the segment meets obstacle edges) are rounded; which side of them is free is decided exactly
// for the rounded points tested. A degenerate segment (a vertex) is free or not.
struct FreeParts {
    std::vector<std::pair<double, double>> parts;
    bool all_free = true;  ///< no point of the segment lies in an obstacle
};

FreeParts free_parts(const Vec2& a, const Vec2& b, const std::vector<Polygon>& obstacles) {
    if (a == b) {
        if (in_obstacle(obstacles, a)) return {{}, false};
        return {{{0.0, 0.0}}, true};
    }
    const Vec2 d = b - a;
    std::vector<double> s = {0.0, 1.0};
    const auto add = [&](double t) {
        if (t > 0.0 && t < 1.0) s.push_back(t);
    };
    for (const Polygon& o : obstacles) {
        for (std::size_t k = 0; k < o.size(); ++k) {
            const Vec2 c = o[k], e = o[(k + 1) % o.size()] - c;
            const double denom = cross2(d, e);
            if (denom != 0.0) {
                const double t = cross2(c - a, e) / denom, u = cross2(c - a, d) / denom;
                if (u >= 0.0 && u <= 1.0) add(t);
            } else if (orient2d(a, b, c) == Sign::Zero) {  // collinear: where the obstacle edge's ends project
                add((c - a).dot(d) / d.squaredNorm());
                add((c + e - a).dot(d) / d.squaredNorm());
            }
        }
    }
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    // Walk point 0, gap 0, point 1, ..., point K; merge free elements into runs.
    FreeParts out;
    auto& parts = out.parts;
    bool open = false;
    const auto visit = [&](bool free, double left, double right) {
        out.all_free = out.all_free && free;
        if (free && open) {
            parts.back().second = right;
        } else if (free) {
            parts.emplace_back(left, right);
        }
        open = free;
    };
    for (std::size_t k = 0; k < s.size(); ++k) {
        visit(!in_obstacle(obstacles, a + s[k] * d), s[k], s[k]);
        if (k + 1 < s.size()) visit(!in_obstacle(obstacles, a + (0.5 * (s[k] + s[k + 1])) * d), s[k], s[k + 1]);
    }
    return out;
}

// A feature's ends exactly (the outline's vertices as typed; a vertex twice).
struct Ends {
    Rational2 from, to;
};

// The cones of forces of a finger on vertex v whose inward normals run counter-clockwise from
// `cw` to `ccw` (the two edges' normals). An arc of pi or more (a sticking finger on a sharp
// vertex) is split at the bisector, so that each part is convex. At a notch the sticking
// finger touches both edges: the sum of their cones.
std::vector<Cone> vertex_actions(const Rational2& v, const Exact2& cw, const Exact2& ccw, const Exact2& bisector, ContactMode slip,
                                 const Rational& mu, bool reflex) {
    if (reflex) {
        return {forces_across(v, v, {friction_edge(cw, mu, true), friction_edge(cw, mu, false),
                                     friction_edge(ccw, mu, true), friction_edge(ccw, mu, false)})};
    }
    const bool left = opposing_friction(slip) > 0;
    if (slip != ContactMode::Fixed) return {forces_across(v, v, {friction_edge(cw, mu, left), friction_edge(ccw, mu, left)})};
    const Exact2 first = friction_edge(cw, mu, true), last = friction_edge(ccw, mu, false);
    if (cross2(first, last).sign() == Sign::Positive) return {forces_across(v, v, {first, last})};
    return {forces_across(v, v, {first, bisector}), forces_across(v, v, {bisector, last})};
}

// The parameter along the edge a-b where the line of action of w crosses it.
double touch_parameter(const PushFeature& f, const Vec3& w) {
    const Vec2 force = force_of(w), d = f.to - f.from;
    return (w.z() - cross2(f.from, force)) / cross2(d, force);
}

Vec3 unit_force(const Vec3& w) { return w / force_of(w).norm(); }

double relative_angle(const Vec2& reference, const Vec2& d) { return std::atan2(cross2(reference, d), reference.dot(d)); }

// The push of the wrench w on the feature: its unit force, at the point where its line of action
// meets the feature (clamped to an edge's ends; a vertex itself).
Push push_of(const PushFeature& f, const Vec3& w) {
    Push push;
    push.direction = force_of(w).normalized();
    push.point = f.kind == PushFeature::Kind::Edge ? Vec2(f.from + std::clamp(touch_parameter(f, w), 0.0, 1.0) * (f.to - f.from))
                                                   : f.from;
    return push;
}

// The mean of the solution cone's extreme unit forces (in its relative interior, up to
// rounding), as a force and the point of the feature where its line of action meets it.
Push representative(const PushFeature& f, const Cone& solutions) {
    Vec3 mean = Vec3::Zero();
    for (const Vec3& w : solutions.generator_values()) mean += unit_force(w);
    return push_of(f, mean);
}

}  // namespace

namespace {

// A finger's forces on the segment a-b with the exact inward normal `normal`.
Cone edge_actions(const Rational2& a, const Rational2& b, const Exact2& normal, ContactMode slip, const Rational& mu) {
    if (slip != ContactMode::Fixed) return forces_across(a, b, {friction_edge(normal, mu, opposing_friction(slip) > 0)});
    return forces_across(a, b, {friction_edge(normal, mu, true), friction_edge(normal, mu, false)});
}

}  // namespace

Cone push_actions(const Vec2& a, const Vec2& b, const Vec2& normal, ContactMode slip, double mu) {
    if (slip == ContactMode::Separating) throw std::invalid_argument("push_actions: slip must be l, f or r");
    if (!(mu >= 0.0) || !std::isfinite(mu)) throw std::invalid_argument("push_actions: mu must be finite and >= 0");
    if (!normal.allFinite() || is_zero(normal)) throw std::invalid_argument("push_actions: the normal must be non-zero");
    return edge_actions(rational(a), rational(b), exact(normal), slip, Rational(mu));
}

std::string PushFeature::name() const { return (kind == Kind::Edge ? "edge " : "vertex ") + std::to_string(index); }

const char* to_string(PushVerdict v) {
    switch (v) {
        case PushVerdict::Feasible: return "feasible";
        case PushVerdict::Boundary: return "boundary";
        case PushVerdict::Blocked: return "blocked";
        case PushVerdict::Infeasible: return "no";
        case PushVerdict::Reflex: return "reflex";
    }
    return "?";
}

Vec3 Push::wrench() const { return wrench_at(point, direction); }

namespace {

// The pieces of one case on the given parts of its feature (parameters along an edge).
std::vector<PushPiece> solve_pieces(const PushFeature& f, const Ends& ends, const Exact2& cw, const Exact2& ccw,
                                    const Exact2& bisector, ContactMode slip, const Rational& mu,
                                    const std::vector<std::pair<double, double>>& parts, const Cone& goal,
                                    const std::vector<Polygon>* obstacles, bool interior_possible) {
    std::vector<PushPiece> pieces;
    for (const auto& [lo, hi] : parts) {
        // The feature's own ends (as typed) where the part reaches them (a + 1.0 (b - a) can
        // round off b); the ends of a part cut by obstacles are points found in doubles.
        const Vec2 p = lo == 0.0 ? f.from : Vec2(f.from + lo * (f.to - f.from));
        const Vec2 q = hi == 1.0 ? f.to : Vec2(f.from + hi * (f.to - f.from));
        const Rational2 exact_p = lo == 0.0 ? ends.from : rational(p), exact_q = hi == 1.0 ? ends.to : rational(q);
        const std::vector<Cone> cones = f.kind == PushFeature::Kind::Edge
                                            ? std::vector<Cone>{edge_actions(exact_p, exact_q, cw, slip, mu)}
                                            : vertex_actions(ends.from, cw, ccw, bisector, slip, mu, f.reflex);
        for (const Cone& w : cones) {
            PushPiece piece{p, q, w, intersection(w, goal), false, std::nullopt};
            // Robust: the solutions meet the interior of E_goal, and a concrete push, the rounded
            // representative, lies there exactly (where the finger is free). A sliver that only
            // rounding opened (inputs that are not dyadic) has no such push: it is a boundary case.
            if (interior_possible && meets_interior(piece.solutions, goal)) {
                piece.representative = representative(f, piece.solutions);
                piece.robust = goal.in_relative_interior(piece.representative->wrench()) &&
                               !(obstacles && in_obstacle(*obstacles, piece.representative->point));
            }
            pieces.push_back(std::move(piece));
        }
    }
    return pieces;
}

// Where the lines of action of the cones' extreme rays meet the feature (segments: one per cone
// on an edge, the vertex once) and the range of their directions.
struct Extents {
    std::vector<std::pair<Vec2, Vec2>> touch;
    std::optional<DirectionRange> directions;
};

// Where the line of action of the exact wrench w = (F, tau) crosses the edge from a to b: the
// parameter s = (tau - a x F) / ((b - a) x F), exactly (the edge's ends as typed); none for a
// force along the edge (not a push across it).
std::optional<Rational> touch_parameter(const Ends& ends, const ExactVector& w) {
    const Exact3 x = w.exact();
    Dyadic p, q;  // a = A / p, b - a = D / q with A, D integers
    const std::vector<Dyadic> a = clear_denominators(ends.from, &p);
    const std::vector<Dyadic> d = clear_denominators(Rational2{ends.to[0] - ends.from[0], ends.to[1] - ends.from[1]}, &q);
    // s = q (p tau - A x F) / (p (D x F))
    const Dyadic across = d[0] * x[1] - d[1] * x[0];
    if (across.is_zero()) return std::nullopt;
    return Rational::quotient(q * (p * x[2] - (a[0] * x[1] - a[1] * x[0])), p * across);
}

Extents extents(const PushFeature& f, const Ends& ends, const std::vector<const Cone*>& cones) {
    Extents out;
    double lo_angle = INFINITY, hi_angle = -INFINITY;
    const Rational zero, one(1.0);
    const auto clamped = [&](Rational s) { return compare(s, zero) < 0 ? zero : compare(s, one) > 0 ? one : s; };
    for (const Cone* cone : cones) {
        std::optional<Rational> s0, s1;
        for (const ExactVector& g : cone->generators()) {
            const Vec3 w = g.value();
            const std::optional<Rational> exact_s = f.kind == PushFeature::Kind::Edge ? touch_parameter(ends, g) : std::nullopt;
            if (exact_s) {
                const Rational s = clamped(*exact_s);
                if (!s0 || compare(s, *s0) < 0) s0 = s;
                if (!s1 || compare(s, *s1) > 0) s1 = s;
            }
            const double angle = relative_angle(f.normal, force_of(w));
            lo_angle = std::min(lo_angle, angle);
            hi_angle = std::max(hi_angle, angle);
        }
        if (f.kind == PushFeature::Kind::Vertex) {
            if (out.touch.empty()) out.touch.emplace_back(f.from, f.from);
        } else if (s0) {
            // The touch points exactly, correctly rounded (an end printed is the end's nearest double).
            const auto at = [&](const Rational& s) {
                return to_double(Rational2{ends.from[0] + s * (ends.to[0] - ends.from[0]), ends.from[1] + s * (ends.to[1] - ends.from[1])});
            };
            out.touch.emplace_back(at(*s0), at(*s1));
        }
    }
    if (lo_angle <= hi_angle) {
        double from = std::atan2(f.normal.y(), f.normal.x()) + lo_angle;
        const double width = hi_angle - lo_angle;
        from = std::remainder(from, 2.0 * M_PI);
        if (from >= M_PI) from -= 2.0 * M_PI;
        out.directions = DirectionRange{from, from + width};
    }
    return out;
}

// Touch segments, direction range and a representative push from the chosen pieces.
void describe(PushCase& c, const Ends& ends, const std::vector<const PushPiece*>& chosen) {
    std::vector<const Cone*> cones;
    for (const PushPiece* piece : chosen) cones.push_back(&piece->solutions);
    Extents e = extents(c.feature, ends, cones);
    c.touch = std::move(e.touch);
    c.directions = e.directions;
    if (!chosen.empty()) c.best = chosen.front()->representative ? *chosen.front()->representative
                                                                 : representative(c.feature, chosen.front()->solutions);
}

// Which of the shown pieces push into the goal alone, and a unique best push when one, rounded,
// still lies in E_goal's interior, in no other mode's set and where the finger is free: of the
// unique parts' representatives (the mean of each part's extreme unit forces), the one farthest
// from every boundary in the wrench metric when there is one, else the first.
void tell_uniqueness(PushCase& c, const Ends& ends, const std::vector<const PushPiece*>& shown, const ModeForces& goal,
                     std::span<const ModeForces> modes, const std::vector<Polygon>* obstacles, const WrenchMetric* metric) {
    c.uniqueness_known = true;
    std::vector<Cone> parts;
    double best_depth = -1.0;
    const auto consider = [&](const Push& push) {
        const Vec3 e = push.wrench();
        const bool alone = std::none_of(modes.begin(), modes.end(), [&](const ModeForces& m) {
            return m.mode.letters != goal.mode.letters && m.applied.has(e);
        });
        if (!alone || !goal.applied.in_relative_interior(e) || (obstacles && in_obstacle(*obstacles, push.point))) return;
        double depth = 0.0;
        if (metric) {
            const QueryMargins m = margins_of(modes, wrench_through(exact(push.point), exact(push.direction)), *metric);
            depth = m.to_other.value_or(std::numeric_limits<double>::infinity());
            for (const double inside : m.inside) depth = std::min(depth, inside);
        }
        if (!c.best_unique || depth > best_depth) {
            c.best = push;
            c.best_unique = true;
            best_depth = depth;
        }
    };
    for (const PushPiece* piece : shown) {
        Uniqueness u = uniqueness(piece->solutions, modes, goal);
        c.shared = c.shared || u.shared;
        if (!u.unique) continue;
        c.unique = true;
        if (metric || !c.best_unique) {
            consider(push_of(c.feature, u.representative->value()));
            for (const Cone& part : u.parts) {
                if (!metric && c.best_unique) break;
                consider(representative(c.feature, part));
            }
        }
        for (Cone& part : u.parts) parts.push_back(std::move(part));
    }
    std::vector<const Cone*> cones;
    for (const Cone& part : parts) cones.push_back(&part);
    Extents e = extents(c.feature, ends, cones);
    // The parts of a 3-D case overlap along the edge: their segments merged, in the edge's order.
    const Vec2 d = c.feature.to - c.feature.from;
    const auto along = [&](const Vec2& p) { return (p - c.feature.from).dot(d); };
    for (auto& [p, q] : e.touch) {
        if (along(q) < along(p)) std::swap(p, q);
    }
    std::sort(e.touch.begin(), e.touch.end(), [&](const auto& x, const auto& y) { return along(x.first) < along(y.first); });
    for (const auto& segment : e.touch) {
        if (!c.unique_touch.empty() && along(segment.first) <= along(c.unique_touch.back().second)) {
            if (along(segment.second) > along(c.unique_touch.back().second)) c.unique_touch.back().second = segment.second;
        } else {
            c.unique_touch.push_back(segment);
        }
    }
    c.unique_directions = e.directions;
}

thread_local std::size_t cases_solved = 0;

PushCase solve_case(const PushFeature& f, const Ends& ends, const Exact2& cw, const Exact2& ccw, const Exact2& bisector, ContactMode slip, const Rational& mu,
                    const std::optional<FreeParts>& free, const Cone& goal, const std::vector<Polygon>& obstacles,
                    const ModeForces& goal_mode, const PlanContext& context) {
    ++cases_solved;
    PushCase c;
    c.feature = f;
    c.slip = slip;
    if (f.reflex && slip != ContactMode::Fixed) {
        c.verdict = PushVerdict::Reflex;
        return c;
    }
    const std::vector<std::pair<double, double>> whole = {{0.0, f.kind == PushFeature::Kind::Edge ? 1.0 : 0.0}};
    // With a fixed wrench the cases are solved on E_goal + cone(-g), full-dimensional even when
    // E_goal is not; then no push puts g + lambda u inside E_goal: knife edges only.
    const bool interior_possible = !context.fixed || goal_mode.applied.dimension() == 3;
    c.pieces = solve_pieces(f, ends, cw, ccw, bisector, slip, mu, whole, goal, nullptr, interior_possible);
    const auto has_solutions = [](const PushPiece& p) { return !p.solutions.is_zero(); };
    const auto robust = [](const PushPiece& p) { return p.robust; };
    const bool robust_anywhere = std::any_of(c.pieces.begin(), c.pieces.end(), robust);
    c.verdict = robust_anywhere                                                    ? PushVerdict::Feasible
                : std::any_of(c.pieces.begin(), c.pieces.end(), has_solutions) ? PushVerdict::Boundary
                                                                                : PushVerdict::Infeasible;
    if (free) {
        c.blocked = free->parts.empty() ? "all" : free->all_free ? "none" : "part";
        if (robust_anywhere && !free->all_free) {
            auto reachable = solve_pieces(f, ends, cw, ccw, bisector, slip, mu, free->parts, goal, &obstacles, interior_possible);
            if (std::any_of(reachable.begin(), reachable.end(), robust)) {
                c.pieces = std::move(reachable);
            } else {
                c.verdict = PushVerdict::Blocked;  // described by the whole feature's solutions
            }
        }
    }
    std::vector<const PushPiece*> shown;
    for (const PushPiece& p : c.pieces) {
        if (c.verdict == PushVerdict::Feasible ? p.robust : has_solutions(p)) shown.push_back(&p);
    }
    describe(c, ends, shown);
    if (!context.modes.empty() && !context.fixed && !shown.empty()) {
        tell_uniqueness(c, ends, shown, goal_mode, context.modes, free ? &obstacles : nullptr, context.metric ? &*context.metric : nullptr);
    }
    if (!context.modes.empty() && !context.fixed && context.metric && c.best) {
        c.best_margins = margins_of(context.modes, wrench_through(exact(c.best->point), exact(c.best->direction)), *context.metric);
    }
    c.magnitudes_known = context.fixed.has_value();
    if (context.fixed && c.best) c.best_magnitudes = magnitudes_through(goal_mode, context, rational(c.best->point), rational(c.best->direction));
    return c;
}

}  // namespace

std::size_t push_cases_solved() { return cases_solved; }

std::vector<PushCase> plan_push(const Scene& scene, const ModeForces& goal, const PushOptions& options) {
    return plan_push(scene, goal, options, PlanContext{});
}

std::vector<PushCase> plan_push(const Scene& scene, const ModeForces& goal, const PushOptions& options,
                                const PlanContext& context) {
    std::vector<PushCase> cases;
    plan_push(scene, goal, options, context, [&](PushCase&& c) { cases.push_back(std::move(c)); });
    return cases;
}

void plan_push(const Scene& scene, const ModeForces& goal, const PushOptions& options, const PlanContext& context,
               const std::function<void(PushCase&&)>& each) {
    if (!scene.body || scene.body->polygon.size() < 3) throw std::invalid_argument("plan_push: the body needs a polygon");
    if (options.mu.sign() == Sign::Negative) throw std::invalid_argument("plan_push: mu must be >= 0");
    const Polygon& poly = scene.body->polygon;
    const std::size_t n = poly.size();
    if (options.feature && options.feature->index >= n) {
        throw std::invalid_argument("plan_push: the body has " +
                                    std::string(options.feature->kind == PushFeature::Kind::Edge ? "edges" : "vertices") +
                                    " 0 .. " + std::to_string(n - 1));
    }
    if (options.slip == ContactMode::Separating) throw std::invalid_argument("plan_push: the slip must be l, f or r");
    const bool ccw = is_counter_clockwise(poly);
    const Cone target = planned_set(goal, context);
    const std::vector<Rational2> typed = scene.body->exact_polygon();  // the vertices as typed
    // The inward normal of edge i, exact (not unit: every condition is homogeneous in it; the
    // edge's denominators cleared), and its unit rounding for the feature's description.
    const auto normal = [&](std::size_t i) {
        const Rational2 &a = typed[i], &b = typed[(i + 1) % n];
        const std::vector<Dyadic> d = clear_denominators(Rational2{b[0] - a[0], b[1] - a[1]});
        return ccw ? Exact2{-d[1], d[0]} : Exact2{d[1], -d[0]};
    };
    const auto unit = [](const Exact2& n_exact) -> Vec2 { return to_double(n_exact).normalized(); };
    for (PushFeature::Kind kind : {PushFeature::Kind::Edge, PushFeature::Kind::Vertex}) {
        if (options.feature && options.feature->kind != kind) continue;
        const std::size_t first = options.feature ? options.feature->index : 0;
        const std::size_t last = options.feature ? first + 1 : n;
        for (std::size_t i = first; i < last; ++i) {
            PushFeature f;
            Exact2 cw = normal(i), ccw_normal = cw, bisector = cw;
            if (kind == PushFeature::Kind::Edge) {
                f = {PushFeature::Kind::Edge, i, poly[i], poly[(i + 1) % n], unit(cw), false};
            } else {
                const Exact2 in = normal((i + n - 1) % n), out = cw;
                const Rational2 &p = typed[(i + n - 1) % n], &v = typed[i], &q = typed[(i + 1) % n];
                const Sign turn = ((v[0] - p[0]) * (q[1] - v[1]) - (v[1] - p[1]) * (q[0] - v[0])).sign();
                const bool reflex = turn == (ccw ? Sign::Negative : Sign::Positive);
                // Convex: the normals turn counter-clockwise from n_in to n_out on a
                // counter-clockwise outline, clockwise on a clockwise one.
                cw = ccw ? in : out;
                ccw_normal = ccw ? out : in;
                if (reflex) std::swap(cw, ccw_normal);
                // The split direction of a wide arc: strictly inside it (the sum of the unit
                // normals, rounded, is far from both ends there); the same exact vector bounds
                // both halves, so their union is the whole arc.
                const Vec2 unit_bisector = (unit(in) + unit(out)).normalized();
                bisector = exact(unit_bisector);
                f = {PushFeature::Kind::Vertex, i, poly[i], poly[i], unit_bisector, reflex};
            }
            // The parts a finger can reach, once per feature (not when interference is ignored).
            const std::optional<FreeParts> free =
                options.ignore_interference ? std::nullopt : std::optional(free_parts(f.from, f.to, scene.obstacles));
            for (ContactMode slip : {ContactMode::SlidingLeft, ContactMode::Fixed, ContactMode::SlidingRight}) {
                if (options.slip && *options.slip != slip) continue;
                const Ends ends{typed[i], kind == PushFeature::Kind::Edge ? typed[(i + 1) % n] : typed[i]};
                each(solve_case(f, ends, cw, ccw_normal, bisector, slip, options.mu, free, target, scene.obstacles, goal, context));
            }
        }
    }
}

}  // namespace momentlab
