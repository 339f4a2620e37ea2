// `momentlab plan tilt SCENE --goal MODE [--json] [-o FILE]...`: the tilts (gravity directions)
// that produce a goal mode (Mason 1991, section 3, Figure 5); `momentlab plan push SCENE --goal
// MODE [--mu M] [--edge I | --vertex I] [--slip l|f|r] [--ignore-interference]`: which features
// and finger slips push it there (Figure 6); `momentlab plan comply SCENE --goal MODE [--centre
// X Y]`: the spring directions through a compliance centre, and the centres that work.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "common.hpp"

namespace momentlab::cli {
namespace {

// The finger's mu when --mu is not given.
TypedNumber default_mu() {
    TypedNumber mu;
    mu.value = 0.5;
    return mu;
}

struct PlanOptions {
    std::string file;
    std::string goal;
    bool json = false;
    PictureOptions picture;
    TypedNumber mu = default_mu();  // exact as typed (0.1 is 1/10)
    std::optional<std::size_t> edge;
    std::optional<std::size_t> vertex;
    std::string slip;
    bool ignore_interference = false;
    std::vector<TypedNumber> centre;  // as typed: 0.1 is 1/10
    bool quasi_static = false;
    std::vector<TypedNumber> gravity;
    std::vector<TypedNumber> fixed;
    std::vector<TypedNumber> forces;
};

// Segments of a feature as text: "(0, 0.5) - (0, 0.25), (1, 0)" (a point once).
std::string segments_text(const std::vector<std::pair<Vec2, Vec2>>& segments) {
    std::string out;
    for (const auto& [p, q] : segments) out += (out.empty() ? "" : ", ") + (p == q ? fmt(p) : fmt(p) + " - " + fmt(q));
    return out;
}

// Arcs as text: "[0, 1.5708], 3.14159 only".
std::string arcs_text(const std::vector<AngleInterval>& arcs) {
    std::string out;
    for (const AngleInterval& i : arcs) {
        out += out.empty() ? "" : ", ";
        out += i.from == i.to ? fmt(i.from) + " only" : "[" + fmt(i.from) + ", " + fmt(i.to) + "]";
    }
    return out.empty() ? "none" : out;
}

// The margins of a best action (a unit force) in the wrench metric.
std::string margins_text(const QueryMargins& m) {
    const auto said = [](double d) { return std::isfinite(d) ? fmt(d) : std::string("unbounded"); };
    return "margin " + said(m.inside.empty() ? 0.0 : m.inside.front()) + " to the boundary of the goal's set, " +
           (m.to_other ? said(*m.to_other) : std::string("unbounded")) + " to the nearest other mode's set";
}

// The intervals, a single direction said as such; the best direction and its margin only when
// some direction lies inside E_goal (`knife_edge`: every solution is on its boundary).
void print_directions(const DirectionPlan& plan, bool knife_edge) {
    for (const AngleInterval& i : plan.intervals) {
        if (i.from == i.to) {
            std::cout << "  " << fmt(i.from) << "   (" << degrees(i.from) << "): this direction only\n";
        } else {
            std::cout << "  [" << fmt(i.from) << ", " << fmt(i.to) << "]   (" << degrees(i.from) << " .. "
                      << degrees(i.to) << ")\n";
        }
    }
    if (knife_edge) {
        std::cout << "  a knife edge: every such direction lies on the boundary of the goal's set, no margin\n";
    } else {
        std::cout << "  best " << fmt(plan.best) << " (" << degrees(plan.best) << "), margin " << fmt(plan.margin) << " ("
                  << degrees(plan.margin) << ") to the nearest "
                  << (plan.best_unique ? "direction where the goal is not alone" : "boundary") << "\n";
    }
    if (plan.uniqueness_known) {
        std::cout << "  the goal alone: " << arcs_text(plan.unique) << "\n  shared with another mode: " << arcs_text(plan.shared)
                  << "\n";
        if (!plan.best_unique && !knife_edge) std::cout << "  (no arc where the goal is alone: the best direction is shared)\n";
    }
    if (plan.best_margins && !knife_edge) {
        std::cout << "  the best direction as a unit force: " << margins_text(*plan.best_margins)
                  << " (docs/design.md, Margins)\n";
    }
    if (plan.magnitudes_known && !knife_edge) {
        std::cout << "  magnitudes along the best direction that give the goal: "
                  << (plan.best_magnitudes ? magnitude_text(*plan.best_magnitudes) : std::string("none (only in the limit)"))
                  << "\n";
    }
}

// The bands of magnitudes of the force through `point` (exact) along `angle`, added to the load.
void print_best_bands(Problem& p, const Load& load, const Rational2& point, double angle) {
    const Vec2 d(std::cos(angle), std::sin(angle));
    std::cout << "  along the best direction, the force's magnitude from 0 up (with the fixed wrench):\n";
    print_bands(p.push_line(point, rational(d), load), p.analysis());
}

// Every interval a single direction.
bool single_directions(const DirectionPlan& plan) {
    return std::all_of(plan.intervals.begin(), plan.intervals.end(),
                       [](const AngleInterval& i) { return i.from == i.to; });
}

int run_tilt(const PlanOptions& o) {
    const std::optional<Box> view = checked_picture_options(o.picture, {o.file});
    TerminalProgress progress;
    Problem p = open_problem(o.file, o.quasi_static, progress);
    const Load load = load_of(o.gravity, o.fixed, o.forces);
    const DirectionPlan plan = p.plan_tilt(o.goal, load);
    progress.finish();
    const Scene& scene = p.scene();
    const ModeForces& goal = p.goal(o.goal);
    const std::optional<Rational3> fixed = p.wrench_of(load);
    if (o.json) {
        nlohmann::json out = to_json(plan);
        out["goal"] = o.goal;
        if (fixed) out["fixed"] = vector_json(to_double(*fixed));
        if (fixed) add_exact(out, "fixed", *fixed);
        std::cout << out.dump() << "\n";
    } else if (!plan.feasible()) {
        std::cout << "no tilt produces mode " << o.goal << " (W \u2229 E is {0})\n";
    } else {
        std::cout << "tilts that produce mode " << o.goal
                  << ": gravity directions, radians from +x (boundaries shared with a neighbouring mode)\n";
        if (fixed) std::cout << "  with the fixed wrench " << fmt(to_double(*fixed)) << " acting too\n";
        print_directions(plan, plan.knife_edge || single_directions(plan));
        if (fixed) print_best_bands(p, load, scene.body->exact_com(), plan.best);
    }
    if (!o.picture.files.empty()) {
        const std::string title = o.picture.title.empty() ? stem(o.file) + ": tilts that produce mode " + o.goal
                                                          : o.picture.title;
        write_picture(render::tilt_figure(title, scene, goal, plan, view), o.picture);
    }
    return 0;
}

int run_comply(const PlanOptions& o) {
    const std::optional<Box> view = checked_picture_options(o.picture, {o.file});
    const std::vector<Rational2> centre = o.centre.empty() ? std::vector<Rational2>{} : checked_points(o.centre, "--centre", 1);
    if (!o.picture.files.empty() && centre.empty()) throw InputError("-o", "a picture shows one centre: give --centre X Y");
    TerminalProgress progress;
    Problem p = open_problem(o.file, o.quasi_static, progress);
    const Load load = load_of(o.gravity, o.fixed, o.forces);
    const ComplyAnswer answer = p.plan_comply(o.goal, centre.empty() ? std::nullopt : std::optional<Rational2>(centre.front()), load);
    progress.finish();
    const Scene& scene = p.scene();
    const ModeForces& goal = p.goal(o.goal);
    const std::optional<Rational3> fixed = p.wrench_of(load);
    const Labels& region = answer.labels;
    const std::optional<ComplyPlan>& plan = answer.centre;
    if (o.json) {
        nlohmann::json out = {{"goal", o.goal}, {"labels", to_json(region)}};
        if (plan) {
            out["centre"] = to_json(*plan);
            add_exact(out["centre"], "point", centre.front());
        }
        std::cout << out.dump() << "\n";
    } else {
        std::cout << "compliance centres for mode " << o.goal << ": those outside both labelled regions of E_" << o.goal
                  << (fixed ? " + cone(-g) (g the fixed wrench " + fmt(to_double(*fixed)) + ")" : std::string())
                  << " work (on a region's boundary only as a knife edge)\n"
                  << "  + region " << region_text(region.plus()) << "\n"
                  << "  - region " << region_text(region.minus()) << "\n";
        if (plan) {
            std::cout << "centre " << fmt(plan->centre) << ": label " << to_string(plan->label) << ", "
                      << to_string(plan->verdict);
            if (!plan->directions.feasible()) {
                std::cout << " (no spring direction through it produces mode " << o.goal << ")\n";
            } else {
                std::cout << "; spring force (offset) directions, radians from +x:\n";
                print_directions(plan->directions, plan->verdict != CentreVerdict::Works);
                if (fixed) print_best_bands(p, load, centre.front(), plan->directions.best);
            }
        }
    }
    if (plan && !o.picture.files.empty()) {
        const std::string title = o.picture.title.empty()
                                      ? stem(o.file) + ": compliance centre " + fmt(plan->centre) + " for mode " + o.goal
                                      : o.picture.title;
        write_picture(render::comply_figure(title, scene, goal, *plan, view), o.picture);
    }
    return 0;
}

std::string case_line(const PushCase& c) {
    std::ostringstream s;
    s << "  " << std::left << std::setw(10) << c.feature.name() << std::setw(6) << letter(c.slip) << std::setw(10)
      << to_string(c.verdict);
    if (c.uniqueness_known) s << std::setw(8) << (c.unique && c.shared ? "both" : c.unique ? "alone" : c.shared ? "shared" : "");
    s << std::setw(34) << segments_text(c.touch);
    if (c.directions) s << degrees(c.directions->from) << " .. " << degrees(c.directions->to);
    if (c.blocked == "part" || c.blocked == "all") s << "   [" << c.blocked << " of it in obstacles]";
    std::string line = s.str();
    while (!line.empty() && line.back() == ' ') line.pop_back();
    return line;
}

// A feasible case's best push, as measured: its direction and point with every digit (17
// significant: they read back as the same doubles), so that `query --push` at the printed push
// gives the printed magnitudes.
std::string best_push_line(const PushCase& c) {
    if (!c.best || c.verdict != PushVerdict::Feasible) return "";
    std::ostringstream s;
    s << "  " << c.feature.name() << " slip " << letter(c.slip) << ": best push " << fmt(c.best->direction, 17) << " at "
      << fmt(c.best->point, 17) << (c.best_unique ? " (the goal alone)" : "");
    if (c.unique && c.unique_directions) {
        s << "; the goal alone touching " << segments_text(c.unique_touch) << ", directions "
          << degrees(c.unique_directions->from) << " .. " << degrees(c.unique_directions->to);
    }
    if (c.best_margins) s << "; as a unit force, " << margins_text(*c.best_margins);
    if (c.magnitudes_known) {
        s << "; magnitudes " << (c.best_magnitudes ? magnitude_text(*c.best_magnitudes) : std::string("none (only in the limit)"));
    }
    s << "\n";
    return s.str();
}

int run_push(const PlanOptions& o) {
    const std::optional<Box> view = checked_picture_options(o.picture, {o.file});
    if (!o.picture.files.empty() && ((!o.edge && !o.vertex) || o.slip.empty())) {
        throw InputError("-o", "a picture shows one case: give --edge or --vertex, and --slip");
    }
    TerminalProgress progress;
    Problem p = open_problem(o.file, o.quasi_static, progress);
    const Load load = load_of(o.gravity, o.fixed, o.forces);
    PushRequest request{o.mu.rational(), o.ignore_interference, o.edge, o.vertex, std::nullopt};
    if (!o.slip.empty()) request.slip = contact_mode(o.slip[0]);
    const Scene& scene = p.scene();
    const std::vector<ModeForces>& analysis = p.analysis();
    progress.finish();
    const ModeForces& goal = p.goal(o.goal);
    const std::optional<Rational3> fixed = p.wrench_of(load);
    const char* interference = o.ignore_interference ? "ignored" : "considered";
    // The cases as they are solved: only their printed rows are kept (a table of 6 n cases needs
    // the memory of its output), and the first case whole, for a picture or its bands.
    std::size_t count = 0, feasible = 0;
    std::optional<PushCase> first;
    std::string rows, bests;
    p.plan_push(o.goal, request, load, [&](PushCase&& c) {
        ++count;
        feasible += c.feasible();
        if (o.json) {
            rows += (rows.empty() ? "" : ",") + to_json(c).dump();
        } else {
            rows += case_line(c) + "\n";
            bests += best_push_line(c);
        }
        if (!first) first = std::move(c);
    });
    if (o.json) {
        // The document as one nlohmann object would dump it: keys in order, "cases" first.
        nlohmann::json rest = {{"goal", o.goal}, {"mu", o.mu.value}, {"interference", interference}};
        add_exact(rest, "mu", std::span<const Rational>(&request.mu, 1));
        if (fixed) rest["fixed"] = vector_json(to_double(*fixed));
        if (fixed) add_exact(rest, "fixed", *fixed);
        std::cout << "{\"cases\":[" << rows << "]," << rest.dump().substr(1) << "\n";
    } else {
        std::cout << "pushing into mode " << o.goal << ": a point finger with mu = " << fmt(o.mu.value) << ", obstacles "
                  << interference << "; " << feasible << " of " << count << " cases feasible\n";
        if (fixed) std::cout << "  with the fixed wrench " << fmt(to_double(*fixed)) << " (--gravity, --wrench) acting too\n";
        std::cout << "  " << std::left << std::setw(10) << "feature" << std::setw(6) << "slip" << std::setw(10) << "verdict";
        if (!fixed) std::cout << std::setw(8) << "goal";
        std::cout << std::setw(34) << "touch" << "push directions (from +x)\n" << rows;
        std::cout << "  (feasible: some push lies inside E_" << o.goal << "; boundary: only on its boundary, a knife edge;\n"
                  << "   blocked: only where obstacles leave no room;"
                  << (fixed ? "" : " goal: alone, shared with another mode, or both\n   in parts;") << " docs/planning.md)\n"
                  << bests;
        if (fixed && count == 1 && first->best && first->verdict == PushVerdict::Feasible) {
            std::cout << "  the best push's magnitude from 0 up (with the fixed wrench):\n";
            print_bands(p.push_line(rational(first->best->point), rational(first->best->direction), load), analysis);
        }
    }
    if (!o.picture.files.empty() && first) {
        const PushCase& c = *first;
        const std::string what = c.feature.name() + ", slip " + std::string(1, letter(c.slip));
        const std::string title =
            o.picture.title.empty() ? stem(o.file) + ": pushing " + what + " to mode " + o.goal : o.picture.title;
        write_picture(render::push_figure(title, scene, goal, c, view), o.picture);
    }
    return 0;
}

}  // namespace

std::function<int()> add_plan_command(CLI::App& app) {
    auto opts = std::make_shared<PlanOptions>();
    CLI::App* plan = app.add_subcommand("plan", "Actions that reach a goal mode (Mason 1991, section 3)");
    plan->require_subcommand(1);
    CLI::App* tilt = plan->add_subcommand("tilt", "The gravity directions (tilts of the tray) that produce the goal mode");
    tilt->add_option("scene", opts->file, "scene JSON (docs/formats.md)")->required();
    tilt->add_option("--goal", opts->goal, "the goal mode's letters, e.g. rr")->required();
    tilt->add_flag("--json", opts->json, "machine-readable output: {\"intervals\": [[from, to], ...], ...}");
    add_picture_options(tilt, opts->picture, false);
    CLI::App* push = plan->add_subcommand("push", "The features (edges, vertices) and finger slips that push the body into the goal mode");
    push->add_option("scene", opts->file, "scene JSON (docs/formats.md)")->required();
    push->add_option("--goal", opts->goal, "the goal mode's letters, e.g. rr")->required();
    push->add_option("--mu", opts->mu, "the finger's friction coefficient (default 0.5)")->transform(number_check());
    push->add_option("--edge", opts->edge, "only this edge (from vertex I to the next)")->check(index_check());
    push->add_option("--vertex", opts->vertex, "only this vertex")->check(index_check());
    push->add_flag("--ignore-interference", opts->ignore_interference,
                   "let the finger touch where obstacles are (as the paper's Figure 6 does)");
    push->add_option("--slip", opts->slip, "only this slip")->check(CLI::IsMember({"l", "f", "r"}));
    push->add_flag("--json", opts->json, "machine-readable output: {\"cases\": [...]}");
    add_picture_options(push, opts->picture, false);
    CLI::App* comply = plan->add_subcommand("comply", "The spring directions through a compliance centre, and the centres that work");
    comply->add_option("scene", opts->file, "scene JSON (docs/formats.md)")->required();
    comply->add_option("--goal", opts->goal, "the goal mode's letters, e.g. rr")->required();
    comply->add_option("--centre", opts->centre, "the compliance centre X Y")->expected(2, 2)->transform(number_check());
    comply->add_flag("--json", opts->json, "machine-readable output: {\"labels\": ..., \"centre\": {\"intervals\": ...}}");
    add_picture_options(comply, opts->picture, false);
    tilt->add_option("--gravity", opts->gravity, "not for tilts: gravity is what a tilt turns")->expected(2);
    tilt->add_option("--wrench", opts->fixed, "FX FY TAU: a wrench acting besides the tilted gravity (docs/planning.md)")
        ->expected(3)
        ->transform(number_check());
    add_force_option(tilt, opts->forces, "besides the tilted gravity");
    for (CLI::App* cmd : {push, comply}) {
        cmd->add_option("--gravity", opts->gravity, "GX GY: gravity acting on the body through its centre of mass, besides the push")
            ->expected(2)
            ->transform(number_check());
        cmd->add_option("--wrench", opts->fixed, "FX FY TAU: a fixed wrench acting besides the push (docs/planning.md)")
            ->expected(3)
            ->transform(number_check());
        add_force_option(cmd, opts->forces, "besides the push");
    }
    for (CLI::App* cmd : {tilt, push, comply}) cmd->add_flag("--quasi-static", opts->quasi_static, "neglect inertia: the applied wrench balances the contact wrench, E = -T (docs/design.md)");
    return [opts, tilt, push, comply] {
        if (tilt->parsed()) return run_tilt(*opts);
        if (push->parsed()) return run_push(*opts);
        if (comply->parsed()) return run_comply(*opts);
        return 2;
    };
}

}  // namespace momentlab::cli
