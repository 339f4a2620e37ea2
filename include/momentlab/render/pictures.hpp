#pragma once

/// \file
/// The pictures of the method (Mason 1991, Figures 1-6): moment labels of force sets, contact
/// modes as regions of rotation centres, and the per-mode sets F_i, T_i, E_i side by side.
/// Each builder returns a Figure (render/figure.hpp); the mechanics are read, never changed.

#include <optional>
#include <string>
#include <vector>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/geometry/labels.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/closure.hpp"
#include "momentlab/mechanics/scene.hpp"
#include "momentlab/planning/comply.hpp"
#include "momentlab/planning/push.hpp"
#include "momentlab/render/figure.hpp"

namespace momentlab::render {

/// A force set to draw in one panel, with its title. `anchors` are points where its forces
/// preferably start their arrows (a force is drawn from the first anchor on its line of action,
/// else from the point of that line nearest the view's centre).
struct ForcePanel {
    std::string title;
    Cone forces;
    std::vector<Vec2> anchors;
};

/// A view fitting the points (padded by `pad` of their extent on each side, never flatter than
/// 1:2, and [-1, 1]^2 when there are none).
[[nodiscard]] Box fit_view(const std::vector<Vec2>& points, double pad = 0.35);

/// The panel of a force set's labels over `view`: + and - regions filled (palette::kPlus /
/// kMinus) with a + or - mark, the +- set drawn in palette::kBoth with a "±" mark, unbounded
/// regions cut at the view with outward arrows where they go on, and the forces (extreme
/// rays and lines of the cone) as arrows along their lines of action.
[[nodiscard]] Panel labels_panel(const ForcePanel& set, const Box& view);

/// The legend of labels panels.
[[nodiscard]] std::vector<LegendEntry> labels_legend();

/// Figures 1 and 2: one panel per force set and, when there are several, a last panel with
/// their sum (labels intersected) or intersection. `view` overrides the automatic view.
[[nodiscard]] Figure labels_figure(const std::string& title, const std::vector<ForcePanel>& parts,
                                   bool intersect, const Cone& combined, std::optional<Box> view = std::nullopt);

/// How much of a scene to draw: everything, everything lighter (over force sets), or the
/// outlines and contact points only (under the modes' regions).
enum class SceneStyle { Full, Faint, Outline };

/// The scene (obstacles, body, centre of mass, contacts with their friction cones and names)
/// drawn into `panel`.
void add_scene(Panel& panel, const Scene& scene, SceneStyle style);
/// The fixed polygons, filled (lighter when `faint`).
void add_obstacles(Panel& panel, const std::vector<Polygon>& obstacles, bool faint);

/// A view fitting the scene's body and contacts (or its obstacles when there is neither).
[[nodiscard]] Box scene_view(const Scene& scene);

/// The scene with each mode's rotation centres (Reuleaux's construction extended by Brost and
/// Mason 1989): regions coloured per mode and marked with the mode string and its sense (↺
/// counter-clockwise, ↻ clockwise); the contact normals and tangents as guides; translations
/// and the mode at rest listed in the legend.
[[nodiscard]] Figure modes_figure(const std::string& title, const Scene& scene, std::optional<Box> view = std::nullopt);

/// Figures 3 and 4: for each chosen mode (indices into `analysis`), the panels F_i (total),
/// T_i (contact) and E_i (applied) side by side over the scene; F_i's panel marks the mode's
/// rotation centres (a point with its coordinates and sense, or the regions dashed) or says
/// its translations.
[[nodiscard]] Figure forces_figure(const std::string& title, const Scene& scene,
                                   const std::vector<ModeForces>& analysis, const std::vector<std::size_t>& modes,
                                   std::optional<Box> view = std::nullopt);

/// A plan's answer, marked in palette::kAnswer on the solutions panel of a synthesis figure: the
/// arcs of force directions through `at` as a fan with their ends in degrees, the segments where
/// a finger may touch drawn thick, and the best action as an arrow (a push ends at its point,
/// a tilt or a spring starts there). Empty parts are not drawn.
struct Answer {
    Vec2 at = Vec2::Zero();
    std::vector<std::pair<double, double>> arcs;  ///< radians from +x, counter-clockwise from first to second
    std::vector<std::pair<Vec2, Vec2>> touch;     ///< segments of the body's outline (a point: twice)
    std::optional<Vec2> best_point;
    Vec2 best_direction = Vec2::Zero();
    bool best_is_push = false;                    ///< the arrow ends at best_point (a finger pushing)
    std::string caption;                          ///< one line in the panel's corner
};

/// Figures 5 and 6: the achievable actions W (e.g. tilts: the forces through the centre of
/// mass), the goal mode's applied wrenches E_i, and the solutions W ∩ E_i (the labels' hulls),
/// side by side over the scene, with the answer marked on the solutions.
[[nodiscard]] Figure synthesis_figure(const std::string& title, const Scene& scene, const ForcePanel& actions,
                                      const ModeForces& goal, const Cone& solutions,
                                      std::optional<Box> view = std::nullopt, const Answer& answer = {});

/// Figure 5 for a tilt plan (plan_tilt): W the forces through the centre of mass, its arcs of
/// gravity directions and its best direction marked.
[[nodiscard]] Figure tilt_figure(const std::string& title, const Scene& scene, const ModeForces& goal,
                                 const DirectionPlan& plan, std::optional<Box> view = std::nullopt);

/// A compliance plan (plan_comply): W the forces through the centre, its arcs of spring
/// directions and its best direction marked.
[[nodiscard]] Figure comply_figure(const std::string& title, const Scene& scene, const ModeForces& goal,
                                   const ComplyPlan& plan, std::optional<Box> view = std::nullopt);

/// Figure 6 for one pushing case (plan_push): W the finger's forces on the feature (the hull of
/// its parts), the touch segments, the arc of push directions at the best push's point and the
/// best push marked.
[[nodiscard]] Figure push_figure(const std::string& title, const Scene& scene, const ModeForces& goal,
                                 const PushCase& c, std::optional<Box> view = std::nullopt);

/// The multi-contact friction cone of the scene (Figure 2 from a scene): one panel per
/// contact's friction cone and their sum.
[[nodiscard]] Figure friction_figure(const std::string& title, const Scene& scene, std::optional<Box> view = std::nullopt);

/// Grasp closure explained by moment labels (Modern Robotics, ch. 12): the labels of the
/// normals' wrenches (form closure) and of the friction cones' sum (force closure) over the
/// scene. Closure holds exactly when both regions are empty; a point in the + region is a
/// centre about which every contact wrench turns counter-clockwise, so nothing resists a
/// clockwise turn about it.
[[nodiscard]] Figure closure_figure(const std::string& title, const Scene& scene, std::optional<Box> view = std::nullopt);

}  // namespace momentlab::render
