// query(scene, e) (mechanics/analysis.hpp): the one-shot path when it can, the exact walk when it
// must; and query(analysis, e) (mechanics/advanced.hpp), mode by mode.
#include "query.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "checks.hpp"

namespace momentlab {

QueryAnswer detail::canonical(SceneAnswer&& answer) {
    std::vector<std::size_t> order(answer.modes.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return answer.modes[a].letters < answer.modes[b].letters; });
    QueryAnswer out;
    out.letters.reserve(order.size());
    out.twists.reserve(order.size());
    for (std::size_t k : order) {
        out.letters.push_back(std::move(answer.modes[k].letters));
        out.twists.push_back(std::move(answer.modes[k].twists));
    }
    out.verdict = verdict_of(out.letters.size());
    return out;
}

QueryAnswer query(const Scene& scene, const Vec3& e, const AnalysisOptions& options, QueryDiagnostics& diagnostics) {
    if (!e.allFinite()) throw std::invalid_argument("query: the wrench must be finite");
    if (!options.quasi_static) detail::check_body(scene, "query");
    detail::check_contacts(scene.contacts);
    diagnostics = {};
    if (std::optional<std::vector<std::string>> letters = detail::one_shot(scene, e, options.quasi_static)) {
        diagnostics.filtered = true;
        QueryAnswer out;
        out.verdict = verdict_of(letters->size());
        out.letters = std::move(*letters);
        return out;
    }
    return detail::canonical(query_scene(scene, e, options, &diagnostics));
}

QueryAnswer query(const Scene& scene, const Exact3& e, const AnalysisOptions& options) {
    if (e[0].fits_double() && e[1].fits_double() && e[2].fits_double()) return query(scene, to_double(e), options);
    if (!options.quasi_static) detail::check_body(scene, "query");
    detail::check_contacts(scene.contacts);
    return detail::canonical(query_scene(scene, e, options));
}

QueryAnswer query(const Scene& scene, const Vec3& e, const AnalysisOptions& options) {
    QueryDiagnostics diagnostics;
    return query(scene, e, options, diagnostics);
}

QueryResult query(const std::vector<ModeForces>& analysis, const Vec3& e) {
    if (!e.allFinite()) throw std::invalid_argument("query: the wrench must be finite");
    QueryResult r;
    for (std::size_t i = 0; i < analysis.size(); ++i) {
        if (analysis[i].applied.has(e)) r.modes.push_back(i);
    }
    r.verdict = verdict_of(r.modes.size());
    return r;
}

}  // namespace momentlab
