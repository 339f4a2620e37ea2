// `momentlab draw SCENE [--mode MODE]... [--what modes|forces|labels|closure|stand] [--gravity GX GY] -o FILE...`:
// pictures of a scene (render layer).
#include <iostream>
#include <memory>

#include "common.hpp"
#include "momentlab/assembly/assembly_json.hpp"
#include "momentlab/render/stand_pictures.hpp"

namespace momentlab::cli {
namespace {

struct DrawOptions {
    std::string file;
    std::vector<std::string> modes;
    std::string what;
    PictureOptions picture;
    bool quasi_static = false;
    std::vector<TypedNumber> gravity;
};

int run(const DrawOptions& o) {
    const std::optional<Box> view = checked_picture_options(o.picture, {o.file});
    const std::string what = !o.what.empty() ? o.what : (o.modes.empty() ? "modes" : "forces");
    if (what != "forces" && !o.modes.empty()) {
        throw InputError("--mode", "applies to --what forces (the " + what + " picture shows the whole scene)");
    }
    if (what != "stand" && !o.gravity.empty()) {
        throw InputError("--gravity", "applies to --what stand (the other pictures have no load)");
    }
    const std::string name = stem(o.file);
    const std::string& title = o.picture.title;
    if (what == "modes") {
        const Scene scene = read_scene_file(o.file);
        write_picture(render::modes_figure(title.empty() ? name + ": contact modes" : title, scene, view), o.picture);
        return 0;
    }
    if (what == "closure") {
        const Scene scene = read_scene_file(o.file);
        write_picture(render::closure_figure(title.empty() ? name + ": grasp closure" : title, scene, view), o.picture);
        return 0;
    }
    if (what == "labels") {
        const Scene scene = read_scene_file(o.file);
        write_picture(render::friction_figure(title.empty() ? name + ": the contacts' friction cones and their sum" : title,
                                              scene, view),
                      o.picture);
        return 0;
    }
    if (what == "stand") {
        InputWarnings warnings;
        const Assembly assembly = read_assembly_text(read_json_file(o.file), &warnings);
        for (const std::string& w : warnings) std::cerr << "momentlab: warning: " << printable(w) << "\n";
        StandOptions options;
        if (!o.gravity.empty()) options.gravity = checked_points(o.gravity, "--gravity", 1).front();
        const StandResult r = stand(assembly, options);
        const std::string heading = title.empty() ? name + (r.equilibrium.can_stand ? ": it can stand" : ": it cannot stand") : title;
        write_picture(render::stand_figure(heading, assembly, r, view), o.picture);
        return 0;
    }
    TerminalProgress progress;
    Problem problem = open_problem(o.file, o.quasi_static, progress);
    const struct {
        const Scene& scene;
        const std::vector<ModeForces>& analysis;
    } p{problem.scene(), problem.analysis("--what forces")};
    progress.finish();
    std::vector<std::size_t> chosen;
    for (const std::string& letters : o.modes) {
        chosen.push_back(static_cast<std::size_t>(&find_mode(p.analysis, letters, "--mode") - p.analysis.data()));
    }
    if (chosen.empty()) {
        for (std::size_t i = 0; i < p.analysis.size(); ++i) chosen.push_back(i);
    }
    std::string heading = title;
    if (heading.empty()) {
        heading = name + ": total, contact and applied forces";
        if (o.modes.size() == 1) heading += " of mode " + o.modes.front();
    }
    write_picture(render::forces_figure(heading, p.scene, p.analysis, chosen, view), o.picture);
    return 0;
}

}  // namespace

std::function<int()> add_draw_command(CLI::App& app) {
    auto opts = std::make_shared<DrawOptions>();
    CLI::App* cmd = add_scene_command(app, opts, "draw", "Draw a scene: its modes, the forces of some modes, its friction cones, closure, or whether an assembly stands");
    cmd->add_option("--mode", opts->modes, "a mode's letters, e.g. rr (repeatable; default: every mode)")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    cmd->add_option("--what", opts->what,
                    "modes: rotation centres of every mode; forces: F, T, E per mode (default with --mode); "
                    "labels: the contacts' friction cones and their sum; closure: the labels that decide grasp closure; "
                    "stand: an assembly's equilibrium forces or collapse mechanism, and each body's labels")
        ->check(CLI::IsMember({"modes", "forces", "labels", "closure", "stand"}));
    cmd->add_option("--gravity", opts->gravity, "GX GY: with --what stand, gravity on every body (default 0 -9.81)")
        ->expected(2, 2)
        ->transform(number_check());
    add_picture_options(cmd, opts->picture, true);
    cmd->add_flag("--quasi-static", opts->quasi_static, "neglect inertia: the applied wrench balances the contact wrench, E = -T (docs/design.md)");
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
