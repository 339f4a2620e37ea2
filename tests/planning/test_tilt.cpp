// Tilting (Mason 1991, Figure 5), checked against a derivation by hand.
#include <gtest/gtest.h>

#include "../common/examples.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

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

}  // namespace
}  // namespace momentlab
