#pragma once

// The exact LP oracle (tests/oracle/lp_oracle) asked about a scene's mode: the contact-force
// generators of each letter, written here from the definitions (DESIGN, "Per-mode force sets"),
// not taken from momentlab's cones. f: the friction cone's edges n +- mu t; r: n - mu_k t;
// l: n + mu_k t; s: none.

#include <string>
#include <vector>

#include "../oracle/lp_oracle.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab::testing {

/// Whether the applied wrench e is in the closed E of the mode `letters`, for the inertia at
/// the origin m, by one exact rational LP.
inline bool exact_lp_applied_in_mode(const Scene& scene, const Mat3& m, const std::string& letters, const Vec3& e) {
    std::vector<Vec3> n, t;
    std::vector<std::vector<Vec3>> generators(scene.contacts.size());
    for (std::size_t j = 0; j < scene.contacts.size(); ++j) {
        const Contact& c = scene.contacts[j];
        n.push_back(c.normal_wrench());
        t.push_back(c.tangent_wrench());
        const Vec2 nv = c.normal, tv = c.tangent();
        if (letters[j] == 'f') generators[j] = {wrench_at(c.point, nv + c.mu * tv), wrench_at(c.point, nv - c.mu * tv)};
        if (letters[j] == 'r') generators[j] = {wrench_at(c.point, nv - c.mu_kinetic * tv)};
        if (letters[j] == 'l') generators[j] = {wrench_at(c.point, nv + c.mu_kinetic * tv)};
    }
    return oracle::applied_in_mode(m, n, t, generators, letters, e);
}

}  // namespace momentlab::testing
