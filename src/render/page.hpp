#pragma once

// The page of a figure (figure.cpp lays it out, painter.cpp paints it with Cairo): its geometry
// in points, the legend's columns, the axes' ticks, texts as they can be shown, and the texts
// painted (for the SVG text layer).

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "momentlab/io/printable.hpp"
#include "momentlab/render/figure.hpp"

namespace momentlab::render::page {

// Page geometry, in points.
constexpr double kMargin = 16.0;
constexpr double kTitleHeight = 28.0;
constexpr double kPanelTitleHeight = 20.0;
constexpr double kGap = 22.0;
constexpr double kPanelSize = 320.0;  // the longer side of a panel's plot area
constexpr double kMinPanelSide = 60.0;
constexpr double kLegendLine = 14.0;
constexpr double kLegendText = 9.5;
constexpr double kLegendSwatch = 26.0;   // swatch and the space after it
constexpr double kLegendColumnGap = 18.0;
constexpr double kLegendMinWidth = 460.0;  // a narrow figure's legend may widen the page to two columns
// Axes: tick labels left of and below each panel.
constexpr double kAxisLeft = 30.0;
constexpr double kAxisBottom = 15.0;
constexpr double kTickText = 8.0;
constexpr double kTickLength = 3.5;
constexpr double kCaptionHeight = 15.0;
constexpr double kCaptionText = 9.5;
constexpr double kTitleText = 15.0;
constexpr double kPanelTitleText = 12.0;
constexpr char kFont[] = "DejaVu Sans";
// The largest pictures written: Cairo's image surfaces stop at 32767 pixels on a side (and a
// picture of 2^28 pixels is a gigabyte of memory); vector pages beyond 200,000 points (70 m)
// are a mistake, not a picture.
constexpr int kMaxPngSide = 32767;
constexpr double kMaxPngPixels = 268435456.0;
constexpr double kMaxVectorSide = 200000.0;

inline double text_width_estimate(const std::string& s, double size) {
    std::size_t chars = 0;
    for (unsigned char c : s) chars += (c & 0xC0) != 0x80;  // UTF-8 code points
    return 0.6 * size * static_cast<double>(chars);
}

// The legend's columns: entries fill them top to bottom, left to right.
struct LegendShape {
    std::size_t columns = 0;
    std::size_t rows = 0;
    double column_width = 0.0;
    [[nodiscard]] double width() const {
        return static_cast<double>(columns) * column_width + static_cast<double>(columns > 0 ? columns - 1 : 0) * kLegendColumnGap;
    }
};

inline LegendShape legend_shape(const std::vector<LegendEntry>& legend, double available) {
    LegendShape shape;
    if (legend.empty()) return shape;
    for (const LegendEntry& e : legend) {
        shape.column_width = std::max(shape.column_width, kLegendSwatch + text_width_estimate(e.text, kLegendText));
    }
    const double room = std::max(available, kLegendMinWidth);
    const auto fit = static_cast<std::size_t>((room + kLegendColumnGap) / (shape.column_width + kLegendColumnGap));
    shape.columns = std::clamp<std::size_t>(fit, 1, legend.size());
    shape.rows = (legend.size() + shape.columns - 1) / shape.columns;
    shape.columns = (legend.size() + shape.rows - 1) / shape.rows;  // no empty column
    return shape;
}

// Ticks of an axis from lo to hi: a step of 1, 2 or 5 times a power of ten, four to ten of them.
struct Ticks {
    double first = 0.0;
    double step = 1.0;
    int count = 0;
    int decimals = 0;
};

inline Ticks ticks(double lo, double hi) {
    Ticks t;
    const double span = hi - lo;
    if (!(span > 0.0) || !std::isfinite(span)) return t;
    const double raw = span / 5.0;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double norm = raw / magnitude;
    t.step = (norm < 1.5 ? 1.0 : norm < 3.5 ? 2.0 : norm < 7.5 ? 5.0 : 10.0) * magnitude;
    const double first = std::ceil(lo / t.step - 1e-9);
    const double last = std::floor(hi / t.step + 1e-9);
    t.first = first;
    t.count = static_cast<int>(std::min(50.0, std::max(0.0, last - first + 1.0)));
    t.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(t.step) + 1e-9)));
    return t;
}

// A tick's label: as few decimals as the step needs, the minus sign U+2212, no "-0".
inline std::string tick_label(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, std::abs(value));
    const bool zero = std::strspn(text, "0.") == std::strlen(text);
    return (value < 0.0 && !zero ? "\u2212" : "") + std::string(text);
}

struct FrameSize {
    double width;
    double height;
};

inline FrameSize frame_size(const Box& view) {
    const double w = view.max.x() - view.min.x(), h = view.max.y() - view.min.y();
    if (!(w > 0.0) || !(h > 0.0) || !std::isfinite(w) || !std::isfinite(h)) {
        throw std::invalid_argument("render: a panel's view must have positive finite width and height");
    }
    if (w >= h) return {kPanelSize, std::max(kMinPanelSide, kPanelSize * h / w)};
    return {std::max(kMinPanelSide, kPanelSize * w / h), kPanelSize};
}

inline std::string xml_escaped(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

// A text as painted: its baseline origin on the page, for the SVG text layer.
struct PaintedText {
    double x;
    double y;
    double size;
    bool bold;
    std::string text;
};

/// Paints the figure on `cr` as `layout` places it; the texts painted, in order.
[[nodiscard]] std::vector<PaintedText> paint(cairo_t* cr, const Layout& layout, const Figure& figure);

}  // namespace momentlab::render::page
