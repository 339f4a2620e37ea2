// `momentlab query SCENE --wrench FX FY TAU | --wrenches FILE [--json]`: which modes an applied
// wrench produces.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "common.hpp"

namespace momentlab::cli {
namespace {

struct QueryOptions {
    std::string file;
    std::vector<double> wrench;
    std::string wrenches;
    bool json = false;
    bool quasi_static = false;
    bool margin = false;
    std::vector<double> push;
    std::vector<double> gravity;
};

// `--push X Y DX DY`: the force of direction (DX, DY) through (X, Y), its magnitude from 0 up, added
// to the fixed wrench (--gravity, --wrench): which modes at which magnitudes.
int run_push_line(const QueryOptions& o, const Problem& p) {
    if (!o.wrenches.empty()) throw InputError("--push", "give --push with one question, not --wrenches");
    const std::vector<Vec2> at = checked_points(o.push, "--push", 2);
    if (is_zero(at[1])) throw InputError("--push", "the direction DX DY must not be zero");
    const std::optional<Exact3> fixed = fixed_wrench(p.scene, o.gravity, o.wrench);
    const Exact3 g = fixed ? *fixed : Exact3{};
    const std::vector<MagnitudeBand> bands = magnitude_bands(p.analysis, g, wrench_through(exact(at[0]), exact(at[1])));
    if (o.json) {
        nlohmann::json out = {{"point", vector_json(at[0])},
                              {"direction", vector_json(at[1])},
                              {"fixed", vector_json(to_double(g))},
                              {"bands", to_json(bands, p.analysis)}};
        std::cout << out.dump() << "\n";
        return 0;
    }
    std::cout << "the force lambda " << fmt(at[1]) << " through " << fmt(at[0]) << ", lambda from 0 up";
    if (fixed) std::cout << ", added to the fixed wrench " << fmt(to_double(g));
    std::cout << ":\n";
    print_bands(bands, p.analysis);
    return 0;
}

// A margin as JSON: a number, or "unbounded" (E = R^3, or no other mode's set to reach).
nlohmann::json margin_json(double d) { return std::isfinite(d) ? nlohmann::json(output_value(d)) : nlohmann::json("unbounded"); }

// {"inside": [per returned mode], "to_other": d, "metric": {"reference", "length"}}.
nlohmann::json margins_json(const Problem& p, const QueryResult& r, const Vec3& e) {
    const WrenchMetric metric = default_metric(p.scene);
    const QueryMargins m = query_margins(p.analysis, r.modes, e, metric);
    nlohmann::json inside = nlohmann::json::array();
    for (double d : m.inside) inside.push_back(margin_json(d));
    return {{"inside", inside},
            {"to_other", m.to_other ? margin_json(*m.to_other) : nlohmann::json("unbounded")},
            {"metric", {{"reference", vector_json(metric.reference)},
                        {"length", output_value(metric.length)}}}};
}

nlohmann::json answer_json(const std::vector<ModeForces>& a, const QueryResult& r) {
    nlohmann::json modes = nlohmann::json::array();
    for (std::size_t i : r.modes) modes.push_back(a[i].mode.letters);
    return {{"modes", modes}, {"verdict", to_string(r.verdict)}};
}

// A walk's answer as one line of JSON, {"modes": [...], "verdict": ...} (as answer_json of one
// through the analysis) and the wrench asked if given: the text nlohmann's dump() gives for it
// (keys in order, no spaces), written as it goes, since an answer's letters can pass 10^8 and a
// document of them would hold them twice more.
void write_answer(std::ostream& out, const SceneAnswer& a, const nlohmann::json* wrench = nullptr) {
    out << "{\"modes\":[";
    for (std::size_t i = 0; i < a.modes.size(); ++i) out << (i ? ",\"" : "\"") << a.modes[i].letters << '"';
    out << "],\"verdict\":\"" << to_string(a.result.verdict) << '"';
    if (wrench) out << ",\"wrench\":" << wrench->dump();
    out << "}\n";
}

// The lines of a regular file that are not blank (a wrench each, or an error); none for a pipe
// or a device, which can be read only once.
std::optional<std::size_t> questions_in(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) return std::nullopt;
    std::ifstream in(path);
    if (!in) return std::nullopt;
    std::size_t count = 0;
    for (std::string line; std::getline(in, line);) count += line.find_first_not_of(" \t\r") != std::string::npos;
    return count;
}

// Up to this many letters (modes x contacts) --wrenches may analyse the scene; beyond, every
// wrench takes the walk (an analysis would hold every mode's letters and sets).
constexpr double kAnalysedLetters = 1e8;

// One JSON array [fx, fy, tau] per line in, one JSON object per line out (answers stream: the
// lines before a bad one have been answered). With --margin the scene is analysed first (the
// margins need every mode's set). Otherwise the wrenches are answered by the walk, as --wrench
// is (SceneQuestions), as long as walking for the questions left costs less than an analysis,
// which then answers each for next to nothing. After each walk, its work (cells walked,
// generators tested and generators scanned by mends) is weighed against an analysis on two
// threads (a cone per mode, of about its closed contacts' generators, the modes shared out): for
// a file, the work per answer so far
// times the questions left; for a pipe, whose length is unknown, the work so far (rent or buy: at
// most about twice the better of the two). When the analysis wins, it is made at the next wrench
// (if its letters stay under kAnalysedLetters) and answers the rest from its index. From a
// regular file the first wrench is answered alone (it prices a walk) and the next ones in
// batches of up to kBatch, each from one walk of the cells (SceneQuestions::answer of a span),
// which the first answer's price overestimates; when the scene has so many modes that an
// analysis is ruled out anyway (SceneQuestions::modes_at_least), the first batch starts at the
// first wrench. From a pipe, one at a time as they come. The answers are the same either way.
constexpr std::size_t kBatch = 256;

// A generator that a mended certificate scans (a few filtered determinants) costs about 1/14 of
// one that testing e against E sorts (one query on the collinear family of 1,000 contacts took
// 1.9 s for 1.73 million generators tested before certificates were mended, 1.1 us each, and
// 0.115 s with 1.44 million generators scanned in the cells that mends tried, 0.08 us each with
// the rest of the walk included); counted at 1/16.
constexpr double kScannedPerTested = 16.0;

void answer_file(const QueryOptions& o) {
    const Scene scene = read_scene_file(o.file);
    TerminalProgress progress;
    const AnalysisOptions options{o.quasi_static, progress.callback()};
    Problem p;
    std::optional<QueryIndex> index;
    std::optional<SceneQuestions> walk;
    const auto analyse = [&] {
        p.scene = scene;
        p.analysis = analyze_input(scene, "query", options);
        index.emplace(p.analysis);  // compiled once for all the questions
        walk.reset();
    };
    if (o.margin) {
        analyse();
    } else {
        walk.emplace(questions_input(scene, "query", options));
    }
    double walked = 0.0;  // cells walked and generators tested (or scanned) so far
    std::size_t walks = 0;
    const std::optional<std::size_t> questions = questions_in(o.wrenches);
    // A scene whose modes' letters surely pass kAnalysedLetters is never analysed: no price is
    // needed, and a file's wrenches go in batches from the first.
    const bool never_analysed = walk && static_cast<double>(walk->modes_at_least()) *
                                                static_cast<double>(scene.contacts.size()) > kAnalysedLetters;
    std::size_t batch = questions && never_analysed ? kBatch : 1;
    bool analyse_next = false;
    std::vector<nlohmann::json> asked;  // the wrenches of the batch, as read
    std::vector<Vec3> pending;
    const auto by_index = [&](const nlohmann::json& w, const Vec3& e) {
        const QueryResult r = index->query(e);
        nlohmann::json out = answer_json(p.analysis, r);
        if (o.margin) out["margins"] = margins_json(p, r, e);
        out["wrench"] = w;
        std::cout << out.dump() << "\n";
    };
    const auto answer_pending = [&] {
        if (pending.empty()) return;
        std::size_t k = 0;
        std::size_t modes = 0, closed_letters = 0;  // the scene's counts, the same in every answer
        walk->answer(std::span<const Vec3>(pending), [&](SceneAnswer&& answer) {
            write_answer(std::cout, answer, &asked[k++]);
            walked += static_cast<double>(answer.tested_generators) + static_cast<double>(answer.scanned_generators) / kScannedPerTested;
            modes = answer.mode_count;
            closed_letters = answer.closed_letters;
        });
        walked += static_cast<double>(modes);
        walks += pending.size();
        pending.clear();
        asked.clear();
        if (questions) batch = kBatch;
        const double analysis = static_cast<double>(modes + closed_letters) / 2.0;  // on two threads
        const double to_walk = questions ? walked / static_cast<double>(walks) *
                                               static_cast<double>(*questions > walks ? *questions - walks : 0)
                                         : walked;
        const double letters = static_cast<double>(modes) * static_cast<double>(scene.contacts.size());
        analyse_next = to_walk >= analysis && letters <= kAnalysedLetters;
    };
    LineReader in(o.wrenches, "--wrenches");
    std::string line;
    for (;;) {
        nlohmann::json w;
        Vec3 e;
        try {  // a bad line (or one too long to read) comes after the lines before it are answered
            if (!in.next(line)) break;
            if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
            const std::string where = o.wrenches + ":" + std::to_string(in.number());
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
            e = checked_wrench(w[0].get<double>(), w[1].get<double>(), w[2].get<double>(), where);
        } catch (const InputError&) {
            answer_pending();
            throw;
        }
        if (analyse_next && !index) analyse();
        if (index) {
            by_index(w, e);
            continue;
        }
        asked.push_back(std::move(w));
        pending.push_back(e);
        if (pending.size() >= batch) answer_pending();
    }
    answer_pending();
    progress.finish();
}

// One wrench, no margins: the direct path (query_scene), which builds a mode's sets only when
// no plane found before rules it out. The same output as through the whole analysis.
int answer_one(const QueryOptions& o) {
    const Scene scene = read_scene_file(o.file);
    const Vec3 e = checked_wrench(o.wrench[0], o.wrench[1], o.wrench[2], "--wrench");
    TerminalProgress progress;
    const SceneAnswer a = query_input(scene, e, "query", AnalysisOptions{o.quasi_static, progress.callback()});
    progress.finish();
    if (o.json) {
        write_answer(std::cout, a);
        return 0;
    }
    std::cout << "verdict: " << to_string(a.result.verdict) << "\n";
    for (const Mode& mode : a.modes) {
        const std::string& letters = mode.letters;
        std::cout << "  " << letters << "  " << describe_mode(scene, letters) << "\n";
    }
    return 0;
}

int run(const QueryOptions& o) {
    if (!o.push.empty()) {
        if (o.margin) throw InputError("--margin", "give --margin with one wrench, not with --push");
        return run_push_line(o, load_problem(o.file, "query", o.quasi_static));
    }
    if (!o.gravity.empty()) throw InputError("--gravity", "gravity goes with --push (a fixed wrench plus a push)");
    if (o.wrenches.empty() && o.wrench.size() != 3) {
        throw InputError("--wrench", "expected three numbers FX FY TAU (or --wrenches FILE)");
    }
    if (!o.wrenches.empty()) {
        answer_file(o);
        return 0;
    }
    if (!o.margin) return answer_one(o);
    const Problem p = load_problem(o.file, "query", o.quasi_static);
    const Vec3 e = checked_wrench(o.wrench[0], o.wrench[1], o.wrench[2], "--wrench");
    const QueryResult r = query(p.analysis, e);
    if (o.json) {
        nlohmann::json out = answer_json(p.analysis, r);
        if (o.margin) out["margins"] = margins_json(p, r, e);
        std::cout << out.dump() << "\n";
        return 0;
    }
    const nlohmann::json margins = o.margin ? margins_json(p, r, e) : nlohmann::json();
    const auto said = [](const nlohmann::json& d) { return d.is_number() ? fmt(d.get<double>()) : d.get<std::string>(); };
    std::cout << "verdict: " << to_string(r.verdict) << "\n";
    for (std::size_t k = 0; k < r.modes.size(); ++k) {
        const std::string& letters = p.analysis[r.modes[k]].mode.letters;
        std::cout << "  " << letters << "  " << describe_mode(p.scene, letters);
        if (o.margin) std::cout << "   (margin " << said(margins["inside"][k]) << " to the boundary of its set)";
        std::cout << "\n";
    }
    if (o.margin) {
        std::cout << "  margin to the nearest set of another mode: " << said(margins["to_other"])
                  << "\n  (distances of (fx, fy, tau / L), tau about the reference ("
                  << said(margins["metric"]["reference"][0]) << ", " << said(margins["metric"]["reference"][1])
                  << "), L = " << said(margins["metric"]["length"]) << "; docs/design.md, Margins)\n";
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
    cmd->add_option("--push", opts->push,
                    "X Y DX DY: a force of direction (DX, DY) through (X, Y) whose magnitude runs from 0 up, added to the "
                    "fixed wrench (--gravity, and --wrench then names a fixed wrench): which modes at which magnitudes")
        ->expected(4)
        ->transform(number_check());
    cmd->add_option("--gravity", opts->gravity, "GX GY: with --push, gravity on the body through its centre of mass")
        ->expected(2)
        ->transform(number_check());
    cmd->add_flag("--json", opts->json, "machine-readable output");
    cmd->add_flag("--margin", opts->margin,
                  "how far the wrench may move before the answer changes: to the boundary of each returned mode's set "
                  "and to the nearest other mode's set (docs/design.md, Margins)");
    cmd->add_flag("--quasi-static", opts->quasi_static, "neglect inertia: the applied wrench balances the contact wrench, E = -T (docs/design.md)");
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
