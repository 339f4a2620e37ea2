#pragma once

/// \file
/// An analysis compiled for many questions: the same answers as query (mechanics/analysis.hpp),
/// tens of millions per second (docs/robustness.md, "Queries"; docs/benchmarks.md).

#include <cstdint>
#include <utility>
#include <vector>

#include "momentlab/core/exact.hpp"
#include "momentlab/mechanics/analysis.hpp"

namespace momentlab {

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
