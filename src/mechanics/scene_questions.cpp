// SceneQuestions and query_scene (mechanics/advanced.hpp): questions about a scene not analysed,
// answered by one walk of the cells per batch (mode_walk.hpp) with a decider per wrench
// (decider.hpp). A batch is a Batch: the all-f mode's task, the walk's parts, then the answers
// and their diagnostics; SceneQuestions::answer only shares the tasks out to the threads.
#include <algorithm>
#include <atomic>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "momentlab/core/parallel.hpp"
#include "momentlab/mechanics/advanced.hpp"
#include "checks.hpp"
#include "decider.hpp"
#include "friction_edges.hpp"
#include "mode_walk.hpp"

namespace momentlab {
namespace {

using detail::Decider;
using detail::FrictionEdges;
using detail::GroupedEdges;
using detail::TwistFilters;

// A batch's walk of a large scene goes in up to this many parts of consecutive faces, handed to
// the two threads one at a time (the work is far from even over the faces).
constexpr std::size_t kWalkParts = 32;

// The all-f mode's E once its closure (the twists of the cells merged into it) is known: the
// images M g of those twists and -T of every contact fixed; kept for membership tests only
// (its extreme rays, not its 2n facets, when it is pointed and full-dimensional).
HeldCone fixed_applied(const std::optional<ExactMatrix>& m, const FrictionEdges& edges, const std::vector<Exact3>& closure) {
    std::vector<ExactVector> generators;
    generators.reserve((m ? closure.size() : 0) + 2 * edges.statics.size());
    if (m) {
        for (const Exact3& g : closure) generators.push_back(ExactVector::from_exact(g).transformed(*m));
    }
    for (std::size_t j = 0; j < edges.statics.size(); ++j) {
        edges.for_contact(j, letter(ContactMode::Fixed), [&](const ExactVector& edge, int) {
            generators.push_back(edge.negated());
            return true;
        });
    }
    return HeldCone(std::move(generators));
}

}  // namespace

struct SceneQuestions::State {
    State(const Scene& scene, const AnalysisOptions& options)
        : m(detail::inertia_of(scene, options, "query_scene")),
          n((detail::check_contacts(scene.contacts), scene.contacts.size())),
          progress(options.progress) {
        // The walk's set-up (A, its faces and their closed contacts) and the friction edges
        // need nothing of each other: on two threads for large scenes.
        const bool large = n >= detail::kTwoThreadContacts;
        std::optional<detail::ModeWalk> w;
        std::optional<FrictionEdges> e;
        detail::for_each_index(2, large, [&](std::size_t task) {
            if (task == 0) {
                w.emplace(scene.contacts);
            } else {
                e.emplace(scene.contacts, !large);
            }
        });
        walk = std::move(*w);
        edges = std::move(*e);
    }

    std::optional<ExactMatrix> m;
    std::size_t n;
    detail::ModeWalk walk{{}};
    FrictionEdges edges{{}};
    Progress progress;
    // After the first answer: the twists of the cells that join the all-f mode; from the second,
    // that mode's E (built once; every answer then tests e against it).
    std::shared_ptr<const std::vector<Exact3>> fixed_closure;
    std::optional<HeldCone> fixed_cone;
};

namespace {

// One batch of wrenches asked of a SceneQuestions' state. The all-f mode (xi = 0 and the cells
// whose letters are all 'f') is decided apart, when its closure is complete; the others as the
// walk meets them. Its E holds -T for every contact fixed (2n generators): decided as one task,
// at the first answer first without the twists of merged cells (a wrench in that smaller cone is
// in E whatever they are). The faces are walked in parts of consecutive faces, each part a task
// with certificates of its own (so that what a part finds does not depend on which thread took
// the parts before it); the tasks share two threads, handed out one at a time: on the cradle of
// 10^5 contacts the first half of the faces took 1.04 s and the second 0.15 s. Every wrench of
// the batch has its own deciders (their certificates are the wrench's) and sees every cell of
// the one walk. A mode that a wrench produces is kept as the walk gives it (its closed contacts
// and their letters, not n letters), once for all the wrenches that produce it: a batch holds
// its answers' letters only one answer at a time.
class Batch {
public:
    Batch(SceneQuestions::State& s, std::span<const ExactVector> wrenches)
        : s_(s), wrenches_(wrenches), n_(s.n), q_(wrenches.size()),
          parts_(s.n >= detail::kTwoThreadContacts ? std::clamp<std::size_t>(s.walk.faces(), 1, kWalkParts) : 1),
          counts_(s.walk.faces()), everyone_(s.n), fixed_letters_(s.n, letter(ContactMode::Fixed)), fixed_holds_(q_, 0),
          closure_known_(s.fixed_closure != nullptr), caller_(std::this_thread::get_id()) {
        std::iota(everyone_.begin(), everyone_.end(), 0);
        fixed_deciders_.reserve(q_);
        for (const ExactVector& e : wrenches) fixed_deciders_.emplace_back(s.walk.feasible_twists(), s.m, s.edges, e);
    }

    // Tasks: 0 the all-f mode, 1 .. parts() the walk's parts.
    [[nodiscard]] std::size_t tasks() const { return 1 + parts_.size(); }
    void run(std::size_t task) {
        if (task == 0) {
            fixed_task();
        } else {
            part_task(task - 1);
        }
    }

    // After every task: the all-f mode's closure completed (at a first batch), then each answer
    // handed to `take` and its diagnostics written.
    void finish(const std::function<void(SceneAnswer&&)>& take, std::vector<QueryDiagnostics>* diagnostics) {
        close_fixed();
        deliver(take, diagnostics);
    }

private:
    struct Kept {
        bool whole;                   // letters holds all n letters (no bigger than the closed ones)
        std::vector<int> closed;      // else the closed contacts
        std::string letters;          // and their letters
        std::vector<Exact3> closure;  // empty for the interior of A (no contact closed): A itself
    };
    struct Member {
        std::size_t face, index;     // index within the face (0: the all-f mode)
        std::shared_ptr<Kept> mode;  // null for the all-f mode
    };
    struct Part {
        std::vector<std::vector<Member>> members;                          // per wrench
        std::vector<std::size_t> built, tested, mended, scanned, grouped;  // per wrench
        std::vector<Exact3> fixed_closure;
        std::size_t closed_letters = 0;
    };

    bool fixed_member(std::size_t k, const std::vector<Exact3>& closure) {
        detail::WalkCell cell;
        cell.closure = &closure;
        cell.closed = everyone_;
        cell.letters = fixed_letters_;
        TwistFilters filters;
        return fixed_deciders_[k].member(cell, filters);
    }

    // The all-f mode, beside the walk.
    void fixed_task() {
        if (closure_known_ && n_ > 0) {  // a later answer: the mode's E, built once
            if (!s_.fixed_cone) {
                s_.fixed_cone = fixed_applied(s_.m, s_.edges, *s_.fixed_closure);
                fixed_built_ = true;
                fixed_tested_ = (s_.m ? s_.fixed_closure->size() : 0) + 2 * n_;
            }
            for (std::size_t k = 0; k < q_; ++k) fixed_holds_[k] = s_.fixed_cone->holds(wrenches_[k]).member;
        } else if (q_ == 1 || n_ == 0) {
            for (std::size_t k = 0; k < q_; ++k) fixed_holds_[k] = fixed_member(k, {});
        } else {  // a first batch: the cone of the fixed edges alone, built once for all
            fixed_edges_.emplace(fixed_applied(s_.m, s_.edges, {}));
            fixed_built_ = true;
            fixed_tested_ = 2 * n_;
            for (std::size_t k = 0; k < q_; ++k) fixed_holds_[k] = fixed_edges_->holds(wrenches_[k]).member;
        }
    }

    // Part p of the walk's faces: each wrench's decider at each of their cells.
    void part_task(std::size_t p) {
        const detail::ModeWalk& walk = s_.walk;
        Part& part = parts_[p];
        std::vector<Decider> deciders;
        deciders.reserve(q_);
        for (const ExactVector& e : wrenches_) deciders.emplace_back(walk.feasible_twists(), s_.m, s_.edges, e);
        part.members.resize(q_);
        TwistFilters filters;
        GroupedEdges groups(s_.edges);
        const std::size_t begin = walk.faces() * p / parts_.size(), end = walk.faces() * (p + 1) / parts_.size();
        // Progress from the calling thread only (the callback need not be thread-safe), by parts
        // when there are several, else face by face.
        const bool reports = s_.progress && std::this_thread::get_id() == caller_;
        walk.run_faces(begin, end, reports && parts_.size() == 1 ? s_.progress : Progress(), counts_, [&](const detail::WalkCell& cell) {
            groups.next_cell(cell);
            if (cell.index == 0) {  // (its letters are counted once, as the all-f mode's)
                if (!closure_known_) part.fixed_closure.insert(part.fixed_closure.end(), cell.closure->begin(), cell.closure->end());
                return;
            }
            part.closed_letters += cell.closed.size();
            filters.next_cell();
            std::shared_ptr<Kept> kept;  // made for the first wrench the mode holds
            for (std::size_t k = 0; k < q_; ++k) {
                if (!deciders[k].member(cell, filters, &groups)) continue;
                if (!kept && cell.closed.size() * (sizeof(int) + 1) >= n_) {  // (a face that closes most contacts)
                    kept = std::make_shared<Kept>(Kept{true, {}, cell.all_letters(n_), *cell.closure});
                } else if (!kept) {
                    kept = std::make_shared<Kept>(Kept{false,
                                                       {cell.closed.begin(), cell.closed.end()},
                                                       {cell.letters.begin(), cell.letters.end()},
                                                       cell.closed.empty() ? std::vector<Exact3>() : *cell.closure});
                }
                part.members[k].push_back({cell.face, cell.index, kept});
            }
        });
        for (const Decider& decider : deciders) {
            part.built.push_back(decider.built());
            part.tested.push_back(decider.tested());
            part.mended.push_back(decider.mended());
            part.scanned.push_back(decider.scanned());
            part.grouped.push_back(decider.grouped());
        }
        faces_done_ += end - begin;
        if (reports && parts_.size() > 1) s_.progress("faces of the cone of motions", faces_done_, walk.faces());
    }

    // At a first batch, the all-f mode's closure from the parts, and its E where the cone of the
    // fixed edges alone left a wrench undecided.
    void close_fixed() {
        if (closure_known_) return;
        const std::optional<ExactMatrix>& m = s_.m;
        std::vector<Exact3> fixed_closure;
        for (const Part& part : parts_) fixed_closure.insert(fixed_closure.end(), part.fixed_closure.begin(), part.fixed_closure.end());
        if (fixed_edges_ && (!m || fixed_closure.empty())) {
            s_.fixed_cone = std::move(fixed_edges_);  // the whole E: no twist joins it
        } else if (fixed_edges_) {
            const bool undecided = std::find(fixed_holds_.begin(), fixed_holds_.end(), 0) != fixed_holds_.end();
            if (undecided) {
                s_.fixed_cone = fixed_applied(m, s_.edges, fixed_closure);
                fixed_tested_ += fixed_closure.size() + 2 * n_;
                for (std::size_t k = 0; k < q_; ++k) fixed_holds_[k] = fixed_holds_[k] || s_.fixed_cone->holds(wrenches_[k]).member;
            }
        } else {
            for (std::size_t k = 0; k < q_; ++k) {
                if (!fixed_holds_[k] && m && !fixed_closure.empty()) fixed_holds_[k] = fixed_member(k, fixed_closure);
            }
        }
        s_.fixed_closure = std::make_shared<const std::vector<Exact3>>(std::move(fixed_closure));
    }

    // Answer k's work, summed over the all-f mode's decider and the parts.
    [[nodiscard]] QueryDiagnostics diagnostics_of(std::size_t k) const {
        QueryDiagnostics d;
        // The all-f mode's E counts once however many times its decider built it (and, built for
        // the batch, with the batch's first answer).
        const bool built_here = fixed_deciders_[k].built() > 0 || (fixed_built_ && k == 0);
        d.built = (built_here ? 1 : 0);
        d.tested_generators = fixed_deciders_[k].tested() + (k == 0 ? fixed_tested_ : 0);
        d.mended = fixed_deciders_[k].mended();
        d.scanned_generators = fixed_deciders_[k].scanned();
        d.closed_letters = n_;
        for (const Part& part : parts_) {
            d.built += part.built[k];
            d.tested_generators += part.tested[k];
            d.mended += part.mended[k];
            d.scanned_generators += part.scanned[k];
            d.grouped += part.grouped[k];
            d.closed_letters += part.closed_letters;
        }
        return d;
    }

    // The modes' indices in enumerate_modes' order, and how many answers of the batch hold each:
    // a mode's cone of twists is built once and kept only while a later answer still needs it
    // (the copies share its exact coordinates).
    void deliver(const std::function<void(SceneAnswer&&)>& take, std::vector<QueryDiagnostics>* diagnostics) {
        const detail::ModeWalk& walk = s_.walk;
        // Face i's modes come after those of the faces before it.
        std::vector<std::size_t> first_index(counts_.size());
        std::size_t total = 1;
        for (std::size_t i = 0; i < counts_.size(); ++i) {
            first_index[i] = total;
            total += counts_[i];
        }
        std::map<std::size_t, std::size_t> uses;
        for (std::size_t k = 0; k < q_; ++k) {
            if (fixed_holds_[k]) ++uses[0];
        }
        for (Part& part : parts_) {
            for (std::vector<Member>& list : part.members) {
                for (Member& member : list) {
                    member.index = first_index[member.face] + member.index - 1;
                    ++uses[member.index];
                }
            }
        }
        std::map<std::size_t, Cone> twist_cones;
        const auto twists_of = [&](std::size_t index, const std::vector<Exact3>& closure) {
            const std::size_t left = --uses[index];
            if (closure.empty() && index != 0) return walk.feasible_twists();  // the interior of A
            const auto kept = twist_cones.find(index);
            if (kept != twist_cones.end()) {
                if (left > 0) return kept->second;
                Cone cone = std::move(kept->second);
                twist_cones.erase(kept);
                return cone;
            }
            std::vector<ExactVector> gens;
            gens.reserve(closure.size());
            for (const Exact3& g : closure) gens.push_back(ExactVector::from_exact(g));
            Cone cone = Cone::from_generators(gens);
            if (left > 0) twist_cones.emplace(index, cone);
            return cone;
        };
        if (diagnostics) {
            diagnostics->clear();
            for (std::size_t k = 0; k < q_; ++k) diagnostics->push_back(diagnostics_of(k));
        }
        for (std::size_t k = 0; k < q_; ++k) {
            SceneAnswer out;
            out.mode_count = total;
            std::vector<Member> members;
            if (fixed_holds_[k]) members.push_back({0, 0, nullptr});
            for (Part& part : parts_) {
                members.insert(members.end(), part.members[k].begin(), part.members[k].end());
                part.members[k] = {};
            }
            std::sort(members.begin(), members.end(), [](const Member& a, const Member& b) { return a.index < b.index; });
            for (Member& member : members) {
                // (a mode's letters moved out of it by the last answer that holds it: this one when no
                // other answer's list still shares it)
                const bool last = member.mode && member.mode.use_count() == 1;
                std::string letters = !member.mode        ? std::string(n_, letter(ContactMode::Fixed))
                                      : member.mode->whole ? (last ? std::move(member.mode->letters) : member.mode->letters)
                                                           : detail::all_letters(member.mode->closed, member.mode->letters, n_);
                out.result.modes.push_back(member.index);
                out.modes.push_back(Mode{std::move(letters), twists_of(member.index, member.mode ? member.mode->closure : *s_.fixed_closure)});
            }
            out.result.verdict = verdict_of(out.result.modes.size());
            take(std::move(out));
        }
    }

    SceneQuestions::State& s_;
    std::span<const ExactVector> wrenches_;
    std::size_t n_, q_;
    std::vector<Part> parts_;
    std::atomic<std::size_t> faces_done_{0};
    std::vector<std::size_t> counts_;
    std::vector<int> everyone_;
    const std::vector<char> fixed_letters_;
    std::vector<Decider> fixed_deciders_;
    std::vector<char> fixed_holds_;
    std::optional<HeldCone> fixed_edges_;  // a first batch's E of the all-f mode without the twists
    bool fixed_built_ = false;
    std::size_t fixed_tested_ = 0;
    // The twists of the cells that join the all-f mode are the same at every answer: collected
    // at the first only.
    const bool closure_known_;
    const std::thread::id caller_;
};

}  // namespace

SceneQuestions::SceneQuestions(const Scene& scene, const AnalysisOptions& options)
    : state_(std::make_unique<State>(scene, options)) {}
SceneQuestions::~SceneQuestions() = default;
SceneQuestions::SceneQuestions(SceneQuestions&&) noexcept = default;
SceneQuestions& SceneQuestions::operator=(SceneQuestions&&) noexcept = default;

std::size_t SceneQuestions::modes_at_least() const { return state_->walk.modes_at_least(); }

SceneAnswer SceneQuestions::answer(const Vec3& e, QueryDiagnostics* diagnostics) {
    std::vector<QueryDiagnostics> d;
    SceneAnswer a = std::move(answer(std::span<const Vec3>(&e, 1), diagnostics ? &d : nullptr).front());
    if (diagnostics) *diagnostics = d.front();
    return a;
}

std::vector<SceneAnswer> SceneQuestions::answer(std::span<const Vec3> wrenches, std::vector<QueryDiagnostics>* diagnostics) {
    std::vector<SceneAnswer> answers;
    answers.reserve(wrenches.size());
    answer(wrenches, [&](SceneAnswer&& a) { answers.push_back(std::move(a)); }, diagnostics);
    return answers;
}

SceneAnswer SceneQuestions::answer(const Exact3& e, QueryDiagnostics* diagnostics) {
    std::vector<QueryDiagnostics> d;
    const ExactVector w = ExactVector::from_exact(e);
    std::optional<SceneAnswer> a;
    answer_exact(std::span<const ExactVector>(&w, 1), [&](SceneAnswer&& x) { a = std::move(x); }, diagnostics ? &d : nullptr);
    if (diagnostics) *diagnostics = d.front();
    return std::move(*a);
}

void SceneQuestions::answer(std::span<const Vec3> wrenches, const std::function<void(SceneAnswer&&)>& take,
                            std::vector<QueryDiagnostics>* diagnostics) {
    for (const Vec3& e : wrenches) {
        if (!e.allFinite()) throw std::invalid_argument("query_scene: the wrench must be finite");
    }
    std::vector<ExactVector> exact;
    exact.reserve(wrenches.size());
    for (const Vec3& e : wrenches) exact.push_back(ExactVector::input(e));
    answer_exact(exact, take, diagnostics);
}

void SceneQuestions::answer_exact(std::span<const ExactVector> wrenches, const std::function<void(SceneAnswer&&)>& take,
                                  std::vector<QueryDiagnostics>* diagnostics) {
    Batch batch(*state_, wrenches);
    detail::for_each_index(batch.tasks(), state_->n >= detail::kTwoThreadContacts, [&](std::size_t task) { batch.run(task); });
    batch.finish(take, diagnostics);
}

SceneAnswer query_scene(const Scene& scene, const Vec3& e, const AnalysisOptions& options, QueryDiagnostics* diagnostics) {
    if (!e.allFinite()) throw std::invalid_argument("query_scene: the wrench must be finite");
    return SceneQuestions(scene, options).answer(e, diagnostics);
}

SceneAnswer query_scene(const Scene& scene, const Exact3& e, const AnalysisOptions& options, QueryDiagnostics* diagnostics) {
    return SceneQuestions(scene, options).answer(e, diagnostics);
}

}  // namespace momentlab
