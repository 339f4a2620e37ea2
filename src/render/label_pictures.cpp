// The moment-labels pictures (Mason 1991, Figure 1): regions, marks and forces on panels.
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

Vec2 centroid(const std::vector<Vec2>& poly) {
    double area = 0.0;
    Vec2 c = Vec2::Zero();
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2& a = poly[i];
        const Vec2& b = poly[(i + 1) % poly.size()];
        const double w = cross2(a, b);
        area += w;
        c += w * (a + b);
    }
    if (std::abs(area) > 0.0 && std::isfinite(area)) return c / (3.0 * area);
    Vec2 mean = Vec2::Zero();
    for (const Vec2& p : poly) mean += p;
    return mean / static_cast<double>(poly.size());
}

// The outward normal of the box side an edge lies on, or zero if it lies on none.
Vec2 side_of(const Vec2& a, const Vec2& b, const Box& box) {
    if (a.x() == box.min.x() && b.x() == box.min.x()) return Vec2(-1.0, 0.0);
    if (a.x() == box.max.x() && b.x() == box.max.x()) return Vec2(1.0, 0.0);
    if (a.y() == box.min.y() && b.y() == box.min.y()) return Vec2(0.0, -1.0);
    if (a.y() == box.max.y() && b.y() == box.max.y()) return Vec2(0.0, 1.0);
    return Vec2::Zero();
}

// A point of the line of action of the force w = (f, tau) nearest to c.
Vec2 nearest_on_line(const Vec3& w, const Vec2& c) {
    const Vec2 f(w.x(), w.y());
    const Vec2 p0 = Vec2(f.y(), -f.x()) * (w.z() / f.squaredNorm());
    const Vec2 u = f.normalized();
    return p0 + (c - p0).dot(u) * u;
}

void draw_forces(Panel& panel, const ForcePanel& set, const Region& both) {
    const Box& view = panel.view;
    const double length = 0.22 * std::max(view_width(view), view_height(view));
    std::vector<Vec2> anchors = set.anchors;
    if (dimension(both) == 0) anchors.push_back(both.vertices.front());
    std::vector<std::string> moments;
    auto draw = [&](const ExactVector& g, bool both_senses) {
        const Vec3& w = g.value();
        if (w.x() == 0.0 && w.y() == 0.0) {
            moments.push_back(both_senses ? std::string(kCounterClockwise) + kClockwise
                                          : (w.z() > 0 ? kCounterClockwise : kClockwise));
            return;
        }
        const Vec2 u = Vec2(w.x(), w.y()).normalized();
        std::optional<Vec2> start;
        for (const Vec2& a : anchors) {
            if (g.dot_sign(moment_functional(a)) == Sign::Zero) {  // a is on the line of action
                start = a;
                break;
            }
        }
        if (!start) {
            start = nearest_on_line(w, view_centre(view));
            // (A +- line is this line of action already.)
            const auto seg = dimension(both) == 1 ? std::nullopt : clip_line(*start, u, view);
            if (seg) {
                panel.shapes.push_back(polyline({(*seg)[0], (*seg)[1]}, Stroke{palette::kInk, 0.8, true, 0.55}));
            }
        }
        Shape arrow = polyline({both_senses ? Vec2(*start - 0.5 * length * u) : *start,
                                both_senses ? Vec2(*start + 0.5 * length * u) : Vec2(*start + length * u)},
                               Stroke{palette::kInk, 1.6});
        arrow.arrow_end = true;
        arrow.arrow_start = both_senses;
        panel.shapes.push_back(arrow);
    };
    for (const ExactVector& r : set.forces.rays()) draw(r, false);
    for (const ExactVector& l : set.forces.lineality()) draw(l, true);
    if (!moments.empty()) {
        std::string text = "pure moments:";
        for (const std::string& m : moments) text += " " + m;
        Text t;
        t.at = Vec2(view.min.x(), view.max.y());
        t.offset = Vec2(8.0 + 3.2 * static_cast<double>(text.size()), -12.0);
        t.text = text;
        t.size = 10.0;
        panel.texts.push_back(t);
    }
}

void add_points(std::vector<Vec2>& points, const Region& r) {
    for (const Vec2& v : r.vertices) {
        if (v.allFinite()) points.push_back(v);
    }
}

}  // namespace

std::optional<std::array<Vec2, 2>> drawing::clip_line(const Vec2& p, const Vec2& u, const Box& box) {
    double lo = -INFINITY, hi = INFINITY;
    for (int k = 0; k < 2; ++k) {
        if (u[k] == 0.0) {
            if (p[k] < box.min[k] || p[k] > box.max[k]) return std::nullopt;
            continue;
        }
        double a = (box.min[k] - p[k]) / u[k], b = (box.max[k] - p[k]) / u[k];
        if (a > b) std::swap(a, b);
        lo = std::max(lo, a);
        hi = std::min(hi, b);
    }
    if (!(lo < hi)) return std::nullopt;
    return std::array<Vec2, 2>{p + lo * u, p + hi * u};
}

void drawing::draw_region(Panel& panel, const Region& region, const Colour& fill, const Colour& edge, double fill_alpha) {
    const std::vector<Vec2> poly = region.clipped(panel.view);
    if (poly.empty()) return;
    const int dim = dimension(region);
    if (dim == 0 || poly.size() == 1) {
        panel.shapes.push_back(dot(poly[0], edge, 4.0));
        return;
    }
    if (dim == 1 || poly.size() == 2) {
        panel.shapes.push_back(polyline({poly.front(), poly.back()}, Stroke{edge, 3.0}));
        return;
    }
    Shape area;
    area.points = poly;
    area.closed = true;
    area.fill = Fill{fill, fill_alpha};
    panel.shapes.push_back(area);
    const double w = std::max(view_width(panel.view), view_height(panel.view));
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2& a = poly[i];
        const Vec2& b = poly[(i + 1) % poly.size()];
        const Vec2 out = side_of(a, b, panel.view);
        if (out == Vec2::Zero()) {
            panel.shapes.push_back(polyline({a, b}, Stroke{edge, 1.3}));
            continue;
        }
        Shape cue = polyline({(a + b) / 2.0 - 0.085 * w * out, (a + b) / 2.0 - 0.02 * w * out}, Stroke{edge, 1.4});
        cue.arrow_end = true;
        panel.shapes.push_back(cue);
    }
}

Text drawing::mark_for(const Region& region, const Box& view, const std::string& text, const Colour& colour,
             double along) {
    const std::vector<Vec2> poly = region.clipped(view);
    Text t;
    t.text = text;
    t.colour = colour;
    t.bold = true;
    t.size = 17.0;
    if (poly.size() >= 3) {
        t.at = centroid(poly);
    } else if (poly.size() == 2) {
        t.at = poly[0] + along * (poly[1] - poly[0]);
        const Vec2 d = (poly[1] - poly[0]).normalized();
        t.offset = 11.0 * Vec2(-d.y(), d.x());
    } else {
        t.at = poly[0];
        t.offset = Vec2(0.0, -16.0);
    }
    return t;
}

std::vector<Vec2> drawing::points_of(const ForcePanel& set) {
    const Labels labels(set.forces);
    std::vector<Vec2> points = set.anchors;
    add_points(points, labels.plus());
    add_points(points, labels.minus());
    const Region both = both_region(set.forces);
    add_points(points, both);
    if (dimension(both) == 1) points.push_back(both.vertices.front());
    return points;
}

Box fit_view(const std::vector<Vec2>& points, double pad) {
    if (points.empty()) return Box{};
    Vec2 lo = points.front(), hi = points.front();
    for (const Vec2& p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    double s = (hi - lo).maxCoeff();
    if (!(s > 0.0)) s = std::max(1.0, lo.cwiseAbs().maxCoeff());
    const Vec2 c = (lo + hi) / 2.0;
    const Vec2 half = (hi - lo).cwiseMax(Vec2(s / 2.0, s / 2.0)) / 2.0 + Vec2(pad * s, pad * s);
    return Box{c - half, c + half};
}

std::vector<LegendEntry> labels_legend() {
    return {{Fill{palette::kPlus, 1.0}, Stroke{palette::kPlusEdge, 1.3}, "+ : every force has moment \u2265 0 about the point"},
            {Fill{palette::kMinus, 1.0}, Stroke{palette::kMinusEdge, 1.3}, "\u2212 : every force has moment \u2264 0 about it"},
            {std::nullopt, Stroke{palette::kBoth, 3.0}, "\u00B1 : every force has moment 0 (+ and \u2212)"},
            {Fill{palette::kPaper, 1.0}, Stroke{palette::kGuide, 0.8}, "unlabelled: moments of both signs"},
            {std::nullopt, Stroke{palette::kInk, 1.6}, "forces of the set; dashed: a line of action"},
            {std::nullopt, Stroke{palette::kPlusEdge, 1.4}, "arrow at the edge: the region goes on"}};
}

Panel labels_panel(const ForcePanel& set, const Box& view) {
    Panel panel;
    panel.title = set.title;
    panel.view = view;
    const Labels labels(set.forces);
    const Region both = both_region(set.forces);
    const int both_dim = dimension(both);
    if (both_dim == 2) {  // F = {0}: every point is + and -
        draw_region(panel, both, palette::kBoth, palette::kBoth, 0.25);
    } else {
        draw_region(panel, labels.plus(), palette::kPlus, palette::kPlusEdge);
        draw_region(panel, labels.minus(), palette::kMinus, palette::kMinusEdge);
        if (both_dim >= 0) draw_region(panel, both, palette::kBoth, palette::kBoth);
    }
    draw_forces(panel, set, both);
    // Marks: a region that is just the +- set gets the +- mark only.
    const std::array<std::pair<const Region*, std::pair<std::string, Colour>>, 2> sheets = {
        {{&labels.plus(), {"+", palette::kPlusEdge}}, {&labels.minus(), {kMinusSign, palette::kMinusEdge}}}};
    for (const auto& [region, mark] : sheets) {
        const int dim = dimension(*region);
        if (dim < 0 || (dim == both_dim) || region->clipped(view).empty()) continue;
        panel.texts.push_back(mark_for(*region, view, mark.first, mark.second));
    }
    if (both_dim >= 0 && !both.clipped(view).empty()) {
        Text t = mark_for(both, view, kPlusMinus, palette::kBoth);
        if (both_dim == 2) t.offset = Vec2(0.0, 0.0);
        panel.texts.push_back(t);
    }
    return panel;
}

Figure labels_figure(const std::string& title, const std::vector<ForcePanel>& parts, bool intersect,
                     const Cone& combined, std::optional<Box> view) {
    std::vector<ForcePanel> panels = parts;
    if (parts.size() > 1) {
        std::vector<Vec2> anchors;
        for (const ForcePanel& p : parts) anchors.insert(anchors.end(), p.anchors.begin(), p.anchors.end());
        panels.push_back({intersect ? "intersection (hull of the labels)" : "sum: + \u2229 +, \u2212 \u2229 \u2212",
                          combined, anchors});
    }
    if (!view) {
        std::vector<Vec2> points;
        for (const ForcePanel& p : panels) {
            const std::vector<Vec2> more = points_of(p);
            points.insert(points.end(), more.begin(), more.end());
        }
        view = fit_view(points, 0.6);
    }
    Figure figure;
    figure.title = title;
    figure.columns = 3;
    for (const ForcePanel& p : panels) figure.panels.push_back(labels_panel(p, *view));
    figure.legend = labels_legend();
    return figure;
}

}  // namespace momentlab::render
