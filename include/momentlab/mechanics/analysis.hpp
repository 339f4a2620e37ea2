#pragma once

/// \file
/// Per-mode force sets of a body at rest (analyze: F, T and E of every mode) and the inverse
/// question "which mode follows from this applied wrench?" (query) (Mason 1991, section 2.1;
/// docs/design.md, "Per-mode force sets"). For many questions about one scene, QueryIndex
/// (mechanics/query_index.hpp); the paths underneath, with their diagnostics, are in
/// mechanics/advanced.hpp.

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/modes.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// The sets of one mode: twists A, total wrenches F = M A, contact wrenches T, applied
/// wrenches E = F + (-T). All are closed cones (the closures of the mode's sets).
struct ModeForces {
    Mode mode;
    Cone total;    ///< F_i
    Cone contact;  ///< T_i: {0} for s, the friction cone (static mu) for f, the ray n -+ mu_k t for r / l
    Cone applied;  ///< E_i
};

/// How the body's dynamics enter the force sets.
struct AnalysisOptions {
    /// Quasi-static: inertia neglected, the applied wrench balances the contact wrench. Then
    /// F_i = {0} and E_i = -T_i for every mode (each mode's set of motions is non-empty), and no
    /// body is needed; a wrench in no E_i cannot be held quasi-statically (docs/design.md).
    bool quasi_static = false;
    /// Told how the enumeration and the per-mode sets go (may be empty). Called from the
    /// calling thread only, even when the modes are shared out to two threads.
    Progress progress = nullptr;
};

/// Every mode with its force sets. Needs the body (mass, centre of mass, inertia) unless
/// quasi-static. Throws std::invalid_argument if the scene has no body, or its com is not
/// finite, or its mass or inertia is not finite and > 0 (and, through enumerate_modes, for bad
/// contacts). When modes x contacts >= 2000 the modes' sets are built on two threads
/// (core/parallel.hpp); the result is the same.
[[nodiscard]] std::vector<ModeForces> analyze(const Scene& scene, const AnalysisOptions& options = {});

/// How many modes an applied wrench produces.
enum class Verdict { Unique, Ambiguous, Inconsistent };

/// "unique", "ambiguous" or "inconsistent".
[[nodiscard]] const char* to_string(Verdict v);

/// The verdict of an answer with that many modes: 0 inconsistent, 1 unique, more ambiguous.
[[nodiscard]] constexpr Verdict verdict_of(std::size_t mode_count) {
    return mode_count == 0 ? Verdict::Inconsistent : (mode_count == 1 ? Verdict::Unique : Verdict::Ambiguous);
}

/// The modes whose (closed) E_i contains the applied wrench e, exactly, by their indices into
/// the analysis (QueryIndex). A wrench on the boundary between modes belongs to each of them, so
/// boundary wrenches can be "ambiguous"; for a generic wrench the closures make no difference.
struct QueryResult {
    std::vector<std::size_t> modes;  ///< indices into the analysis, increasing
    Verdict verdict = Verdict::Inconsistent;
};

/// The answer to "which modes does the applied wrench e produce?". Every answer lists its modes in
/// one order: their letters sorted as strings ('f' < 'l' < 'r' < 's'), whichever path found them.
struct QueryAnswer {
    std::vector<std::string> letters;  ///< the modes e produces, sorted
    /// Each mode's closed cone of twists, in the order of `letters`, when the exact walk answered;
    /// empty when the one-shot path did (it finds the letters only).
    std::vector<Cone> twists;
    Verdict verdict = Verdict::Inconsistent;
};

/// Which modes the applied wrench e (fx, fy, tau about the origin) produces on a scene, exactly,
/// the same modes as analyze(scene) holds e in (closed sets E_i). The fast path first: for 2 to
/// 12 contacts the modes and their sets E are found in double arithmetic that carries a forward
/// error bound with every number, as long as every sign it meets is certified by its bound (the
/// scene is generic: no three contact wrenches N_j dependent, no sliding direction exactly zero on
/// a ray of A, e on no boundary); otherwise, and for other sizes, the exact walk of the cells
/// (query_scene, mechanics/advanced.hpp) answers, which builds a mode's E only where no
/// certificate from the cells before decides (docs/robustness.md, "One question about a new
/// scene"). One-shot O(n^3 + M k^3) for n contacts, M modes, at most k generators per E. Throws
/// as analyze does, and std::invalid_argument for a non-finite wrench.
[[nodiscard]] QueryAnswer query(const Scene& scene, const Vec3& e, const AnalysisOptions& options = {});

}  // namespace momentlab
