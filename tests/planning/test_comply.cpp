// Compliance (Mason 1991, section 3): the spring directions through a centre and the centres
// that work, for the block along the wall, against the conditions derived by hand.
#include <gtest/gtest.h>

#include "../common/examples.hpp"

#include <cmath>

#include "mode_oracle.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/planning/comply.hpp"

namespace momentlab {
namespace {

// E_rr of the block along the wall is cone{g1, g2, g3}: g1 = (1, 0, -1/4), the body's mass
// times its acceleration along +x, and g2 = (1/2, -1, 0), g3 = (1/2, -1, -1), the negated wall
// forces at (0, 0) and (1, 0) (docs/planning.md). The moment of g about c = (x, y) is
// y fx - x fy + tau: y - 1/4, x + y/2 and x + y/2 - 1. So the + region (all >= 0) is
// {y >= 1/4, x + y/2 >= 1} and the - region (all <= 0) is {y <= 1/4, x + y/2 <= 0}.
CentreVerdict by_hand(double x, double y) {
    const double a = y - 0.25, b = x + y / 2, c = x + y / 2 - 1;
    if ((a > 0 && c > 0) || (a < 0 && b < 0)) return CentreVerdict::Fails;        // strictly inside
    if ((a >= 0 && c >= 0) || (a <= 0 && b <= 0)) return CentreVerdict::Boundary;  // on an edge
    return CentreVerdict::Works;
}

// A force (cos t, sin t) through (x, y) is in E_rr iff, with tau = x fy - y fx, alpha = fx +
// fy / 2 >= 0, -fy >= 0 and gamma = -tau - alpha / 4 in [0, -fy]; inside iff all are strict.
bool strictly_in_e(double x, double y, double t) {
    const double fx = std::cos(t), fy = std::sin(t), tau = x * fy - y * fx;
    const double alpha = fx + fy / 2, gamma = -tau - alpha / 4;
    return alpha > 1e-9 && -fy > 1e-9 && gamma > 1e-9 && gamma < -fy - 1e-9;
}

const ModeForces& rr_of(const std::vector<ModeForces>& analysis) {
    for (const ModeForces& m : analysis) {
        if (m.mode.letters == "rr") return m;
    }
    throw std::logic_error("no rr");
}

TEST(Comply, CentresOnAnEighthGridGetTheVerdictDerivedByHand) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const ModeForces& rr = rr_of(analysis);
    int counts[3] = {0, 0, 0};
    for (int i = -16; i <= 24; ++i) {
        for (int j = -16; j <= 16; ++j) {
            const double x = i / 8.0, y = j / 8.0;
            const ComplyPlan plan = plan_comply(rr, Vec2(x, y));
            const CentreVerdict expected = by_hand(x, y);
            EXPECT_EQ(plan.verdict, expected) << x << ", " << y;
            ++counts[static_cast<int>(expected)];
            // Sampled directions strictly inside E_rr lie in the intervals, and exist only where
            // the centre works.
            bool any = false;
            for (int k = 0; k < 720; ++k) {
                const double t = -M_PI + (k + 0.5) * M_PI / 360;
                if (!strictly_in_e(x, y, t)) continue;
                any = true;
                bool inside = false;
                for (const AngleInterval& iv : plan.directions.intervals) inside = inside || (iv.from <= t && t <= iv.to);
                EXPECT_TRUE(inside) << x << ", " << y << " direction " << t;
            }
            if (any) {
                EXPECT_EQ(plan.verdict, CentreVerdict::Works) << x << ", " << y;
            }
            if (plan.verdict == CentreVerdict::Works) {
                EXPECT_TRUE(strictly_in_e(x, y, plan.directions.best)) << x << ", " << y;
            }
        }
    }
    EXPECT_GT(counts[0], 100);  // works
    EXPECT_GT(counts[1], 20);   // boundary
    EXPECT_GT(counts[2], 100);  // fails
}

// At the outboard trailing corner (0, 1/2) the spring directions are those of a finger on that
// vertex: from -atan 2 to -atan(2/7) (docs/planning.md); at the centre of mass, the tilts.
TEST(Comply, DirectionsAtTheCornerAndAtTheCentreOfMass) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const ComplyPlan corner = plan_comply(rr_of(analysis), Vec2(0, 0.5));
    ASSERT_EQ(corner.directions.intervals.size(), 1u);
    EXPECT_NEAR(corner.directions.intervals[0].from, -std::atan(2.0), 1e-15);
    EXPECT_NEAR(corner.directions.intervals[0].to, -std::atan(2.0 / 7.0), 1e-15);
    const ComplyPlan com = plan_comply(rr_of(analysis), Vec2(0.5, 0.25));
    ASSERT_EQ(com.directions.intervals.size(), 1u);
    EXPECT_NEAR(com.directions.intervals[0].from, -std::atan(2.0), 1e-15);
    EXPECT_EQ(com.directions.intervals[0].to, 0.0);
}

// A centre a hair's breadth from the contact (0, 0): the spring directions through it that
// produce rr are nearly the one direction of the contact force's line, an arc of about 1e-16.
// The best direction lies in the arc and the margin is half of it (they were computed from acos
// of the ends' dot product, which made the margin 1e-8 and put the best outside the arc).
TEST(Comply, BestDirectionLiesInItsArcEvenWhenTheArcIsTiny) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const ComplyPlan near = plan_comply(rr_of(analysis), Vec2(1e-16, 0));
    ASSERT_EQ(near.directions.intervals.size(), 1u);
    const AngleInterval& arc = near.directions.intervals[0];
    EXPECT_LE(arc.from, near.directions.best);
    EXPECT_LE(near.directions.best, arc.to);
    EXPECT_LE(near.directions.margin, (arc.to - arc.from) / 2.0 + 1e-300);
    EXPECT_LT(arc.to - arc.from, 1e-15);
}


// Issue 44, item 1, for springs: the antipodal grasp of test_tilt's
// GoalHoldingEveryTiltButSharingOneIsAloneOnTheRestOfTheTurn (E_ff = R^3, quasi-static), with the
// compliance centre at (0, 1): the spring forces through it are the tilts there, so ff is alone
// on every direction but (1, 0), which sf's -FC_2 (forces through (2, 1)) shares. The exact LP
// on the raw numbers: (1, 0) through (0, 1) is in E_ff and E_sf, (-1, 0) in E_ff alone.
TEST(Comply, GoalHoldingEveryDirectionButSharingOneIsAloneOnTheRestOfTheTurn) {
    const Scene scene = read_scene_text(
        R"({"body": {"mass": 1, "com": [0, 1], "inertia": 1}, "contacts": [{"point": [0, 0], "normal": [1, 1], "mu": 0.5, "mu_kinetic": 2}, {"point": [2, 1], "normal": [-4, -1], "mu": 0.5, "mu_kinetic": 2}]})");
    const auto analysis = analyze(scene, AnalysisOptions{.quasi_static = true});
    const auto holding = [&](const reference::QVec& e) {
        std::string out;
        for (const ModeForces& m : analysis) {
            if (testing::exact_lp_quasi_static_in_mode(scene, m.mode.letters, e)) out += m.mode.letters + " ";
        }
        return out;
    };
    EXPECT_EQ(holding(reference::wrench(0, 1, 1, 0)), "ff sf ");
    EXPECT_EQ(holding(reference::wrench(0, 1, -1, 0)), "ff ");
    const ModeForces* ff = nullptr;
    for (const ModeForces& m : analysis) ff = m.mode.letters == "ff" ? &m : ff;
    ASSERT_NE(ff, nullptr);
    const ComplyPlan plan = plan_comply(*ff, Vec2(0, 1), PlanContext{.modes = analysis, .fixed = std::nullopt, .metric = std::nullopt});
    const DirectionPlan& d = plan.directions;
    ASSERT_EQ(d.unique.size(), 1u);
    EXPECT_EQ(d.unique[0].from, -M_PI);
    EXPECT_EQ(d.unique[0].to, M_PI);
    ASSERT_EQ(d.shared.size(), 1u);
    EXPECT_EQ(d.shared[0].from, 0.0);
    EXPECT_EQ(d.shared[0].to, 0.0);
    EXPECT_TRUE(d.best_unique);
    EXPECT_EQ(std::abs(d.best), M_PI);
    EXPECT_EQ(d.margin, M_PI);
}

}  // namespace
}  // namespace momentlab
