// `momentlab draw SCENE [--mode MODE]... [--what modes|forces|labels] -o FILE...`: pictures of a
// scene (render layer), and the picture options shared with `label -o`.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "momentlab/io/input_error.hpp"
#include "momentlab/mechanics/dynamics.hpp"
#include "momentlab/render/pictures.hpp"

namespace momentlab::cli {
namespace {

struct DrawOptions {
    std::string file;
    std::vector<std::string> modes;
    std::string what;
    PictureOptions picture;
};

int run(const DrawOptions& o) {
    const std::optional<Box> view = checked_picture_options(o.picture);
    const std::string what = !o.what.empty() ? o.what : (o.modes.empty() ? "modes" : "forces");
    const Scene scene = read_scene_file(o.file);
    const std::string name = std::filesystem::path(o.file).stem().string();
    if (what == "modes") {
        if (!o.modes.empty()) throw InputError("--mode", "applies to --what forces (the modes picture shows every mode)");
        write_picture(render::modes_figure(o.picture.title.empty() ? name + ": contact modes" : o.picture.title,
                                           scene, view),
                      o.picture);
        return 0;
    }
    if (what == "labels") {
        if (scene.contacts.empty()) throw InputError("$.contacts", "the scene has no contacts to draw friction cones of");
        write_picture(render::friction_figure(o.picture.title.empty() ? name + ": the contacts' friction cones and their sum"
                                                                      : o.picture.title,
                                              scene, view),
                      o.picture);
        return 0;
    }
    if (!scene.body) throw InputError("$", "missing field \"body\" (--what forces needs its mass, com and inertia)");
    const std::vector<ModeForces> analysis = analyze(scene);
    std::vector<std::size_t> chosen;
    for (const std::string& letters : o.modes) chosen.push_back(mode_index(analysis, letters, "--mode"));
    if (chosen.empty()) {
        for (std::size_t i = 0; i < analysis.size(); ++i) chosen.push_back(i);
    }
    std::string title = o.picture.title;
    if (title.empty()) {
        title = name + ": total, contact and applied forces";
        if (o.modes.size() == 1) title += " of mode " + o.modes.front();
    }
    write_picture(render::forces_figure(title, scene, analysis, chosen, view), o.picture);
    return 0;
}

}  // namespace

std::size_t mode_index(const std::vector<ModeForces>& analysis, const std::string& letters, const std::string& option) {
    for (std::size_t i = 0; i < analysis.size(); ++i) {
        if (analysis[i].mode.letters == letters) return i;
    }
    std::string modes;
    for (const ModeForces& m : analysis) modes += (modes.empty() ? "" : ", ") + m.mode.letters;
    throw InputError(option, "no mode \"" + letters + "\" in this scene (its modes: " + modes + ")");
}

void add_picture_options(CLI::App* cmd, PictureOptions& options, bool required) {
    auto* out = cmd->add_option("-o,--output", options.files, "write a picture: FILE.svg, FILE.pdf or FILE.png (repeatable)")
                    ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    if (required) out->required();
    cmd->add_option("--view", options.view, "XMIN YMIN XMAX YMAX: the part of the plane drawn (default: fitted)")
        ->expected(4);
    cmd->add_option("--title", options.title, "the picture's title");
}

std::optional<Box> checked_picture_options(const PictureOptions& options) {
    for (const std::string& f : options.files) {
        try {
            (void)render::format_for(f);
        } catch (const std::invalid_argument& e) {
            throw InputError("-o", e.what());
        }
    }
    if (options.view.empty()) return std::nullopt;
    const auto& v = options.view;
    const bool finite = std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
    if (v.size() != 4 || !finite || !(v[0] < v[2]) || !(v[1] < v[3]) ||
        !magnitude_in_range(std::max(std::abs(v[2] - v[0]), std::abs(v[3] - v[1])))) {
        throw InputError("--view", "expected finite XMIN YMIN XMAX YMAX with XMIN < XMAX and YMIN < YMAX");
    }
    return Box{Vec2(v[0], v[1]), Vec2(v[2], v[3])};
}

void write_picture(const render::Figure& figure, const PictureOptions& options) {
    for (const std::string& f : options.files) {
        try {
            render::write(figure, f);
        } catch (const std::runtime_error& e) {
            throw InputError("-o", e.what());
        }
        std::cout << "wrote " << f << "\n";
    }
}

std::function<int()> add_draw_command(CLI::App& app) {
    auto opts = std::make_shared<DrawOptions>();
    CLI::App* cmd = app.add_subcommand("draw", "Draw a scene: its modes, the forces of some modes, or its friction cones");
    cmd->add_option("scene", opts->file, "scene JSON (DESIGN.md)")->required();
    cmd->add_option("--mode", opts->modes, "a mode's letters, e.g. rr (repeatable; default: every mode)")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    cmd->add_option("--what", opts->what,
                    "modes: rotation centres of every mode; forces: F, T, E per mode (default with --mode); "
                    "labels: the contacts' friction cones and their sum")
        ->check(CLI::IsMember({"modes", "forces", "labels"}));
    add_picture_options(cmd, opts->picture, true);
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
