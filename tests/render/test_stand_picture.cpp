// The picture of `momentlab stand` (render/stand_pictures.hpp): what it draws against answers
// derived by hand in docs/assemblies.md, and each body's contact wrenches against cones built
// here from the scene's raw numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "momentlab/assembly/assembly_json.hpp"
#include "momentlab/render/stand_pictures.hpp"

namespace momentlab::render {
namespace {

Assembly example(const std::string& name) {
    std::ifstream in(std::string(MOMENTLAB_EXAMPLES) + "/" + name);
    std::ostringstream s;
    s << in.rdbuf();
    return read_assembly_text(s.str());
}

bool same(const Colour& a, const Colour& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

// The answer's arrows of a panel: polylines in palette::kAnswer ending in an arrowhead.
std::vector<Shape> answer_arrows(const Panel& p) {
    std::vector<Shape> out;
    for (const Shape& s : p.shapes) {
        if (s.arrow_end && s.stroke && same(s.stroke->colour, palette::kAnswer)) out.push_back(s);
    }
    return out;
}

// The crosses of a panel: two-point answer strokes without arrowheads (a cross is two of them).
std::size_t answer_strokes(const Panel& p) {
    return static_cast<std::size_t>(std::count_if(p.shapes.begin(), p.shapes.end(), [](const Shape& s) {
        return !s.arrow_end && s.stroke && same(s.stroke->colour, palette::kAnswer) && s.points.size() == 2;
    }));
}

TEST(StandPicture, HarmonicStackDrawsTheLoadAtTheFourOuterEnds) {
    // docs/assemblies.md: the top k bricks' weight k is carried at the outer end of their lowest
    // interface, (0, 0), (3, 1), (7, 2), (13, 3) from the floor up, straight up; nothing at the
    // four inner ends, in every equilibrium.
    const Assembly a = example("assembly-harmonic-stack.json");
    const Figure f = stand_figure("stack", a, stand(a));
    ASSERT_EQ(f.panels.size(), 1u + 4u);  // the assembly, and a labels panel per brick
    const std::vector<Shape> arrows = answer_arrows(f.panels[0]);
    ASSERT_EQ(arrows.size(), 4u);
    const std::vector<std::pair<Vec2, double>> expected = {{Vec2(0, 0), 4}, {Vec2(3, 1), 3}, {Vec2(7, 2), 2}, {Vec2(13, 3), 1}};
    const double unit = (arrows[0].points[1] - arrows[0].points[0]).norm() /
                        std::find_if(expected.begin(), expected.end(), [&](const auto& e) { return e.first == arrows[0].points[0]; })->second;
    for (const auto& e : expected) {
        const Vec2 at = e.first;
        const double load = e.second;
        const auto arrow = std::find_if(arrows.begin(), arrows.end(), [&](const Shape& s) { return s.points[0] == at; });
        ASSERT_NE(arrow, arrows.end()) << at.transpose();
        const Vec2 d = arrow->points[1] - arrow->points[0];
        EXPECT_NEAR(d.x(), 0.0, 1e-9 * unit);
        EXPECT_NEAR(d.y(), load * unit, 1e-9 * unit);  // up (the force on the upper brick), in proportion
    }
    EXPECT_NE(f.panels[0].caption.find("4 of 8 contacts carry force"), std::string::npos) << f.panels[0].caption;
}

TEST(StandPicture, FallingAssemblyDrawsAMechanismAlongWhichGravityWorks) {
    // Modern Robotics as given falls (mu_A = 0.1 < 10/31): no forces; each moving body's centre of
    // mass gets an arrow in proportion to its velocity, so gravity (0, -1) does positive work on
    // the arrows: sum of mass times the arrow's y < 0.
    const Assembly a = example("assembly-modern-robotics.json");
    const StandResult r = stand(a);
    ASSERT_FALSE(r.equilibrium.can_stand);
    const Figure f = stand_figure("mr", a, r);
    const Panel& p = f.panels[0];
    EXPECT_EQ(p.caption.rfind("falls", 0), 0u) << p.caption;
    const std::vector<Shape> arrows = answer_arrows(p);
    ASSERT_FALSE(arrows.empty());
    double work = 0.0;
    for (const Shape& s : arrows) {
        const auto body = std::find_if(a.bodies.begin(), a.bodies.end(), [&](const AssemblyBody& b) { return b.com == s.points[0]; });
        ASSERT_NE(body, a.bodies.end()) << "an arrow not at a centre of mass";
        work -= body->mass * (s.points[1] - s.points[0]).y();
    }
    EXPECT_GT(work, 0.0);
    std::size_t turning = 0;
    for (const BodyMotion& m : r.equilibrium.mechanism) turning += m.rotation_centre ? 1 : 0;
    EXPECT_EQ(answer_strokes(p), 2 * turning);
}

// A friction cone's edges as wrenches (f, p x f), from the raw numbers: n +- mu t, t = (n.y, -n.x).
void add_edges(std::vector<Vec3>& out, const Vec2& p, const Vec2& n, double mu, double sign) {
    const Vec2 t(n.y(), -n.x());
    for (const Vec2& f : {Vec2(sign * (n + mu * t)), Vec2(sign * (n - mu * t))}) out.emplace_back(f.x(), f.y(), cross2(p, f));
}

TEST(StandPicture, ContactWrenchesOfABodyAreItsConesWithBsNegated) {
    // Modern Robotics, body 2: the floor at (60, 0) and (72, 0) (normal (0, 1), mu 1/2), and the
    // opposite of body 1's cone at (60, 60) (normal (-1, 0) into body 1, mu 1/2).
    const Assembly a = example("assembly-modern-robotics.json");
    std::vector<Vec3> g;
    add_edges(g, Vec2(60, 0), Vec2(0, 1), 0.5, 1.0);
    add_edges(g, Vec2(72, 0), Vec2(0, 1), 0.5, 1.0);
    add_edges(g, Vec2(60, 60), Vec2(-1, 0), 0.5, -1.0);
    EXPECT_TRUE(contact_wrenches(a, 2) == Cone::from_generators(std::span<const Vec3>(g)));
    std::vector<Vec3> h;
    add_edges(h, Vec2(0, 0), Vec2(0, 1), 0.1, 1.0);
    add_edges(h, Vec2(60, 60), Vec2(-1, 0), 0.5, 1.0);
    EXPECT_TRUE(contact_wrenches(a, 1) == Cone::from_generators(std::span<const Vec3>(h)));
    EXPECT_THROW((void)contact_wrenches(a, 3), std::out_of_range);
    EXPECT_THROW((void)contact_wrenches(a, 0), std::out_of_range);
}

TEST(StandPicture, ManyBodiesGetTheFirstLabelPanelsOnly) {
    const std::vector<AssemblyBody> four = example("assembly-harmonic-stack.json").bodies;
    Assembly wide;
    for (std::size_t i = 0; i < 3; ++i) {
        for (AssemblyBody b : four) {
            b.com.x() += 100.0 * static_cast<double>(i);
            b.polygon.clear();  // a dot at the centre of mass, where its one contact holds it
            wide.bodies.push_back(b);
        }
    }
    for (std::size_t k = 1; k <= wide.bodies.size(); ++k) {
        wide.contacts.push_back({k, 0, Contact::make(wide.bodies[k - 1].com, Vec2(0, 1), 0.5)});
    }
    const Figure f = stand_figure("wide", wide, stand(wide));
    EXPECT_EQ(f.panels.size(), 1 + kStandLabelPanels);
    EXPECT_NE(f.panels[0].title.find("first 8 bodies"), std::string::npos);
}

}  // namespace
}  // namespace momentlab::render
