#pragma once

/// \file
/// Synthesis by pushing (Mason 1991, section 3, Example 2; docs/design.md, Synthesis): a finger touches
/// a feature of the body (an edge or a vertex) and slips along it (l, r) or sticks (f); its
/// force set on that feature is a cone W (or a union of cones), and the pushes that produce a
/// goal mode i are W ∩ E_i. Letters as for contacts, the finger being the fixed side: n points
/// into the body, t = (n.y, -n.x), r means the body slides along +t relative to the finger
/// (friction on the body along -t, force n - mu t), l along -t (force n + mu t). docs/planning.md
/// has the definitions and the block-along-the-wall table worked by hand.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "momentlab/core/rational.hpp"
#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/modes.hpp"
#include "momentlab/planning/directions.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// The finger's forces on the body anywhere along the segment a-b, with inward normal `normal`
/// and friction coefficient mu >= 0, for slip l, f or r: the positive combinations of the
/// slip's friction-cone edges at a and at b (a force at a point between them is such a
/// combination). Throws std::invalid_argument for a separating slip, a zero normal or mu < 0.
[[nodiscard]] Cone push_actions(const Vec2& a, const Vec2& b, const Vec2& normal, ContactMode slip, double mu);

/// A feature of the body polygon, numbered in the polygon's own order: edge i runs from vertex
/// i to vertex i + 1.
struct PushFeature {
    enum class Kind { Edge, Vertex };
    Kind kind = Kind::Edge;
    std::size_t index = 0;
    Vec2 from = Vec2::Zero();  ///< an edge's first vertex, or the vertex
    Vec2 to = Vec2::Zero();    ///< an edge's second vertex, or the vertex again
    /// An edge's unit inward normal; for a vertex the unit bisector of its two edges' normals.
    Vec2 normal = Vec2::Zero();
    /// A vertex where the polygon turns against its orientation (a notch).
    bool reflex = false;
    /// "edge 3" or "vertex 3".
    [[nodiscard]] std::string name() const;
};

/// How a pushing case turned out.
enum class PushVerdict {
    Feasible,    ///< a push of W lies in the interior of E_goal, where the finger can reach
    Boundary,    ///< W ∩ E_goal is not {0} but lies on the boundary of E_goal: a knife edge
    Blocked,     ///< feasible, but only where obstacles leave the finger no room
    Infeasible,  ///< W ∩ E_goal = {0}
    Reflex,      ///< slipping at a notch: the finger leaves one of its edges (see the edge cases)
};

/// "feasible", "boundary", "blocked", "no" or "reflex".
[[nodiscard]] const char* to_string(PushVerdict v);

/// A single push: a unit force and the point of the feature where the finger applies it.
struct Push {
    Vec2 point = Vec2::Zero();
    Vec2 direction = Vec2::Zero();
    [[nodiscard]] Vec3 wrench() const;
};

/// A part of a case: the finger on a stretch from-to of the feature (a vertex: one point) with
/// a cone of forces; W is the union of the parts' `actions`.
struct PushPiece {
    Vec2 from = Vec2::Zero();
    Vec2 to = Vec2::Zero();
    Cone actions;    ///< W on this part
    Cone solutions;  ///< W ∩ E_goal on this part
    /// The solutions meet the interior of E_goal, and the representative push lies in it
    /// exactly (as doubles), at a point where the finger is free.
    bool robust = false;
    /// When the solutions meet the interior of E_goal: the mean of their extreme unit forces.
    std::optional<Push> representative;
};

/// One pushing case: a feature and a slip.
struct PushCase {
    PushFeature feature;
    ContactMode slip = ContactMode::Fixed;
    /// The parts of the feature the case was solved on: the whole feature, or its parts free of
    /// obstacles; a vertex whose arc of forces is pi or more wide has two parts.
    std::vector<PushPiece> pieces;
    PushVerdict verdict = PushVerdict::Infeasible;
    /// "none", "part" or "all": how much of the feature lies in obstacles (interference not
    /// ignored), or "ignored".
    std::string blocked = "ignored";
    /// Where the finger may touch, as segments of the feature (a vertex: from == to), and the
    /// range of push directions. For a feasible case they describe the reachable robust parts;
    /// for a boundary or blocked case the solutions there are, reachable or not. Each segment
    /// and the range are the extents of the solution set (a touch point and a direction are
    /// not independent: docs/planning.md).
    std::vector<std::pair<Vec2, Vec2>> touch;
    std::optional<DirectionRange> directions;
    /// A representative solution, exactly in the interior of E_goal for feasible cases: the
    /// mean of the solution cone's extreme unit forces.
    std::optional<Push> best;
    /// Told the modes (and no fixed wrench): whether some pushes of the case's solutions, a part
    /// of their own dimension, give the goal alone, and whether some give another mode too; `best`
    /// is then a unique push when there is one that lies, as rounded, in E_goal's interior and in
    /// no other mode's set (best_unique).
    bool uniqueness_known = false;
    bool unique = false;
    bool shared = false;
    bool best_unique = false;
    /// The extents of the unique part, as `touch` and `directions` are of all the solutions.
    std::vector<std::pair<Vec2, Vec2>> unique_touch;
    std::optional<DirectionRange> unique_directions;
    /// With a fixed wrench: the magnitudes of `best` (a unit force times lambda) that give the goal.
    std::optional<MagnitudeRange> best_magnitudes;
    bool magnitudes_known = false;  ///< planned with a fixed wrench
    /// With the modes and a metric: the margins of `best` as a unit force (query_margins).
    std::optional<QueryMargins> best_margins;
    [[nodiscard]] bool feasible() const { return verdict == PushVerdict::Feasible; }
};

/// One feature of the body polygon: edge `index` (from vertex index to the next) or vertex `index`.
struct PushFeatureId {
    PushFeature::Kind kind = PushFeature::Kind::Edge;
    std::size_t index = 0;
};

/// Options of plan_push.
struct PushOptions {
    /// The finger's friction coefficient (>= 0), exact: a decimal as typed keeps its meaning
    /// (0.1 is 1/10); Rational(x) for a double x.
    Rational mu = Rational(0.5);
    /// Ignore obstacles (as the paper does for Figure 6); otherwise a point of a feature lying
    /// in a closed obstacle polygon cannot be touched by the (point) finger.
    bool ignore_interference = false;
    /// Only the cases of this feature (none: every feature).
    std::optional<PushFeatureId> feature = std::nullopt;
    /// Only the cases of this slip, l, f or r (none: all three).
    std::optional<ContactMode> slip = std::nullopt;
};

/// Every feature of the body polygon (its edges, then its vertices) with each slip l, f, r, in
/// that order: 6 n cases for n vertices, or those of `options.feature` and `options.slip`. The
/// cases chosen cost O(n) together (the polygon's orientation) plus each its own solution
/// (docs/reliability.md, "Large inputs": one case of a 10^5-gon in the time of its analysis).
/// Throws std::invalid_argument if the scene has no body polygon, mu is negative,
/// the feature's index is not one of the polygon's, or the slip is s.
[[nodiscard]] std::vector<PushCase> plan_push(const Scene& scene, const ModeForces& goal, const PushOptions& options = {});

/// The same told the context (directions.hpp): with the modes, which cases push into the goal
/// alone; with a fixed wrench g (gravity), the pushes u for which g + lambda u gives the goal at
/// some magnitude lambda (the cases are solved on E_goal + cone(-g)), and the magnitudes of each
/// case's best push.
[[nodiscard]] std::vector<PushCase> plan_push(const Scene& scene, const ModeForces& goal, const PushOptions& options,
                                              const PlanContext& context);

/// The same, case by case: `each` is given every case as it is solved, in the same order, so that
/// a table of 6 n cases needs the memory of one case at a time (a caller keeps what it prints).
void plan_push(const Scene& scene, const ModeForces& goal, const PushOptions& options, const PlanContext& context,
               const std::function<void(PushCase&&)>& each);

/// How many pushing cases plan_push has solved in the calling thread since it started: the
/// tests' check that a case asked for alone costs one case, not the table's 6 n.
[[nodiscard]] std::size_t push_cases_solved();

}  // namespace momentlab
