#pragma once

/// \file
/// Many questions about one scene: an analysis compiled into planes, tens of millions of answers
/// per second (docs/robustness.md, "Queries"; docs/benchmarks.md), or a scene whose index chooses
/// between walking its cells for each batch of questions and analysing it once.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "momentlab/core/exact.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/diagnostics.hpp"

namespace momentlab {

/// Many questions about one scene, each answered exactly as query(scene, e) and
/// query(analyze(scene), e) answer it.
///
/// Made from an analysis: every distinct plane of every E_i is stored once. For up to 32 modes
/// each plane carries a certified single-precision filter and the set of modes allowed on either
/// side, so a question is one vectorised pass over the planes and a few AND instructions; when
/// the filter cannot decide some plane (or for more modes) every side is decided exactly and each
/// mode checks its own. The analysis is not kept (its modes' letters are, for answer()).
///
/// Made from a scene: the questions are answered by the exact walk of the cells
/// (SceneQuestions, mechanics/advanced.hpp), a batch of wrenches per walk, for as long as walking
/// for the questions left costs less than an analysis; then the scene is analysed and compiled
/// as above, and answers the rest for next to nothing (rent or buy: at most about twice the better
/// of the two). After each walk its work (cells walked, generators tested, generators scanned by
/// mends; QueryDiagnostics) is weighed against an analysis on two threads (about the modes plus
/// their closed contacts): the work per answer so far times the questions left, when their number
/// was given, else the work so far. A scene whose modes would hold more than 10^8 letters is never
/// analysed. The answers are the same either way. Not for two threads at once.
class QueryIndex {
public:
    /// The analysis compiled (its modes' indices are the answers' indices).
    explicit QueryIndex(const std::vector<ModeForces>& analysis);
    /// Questions about a scene, `questions` of them when known (a file's lines), to be asked in
    /// batches of batch() wrenches (any size works; that one costs least). Throws as analyze does.
    explicit QueryIndex(const Scene& scene, const AnalysisOptions& options = {},
                        std::optional<std::size_t> questions = std::nullopt);
    ~QueryIndex();
    QueryIndex(QueryIndex&&) noexcept;
    QueryIndex& operator=(QueryIndex&&) noexcept;

    /// The modes (indices into the analysis, analyze's order, increasing) whose closed E_i holds
    /// e, written to `modes` (cleared first; its capacity is reused), and the verdict. Throws
    /// std::invalid_argument for a wrench with a NaN or infinite coordinate.
    Verdict query(const Vec3& e, std::vector<std::size_t>& modes) const;

    /// The same, allocating the result.
    [[nodiscard]] QueryResult query(const Vec3& e) const;

    /// The answers to a batch of wrenches, handed to `take` in order, each a QueryAnswer (letters
    /// sorted; twists when the walk answered). Throws std::invalid_argument, answering none, if a
    /// wrench is not finite.
    void answer(std::span<const Vec3> wrenches, const std::function<void(QueryAnswer&&)>& take);
    /// One wrench's answer.
    [[nodiscard]] QueryAnswer answer(const Vec3& e);

    /// How many wrenches the next call to answer() had best bring: for an index made from a
    /// scene, 1 while the walk is being priced (or when the next answer comes from the analysis),
    /// then batches of 256 when the number of questions is known (one walk for all of them);
    /// 1 for an index made from an analysis.
    [[nodiscard]] std::size_t batch() const;

    /// The analysis behind the answers: made now if this index, made from a scene, has not made it
    /// yet. Throws std::logic_error for an index made from an analysis (which keeps none).
    [[nodiscard]] const std::vector<ModeForces>& analysis();

    /// The work of the walks so far (summed over their answers; none once analysed, or for an
    /// index made from an analysis).
    [[nodiscard]] const QueryDiagnostics& diagnostics() const;

    /// The number of distinct planes (a plane and its opposite count once); 0 before an index
    /// made from a scene has analysed it.
    [[nodiscard]] std::size_t planes() const;
    /// The number of modes (0 before an index made from a scene has analysed it).
    [[nodiscard]] std::size_t modes() const;

    struct Walk;  ///< the state of an index made from a scene (internal)

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
    // The modes' letters, for answer() (an index made from an analysis).
    std::vector<std::string> letters_;
    // An index made from a scene: its walk, and then its analysis with an index of its own.
    std::unique_ptr<Walk> walk_;
};

}  // namespace momentlab
