#pragma once

/// \file
/// Per-mode force sets of a body at rest and the inverse question "which mode follows from
/// this applied wrench?" (Mason 1991, section 2.1; DESIGN, "Per-mode force sets").

#include <cstdint>
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

/// Every mode with its force sets. Needs the body (mass, centre of mass, inertia).
/// Throws std::invalid_argument if the scene has no body, or its com is not finite, or its
/// mass or inertia is not finite and > 0 (and, through enumerate_modes, for bad contacts).
[[nodiscard]] std::vector<ModeForces> analyze(const Scene& scene);

/// How many modes an applied wrench produces.
enum class Verdict { Unique, Ambiguous, Inconsistent };

/// "unique", "ambiguous" or "inconsistent".
[[nodiscard]] const char* to_string(Verdict v);

/// The modes whose (closed) E_i contains the applied wrench e, exactly. A wrench on the
/// boundary between modes belongs to each of them, so boundary wrenches can be "ambiguous";
/// for a generic wrench the closures make no difference.
struct QueryResult {
    std::vector<std::size_t> modes;  ///< indices into the analysis, increasing
    Verdict verdict = Verdict::Inconsistent;
};

/// Which modes the applied wrench e (fx, fy, tau about the origin) can produce. Throws
/// std::invalid_argument for a non-finite wrench.
[[nodiscard]] QueryResult query(const std::vector<ModeForces>& analysis, const Vec3& e);

/// The analysis compiled for many questions (planners, `query --wrenches`). Every distinct
/// plane of every E_i is stored once. For up to 32 modes each plane carries a certified
/// single-precision filter and the set of modes allowed on either side, so a question is one
/// vectorised pass over the planes and a few AND instructions; when the filter cannot decide
/// some plane (or for more modes) every side is decided exactly and each mode checks its own.
/// Answers are exactly those of query(analysis, e).
class QueryIndex {
public:
    explicit QueryIndex(const std::vector<ModeForces>& analysis);

    /// The modes (indices into the analysis, increasing) whose closed E_i holds e, written to
    /// `modes` (cleared first; its capacity is reused), and the verdict. Throws
    /// std::invalid_argument for a wrench with a NaN or infinite coordinate.
    Verdict query(const Vec3& e, std::vector<std::size_t>& modes) const;

    /// The same, allocating the result.
    [[nodiscard]] QueryResult query(const Vec3& e) const;

    /// The number of distinct planes (a plane and its opposite count once).
    [[nodiscard]] std::size_t planes() const { return exact_.size(); }
    /// The number of modes.
    [[nodiscard]] std::size_t modes() const { return mode_count_; }

private:
    static constexpr std::size_t kBlock = 8;  // planes per step of the filter pass
    using Rows = std::vector<std::vector<std::pair<std::uint32_t, int>>>;
    void build_filter(const Rows& per_mode);
    // Every plane's side decided exactly, then each mode's half-spaces checked.
    Verdict exact_query(const Vec3& e, std::vector<std::size_t>& modes) const;

    std::size_t mode_count_ = 0;
    std::vector<ExactVector> exact_;  // the planes
    // Up to 32 modes, a single-precision filter, padded to whole blocks: the planes scaled by
    // powers of two (one array per coordinate), the error bound per unit of max|e_k|, and the
    // modes allowed when the plane is positive / negative (zero allows all).
    std::vector<float> ax_, ay_, az_, bound_;
    std::vector<std::uint32_t> if_positive_, if_negative_;
    // Mode i's half-spaces as (plane, orientation), in rows.
    std::vector<std::uint32_t> row_start_;
    std::vector<std::pair<std::uint32_t, int>> halfspaces_;
};

}  // namespace momentlab
