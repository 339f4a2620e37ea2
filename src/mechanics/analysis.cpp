// analyze and query (mechanics/analysis.hpp): every mode's F, T and E, and the modes whose
// closed E holds an applied wrench.
#include "momentlab/mechanics/analysis.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "momentlab/geometry/force_sets.hpp"

namespace momentlab {

std::vector<ModeForces> analyze(const Scene& scene, const AnalysisOptions& options) {
    std::optional<ExactMatrix> m;
    if (!options.quasi_static) {
        if (!scene.body) throw std::invalid_argument("analyze: the scene needs a body (mass, com, inertia)");
        const Body& b = *scene.body;
        const bool inertia_ok = b.radius_of_gyration ? *b.radius_of_gyration > 0.0 && std::isfinite(*b.radius_of_gyration)
                                                     : b.inertia > 0.0 && std::isfinite(b.inertia);
        if (!b.com.allFinite() || !(b.mass > 0.0) || !std::isfinite(b.mass) || !inertia_ok) {
            throw std::invalid_argument(
                "analyze: the body needs a finite com, 0 < mass < inf and 0 < inertia < inf (or radius of gyration)");
        }
        m = inertia_at_origin(*scene.body);
    }
    const ModeSet modes = enumerate_modes(scene.contacts, options.progress);
    // Each contact's friction edges, built once for all the modes (exact constructions; copies
    // share them): the static cone's two edges, and the kinetic ones n + mu_k t, n - mu_k t.
    std::vector<std::array<ExactVector, 2>> static_edges, kinetic_edges;
    for (const Contact& c : scene.contacts) {
        static_edges.push_back(friction_cone_edges(c.point, c.normal, c.mu));
        kinetic_edges.push_back(c.mu_kinetic == c.mu ? static_edges.back()
                                                     : friction_cone_edges(c.point, c.normal, c.mu_kinetic));
    }
    std::vector<ModeForces> out;
    out.reserve(modes.modes.size());
    for (const Mode& mode : modes.modes) {
        if (options.progress) options.progress("force sets of the modes", out.size(), modes.modes.size());
        std::vector<ExactVector> contact_generators;
        for (std::size_t j = 0; j < scene.contacts.size(); ++j) {
            switch (mode.at(j)) {
                case ContactMode::Fixed:  // anywhere in the friction cone (static mu)
                    contact_generators.insert(contact_generators.end(), static_edges[j].begin(), static_edges[j].end());
                    break;
                case ContactMode::SlidingRight:  // friction opposes sliding along +t: n - mu_k t
                    contact_generators.push_back(kinetic_edges[j][1]);
                    break;
                case ContactMode::SlidingLeft:  // n + mu_k t
                    contact_generators.push_back(kinetic_edges[j][0]);
                    break;
                case ContactMode::Separating:
                    break;
            }
        }
        ModeForces f{mode, m ? mode.twists.linear_image(*m) : Cone(), Cone::from_generators(contact_generators), Cone()};
        // Quasi-static: no inertia, F = {0}, so E = -T (the applied wrench balances the contacts').
        f.applied = m ? sum(f.total, f.contact.negated()) : f.contact.negated();
        out.push_back(std::move(f));
    }
    return out;
}

const char* to_string(Verdict v) {
    switch (v) {
        case Verdict::Unique: return "unique";
        case Verdict::Ambiguous: return "ambiguous";
        default: return "inconsistent";
    }
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
