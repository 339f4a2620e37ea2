// `momentlab analyze SCENE [--json]`: every mode with its sets of twists, total, contact and
// applied wrenches, and their labels.
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "common.hpp"

namespace momentlab::cli {
namespace {

struct AnalyzeOptions {
    std::string file;
    bool json = false;
    bool quasi_static = false;
};

int run(const AnalyzeOptions& o) {
    const Problem p = load_problem(o.file, "analyze", o.quasi_static);
    if (o.json) {
        nlohmann::json modes = nlohmann::json::array();
        for (const ModeForces& m : p.analysis) {
            modes.push_back({{"mode", m.mode.letters},
                             {"A", to_json(m.mode.twists)},
                             {"rotation_centres", to_json(rotation_centres(m.mode))},
                             {"F", {{"cone", to_json(m.total)}, {"labels", to_json(Labels(m.total))}}},
                             {"T", {{"cone", to_json(m.contact)}, {"labels", to_json(Labels(m.contact))}}},
                             {"E", {{"cone", to_json(m.applied)}, {"labels", to_json(Labels(m.applied))}}}});
        }
        // Moved, not copied, into the document, and streamed (the same text as dump(2)): on
        // 10^5 contacts the document is hundreds of megabytes.
        nlohmann::json doc = nlohmann::json::object();
        doc["modes"] = std::move(modes);
        std::cout << std::setw(2) << doc << "\n";
        return 0;
    }
    // The whole answer first: a value that cannot be printed stops it before any of it is.
    std::ostringstream out;
    out << p.analysis.size() << " contact modes" << (o.quasi_static ? " (quasi-static: E = -T, inertia neglected)" : "") << "\n";
    for (const ModeForces& m : p.analysis) {
        const Labels centres = rotation_centres(m.mode);
        const Labels applied(m.applied);
        out << "  " << std::left << std::setw(static_cast<int>(p.scene.contacts.size()) + 2) << m.mode.letters
                  << describe_mode(p.scene, m.mode.letters) << "\n"
                  << "      rotation centres  + " << region_text(centres.plus()) << ";  - "
                  << region_text(centres.minus()) << "\n"
                  << "      applied wrenches E: " << m.applied.kind() << "; labels + "
                  << region_text(applied.plus()) << ";  - " << region_text(applied.minus()) << "\n";
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
