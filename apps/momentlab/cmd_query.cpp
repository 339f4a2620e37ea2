// `momentlab query SCENE --wrench FX FY TAU | --wrenches FILE [--json]`: which modes an applied
// wrench produces.
#include <iostream>
#include <memory>

#include "common.hpp"

namespace momentlab::cli {
namespace {

struct QueryOptions {
    std::string file;
    std::vector<double> wrench;
    std::string wrenches;
    bool json = false;
    bool quasi_static = false;
};

nlohmann::json answer_json(const std::vector<ModeForces>& a, const QueryResult& r) {
    nlohmann::json modes = nlohmann::json::array();
    for (std::size_t i : r.modes) modes.push_back(a[i].mode.letters);
    return {{"modes", modes}, {"verdict", to_string(r.verdict)}};
}

// One JSON array [fx, fy, tau] per line in, one JSON object per line out (answers stream: the
// lines before a bad one have been answered).
void answer_file(const Problem& p, const std::string& path) {
    LineReader in(path, "--wrenches");
    const QueryIndex index(p.analysis);  // compiled once for all the questions
    std::string line;
    while (in.next(line)) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const std::string where = path + ":" + std::to_string(in.number());
        nlohmann::json w;
        try {
            w = nlohmann::json::parse(line);
        } catch (const nlohmann::json::exception&) {  // malformed, or a number like 1e999
            throw InputError(where, "expected [fx, fy, tau] of finite numbers");
        }
        if (const std::optional<std::string> tiny = underflowing_number(line)) {
            throw InputError(where, "\"" + printable(*tiny) + "\" is too small for a double: it would be taken as 0 "
                                    "(expected 0 or a magnitude 1e-60 .. 1e60)");
        }
        if (!w.is_array() || w.size() != 3 || !w[0].is_number() || !w[1].is_number() || !w[2].is_number()) {
            throw InputError(where, "expected [fx, fy, tau]");
        }
        const Vec3 e = checked_wrench(w[0].get<double>(), w[1].get<double>(), w[2].get<double>(), where);
        nlohmann::json out = answer_json(p.analysis, index.query(e));
        out["wrench"] = w;
        std::cout << out.dump() << "\n";
    }
}

int run(const QueryOptions& o) {
    if (o.wrenches.empty() && o.wrench.size() != 3) {
        throw InputError("--wrench", "expected three numbers FX FY TAU (or --wrenches FILE)");
    }
    const Problem p = load_problem(o.file, "query", o.quasi_static);
    if (!o.wrenches.empty()) {
        answer_file(p, o.wrenches);
        return 0;
    }
    const Vec3 e = checked_wrench(o.wrench[0], o.wrench[1], o.wrench[2], "--wrench");
    const QueryResult r = query(p.analysis, e);
    if (o.json) {
        std::cout << answer_json(p.analysis, r).dump() << "\n";
        return 0;
    }
    std::cout << "verdict: " << to_string(r.verdict) << "\n";
    for (std::size_t i : r.modes) {
        const std::string& letters = p.analysis[i].mode.letters;
        std::cout << "  " << letters << "  " << describe_mode(p.scene, letters) << "\n";
    }
    return 0;
}

}  // namespace

std::function<int()> add_query_command(CLI::App& app) {
    auto opts = std::make_shared<QueryOptions>();
    CLI::App* cmd = add_scene_command(app, opts, "query", "Which contact mode(s) an applied wrench produces");
    auto* one = cmd->add_option("--wrench", opts->wrench, "FX FY TAU: the applied wrench (torque about the origin)")
                    ->expected(3)
                    ->allow_extra_args(false)
                    ->transform(number_check());
    auto* many = cmd->add_option("--wrenches", opts->wrenches, "file with one [fx, fy, tau] per line; JSON lines out")
                     ->check(CLI::Validator(
                         [](std::string& s) { return s.empty() ? std::string("expected a file name, got an empty string") : ""; },
                         "FILE"));
    one->excludes(many);
    cmd->add_flag("--json", opts->json, "machine-readable output");
    cmd->add_flag("--quasi-static", opts->quasi_static, "neglect inertia: the applied wrench balances the contact wrench, E = -T (docs/design.md)");
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
