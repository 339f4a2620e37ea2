// Painting a laid-out figure with Cairo (page.hpp): panels with their axes, display lists,
// captions and the legend; every text recorded for the SVG text layer.
#include "page.hpp"

namespace momentlab::render::page {
namespace {

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
        const std::string text = printable(raw);
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
        const std::string text = printable(raw);
        cairo_select_font_face(cr_, kFont, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr_, size);
        cairo_text_extents_t e;
        cairo_text_extents(cr_, text.c_str(), &e);
        text_from(x - e.x_advance, y - (e.y_bearing + e.height / 2.0), text, size, false, colour);
    }

    // Text with its baseline starting at (x, y).
    void text_from(double x, double y, const std::string& raw, double size, bool bold, const Colour& colour) {
        const std::string text = printable(raw);
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

}  // namespace

std::vector<PaintedText> paint(cairo_t* cr, const Layout& layout, const Figure& figure) {
    Painter painter(cr, layout);
    painter.figure(figure);
    return painter.texts();
}

}  // namespace momentlab::render::page
