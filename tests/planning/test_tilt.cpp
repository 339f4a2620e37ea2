// Tilting (Mason 1991, Figure 5), checked against a derivation by hand.
#include <gtest/gtest.h>

#include "../common/examples.hpp"

#include <cmath>
#include <set>
#include <fstream>
#include <sstream>

#include "mode_oracle.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/planning/tilt.hpp"

namespace momentlab {
namespace {

Scene example(const std::string& name) { return testing::example_scene(name); }

const ModeForces& mode(const std::vector<ModeForces>& a, const std::string& letters) {
    for (const ModeForces& m : a) {
        if (m.mode.letters == letters) return m;
    }
    throw std::logic_error("no mode " + letters);
}

// The block on the floor (contacts (0, 0) and (1, 0), normal +y, mu = 1/2, centre of mass
// (1/2, 1/4)) slides right without turning (rr) under gravity g = (cos t, sin t) through its
// centre of mass exactly when the contact forces l_j (-1/2, 1), l_j >= 0, balance it:
//   vertical:   l_1 + l_2 = -sin t >= 0                 -> t in [-pi, 0]
//   horizontal: m a_x = cos t + sin t / 2 >= 0          -> t in [-atan 2, pi - atan 2]
//   moment about the centre of mass: -5/8 l_1 + 3/8 l_2 = 0, l_2 = 5/3 l_1 >= 0 (always).
// So t in [-atan 2, 0]: gravity at most atan(1/mu) below the horizontal, towards +x.
TEST(Tilt, BlockAlongTheWallSlidesRightForGravityBetweenMinusAtan2AndZero) {
    const Scene scene = example("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const DirectionPlan plan = plan_tilt(scene, mode(analysis, "rr"));
    ASSERT_EQ(plan.intervals.size(), 1u);
    EXPECT_NEAR(plan.intervals[0].from, -std::atan(2.0), 1e-15);
    EXPECT_EQ(plan.intervals[0].to, 0.0);
    EXPECT_NEAR(plan.margin, std::atan(2.0) / 2, 1e-15);
    EXPECT_NEAR(plan.best, -std::atan(2.0) / 2, 1e-15);
    // Mirror image: sliding left needs gravity in [-pi, -pi + atan 2].
    const DirectionPlan left = plan_tilt(scene, mode(analysis, "ll"));
    ASSERT_EQ(left.intervals.size(), 1u);
    EXPECT_EQ(left.intervals[0].from, -M_PI);
    EXPECT_NEAR(left.intervals[0].to, -M_PI + std::atan(2.0), 1e-15);
    // Staying put (ff): gravity within the friction cone's reach, [-pi + atan 2, -atan 2].
    const DirectionPlan rest = plan_tilt(scene, mode(analysis, "ff"));
    ASSERT_EQ(rest.intervals.size(), 1u);
    EXPECT_NEAR(rest.intervals[0].from, -M_PI + std::atan(2.0), 1e-15);
    EXPECT_NEAR(rest.intervals[0].to, -std::atan(2.0), 1e-15);
}

// Lifting the leading corner while the trailing one slides left (ls) under gravity
// g = (cos t, sin t) through the centre of mass c = (1/2, 1/4), with the trailing contact's
// force l (1/2, 1), l >= 0 (sliding along -t, t = (1, 0)), and k = 3/16 / I > 0: the
// trailing corner (c + (-1/2, -1/4)) keeps contact, a_y - alpha/2 = 0, so
// sin t + l + (3/16) l / I = 0, sin t = -l (1 + k); the leading corner (c + (1/2, -1/4)) lifts,
// a_y + alpha/2 = sin t + l - k l >= 0, so -2 k l >= 0: l = 0, sin t = 0, and sliding left
// needs cos t <= 0. Only t = pi: one direction, not the full turn (a regression: the arc
// from pi to pi was read as a wrap through pi).
TEST(Tilt, LiftingTheLeadingCornerWhileSlidingLeftOnlyForGravityAlongMinusX) {
    const Scene scene = example("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const DirectionPlan plan = plan_tilt(scene, mode(analysis, "ls"));
    ASSERT_EQ(plan.intervals.size(), 1u);
    EXPECT_EQ(plan.intervals[0].from, -M_PI);
    EXPECT_EQ(plan.intervals[0].to, -M_PI);
    EXPECT_LT(plan.intervals[0].from_direction.x(), 0.0);  // along -x (any length)
    EXPECT_EQ(plan.intervals[0].from_direction.y(), 0.0);
    EXPECT_EQ(plan.margin, 0.0);
}

TEST(Tilt, EveryDirectionInsideTheIntervalIsInETheOthersAreNot) {
    const Scene scene = example("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const ModeForces& rr = mode(analysis, "rr");
    const Vec2 c = scene.body->com;
    for (int k = -180; k < 180; ++k) {
        const double t = (k + 0.5) * M_PI / 180;  // never a boundary
        const bool inside = t >= -std::atan(2.0) && t <= 0;
        EXPECT_EQ(rr.applied.has(wrench_at(c, Vec2(std::cos(t), std::sin(t)))), inside) << t;
    }
}


// The modes whose E holds gravity (cos t, sin t) through the centre of mass, as rounded doubles
// read exactly: the exact LP of reference/mode_oracle.hpp on the scene's raw numbers.
std::set<std::string> oracle_answer(const Scene& scene, const std::vector<ModeForces>& analysis, double t, bool quasi_static) {
    const reference::Q fx(std::cos(t)), fy(std::sin(t));
    const reference::QVec e = reference::wrench(reference::q(scene.body->com.x()), reference::q(scene.body->com.y()), fx, fy);
    std::set<std::string> out;
    for (const ModeForces& m : analysis) {
        const bool in = quasi_static ? testing::exact_lp_quasi_static_in_mode(scene, m.mode.letters, e)
                                     : testing::exact_lp_applied_in_mode(scene, m.mode.letters, e);
        if (in) out.insert(m.mode.letters);
    }
    return out;
}

// Issue 44, item 1. Two fingers at (0, 0) (normal (1, 1)) and (2, 1) (normal (-4, -1)), mu = 1/2,
// centre of mass (0, 1), quasi-static (E_i = -T_i). The line between the contacts, direction
// (2, 1), is 18.4 degrees from the first normal and 12.5 from the second, inside both friction
// cones (26.6): an antipodal grasp, whose friction cones positively span R^3, so E_ff = R^3 and
// every tilt gives ff. sf's set -FC_2 holds the forces through (2, 1) with directions from
// (4.5, -1) to (3.5, 3) (the negated edges n +- t/2): through the centre of mass as well only on
// the line y = 1, and of its two directions only (1, 0), t = 0, lies between them. So ff is
// shared with sf at t = 0 and (the exact LP, every mode) alone at every other tilt sampled:
// unique [-pi, pi] (the closure of the turn less one direction), shared {0}, best the opposite,
// +-pi, a half-turn from where the goal is not alone.
TEST(Tilt, GoalHoldingEveryTiltButSharingOneIsAloneOnTheRestOfTheTurn) {
    const Scene scene = read_scene_text(
        R"({"body": {"mass": 1, "com": [0, 1], "inertia": 1}, "contacts": [{"point": [0, 0], "normal": [1, 1], "mu": 0.5, "mu_kinetic": 2}, {"point": [2, 1], "normal": [-4, -1], "mu": 0.5, "mu_kinetic": 2}]})");
    const auto analysis = analyze(scene, AnalysisOptions{.quasi_static = true});
    // The derivation above, by the exact LP: ff and sf at t = 0, ff alone elsewhere.
    EXPECT_EQ(oracle_answer(scene, analysis, 0.0, true), (std::set<std::string>{"ff", "sf"}));
    for (int k = -179; k <= 180; k += 7) {
        if (k == 0) continue;
        EXPECT_EQ(oracle_answer(scene, analysis, k * M_PI / 180, true), std::set<std::string>{"ff"}) << k;
    }
    const DirectionPlan plan = plan_tilt(scene, mode(analysis, "ff"), PlanContext{.modes = analysis, .fixed = std::nullopt, .metric = std::nullopt});
    ASSERT_TRUE(plan.uniqueness_known);
    ASSERT_EQ(plan.unique.size(), 1u);
    EXPECT_EQ(plan.unique[0].from, -M_PI);
    EXPECT_EQ(plan.unique[0].to, M_PI);
    ASSERT_EQ(plan.shared.size(), 1u);
    EXPECT_EQ(plan.shared[0].from, 0.0);
    EXPECT_EQ(plan.shared[0].to, 0.0);
    EXPECT_TRUE(plan.best_unique);
    EXPECT_EQ(std::abs(plan.best), M_PI);
    EXPECT_EQ(plan.margin, M_PI);
    EXPECT_EQ(oracle_answer(scene, analysis, plan.best, true), std::set<std::string>{"ff"});
}

// The same shape dynamically (the issue's second scene): ffff holds every tilt, and one other
// mode's set meets the plane in one direction. The exact LP finds ffff alone at 360 sampled tilts
// away from that direction and at the opposite one, the plan's best.
TEST(Tilt, DynamicGoalHoldingEveryTiltButSharingOneIsAloneOnTheRestOfTheTurn) {
    const Scene scene = read_scene_text(
        R"({"contacts": [{"point": [0.875, 0.125], "normal": [-7.125, -4.125], "mu": 1.0}, {"point": [1.0, 0.875], "normal": [5.0, 4.25], "mu": 0.25}, {"point": [0.875, -1.625], "normal": [2.375, -0.375], "mu": 0.5}, {"point": [-1.875, -1.625], "normal": [0.375, 0.375], "mu": 0.5}], "body": {"mass": 0.5, "com": [-0.875, -0.375], "inertia": 1.0}})");
    const auto analysis = analyze(scene);
    const DirectionPlan plan = plan_tilt(scene, mode(analysis, "ffff"), PlanContext{.modes = analysis, .fixed = std::nullopt, .metric = std::nullopt});
    ASSERT_EQ(plan.intervals.size(), 1u);
    EXPECT_EQ(plan.intervals[0].to - plan.intervals[0].from, 2 * M_PI);
    ASSERT_EQ(plan.shared.size(), 1u);
    const double shared = plan.shared[0].from;
    EXPECT_EQ(plan.shared[0].to, shared);
    ASSERT_EQ(plan.unique.size(), 1u);
    EXPECT_EQ(plan.unique[0].from, -M_PI);
    EXPECT_EQ(plan.unique[0].to, M_PI);
    EXPECT_TRUE(plan.best_unique);
    EXPECT_NEAR(std::abs(std::remainder(plan.best - shared, 2 * M_PI)), M_PI, 1e-15);
    EXPECT_EQ(plan.margin, M_PI);
    EXPECT_EQ(oracle_answer(scene, analysis, plan.best, false), std::set<std::string>{"ffff"});
    for (int k = -180; k < 180; ++k) {
        const double t = (k + 0.5) * M_PI / 180;
        if (std::abs(std::remainder(t - shared, 2 * M_PI)) < 1e-3) continue;
        EXPECT_EQ(oracle_answer(scene, analysis, t, false), std::set<std::string>{"ffff"}) << t;
    }
}

}  // namespace
}  // namespace momentlab
