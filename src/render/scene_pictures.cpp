// The scene pictures: bodies and obstacles, contact modes with their rotation centres, force
// sets over the scene, friction cones and closure.
#include "momentlab/render/pictures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "momentlab/geometry/force_sets.hpp"
#include "momentlab/mechanics/modes.hpp"
#include "drawing.hpp"


namespace momentlab::render {
namespace {

using namespace drawing;

// Pastel colours for modes (12, repeated), chosen to stay apart from each other.
const std::array<Colour, 12> kModeColours = {{{0.651, 0.808, 0.890}, {0.698, 0.875, 0.541}, {0.984, 0.604, 0.600},
                                              {0.992, 0.749, 0.435}, {0.792, 0.698, 0.839}, {1.000, 1.000, 0.600},
                                              {0.553, 0.827, 0.780}, {0.988, 0.804, 0.898}, {0.851, 0.851, 0.851},
                                              {0.800, 0.922, 0.773}, {0.737, 0.502, 0.741}, {1.000, 0.929, 0.435}}};

// The translations of a mode, said from its twists: the twists with omega = 0 in the relative
// interior of the mode's (closed) twist cone C. S = C ∩ {omega = 0} meets the relative interior
// of C exactly when S lies in no facet of C (a convex part of C's relative boundary lies in one
// facet), decided exactly; then the translations are S without its part on C's boundary, and
// the text gives S's generators: "translation along (1, 0)", "translations in cone{(0, 1),
// ±(1, 0)}". Empty when the mode has no translation.
std::string translations_text(const Cone& twists) {
    const Cone plane = Cone::from_halfspaces(std::vector<Vec3>{Vec3::UnitZ(), -Vec3::UnitZ()});
    const Cone s = intersection(twists, plane);
    if (s.is_zero()) return {};
    std::vector<ExactVector> spanning = s.rays();
    for (const ExactVector& l : s.lineality()) {
        spanning.push_back(l);
        spanning.push_back(l.negated());
    }
    for (const ExactVector& f : twists.facets()) {
        const bool in_facet = std::all_of(spanning.begin(), spanning.end(),
                                          [&](const ExactVector& g) { return dot_sign(f, g) == Sign::Zero; });
        if (in_facet) return {};
    }
    std::vector<std::string> parts;
    for (const ExactVector& r : s.rays()) parts.push_back("(" + fmt(r.value().x()) + ", " + fmt(r.value().y()) + ")");
    for (const ExactVector& l : s.lineality()) {
        parts.push_back("\u00B1(" + fmt(l.value().x()) + ", " + fmt(l.value().y()) + ")");
    }
    if (s.rays().size() == 1 && s.lineality().empty()) return "translation along " + parts.front();
    if (s.rays().empty() && s.lineality().size() == 1) return "translations along " + parts.front();
    std::string text = "translations in cone{";
    for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? ", " : "") + parts[i];
    return text + "}";
}

std::vector<LegendEntry> scene_legend() {
    return {{Fill{palette::kBody, 0.15}, Stroke{palette::kBody, 1.5}, "body; dot: centre of mass"},
            {Fill{palette::kObstacle, 0.45}, Stroke{palette::kObstacle, 1.0}, "fixed polygons"},
            {Fill{palette::kFriction, 0.25}, Stroke{palette::kFriction, 1.0}, "friction cone; arrow: normal into the body"}};
}

// A mode's rotation centres on a panel: a point with a cross and its coordinates, a set dashed;
// a caption names them or the mode's translations (design.md: a rotation about (x, y) with
// angular velocity w is the twist w (y, -x, 1)).
void draw_rotation_centres(Panel& panel, const Mode& mode, std::vector<LegendEntry>& legend) {
    if (mode.twists.is_zero()) return;
    const Labels centres = rotation_centres(mode);
    const double size = std::max(view_width(panel.view), view_height(panel.view));
    std::vector<std::string> said;
    bool drawn = false;
    for (const auto& [region, sense] : {std::pair{&centres.plus(), kCounterClockwise}, std::pair{&centres.minus(), kClockwise}}) {
        const int dim = dimension(*region);
        if (dim < 0) continue;
        if (dim == 0) {
            const Vec2 c = region->vertices.front();
            said.push_back("rotation about " + point_text(c) + " " + sense);
            if (region->clipped(panel.view).empty()) continue;
            rotation_cross(panel, c, 0.025 * size);
            Text t;
            t.at = c;
            t.offset = Vec2(0.0, -13.0);
            t.text = point_text(c) + " " + sense;
            t.size = 9.0;
            t.bold = true;
            t.colour = darker(palette::kAnswer, 0.8);
            panel.texts.push_back(t);
            drawn = true;
            continue;
        }
        said.push_back(std::string("rotation centres dashed (") + sense + ")");
        const std::vector<Vec2> poly = region->clipped(panel.view);
        if (poly.empty()) continue;
        Shape outline = polyline(poly, Stroke{palette::kAnswer, 1.6, true});
        outline.closed = poly.size() > 2;
        panel.shapes.push_back(outline);
        drawn = true;
    }
    const std::string translations = translations_text(mode.twists);
    if (!translations.empty()) said.push_back(translations);
    std::string caption = mode.letters + ":";
    for (std::size_t i = 0; i < said.size(); ++i) caption += (i ? "; " : " ") + said[i];
    set_caption(panel, caption);
    if (drawn && legend.size() < 64) {
        const std::string text = "answer: the rotation centre (\u00D7, or dashed: a set of them)";
        if (std::none_of(legend.begin(), legend.end(), [&](const LegendEntry& e) { return e.text == text; })) {
            legend.push_back({std::nullopt, Stroke{palette::kAnswer, 2.0}, text});
        }
    }
}


}  // namespace

void add_obstacles(Panel& panel, const std::vector<Polygon>& obstacles, bool faint) {
    for (const Polygon& o : obstacles) {
        Shape s;
        s.points = o;
        s.closed = true;
        s.fill = Fill{palette::kObstacle, faint ? 0.2 : 0.45};
        s.stroke = Stroke{palette::kObstacle, 1.0};
        panel.shapes.push_back(s);
    }
}

void add_scene(Panel& panel, const Scene& scene, SceneStyle style) {
    const bool faint = style != SceneStyle::Full;
    const Box v = scene_view(scene);
    const double length = 0.16 * std::max(view_width(v), view_height(v));
    add_obstacles(panel, scene.obstacles, faint);
    if (scene.body) {
        if (!scene.body->polygon.empty()) {
            Shape s;
            s.points = scene.body->polygon;
            s.closed = true;
            s.fill = Fill{palette::kBody, faint ? 0.05 : 0.15};
            s.stroke = Stroke{palette::kBody, faint ? 1.0 : 1.8, false, faint ? 0.7 : 1.0};
            panel.shapes.push_back(s);
        }
        panel.shapes.push_back(dot(scene.body->com, palette::kInk, faint ? 2.0 : 3.0));
    }
    for (const Contact& c : scene.contacts) {
        const Vec2 n = c.normal, t = c.tangent();
        if (style == SceneStyle::Outline) {
            panel.shapes.push_back(dot(c.point, palette::kFriction, 3.0));
            continue;
        }
        if (c.mu > 0.0) {
            Shape wedge;
            wedge.points = {c.point, c.point + length * (n + c.mu * t).normalized(),
                            c.point + length * (n - c.mu * t).normalized()};
            wedge.closed = true;
            wedge.fill = Fill{palette::kFriction, faint ? 0.12 : 0.25};
            wedge.stroke = Stroke{palette::kFriction, 0.8, false, faint ? 0.6 : 1.0};
            panel.shapes.push_back(wedge);
        }
        Shape normal = polyline({c.point, c.point + length * n}, Stroke{palette::kFriction, 1.2, false, faint ? 0.6 : 1.0});
        normal.arrow_end = true;
        panel.shapes.push_back(normal);
        panel.shapes.push_back(dot(c.point, palette::kFriction, faint ? 2.0 : 2.8));
        if (!faint && !c.name.empty()) {
            Text name;
            name.at = c.point;
            name.offset = 14.0 * Vec2(-n.x(), n.y()) + Vec2(0.0, -2.0);
            name.text = c.name;
            name.size = 9.0;
            name.colour = palette::kFriction;
            panel.texts.push_back(name);
        }
    }
}

namespace {

// The scene, faint, over a labels panel (drawn after its regions; the marks stay on top: they
// are texts).
void add_faint_scene(Panel& panel, const Scene& scene) {
    Panel scene_layer;
    scene_layer.view = panel.view;
    add_scene(scene_layer, scene, SceneStyle::Faint);
    panel.shapes.insert(panel.shapes.end(), scene_layer.shapes.begin(), scene_layer.shapes.end());
}

}  // namespace

Box scene_view(const Scene& scene) {
    std::vector<Vec2> points;
    if (scene.body) {
        points.insert(points.end(), scene.body->polygon.begin(), scene.body->polygon.end());
        points.push_back(scene.body->com);
    }
    for (const Contact& c : scene.contacts) points.push_back(c.point);
    if (points.empty()) {
        for (const Polygon& o : scene.obstacles) points.insert(points.end(), o.begin(), o.end());
    }
    return fit_view(points, 0.6);
}

Figure modes_figure(const std::string& title, const Scene& scene, std::optional<Box> view) {
    const ModeSet modes = enumerate_modes(scene.contacts);
    Panel panel;
    panel.title = "rotation centres of each mode";
    panel.view = view ? *view : scene_view(scene);
    for (const Contact& c : scene.contacts) {
        for (const Vec2& d : {c.normal, c.tangent()}) {
            if (const auto seg = clip_line(c.point, d, panel.view)) {
                panel.shapes.push_back(polyline({(*seg)[0], (*seg)[1]}, Stroke{palette::kGuide, 0.8, true}));
            }
        }
    }
    Figure figure;
    figure.title = title;
    // Regions with interior first, then segments, then points, so nothing hides a smaller one.
    std::vector<Labels> centres_of;  // each mode's rotation centres, built once
    for (const Mode& mode : modes.modes) centres_of.push_back(rotation_centres(mode));
    std::vector<Text> marks;
    for (int pass = 2; pass >= 0; --pass) {
        for (std::size_t k = 0; k < modes.modes.size(); ++k) {
            const Mode& mode = modes.modes[k];
            const Colour colour = kModeColours[k % kModeColours.size()];
            const Labels& centres = centres_of[k];
            for (const auto& [region, sense] : {std::pair{&centres.plus(), kCounterClockwise},
                                                std::pair{&centres.minus(), kClockwise}}) {
                if (dimension(*region) != pass || region->clipped(panel.view).empty()) continue;
                draw_region(panel, *region, colour, darker(colour, pass == 2 ? 0.8 : 0.6));
                Text t = mark_for(*region, panel.view, mode.letters + " " + sense, darker(colour, 0.45), 0.5);
                t.size = 10.0;
                // Two senses of rotation about one point: the marks go to either side of it.
                if (pass == 0) t.offset = sense == kCounterClockwise ? Vec2(-20.0, -12.0) : Vec2(20.0, 12.0);
                marks.push_back(t);
            }
        }
    }
    for (std::size_t k = 0; k < modes.modes.size(); ++k) {
        const Mode& mode = modes.modes[k];
        const Colour colour = kModeColours[k % kModeColours.size()];
        const Labels& centres = centres_of[k];
        const bool drawn = !centres.plus().clipped(panel.view).empty() || !centres.minus().clipped(panel.view).empty();
        std::string text = mode.letters + ":";
        if (mode.twists.is_zero()) {
            text += " at rest (no contact moves)";
        } else {
            if (drawn) text += " rotation centres (" + std::string(kCounterClockwise) + " counter-clockwise, " + kClockwise + " clockwise)";
            const std::string translations = translations_text(mode.twists);
            if (!translations.empty()) text += (drawn ? "; " : " ") + translations;
            if (!drawn && translations.empty()) text += " rotation centres outside the view";
        }
        if (drawn) {
            figure.legend.push_back({Fill{colour, 1.0}, Stroke{darker(colour, 0.7), 0.8}, text});
        } else {
            figure.legend.push_back({std::nullopt, std::nullopt, text});
        }
    }
    add_scene(panel, scene, SceneStyle::Outline);
    panel.texts.insert(panel.texts.end(), marks.begin(), marks.end());
    figure.panels.push_back(panel);
    for (const LegendEntry& e : scene_legend()) figure.legend.push_back(e);
    figure.legend.push_back({std::nullopt, Stroke{palette::kGuide, 0.8, true}, "contact normals and tangents"});
    return figure;
}

// Panels of force sets over a faint scene, three to a row, sharing one view (drawing.hpp).
Figure drawing::scene_sets_figure(const std::string& title, const Scene& scene, const std::vector<ForcePanel>& sets,
                         std::optional<Box> view) {
    if (!view) {
        // The scene, and the sets' corners near it (far corners would shrink the scene away).
        const Box sv = scene_view(scene);
        const Vec2 c = view_centre(sv);
        const double reach = 2.5 * std::max(view_width(sv), view_height(sv));
        std::vector<Vec2> points = {sv.min, sv.max};
        for (const ForcePanel& s : sets) {
            for (const Vec2& p : points_of(s)) {
                if ((p - c).cwiseAbs().maxCoeff() <= reach) points.push_back(p);
            }
        }
        view = fit_view(points, 0.08);
    }
    Figure figure;
    figure.title = title;
    figure.columns = 3;
    for (const ForcePanel& s : sets) {
        Panel p = labels_panel(s, *view);
        add_faint_scene(p, scene);
        figure.panels.push_back(std::move(p));
    }
    figure.legend = labels_legend();
    for (const LegendEntry& e : scene_legend()) figure.legend.push_back(e);
    return figure;
}

Figure forces_figure(const std::string& title, const Scene& scene, const std::vector<ModeForces>& analysis,
                     const std::vector<std::size_t>& modes, std::optional<Box> view) {
    std::vector<Vec2> contact_points;
    for (const Contact& c : scene.contacts) contact_points.push_back(c.point);
    std::vector<ForcePanel> sets;
    for (std::size_t k : modes) {
        const ModeForces& m = analysis.at(k);
        const std::string& letters = m.mode.letters;
        std::vector<Vec2> com;
        if (scene.body) com.push_back(scene.body->com);
        sets.push_back({"F total (" + letters + ")", m.total, com});
        sets.push_back({"T contact (" + letters + ")", m.contact, contact_points});
        sets.push_back({"E applied (" + letters + ")", m.applied, {}});
    }
    Figure figure = scene_sets_figure(title, scene, sets, view);
    for (std::size_t i = 0; i < modes.size(); ++i) {
        draw_rotation_centres(figure.panels.at(3 * i), analysis.at(modes[i]).mode, figure.legend);
    }
    return figure;
}

Figure friction_figure(const std::string& title, const Scene& scene, std::optional<Box> view) {
    std::vector<ForcePanel> parts;
    std::vector<Cone> cones;
    for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
        const Contact& c = scene.contacts[i];
        cones.push_back(friction_cone(c.point, c.normal, c.mu));
        const std::string name = c.name.empty() ? "contact " + std::to_string(i + 1) : c.name;
        parts.push_back({name + ", \u03BC = " + fmt(c.mu), cones.back(), {c.point}});
    }
    if (!view) view = scene_view(scene);
    Figure figure = labels_figure(title, parts, false, sum(cones), view);
    for (Panel& p : figure.panels) add_faint_scene(p, scene);
    for (const LegendEntry& e : scene_legend()) figure.legend.push_back(e);
    return figure;
}

Figure closure_figure(const std::string& title, const Scene& scene, std::optional<Box> view) {
    const Closure c = closure(scene);
    std::vector<Vec2> anchors;
    for (const Contact& contact : scene.contacts) anchors.push_back(contact.point);
    if (!view) view = scene_view(scene);
    auto says = [](const ClosureTest& t) { return std::string(t.holds ? "holds (no label)" : "fails"); };
    Figure figure;
    figure.title = title;
    figure.columns = 2;
    for (const auto& [heading, test] : {std::pair<std::string, const ClosureTest*>{"form closure (normals): ", &c.form},
                                         std::pair<std::string, const ClosureTest*>{"force closure (friction cones): ", &c.force}}) {
        Panel panel = labels_panel(ForcePanel{heading + says(*test), test->wrenches, anchors}, *view);
        add_faint_scene(panel, scene);
        figure.panels.push_back(std::move(panel));
    }
    figure.legend = labels_legend();
    for (const LegendEntry& e : scene_legend()) figure.legend.push_back(e);
    return figure;
}

}  // namespace momentlab::render
