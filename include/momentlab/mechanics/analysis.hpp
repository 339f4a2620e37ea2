#pragma once

/// \file
/// Per-mode force sets of a body at rest (analyze: F, T and E of every mode) and the inverse
/// question "which mode follows from this applied wrench?" (query) (Mason 1991, section 2.1;
/// docs/design.md, "Per-mode force sets"). For many questions about one analysis, QueryIndex
/// (mechanics/query_index.hpp).

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

/// One question about a scene not analysed: which of its modes e produces.
struct SceneAnswer {
    std::vector<Mode> modes;     ///< the modes e produces (letters and twists), in the order of result.modes
    QueryResult result;          ///< their indices in enumerate_modes' order (analyze's), increasing
    std::size_t mode_count = 0;  ///< how many modes the scene has
    std::size_t built = 0;       ///< how many modes' E e was tested against (the rest were decided by certificates)
    /// The generators of those E: with mode_count and scanned_generators, the work of this answer.
    std::size_t tested_generators = 0;
    /// How many modes were decided by a certificate mended from the cell before (a few scans of
    /// the cell's generators with exact predicates, where testing e against E sorts them).
    std::size_t mended = 0;
    /// The generators of the cells whose certificate a mend tried (each scanned a few times).
    std::size_t scanned_generators = 0;
    /// Of the built E, how many were of cells on a face whose closed contacts' edges have few
    /// distinct forces (a floor of one mu): each such group of edges given by its two of least
    /// and greatest torque, updated from the cell before in O(log n) a contact that changed.
    std::size_t grouped = 0;
    /// The closed contacts summed over the modes (the letters that are not 's'): about the
    /// generators an analysis of the scene builds.
    std::size_t closed_letters = 0;
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
/// Throws as analyze does, and std::invalid_argument for a non-finite wrench.
[[nodiscard]] SceneAnswer query_scene(const Scene& scene, const Vec3& e, const AnalysisOptions& options = {});

/// Questions about one scene not analysed, asked one after another: each answer is
/// query_scene's, but what does not depend on the wrench is done once: the cone of motions A, its
/// faces and the contacts closed on each, the friction edges, and (built at the second answer) the
/// all-f mode's E. Each call still walks every cell, O(M + C + B k log k) in query_scene's terms
/// for one wrench (a batch of q wrenches walks once: the cells are made once and each wrench's
/// certificates are checked at each cell, still O(q (M + C + B k log k)) but with less per
/// wrench), so for many questions about a scene small enough to analyse, analyze and QueryIndex answer
/// faster; this is for scenes whose analysis would be too big (every mode's letters). Keeps
/// nothing of the scene. Not for two threads at once.
class SceneQuestions {
public:
    /// Throws as analyze does.
    explicit SceneQuestions(const Scene& scene, const AnalysisOptions& options = {});
    ~SceneQuestions();
    SceneQuestions(SceneQuestions&&) noexcept;
    SceneQuestions& operator=(SceneQuestions&&) noexcept;

    /// query_scene(scene, e, options). Throws std::invalid_argument for a non-finite wrench.
    [[nodiscard]] SceneAnswer answer(const Vec3& e);
    /// The answers to several wrenches, in their order, from one walk of the cells: each is what
    /// answer(e) gives, and the walk itself (the cells and their letter changes) is paid once for
    /// the batch; every wrench still has its own certificates and E's tested. Throws
    /// std::invalid_argument, answering none, if any wrench is not finite.
    [[nodiscard]] std::vector<SceneAnswer> answer(std::span<const Vec3> wrenches);
    /// The same answers handed to `take` one by one, in order, as they are made: the batch's
    /// answers need not all be held at once (a mode's cone of twists can be big).
    void answer(std::span<const Vec3> wrenches, const std::function<void(SceneAnswer&&)>& take);
    /// A lower bound on the scene's number of modes (SceneAnswer::mode_count), known before any
    /// answer: 1 plus the 2-D faces of A, each of which holds a mode where a contact slides.
    [[nodiscard]] std::size_t modes_at_least() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

/// The answer to one question about a new scene: the letters of the modes e produces.
struct OneShotAnswer {
    std::vector<std::string> letters;  ///< sorted; the same modes as query_scene's
    Verdict verdict = Verdict::Inconsistent;
    /// True when double arithmetic with certified error bounds decided every sign; false when
    /// the scene took the exact path (query_scene).
    bool filtered = false;
};

/// The modes query_scene(scene, e, options) gives, by their letters, for a scene asked once. For
/// 2 to 12 contacts the modes and their sets E are found in double arithmetic that carries a
/// forward error bound with every number, as long as every sign it meets is certified by its bound
/// (the scene is generic: no three contact wrenches N_j dependent, no sliding direction
/// exactly zero on a ray of A, e on no boundary); otherwise, and for other sizes, the exact path
/// query_scene answers. Either way the answer is exact (docs/robustness.md, "One question about a
/// new scene"). O(n^3 + M k^3) for n contacts, M modes and at most k generators per E.
/// Throws as query_scene does (naming query_once).
[[nodiscard]] OneShotAnswer query_once(const Scene& scene, const Vec3& e, const AnalysisOptions& options = {});

}  // namespace momentlab
