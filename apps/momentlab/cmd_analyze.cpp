// `momentlab analyze SCENE [--json]`: every mode with its sets of twists, total, contact and
// applied wrenches, and their labels.
#include <array>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "common.hpp"
#include "momentlab/core/parallel.hpp"
#include "momentlab/io/json_writer.hpp"

namespace momentlab::cli {
namespace {

struct AnalyzeOptions {
    std::string file;
    bool json = false;
    bool quasi_static = false;
};

int run(const AnalyzeOptions& o) {
    TerminalProgress progress;
    Problem problem = open_problem(o.file, o.quasi_static, progress);
    struct {
        const Scene& scene;
        std::vector<ModeForces> analysis;
    } p{problem.scene(), problem.analysis("analyze")};
    progress.finish();
    if (o.json) {
        // Written as it is made, one mode at a time: on 10^5 contacts the document is hundreds
        // of megabytes, the text nlohmann's dump(2) writes for {"modes": [...]}.
        JsonWriter w(std::cout);
        w.begin_object();
        if (const nlohmann::json found = found_contacts_json(p.scene); !found.empty()) {
            w.key("found_contacts");
            write_json_value(w, found);
        }
        w.key("modes");
        w.begin_array();
        for (ModeForces& m : p.analysis) {
            // The labels of E, F and T (each keeps its cone: moved in, not copied) and the
            // rotation centres, on two threads when the mode is big.
            std::array<std::optional<Labels>, 4> labels;
            Cone* const sets[] = {&m.applied, &m.total, &m.contact};
            const std::size_t size = m.applied.rays().size() + m.applied.facets().size() + m.contact.rays().size();
            detail::for_each_index(4, size > 1000, [&](std::size_t i) {
                labels[i].emplace(i < 3 ? Labels(std::move(*sets[i])) : rotation_centres(m.mode));
            });
            w.begin_object();  // keys sorted, as a document holds them
            w.key("A");
            write_json(w, m.mode.twists);
            for (std::size_t i = 0; i < 3; ++i) {
                w.key(i == 0 ? "E" : i == 1 ? "F" : "T");
                w.begin_object();
                w.key("cone");
                write_json(w, labels[i]->forces());
                w.key("labels");
                write_json(w, *labels[i]);
                w.end_object();
            }
            w.key("mode");
            w.value(m.mode.letters);
            w.key("rotation_centres");
            write_json(w, *labels[3]);
            w.end_object();
        }
        w.end_array();
        w.end_object();
        w.flush();
        std::cout << "\n";
        return 0;
    }
    // The whole answer first: a value that cannot be printed stops it before any of it is.
    std::ostringstream out;
    out << found_contacts_text(p.scene) << p.analysis.size() << " contact modes"
        << (o.quasi_static ? " (quasi-static: E = -T, inertia neglected)" : "") << "; each region is conv(vertices) + "
        << "cone(rays) + span(lines), " << kRegionDigits << " digits (--json: the sets as well)\n";
    for (const ModeForces& m : p.analysis) {
        const Labels centres = rotation_centres(m.mode);
        const Labels applied(m.applied);
        out << "  " << std::left << std::setw(static_cast<int>(p.scene.contacts.size()) + 2) << m.mode.letters
            << describe_mode(p.scene, m.mode.letters) << "\n"
            << "      rotation centres   + " << region_text(centres.plus()) << "\n"
            << "                         - " << region_text(centres.minus()) << "\n"
            << "      applied wrenches E (" << m.applied.kind() << "), labels\n"
            << "                         + " << region_text(applied.plus()) << "\n"
            << "                         - " << region_text(applied.minus()) << "\n";
    }
    std::cout << out.str();
    return 0;
}

}  // namespace

std::function<int()> add_analyze_command(CLI::App& app) {
    auto opts = std::make_shared<AnalyzeOptions>();
    CLI::App* cmd = add_scene_command(app, opts, "analyze", "Every mode with its twists, total, contact and applied wrenches",
                                      "machine-readable output");
    cmd->add_flag("--quasi-static", opts->quasi_static, "neglect inertia: the applied wrench balances the contact wrench, E = -T (docs/design.md)");
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
