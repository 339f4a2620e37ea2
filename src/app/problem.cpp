// Problem (app/problem.hpp): a scene, its analysis and index made on first need, and the checks
// and messages of every front end, once.
#include "momentlab/app/problem.hpp"

#include <algorithm>
#include <numeric>

#include "momentlab/io/scene_json.hpp"
#include "momentlab/mechanics/advanced.hpp"

namespace momentlab {
namespace {

// "$: missing field "body" (<why>)".
InputError missing_body(const std::string& why) { return InputError("$", "missing field \"body\" (" + why + ")"); }

bool fits_doubles(const Exact3& w) { return w[0].fits_double() && w[1].fits_double() && w[2].fits_double(); }

// The wrench times its common denominator (a positive number, received in `common`).
Exact3 cleared(const Rational3& w, Dyadic* common = nullptr) {
    const std::vector<Dyadic> e = clear_denominators(w, common);
    return {e[0], e[1], e[2]};
}

// The modes of the analysis (indices) as a QueryAnswer: letters sorted, twists alongside.
QueryAnswer answer_of(const std::vector<ModeForces>& analysis, std::vector<std::size_t> modes) {
    std::sort(modes.begin(), modes.end(),
              [&](std::size_t a, std::size_t b) { return analysis[a].mode.letters < analysis[b].mode.letters; });
    QueryAnswer out;
    for (std::size_t k : modes) {
        out.letters.push_back(analysis[k].mode.letters);
        out.twists.push_back(analysis[k].mode.twists);
    }
    out.verdict = verdict_of(modes.size());
    return out;
}

}  // namespace

InputNames InputNames::command_line() {
    InputNames n;
    for (std::string* s : {&n.goal, &n.mu, &n.gravity, &n.wrench, &n.force, &n.centre, &n.reference, &n.length, &n.edge, &n.vertex}) {
        *s = "--" + *s;
    }
    n.point = n.direction = "--push";
    return n;
}

Problem::Problem(Scene scene, bool quasi_static, InputNames names, Progress progress)
    : scene_(std::move(scene)), quasi_static_(quasi_static), names_(std::move(names)), progress_(std::move(progress)) {}

const std::vector<ModeForces>& Problem::analysis(const std::string& command) {
    if (!analysis_) analysis_ = analyze_input(scene_, command, AnalysisOptions{quasi_static_, progress_});
    return *analysis_;
}

const QueryIndex& Problem::index() {
    if (!index_) index_.emplace(analysis());
    return *index_;
}

const ModeForces& Problem::goal(const std::string& letters) { return find_mode(analysis(), letters, names_.goal); }

std::optional<Rational3> Problem::wrench_of(const Load& load) const {
    std::optional<Rational3> out;
    const auto add = [&](const Rational3& w) { out = out ? Rational3{(*out)[0] + w[0], (*out)[1] + w[1], (*out)[2] + w[2]} : w; };
    // The force f through p: (f, p x f).
    const auto through = [](const Rational2& p, const Rational2& f) { return Rational3{f[0], f[1], p[0] * f[1] - p[1] * f[0]}; };
    if (load.gravity) {
        (void)checked_vector(to_double(*load.gravity), names_.gravity);
        if (!scene_.body) throw missing_body(names_.gravity + " acts on its mass through its centre of mass");
        const Body& b = *scene_.body;
        const BodyValues* v = b.exact_values();
        const Rational m = v ? v->mass : Rational(b.mass);
        add(through(b.exact_com(), {m * (*load.gravity)[0], m * (*load.gravity)[1]}));
    }
    if (load.wrench) {
        (void)checked_vector(to_double(*load.wrench), names_.wrench);
        add(*load.wrench);
    }
    for (const auto& [point, force] : load.forces) {
        (void)checked_vector(to_double(point), names_.force);
        (void)checked_vector(to_double(force), names_.force);
        add(through(point, force));
    }
    return out;
}

QueryAnswer Problem::query(const Load& load) {
    const std::optional<Rational3> w = wrench_of(load);
    if (!w) throw InputError(names_.wrench, "expected the applied wrench (or gravity, or forces at points)");
    require_body(scene_, "query", AnalysisOptions{quasi_static_});
    // (a wrench beyond doubles is walked exactly too: no analysis of the scene)
    return momentlab::query(scene_, cleared(*w), AnalysisOptions{quasi_static_, progress_});
}

MarginAnswer Problem::margins(const Load& load) {
    const std::optional<Rational3> w = wrench_of(load);
    if (!w) throw InputError(names_.wrench, "expected the applied wrench (or gravity, or forces at points)");
    const std::vector<ModeForces>& a = analysis("query");
    const Exact3 e = cleared(*w);
    std::vector<std::size_t> modes;
    if (fits_doubles(e)) {
        modes = index().query(to_double(e)).modes;
    } else {
        const ExactVector v = ExactVector::from_exact(e);
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (a[i].applied.has(v)) modes.push_back(i);
        }
    }
    MarginAnswer out;
    out.metric = default_metric(scene_);
    const QueryMargins m = query_margins(a, modes, to_double(*w), out.metric);
    // In the answer's order (letters sorted).
    std::vector<std::size_t> order(modes.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return a[modes[x]].mode.letters < a[modes[y]].mode.letters; });
    for (std::size_t k : order) out.inside.push_back(m.inside[k]);
    out.to_other = m.to_other;
    out.answer = answer_of(a, std::move(modes));
    return out;
}

std::vector<MagnitudeBand> Problem::push_line(const Rational2& point, const Rational2& direction, const Load& load) {
    (void)checked_vector(to_double(point), names_.point);
    (void)checked_direction(to_double(direction), names_.direction);
    // g + lambda u with both cleared (Magnitude::scaled_back)
    const Rational3 fixed = wrench_of(load).value_or(Rational3{});
    const Rational3 u{direction[0], direction[1], point[0] * direction[1] - point[1] * direction[0]};
    Dyadic s_g, s_u;
    const Exact3 g = cleared(fixed, &s_g), cu = cleared(u, &s_u);
    std::vector<MagnitudeBand> bands = magnitude_bands(analysis("query"), g, cu);
    for (MagnitudeBand& b : bands) {
        b.from = b.from.scaled_back(s_u, s_g);
        if (b.to) b.to = b.to->scaled_back(s_u, s_g);
    }
    return bands;
}

PlanContext Problem::context(const Load& load) {
    PlanContext c;
    // exactly: a decimal load's denominators cleared (its directions), scaled back in magnitudes
    if (const std::optional<Rational3> w = wrench_of(load)) c.fixed = cleared(*w, &c.fixed_scale);
    c.modes = analysis();
    c.metric = default_metric(scene_);
    return c;
}

DirectionPlan Problem::plan_tilt(const std::string& goal_letters, const Load& load) {
    if (load.gravity) {
        throw InputError(names_.gravity, "a tilt turns gravity itself: give a fixed wrench acting besides it with " + names_.wrench);
    }
    if (!scene_.body) throw missing_body("plan tilt needs its centre of mass");
    const ModeForces& g = find_mode(analysis("plan tilt"), goal_letters, names_.goal);
    return momentlab::plan_tilt(scene_, g, context(load));
}

void Problem::plan_push(const std::string& goal_letters, const PushRequest& request, const Load& load,
                        const std::function<void(PushCase&&)>& each) {
    const Rational mu = checked_coefficient(request.mu, names_.mu);
    if (request.edge && request.vertex) throw InputError(names_.vertex, "give " + names_.edge + " or " + names_.vertex + ", not both");
    if (!scene_.body) throw missing_body("plan push needs its mass, com, inertia and polygon");
    const std::size_t n = scene_.body->polygon.size();
    if (n < 3) throw InputError("$.body.polygon", "plan push needs the body's polygon");
    if (request.edge && *request.edge >= n) throw InputError(names_.edge, "the body has edges 0 .. " + std::to_string(n - 1));
    if (request.vertex && *request.vertex >= n) throw InputError(names_.vertex, "the body has vertices 0 .. " + std::to_string(n - 1));
    const ModeForces& g = find_mode(analysis("plan push"), goal_letters, names_.goal);
    PushOptions options{mu, request.ignore_interference};
    if (request.edge) options.feature = PushFeatureId{PushFeature::Kind::Edge, *request.edge};
    if (request.vertex) options.feature = PushFeatureId{PushFeature::Kind::Vertex, *request.vertex};
    options.slip = request.slip;
    momentlab::plan_push(scene_, g, options, context(load), each);
}

std::vector<PushCase> Problem::plan_push(const std::string& goal_letters, const PushRequest& request, const Load& load) {
    std::vector<PushCase> cases;
    plan_push(goal_letters, request, load, [&cases](PushCase&& c) { cases.push_back(std::move(c)); });
    return cases;
}

ComplyAnswer Problem::plan_comply(const std::string& goal_letters, const std::optional<Rational2>& centre, const Load& load) {
    if (centre) (void)checked_vector(to_double(*centre), names_.centre);
    const ModeForces& g = find_mode(analysis("plan comply"), goal_letters, names_.goal);
    const PlanContext c = context(load);
    ComplyAnswer out{compliance_labels(g, c), std::nullopt};
    if (centre) out.centre = momentlab::plan_comply(g, *centre, c);
    return out;
}

Closure Problem::closure(const std::optional<Vec2>& reference, const std::optional<double>& length) const {
    ClosureOptions options;
    if (reference) options.reference = checked_vector(*reference, names_.reference);
    if (length) options.length = checked_length(*length, names_.length);
    return momentlab::closure(scene_, options);
}

}  // namespace momentlab
