// A fixed wrench plus a controlled push (planning/fixed_wrench.hpp), against Newton-Euler worked
// by hand for the block on the table.
#include <gtest/gtest.h>

#include "../common/examples.hpp"

#include <algorithm>
#include <random>

#include "cone_membership.hpp"
#include "mode_oracle.hpp"

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

reference::Q rational(const Magnitude& m) { return reference::to_q(m.num) / reference::to_q(m.den); }

// On random cones of half-integer generators, against brute-force membership in exact rationals
// (reference/cone_membership.hpp, no momentlab code): reachable_directions is cone(G) + cone(-g),
// as a set; and magnitudes() gives exactly the lambda >= 0 with g + lambda u in cone(G): its ends
// are members (closed), lambda a little below the low end (when > 0) and above the high end are
// not, and the middle is; with no range, no lambda of a sweep is a member.
TEST(FixedWrench, ReachableDirectionsAndMagnitudesAgreeWithBruteForceMembership) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> coord(-4, 4);
    const auto v = [&] { return Vec3(coord(rng) / 2.0, coord(rng) / 2.0, coord(rng) / 2.0); };
    int with = 0, without = 0, reachable = 0, unreachable = 0, bounded = 0, from_above_zero = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const std::vector<Vec3> gens = {v(), v(), v()};
        const Cone e = Cone::from_generators(gens);
        const Vec3 gd = v();
        const Exact3 g = exact(gd);
        const Cone reach = reachable_directions(e, g);
        std::vector<reference::QVec> q_gens, q_reach;
        for (const Vec3& x : gens) q_gens.push_back(reference::q(x));
        q_reach = q_gens;
        q_reach.push_back(reference::neg(reference::q(gd)));
        const auto member = [&](const reference::Q& lambda, const reference::QVec& u) {
            return reference::in_cone(q_gens, reference::add(reference::q(gd), reference::scale(lambda, u)));
        };
        for (int k = 0; k < 20; ++k) {
            const Vec3 ud = v();
            const reference::QVec u = reference::q(ud);
            const bool in_reach = reference::in_cone(q_reach, u);
            EXPECT_EQ(reach.has(ud), in_reach) << "trial " << trial;
            (in_reach ? reachable : unreachable) += 1;
            const auto r = magnitudes(e, g, exact(ud));
            if (!r) {
                for (int l : {0, 1, 4, 16, 64}) EXPECT_FALSE(member(reference::Q(l, 4), u)) << "trial " << trial << " lambda " << l / 4.0;
                ++without;
                continue;
            }
            ++with;
            const reference::Q lo = rational(r->lo);
            EXPECT_GE(reference::sign(lo), 0);
            EXPECT_TRUE(member(lo, u)) << "trial " << trial;
            const reference::Q step(1, 1 << 20);
            if (reference::sign(lo) > 0) {
                EXPECT_FALSE(member(lo * (1 - step), u)) << "trial " << trial;
                ++from_above_zero;
            }
            if (r->hi) {
                const reference::Q hi = rational(*r->hi);
                EXPECT_TRUE(member(hi, u)) << "trial " << trial;
                EXPECT_TRUE(member((lo + hi) / 2, u)) << "trial " << trial;
                EXPECT_FALSE(member(hi * (1 + step) + step, u)) << "trial " << trial;
                ++bounded;
            } else {
                for (int l = 1; l <= 3; ++l) EXPECT_TRUE(member(lo + reference::Q(1 << (8 * l)), u)) << "trial " << trial;
            }
        }
    }
    std::cout << "[FixedWrench] " << with << " pushes with magnitudes (" << bounded << " bounded, " << from_above_zero
              << " from above 0), " << without << " without; " << reachable << " directions reachable, " << unreachable
              << " not\n";
    EXPECT_GT(with, 100);
    EXPECT_GT(without, 100);
    EXPECT_GT(bounded, 30);
    EXPECT_GT(from_above_zero, 30);
    EXPECT_GT(reachable, 100);
    EXPECT_GT(unreachable, 100);
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
        for (const PushCase& c : plan_push(scene, *m, PushOptions{Rational(0.5), false}, context)) {
            if (c.feature.kind != PushFeature::Kind::Edge || c.feature.index != 3 || c.slip != ContactMode::Fixed) continue;
            found = true;
            EXPECT_EQ(c.verdict, PushVerdict::Feasible) << goal;
            ASSERT_TRUE(c.best && c.best_magnitudes) << goal;
            // The oracle (exact LP, the scene's raw numbers): gravity plus the best push, at its
            // magnitudes' ends and middle (or past the start), is in E_goal; a little outside them it is not.
            const reference::QVec gq = reference::wrench(reference::q(scene.body->com.x()), reference::q(scene.body->com.y()),
                                                         reference::Q(0), reference::q(scene.body->mass) * reference::Q(-10));
            const reference::QVec u = reference::wrench(reference::q(c.best->point.x()), reference::q(c.best->point.y()),
                                                        reference::q(c.best->direction.x()), reference::q(c.best->direction.y()));
            const auto in_goal = [&](const reference::Q& lambda) {
                return testing::exact_lp_applied_in_mode(scene, goal, reference::add(gq, reference::scale(lambda, u)));
            };
            const reference::Q lo = rational(c.best_magnitudes->lo), step(1, 1 << 20);
            EXPECT_TRUE(in_goal(lo)) << goal;
            if (reference::sign(lo) > 0) EXPECT_FALSE(in_goal(lo * (1 - step))) << goal;
            if (c.best_magnitudes->hi) {
                const reference::Q hi = rational(*c.best_magnitudes->hi);
                EXPECT_TRUE(in_goal((lo + hi) / 2)) << goal;
                EXPECT_TRUE(in_goal(hi)) << goal;
                EXPECT_FALSE(in_goal(hi * (1 + step))) << goal;
            } else {
                EXPECT_TRUE(in_goal(lo * 2 + 1)) << goal;
            }
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
    for (const PushCase& c : plan_push(scene, *ff, PushOptions{Rational(0.5), true}, context)) {
        EXPECT_NE(c.verdict, PushVerdict::Feasible) << c.feature.name() << " " << letter(c.slip);
    }
    const ComplyPlan comply = plan_comply(*ff, Vec2(0.5, 3.0), context);
    EXPECT_NE(comply.verdict, CentreVerdict::Works);
}

// plan_comply with gravity: its label and verdict are those of E_goal + cone(-g), derived by hand.
// Block on the table, rr: E_rr = cone{(1, 0, -1/4), (1/2, -1, 0), (1/2, -1, -1)} (M times the
// translation along +x; the floor's forces n - mu t = (-1/2, 1) at (0, 0) and (1, 0), negated), and
// -g = (0, 10, 5) (the weight 10 through (1/2, 1/4), negated). Their moments about c = (x, y),
// tau - x fy + y fx: y - 1/4, x + y/2, x + y/2 - 1 and 5 - 10 x. The label is + where all four are
// >= 0, - where all are <= 0, none elsewhere; a labelled centre fails when all are strictly of
// its sign and is a boundary (a knife edge) otherwise. Every quarter unit over [-2, 3] x [-2, 3].
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
    int counts[3] = {0, 0, 0};
    for (int i = -8; i <= 12; ++i) {
        for (int j = -8; j <= 12; ++j) {
            const double x = i / 4.0, y = j / 4.0;  // (the moments below are exact in doubles)
            const double moments[] = {y - 0.25, x + y / 2, x + y / 2 - 1, 5 - 10 * x};
            const bool nonneg = std::all_of(std::begin(moments), std::end(moments), [](double m) { return m >= 0; });
            const bool nonpos = std::all_of(std::begin(moments), std::end(moments), [](double m) { return m <= 0; });
            const bool pos = std::all_of(std::begin(moments), std::end(moments), [](double m) { return m > 0; });
            const bool neg = std::all_of(std::begin(moments), std::end(moments), [](double m) { return m < 0; });
            const Label label = nonneg && nonpos ? Label::Both : nonneg ? Label::Plus : nonpos ? Label::Minus : Label::None;
            const CentreVerdict verdict = label == Label::None ? CentreVerdict::Works
                                          : pos || neg         ? CentreVerdict::Fails
                                                               : CentreVerdict::Boundary;
            const ComplyPlan plan = plan_comply(*rr, Vec2(x, y), context);
            EXPECT_EQ(plan.label, label) << x << ", " << y;
            EXPECT_EQ(plan.verdict, verdict) << x << ", " << y;
            ++counts[static_cast<int>(verdict)];
        }
    }
    EXPECT_GT(counts[static_cast<int>(CentreVerdict::Works)], 10);
    EXPECT_GT(counts[static_cast<int>(CentreVerdict::Fails)], 10);
    EXPECT_GT(counts[static_cast<int>(CentreVerdict::Boundary)], 5);
}

}  // namespace
}  // namespace momentlab
