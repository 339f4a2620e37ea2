#pragma once

/// \file
/// The application layer: one contact problem as the command line, the Python module and the
/// web module pose it. A Problem holds a scene and, made on first need, its analysis and query
/// index; it checks what a user gives besides the scene (app/checks.hpp), builds the wrench that
/// acts besides the controlled one (gravity through the centre of mass, a wrench, forces at
/// points: summed exactly), and asks the library's questions and plans with the same checks
/// and messages for every front end. The front ends only convert values and print.

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "momentlab/app/checks.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/closure.hpp"
#include "momentlab/mechanics/margin.hpp"
#include "momentlab/mechanics/query_index.hpp"
#include "momentlab/planning/comply.hpp"
#include "momentlab/planning/fixed_wrench.hpp"
#include "momentlab/planning/push.hpp"
#include "momentlab/planning/tilt.hpp"

namespace momentlab {

/// How a front end names its inputs in messages: keywords by default ("goal", "wrench", as
/// Python and JavaScript take them), options on the command line ("--goal", "--wrench").
struct InputNames {
    std::string goal = "goal", mu = "mu", gravity = "gravity", wrench = "wrench", force = "force", centre = "centre",
                point = "point", direction = "direction", reference = "reference", length = "length", edge = "edge",
                vertex = "vertex";
    /// The command line's names: "--goal", "--mu", ...; a push line's point and direction are "--push".
    [[nodiscard]] static InputNames command_line();
};

/// What acts on the body besides a controlled action (a tilt, a push, a spring), or the applied
/// wrench of a question: gravity (an acceleration, through the centre of mass), a wrench
/// (fx, fy, tau about the origin) and forces (a point and a force each). Any may be absent.
/// The numbers are exact: decimals as typed on the command line, doubles as given by the C++,
/// Python and JavaScript APIs (rational() of a Vec2 or Vec3), Python's Fractions.
struct Load {
    std::optional<Rational2> gravity;
    std::optional<Rational3> wrench;
    std::vector<std::pair<Rational2, Rational2>> forces;  ///< (point, force)
    [[nodiscard]] bool empty() const { return !gravity && !wrench && forces.empty(); }
};

/// A push plan's request: the finger's mu, obstacles ignored or not, and, when given, one feature
/// (an edge or a vertex of the body's outline) and one finger slip.
struct PushRequest {
    Rational mu = Rational(0.5);  ///< exact, as typed
    bool ignore_interference = false;
    std::optional<std::size_t> edge, vertex;
    std::optional<ContactMode> slip;
};

/// The answer of a compliance question: the labelled regions of E_goal (+ cone(-g) with a fixed
/// wrench), and the plan of one centre when given.
struct ComplyAnswer {
    Labels labels;
    std::optional<ComplyPlan> centre;
};

/// A question's answer with its margins (docs/design.md, Margins): the distance of each mode's
/// set boundary, in the order of answer.letters, and to the nearest set of another mode.
struct MarginAnswer {
    QueryAnswer answer;
    std::vector<double> inside;       ///< infinite for a set that is R^3
    std::optional<double> to_other;   ///< none when every mode holds the wrench
    WrenchMetric metric;
};

/// One contact problem: a scene and the questions asked of it.
class Problem {
public:
    /// The scene; quasi_static neglects inertia (no body needed); `names` for messages;
    /// `progress` told of long work (may be empty).
    explicit Problem(Scene scene, bool quasi_static = false, InputNames names = {}, Progress progress = nullptr);

    [[nodiscard]] const Scene& scene() const { return scene_; }
    [[nodiscard]] bool quasi_static() const { return quasi_static_; }
    [[nodiscard]] const InputNames& names() const { return names_; }

    /// Every mode with its sets, made once. The dynamic model needs the body: an InputError at "$"
    /// naming `command` (what needs its mass, com and inertia) otherwise.
    const std::vector<ModeForces>& analysis(const std::string& command = "analyze");
    /// The analysis compiled for many questions (QueryIndex).
    const QueryIndex& index();
    /// A mode of the analysis by its letters: an InputError at names().goal listing the scene's
    /// modes when there is none.
    const ModeForces& goal(const std::string& letters);

    /// The wrench of a load, exactly (gravity needs the body: an InputError at "$" naming
    /// names().gravity); none for an empty load. Every number is checked (app/checks.hpp).
    [[nodiscard]] std::optional<Rational3> wrench_of(const Load& load) const;

    /// Which modes the load's wrench produces: query(scene, e) (the one-shot path when it can,
    /// the exact walk when it must) for a wrench whose direction is exactly doubles (its
    /// denominators cleared), the analysis exactly otherwise (gravity and forces at points make
    /// products that doubles may not hold). An empty load is an InputError at names().wrench.
    [[nodiscard]] QueryAnswer query(const Load& load);
    /// The same with the margins (the analysis is made).
    [[nodiscard]] MarginAnswer margins(const Load& load);

    /// The bands of magnitudes of the force lambda * direction through `point`, lambda from 0 up,
    /// added to the load's wrench (magnitude_bands).
    [[nodiscard]] std::vector<MagnitudeBand> push_line(const Rational2& point, const Rational2& direction, const Load& load);

    /// The planning context: every mode, the margins' metric, and the load's fixed_wrench.
    [[nodiscard]] PlanContext context(const Load& load);
    /// plan_tilt for the goal; the load may not hold gravity (a tilt turns gravity itself).
    [[nodiscard]] DirectionPlan plan_tilt(const std::string& goal, const Load& load);
    /// plan_push for the goal: the body needs a polygon; the request's feature and slip, when
    /// given, select the cases.
    [[nodiscard]] std::vector<PushCase> plan_push(const std::string& goal, const PushRequest& request, const Load& load);
    /// The same case by case, as each is solved (a table of 6 n cases in the memory of one).
    void plan_push(const std::string& goal, const PushRequest& request, const Load& load,
                   const std::function<void(PushCase&&)>& each);
    /// The compliance regions of the goal, and the plan of `centre` when given.
    [[nodiscard]] ComplyAnswer plan_comply(const std::string& goal, const std::optional<Rational2>& centre, const Load& load);
    /// Grasp closure of the scene's contacts (no body needed).
    [[nodiscard]] Closure closure(const std::optional<Vec2>& reference, const std::optional<double>& length) const;

private:
    Scene scene_;
    bool quasi_static_;
    InputNames names_;
    Progress progress_;
    std::optional<std::vector<ModeForces>> analysis_;
    std::optional<QueryIndex> index_;
};

}  // namespace momentlab
