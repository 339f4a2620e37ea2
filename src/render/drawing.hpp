#pragma once

// What the picture builders of src/render share (label_pictures.cpp, scene_pictures.cpp, plan_pictures.cpp): marks, number
// formats and small shapes. Private to the render layer.

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "momentlab/render/pictures.hpp"

namespace momentlab::render::drawing {

inline constexpr char kMinusSign[] = "\u2212";
inline constexpr char kPlusMinus[] = "\u00B1";
inline constexpr char kCounterClockwise[] = "\u21BA";
inline constexpr char kClockwise[] = "\u21BB";

// 0 for a point, 1 for a segment / ray / line, 2 for a region with interior, -1 when empty.
inline int dimension(const Region& r) {
    const std::string k = r.kind();
    if (k == "empty") return -1;
    if (k == "point") return 0;
    if (k == "segment" || k == "ray" || k == "line") return 1;
    return 2;
}

inline std::string fmt(double x) {
    std::ostringstream s;
    s.precision(4);
    s << (x == 0.0 ? 0.0 : x);
    return s.str();
}

inline Colour darker(const Colour& c, double f) { return {c.r * f, c.g * f, c.b * f}; }


inline double view_width(const Box& v) { return v.max.x() - v.min.x(); }
inline double view_height(const Box& v) { return v.max.y() - v.min.y(); }
inline Vec2 view_centre(const Box& v) { return (v.min + v.max) / 2.0; }

inline Shape polyline(std::vector<Vec2> points, const Stroke& stroke) {
    Shape s;
    s.points = std::move(points);
    s.stroke = stroke;
    return s;
}

inline Shape dot(const Vec2& p, const Colour& colour, double radius) {
    Shape s;
    s.points = {p};
    s.fill = Fill{colour, 1.0};
    s.dot_radius = radius;
    return s;
}

// An angle in degrees, two decimals at most: "−63.43°", "0°".
inline std::string degrees_text(double radians) {
    const double d = std::round(radians * 18000.0 / M_PI) / 100.0;
    char digits[32];
    std::snprintf(digits, sizeof digits, "%.2f", std::abs(d));
    std::string text = digits;
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
    return (d < 0.0 ? kMinusSign : "") + text + "\u00B0";
}

inline std::string point_text(const Vec2& p) {
    auto coordinate = [](double x) { return (x < 0.0 ? std::string(kMinusSign) : std::string()) + fmt(std::abs(x)); };
    return "(" + coordinate(p.x()) + ", " + coordinate(p.y()) + ")";
}

inline Vec2 unit(double angle) { return Vec2(std::cos(angle), std::sin(angle)); }

// A panel's caption in the answer's colour.
inline void set_caption(Panel& panel, const std::string& text) {
    panel.caption = text;
    panel.caption_colour = darker(palette::kAnswer, 0.8);
}

/// Panels of force sets over a faint scene, three to a row, sharing one view (the scene's and
/// the sets' corners near it by default), with the labels' and the scene's legend.
Figure scene_sets_figure(const std::string& title, const Scene& scene, const std::vector<ForcePanel>& sets,
                         std::optional<Box> view);

// A rotation centre's mark: a cross of arms `arm` at c.
inline void rotation_cross(Panel& panel, const Vec2& c, double arm) {
    for (const Vec2& d : {Vec2(1.0, 1.0), Vec2(1.0, -1.0)}) {
        panel.shapes.push_back(polyline({c - arm * d, c + arm * d}, Stroke{palette::kAnswer, 2.0}));
    }
}

// Defined in label_pictures.cpp, used by the scene pictures too.
// The part of the line p + s u inside the box (Liang-Barsky), if any.
std::optional<std::array<Vec2, 2>> clip_line(const Vec2& p, const Vec2& u, const Box& box);
// A region of labels: filled (interior), stroked (segment, ray, line) or a dot (point); edges cut
// by the view are left open, with an arrow saying the region goes on.
void draw_region(Panel& panel, const Region& region, const Colour& fill, const Colour& edge, double fill_alpha = 1.0);
// Where a region's mark goes, with a page offset for regions without interior.
Text mark_for(const Region& region, const Box& view, const std::string& text, const Colour& colour, double along = 0.8);
// The points a force panel's view must hold.
std::vector<Vec2> points_of(const ForcePanel& set);

}  // namespace momentlab::render::drawing
