// `momentlab query SCENE [--wrench FX FY TAU] [--gravity GX GY] [--force X Y FX FY]... | --wrenches
// FILE [--json]`: which modes an applied wrench produces (its modes by their letters, sorted).
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
    std::vector<TypedNumber> wrench;
    std::string wrenches;
    bool json = false;
    bool quasi_static = false;
    bool margin = false;
    std::vector<TypedNumber> push;
    std::vector<TypedNumber> gravity;
    std::vector<TypedNumber> forces;
};

// `--push X Y DX DY`: the force of direction (DX, DY) through (X, Y), its magnitude from 0 up, added
// to the fixed wrench (--gravity, --wrench, --force): which modes at which magnitudes.
int run_push_line(const QueryOptions& o) {
    if (!o.wrenches.empty()) throw InputError("--push", "give --push with one question, not --wrenches");
    if (o.margin) throw InputError("--margin", "give --margin with one wrench, not with --push");
    const std::vector<Rational2> typed = checked_points(o.push, "--push", 2);
    const std::vector<Vec2> at = {to_double(typed[0]), to_double(typed[1])};
    TerminalProgress progress;
    Problem p = open_problem(o.file, o.quasi_static, progress);
    const Load load = load_of(o.gravity, o.wrench, o.forces);
    const std::vector<MagnitudeBand> bands = p.push_line(typed[0], typed[1], load);
    const std::optional<Rational3> fixed = p.wrench_of(load);
    const Rational3 g = fixed ? *fixed : Rational3{};
    progress.finish();
    if (o.json) {
        nlohmann::json out = {{"point", vector_json(at[0])},
                              {"direction", vector_json(at[1])},
                              {"fixed", vector_json(to_double(g))},
                              {"bands", to_json(bands, p.analysis())}};
        add_exact(out, "point", typed[0]);
        add_exact(out, "direction", typed[1]);
        add_exact(out, "fixed", g);
        std::cout << out.dump() << "\n";
        return 0;
    }
    std::cout << "the force lambda " << fmt(at[1]) << " through " << fmt(at[0]) << ", lambda from 0 up";
    if (fixed) std::cout << ", added to the fixed wrench " << fmt(to_double(g));
    std::cout << ":\n";
    print_bands(bands, p.analysis());
    return 0;
}

// A margin as JSON: a number, or "unbounded" (E = R^3, or no other mode's set to reach).
nlohmann::json margin_json(double d) { return std::isfinite(d) ? nlohmann::json(output_value(d)) : nlohmann::json("unbounded"); }

// {"inside": [per returned mode], "to_other": d, "metric": {"reference", "length"}}.
nlohmann::json margins_json(const MarginAnswer& m) {
    nlohmann::json inside = nlohmann::json::array();
    for (double d : m.inside) inside.push_back(margin_json(d));
    return {{"inside", inside},
            {"to_other", m.to_other ? margin_json(*m.to_other) : nlohmann::json("unbounded")},
            {"metric", {{"reference", vector_json(m.metric.reference)}, {"length", output_value(m.metric.length)}}}};
}

// An answer as one line of JSON, {"margins" (if given), "modes": [...], "verdict", "wrench" (if given)}:
// the text nlohmann's dump() gives for it (keys in order, no spaces), written as it goes, since an
// answer's letters can pass 10^8 and a document of them would hold them twice more.
void write_answer(std::ostream& out, const QueryAnswer& a, const nlohmann::json* wrench = nullptr,
                  const MarginAnswer* margins = nullptr) {
    out << '{';
    if (margins) out << "\"margins\":" << margins_json(*margins).dump() << ',';
    out << "\"modes\":[";
    for (std::size_t i = 0; i < a.letters.size(); ++i) out << (i ? ",\"" : "\"") << a.letters[i] << '"';
    out << "],\"verdict\":\"" << to_string(a.verdict) << '"';
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

// The exact values of a line's [fx, fy, tau] (w, as nlohmann read it): each number's text read
// as the decimal it spells.
Rational3 typed_wrench(const std::string& line, const nlohmann::json& w) {
    Rational3 out{Rational(w[0].get<double>()), Rational(w[1].get<double>()), Rational(w[2].get<double>())};
    std::size_t at = line.find('['), k = 0;
    while (at != std::string::npos && k < 3) {
        const std::size_t from = line.find_first_not_of(" \t\r", at + 1);
        if (from == std::string::npos) break;
        const std::size_t to = line.find_first_of(" \t\r,]", from);
        if (to == std::string::npos) break;
        if (const std::optional<Rational> r = Rational::parse(std::string_view(line).substr(from, to - from))) out[k] = *r;
        ++k;
        at = line.find(',', to);
    }
    return out;
}

// One JSON array [fx, fy, tau] per line in, one JSON object per line out (answers stream: the
// lines before a bad one have been answered). The questions go to a QueryIndex made from the
// scene, in the batches it asks for (batch()): it walks the scene's cells for them as long as
// that costs less than an analysis, which then answers the rest (mechanics/query_index.hpp). With
// --margin the scene is analysed first (the margins need every mode's set). A file's number of
// questions is told to the index; a pipe's is unknown.
void answer_file(const QueryOptions& o) {
    TerminalProgress progress;
    Problem p = open_problem(o.file, o.quasi_static, progress);
    require_body(p.scene(), "query", AnalysisOptions{o.quasi_static});
    QueryIndex index(p.scene(), AnalysisOptions{o.quasi_static, progress.callback()}, questions_in(o.wrenches));
    std::vector<nlohmann::json> asked;  // the wrenches of the batch, as read
    std::vector<Vec3> pending;
    const auto answer_pending = [&] {
        std::size_t k = 0;
        if (o.margin) {
            for (const Vec3& e : pending) {
                const MarginAnswer m = p.margins(Load{.wrench = rational(e)});
                write_answer(std::cout, m.answer, &asked[k++], &m);
            }
        } else if (!pending.empty()) {
            index.answer(pending, [&](QueryAnswer&& a) { write_answer(std::cout, a, &asked[k++]); });
        }
        pending.clear();
        asked.clear();
    };
    LineReader in(o.wrenches, "--wrenches");
    std::string line;
    for (;;) {
        try {  // a bad line (or one too long to read) comes after the lines before it are answered
            if (!in.next(line)) break;
            if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
            const std::string where = o.wrenches + ":" + std::to_string(in.number());
            nlohmann::json w;
            try {
                w = nlohmann::json::parse(line);
            } catch (const nlohmann::json::exception&) {  // malformed, or a number like 1e999
                throw InputError(where, "expected [fx, fy, tau] of finite numbers");
            }
            if (const std::optional<std::string> tiny = underflowing_number(line)) {
                throw InputError(where, "\"" + printable(*tiny) + "\" is " + std::string(kTooSmallForADouble));
            }
            if (!w.is_array() || w.size() != 3 || !w[0].is_number() || !w[1].is_number() || !w[2].is_number()) {
                throw InputError(where, "expected [fx, fy, tau]");
            }
            (void)checked_vector(Vec3(w[0].get<double>(), w[1].get<double>(), w[2].get<double>()), where);
            // The wrench as typed (0.1 is 1/10), times its common denominator: the same modes.
            const Rational3 typed = typed_wrench(line, w);
            const std::vector<Dyadic> e = clear_denominators(typed);
            if (!(e[0].fits_double() && e[1].fits_double() && e[2].fits_double())) {
                // Beyond doubles even so: answered exactly, alone, after those before it.
                answer_pending();
                const QueryAnswer a = o.margin ? p.margins(Load{.wrench = typed}).answer : p.query(Load{.wrench = typed});
                write_answer(std::cout, a, &w);
                continue;
            }
            pending.push_back(Vec3(e[0].to_double(), e[1].to_double(), e[2].to_double()));
            asked.push_back(std::move(w));
        } catch (const InputError&) {
            answer_pending();
            throw;
        }
        if (o.margin || pending.size() >= index.batch()) answer_pending();
    }
    answer_pending();
    progress.finish();
}

// The text of one answer: the verdict, then each mode with what its contacts do (and its margin).
void print_answer(const Scene& scene, const QueryAnswer& a, const MarginAnswer* m) {
    const auto said = [](double d) { return std::isfinite(d) ? fmt(d) : std::string("unbounded"); };
    std::cout << "verdict: " << to_string(a.verdict) << "\n";
    for (std::size_t k = 0; k < a.letters.size(); ++k) {
        std::cout << "  " << a.letters[k] << "  " << describe_mode(scene, a.letters[k]);
        if (m) std::cout << "   (margin " << said(m->inside[k]) << " to the boundary of its set)";
        std::cout << "\n";
    }
    if (m) {
        std::cout << "  margin to the nearest set of another mode: " << (m->to_other ? said(*m->to_other) : "unbounded")
                  << "\n  (distances of (fx, fy, tau / L), tau about the reference (" << fmt(m->metric.reference.x()) << ", "
                  << fmt(m->metric.reference.y()) << "), L = " << fmt(m->metric.length) << "; docs/design.md, Margins)\n";
    }
}

int run(const QueryOptions& o) {
    if (!o.push.empty()) return run_push_line(o);
    if (!o.wrenches.empty()) {
        if (!o.gravity.empty() || !o.forces.empty()) {
            throw InputError(!o.gravity.empty() ? "--gravity" : "--force", "give the wrenches of --wrenches alone");
        }
        answer_file(o);
        return 0;
    }
    if (o.wrench.empty() && o.gravity.empty() && o.forces.empty()) {
        throw InputError("--wrench", "expected three numbers FX FY TAU (or --gravity, --force, or --wrenches FILE)");
    }
    TerminalProgress progress;
    Problem p = open_problem(o.file, o.quasi_static, progress);
    const Load load = load_of(o.gravity, o.wrench, o.forces);
    std::optional<MarginAnswer> margins;
    if (o.margin) margins = p.margins(load);
    const QueryAnswer a = margins ? margins->answer : p.query(load);
    progress.finish();
    if (o.json) {
        write_answer(std::cout, a, nullptr, margins ? &*margins : nullptr);
        return 0;
    }
    print_answer(p.scene(), a, margins ? &*margins : nullptr);
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
    cmd->add_option("--gravity", opts->gravity, "GX GY: gravity on the body through its centre of mass, added to the applied wrench")
        ->expected(2)
        ->transform(number_check());
    add_force_option(cmd, opts->forces, "added to the applied wrench");
    cmd->add_flag("--json", opts->json, "machine-readable output");
    cmd->add_flag("--margin", opts->margin,
                  "how far the wrench may move before the answer changes: to the boundary of each returned mode's set "
                  "and to the nearest other mode's set (docs/design.md, Margins)");
    cmd->add_flag("--quasi-static", opts->quasi_static, "neglect inertia: the applied wrench balances the contact wrench, E = -T (docs/design.md)");
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
