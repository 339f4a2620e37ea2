#pragma once

// The exact LP oracle (reference/lp_oracle) asked about a scene: every quantity built in exact
// rationals from the scene's raw numbers (reference/exact_scene.hpp), following the definitions
// (docs/design.md, "Per-mode force sets"), never from momentlab's wrenches, matrices or cones.
// f: the friction cone's edges n +- mu t; r: n - mu_k t; l: n + mu_k t; s: none.

#include <set>
#include <string>
#include <vector>

#include "exact_scene.hpp"
#include "lp_oracle.hpp"

namespace momentlab::testing {

/// The contacts' N_j and T_j, exactly.
struct ExactContacts {
    std::vector<reference::QVec> n, t;
    std::vector<reference::QContact> raw;
    explicit ExactContacts(const std::vector<Contact>& contacts) {
        for (const Contact& c : contacts) {
            raw.emplace_back(c);
            n.push_back(raw.back().normal());
            t.push_back(raw.back().tangent());
        }
    }
};

/// Every contact mode of the contacts, by brute force over {s, f, r, l}^n with exact LPs.
inline std::set<std::string> exact_modes(const std::vector<Contact>& contacts) {
    const ExactContacts c(contacts);
    return oracle::all_modes(c.n, c.t);
}

/// Whether the applied wrench e (exact rationals) is in the closed E of the mode `letters`,
/// by one exact rational LP.
inline bool exact_lp_applied_in_mode(const Scene& scene, const std::string& letters, const reference::QVec& e) {
    const ExactContacts c(scene.contacts);
    std::vector<std::vector<reference::QVec>> generators;
    for (std::size_t j = 0; j < scene.contacts.size(); ++j) generators.push_back(c.raw[j].generators(letters[j]));
    return oracle::applied_in_mode(reference::inertia(*scene.body), c.n, c.t, generators, letters, e);
}

inline bool exact_lp_applied_in_mode(const Scene& scene, const std::string& letters, const Vec3& e) {
    return exact_lp_applied_in_mode(scene, letters, reference::q(e));
}

/// The same LP with the inertia terms removed (the quasi-static model): e = -c, c in T of the
/// mode, the mode's twists only required to exist (the LP's twist constraints stay, with a zero
/// inertia matrix). No body is read.
inline bool exact_lp_quasi_static_in_mode(const Scene& scene, const std::string& letters, const reference::QVec& e) {
    const ExactContacts c(scene.contacts);
    std::vector<std::vector<reference::QVec>> generators;
    for (std::size_t j = 0; j < scene.contacts.size(); ++j) generators.push_back(c.raw[j].generators(letters[j]));
    const reference::QVec zero{0, 0, 0};
    return oracle::applied_in_mode(reference::QMat{zero, zero, zero}, c.n, c.t, generators, letters, e);
}

/// The oracle's answer to "which modes does e produce": every mode of `modes` (the brute-force
/// list, exact_modes) whose closed E holds e, by one exact LP each, sorted by letters.
inline std::vector<std::string> exact_answer(const Scene& scene, const std::set<std::string>& modes,
                                             const reference::QVec& e, bool quasi_static) {
    std::vector<std::string> out;
    for (const std::string& letters : modes) {
        const bool in = quasi_static ? exact_lp_quasi_static_in_mode(scene, letters, e)
                                     : exact_lp_applied_in_mode(scene, letters, e);
        if (in) out.push_back(letters);
    }
    return out;  // (a std::set iterates in sorted order)
}

}  // namespace momentlab::testing
