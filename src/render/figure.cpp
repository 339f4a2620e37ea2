#include "momentlab/render/figure.hpp"

#include "page.hpp"

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

using namespace page;

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
    svg.insert(open_end + 1, "\n<title>" + xml_escaped(printable(f.title)) + "</title>");
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
            cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE, printable(figure.title).c_str());
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
        texts = page::paint(cr.get(), page, figure);
        check(cairo_status(cr.get()));
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
