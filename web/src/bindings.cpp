// The library compiled to WebAssembly (docs/web.md), on the application layer as the command line
// and Python are: a Session holds one app::Problem (the scene, its analysis and query index), every
// number a user gives is checked there (app/checks.hpp: one rule, the largest coordinate's) and
// answers leave as the CLI's --json texts (io/json_output.hpp). Nothing here throws into
// JavaScript: a bad input becomes {"error": the CLI's one-line message}, and web/src/api.js turns
// it into a JS Error. api.js checks the shapes of JS values (arrays, lengths, NaN, unknown options)
// and hands loads over as JSON text: {"gravity": [gx, gy], "wrench": [fx, fy, tau], "forces":
// [[[x, y], [fx, fy]], ...]}, each key optional.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "momentlab/app/problem.hpp"
#include "momentlab/assembly/assembly_json.hpp"
#include "momentlab/io/force_set_json.hpp"
#include "momentlab/io/json_output.hpp"
#include "momentlab/io/scene_json.hpp"

namespace momentlab::web {
namespace {

using emscripten::val;
using nlohmann::json;

// Runs `answer`; any exception becomes {"error": message}.
template <class F>
std::string guarded(F&& answer) {
    try {
        return answer().dump();
    } catch (const std::exception& e) {
        return json{{"error", e.what()}}.dump();
    }
}

// The names of the module's inputs in messages: JavaScript's keywords.
InputNames web_names() {
    InputNames n;
    n.force = "forces";
    return n;
}

// A number of a load: a JS number its binary value, a decimal string (api.js checked its
// grammar) the decimal it spells (0.1 is 1/10), each finite and in range (app/checks.hpp).
Rational typed(const json& v, const std::string& where) {
    const std::optional<Rational> x = v.is_string() ? Rational::parse(v.get<std::string>()) : std::optional<Rational>(Rational(v.get<double>()));
    // A decimal whose exponent takes it beyond the doubles (1e-999999999): as files say it.
    if (!x && std::strtod(v.get<std::string>().c_str(), nullptr) == 0.0) {
        throw InputError(where, "a number is " + std::string(kTooSmallForADouble));
    }
    if (!x || !std::isfinite(x->to_double())) throw InputError(where, "expected a finite number");
    // as in files and options: a non-zero number never reads as 0 (docs/reliability.md)
    if (!x->is_zero() && x->to_double() == 0.0) throw InputError(where, "a number is " + std::string(kTooSmallForADouble));
    return *x;
}

template <std::size_t N>
std::array<Rational, N> typed_vector(const json& v, const std::string& where) {
    std::array<Rational, N> out;
    std::array<double, N> rounded{};
    for (std::size_t i = 0; i < N; ++i) {
        out[i] = typed(v[i], where + "[" + std::to_string(i) + "]");
        rounded[i] = out[i].to_double();
    }
    if constexpr (N == 2) (void)checked_vector(Vec2(rounded[0], rounded[1]), where);
    if constexpr (N == 3) (void)checked_vector(Vec3(rounded[0], rounded[1], rounded[2]), where);
    return out;
}

// A load from api.js's JSON text (shapes checked there; ranges here, as the Problem's).
Load load_of(const std::string& text) {
    const json doc = json::parse(text);
    Load load;
    if (doc.contains("gravity")) load.gravity = typed_vector<2>(doc["gravity"], "gravity");
    if (doc.contains("wrench")) load.wrench = typed_vector<3>(doc["wrench"], "wrench");
    std::size_t i = 0;
    for (const json& f : doc.value("forces", json::array())) {
        const std::string where = "forces[" + std::to_string(i++) + "]";
        load.forces.emplace_back(typed_vector<2>(f[0], where + "[0]"), typed_vector<2>(f[1], where + "[1]"));
    }
    return load;
}

// A region for drawing: its exact description (as the CLI writes it) and its part in the view.
json drawn(const Region& region, const Box& view) {
    json out = to_json(region);
    json polygon = json::array();
    if (!region.is_empty) {
        for (const Vec2& p : region.clipped(view)) polygon.push_back({output_value(p.x()), output_value(p.y())});
    }
    out["clipped"] = polygon;
    return out;
}

json drawn(const Labels& labels, const Box& view) { return {{"plus", drawn(labels.plus(), view)}, {"minus", drawn(labels.minus(), view)}}; }

// A force set with its labels, cut to the view: {"cone", "plus", "minus", "both"}.
json force_set(const Cone& cone, const Box& view) {
    json out = drawn(Labels(cone), view);
    out["cone"] = to_json(cone);
    out["both"] = drawn(both_region(cone), view);
    return out;
}

Box view_of(double xmin, double ymin, double xmax, double ymax) { return checked_view(xmin, ymin, xmax, ymax, "view"); }

class Session {
public:
    Session(const std::string& scene_text, bool quasi_static) {
        try {
            problem_.emplace(read_scene_text(scene_text, &warnings_), quasi_static, web_names());
            problem_->index();  // the analysis, made now: a scene it cannot analyse is refused here
        } catch (const std::exception& e) {
            error_ = e.what();
        }
    }

    [[nodiscard]] std::string error() const { return error_; }

    [[nodiscard]] val warnings() const {
        val out = val::array();
        for (const std::string& w : warnings_) out.call<void>("push", w);
        return out;
    }

    [[nodiscard]] val modes() {
        val out = val::array();
        for (const ModeForces& m : problem_->analysis()) out.call<void>("push", m.mode.letters);
        return out;
    }

    // The modes of one wrench and, besides it, gravity and forces at points: {"modes", "verdict"}.
    // A wrench of doubles alone is checked and asked of the index (a drag asks many); a load with
    // gravity, forces or decimals goes to Problem::query (exact sums).
    [[nodiscard]] std::string query(const std::string& load_text) {
        return guarded([&] {
            const Load load = load_of(load_text);
            json modes = json::array();
            if (load.wrench && is_double(*load.wrench) && !load.gravity && load.forces.empty()) {
                const auto& a = problem_->analysis();
                std::vector<std::size_t> found = problem_->index().query(checked_vector(to_double(*load.wrench), "wrench")).modes;
                std::sort(found.begin(), found.end(), [&](std::size_t x, std::size_t y) { return a[x].mode.letters < a[y].mode.letters; });
                for (std::size_t k : found) modes.push_back(a[k].mode.letters);
                return json{{"modes", modes}, {"verdict", to_string(verdict_of(found.size()))}};
            }
            const QueryAnswer answer = problem_->query(load);
            for (const std::string& m : answer.letters) modes.push_back(m);
            return json{{"modes", modes}, {"verdict", to_string(answer.verdict)}};
        });
    }

    // For N wrenches (3 N numbers, finite), N * modes bytes: 1 where the mode holds the wrench; or
    // the error's JSON text.
    [[nodiscard]] val query_batch(const val& numbers) {
        const std::vector<double> w = emscripten::convertJSArrayToNumberVector<double>(numbers);
        const std::size_t n = w.size() / 3, m = problem_->analysis().size();
        std::vector<unsigned char> hits(n * m, 0);
        std::vector<std::size_t> found;
        try {
            for (std::size_t i = 0; i < n; ++i) {
                const Vec3 e = checked_vector(Vec3(w[3 * i], w[3 * i + 1], w[3 * i + 2]), "wrenches[" + std::to_string(i) + "]");
                problem_->index().query(e, found);
                for (std::size_t k : found) hits[i * m + k] = 1;
            }
        } catch (const std::exception& e) {
            return val(json{{"error", e.what()}}.dump());
        }
        return val::global("Uint8Array").new_(emscripten::typed_memory_view(hits.size(), hits.data())).call<val>("slice");
    }

    // One mode's sets, each with its labels cut to the view, and its rotation centres.
    [[nodiscard]] std::string mode(const std::string& letters, double xmin, double ymin, double xmax, double ymax) {
        return guarded([&] {
            const Box view = view_of(xmin, ymin, xmax, ymax);
            const ModeForces& m = find_mode(problem_->analysis(), letters, "mode");
            return json{{"mode", letters},
                        {"twists", to_json(m.mode.twists)},
                        {"F", force_set(m.total, view)},
                        {"T", force_set(m.contact, view)},
                        {"E", force_set(m.applied, view)},
                        {"centres", drawn(rotation_centres(m.mode), view)}};
        });
    }

    // As `plan tilt --json`.
    [[nodiscard]] std::string plan_tilt(const std::string& goal, const std::string& load_text) {
        return guarded([&] {
            const Load load = load_of(load_text);
            json out = to_json(problem_->plan_tilt(goal, load));
            out["goal"] = goal;
            if (const std::optional<Rational3> fixed = problem_->wrench_of(load)) {
                out["fixed"] = vector_json(to_double(*fixed));
                add_exact(out, "fixed", *fixed);
            }
            return out;
        });
    }

    // As `plan push --json`; edge and vertex -1 for none, slip "" for every slip.
    // mu: api.js's JSON text of a number or a decimal string (as loads).
    [[nodiscard]] std::string plan_push(const std::string& goal, const std::string& mu_text, bool ignore_interference, int edge,
                                        int vertex, const std::string& slip, const std::string& load_text) {
        return guarded([&] {
            const Load load = load_of(load_text);
            const Rational mu = checked_coefficient(typed(json::parse(mu_text), "mu"), "mu");
            PushRequest request{mu, ignore_interference, std::nullopt, std::nullopt, std::nullopt};
            if (edge >= 0) request.edge = static_cast<std::size_t>(edge);
            if (vertex >= 0) request.vertex = static_cast<std::size_t>(vertex);
            if (!slip.empty()) request.slip = contact_mode(slip[0]);
            json out = {{"goal", goal},
                        {"mu", mu.to_double()},
                        {"interference", ignore_interference ? "ignored" : "considered"},
                        {"cases", json::array()}};
            add_exact(out, "mu", std::span<const Rational>(&mu, 1));  // as the CLI's echo
            for (const PushCase& c : problem_->plan_push(goal, request, load)) out["cases"].push_back(to_json(c));
            if (const std::optional<Rational3> fixed = problem_->wrench_of(load)) {
                out["fixed"] = vector_json(to_double(*fixed));
                add_exact(out, "fixed", *fixed);
            }
            return out;
        });
    }

    // As `plan comply --json` ({"goal", "labels", "centre" when given}), the labels cut to the view.
    // The centre: api.js's JSON text of [x, y] (numbers or decimal strings, as loads), or "".
    [[nodiscard]] std::string plan_comply(const std::string& goal, const std::string& centre_text, double xmin, double ymin,
                                          double xmax, double ymax, const std::string& load_text) {
        return guarded([&] {
            const Box view = view_of(xmin, ymin, xmax, ymax);
            std::optional<Rational2> centre;
            if (!centre_text.empty()) centre = typed_vector<2>(json::parse(centre_text), "centre");
            const ComplyAnswer answer = problem_->plan_comply(goal, centre, load_of(load_text));
            json out = {{"goal", goal}, {"labels", drawn(answer.labels, view)}};
            if (answer.centre) {
                out["centre"] = to_json(*answer.centre);
                add_exact(out["centre"], "point", *centre);
            }
            return out;
        });
    }

    // As `query --push X Y DX DY --json`: the bands of magnitudes of the force along a line; the
    // line is api.js's JSON text [[x, y], [dx, dy]] (numbers or decimal strings, as loads).
    [[nodiscard]] std::string push_line(const std::string& line_text, const std::string& load_text) {
        return guarded([&] {
            const json line = json::parse(line_text);
            const Rational2 point = typed_vector<2>(line[0], "point"), direction = typed_vector<2>(line[1], "direction");
            const Load load = load_of(load_text);
            const std::vector<MagnitudeBand> bands = problem_->push_line(point, direction, load);
            const Rational3 fixed = problem_->wrench_of(load).value_or(Rational3{});
            json out = {{"point", vector_json(to_double(point))},
                        {"direction", vector_json(to_double(direction))},
                        {"fixed", vector_json(to_double(fixed))},
                        {"bands", to_json(bands, problem_->analysis())}};
            add_exact(out, "point", point);  // as the CLI's echo of its typed numbers
            add_exact(out, "direction", direction);
            add_exact(out, "fixed", fixed);
            return out;
        });
    }

    [[nodiscard]] std::string scene_json() const { return to_json(problem_->scene()).dump(); }

private:
    std::optional<Problem> problem_;
    InputWarnings warnings_;
    std::string error_;
};

// Grasp closure of a scene's contacts (the body optional), as `momentlab closure --json`; with a
// view, "labels": the moment labels of the form and force tests' contact wrenches cut to it.
std::string closure_of(const std::string& scene_text, bool has_reference, double rx, double ry, bool has_length, double length,
                       bool has_view,
                       double xmin, double ymin, double xmax, double ymax) {
    return guarded([&] {
        const Problem problem(read_scene_text(scene_text), true, web_names());
        const Closure c = problem.closure(has_reference ? std::optional<Vec2>(Vec2(rx, ry)) : std::nullopt,
                                          !has_length ? std::nullopt : std::optional<double>(length));
        json out = to_json(c);
        if (has_view) {
            const Box view = view_of(xmin, ymin, xmax, ymax);
            out["labels"] = {{"form", force_set(c.form.wrenches, view)}, {"force", force_set(c.force.wrenches, view)}};
        }
        return out;
    });
}

// The labels of a force set in the format of `momentlab label` (docs/formats.md), cut to a view.
std::string labels(const std::string& text, double xmin, double ymin, double xmax, double ymax) {
    return guarded([&] { return force_set(read_force_set_text(text), view_of(xmin, ymin, xmax, ymax)); });
}

// An assembly as `momentlab stand --json` answers it (gravity as a load's: numbers or decimal
// strings; by default (0, -9.81) as the decimal), and "assembly": the scene as read, contacts written out (found ones
// included) for drawing: {"bodies": [{"name", "mass", "com", "polygon"}], "contacts": [{"bodies",
// "point", "normal", "mu"}], "obstacles": [[x, y], ...]}, with "warnings".
std::string stand_of(const std::string& scene_text, const std::string& load_text, bool tilt) {
    return guarded([&] {
        InputWarnings warnings;
        const Assembly a = read_assembly_text(scene_text, &warnings);
        StandOptions options;
        if (const Load load = load_of(load_text); load.gravity) options.gravity = *load.gravity;
        options.tilt = tilt;
        json out = to_json(stand(a, options));
        json bodies = json::array(), contacts = json::array(), obstacles = json::array();
        const auto polygon = [](const Polygon& p) {
            json v = json::array();
            for (const Vec2& q : p) v.push_back(vector_json(q));
            return v;
        };
        for (const AssemblyBody& b : a.bodies) {
            bodies.push_back({{"name", b.name}, {"mass", output_value(b.mass)}, {"com", vector_json(b.com)}, {"polygon", polygon(b.polygon)}});
        }
        for (const AssemblyContact& c : a.contacts) {
            contacts.push_back({{"bodies", {c.a, c.b}},
                                {"point", vector_json(c.contact.point)},
                                {"normal", vector_json(c.contact.normal)},
                                {"mu", output_value(c.contact.mu)}});
        }
        for (const Polygon& o : a.obstacles) obstacles.push_back(polygon(o));
        out["assembly"] = {{"bodies", bodies}, {"contacts", contacts}, {"obstacles", obstacles}};
        out["warnings"] = warnings;
        return out;
    });
}

}  // namespace
}  // namespace momentlab::web

EMSCRIPTEN_BINDINGS(momentlab) {
    using namespace momentlab::web;
    emscripten::class_<Session>("Session")
        .constructor<std::string, bool>()
        .function("error", &Session::error)
        .function("warnings", &Session::warnings)
        .function("modes", &Session::modes)
        .function("query", &Session::query)
        .function("queryBatch", &Session::query_batch)
        .function("mode", &Session::mode)
        .function("planTilt", &Session::plan_tilt)
        .function("planPush", &Session::plan_push)
        .function("planComply", &Session::plan_comply)
        .function("pushLine", &Session::push_line)
        .function("sceneJson", &Session::scene_json);
    emscripten::function("labels", &labels);
    emscripten::function("closure", &closure_of);
    emscripten::function("standJson", &stand_of);
}
