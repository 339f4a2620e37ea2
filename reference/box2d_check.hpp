#pragma once

// When Box2D's answer can be held against momentlab's, decided from momentlab's margin and the
// independent LCP before Box2D runs (never from Box2D's own reading), and the arbitration of a
// disagreement by a third engine. Shared by validate_box2d and test_box2d.

#include <algorithm>
#include <string>
#include <vector>

#include "box2d_sim.hpp"
#include "coulomb_lcp.hpp"
#include "momentlab/mechanics/analysis.hpp"

namespace momentlab::physics {

/// How deep e lies in mode i's region, as a fraction of |e|: the largest radius of a ball around
/// e inside E_i and outside every other E_j, from the facet planes (conservative). Negative when
/// e is not in E_i alone.
inline double unique_margin(const std::vector<ModeForces>& analysis, std::size_t i, const Vec3& e) {
    const Vec3 u = e.normalized();
    double m = 1.0;
    for (std::size_t j = 0; j < analysis.size(); ++j) {
        const Cone& c = analysis[j].applied;
        if (j == i) {
            if (!c.equations().empty()) return -1;  // a lower-dimensional E_i has no inside
            for (const ExactVector& f : c.facets()) m = std::min(m, f.value().normalized().dot(u));
            continue;
        }
        // Outside E_j by d: some facet (or equation) separates e from E_j by d.
        double out = -1.0;
        for (const ExactVector& f : c.facets()) out = std::max(out, -f.value().normalized().dot(u));
        for (const ExactVector& f : c.equations()) out = std::max(out, std::abs(f.value().normalized().dot(u)));
        if (c.facets().empty() && c.equations().empty()) out = -1.0;  // E_j is everything
        m = std::min(m, out);
    }
    return m;
}

/// Whether Box2D can show the answer at all, decided from the independent LCP (Siconos Lemke,
/// checked) before Box2D runs: a contact that the LCP's acceleration moves, but at under 5% of
/// the fastest contact point, lies near the rotation centre, where the engine's slip (about
/// 0.5%) is as large as the motion and no reading tells its letter. When Lemke fails (it does
/// on about 10% of such LCPs, docs/validation.md), Siconos' enumeration gives the solution (up
/// to 4 contacts); not comparable: an LCP that neither solves.
enum class Readable { Yes, NearTheRotationCentre, NoLcpSolution };

inline Readable readable(validation::CoulombLcp& lcp, const Scene& scene, const Vec3& e) {
    validation::LcpSolution s;
    if (!lcp.lemke(e, s) || !lcp.solves(e, s)) {
        if (scene.contacts.size() > 4) return Readable::NoLcpSolution;
        bool found = false;
        for (const validation::LcpSolution& candidate : lcp.enumerate(e).solutions) {
            if (lcp.solves(e, candidate)) {
                s = candidate;
                found = true;
                break;
            }
        }
        if (!found) return Readable::NoLcpSolution;
    }
    const Vec3 a = lcp.acceleration(e, s);
    std::vector<double> speed;
    double fastest = 0.0;
    for (const Contact& c : scene.contacts) {
        const Vec2 v(a.x() - a.z() * c.point.y(), a.y() + a.z() * c.point.x());
        speed.push_back(v.norm());
        fastest = std::max(fastest, speed.back());
    }
    for (double v : speed) {
        if (v > 1e-6 * fastest && v < 0.05 * fastest) return Readable::NearTheRotationCentre;
    }
    return Readable::Yes;
}

/// True when Siconos' enumeration finds solutions of the LCP and every one has mode `letters`:
/// the arbitration of a disagreement between Box2D and momentlab by a third engine.
inline bool every_lcp_solution_has(validation::CoulombLcp& lcp, const Vec3& e, const std::string& letters) {
    int solving = 0, same = 0;
    for (const validation::LcpSolution& sol : lcp.enumerate(e).solutions) {
        if (!lcp.solves(e, sol)) continue;
        ++solving;
        same += lcp.mode(e, sol) == letters;
    }
    return solving > 0 && same == solving;
}

}  // namespace momentlab::physics
