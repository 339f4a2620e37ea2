// QueryIndex made from a scene (mechanics/query_index.hpp): walk or analyse, rent or buy.
#include "scene_index.hpp"

#include <stdexcept>

#include "query.hpp"

namespace momentlab {
namespace {

// Up to this many letters (modes x contacts) the scene may be analysed; beyond, every wrench
// takes the walk (an analysis would hold every mode's letters and sets).
constexpr double kAnalysedLetters = 1e8;

// The batch of wrenches walked at once when the number of questions is known (the first is
// answered alone: it prices a walk, which a batch's answers cost less than).
constexpr std::size_t kBatch = 256;

// A generator that a mended certificate scans (a few filtered determinants) costs about 1/14 of
// one that testing e against E sorts (one query on the collinear family of 1,000 contacts took
// 1.9 s for 1.73 million generators tested before certificates were mended, 1.1 us each, and
// 0.115 s with 1.44 million generators scanned in the cells that mends tried, 0.08 us each with
// the rest of the walk included); counted at 1/16.
constexpr double kScannedPerTested = 16.0;

}  // namespace

QueryIndex::Walk::Walk(const Scene& s, const AnalysisOptions& o, std::optional<std::size_t> q)
    : scene(s), options(o), questions(q) {
    walk.emplace(scene, options);
    // A scene whose modes' letters surely pass kAnalysedLetters is never analysed: no price is
    // needed, and known questions go in batches from the first.
    const bool never_analysed = static_cast<double>(walk->modes_at_least()) * static_cast<double>(scene.contacts.size()) >
                                kAnalysedLetters;
    batch = questions && never_analysed ? kBatch : 1;
}

void QueryIndex::Walk::buy() {
    if (analysis) return;
    analysis = analyze(scene, options);
    index = std::make_unique<QueryIndex>(*analysis);  // compiled once for all the questions
    walk.reset();
    batch = 1;
}

void QueryIndex::Walk::walk_batch(std::span<const Vec3> wrenches, const std::function<void(SceneAnswer&&)>& take) {
    std::vector<QueryDiagnostics> diagnostics;
    std::size_t modes = 0;
    walk->answer(wrenches, [&](SceneAnswer&& a) {
        modes = a.mode_count;
        take(std::move(a));
    }, &diagnostics);
    std::size_t closed_letters = 0;  // the scene's count, the same in every answer
    for (const QueryDiagnostics& d : diagnostics) {
        walked += static_cast<double>(d.tested_generators) + static_cast<double>(d.scanned_generators) / kScannedPerTested;
        closed_letters = d.closed_letters;
        work.built += d.built;
        work.tested_generators += d.tested_generators;
        work.mended += d.mended;
        work.scanned_generators += d.scanned_generators;
        work.grouped += d.grouped;
        work.closed_letters = d.closed_letters;
    }
    walked += static_cast<double>(modes);
    walks += wrenches.size();
    if (questions) batch = kBatch;
    const double analysis_price = static_cast<double>(modes + closed_letters) / 2.0;  // on two threads
    const double to_walk = questions ? walked / static_cast<double>(walks) *
                                           static_cast<double>(*questions > walks ? *questions - walks : 0)
                                     : walked;
    const double letters = static_cast<double>(modes) * static_cast<double>(scene.contacts.size());
    analyse_next = to_walk >= analysis_price && letters <= kAnalysedLetters;
    if (analyse_next) batch = 1;  // the next wrench is answered from the analysis, made then
}

Verdict QueryIndex::Walk::query(const Vec3& e, std::vector<std::size_t>& modes) {
    if (analyse_next) buy();
    if (index) return index->query(e, modes);
    if (!e.allFinite()) throw std::invalid_argument("query: the wrench must be finite");
    Verdict verdict = Verdict::Inconsistent;
    walk_batch(std::span<const Vec3>(&e, 1), [&](SceneAnswer&& a) {
        modes = std::move(a.result.modes);
        verdict = a.result.verdict;
    });
    return verdict;
}

void QueryIndex::Walk::answer(std::span<const Vec3> wrenches, const std::function<void(QueryAnswer&&)>& take) {
    if (analyse_next) buy();
    if (index) {
        index->answer(wrenches, take);
        return;
    }
    walk_batch(wrenches, [&](SceneAnswer&& a) { take(detail::canonical(std::move(a))); });
}

QueryIndex::QueryIndex(const Scene& scene, const AnalysisOptions& options, std::optional<std::size_t> questions)
    : walk_(std::make_unique<Walk>(scene, options, questions)) {}

void QueryIndex::answer(std::span<const Vec3> wrenches, const std::function<void(QueryAnswer&&)>& take) {
    for (const Vec3& e : wrenches) {
        if (!e.allFinite()) throw std::invalid_argument("query: the wrench must be finite");
    }
    if (walk_) {
        walk_->answer(wrenches, take);
        return;
    }
    std::vector<std::size_t> found;
    for (const Vec3& e : wrenches) {
        QueryAnswer out;
        out.verdict = query(e, found);
        for (std::size_t k : found) out.letters.push_back(letters_[k]);
        std::sort(out.letters.begin(), out.letters.end());
        take(std::move(out));
    }
}

QueryAnswer QueryIndex::answer(const Vec3& e) {
    QueryAnswer out;
    answer(std::span<const Vec3>(&e, 1), [&](QueryAnswer&& a) { out = std::move(a); });
    return out;
}

std::size_t QueryIndex::batch() const { return walk_ ? walk_->batch : 1; }

const std::vector<ModeForces>& QueryIndex::analysis() {
    if (!walk_) throw std::logic_error("QueryIndex::analysis: an index made from an analysis keeps none");
    walk_->buy();
    return *walk_->analysis;
}

const QueryDiagnostics& QueryIndex::diagnostics() const {
    static const QueryDiagnostics none;
    return walk_ ? walk_->work : none;
}

std::size_t QueryIndex::planes() const { return walk_ ? (walk_->index ? walk_->index->planes() : 0) : exact_.size(); }

std::size_t QueryIndex::modes() const { return walk_ ? (walk_->index ? walk_->index->modes() : 0) : mode_count_; }

}  // namespace momentlab
