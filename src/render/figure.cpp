#include "momentlab/render/figure.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace momentlab::render {
namespace {

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

double text_width_estimate(const std::string& s, double size) {
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

LegendShape legend_shape(const std::vector<LegendEntry>& legend, double available) {
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

Ticks ticks(double lo, double hi) {
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
std::string tick_label(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, std::abs(value));
    const bool zero = std::strspn(text, "0.") == std::strlen(text);
    return (value < 0.0 && !zero ? "\u2212" : "") + std::string(text);
}

struct FrameSize {
    double width;
    double height;
};

FrameSize frame_size(const Box& view) {
    const double w = view.max.x() - view.min.x(), h = view.max.y() - view.min.y();
    if (!(w > 0.0) || !(h > 0.0) || !std::isfinite(w) || !std::isfinite(h)) {
        throw std::invalid_argument("render: a panel's view must have positive finite width and height");
    }
    if (w >= h) return {kPanelSize, std::max(kMinPanelSide, kPanelSize * h / w)};
    return {std::max(kMinPanelSide, kPanelSize * w / h), kPanelSize};
}

// A text as it can be shown: a control character (which XML 1.0 cannot hold and a font has no
// glyph for) as its escape \xNN, and a byte that is not part of valid UTF-8 (which Cairo
// refuses) as U+FFFD. Names and titles come from users' files and options.
std::string displayable(const std::string& s) {
    std::string out;
    const auto* p = reinterpret_cast<const unsigned char*>(s.data());
    const std::size_t n = s.size();
    for (std::size_t i = 0; i < n;) {
        const unsigned char c = p[i];
        if (c < 0x20 || c == 0x7F) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
            ++i;
            continue;
        }
        if (c < 0x80) {
            out += static_cast<char>(c);
            ++i;
            continue;
        }
        // The length of a well-formed UTF-8 sequence starting with c, and the range of its
        // second byte (no overlong forms, no surrogates, nothing above U+10FFFF).
        std::size_t len = 0;
        unsigned char lo = 0x80, hi = 0xBF;
        if (c >= 0xC2 && c <= 0xDF) len = 2;
        else if (c == 0xE0) len = 3, lo = 0xA0;
        else if (c >= 0xE1 && c <= 0xEC) len = 3;
        else if (c == 0xED) len = 3, hi = 0x9F;
        else if (c >= 0xEE && c <= 0xEF) len = 3;
        else if (c == 0xF0) len = 4, lo = 0x90;
        else if (c >= 0xF1 && c <= 0xF3) len = 4;
        else if (c == 0xF4) len = 4, hi = 0x8F;
        bool ok = len > 0 && i + len <= n && p[i + 1] >= lo && p[i + 1] <= hi;
        for (std::size_t k = 2; ok && k < len; ++k) ok = p[i + k] >= 0x80 && p[i + k] <= 0xBF;
        if (ok) {
            out.append(s, i, len);
            i += len;
        } else {
            out += "\xEF\xBF\xBD";
            ++i;
        }
    }
    return out;
}

std::string xml_escaped(const std::string& s) {
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

class Painter {
public:
    Painter(cairo_t* cr, const Layout& layout) : cr_(cr), layout_(layout) {}

    void figure(const Figure& f) {
        cairo_set_source_rgb(cr_, 1.0, 1.0, 1.0);
        cairo_paint(cr_);
        cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
        cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
        if (!f.title.empty()) {
            text_at(Vec2(layout_.width / 2.0, kMargin + kTitleHeight / 2.0), f.title, kTitleText, true,
                    palette::kInk);
        }
        for (std::size_t i = 0; i < f.panels.size(); ++i) panel(i, f.panels[i]);
        legend(f);
    }

    [[nodiscard]] const std::vector<PaintedText>& texts() const { return texts_; }

private:
    void set_colour(const Colour& c, double alpha) { cairo_set_source_rgba(cr_, c.r, c.g, c.b, alpha); }

    void panel(std::size_t index, const Panel& p) {
        const Layout::Frame& fr = layout_.panels[index];
        if (!p.title.empty()) {
            text_at(Vec2(fr.x + fr.width / 2.0, fr.y - kPanelTitleHeight / 2.0), p.title, kPanelTitleText, true,
                    palette::kInk);
        }
        cairo_save(cr_);
        cairo_rectangle(cr_, fr.x, fr.y, fr.width, fr.height);
        cairo_clip(cr_);
        for (const Shape& s : p.shapes) shape(index, s);
        for (const Text& t : p.texts) {
            const Vec2 at = layout_.to_page(index, t.at);
            text_at(Vec2(at.x() + t.offset.x(), at.y() - t.offset.y()), t.text, t.size, t.bold, t.colour);
        }
        cairo_restore(cr_);
        cairo_rectangle(cr_, fr.x, fr.y, fr.width, fr.height);
        set_colour(palette::kGuide, 1.0);
        cairo_set_line_width(cr_, 0.8);
        cairo_stroke(cr_);
        axes(index);
        if (!p.caption.empty()) {
            text_at(Vec2(fr.x + fr.width / 2.0, fr.y + fr.height + kAxisBottom + kCaptionHeight / 2.0), p.caption, kCaptionText,
                    true, p.caption_colour);
        }
    }

    // Coordinates: ticks and their values below the panel (x) and left of it (y), over the part
    // of the plane the frame shows.
    void axes(std::size_t index) {
        const Layout::Frame& fr = layout_.panels[index];
        const double x0 = fr.view.min.x(), x1 = x0 + fr.width / fr.scale;
        const double y1 = fr.view.max.y(), y0 = y1 - fr.height / fr.scale;
        const Ticks tx = ticks(x0, x1), ty = ticks(y0, y1);
        cairo_set_line_width(cr_, 0.8);
        set_colour(palette::kGuide, 1.0);
        for (int k = 0; k < tx.count; ++k) {
            const double v = (tx.first + k) * tx.step;
            const double px = fr.x + (v - x0) * fr.scale;
            cairo_move_to(cr_, px, fr.y + fr.height);
            cairo_line_to(cr_, px, fr.y + fr.height + kTickLength);
        }
        for (int k = 0; k < ty.count; ++k) {
            const double v = (ty.first + k) * ty.step;
            const double py = fr.y + (y1 - v) * fr.scale;
            cairo_move_to(cr_, fr.x - kTickLength, py);
            cairo_line_to(cr_, fr.x, py);
        }
        cairo_stroke(cr_);
        for (int k = 0; k < tx.count; ++k) {
            const double v = (tx.first + k) * tx.step;
            text_at(Vec2(fr.x + (v - x0) * fr.scale, fr.y + fr.height + kTickLength + 0.75 * kTickText),
                    tick_label(v, tx.decimals), kTickText, false, palette::kAxis);
        }
        for (int k = 0; k < ty.count; ++k) {
            const double v = (ty.first + k) * ty.step;
            text_right_of(fr.x - kTickLength - 2.0, fr.y + (y1 - v) * fr.scale, tick_label(v, ty.decimals), kTickText,
                          palette::kAxis);
        }
    }

    void shape(std::size_t panel_index, const Shape& s) {
        if (s.points.empty()) return;
        std::vector<Vec2> page;
        page.reserve(s.points.size());
        for (const Vec2& w : s.points) page.push_back(layout_.to_page(panel_index, w));
        if (page.size() == 1) {
            cairo_new_path(cr_);
            cairo_arc(cr_, page[0].x(), page[0].y(), std::max(s.dot_radius, 0.5), 0.0, 2.0 * M_PI);
            if (s.fill) {
                set_colour(s.fill->colour, s.fill->alpha);
                cairo_fill_preserve(cr_);
            }
            if (s.stroke) stroke(*s.stroke);
            cairo_new_path(cr_);
            return;
        }
        cairo_new_path(cr_);
        cairo_move_to(cr_, page[0].x(), page[0].y());
        for (std::size_t i = 1; i < page.size(); ++i) cairo_line_to(cr_, page[i].x(), page[i].y());
        if (s.closed) cairo_close_path(cr_);
        if (s.fill && s.closed) {
            set_colour(s.fill->colour, s.fill->alpha);
            cairo_fill_preserve(cr_);
        }
        if (s.stroke) stroke(*s.stroke);
        cairo_new_path(cr_);
        if (s.stroke && s.arrow_end) arrowhead(page[page.size() - 2], page.back(), *s.stroke);
        if (s.stroke && s.arrow_start) arrowhead(page[1], page[0], *s.stroke);
    }

    void stroke(const Stroke& st) {
        set_colour(st.colour, st.alpha);
        cairo_set_line_width(cr_, st.width);
        const double dashes[] = {5.0, 3.5};
        cairo_set_dash(cr_, dashes, st.dashed ? 2 : 0, 0.0);
        cairo_stroke_preserve(cr_);
        cairo_set_dash(cr_, nullptr, 0, 0.0);
    }

    // A filled triangle with its tip at `tip`, pointing away from `from` (page coordinates).
    void arrowhead(const Vec2& from, const Vec2& tip, const Stroke& st) {
        const Vec2 d = tip - from;
        const double length = d.norm();
        if (!(length > 0.0)) return;
        const Vec2 u = d / length, n(-u.y(), u.x());
        const double l = 7.0 + 1.5 * st.width, w = 2.8 + 0.8 * st.width;
        const Vec2 a = tip - l * u + w * n, b = tip - l * u - w * n;
        cairo_new_path(cr_);
        cairo_move_to(cr_, tip.x(), tip.y());
        cairo_line_to(cr_, a.x(), a.y());
        cairo_line_to(cr_, b.x(), b.y());
        cairo_close_path(cr_);
        set_colour(st.colour, st.alpha);
        cairo_fill(cr_);
    }

    // Text centred at a page point.
    void text_at(const Vec2& centre, const std::string& raw, double size, bool bold, const Colour& colour) {
        if (raw.empty()) return;
        const std::string text = displayable(raw);
        cairo_select_font_face(cr_, kFont, CAIRO_FONT_SLANT_NORMAL,
                               bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr_, size);
        cairo_text_extents_t e;
        cairo_text_extents(cr_, text.c_str(), &e);
        const double x = centre.x() - (e.x_bearing + e.width / 2.0);
        const double y = centre.y() - (e.y_bearing + e.height / 2.0);
        text_from(x, y, text, size, bold, colour);
    }

    // Text ending at x, centred vertically on y.
    void text_right_of(double x, double y, const std::string& raw, double size, const Colour& colour) {
        const std::string text = displayable(raw);
        cairo_select_font_face(cr_, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr_, size);
        cairo_text_extents_t e;
        cairo_text_extents(cr_, text.c_str(), &e);
        text_from(x - e.x_advance, y - (e.y_bearing + e.height / 2.0), text, size, false, colour);
    }

    // Text with its baseline starting at (x, y).
    void text_from(double x, double y, const std::string& raw, double size, bool bold, const Colour& colour) {
        const std::string text = displayable(raw);
        cairo_select_font_face(cr_, kFont, CAIRO_FONT_SLANT_NORMAL,
                               bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr_, size);
        set_colour(colour, 1.0);
        cairo_move_to(cr_, x, y);
        cairo_show_text(cr_, text.c_str());
        cairo_new_path(cr_);
        texts_.push_back({x, y, size, bold, text});
    }

    // The legend below the panels, in columns filled top to bottom, centred.
    void legend(const Figure& f) {
        if (f.legend.empty()) return;
        const LegendShape shape = legend_shape(f.legend, layout_.width - 2.0 * kMargin);
        const double top = layout_.height - kMargin - kLegendLine * static_cast<double>(shape.rows);
        const double left = (layout_.width - shape.width()) / 2.0;
        for (std::size_t i = 0; i < f.legend.size(); ++i) {
            const LegendEntry& e = f.legend[i];
            const double x = left + static_cast<double>(i / shape.rows) * (shape.column_width + kLegendColumnGap);
            const double mid = top + (static_cast<double>(i % shape.rows) + 0.5) * kLegendLine;
            if (e.fill) {
                cairo_rectangle(cr_, x, mid - 5.0, 20.0, 10.0);
                set_colour(e.fill->colour, e.fill->alpha);
                cairo_fill_preserve(cr_);
                if (e.stroke) {
                    stroke(*e.stroke);
                }
                cairo_new_path(cr_);
            } else if (e.stroke) {
                cairo_move_to(cr_, x, mid);
                cairo_line_to(cr_, x + 20.0, mid);
                stroke(*e.stroke);
                cairo_new_path(cr_);
            }
            text_from(x + kLegendSwatch, mid + kLegendText * 0.36, e.text, kLegendText, false, palette::kInk);
        }
    }

    cairo_t* cr_;
    const Layout& layout_;
    std::vector<PaintedText> texts_;
};

cairo_status_t append_to_string(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

void check(cairo_status_t status) {
    if (status != CAIRO_STATUS_SUCCESS) {
        throw std::runtime_error(std::string("render: cairo: ") + cairo_status_to_string(status));
    }
}

// The SVG with a title and the figure's texts as transparent SVG text over the glyphs.
std::string with_text_layer(std::string svg, const Figure& f, const std::vector<PaintedText>& texts) {
    std::string layer = "<g id=\"momentlab-text\" fill=\"#000\" fill-opacity=\"0\" stroke=\"none\">\n";
    for (const PaintedText& t : texts) {
        char pos[96];
        std::snprintf(pos, sizeof pos, "x=\"%.3f\" y=\"%.3f\" font-size=\"%.2f\"", t.x, t.y, t.size);
        layer += std::string("<text ") + pos + " font-family=\"" + kFont + "\"" +
                 (t.bold ? " font-weight=\"bold\"" : "") + ">" + xml_escaped(t.text) + "</text>\n";
    }
    layer += "</g>\n";
    const std::size_t end = svg.rfind("</svg>");
    if (end == std::string::npos) throw std::runtime_error("render: cairo wrote no SVG end tag");
    svg.insert(end, layer);
    const std::size_t open = svg.find("<svg");
    const std::size_t open_end = open == std::string::npos ? open : svg.find('>', open);
    if (open_end == std::string::npos) throw std::runtime_error("render: cairo wrote no SVG start tag");
    svg.insert(open_end + 1, "\n<title>" + xml_escaped(displayable(f.title)) + "</title>");
    return svg;
}

}  // namespace

Vec2 Layout::to_page(std::size_t panel, const Vec2& world) const {
    const Frame& f = panels.at(panel);
    return Vec2(f.x + (world.x() - f.view.min.x()) * f.scale, f.y + (f.view.max.y() - world.y()) * f.scale);
}

Layout layout(const Figure& figure) {
    Layout out;
    const std::size_t n = figure.panels.size();
    const std::size_t columns = std::max<std::size_t>(1, std::min(figure.columns, std::max<std::size_t>(n, 1)));
    const std::size_t rows = (n + columns - 1) / columns;
    double cell_w = 0.0, cell_h = 0.0;
    std::vector<FrameSize> sizes;
    for (const Panel& p : figure.panels) {
        sizes.push_back(frame_size(p.view));
        cell_w = std::max(cell_w, sizes.back().width);
        cell_h = std::max(cell_h, sizes.back().height);
    }
    const double top = kMargin + (figure.title.empty() ? 0.0 : kTitleHeight);
    cell_w += kAxisLeft;
    cell_h += kAxisBottom;
    const bool captions = std::any_of(figure.panels.begin(), figure.panels.end(), [](const Panel& p) { return !p.caption.empty(); });
    double caption_w = 0.0;
    for (const Panel& p : figure.panels) caption_w = std::max(caption_w, text_width_estimate(p.caption, kCaptionText));
    cell_w = std::max(cell_w, kAxisLeft + caption_w);
    if (captions) cell_h += kCaptionHeight;
    const double grid_w = static_cast<double>(columns) * cell_w + static_cast<double>(columns - 1) * kGap;
    const double title_w = text_width_estimate(figure.title, kTitleText);
    const double content_w = std::max({grid_w, title_w, 120.0});
    const LegendShape legend = legend_shape(figure.legend, content_w);
    out.width = 2.0 * kMargin + std::max(content_w, legend.width());
    const double row_h = kPanelTitleHeight + cell_h;
    const double grid_h = static_cast<double>(rows) * row_h + static_cast<double>(rows > 0 ? rows - 1 : 0) * kGap;
    const double legend_h = figure.legend.empty() ? 0.0 : kGap / 2.0 + kLegendLine * static_cast<double>(legend.rows);
    out.height = top + grid_h + legend_h + kMargin;
    const double grid_x = (out.width - grid_w) / 2.0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t r = i / columns, c = i % columns;
        Layout::Frame f;
        f.view = figure.panels[i].view;
        f.width = sizes[i].width;
        f.height = sizes[i].height;
        f.scale = std::min(f.width / (f.view.max.x() - f.view.min.x()), f.height / (f.view.max.y() - f.view.min.y()));
        f.x = grid_x + static_cast<double>(c) * (cell_w + kGap) + kAxisLeft + (cell_w - kAxisLeft - f.width) / 2.0;
        const double below = kAxisBottom + (captions ? kCaptionHeight : 0.0);
        f.y = top + static_cast<double>(r) * (row_h + kGap) + kPanelTitleHeight + (cell_h - below - f.height) / 2.0;
        out.panels.push_back(f);
    }
    return out;
}

Format format_for(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".svg") return Format::Svg;
    if (ext == ".pdf") return Format::Pdf;
    if (ext == ".png") return Format::Png;
    throw std::invalid_argument("cannot tell the format of \"" + path + "\": expected a name ending in .svg, .pdf or .png");
}

std::string render(const Figure& figure, Format format) {
    const Layout page = layout(figure);
    std::string bytes;
    SurfacePtr surface(nullptr, cairo_surface_destroy);
    switch (format) {
        case Format::Svg:
            if (!(page.width <= kMaxVectorSide && page.height <= kMaxVectorSide)) {
                throw std::runtime_error("the picture would be larger than " + std::to_string(static_cast<int>(kMaxVectorSide)) +
                                         " points on a side: draw fewer panels");
            }
            surface.reset(cairo_svg_surface_create_for_stream(append_to_string, &bytes, page.width, page.height));
            break;
        case Format::Pdf:
            if (!(page.width <= kMaxVectorSide && page.height <= kMaxVectorSide)) {
                throw std::runtime_error("the picture would be larger than " + std::to_string(static_cast<int>(kMaxVectorSide)) +
                                         " points on a side: draw fewer panels");
            }
            surface.reset(cairo_pdf_surface_create_for_stream(append_to_string, &bytes, page.width, page.height));
            cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE, displayable(figure.title).c_str());
            cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "momentlab");
            break;
        case Format::Png: {
            const double w = std::ceil(page.width * kPngScale), h = std::ceil(page.height * kPngScale);
            if (!(w <= kMaxPngSide && h <= kMaxPngSide && w * h <= kMaxPngPixels)) {
                char text[200];
                std::snprintf(text, sizeof text,
                              "the picture would be %.0f x %.0f pixels (at most %d on a side and %.0f in all): draw "
                              "fewer panels, or write .svg or .pdf",
                              w, h, kMaxPngSide, kMaxPngPixels);
                throw std::runtime_error(text);
            }
            surface.reset(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(w), static_cast<int>(h)));
            break;
        }
    }
    check(cairo_surface_status(surface.get()));
    std::vector<PaintedText> texts;
    {
        ContextPtr cr(cairo_create(surface.get()), cairo_destroy);
        if (format == Format::Png) cairo_scale(cr.get(), kPngScale, kPngScale);
        Painter painter(cr.get(), page);
        painter.figure(figure);
        check(cairo_status(cr.get()));
        texts = painter.texts();
    }
    if (format == Format::Png) check(cairo_surface_write_to_png_stream(surface.get(), append_to_string, &bytes));
    cairo_surface_finish(surface.get());
    check(cairo_surface_status(surface.get()));
    if (format == Format::Svg) return with_text_layer(std::move(bytes), figure, texts);
    return bytes;
}

void write(const Figure& figure, const std::string& path) {
    const std::string bytes = render(figure, format_for(path));
    // A new file with a name nobody can guess, created exclusively (mkstemp: O_CREAT | O_EXCL,
    // mode 0600) in the target's directory, then renamed over the target: a symbolic link
    // planted anywhere cannot redirect the write, and a reader never sees half a picture.
    const std::filesystem::path target(path);
    const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
    std::string temp = (dir / ".momentlab-XXXXXX").string();
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) throw std::runtime_error("cannot write \"" + path + "\" (" + std::strerror(errno) + ")");
    const mode_t mask = ::umask(0);
    ::umask(mask);
    bool ok = ::fchmod(fd, 0666 & ~mask) == 0;
    for (std::size_t done = 0; ok && done < bytes.size();) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        ok = n > 0;
        if (ok) done += static_cast<std::size_t>(n);
    }
    const int error = ok ? 0 : errno;
    if (::close(fd) != 0 && ok) ok = false;
    if (ok && ::rename(temp.c_str(), path.c_str()) != 0) ok = false;
    if (!ok) {
        const std::string why = std::strerror(error != 0 ? error : errno);
        ::unlink(temp.c_str());
        throw std::runtime_error("cannot write \"" + path + "\" (" + why + ")");
    }
}

}  // namespace momentlab::render
