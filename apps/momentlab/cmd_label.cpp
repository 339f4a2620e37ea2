// `momentlab label FILE [--json] [--at X Y]... [-o PICTURE]...`: the cone of a force set and its
// labels, printed and drawn.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "momentlab/geometry/labels.hpp"
#include "momentlab/io/force_set_json.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/io/json_output.hpp"
#include "momentlab/render/pictures.hpp"

namespace momentlab::cli {
namespace {

struct LabelOptions {
    std::string file;
    bool json = false;
    std::vector<double> at;
    PictureOptions picture;
};

std::string fmt(double x) {
    std::ostringstream s;
    s << std::setprecision(10) << (x == 0.0 ? 0.0 : x);  // no "-0"
    return s.str();
}

std::string fmt(const Vec2& v) { return "(" + fmt(v.x()) + ", " + fmt(v.y()) + ")"; }
std::string fmt(const Vec3& v) { return "(" + fmt(v.x()) + ", " + fmt(v.y()) + ", " + fmt(v.z()) + ")"; }

template <class List>
void print_list(const char* name, const List& list) {
    if (list.empty()) return;
    std::cout << "    " << std::left << std::setw(10) << name;
    for (std::size_t i = 0; i < list.size(); ++i) {
        if constexpr (std::is_same_v<typename List::value_type, ExactVector>) {
            std::cout << (i ? "  " : "") << fmt(list[i].value());
        } else {
            std::cout << (i ? "  " : "") << fmt(list[i]);
        }
    }
    std::cout << "\n";
}

void print_region(const char* name, const Region& r) {
    std::cout << "  " << name << " region: " << r.kind() << "\n";
    print_list("vertices", r.vertices);
    print_list("rays", r.rays);
    print_list("lines", r.lines);
}

int run(const LabelOptions& o) {
    for (std::size_t i = 0; i + 1 < o.at.size(); i += 2) {
        const Vec2 p(o.at[i], o.at[i + 1]);
        if (!p.allFinite() || !magnitude_in_range(p.cwiseAbs().maxCoeff())) {
            throw InputError("--at", "expected finite X Y, 0 or of magnitude 1e-60 .. 1e60");
        }
    }
    const std::optional<Box> view = checked_picture_options(o.picture);
    InputWarnings warnings;
    const ForceSetFile parts = read_force_set_parts_text(read_file(o.file), &warnings);
    for (const std::string& w : warnings) std::cerr << "momentlab: warning: " << w << "\n";
    const Labels labels(parts.result);
    const Cone& f = labels.forces();
    if (!o.picture.files.empty()) {
        std::vector<render::ForcePanel> panels;
        for (std::size_t i = 0; i < parts.parts.size(); ++i) {
            panels.push_back({parts.parts.size() == 1 ? "F" : "F" + std::to_string(i + 1), parts.parts[i], {}});
        }
        const std::string title =
            o.picture.title.empty() ? std::filesystem::path(o.file).stem().string() + ": moment labels" : o.picture.title;
        write_picture(render::labels_figure(title, panels, parts.intersect, parts.result, view), o.picture);
    }
    if (o.json) {
        nlohmann::json out = {{"cone", to_json(f)}, {"labels", to_json(labels)}};
        for (std::size_t i = 0; i + 1 < o.at.size(); i += 2) {
            const Vec2 p(o.at[i], o.at[i + 1]);
            out["at"].push_back({{"point", {p.x(), p.y()}}, {"label", to_string(labels.at(p))}});
        }
        std::cout << out.dump(2) << "\n";
        return 0;
    }
    std::cout << "force set: " << f.kind() << " (dimension " << f.dimension() << ", lineality "
              << f.lineality_dimension() << ")\n";
    print_list("rays", f.rays());
    print_list("lines", f.lineality());
    print_list("facets", f.facets());
    print_list("equations", f.equations());
    std::cout << "moment labels:\n";
    print_region("+", labels.plus());
    print_region("-", labels.minus());
    for (std::size_t i = 0; i + 1 < o.at.size(); i += 2) {
        const Vec2 p(o.at[i], o.at[i + 1]);
        std::cout << "  label at " << fmt(p) << ": " << to_string(labels.at(p)) << "\n";
    }
    return 0;
}

}  // namespace

std::string read_file(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError("$", "cannot read file \"" + path + "\" (a directory)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError("$", "cannot read file \"" + path + "\"");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

namespace {

void print_warnings(const InputWarnings& warnings) {
    for (const std::string& w : warnings) std::cerr << "momentlab: warning: " << w << "\n";
}

}  // namespace

Scene read_scene_file(const std::string& path) {
    InputWarnings warnings;
    Scene scene = read_scene_text(read_file(path), &warnings);
    print_warnings(warnings);
    return scene;
}

Cone read_force_set_file(const std::string& path) {
    InputWarnings warnings;
    Cone cone = read_force_set_text(read_file(path), &warnings);
    print_warnings(warnings);
    return cone;
}

std::function<int()> add_label_command(CLI::App& app) {
    auto opts = std::make_shared<LabelOptions>();
    CLI::App* cmd = app.add_subcommand("label", "Print a force set (JSON file) as a cone and its moment labels");
    cmd->add_option("file", opts->file, "force-set JSON (see docs/formats.md)")->required();
    cmd->add_flag("--json", opts->json, "machine-readable output on stdout");
    cmd->add_option("--at", opts->at, "X Y: also print the label of this point (repeatable)")
        ->expected(2)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    add_picture_options(cmd, opts->picture, false);
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
