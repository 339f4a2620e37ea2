#pragma once

/// \file
/// Synthesis by pushing (Mason 1991, section 3, Example 2; DESIGN, Synthesis): a finger touches
/// an edge of the body and slips along it (l, r) or sticks (f); its force set along the edge is a
/// cone W, and the pushes that produce a goal mode i are W ∩ E_i. Letters as for contacts, the
/// finger being the fixed side: n points into the body, t = (n.y, -n.x), r means the body
/// slides along +t relative to the finger (friction on the body along -t).

#include <string>
#include <vector>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/dynamics.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// The finger's forces on the body anywhere along the segment a-b, with inward normal `normal`
/// and friction coefficient mu >= 0, for slip 'l', 'f' or 'r': the positive combinations of the
/// slip's friction-cone edges at a and at b (a force at a point between them is such a
/// combination). Throws std::invalid_argument for another slip letter, a zero normal or mu < 0.
[[nodiscard]] Cone push_actions(const Vec2& a, const Vec2& b, const Vec2& normal, char slip, double mu);

/// One pushing case: an edge of the body polygon and a slip.
struct PushCase {
    std::size_t edge = 0;  ///< the edge from vertex `edge` to the next, in the polygon's order
    Vec2 from = Vec2::Zero();
    Vec2 to = Vec2::Zero();
    Vec2 normal = Vec2::Zero();  ///< unit inward normal (rounded)
    char slip = 'f';
    Cone actions;    ///< W
    Cone solutions;  ///< W ∩ E_goal
    [[nodiscard]] bool feasible() const { return !solutions.is_zero(); }
};

/// Every edge of the body polygon with each slip l, f, r, pushed with finger friction mu;
/// interference with obstacles is ignored (as in the paper). Throws std::invalid_argument if the
/// scene has no body polygon or mu < 0.
[[nodiscard]] std::vector<PushCase> plan_push_edges(const Scene& scene, const ModeForces& goal, double mu);

}  // namespace momentlab
