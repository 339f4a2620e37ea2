// analyze (mechanics/analysis.hpp): every mode's F, T and E; the body's checks and inertia.
#include "momentlab/mechanics/analysis.hpp"

#include <atomic>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "momentlab/core/parallel.hpp"
#include "checks.hpp"
#include "friction_edges.hpp"

namespace momentlab {

void detail::check_body(const Scene& scene, const char* who) {
    if (!scene.body) throw std::invalid_argument(std::string(who) + ": the scene needs a body (mass, com, inertia)");
    const Body& b = *scene.body;
    const bool inertia_ok = b.radius_of_gyration ? *b.radius_of_gyration > 0.0 && std::isfinite(*b.radius_of_gyration)
                                                 : b.inertia > 0.0 && std::isfinite(b.inertia);
    if (!b.com.allFinite() || !(b.mass > 0.0) || !std::isfinite(b.mass) || !inertia_ok) {
        throw std::invalid_argument(std::string(who) +
                                    ": the body needs a finite com, 0 < mass < inf and 0 < inertia < inf (or radius of gyration)");
    }
}

std::optional<ExactMatrix> detail::inertia_of(const Scene& scene, const AnalysisOptions& options, const char* who) {
    if (options.quasi_static) return std::nullopt;
    detail::check_body(scene, who);
    return inertia_at_origin(*scene.body);
}

std::vector<ModeForces> analyze(const Scene& scene, const AnalysisOptions& options) {
    const std::optional<ExactMatrix> m = detail::inertia_of(scene, options, "analyze");
    const ModeSet modes = enumerate_modes(scene.contacts, options.progress);
    const detail::FrictionEdges edges(scene.contacts);
    // The modes are independent: on two threads when there is enough to do (about n letters of
    // work per mode; below 2000 letters a thread costs more than it saves).
    const std::size_t count = modes.modes.size();
    std::vector<ModeForces> out(count);
    std::atomic<std::size_t> done{0};
    const std::thread::id caller = std::this_thread::get_id();
    detail::for_each_index(count, count * scene.contacts.size() >= 2000, [&](std::size_t i) {
        // Progress from the calling thread only (the callback need not be thread-safe).
        if (options.progress && std::this_thread::get_id() == caller) options.progress("force sets of the modes", done, count);
        const Mode& mode = modes.modes[i];
        std::vector<ExactVector> contact_generators;
        edges.for_each(mode, [&](const ExactVector& g) { contact_generators.push_back(g); });
        ModeForces f{mode, m ? mode.twists.linear_image(*m) : Cone(), Cone::from_generators(contact_generators), Cone()};
        // Quasi-static: no inertia, F = {0}, so E = -T (the applied wrench balances the contacts').
        f.applied = m ? sum(f.total, f.contact.negated()) : f.contact.negated();
        out[i] = std::move(f);
        ++done;
    });
    return out;
}

const char* to_string(Verdict v) {
    switch (v) {
        case Verdict::Unique: return "unique";
        case Verdict::Ambiguous: return "ambiguous";
        default: return "inconsistent";
    }
}

}  // namespace momentlab
