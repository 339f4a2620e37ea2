// The pictures: SVG parsed for what it must contain, PNG pixels sampled against the definition of
// the labels (Mason 1991, section 2: + where every force has moment >= 0 about the point, - where
// every force has moment <= 0), computed here from the forces by hand, not by the labels code.
#include <cairo.h>
#include <gtest/gtest.h>

#include "../common/examples.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "momentlab/geometry/force_sets.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/planning/comply.hpp"
#include "momentlab/planning/push.hpp"
#include "momentlab/planning/tilt.hpp"
#include "momentlab/render/figure.hpp"
#include "momentlab/render/pictures.hpp"

namespace momentlab::render {
namespace {

// ---------------------------------------------------------------- the oracle: labels by definition

// A force f acting at p; its moment about x is (p - x) x f.
struct Force {
    Vec2 p;
    Vec2 f;
    [[nodiscard]] double moment_about(const Vec2& x) const { return cross2(p - x, f); }
    // Distance of x from the line of action.
    [[nodiscard]] double distance(const Vec2& x) const { return std::abs(moment_about(x)) / f.norm(); }
};

enum class Expected { Plus, Minus, None };

// The label of x for the positive combinations of `forces` (their extreme forces suffice).
Expected label_by_definition(const std::vector<Force>& forces, const Vec2& x) {
    bool all_pos = true, all_neg = true;
    for (const Force& f : forces) {
        const double m = f.moment_about(x);
        all_pos = all_pos && m > 0;
        all_neg = all_neg && m < 0;
    }
    return all_pos ? Expected::Plus : (all_neg ? Expected::Minus : Expected::None);
}

// Coulomb cone edges n +- mu t, t = (n.y, -n.x) (docs/design.md, Conventions).
std::vector<Force> cone_edges(const Vec2& p, const Vec2& n, double mu) {
    const Vec2 t(n.y(), -n.x());
    return {{p, n + mu * t}, {p, n - mu * t}};
}

// ---------------------------------------------------------------- PNG pixels

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> pixels;  // ARGB32, premultiplied (opaque here)

    [[nodiscard]] std::array<int, 3> at(const Vec2& page_pt) const {
        const int x = static_cast<int>(std::floor(page_pt.x() * kPngScale));
        const int y = static_cast<int>(std::floor(page_pt.y() * kPngScale));
        EXPECT_TRUE(x >= 0 && y >= 0 && x < width && y < height);
        const std::uint32_t v = pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
        return {static_cast<int>((v >> 16) & 0xFF), static_cast<int>((v >> 8) & 0xFF), static_cast<int>(v & 0xFF)};
    }
};

struct Reader {
    const std::string* bytes;
    std::size_t offset = 0;
};

cairo_status_t read_bytes(void* closure, unsigned char* data, unsigned int length) {
    auto* r = static_cast<Reader*>(closure);
    if (r->offset + length > r->bytes->size()) return CAIRO_STATUS_READ_ERROR;
    std::copy_n(r->bytes->data() + r->offset, length, data);
    r->offset += length;
    return CAIRO_STATUS_SUCCESS;
}

Image decode_png(const std::string& png) {
    Reader reader{&png};
    cairo_surface_t* s = cairo_image_surface_create_from_png_stream(read_bytes, &reader);
    EXPECT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
    Image img;
    img.width = cairo_image_surface_get_width(s);
    img.height = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    for (int y = 0; y < img.height; ++y) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
        img.pixels.insert(img.pixels.end(), row, row + img.width);
    }
    cairo_surface_destroy(s);
    return img;
}

std::array<int, 3> bytes_of(const Colour& c) {
    return {static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)),
            static_cast<int>(std::lround(c.b * 255))};
}

bool same(const std::array<int, 3>& a, const Colour& c) {
    const auto b = bytes_of(c);
    for (int k = 0; k < 3; ++k) {
        if (std::abs(a[k] - b[k]) > 2) return false;
    }
    return true;
}

const Colour& colour_of(Expected e) {
    return e == Expected::Plus ? palette::kPlus : (e == Expected::Minus ? palette::kMinus : palette::kPaper);
}

// What a grid of samples over one panel showed: points farther than 10 pt from every line of
// action, how many show their label's fill, how many show another label's fill, and how many
// of each label the grid met.
struct FillCheck {
    int sampled = 0;
    int right = 0;
    int wrong = 0;
    std::array<int, 3> seen = {0, 0, 0};
};

std::vector<FillCheck> sample_fills(const Figure& figure, const std::vector<std::vector<Force>>& panel_forces) {
    const Image img = decode_png(render(figure, Format::Png));
    const Layout page = layout(figure);
    const Colour* fills[] = {&palette::kPlus, &palette::kMinus, &palette::kPaper};
    std::vector<FillCheck> out;
    for (std::size_t k = 0; k < figure.panels.size(); ++k) {
        const Box& v = figure.panels[k].view;
        const double margin = 10.0 / page.panels[k].scale;  // 10 pt in world units
        FillCheck c;
        for (int i = 1; i < 30; ++i) {
            for (int j = 1; j < 30; ++j) {
                const Vec2 x(v.min.x() + (v.max.x() - v.min.x()) * i / 30.0, v.min.y() + (v.max.y() - v.min.y()) * j / 30.0);
                bool near = false;
                for (const Force& f : panel_forces.at(k)) near = near || f.distance(x) < margin;
                if (near) continue;
                const Expected e = label_by_definition(panel_forces[k], x);
                const auto got = img.at(page.to_page(k, x));
                ++c.sampled;
                ++c.seen[static_cast<std::size_t>(e)];
                if (same(got, colour_of(e))) ++c.right;
                for (const Colour* other : fills) {
                    if (other != &colour_of(e) && same(got, *other)) ++c.wrong;
                }
            }
        }
        out.push_back(c);
    }
    return out;
}

// No sample shows a wrong label's fill; nearly all show the right one (marks, arrows and the
// cues at the view's edge cover a few); the grid meets +, - and unlabelled points.
void check_fills(const Figure& figure, const std::vector<std::vector<Force>>& panel_forces) {
    ASSERT_EQ(figure.panels.size(), panel_forces.size());
    const std::vector<FillCheck> checks = sample_fills(figure, panel_forces);
    for (std::size_t k = 0; k < checks.size(); ++k) {
        const FillCheck& c = checks[k];
        EXPECT_EQ(c.wrong, 0) << "panel " << k;
        EXPECT_GT(c.sampled, 300) << "panel " << k;
        EXPECT_GE(c.right, static_cast<int>(0.95 * c.sampled)) << "panel " << k;
        for (int n : c.seen) EXPECT_GT(n, 10) << "panel " << k << ": the grid must meet +, - and unlabelled points";
    }
}

ForcePanel panel_of(const std::string& title, Cone forces) { return {title, std::move(forces), {}}; }

// ---------------------------------------------------------------- PNG: Figures 1 and 2

TEST(Pictures, Figure1aFillsMatchTheDefinitionAndTheLineIsPlusMinus) {
    const Cone f = force_ray(Vec2(0, 0), Vec2(1, 0));
    const Box view{Vec2(-3, -3), Vec2(3, 3)};
    const Figure fig = labels_figure("1a", {panel_of("F", f)}, false, f, view);
    const Image img = decode_png(render(fig, Format::Png));
    const Layout page = layout(fig);
    // Left of the directed line is +, right is - (the paper's Figure 1a caption); on it, both.
    EXPECT_TRUE(same(img.at(page.to_page(0, Vec2(-1.5, 1.0))), palette::kPlus));
    EXPECT_TRUE(same(img.at(page.to_page(0, Vec2(1.5, -1.0))), palette::kMinus));
    EXPECT_TRUE(same(img.at(page.to_page(0, Vec2(-0.9, 0.0))), palette::kBoth));
    EXPECT_TRUE(same(img.at(page.to_page(0, Vec2(2.4, 2.4))), palette::kPlus));
    EXPECT_TRUE(same(img.at(page.to_page(0, Vec2(-2.4, -2.4))), palette::kMinus));
}

TEST(Pictures, Figure1bIsOnePlusMinusPointAndNothingElse) {
    const Cone f = forces_through_point(Vec2(1, 2));
    const Box view{Vec2(-1, 0), Vec2(3, 4)};
    const Figure fig = labels_figure("1b", {panel_of("F", f)}, false, f, view);
    const Image img = decode_png(render(fig, Format::Png));
    const Layout page = layout(fig);
    // A point 2 pt below (1, 2): inside the 4 pt dot, clear of the arrows along x = 1 and y = 2.
    EXPECT_TRUE(same(img.at(page.to_page(0, Vec2(1, 2)) + Vec2(1.5, 1.5)), palette::kBoth));
    for (const Vec2& x : {Vec2(0, 0.5), Vec2(2.5, 0.5), Vec2(-0.5, 3.5), Vec2(2.5, 3.5), Vec2(0, 3)}) {
        EXPECT_TRUE(same(img.at(page.to_page(0, x)), palette::kPaper)) << x.transpose();
    }
}

TEST(Pictures, Figure1cFillsMatchTheDefinition) {
    const Cone f = friction_cone(Vec2(0, 0), Vec2(0, 1), 0.5);
    const Box view{Vec2(-2, -2), Vec2(2, 2)};
    const Figure fig = labels_figure("1c", {panel_of("F", f)}, false, f, view);
    check_fills(fig, {cone_edges(Vec2(0, 0), Vec2(0, 1), 0.5)});
    // The apex is in both sets; 1.5 pt below it is inside the dot and clear of the arrows.
    const Image img = decode_png(render(fig, Format::Png));
    EXPECT_TRUE(same(img.at(layout(fig).to_page(0, Vec2(0, 0)) + Vec2(0.0, 1.5)), palette::kBoth));
}

TEST(Pictures, Figure2EachConeAndTheirSumMatchTheDefinition) {
    const Vec2 p1(0, 0), n1(0, 1), p2(2, 0), n2(-1, 1);
    const Cone c1 = friction_cone(p1, n1, 0.5), c2 = friction_cone(p2, n2, 0.5);
    const Box view{Vec2(-2.5, -2), Vec2(4.5, 4)};
    const Figure fig = labels_figure("2", {panel_of("F1", c1), panel_of("F2", c2)}, false, sum(c1, c2), view);
    std::vector<Force> both = cone_edges(p1, n1, 0.5);
    for (const Force& f : cone_edges(p2, n2, 0.5)) both.push_back(f);
    check_fills(fig, {cone_edges(p1, n1, 0.5), cone_edges(p2, n2, 0.5), both});
}

TEST(Pictures, AWrongFillWouldBeCaught) {
    // The fill check can fail: the labels of the cone drawn for the forces of its negation.
    const Cone f = friction_cone(Vec2(0, 0), Vec2(0, 1), 0.5);
    const Figure fig = labels_figure("1c", {panel_of("F", f.negated())}, false, f.negated(),
                                     Box{Vec2(-2, -2), Vec2(2, 2)});
    const std::vector<FillCheck> checks = sample_fills(fig, {cone_edges(Vec2(0, 0), Vec2(0, 1), 0.5)});
    EXPECT_GT(checks.at(0).wrong, 100);
}

// ---------------------------------------------------------------- SVG: what it must contain

struct Svg {
    std::string text;

    // Filled shapes without a stroke in exactly this colour (regions, dots, arrowheads).
    [[nodiscard]] int fills(const Colour& c) const {
        char want[96];
        std::snprintf(want, sizeof want, "stroke:none;fill-rule:nonzero;fill:rgb(%g%%,%g%%,%g%%)",
                      std::round(c.r * 1000) / 10, std::round(c.g * 1000) / 10, std::round(c.b * 1000) / 10);
        int n = 0;
        for (std::size_t at = text.find(want); at != std::string::npos; at = text.find(want, at + 1)) ++n;
        return n;
    }
    // The texts of the searchable text layer.
    [[nodiscard]] std::vector<std::string> texts() const {
        std::vector<std::string> out;
        const std::regex t("<text [^>]*>([^<]*)</text>");
        for (auto it = std::sregex_iterator(text.begin(), text.end(), t); it != std::sregex_iterator(); ++it) {
            out.push_back((*it)[1]);
        }
        return out;
    }
    [[nodiscard]] int count_text(const std::string& s) const {
        int n = 0;
        for (const std::string& t : texts()) n += t == s;
        return n;
    }
    [[nodiscard]] bool has_text_containing(const std::string& s) const {
        for (const std::string& t : texts()) {
            if (t.find(s) != std::string::npos) return true;
        }
        return false;
    }
    [[nodiscard]] int glyphs() const {
        int n = 0;
        for (std::size_t at = text.find("<use xlink:href=\"#glyph"); at != std::string::npos;
             at = text.find("<use xlink:href=\"#glyph", at + 1)) {
            ++n;
        }
        return n;
    }
};

int non_space_characters(const std::vector<std::string>& texts) {
    int n = 0;
    for (const std::string& t : texts) {
        for (unsigned char c : t) n += c != ' ' && (c & 0xC0) != 0x80;
    }
    return n;
}

const char* const kMinus = "\u2212";
const char* const kPlusMinus = "\u00B1";

TEST(Svg, Figure1cHasOnePlusOneMinusRegionAndOnePlusMinusPoint) {
    const Cone f = friction_cone(Vec2(0, 0), Vec2(0, 1), 0.5);
    const Svg svg{render(labels_figure("Figure 1c", {panel_of("F", f)}, false, f), Format::Svg)};
    EXPECT_EQ(svg.fills(palette::kPlus), 1);
    EXPECT_EQ(svg.fills(palette::kMinus), 1);
    EXPECT_EQ(svg.fills(palette::kBoth), 1);  // the apex
    EXPECT_EQ(svg.count_text("+"), 1);
    EXPECT_EQ(svg.count_text(kMinus), 1);
    EXPECT_EQ(svg.count_text(kPlusMinus), 1);
    EXPECT_TRUE(svg.has_text_containing("Figure 1c"));
    // The texts were drawn, not only listed: Cairo writes one glyph per visible character.
    EXPECT_GE(svg.glyphs(), non_space_characters(svg.texts()));
}

TEST(Svg, Figure2HasThreePanelsEachWithPlusAndMinusAndTwoApexes) {
    const Cone c1 = friction_cone(Vec2(0, 0), Vec2(0, 1), 0.5), c2 = friction_cone(Vec2(2, 0), Vec2(-1, 1), 0.5);
    const Svg svg{render(labels_figure("Figure 2", {panel_of("F1", c1), panel_of("F2", c2)}, false, sum(c1, c2)),
                         Format::Svg)};
    EXPECT_EQ(svg.fills(palette::kPlus), 3);
    EXPECT_EQ(svg.fills(palette::kMinus), 3);
    EXPECT_EQ(svg.fills(palette::kBoth), 2);  // each cone's apex; the sum spans R^3, so none
    EXPECT_EQ(svg.count_text("+"), 3);
    EXPECT_EQ(svg.count_text(kMinus), 3);
    EXPECT_EQ(svg.count_text(kPlusMinus), 2);
}

TEST(Svg, Figure1aLineOfForceIsPlusMinusAndTheHalfPlanesGoOn) {
    const Cone f = force_ray(Vec2(0, 0), Vec2(1, 0));
    const Svg svg{render(labels_figure("Figure 1a", {panel_of("F", f)}, false, f), Format::Svg)};
    EXPECT_EQ(svg.fills(palette::kPlus), 1);
    EXPECT_EQ(svg.fills(palette::kMinus), 1);
    EXPECT_EQ(svg.count_text(kPlusMinus), 1);
    // Each half-plane is cut by the view on three sides: three arrowheads in its edge colour.
    EXPECT_EQ(svg.fills(palette::kPlusEdge), 3);
    EXPECT_EQ(svg.fills(palette::kMinusEdge), 3);
}

Scene example(const std::string& name) { return testing::example_scene(name); }

TEST(Svg, ModesOfTheBlockAlongTheWallAreAllNamed) {
    // Two contacts on one flat wall (Brost and Mason 1989): ff and ss; each contact fixed,
    // sliding either way or separating while the other separates (fs, rs, ls, sf, sr, sl); both
    // sliding together (rr, ll). Ten modes.
    const Svg svg{render(modes_figure("modes", example("figure-3-block-along-wall.json")), Format::Svg)};
    for (const char* m : {"ff", "ss", "fs", "rs", "ls", "sf", "sr", "sl", "rr", "ll"}) {
        EXPECT_TRUE(svg.has_text_containing(std::string(m) + ":")) << m << " in the legend";
    }
    // Separating about a centre left of the block turns it counter-clockwise, right of it
    // clockwise; both regions are drawn and marked.
    EXPECT_EQ(svg.count_text("ss \u21BA"), 1);
    EXPECT_EQ(svg.count_text("ss \u21BB"), 1);
    // Sliding together is a translation (no finite centre), so rr and ll are legend-only.
    EXPECT_EQ(svg.count_text("rr \u21BA") + svg.count_text("rr \u21BB"), 0);
    EXPECT_TRUE(svg.has_text_containing("rr: translation along (1, 0)"));
    // Translations come from the mode's own twists (vx, vy, omega) with omega = 0. Contacts at
    // (0, 0) and (1, 0), normal +y: contact j separates when vy + omega x_j > 0 and slides
    // right (r) when vy + omega x_j = 0 and vx > 0. ss: vy > 0, vy + omega > 0, so the
    // translations are those with vy > 0: the cone of (0, 1) and +-(1, 0) without its edge.
    // rs: vy = 0, vx > 0 and omega > 0; sr: vy + omega = 0, vy > 0, so omega < 0; fs, sf, ls,
    // sl likewise turn: none of them translates (the legend listed +-(1, 0) for ss and some
    // for rs, sr: the rays with omega = 0 of the closed cone, on its boundary).
    bool ss_said = false;
    for (const std::string& t : svg.texts()) {
        if (t.rfind("ss:", 0) == 0) {
            ss_said = true;
            EXPECT_TRUE(t.find("translations in cone{(0, 1), \u00B1(1, 0)}") != std::string::npos ||
                        t.find("translations in cone{(0, 1), \u00B1(-1, 0)}") != std::string::npos) << t;
        }
        for (const char* m : {"fs:", "rs:", "ls:", "sf:", "sr:", "sl:", "ff:"}) {
            if (t.rfind(m, 0) == 0) {
                EXPECT_EQ(t.find("translation"), std::string::npos) << t;
            }
        }
    }
    EXPECT_TRUE(ss_said);
}

TEST(Svg, Figure3PanelsAreTotalContactAppliedForModeRr) {
    const Scene scene = example("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    std::size_t rr = analysis.size();
    for (std::size_t i = 0; i < analysis.size(); ++i) {
        if (analysis[i].mode.letters == "rr") rr = i;
    }
    ASSERT_LT(rr, analysis.size());
    const Svg svg{render(forces_figure("Figure 3", scene, analysis, {rr}), Format::Svg)};
    EXPECT_EQ(svg.count_text("F total (rr)"), 1);
    EXPECT_EQ(svg.count_text("T contact (rr)"), 1);
    EXPECT_EQ(svg.count_text("E applied (rr)"), 1);
    // F: a line through the centre of mass (a +- line), + above, - below; T: two lines of
    // force through the contacts, + and - wedges; E: + and - regions. Each panel one of each.
    EXPECT_EQ(svg.fills(palette::kPlus), 3);
    EXPECT_EQ(svg.fills(palette::kMinus), 3);
    EXPECT_EQ(svg.count_text("+"), 3);
    EXPECT_EQ(svg.count_text(kMinus), 3);
}

// ---------------------------------------------------------------- axes, legend, answers

bool white(const std::array<int, 3>& p) { return p[0] >= 250 && p[1] >= 250 && p[2] >= 250; }

TEST(Axes, TicksAndTheirValuesSitAtTheirCoordinates) {
    // The view [-3, 3]^2: a step of 1 (span / 5 = 1.2 rounds to 1), ticks -3 .. 3 on both axes.
    const Cone f = force_ray(Vec2(0, 0), Vec2(1, 0));
    const Figure fig = labels_figure("1a", {panel_of("F", f)}, false, f, Box{Vec2(-3, -3), Vec2(3, 3)});
    const Svg svg{render(fig, Format::Svg)};
    for (const char* v : {"\u22123", "\u22122", "\u22121", "0", "1", "2", "3"}) EXPECT_EQ(svg.count_text(v), 2) << v;
    EXPECT_EQ(svg.count_text("-1"), 0);  // the minus sign, not a hyphen
    const Image img = decode_png(render(fig, Format::Png));
    const Layout page = layout(fig);
    const Layout::Frame& fr = page.panels[0];
    for (int v = -3; v <= 3; ++v) {
        // 2 pt outside the frame: on each tick, and halfway to the next one (26 pt away), blank.
        const Vec2 at = page.to_page(0, Vec2(v, v)), between = page.to_page(0, Vec2(v + 0.5, v + 0.5));
        EXPECT_FALSE(white(img.at(Vec2(at.x(), fr.y + fr.height + 2.0)))) << "x tick " << v;
        EXPECT_FALSE(white(img.at(Vec2(fr.x - 2.0, at.y())))) << "y tick " << v;
        if (v == 3) continue;
        EXPECT_TRUE(white(img.at(Vec2(between.x(), fr.y + fr.height + 2.0)))) << "x between " << v;
        EXPECT_TRUE(white(img.at(Vec2(fr.x - 2.0, between.y())))) << "y between " << v;
    }
}

// How much of the page lies below the lowest panel and its axis: the legend and the margin.
double below_panels(const Figure& fig) {
    const Layout page = layout(fig);
    double bottom = 0.0;
    for (const Layout::Frame& f : page.panels) bottom = std::max(bottom, f.y + f.height);
    return (page.height - bottom) / page.height;
}

TEST(Legend, ColumnsKeepItUnderAQuarterOfThePage) {
    const Scene scene = example("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    std::size_t rr = 0;
    while (analysis.at(rr).mode.letters != "rr") ++rr;
    const Figure fig = forces_figure("Figure 3", scene, analysis, {rr});
    ASSERT_GE(fig.legend.size(), 9U);
    EXPECT_LT(below_panels(fig), 0.25);
    const Cone f = friction_cone(Vec2(0, 0), Vec2(0, 1), 0.5);
    EXPECT_LT(below_panels(labels_figure("1c", {panel_of("F", f)}, false, f)), 0.3);
    // Every entry is drawn, once.
    const Svg svg{render(fig, Format::Svg)};
    for (const LegendEntry& e : fig.legend) EXPECT_EQ(svg.count_text(e.text), 1) << e.text;
}

// A pixel of the picture with the answer against the same picture without it.
struct Tint {
    std::array<int, 3> with;
    std::array<int, 3> without;
    // Blending in kAnswer (red 0.83, green 0.11) raises red over green.
    [[nodiscard]] bool tinted() const { return with[0] - with[1] > without[0] - without[1] + 20; }
    [[nodiscard]] bool same() const { return with == without; }
};

const ModeForces& mode_of(const std::vector<ModeForces>& analysis, const std::string& letters) {
    for (const ModeForces& m : analysis) {
        if (m.mode.letters == letters) return m;
    }
    throw std::invalid_argument(letters);
}

TEST(Answer, TiltFigureMarksTheGravityDirectionsAndTheBest) {
    // docs/planning.md by hand: rr for gravity directions [-atan 2, 0] through (1/2, 1/4).
    const Scene scene = example("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const ModeForces& rr = mode_of(analysis, "rr");
    PlanContext context;
    context.modes = analysis;
    const DirectionPlan plan = plan_tilt(scene, rr, context);
    const Figure fig = tilt_figure("tilt", scene, rr, plan);
    const Svg svg{render(fig, Format::Svg)};
    EXPECT_EQ(svg.count_text("\u221263.43\u00B0"), 1);  // -atan 2 = -63.4349 degrees
    EXPECT_EQ(svg.count_text("0\u00B0"), 1);
    EXPECT_EQ(svg.count_text("gravity directions: [\u221263.43\u00B0, 0\u00B0]"), 1);
    // The fan (and its swatch in the legend), filled and outlined in one element; the best
    // direction's arrowhead, filled.
    char fan[96];
    std::snprintf(fan, sizeof fan, "fill:rgb(%g%%,%g%%,%g%%);fill-opacity:0.22;", std::round(palette::kAnswer.r * 1000) / 10,
                  std::round(palette::kAnswer.g * 1000) / 10, std::round(palette::kAnswer.b * 1000) / 10);
    int fans = 0;
    for (std::size_t at = svg.text.find(fan); at != std::string::npos; at = svg.text.find(fan, at + 1)) ++fans;
    EXPECT_EQ(fans, 2);
    EXPECT_EQ(svg.fills(palette::kAnswer), 1);
    // Inside the fan (the middle direction, half its radius from the centre of mass) the panel
    // is tinted; opposite it, it is not.
    const Figure bare = synthesis_figure("tilt", scene, ForcePanel{"W", plan.actions, {scene.body->com}}, rr, plan.solutions);
    const Image a = decode_png(render(fig, Format::Png)), b = decode_png(render(bare, Format::Png));
    const Layout page = layout(fig);
    ASSERT_EQ(page.panels.size(), 3U);
    const Box& v = fig.panels[2].view;
    const double radius = 0.2 * std::max(v.max.x() - v.min.x(), v.max.y() - v.min.y());
    const double mid = -std::atan(2.0) / 2.0;
    const Vec2 in = scene.body->com + 0.5 * radius * Vec2(std::cos(mid), std::sin(mid));
    const Vec2 out = scene.body->com - 0.5 * radius * Vec2(std::cos(mid), std::sin(mid));
    EXPECT_TRUE((Tint{a.at(page.to_page(2, in)), b.at(layout(bare).to_page(2, in))}.tinted()));
    EXPECT_TRUE((Tint{a.at(page.to_page(2, out)), b.at(layout(bare).to_page(2, out))}.same()));
}

TEST(Answer, PushFigureMarksTheTouchSegment) {
    // docs/planning.md by hand: the trailing edge (0, y), slip l, pushes (1, -1/2) for y in [3/16, 1/2].
    const Scene scene = example("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const ModeForces& rr = mode_of(analysis, "rr");
    std::optional<PushCase> chosen;
    for (const PushCase& c : plan_push(scene, rr, PushOptions{})) {
        if (c.feature.kind == PushFeature::Kind::Edge && c.feature.index == 3 && c.slip == ContactMode::SlidingLeft) chosen = c;
    }
    ASSERT_TRUE(chosen);
    const Figure fig = push_figure("push", scene, rr, *chosen);
    const Svg svg{render(fig, Format::Svg)};
    EXPECT_TRUE(svg.has_text_containing("touch (0, 0.1875)\u2013(0, 0.5)") ||
                svg.has_text_containing("touch (0, 0.5)\u2013(0, 0.1875)"))
        << "the touch segment in the caption";
    EXPECT_EQ(svg.count_text("\u221226.57\u00B0"), 1);  // the direction (1, -1/2): -atan(1/2)
    const Image img = decode_png(render(fig, Format::Png));
    const Layout page = layout(fig);
    for (double y : {0.25, 0.3125, 0.4375}) {  // on the segment, clear of the best push's point
        EXPECT_TRUE(same(img.at(page.to_page(2, Vec2(0, y))), palette::kAnswer)) << y;
    }
    for (double y : {0.0625, 0.125}) {  // the edge below 3/16 is not where to touch
        EXPECT_FALSE(same(img.at(page.to_page(2, Vec2(0, y))), palette::kAnswer)) << y;
    }
}

TEST(Answer, ComplyFigureMarksTheSpringDirections) {
    // docs/problems.md by hand: a force (x, -1) through (0, 2) inserts the peg for 0 <= x <= 4/5:
    // directions from -90 degrees to atan2(-5, 4) = -51.34 degrees.
    const Scene scene = example("problem-peg-in-hole.json");
    const auto analysis = analyze(scene);
    const ModeForces& rl = mode_of(analysis, "rl");
    PlanContext context;
    context.modes = analysis;
    const ComplyPlan plan = plan_comply(rl, Vec2(0, 2), context);
    const Svg svg{render(comply_figure("peg", scene, rl, plan), Format::Svg)};
    EXPECT_EQ(svg.count_text("\u221290\u00B0"), 1);
    EXPECT_EQ(svg.count_text("\u221251.34\u00B0"), 1);
}

TEST(Answer, ForcesFigureMarksTheRotationCentreOrTheTranslation) {
    // tests/mechanics/test_paper_figures.cpp by hand: the peg on the lip slides in (rl) turning
    // counter-clockwise about (4, -3/2); the block along the wall slides (rr) without turning.
    const Scene lip = example("figure-4b-peg-on-the-lip.json");
    const auto peg = analyze(lip);
    std::size_t rl = 0;
    while (peg.at(rl).mode.letters != "rl") ++rl;
    const Svg a{render(forces_figure("4b", lip, peg, {rl}), Format::Svg)};
    EXPECT_EQ(a.count_text("(4, \u22121.5) \u21BA"), 1);
    EXPECT_TRUE(a.has_text_containing("rl: rotation about (4, \u22121.5) \u21BA"));
    const Scene block = example("figure-3-block-along-wall.json");
    const auto analysis = analyze(block);
    std::size_t rr = 0;
    while (analysis.at(rr).mode.letters != "rr") ++rr;
    const Svg b{render(forces_figure("3", block, analysis, {rr}), Format::Svg)};
    EXPECT_TRUE(b.has_text_containing("rr: translation along (1, 0)"));
    EXPECT_FALSE(b.has_text_containing("rotation about"));
}

// ---------------------------------------------------------------- files

// Titles and names come from users: a control character (which XML 1.0 cannot hold) or a byte
// that is not UTF-8 (which Cairo refuses) is drawn as text, and the SVG stays well-formed: no
// byte below 0x20 but blanks, and valid UTF-8 throughout (checked byte by byte here).
TEST(Svg, ControlCharactersAndBadUtf8InTextsAreDrawnAsText) {
    const Cone f = force_ray(Vec2(0, 0), Vec2(1, 0));
    const Figure fig = labels_figure(std::string("a\x01" "b\x1b" "c\xff" "d<&"), {panel_of(std::string("F\x02\xc3"), f)},
                                     false, f, Box{Vec2(-3, -3), Vec2(3, 3)});
    const std::string svg = render(fig, Format::Svg);
    for (std::size_t i = 0; i < svg.size();) {
        const auto c = static_cast<unsigned char>(svg[i]);
        ASSERT_FALSE(c < 0x20 && c != '\n' && c != '\t' && c != '\r') << "control byte at " << i;
        std::size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
        ASSERT_NE(len, 0U) << "not UTF-8 at " << i;
        for (std::size_t k = 1; k < len; ++k) {
            ASSERT_EQ(static_cast<unsigned char>(svg.at(i + k)) >> 6, 2U) << "not UTF-8 at " << i + k;
        }
        i += len;
    }
    EXPECT_NE(svg.find("<title>a\\x01b\\x1bc\xEF\xBF\xBD" "d&lt;&amp;</title>"), std::string::npos);
    EXPECT_NO_THROW((void)render(fig, Format::Pdf));
    EXPECT_NO_THROW((void)render(fig, Format::Png));
}

TEST(Write, FormatComesFromTheExtension) {
    EXPECT_EQ(format_for("a.svg"), Format::Svg);
    EXPECT_EQ(format_for("dir.x/a.PDF"), Format::Pdf);
    EXPECT_EQ(format_for("a.png"), Format::Png);
    EXPECT_THROW((void)format_for("a.jpg"), std::invalid_argument);
    EXPECT_THROW((void)format_for("svg"), std::invalid_argument);
}

TEST(Write, EachFormatHasItsSignature) {
    const Cone f = forces_through_point(Vec2(0, 0));
    const Figure fig = labels_figure("t", {panel_of("F", f)}, false, f);
    EXPECT_EQ(render(fig, Format::Pdf).substr(0, 5), "%PDF-");
    EXPECT_EQ(render(fig, Format::Png).substr(1, 3), "PNG");
    EXPECT_NE(render(fig, Format::Svg).find("<svg"), std::string::npos);
}

TEST(Write, NothingIsLeftBehindWhenTheFileCannotBeWritten) {
    const Cone f = forces_through_point(Vec2(0, 0));
    const Figure fig = labels_figure("t", {panel_of("F", f)}, false, f);
    const auto dir = std::filesystem::temp_directory_path() / ("momentlab-render-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    EXPECT_THROW(write(fig, (dir / "missing" / "a.svg").string()), std::runtime_error);
    EXPECT_THROW(write(fig, (dir / "a.gif").string()), std::invalid_argument);
    write(fig, (dir / "a.svg").string());
    std::vector<std::string> left;
    for (const auto& e : std::filesystem::directory_iterator(dir)) left.push_back(e.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"a.svg"});
    std::filesystem::remove_all(dir);
}

TEST(Layout, PanelsKeepEqualScaleInXAndY) {
    const Cone f = forces_through_point(Vec2(0, 0));
    Figure fig = labels_figure("t", {panel_of("F", f)}, false, f, Box{Vec2(0, 0), Vec2(4, 1)});
    const Layout page = layout(fig);
    const Vec2 a = page.to_page(0, Vec2(0, 0)), b = page.to_page(0, Vec2(1, 1));
    EXPECT_DOUBLE_EQ(b.x() - a.x(), a.y() - b.y());
    fig.panels[0].view = Box{Vec2(0, 0), Vec2(0, 1)};
    EXPECT_THROW((void)layout(fig), std::invalid_argument);
}

}  // namespace
}  // namespace momentlab::render
