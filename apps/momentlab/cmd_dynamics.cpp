// `momentlab query SCENE --wrench FX FY TAU | --wrenches FILE [--json]` and
// `momentlab analyze SCENE [--json]`: which modes an applied wrench produces, and every
// mode with its sets of twists, total, contact and applied wrenches.
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "describe.hpp"
#include "momentlab/geometry/labels.hpp"
#include "momentlab/io/json_output.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/mechanics/dynamics.hpp"

namespace momentlab::cli {
namespace {

struct QueryOptions {
    std::string file;
    std::vector<double> wrench;
    std::string wrenches;
    bool json = false;
};

// A wrench from the command line or a wrench file: finite, 0 or with its largest coordinate
// of magnitude 1e-60 .. 1e60, like every vector read (docs/reliability.md).
Vec3 checked_wrench(double fx, double fy, double tau, const std::string& where) {
    const Vec3 e(fx, fy, tau);
    if (!e.allFinite()) throw InputError(where, "expected finite numbers FX FY TAU");
    if (!magnitude_in_range(e.cwiseAbs().maxCoeff())) {
        throw InputError(where, "the wrench's magnitude is out of range (expected 0 or 1e-60 .. 1e60)");
    }
    return e;
}

// query and analyze need the body's mass properties.
const Scene& needs_body(const Scene& scene) {
    if (!scene.body) throw InputError("$", "missing field \"body\" (query and analyze need its mass, com and inertia)");
    return scene;
}

nlohmann::json answer_json(const std::vector<ModeForces>& a, const QueryResult& r) {
    nlohmann::json modes = nlohmann::json::array();
    for (std::size_t i : r.modes) modes.push_back(a[i].mode.letters);
    return {{"modes", modes}, {"verdict", to_string(r.verdict)}};
}

int run_query(const QueryOptions& o) {
    const Scene scene = read_scene_file(o.file);
    const auto analysis = analyze(needs_body(scene));
    if (!o.wrenches.empty()) {  // one JSON array [fx, fy, tau] per line in, one JSON object per line out
        std::ifstream in(o.wrenches);
        if (!in) throw InputError("--wrenches", "cannot read file \"" + o.wrenches + "\"");
        const QueryIndex index(analysis);  // compiled once for all the questions
        std::string line;
        std::size_t number = 0;
        while (std::getline(in, line)) {
            ++number;
            if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
            const std::string where = o.wrenches + ":" + std::to_string(number);
            nlohmann::json w;
            try {
                w = nlohmann::json::parse(line);
            } catch (const nlohmann::json::exception&) {  // malformed, or a number like 1e999
                throw InputError(where, "expected [fx, fy, tau] of finite numbers");
            }
            if (!w.is_array() || w.size() != 3 || !w[0].is_number() || !w[1].is_number() || !w[2].is_number()) {
                throw InputError(where, "expected [fx, fy, tau]");
            }
            const Vec3 e = checked_wrench(w[0].get<double>(), w[1].get<double>(), w[2].get<double>(), where);
            nlohmann::json out = answer_json(analysis, index.query(e));
            out["wrench"] = w;
            std::cout << out.dump() << "\n";
        }
        return 0;
    }
    if (o.wrench.size() != 3) throw InputError("--wrench", "expected three numbers FX FY TAU (or --wrenches FILE)");
    const Vec3 e = checked_wrench(o.wrench[0], o.wrench[1], o.wrench[2], "--wrench");
    const QueryResult r = query(analysis, e);
    if (o.json) {
        std::cout << answer_json(analysis, r).dump() << "\n";
        return 0;
    }
    std::cout << "verdict: " << to_string(r.verdict) << "\n";
    for (std::size_t i : r.modes) {
        std::cout << "  " << analysis[i].mode.letters << "  " << describe_mode(scene, analysis[i].mode.letters) << "\n";
    }
    return 0;
}

struct AnalyzeOptions {
    std::string file;
    bool json = false;
};

int run_analyze(const AnalyzeOptions& o) {
    const Scene scene = read_scene_file(o.file);
    const auto analysis = analyze(needs_body(scene));
    if (o.json) {
        nlohmann::json modes = nlohmann::json::array();
        for (const ModeForces& m : analysis) {
            const Labels centres = rotation_centres(m.mode);
            modes.push_back({{"mode", m.mode.letters},
                             {"A", to_json(m.mode.twists)},
                             {"rotation_centres", to_json(centres)},
                             {"F", {{"cone", to_json(m.total)}, {"labels", to_json(Labels(m.total))}}},
                             {"T", {{"cone", to_json(m.contact)}, {"labels", to_json(Labels(m.contact))}}},
                             {"E", {{"cone", to_json(m.applied)}, {"labels", to_json(Labels(m.applied))}}}});
        }
        std::cout << nlohmann::json{{"modes", modes}}.dump(2) << "\n";
        return 0;
    }
    std::cout << analysis.size() << " contact modes\n";
    for (const ModeForces& m : analysis) {
        const Labels centres = rotation_centres(m.mode);
        const Labels applied(m.applied);
        std::cout << "  " << std::left << std::setw(static_cast<int>(scene.contacts.size()) + 2) << m.mode.letters
                  << describe_mode(scene, m.mode.letters) << "\n"
                  << "      rotation centres  + " << region_text(centres.plus()) << ";  - "
                  << region_text(centres.minus()) << "\n"
                  << "      applied wrenches E: " << m.applied.kind() << "; labels + "
                  << region_text(applied.plus()) << ";  - " << region_text(applied.minus()) << "\n";
    }
    return 0;
}

}  // namespace

std::function<int()> add_query_command(CLI::App& app) {
    auto opts = std::make_shared<QueryOptions>();
    CLI::App* cmd = app.add_subcommand("query", "Which contact mode(s) an applied wrench produces");
    cmd->add_option("scene", opts->file, "scene JSON (DESIGN.md)")->required();
    cmd->add_option("--wrench", opts->wrench, "FX FY TAU: the applied wrench (torque about the origin)")
        ->expected(3)->allow_extra_args(false);
    cmd->add_option("--wrenches", opts->wrenches, "file with one [fx, fy, tau] per line; JSON lines out");
    cmd->add_flag("--json", opts->json, "machine-readable output");
    return [opts] { return run_query(*opts); };
}

std::function<int()> add_analyze_command(CLI::App& app) {
    auto opts = std::make_shared<AnalyzeOptions>();
    CLI::App* cmd = app.add_subcommand("analyze", "Every mode with its twists, total, contact and applied wrenches");
    cmd->add_option("scene", opts->file, "scene JSON (DESIGN.md)")->required();
    cmd->add_flag("--json", opts->json, "machine-readable output");
    return [opts] { return run_analyze(*opts); };
}

}  // namespace momentlab::cli
