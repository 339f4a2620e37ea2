// The picture of `momentlab stand`: the assembly with its equilibrium's forces or its collapse
// mechanism, and each body's moment labels (stand_pictures.hpp).
#include "momentlab/render/stand_pictures.hpp"

#include <algorithm>
#include <stdexcept>

#include "momentlab/geometry/force_sets.hpp"
#include "drawing.hpp"

namespace momentlab::render {
namespace {

using namespace drawing;

std::string body_label(const Assembly& a, std::size_t k) {
    const std::string& name = a.bodies[k].name;
    return std::to_string(k + 1) + (name.empty() ? "" : " " + name);
}

Box assembly_view(const Assembly& a) {
    std::vector<Vec2> points;
    for (const AssemblyBody& b : a.bodies) {
        points.insert(points.end(), b.polygon.begin(), b.polygon.end());
        points.push_back(b.com);
    }
    for (const AssemblyContact& c : a.contacts) points.push_back(c.contact.point);
    return fit_view(points, 0.25);
}

// Obstacles, bodies (outlined; `outlined` in ink), centres of mass and numbers, contacts.
void add_assembly(Panel& panel, const Assembly& a, bool faint, std::optional<std::size_t> outlined = std::nullopt) {
    const double size = std::max(view_width(panel.view), view_height(panel.view));
    add_obstacles(panel, a.obstacles, faint);
    for (std::size_t k = 0; k < a.bodies.size(); ++k) {
        const AssemblyBody& b = a.bodies[k];
        const bool own = outlined && *outlined == k;
        if (!b.polygon.empty()) {
            Shape s;
            s.points = b.polygon;
            s.closed = true;
            s.fill = Fill{palette::kBody, own ? 0.25 : (faint ? 0.05 : 0.15)};
            s.stroke = Stroke{own ? palette::kInk : palette::kBody, own ? 2.2 : (faint ? 1.0 : 1.8), false, faint && !own ? 0.7 : 1.0};
            panel.shapes.push_back(s);
        }
        panel.shapes.push_back(dot(b.com, palette::kInk, b.polygon.empty() ? 4.5 : (faint ? 2.0 : 3.0)));
        Text t;
        t.at = b.com;
        t.offset = Vec2(0.0, 11.0);
        t.text = body_label(a, k);
        t.size = 9.0;
        t.bold = own;
        panel.texts.push_back(t);
    }
    const double length = 0.1 * size;
    for (const AssemblyContact& ac : a.contacts) {
        const Contact& c = ac.contact;
        const Vec2 n = c.normal.normalized(), t = c.tangent().normalized();
        if (faint) {
            panel.shapes.push_back(dot(c.point, palette::kFriction, 2.0));
            continue;
        }
        if (c.mu > 0.0) {
            Shape wedge;
            wedge.points = {c.point, c.point + length * (n + c.mu * t).normalized(), c.point + length * (n - c.mu * t).normalized()};
            wedge.closed = true;
            wedge.fill = Fill{palette::kFriction, 0.2};
            wedge.stroke = Stroke{palette::kFriction, 0.8};
            panel.shapes.push_back(wedge);
        }
        Shape normal = polyline({c.point, c.point + length * n}, Stroke{palette::kFriction, 1.0});
        normal.arrow_end = true;
        panel.shapes.push_back(normal);
        panel.shapes.push_back(dot(c.point, palette::kFriction, 2.8));
    }
}

Shape answer_arrow(const Vec2& from, const Vec2& to) {
    Shape arrow = polyline({from, to}, Stroke{palette::kAnswer, 2.2});
    arrow.arrow_end = true;
    return arrow;
}

// The contact forces of the equilibrium, on body a, from each contact point.
void draw_equilibrium(Panel& panel, const Equilibrium& e, const Assembly& a) {
    double largest = 0.0;
    for (const Vec2& f : e.forces) largest = std::max(largest, f.norm());
    const double size = std::max(view_width(panel.view), view_height(panel.view));
    std::size_t carrying = 0;
    for (std::size_t j = 0; j < e.forces.size(); ++j) {
        const Vec2& f = e.forces[j];
        if (f == Vec2::Zero()) continue;
        ++carrying;
        const Vec2& p = a.contacts[j].contact.point;
        panel.shapes.push_back(answer_arrow(p, p + 0.2 * size * f / largest));
    }
    set_caption(panel, "stands: the contact forces of one equilibrium (on body a; " + std::to_string(carrying) + " of " +
                           std::to_string(e.forces.size()) + " contacts carry force)");
}

// The mechanism: rotation centres and the velocities of the centres of mass.
void draw_mechanism(Panel& panel, const Equilibrium& e, const Assembly& a) {
    const double size = std::max(view_width(panel.view), view_height(panel.view));
    std::vector<Vec2> velocity;
    double fastest = 0.0;
    for (std::size_t k = 0; k < e.mechanism.size(); ++k) {
        const Vec3& v = e.mechanism[k].twist;
        const Vec2& c = a.bodies[k].com;
        velocity.push_back(Vec2(v.x() - v.z() * c.y(), v.y() + v.z() * c.x()));
        fastest = std::max(fastest, velocity.back().norm());
    }
    std::vector<std::string> said;
    for (std::size_t k = 0; k < e.mechanism.size(); ++k) {
        const BodyMotion& m = e.mechanism[k];
        const std::string who = std::to_string(k + 1);
        if (velocity[k] != Vec2::Zero() && fastest > 0.0) {
            const Vec2& c = a.bodies[k].com;
            panel.shapes.push_back(answer_arrow(c, c + 0.18 * size * velocity[k] / fastest));
        }
        if (m.rotation_centre) {
            const char* sense = m.twist.z() > 0.0 ? kCounterClockwise : kClockwise;
            said.push_back(who + " turns about " + point_text(*m.rotation_centre) + " " + sense);
            const Vec2& r = *m.rotation_centre;
            rotation_cross(panel, r, 0.02 * size);
            Text t;
            t.at = r;
            t.offset = Vec2(0.0, -13.0);
            t.text = who + " " + sense;
            t.size = 9.0;
            t.bold = true;
            t.colour = darker(palette::kAnswer, 0.8);
            panel.texts.push_back(t);
        } else if (m.twist.x() != 0.0 || m.twist.y() != 0.0) {
            said.push_back(who + " translates");
        }
    }
    std::string caption = "falls: a collapse mechanism";
    for (std::size_t i = 0; i < said.size(); ++i) caption += (i ? "; " : ": ") + said[i];
    set_caption(panel, caption);
}

}  // namespace

Cone contact_wrenches(const Assembly& assembly, std::size_t k) {
    if (k < 1 || k > assembly.bodies.size()) throw std::out_of_range("contact_wrenches: no body " + std::to_string(k));
    std::vector<ExactVector> edges;
    for (const AssemblyContact& ac : assembly.contacts) {
        if (ac.a != k && ac.b != k) continue;
        for (const ExactVector& e : friction_cone_edges(ac.contact.point, ac.contact.normal, ac.contact.mu)) {
            edges.push_back(ac.a == k ? e : e.negated());
        }
    }
    return Cone::from_generators(std::span<const ExactVector>(edges));
}

Figure stand_figure(const std::string& title, const Assembly& assembly, const StandResult& result, std::optional<Box> view) {
    const Box box = view ? *view : assembly_view(assembly);
    Figure figure;
    figure.title = title;
    figure.columns = 3;
    Panel main;
    main.title = "the assembly and its answer";
    main.view = box;
    add_assembly(main, assembly, false);
    if (result.equilibrium.can_stand) {
        draw_equilibrium(main, result.equilibrium, assembly);
    } else {
        draw_mechanism(main, result.equilibrium, assembly);
    }
    figure.panels.push_back(std::move(main));
    const std::size_t shown = std::min(assembly.bodies.size(), kStandLabelPanels);
    for (std::size_t k = 1; k <= shown; ++k) {
        std::vector<Vec2> anchors;
        for (const AssemblyContact& ac : assembly.contacts) {
            if (ac.a == k || ac.b == k) anchors.push_back(ac.contact.point);
        }
        Panel p = labels_panel({"body " + body_label(assembly, k - 1) + ": wrenches its contacts can apply",
                                contact_wrenches(assembly, k), anchors},
                               box);
        Panel layer;
        layer.view = box;
        add_assembly(layer, assembly, true, k - 1);
        p.shapes.insert(p.shapes.end(), layer.shapes.begin(), layer.shapes.end());
        p.texts.insert(p.texts.end(), layer.texts.begin(), layer.texts.end());
        figure.panels.push_back(std::move(p));
    }
    if (shown < assembly.bodies.size()) {
        figure.panels.front().title += " (labels of the first " + std::to_string(shown) + " bodies)";
    }
    figure.legend.push_back({Fill{palette::kBody, 0.15}, Stroke{palette::kBody, 1.5}, "bodies 1..N; dot: centre of mass"});
    figure.legend.push_back({Fill{palette::kObstacle, 0.45}, Stroke{palette::kObstacle, 1.0}, "the fixed world (body 0)"});
    figure.legend.push_back({Fill{palette::kFriction, 0.2}, Stroke{palette::kFriction, 1.0},
                             "friction cone; arrow: normal into body a"});
    if (result.equilibrium.can_stand) {
        figure.legend.push_back({std::nullopt, Stroke{palette::kAnswer, 2.2}, "answer: the force on body a at a contact"});
    } else {
        figure.legend.push_back({std::nullopt, Stroke{palette::kAnswer, 2.2},
                                 "answer: a body's rotation centre (\u00D7) and its centre of mass's velocity"});
    }
    for (const LegendEntry& e : labels_legend()) figure.legend.push_back(e);
    return figure;
}

}  // namespace momentlab::render
