#pragma once

/// \file
/// The paths underneath `query(scene, e)` and `QueryIndex` (mechanics/analysis.hpp,
/// mechanics/query_index.hpp), for tests, benchmarks and tools that compare or measure them: the
/// exact walk of one scene (query_scene, SceneQuestions), a question tested mode by mode on an
/// analysis (query(analysis, e)), and the diagnostics of each answer. A program asks through the
/// front door (momentlab/momentlab.hpp); the answers here are the same, with more work shown.

#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/diagnostics.hpp"

namespace momentlab {

/// Which modes of the analysis hold the applied wrench e (fx, fy, tau about the origin): each
/// mode's E tested in turn (QueryIndex gives the same answers faster). Throws
/// std::invalid_argument for a non-finite wrench.
[[nodiscard]] QueryResult query(const std::vector<ModeForces>& analysis, const Vec3& e);

/// query(scene, e, options), and how it was answered (diagnostics.filtered: the one-shot path).
[[nodiscard]] QueryAnswer query(const Scene& scene, const Vec3& e, const AnalysisOptions& options,
                                QueryDiagnostics& diagnostics);

/// One question about a scene not analysed, answered by the exact walk: which of its modes e
/// produces, in enumerate_modes' order.
struct SceneAnswer {
    std::vector<Mode> modes;     ///< the modes e produces (letters and twists), in the order of result.modes
    QueryResult result;          ///< their indices in enumerate_modes' order (analyze's), increasing
    std::size_t mode_count = 0;  ///< how many modes the scene has
};

/// The same answer as query(analyze(scene, options), e), without building every mode's sets or
/// writing every mode's letters. The modes are met cell by cell along the faces of the cone of
/// motions (a 2-D face in angular order, where neighbouring cells differ by the contacts whose
/// sliding direction changes between them), each tried first against certificates kept from the
/// cells before: a plane h with h . e < 0 that holds every generator of this E on its side proves
/// e is not in E (Farkas; along a face only the generators that changed are checked against the
/// latest plane), and three generators of an earlier E whose cone holds e, when this cell has all
/// three, prove e is in it. Only a cell that no certificate decides has e tested against its E
/// (cone_holds: E's extreme rays, with no facet built but the separating one; this gives a new
/// certificate; before it, a plane found in doubles with room on both sides is tried, and kept
/// when exact signs confirm it). On a face of many closed contacts whose edges have few distinct
/// forces, each group of one force counts by its edges of least and greatest torque. Every sign
/// is exact. O(n log n + M + C log n + (B log k + R) k + L) for n contacts, M modes, C letter
/// changes along the walks, B modes tested so and R certificates mended on faces not grouped, k
/// closed contacts per face and L letters in the answer; memory O(n + L) (docs/benchmarks.md,
/// "Nearly degenerate scenes"). From 20 contacts on two threads: the walk's set-up beside the
/// friction edges, then the all-f mode and up to 32 parts of the faces; the result is the same.
/// The answer's work goes to `diagnostics` when given. Throws as analyze does, and
/// std::invalid_argument for a non-finite wrench.
[[nodiscard]] SceneAnswer query_scene(const Scene& scene, const Vec3& e, const AnalysisOptions& options = {},
                                      QueryDiagnostics* diagnostics = nullptr);
/// The same for an exact wrench, which need not be doubles (a decimal one with its denominators
/// cleared): the same walk, every decision against e exactly.
[[nodiscard]] SceneAnswer query_scene(const Scene& scene, const Exact3& e, const AnalysisOptions& options = {},
                                      QueryDiagnostics* diagnostics = nullptr);

/// query(scene, e, options) for an exact wrench: the one-shot path when e is doubles, else the
/// exact walk (query_scene), never an analysis of the scene.
[[nodiscard]] QueryAnswer query(const Scene& scene, const Exact3& e, const AnalysisOptions& options = {});

/// Questions about one scene not analysed, asked one after another: each answer is
/// query_scene's, but what does not depend on the wrench is done once: the cone of motions A, its
/// faces and the contacts closed on each, the friction edges, and (built at the second answer) the
/// all-f mode's E. Each call still walks every cell, O(M + C + B k log k) in query_scene's terms
/// for one wrench (a batch of q wrenches walks once: the cells are made once and each wrench's
/// certificates are checked at each cell, still O(q (M + C + B k log k)) but with less per
/// wrench), so for many questions about a scene small enough to analyse, analyze and QueryIndex
/// answer faster (QueryIndex made from a scene chooses between them). Keeps nothing of the scene.
/// Not for two threads at once.
class SceneQuestions {
public:
    /// Throws as analyze does.
    explicit SceneQuestions(const Scene& scene, const AnalysisOptions& options = {});
    ~SceneQuestions();
    SceneQuestions(SceneQuestions&&) noexcept;
    SceneQuestions& operator=(SceneQuestions&&) noexcept;

    /// query_scene(scene, e, options, diagnostics). Throws std::invalid_argument for a non-finite
    /// wrench.
    [[nodiscard]] SceneAnswer answer(const Vec3& e, QueryDiagnostics* diagnostics = nullptr);
    /// The same for an exact wrench (a decimal one, with its denominators cleared, need not be
    /// doubles).
    [[nodiscard]] SceneAnswer answer(const Exact3& e, QueryDiagnostics* diagnostics = nullptr);
    /// The answers to several wrenches, in their order, from one walk of the cells: each is what
    /// answer(e) gives, and the walk itself (the cells and their letter changes) is paid once for
    /// the batch; every wrench still has its own certificates and E's tested. Each answer's work
    /// goes to `diagnostics` (one per wrench) when given. Throws std::invalid_argument, answering
    /// none, if any wrench is not finite.
    [[nodiscard]] std::vector<SceneAnswer> answer(std::span<const Vec3> wrenches,
                                                  std::vector<QueryDiagnostics>* diagnostics = nullptr);
    /// The same answers handed to `take` one by one, in order, as they are made: the batch's
    /// answers need not all be held at once (a mode's cone of twists can be big). `diagnostics`,
    /// when given, is filled before the first answer is handed over.
    void answer(std::span<const Vec3> wrenches, const std::function<void(SceneAnswer&&)>& take,
                std::vector<QueryDiagnostics>* diagnostics = nullptr);
    /// A lower bound on the scene's number of modes (SceneAnswer::mode_count), known before any
    /// answer: 1 plus the 2-D faces of A, each of which holds a mode where a contact slides.
    [[nodiscard]] std::size_t modes_at_least() const;

    struct State;  ///< the walk's set-up and the all-f mode's E (internal)

private:
    void answer_exact(std::span<const ExactVector> wrenches, const std::function<void(SceneAnswer&&)>& take,
                      std::vector<QueryDiagnostics>* diagnostics);
    std::unique_ptr<State> state_;
};

}  // namespace momentlab
