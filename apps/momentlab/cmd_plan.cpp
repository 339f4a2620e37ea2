// `momentlab plan tilt SCENE --goal MODE [--json] [-o FILE]...`: the tilts (gravity directions)
// that produce a goal mode (Mason 1991, section 3, Figure 5); `momentlab plan push SCENE --goal
// MODE [--mu M] [--edge I] [--slip l|f|r]`: which edges and finger slips can push it there
// (Figure 6).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "momentlab/io/input_error.hpp"
#include "momentlab/planning/push.hpp"
#include "momentlab/planning/tilt.hpp"
#include "momentlab/render/pictures.hpp"

namespace momentlab::cli {
namespace {

struct PlanOptions {
    std::string file;
    std::string goal;
    bool json = false;
    PictureOptions picture;
    double mu = 0.5;
    std::optional<std::size_t> edge;
    std::string slip;
};

std::string degrees(double radians) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(2) << radians * 180.0 / M_PI << "\u00B0";
    return s.str();
}

int run_tilt(const PlanOptions& o) {
    const std::optional<Box> view = checked_picture_options(o.picture);
    const Scene scene = read_scene_file(o.file);
    if (!scene.body) throw InputError("$", "missing field \"body\" (plan tilt needs its mass, com and inertia)");
    const std::vector<ModeForces> analysis = analyze(scene);
    const ModeForces& goal = analysis[mode_index(analysis, o.goal, "--goal")];
    const TiltPlan plan = plan_tilt(scene, goal);
    if (o.json) {
        nlohmann::json intervals = nlohmann::json::array();
        for (const AngleInterval& i : plan.intervals) intervals.push_back({i.from, i.to});
        nlohmann::json out = {{"goal", o.goal}, {"intervals", intervals}};
        if (plan.feasible()) {
            out["best"] = plan.best;
            out["margin"] = plan.margin;
        }
        std::cout << out.dump() << "\n";
    } else if (!plan.feasible()) {
        std::cout << "no tilt produces mode " << o.goal << " (W \u2229 E is {0})\n";
    } else {
        std::cout << "tilts that produce mode " << o.goal
                  << ": gravity directions, radians from +x (boundaries shared with a neighbouring mode)\n";
        for (const AngleInterval& i : plan.intervals) {
            std::cout << "  [" << i.from << ", " << i.to << "]   (" << degrees(i.from) << " .. " << degrees(i.to) << ")\n";
        }
        std::cout << "  best " << plan.best << " (" << degrees(plan.best) << "), margin " << plan.margin << " ("
                  << degrees(plan.margin) << ") to the nearest boundary\n";
    }
    if (!o.picture.files.empty()) {
        const std::string title = o.picture.title.empty()
                                      ? std::filesystem::path(o.file).stem().string() + ": tilts that produce mode " + o.goal
                                      : o.picture.title;
        const render::ForcePanel actions{"W: tilts (gravity through the centre of mass)", plan.actions,
                                         {scene.body->com}};
        write_picture(render::synthesis_figure(title, scene, actions, goal, plan.solutions, view), o.picture);
    }
    return 0;
}

std::string fmt(const Vec2& v) {
    std::ostringstream s;
    s << "(" << v.x() << ", " << v.y() << ")";
    return s.str();
}

int run_push(const PlanOptions& o) {
    const std::optional<Box> view = checked_picture_options(o.picture);
    if (!(o.mu >= 0.0) || !std::isfinite(o.mu)) throw InputError("--mu", "expected a finite mu >= 0");
    if (!o.picture.files.empty() && (!o.edge || o.slip.empty())) {
        throw InputError("-o", "a picture shows one case: give --edge and --slip");
    }
    const Scene scene = read_scene_file(o.file);
    if (!scene.body) throw InputError("$", "missing field \"body\" (plan push needs its mass, com, inertia and polygon)");
    if (scene.body->polygon.size() < 3) throw InputError("$.body.polygon", "plan push needs the body's polygon");
    if (o.edge && *o.edge >= scene.body->polygon.size()) {
        throw InputError("--edge", "the body has edges 0 .. " + std::to_string(scene.body->polygon.size() - 1));
    }
    const std::vector<ModeForces> analysis = analyze(scene);
    const ModeForces& goal = analysis[mode_index(analysis, o.goal, "--goal")];
    std::vector<PushCase> cases;
    for (PushCase& c : plan_push_edges(scene, goal, o.mu)) {
        if ((!o.edge || c.edge == *o.edge) && (o.slip.empty() || c.slip == o.slip[0])) cases.push_back(std::move(c));
    }
    if (o.json) {
        nlohmann::json out = {{"goal", o.goal}, {"mu", o.mu}, {"cases", nlohmann::json::array()}};
        for (const PushCase& c : cases) {
            out["cases"].push_back({{"feature", "edge " + std::to_string(c.edge)},
                                    {"from", {c.from.x(), c.from.y()}},
                                    {"to", {c.to.x(), c.to.y()}},
                                    {"slip", std::string(1, c.slip)},
                                    {"feasible", c.feasible()}});
        }
        std::cout << out.dump() << "\n";
    } else {
        std::cout << "pushing to mode " << o.goal << " with a finger (mu = " << o.mu
                  << ") on each edge; interference with obstacles ignored\n";
        for (const PushCase& c : cases) {
            std::cout << "  edge " << c.edge << " " << fmt(c.from) << " - " << fmt(c.to) << "  slip " << c.slip << "  "
                      << (c.feasible() ? "feasible" : "no") << "\n";
        }
    }
    if (!o.picture.files.empty() && !cases.empty()) {
        const PushCase& c = cases.front();
        const std::string what = "edge " + std::to_string(c.edge) + ", slip " + std::string(1, c.slip);
        const std::string title = o.picture.title.empty()
                                      ? std::filesystem::path(o.file).stem().string() + ": pushing " + what +
                                            " to mode " + o.goal
                                      : o.picture.title;
        const render::ForcePanel actions{"W: pushes (" + what + ")", c.actions, {c.from, c.to}};
        write_picture(render::synthesis_figure(title, scene, actions, goal, c.solutions, view), o.picture);
    }
    return 0;
}

}  // namespace

std::function<int()> add_plan_command(CLI::App& app) {
    auto opts = std::make_shared<PlanOptions>();
    CLI::App* plan = app.add_subcommand("plan", "Actions that reach a goal mode (Mason 1991, section 3)");
    plan->require_subcommand(1);
    CLI::App* tilt = plan->add_subcommand("tilt", "The gravity directions (tilts of the tray) that produce the goal mode");
    tilt->add_option("scene", opts->file, "scene JSON (DESIGN.md)")->required();
    tilt->add_option("--goal", opts->goal, "the goal mode's letters, e.g. rr")->required();
    tilt->add_flag("--json", opts->json, "machine-readable output: {\"intervals\": [[from, to], ...], ...}");
    add_picture_options(tilt, opts->picture, false);
    CLI::App* push = plan->add_subcommand("push", "The edges and finger slips that can push the body into the goal mode");
    push->add_option("scene", opts->file, "scene JSON (DESIGN.md)")->required();
    push->add_option("--goal", opts->goal, "the goal mode's letters, e.g. rr")->required();
    push->add_option("--mu", opts->mu, "the finger's friction coefficient (default 0.5)");
    push->add_option("--edge", opts->edge, "only this edge (from vertex I to the next)");
    push->add_option("--slip", opts->slip, "only this slip")->check(CLI::IsMember({"l", "f", "r"}));
    push->add_flag("--json", opts->json, "machine-readable output: {\"cases\": [...]}");
    add_picture_options(push, opts->picture, false);
    return [opts, tilt, push] {
        if (tilt->parsed()) return run_tilt(*opts);
        if (push->parsed()) return run_push(*opts);
        return 2;
    };
}

}  // namespace momentlab::cli
