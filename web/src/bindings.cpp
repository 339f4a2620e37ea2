// The library compiled to WebAssembly (docs/web.md): a Session holds one scene with its analysis
// and compiled QueryIndex; answers leave as JSON texts (the same views as the CLI's --json, from
// io/json_output.hpp) or JS arrays. Nothing here throws into JavaScript: a bad input is kept as
// the CLI's one-line message, and web/src/api.js turns it into a JS Error.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "momentlab/io/force_set_json.hpp"
#include "momentlab/io/json_output.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/closure.hpp"
#include "momentlab/mechanics/query_index.hpp"
#include "momentlab/planning/comply.hpp"
#include "momentlab/planning/push.hpp"
#include "momentlab/planning/tilt.hpp"

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

std::optional<Box> box_of(double xmin, double ymin, double xmax, double ymax) {
    if (!std::isfinite(xmin) || !std::isfinite(ymin) || !std::isfinite(xmax) || !std::isfinite(ymax) || !(xmin < xmax) ||
        !(ymin < ymax)) {
        throw InputError("view", "expected a box with xmin < xmax and ymin < ymax, all finite");
    }
    return Box{Vec2(xmin, ymin), Vec2(xmax, ymax)};
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

// A force set with its labels, cut to the view: {"cone", "plus", "minus", "both"}.
json force_set(const Cone& cone, const Box& view) {
    const Labels labels(cone);
    return {{"cone", to_json(cone)},
            {"plus", drawn(labels.plus(), view)},
            {"minus", drawn(labels.minus(), view)},
            {"both", drawn(both_region(cone), view)}};
}

class Session {
public:
    Session(const std::string& scene_text, bool quasi_static) {
        try {
            scene_ = read_scene_text(scene_text, &warnings_);
            analysis_ = analyze_input(scene_, "analyze", AnalysisOptions{quasi_static});
            index_.emplace(analysis_);
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

    [[nodiscard]] val modes() const {
        val out = val::array();
        for (const ModeForces& m : analysis_) out.call<void>("push", m.mode.letters);
        return out;
    }

    // The modes of one wrench (the caller checked it is finite).
    [[nodiscard]] val query(double fx, double fy, double tau) const {
        val out = val::array();
        if (!index_) return out;
        index_->query(Vec3(fx, fy, tau), found_);
        for (std::size_t k : found_) out.call<void>("push", analysis_[k].mode.letters);
        return out;
    }

    // For N wrenches (3 N numbers, finite), N * modes bytes: 1 where the mode holds the wrench.
    [[nodiscard]] val query_batch(const val& numbers) const {
        const std::vector<double> w = emscripten::convertJSArrayToNumberVector<double>(numbers);
        const std::size_t n = w.size() / 3, m = analysis_.size();
        std::vector<unsigned char> hits(n * m, 0);
        for (std::size_t i = 0; i < n && index_; ++i) {
            index_->query(Vec3(w[3 * i], w[3 * i + 1], w[3 * i + 2]), found_);
            for (std::size_t k : found_) hits[i * m + k] = 1;
        }
        return val::global("Uint8Array").new_(emscripten::typed_memory_view(hits.size(), hits.data())).call<val>("slice");
    }

    // One mode's sets, each with its labels cut to the view, and its rotation centres.
    [[nodiscard]] std::string mode(const std::string& letters, double xmin, double ymin, double xmax, double ymax) const {
        return guarded([&] {
            const Box view = *box_of(xmin, ymin, xmax, ymax);
            const ModeForces& m = find(letters);
            const Labels centres = rotation_centres(m.mode);
            return json{{"mode", letters},
                        {"twists", to_json(m.mode.twists)},
                        {"F", force_set(m.total, view)},
                        {"T", force_set(m.contact, view)},
                        {"E", force_set(m.applied, view)},
                        {"centres", {{"plus", drawn(centres.plus(), view)}, {"minus", drawn(centres.minus(), view)}}}};
        });
    }

    [[nodiscard]] std::string plan_tilt(const std::string& goal) const {
        return guarded([&] {
            json out = to_json(momentlab::plan_tilt(scene_, find(goal), context()));
            out["goal"] = goal;
            return out;
        });
    }

    [[nodiscard]] std::string plan_push(const std::string& goal, double mu, bool ignore_interference) const {
        return guarded([&] {
            if (!(mu >= 0.0) || !std::isfinite(mu) || !magnitude_in_range(mu)) {
                throw InputError("mu", "expected a finite mu >= 0 (0 or 1e-60 .. 1e60)");
            }
            if (!scene_.body || scene_.body->polygon.size() < 3) throw InputError("$.body.polygon", "plan push needs the body's polygon");
            json out = {{"goal", goal}, {"mu", mu}, {"cases", json::array()}};
            for (const PushCase& c : momentlab::plan_push(scene_, find(goal), PushOptions{mu, ignore_interference}, context())) {
                out["cases"].push_back(to_json(c));
            }
            return out;
        });
    }

    [[nodiscard]] std::string plan_comply(const std::string& goal, double x, double y, double xmin, double ymin,
                                          double xmax, double ymax) const {
        return guarded([&] {
            const Box view = *box_of(xmin, ymin, xmax, ymax);
            if (!std::isfinite(x) || !std::isfinite(y)) throw InputError("centre", "expected finite numbers");
            const ModeForces& g = find(goal);
            const Labels labels = compliance_labels(g);
            return json{{"goal", goal},
                        {"labels", {{"plus", drawn(labels.plus(), view)}, {"minus", drawn(labels.minus(), view)}}},
                        {"centre", to_json(momentlab::plan_comply(g, Vec2(x, y), context()))}};
        });
    }

    [[nodiscard]] std::string scene_json() const { return to_json(scene_).dump(); }

private:
    const ModeForces& find(const std::string& letters) const { return find_mode(analysis_, letters, "mode"); }
    // As the CLI plans: told every mode (unique and shared) and the margins' metric.
    [[nodiscard]] PlanContext context() const {
        PlanContext c;
        c.modes = analysis_;
        c.metric = default_metric(scene_);
        return c;
    }

    Scene scene_;
    std::vector<ModeForces> analysis_;
    std::optional<QueryIndex> index_;
    InputWarnings warnings_;
    std::string error_;
    mutable std::vector<std::size_t> found_;
};

// Grasp closure of a scene's contacts (the body optional), as `momentlab closure --json`.
std::string closure_of(const std::string& scene_text) {
    return guarded([&] { return to_json(closure(read_scene_text(scene_text))); });
}

// The labels of a force set in the format of `momentlab label` (docs/formats.md), cut to a view.
std::string labels(const std::string& text, double xmin, double ymin, double xmax, double ymax) {
    return guarded([&] { return force_set(read_force_set_text(text), *box_of(xmin, ymin, xmax, ymax)); });
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
        .function("sceneJson", &Session::scene_json);
    emscripten::function("labels", &labels);
    emscripten::function("closure", &closure_of);
}
