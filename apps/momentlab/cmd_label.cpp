// `momentlab label FILE [--json] [--at X Y]... [-o PICTURE]...`: the cone of a force set and its
// labels, printed and drawn.
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "common.hpp"

namespace momentlab::cli {
namespace {

struct LabelOptions {
    std::string file;
    bool json = false;
    std::vector<TypedNumber> at;  // as typed: 0.1 is 1/10
    PictureOptions picture;
};

// Exact points and vectors are printed with 10 digits.
constexpr int kDigits = 10;

template <class List>
void print_list(std::ostream& out, const char* name, const List& list) {
    if (list.empty()) return;
    out << "    " << std::left << std::setw(10) << name;
    for (std::size_t i = 0; i < list.size(); ++i) {
        if constexpr (std::is_same_v<typename List::value_type, ExactVector>) {
            out << (i ? "  " : "") << fmt(list[i].value(), kDigits);
        } else {
            out << (i ? "  " : "") << fmt(list[i], kDigits);
        }
    }
    out << "\n";
}

void print_region(std::ostream& out, const char* name, const Region& r) {
    out << "  " << name << " region: " << r.kind() << "\n";
    if (!r.vertices_h.empty()) {  // each coordinate the exact x / s correctly rounded
        out << "    " << std::left << std::setw(10) << "vertices";
        for (std::size_t i = 0; i < r.vertices_h.size(); ++i) out << (i ? "  " : "") << fmt_point(r.vertices_h[i], kDigits);
        out << "\n";
    }
    print_list(out, "rays", r.rays);
    print_list(out, "lines", r.lines);
}

int run(const LabelOptions& o) {
    const std::vector<Rational2> points = checked_points(o.at, "--at");
    const std::optional<Box> view = checked_picture_options(o.picture, {o.file});
    InputWarnings warnings;
    const ForceSetFile parts = read_force_set_parts_text(read_json_file(o.file), &warnings);
    for (const std::string& w : warnings) std::cerr << "momentlab: warning: " << printable(w) << "\n";
    const Labels labels(parts.result);
    const Cone& f = labels.forces();
    if (!o.picture.files.empty()) {
        std::vector<render::ForcePanel> panels;
        for (std::size_t i = 0; i < parts.parts.size(); ++i) {
            panels.push_back({parts.parts.size() == 1 ? "F" : "F" + std::to_string(i + 1), parts.parts[i], {}});
        }
        const std::string title = o.picture.title.empty() ? stem(o.file) + ": moment labels" : o.picture.title;
        write_picture(render::labels_figure(title, panels, parts.intersect, parts.result, view), o.picture);
    }
    if (o.json) {
        nlohmann::json doc = {{"cone", to_json(f)}, {"labels", to_json(labels)}};
        for (const Rational2& p : points) {
            const Vec2 rounded = to_double(p);
            doc["at"].push_back({{"point", {rounded.x(), rounded.y()}}, {"label", to_string(labels.at(p))}});
            add_exact(doc["at"].back(), "point", p);
        }
        std::cout << doc.dump(2) << "\n";
        return 0;
    }
    // The whole answer first: a value that cannot be printed stops it before any of it is.
    std::ostringstream out;
    out << "force set: " << f.kind() << " (dimension " << f.dimension() << ", lineality "
              << f.lineality_dimension() << ")\n";
    print_list(out, "rays", f.rays());
    print_list(out, "lines", f.lineality());
    print_list(out, "facets", f.facets());
    print_list(out, "equations", f.equations());
    out << "moment labels:\n";
    print_region(out, "+", labels.plus());
    print_region(out, "-", labels.minus());
    for (const Rational2& p : points) out << "  label at " << fmt(to_double(p), kDigits) << ": " << to_string(labels.at(p)) << "\n";
    std::cout << out.str();
    return 0;
}

}  // namespace

std::function<int()> add_label_command(CLI::App& app) {
    auto opts = std::make_shared<LabelOptions>();
    CLI::App* cmd = app.add_subcommand("label", "Print a force set (JSON file) as a cone and its moment labels");
    cmd->add_option("file", opts->file, "force-set JSON (see docs/formats.md)")->required();
    cmd->add_flag("--json", opts->json, "machine-readable output on stdout");
    cmd->add_option("--at", opts->at, "X Y: also print the label of this point (repeatable)")
        ->expected(2, 2)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->transform(number_check());
    add_picture_options(cmd, opts->picture, false);
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
