#pragma once

/// \file
/// A figure as a display list (panels of shapes and texts in world coordinates) and one Cairo
/// painter that writes it as SVG, PDF or PNG. Everything here is for looking at: coordinates
/// are rounded doubles and nothing is decided from them (docs/design.md, Robustness).

#include <optional>
#include <string>
#include <vector>

#include "momentlab/core/vec.hpp"
#include "momentlab/geometry/labels.hpp"

namespace momentlab::render {

/// An sRGB colour, each channel in [0, 1].
struct Colour {
    double r = 0.0;
    double g = 0.0;
    double b = 0.0;
};

/// The colours with a meaning; the legend, the docs and the pixel tests use them.
namespace palette {
inline constexpr Colour kPaper{1.0, 1.0, 1.0};          ///< unlabelled points
inline constexpr Colour kInk{0.12, 0.12, 0.14};         ///< forces, outlines, text
inline constexpr Colour kPlus{0.992, 0.773, 0.522};     ///< + regions (fill)
inline constexpr Colour kPlusEdge{0.851, 0.447, 0.043}; ///< + region edges, + marks
inline constexpr Colour kMinus{0.600, 0.784, 0.949};    ///< - regions (fill)
inline constexpr Colour kMinusEdge{0.129, 0.416, 0.710};///< - region edges, - marks
inline constexpr Colour kBoth{0.478, 0.110, 0.588};     ///< +- sets (lines, points)
inline constexpr Colour kBody{0.35, 0.35, 0.38};        ///< the moving body
inline constexpr Colour kObstacle{0.55, 0.55, 0.55};    ///< fixed polygons
inline constexpr Colour kFriction{0.180, 0.600, 0.310}; ///< friction cones at contacts
inline constexpr Colour kGuide{0.62, 0.62, 0.66};       ///< contact normals and tangents, panel frames
inline constexpr Colour kAxis{0.38, 0.38, 0.42};        ///< coordinates on the axes
inline constexpr Colour kAnswer{0.827, 0.106, 0.447};   ///< a plan's answer: its arcs, touch segments, best action
}  // namespace palette

/// How a shape's outline is drawn; widths in points (1/72 inch).
struct Stroke {
    Colour colour = palette::kInk;
    double width = 1.0;
    bool dashed = false;
    double alpha = 1.0;
};

/// How a closed shape is filled.
struct Fill {
    Colour colour = palette::kPaper;
    double alpha = 1.0;
};

/// A point, polyline or polygon in world coordinates. One point is drawn as a dot of
/// `dot_radius` points; an arrowhead can end a polyline (`arrow_end`) or start it (`arrow_start`).
struct Shape {
    std::vector<Vec2> points;
    bool closed = false;
    std::optional<Fill> fill;
    std::optional<Stroke> stroke;
    bool arrow_start = false;
    bool arrow_end = false;
    double dot_radius = 0.0;
};

/// A text centred at a world point, moved by `offset` points on the page (x right, y up).
struct Text {
    Vec2 at = Vec2::Zero();
    std::string text;
    double size = 11.0;
    Colour colour = palette::kInk;
    bool bold = false;
    Vec2 offset = Vec2::Zero();
};

/// One plot: a view of the plane (kept at equal scale in x and y), a title, what is drawn, and
/// a caption (one line below its axis; e.g. a plan's answer in words).
struct Panel {
    std::string title;
    Box view;
    std::vector<Shape> shapes;
    std::vector<Text> texts;
    std::string caption;
    Colour caption_colour = palette::kInk;
};

/// A line of the legend: a swatch (a filled square, or a stroke) and its meaning.
struct LegendEntry {
    std::optional<Fill> fill;
    std::optional<Stroke> stroke;
    std::string text;
};

/// Panels side by side (`columns` per row), each with its coordinates on the axes below and left
/// of it, a title above and a legend below, in as many columns as the page's width holds.
struct Figure {
    std::string title;
    std::vector<Panel> panels;
    std::size_t columns = 3;
    std::vector<LegendEntry> legend;
};

/// Where a figure's parts land on the page, in points with y down.
struct Layout {
    /// The plot area of one panel and its world-to-page scale (points per world unit).
    struct Frame {
        double x = 0.0;
        double y = 0.0;
        double width = 0.0;
        double height = 0.0;
        double scale = 1.0;
        Box view;
    };
    double width = 0.0;
    double height = 0.0;
    std::vector<Frame> panels;

    /// The page position of a world point in panel `panel`.
    [[nodiscard]] Vec2 to_page(std::size_t panel, const Vec2& world) const;
};

/// The page layout of a figure (the painter uses it; so do tests that sample pixels).
[[nodiscard]] Layout layout(const Figure& figure);

/// Output formats, chosen by the file name's extension.
enum class Format { Svg, Pdf, Png };

/// Pixels per point in PNG output.
inline constexpr double kPngScale = 2.0;

/// The format for `path` (".svg", ".pdf" or ".png", any case). Throws std::invalid_argument
/// naming the path for any other extension.
[[nodiscard]] Format format_for(const std::string& path);

/// The figure as the bytes of a file in `format`. SVG output also carries every text of the
/// figure as (transparent) SVG text over Cairo's glyph outlines, so it can be searched,
/// selected and read by tools. Throws std::runtime_error for a picture too large to write
/// (PNG: more than 32767 pixels on a side or 2^28 in all; SVG, PDF: 200,000 points on a side).
[[nodiscard]] std::string render(const Figure& figure, Format format);

/// Renders the figure into `path` (format from the extension). The file appears complete or
/// not at all: it is written to a new file of an unguessable name created exclusively in the
/// target's directory (mkstemp), then renamed over the target (a symbolic link there is
/// replaced, not followed). Throws std::invalid_argument for an
/// unknown extension and std::runtime_error when the file cannot be written.
void write(const Figure& figure, const std::string& path);

}  // namespace momentlab::render
