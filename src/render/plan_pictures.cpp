#include "momentlab/render/pictures.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "drawing.hpp"

// Pictures of plans (Mason 1991, Figures 5 and 6): W, E_goal and W ∩ E_goal side by side, with
// the plan's answer marked on the solutions (pictures.hpp, Answer; docs/pictures.md).

namespace momentlab::render {
namespace {

using namespace drawing;

// The answer of a plan on a panel (pictures.hpp, Answer), and its lines of the legend.
void draw_answer(Panel& panel, const Answer& a, std::vector<LegendEntry>& legend) {
    const double size = std::max(view_width(panel.view), view_height(panel.view));
    const double radius = 0.2 * size;
    // A push's arcs are drawn on the side its forces come from: the finger is outside the body.
    const double behind = a.best_is_push ? M_PI : 0.0;
    const Colour label_colour = darker(palette::kAnswer, 0.8);
    for (const auto& [from, to] : a.arcs) {
        if (to > from) {
            Shape fan;
            fan.points = {a.at};
            const int steps = std::max(2, static_cast<int>(std::ceil((to - from) / 0.05)));
            for (int k = 0; k <= steps; ++k) fan.points.push_back(a.at + radius * unit(behind + from + (to - from) * k / steps));
            fan.closed = true;
            fan.fill = Fill{palette::kAnswer, 0.22};
            fan.stroke = Stroke{palette::kAnswer, 1.2};
            panel.shapes.push_back(fan);
        } else {
            panel.shapes.push_back(polyline({a.at, a.at + radius * unit(behind + from)}, Stroke{palette::kAnswer, 2.0}));
        }
        for (double end : to > from ? std::vector<double>{from, to} : std::vector<double>{from}) {
            Text t;
            t.at = a.at + 1.25 * radius * unit(behind + end);
            t.text = degrees_text(end);
            t.size = 9.0;
            t.bold = true;
            t.colour = label_colour;
            panel.texts.push_back(t);
        }
    }
    for (const auto& [p, q] : a.touch) {
        if (p == q) {
            panel.shapes.push_back(dot(p, palette::kAnswer, 4.5));
        } else {
            panel.shapes.push_back(polyline({p, q}, Stroke{palette::kAnswer, 4.5}));
        }
    }
    if (a.best_point) {
        const Vec2 d = a.best_direction.normalized(), p = *a.best_point;
        const double length = 0.3 * size;
        Shape arrow = a.best_is_push ? polyline({p - length * d, p}, Stroke{palette::kAnswer, 2.2})
                                     : polyline({p, p + length * d}, Stroke{palette::kAnswer, 2.2});
        arrow.arrow_end = true;
        panel.shapes.push_back(arrow);
    }
    if (!a.caption.empty()) set_caption(panel, a.caption);
    if (!a.arcs.empty()) {
        legend.push_back({Fill{palette::kAnswer, 0.22}, Stroke{palette::kAnswer, 1.2},
                          std::string("answer: the ") + (a.best_is_push ? "push" : "force") + " directions that work (degrees from +x)"});
    }
    if (!a.touch.empty()) legend.push_back({std::nullopt, Stroke{palette::kAnswer, 4.5}, "answer: where the finger may touch"});
    if (a.best_point) {
        legend.push_back({std::nullopt, Stroke{palette::kAnswer, 2.2},
                          std::string("answer: the best ") + (a.best_is_push ? "push" : "direction")});
    }
}

// "[−63.43°, 0°]" for each arc.
std::string arcs_text(const std::vector<AngleInterval>& arcs) {
    std::string text;
    for (const AngleInterval& i : arcs) {
        text += (text.empty() ? "" : " and ") + (i.from == i.to ? degrees_text(i.from) + " only"
                                                                 : "[" + degrees_text(i.from) + ", " + degrees_text(i.to) + "]");
    }
    return text.empty() ? "none" : text;
}

}  // namespace

Figure synthesis_figure(const std::string& title, const Scene& scene, const ForcePanel& actions,
                        const ModeForces& goal, const Cone& solutions, std::optional<Box> view, const Answer& answer) {
    const std::string& letters = goal.mode.letters;
    const std::vector<ForcePanel> sets = {
        actions,
        {"E applied (" + letters + ")", goal.applied, {}},
        {"solutions: W \u2229 E (" + letters + ")", solutions, actions.anchors}};
    Figure figure = scene_sets_figure(title, scene, sets, view);
    draw_answer(figure.panels.back(), answer, figure.legend);
    return figure;
}

namespace {

// The answer of a plan of directions through one point (a tilt, a spring).
Answer directions_answer(const Vec2& at, const DirectionPlan& plan, const std::string& what) {
    Answer a;
    a.at = at;
    for (const AngleInterval& i : plan.intervals) a.arcs.emplace_back(i.from, i.to);
    if (plan.feasible()) {
        a.best_point = at;
        a.best_direction = unit(plan.best);
    }
    a.caption = what + ": " + arcs_text(plan.intervals);
    return a;
}

}  // namespace

Figure tilt_figure(const std::string& title, const Scene& scene, const ModeForces& goal, const DirectionPlan& plan,
                   std::optional<Box> view) {
    if (!scene.body) throw std::invalid_argument("tilt_figure: the scene has no body (its centre of mass is where gravity acts)");
    const Vec2 com = scene.body->com;
    const ForcePanel actions{"W: tilts (gravity through the centre of mass)", plan.actions, {com}};
    return synthesis_figure(title, scene, actions, goal, plan.solutions, view,
                            directions_answer(com, plan, "gravity directions"));
}

Figure comply_figure(const std::string& title, const Scene& scene, const ModeForces& goal, const ComplyPlan& plan,
                     std::optional<Box> view) {
    const ForcePanel actions{"W: spring forces through the centre", plan.directions.actions, {plan.centre}};
    Answer a = directions_answer(plan.centre, plan.directions, "spring directions");
    return synthesis_figure(title, scene, actions, goal, plan.directions.solutions, view, a);
}

Figure push_figure(const std::string& title, const Scene& scene, const ModeForces& goal, const PushCase& c,
                   std::optional<Box> view) {
    std::vector<Cone> actions, solutions;
    for (const PushPiece& p : c.pieces) {
        actions.push_back(p.actions);
        solutions.push_back(p.solutions);
    }
    // Several pieces (parts free of obstacles, or a wide vertex arc): their hulls are drawn.
    const std::string what = c.feature.name() + ", slip " + std::string(1, letter(c.slip));
    const ForcePanel panel{"W: pushes (" + what + ")", sum(actions), {c.feature.from, c.feature.to}};
    Answer a;
    a.touch = c.touch;
    a.best_is_push = true;
    if (c.best) {
        a.at = c.best->point;
        a.best_point = c.best->point;
        a.best_direction = c.best->direction;
        if (c.directions) a.arcs.emplace_back(c.directions->from, c.directions->to);
    }
    std::string touch;
    for (const auto& [p, q] : c.touch) {
        touch += (touch.empty() ? "" : ", ") + (p == q ? point_text(p) : point_text(p) + "\u2013" + point_text(q));
    }
    a.caption = std::string(to_string(c.verdict)) + (touch.empty() ? "" : "; touch " + touch);
    if (c.directions) {
        a.caption += "; directions " + (c.directions->from == c.directions->to
                                            ? degrees_text(c.directions->from)
                                            : "[" + degrees_text(c.directions->from) + ", " + degrees_text(c.directions->to) + "]");
    }
    return synthesis_figure(title, scene, panel, goal, sum(solutions), view, a);
}

}  // namespace momentlab::render
