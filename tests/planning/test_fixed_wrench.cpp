// A fixed wrench plus a controlled push (planning/fixed_wrench.hpp), against Newton-Euler worked
// by hand for the block on the table.
#include <gtest/gtest.h>

#include "../common/examples.hpp"

#include <random>

#include "momentlab/planning/fixed_wrench.hpp"
#include "momentlab/planning/comply.hpp"
#include "momentlab/planning/push.hpp"
#include "momentlab/planning/tilt.hpp"

namespace momentlab {
namespace {

std::vector<std::string> letters(const std::vector<ModeForces>& a, const std::vector<std::size_t>& modes) {
    std::vector<std::string> out;
    for (std::size_t j : modes) out.push_back(a[j].mode.letters);
    std::sort(out.begin(), out.end());
    return out;
}

Magnitude ratio(double num, double den) { return {Dyadic(num), Dyadic(den)}; }
Magnitude ratio(const Dyadic& num, const Dyadic& den) { return {num, den}; }

// The block on the table (examples/block-on-table.json): width w = 1, mass m = 1, centre of mass
// c = (1/2, 1/4), inertia I about it, contacts at (0, 0) ("rear") and (1, 0) ("front") with normal
// +y and mu = 1/2 (t = +x: r is sliding towards +x). Gravity (0, -g), g = 10, through c; a finger
// pushes with force (P, 0) at (0, h). Newton-Euler from rest, forces on the block:
//
//   ff (at rest): l_1 + l_2 = m g, friction -P with |friction| <= mu (l_1 + l_2), moments about
//      the front corner: l_1 = m g w/2 - h P... >= 0. So P <= mu m g (and h P <= m g w / 2).
//   rr (sliding, no turning, acceleration a >= 0): l_1 + l_2 = m g; P - mu m g = m a >= 0;
//      moments about the origin, the inertia term of a translation being -c_y m a:
//      -m g w/2 - h P = -c_y m a - w l_2, so w l_2 = m g w/2 + h P - c_y (P - mu m g).
//      l_2 <= m g (l_1 >= 0):  (h - c_y) P <= m g (w/2 - mu c_y);
//      l_2 >= 0:               (c_y - h) P <= m g (w/2 + mu c_y).
//   sr (the rear lifts, the front slides): the same boundary as rr's l_1 = 0 from the other side,
//      (h - c_y) P >= m g (w/2 - mu c_y) (turning clockwise about the front corner, beta >= 0:
//      beta D = (h - c_y) P - m g (w/2 - mu c_y) with D = I_front - m c_y (c_y + mu w/2) > 0).
//   rs (the front lifts, the rear slides): past rr's l_2 = 0, (c_y - h) P >= m g (w/2 + mu c_y).
// So for h > c_y: ff on [0, mu m g], rr on [mu m g, T], sr from T up, T = m g (w/2 - mu c_y) / (h - c_y);
// for h < c_y the same with rs from T' = m g (w/2 + mu c_y) / (c_y - h); for h = c_y rr to the end.
struct Expected {
    std::vector<std::string> modes;
    std::optional<Magnitude> to;  // the band's upper end
};

void expect_bands(double h, const std::vector<Expected>& want) {
    const Scene scene = testing::example_scene("block-on-table.json");
    const auto a = analyze(scene);
    const Exact3 g = gravity_wrench(*scene.body, Vec2(0.0, -10.0));
    const auto bands = magnitude_bands(a, g, wrench_through(exact(Vec2(0.0, h)), exact(Vec2(1.0, 0.0))));
    ASSERT_EQ(bands.size(), want.size()) << "h = " << h;
    for (std::size_t k = 0; k < bands.size(); ++k) {
        EXPECT_EQ(letters(a, bands[k].modes), want[k].modes) << "h = " << h << ", band " << k;
        ASSERT_EQ(bands[k].to.has_value(), want[k].to.has_value()) << "h = " << h << ", band " << k;
        if (want[k].to) {
            EXPECT_EQ(compare(*bands[k].to, *want[k].to), 0) << "h = " << h << ", band " << k << ": " << bands[k].to->value()
                                                            << " vs " << want[k].to->value();
        }
        if (k > 0) {
            EXPECT_EQ(compare(bands[k].from, *bands[k - 1].to), 0);
        }
    }
    EXPECT_EQ(bands.front().from.value(), 0.0);
}

TEST(FixedWrench, BlockOnTablePushedHighSlidesThenTipsForward) {
    const double mg = 10.0, w = 1.0, mu = 0.5, cy = 0.25;
    for (double h : {0.5, 0.375, 0.3125}) {
        const Magnitude slide = ratio(mu * mg, 1.0);
        const Magnitude tip = ratio(Dyadic(mg) * (Dyadic(w / 2) - Dyadic(mu) * Dyadic(cy)), Dyadic(h) - Dyadic(cy));
        expect_bands(h, {{{"ff"}, slide}, {{"ff", "rr"}, slide}, {{"rr"}, tip}, {{"rr", "sr"}, tip}, {{"sr"}, std::nullopt}});
    }
    // h = 1/2: sliding from 5, tipping from 15 (10 (1/2 - 1/8) / (1/4)).
    expect_bands(0.5, {{{"ff"}, ratio(5, 1)}, {{"ff", "rr"}, ratio(5, 1)}, {{"rr"}, ratio(15, 1)},
                       {{"rr", "sr"}, ratio(15, 1)}, {{"sr"}, std::nullopt}});
}

TEST(FixedWrench, BlockOnTablePushedLowLiftsItsFront) {
    const double mg = 10.0, w = 1.0, mu = 0.5, cy = 0.25;
    for (double h : {0.1, 0.125, 0.0}) {  // 0.1 is not dyadic: the threshold is an exact ratio all the same
        const Magnitude slide = ratio(mu * mg, 1.0);
        const Magnitude lift = ratio(Dyadic(mg) * (Dyadic(w / 2) + Dyadic(mu) * Dyadic(cy)), Dyadic(cy) - Dyadic(h));
        expect_bands(h, {{{"ff"}, slide}, {{"ff", "rr"}, slide}, {{"rr"}, lift}, {{"rr", "rs"}, lift}, {{"rs"}, std::nullopt}});
    }
}

TEST(FixedWrench, BlockOnTablePushedAtTheHeightOfItsCentreOfMassSlidesForEveryForceAboveTheFriction) {
    expect_bands(0.25, {{{"ff"}, ratio(5, 1)}, {{"ff", "rr"}, ratio(5, 1)}, {{"rr"}, std::nullopt}});
}

// magnitudes() against the definition on a cone given by hand: E = {x >= 0, y >= 0} x R (a
// wedge times a line), g = (-2, 3, 7), u = (1, -1, 0): g + l u = (l - 2, 3 - l, 7) is in E for
// l in [2, 3].
TEST(FixedWrench, MagnitudesOfAWedge) {
    const std::vector<Vec3> normals = {Vec3(1, 0, 0), Vec3(0, 1, 0)};
    const Cone e = Cone::from_halfspaces(normals);
    const auto r = magnitudes(e, exact(Vec3(-2, 3, 7)), exact(Vec3(1, -1, 0)));
    ASSERT_TRUE(r.has_value());
    EXPECT_EQ(r->lo.value(), 2.0);
    ASSERT_TRUE(r->hi.has_value());
    EXPECT_EQ(r->hi->value(), 3.0);
    EXPECT_FALSE(magnitudes(e, exact(Vec3(-2, 3, 7)), exact(Vec3(-1, 0, 0))).has_value());  // away from it
    const auto all = magnitudes(e, exact(Vec3(2, 3, 7)), exact(Vec3(1, 1, 5)));  // g inside, u into it
    ASSERT_TRUE(all.has_value());
    EXPECT_EQ(all->lo.value(), 0.0);
    EXPECT_FALSE(all->hi.has_value());
    // A plane (an equation): exactly one magnitude, 4/3 (not a dyadic number).
    const Cone plane = Cone::from_generators(std::vector<Vec3>{Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)});
    const auto one = magnitudes(plane, exact(Vec3(0, 0, -4)), exact(Vec3(1, 1, 3)));
    ASSERT_TRUE(one.has_value());
    ASSERT_TRUE(one->hi.has_value());
    EXPECT_EQ(compare(one->lo, *one->hi), 0);
    EXPECT_EQ(compare(one->lo, ratio(4, 3)), 0);
}

// The directions that work at some positive magnitude are exactly E + cone(-g): checked on random cones
// and dyadic vectors against magnitudes() (members of the interior have a magnitude; vectors
// with a magnitude are members).
TEST(FixedWrench, ReachableDirectionsAreTheDirectionsWithAMagnitude) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> coord(-4, 4);
    const auto v = [&] { return Vec3(coord(rng) / 2.0, coord(rng) / 2.0, coord(rng) / 2.0); };
    int with = 0, without = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const std::vector<Vec3> gens = {v(), v(), v()};
        const Cone e = Cone::from_generators(gens);
        const Exact3 g = exact(v());
        const Cone reach = reachable_directions(e, g);
        for (int k = 0; k < 20; ++k) {
            const Vec3 u = v();
            const auto r = magnitudes(e, g, exact(u));  // a positive magnitude (0 is no push at all)
            const bool has_magnitude = r && (!r->hi || r->hi->num.sign() == Sign::Positive);
            if (has_magnitude) {
                EXPECT_TRUE(reach.has(u));
                ++with;
            } else {
                EXPECT_FALSE(reach.in_relative_interior(u) && reach.dimension() == 3);
                ++without;
            }
        }
    }
    EXPECT_GT(with, 100);
    EXPECT_GT(without, 100);
}

// plan push with gravity: the finger sticking on the block's rear face (edge 3) can slide it and
// can tip it; the best push's magnitudes are those of the bands along it.
TEST(FixedWrench, PushPlanUnderGravityReportsMagnitudes) {
    const Scene scene = testing::example_scene("block-on-table.json");
    const auto a = analyze(scene);
    PlanContext context;
    context.fixed = gravity_wrench(*scene.body, Vec2(0.0, -10.0));
    for (const char* goal : {"rr", "sr"}) {
        const ModeForces* m = nullptr;
        for (const ModeForces& f : a) {
            if (f.mode.letters == goal) m = &f;
        }
        ASSERT_NE(m, nullptr);
        bool found = false;
        for (const PushCase& c : plan_push(scene, *m, PushOptions{0.5, false}, context)) {
            if (c.feature.kind != PushFeature::Kind::Edge || c.feature.index != 3 || c.slip != ContactMode::Fixed) continue;
            found = true;
            EXPECT_EQ(c.verdict, PushVerdict::Feasible) << goal;
            ASSERT_TRUE(c.best && c.best_magnitudes) << goal;
            // The best push at the middle of its magnitudes (or just past the start) gives the goal.
            const Exact3 u = wrench_through(exact(c.best->point), exact(c.best->direction));
            const double lo = c.best_magnitudes->lo.value();
            const double l = c.best_magnitudes->hi ? (lo + c.best_magnitudes->hi->value()) / 2 : lo * 1.5;
            const Vec3 e = to_double(*context.fixed + Dyadic(l) * u);
            EXPECT_TRUE(m->applied.has(e)) << goal;
        }
        EXPECT_TRUE(found);
    }
}

// A frictionless block: E_ff (held by two normal forces) is a plane, so no g + lambda u lies in
// its interior: with a fixed wrench every plan for ff is a knife edge, never feasible (E_ff +
// cone(-g) is full-dimensional all the same: the verdicts must not be read off it alone).
TEST(FixedWrench, LowerDimensionalGoalsAreKnifeEdges) {
    Scene scene = testing::example_scene("block-on-table.json");
    for (Contact& c : scene.contacts) c = Contact::make(c.point, c.normal, 0.0, 0.0);
    const auto a = analyze(scene);
    const ModeForces* ff = nullptr;
    for (const ModeForces& m : a) {
        if (m.mode.letters == "ff") ff = &m;
    }
    ASSERT_NE(ff, nullptr);
    ASSERT_EQ(ff->applied.dimension(), 2);
    PlanContext context;
    context.fixed = exact(Vec3(1.0, 0.0, 0.0));
    const DirectionPlan tilt = plan_tilt(scene, *ff, context);
    ASSERT_TRUE(tilt.feasible());
    EXPECT_TRUE(tilt.knife_edge);
    EXPECT_EQ(tilt.margin, 0.0);
    for (const PushCase& c : plan_push(scene, *ff, PushOptions{0.5, true}, context)) {
        EXPECT_NE(c.verdict, PushVerdict::Feasible) << c.feature.name() << " " << letter(c.slip);
    }
    const ComplyPlan comply = plan_comply(*ff, Vec2(0.5, 3.0), context);
    EXPECT_NE(comply.verdict, CentreVerdict::Works);
}

// plan_comply with gravity: its label and verdict are those of E_goal + cone(-g), whose labels
// compliance_labels gives: a centre works exactly when it is unlabelled there (block on the
// table, rr, every quarter unit over [-2, 3] x [-2, 3]).
TEST(FixedWrench, ComplianceLabelsFollowTheFixedWrench) {
    const Scene scene = testing::example_scene("block-on-table.json");
    const auto a = analyze(scene);
    const ModeForces* rr = nullptr;
    for (const ModeForces& m : a) {
        if (m.mode.letters == "rr") rr = &m;
    }
    ASSERT_NE(rr, nullptr);
    PlanContext context;
    context.fixed = gravity_wrench(*scene.body, Vec2(0.0, -10.0));
    const Labels labels = compliance_labels(*rr, context);
    int works = 0, fails = 0;
    for (int i = -8; i <= 12; ++i) {
        for (int j = -8; j <= 12; ++j) {
            const Vec2 c(i / 4.0, j / 4.0);
            const ComplyPlan plan = plan_comply(*rr, c, context);
            EXPECT_EQ(plan.label, labels.at(c)) << c.transpose();
            if (plan.label == Label::None) {
                EXPECT_EQ(plan.verdict, CentreVerdict::Works) << c.transpose();
            }
            if (plan.verdict == CentreVerdict::Works) ++works;
            if (plan.verdict == CentreVerdict::Fails) ++fails;
        }
    }
    EXPECT_GT(works, 10);
    EXPECT_GT(fails, 10);
}

}  // namespace
}  // namespace momentlab
