// The state of a QueryIndex made from a scene (mechanics/query_index.hpp): the walk that answers
// batches of questions, its running price, and the analysis once bought. Internal to the
// mechanics layer.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/mechanics/query_index.hpp"

namespace momentlab {

struct QueryIndex::Walk {
    Walk(const Scene& scene, const AnalysisOptions& options, std::optional<std::size_t> questions);

    /// The modes (indices) of one wrench: walked, or from the analysis once bought.
    Verdict query(const Vec3& e, std::vector<std::size_t>& modes);
    /// A batch's answers: walked, or from the analysis once bought.
    void answer(std::span<const Vec3> wrenches, const std::function<void(QueryAnswer&&)>& take);
    /// Analyses the scene (once).
    void buy();

    Scene scene;
    AnalysisOptions options;
    std::optional<std::size_t> questions;
    std::optional<SceneQuestions> walk;
    std::optional<std::vector<ModeForces>> analysis;
    std::unique_ptr<QueryIndex> index;  // of the analysis
    QueryDiagnostics work;              // of the walks so far
    double walked = 0.0;                // cells walked and generators tested (or scanned) so far
    std::size_t walks = 0;              // answers walked
    std::size_t batch = 1;
    bool analyse_next = false;

private:
    // A batch walked, each answer handed to `take` with its work counted into the price.
    void walk_batch(std::span<const Vec3> wrenches, const std::function<void(SceneAnswer&&)>& take);
};

}  // namespace momentlab
