// `momentlab closure SCENE [--json] [--reference X Y] [--length L] [-o FILE]...`: first-order form
// closure and force closure of the scene's contacts, decided exactly, with a certificate either
// way (docs/design.md, "Closure"; docs/formats.md).
#include <iostream>
#include <memory>

#include "common.hpp"

namespace momentlab::cli {
namespace {

struct ClosureCommandOptions {
    std::string file;
    bool json = false;
    std::vector<double> reference;
    std::optional<double> length;
    PictureOptions picture;
};

void print_test(const char* name, const ClosureTest& t, bool form) {
    std::cout << name << ": " << (t.holds ? "holds" : "fails");
    if (t.holds) {
        std::cout << ", quality " << fmt(t.quality) << "\n";
        return;
    }
    const Vec3 w = t.unresisted->value();
    std::cout << "; the contacts cannot resist the wrench (" << fmt(w.x()) << ", " << fmt(w.y()) << ", " << fmt(w.z())
              << ")";
    if (form) std::cout << ", and the twist with these coordinates moves no contact into its obstacle";
    std::cout << "\n";
}

int run(const ClosureCommandOptions& o) {
    const std::optional<Box> view = checked_picture_options(o.picture, {o.file});
    ClosureOptions options;
    if (!o.reference.empty()) options.reference = checked_points(o.reference, "--reference", 1).front();
    if (o.length && (!(*o.length > 0.0) || !magnitude_in_range(*o.length))) {
        throw InputError("--length", "expected a length > 0, of magnitude 1e-60 .. 1e60");
    }
    options.length = o.length;
    const Scene scene = read_scene_file(o.file);
    const Closure c = closure(scene, options);
    if (o.json) {
        std::cout << to_json(c).dump() << "\n";
    } else {
        print_test("form closure (frictionless contacts)", c.form, true);
        print_test("force closure (each contact's friction cone)", c.force, false);
        std::cout << "  (quality: " << kClosureQualityMetric << "; reference " << fmt(c.reference) << ", length "
                  << fmt(c.length) << ")\n";
    }
    if (!o.picture.files.empty()) {
        const std::string title = o.picture.title.empty() ? stem(o.file) + ": grasp closure" : o.picture.title;
        write_picture(render::closure_figure(title, scene, view), o.picture);
    }
    return 0;
}

}  // namespace

std::function<int()> add_closure_command(CLI::App& app) {
    auto opts = std::make_shared<ClosureCommandOptions>();
    CLI::App* cmd = add_scene_command(app, opts, "closure", "Form and force closure of the contacts (the body is optional)",
                                      "machine-readable output: {\"form_closure\", \"force_closure\", ...}");
    cmd->add_option("--reference", opts->reference, "X Y: the point torques are taken about in the quality measure")
        ->expected(2, 2)
        ->transform(number_check());
    cmd->add_option("--length", opts->length, "the characteristic length that scales torques in the quality measure")
        ->transform(number_check());
    add_picture_options(cmd, opts->picture, false);
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
