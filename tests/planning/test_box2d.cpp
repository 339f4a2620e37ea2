// Plans checked physically with Box2D (reference/box2d_sim.hpp): the planned action, applied
// to the body from rest, produces the goal mode; actions just outside the computed sets do not.
#include <gtest/gtest.h>

#include "../common/examples.hpp"
#include "box2d_check.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/planning/comply.hpp"
#include "momentlab/planning/push.hpp"
#include "momentlab/planning/tilt.hpp"

namespace momentlab {
namespace {

constexpr double kForce = 10.0;  // newtons (the bodies weigh 1 kg)

Vec2 unit(double angle) { return Vec2(std::cos(angle), std::sin(angle)); }

physics::SimResult gravity(const Scene& scene, double angle) {
    return physics::simulate(scene, {kForce * scene.body->mass * unit(angle), scene.body->com});
}

const ModeForces& mode(const std::vector<ModeForces>& a, const std::string& letters) {
    for (const ModeForces& m : a) {
        if (m.mode.letters == letters) return m;
    }
    throw std::logic_error("no mode " + letters);
}

bool in_intervals(const DirectionPlan& plan, double angle) {
    const double a = std::remainder(angle, 2 * M_PI);
    for (const AngleInterval& i : plan.intervals) {
        if (i.from <= a && a <= i.to) return true;
    }
    return false;
}

// Box2D's contacts are the scene's: its manifold points lie on the scene's contact points.
TEST(Box2d, ContactPointsAreTheScenes) {
    for (const char* name : {"figure-3-block-along-wall.json", "figure-4-peg-in-hole.json", "rod-in-corner.json"}) {
        const Scene scene = testing::example_scene(name);
        const auto r = gravity(scene, -M_PI / 2);
        EXPECT_EQ(r.contact_points.size(), scene.contacts.size()) << name;
        for (const Vec2& p : r.contact_points) {
            double nearest = INFINITY;
            for (const Contact& c : scene.contacts) nearest = std::min(nearest, (c.point - p).norm());
            EXPECT_LT(nearest, 0.01) << name << ": " << p.transpose();
        }
    }
}

// Every mode a tilt can produce with a margin of at least 3 degrees, on every bundled scene:
// gravity at the best direction gives the mode; 3 degrees outside each end of the interval
// (where that direction is no longer in it) does not.
TEST(Box2d, TiltsProduceTheirModeAndJustOutsideDoNot) {
    int checked = 0;
    for (const char* name : {"figure-3-block-along-wall.json", "figure-4-peg-in-hole.json", "rod-in-corner.json"}) {
        const Scene scene = testing::example_scene(name);
        const auto analysis = analyze(scene);
        for (const ModeForces& goal : analysis) {
            const DirectionPlan plan = plan_tilt(scene, goal);
            if (!plan.feasible() || plan.margin < 3 * M_PI / 180) continue;
            // Only where the goal is the one answer (no Painleve ambiguity with another mode).
            if (query(analysis, wrench_at(scene.body->com, unit(plan.best))).verdict != Verdict::Unique) continue;
            const auto r = gravity(scene, plan.best);
            EXPECT_EQ(r.mode, goal.mode.letters) << name << " best " << plan.best;
            ++checked;
            for (const AngleInterval& i : plan.intervals) {
                for (const double outside : {i.from - 3 * M_PI / 180, i.to + 3 * M_PI / 180}) {
                    if (in_intervals(plan, outside)) continue;
                    EXPECT_NE(gravity(scene, outside).mode, goal.mode.letters) << name << " outside " << outside;
                }
            }
        }
    }
    EXPECT_GE(checked, 5);
}

// The feasible pushes of the block along the wall (the golden table): each case's best push
// slides the block along the wall without turning (rr), with the acceleration of the hand
// derivation: the wall pushes back with l (-1/2, 1), l = -fy, so m a = fx + fy / 2 along x.
TEST(Box2d, FeasiblePushesSlideTheBlockAlongTheWall) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    int feasible = 0;
    for (const PushCase& c : plan_push(scene, mode(analysis, "rr"))) {
        if (!c.feasible()) continue;
        ++feasible;
        const Vec2 force = kForce * c.best->direction;
        const physics::SimOptions options;
        const auto r = physics::simulate(scene, {force, c.best->point}, options);
        EXPECT_EQ(r.mode, "rr") << c.feature.name() << " " << c.slip;
        EXPECT_LT(std::abs(r.angle), 1e-4) << c.feature.name() << " " << c.slip;
        const double expected = (force.x() + force.y() / 2) / scene.body->mass * options.duration;
        EXPECT_NEAR(r.com_velocity.x(), expected, 0.02 * expected) << c.feature.name() << " " << c.slip;
        EXPECT_NEAR(r.com_velocity.y(), 0.0, 0.01 * expected) << c.feature.name() << " " << c.slip;
    }
    EXPECT_EQ(feasible, 5);
}

// Just outside: the trailing-edge push (1, -1/2) below the touch interval [3/16, 1/2], and the
// outboard vertex pushed 6 degrees outside its range of directions.
TEST(Box2d, PushesJustOutsideTheSolutionsDoNotSlideTheBlock) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const Vec2 l = Vec2(1, -0.5).normalized();
    EXPECT_NE(physics::simulate(scene, {kForce * l, Vec2(0, 0.1)}).mode, "rr");
    EXPECT_EQ(physics::simulate(scene, {kForce * l, Vec2(0, 0.3)}).mode, "rr");
    const double low = -std::atan(2.0), high = -std::atan(2.0 / 7.0), off = 6 * M_PI / 180;
    EXPECT_NE(physics::simulate(scene, {kForce * unit(low - off), Vec2(0, 0.5)}).mode, "rr");
    EXPECT_NE(physics::simulate(scene, {kForce * unit(high + off), Vec2(0, 0.5)}).mode, "rr");
    EXPECT_EQ(physics::simulate(scene, {kForce * unit((low + high) / 2), Vec2(0, 0.5)}).mode, "rr");
}

// A spring through the compliance centre: the best direction works from a centre that works;
// from a failing centre no sampled direction gives the goal.
TEST(Box2d, ComplianceCentres) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const ModeForces& rr = mode(analysis, "rr");
    for (const Vec2& centre : {Vec2(0, 0.5), Vec2(0.25, 0.5), Vec2(0.5, 0.25)}) {
        const ComplyPlan plan = plan_comply(rr, centre);
        ASSERT_EQ(plan.verdict, CentreVerdict::Works);
        EXPECT_EQ(physics::simulate(scene, {kForce * unit(plan.directions.best), centre}).mode, "rr") << centre.transpose();
    }
    // (2, 1) is inside E_rr's + region (y > 1/4, x + y/2 > 1: test_comply): every spring force
    // through it turns or stops the block.
    ASSERT_EQ(plan_comply(rr, Vec2(2, 1)).verdict, CentreVerdict::Fails);
    for (int k = 0; k < 36; ++k) {
        const double angle = -M_PI + (k + 0.5) * M_PI / 18;
        EXPECT_NE(physics::simulate(scene, {kForce * unit(angle), Vec2(2, 1)}).mode, "rr") << angle;
    }
}

// Gravity every 5 degrees on the bundled scenes (rounded to doubles: cos and sin of k 5
// degrees): wherever query gives one mode with a margin and the independent LCP says every
// contact is readable (reference/box2d_check.hpp, decided before Box2D runs), Box2D shows that
// mode letter for letter, or else Siconos' enumeration of the LCP shows that every solution
// has query's mode (Box2D alone is wrong). No other disagreement is allowed.
TEST(Box2d, GravitySweepAgreesWithQuery) {
    for (const char* name : {"figure-3-block-along-wall.json", "figure-4-peg-in-hole.json", "rod-in-corner.json"}) {
        const Scene scene = testing::example_scene(name);
        const auto analysis = analyze(scene);
        validation::CoulombLcp lcp(scene);
        int compared = 0, agree = 0, box2d_wrong = 0, not_compared = 0;
        std::ostringstream disagreements;
        for (int k = 0; k < 72; ++k) {
            const double angle = -M_PI + k * M_PI / 36;
            const Vec3 e = wrench_at(scene.body->com, unit(angle));
            const QueryResult q = query(analysis, e);
            if (q.verdict != Verdict::Unique || physics::unique_margin(analysis, q.modes[0], e) < 0.05 ||
                physics::readable(lcp, scene, e) != physics::Readable::Yes) {
                ++not_compared;
                continue;
            }
            ++compared;
            const std::string box2d = gravity(scene, angle).mode, predicted = analysis[q.modes[0]].mode.letters;
            if (box2d == predicted) {
                ++agree;
            } else if (physics::every_lcp_solution_has(lcp, e, predicted)) {
                ++box2d_wrong;
            } else {
                disagreements << " " << k * 5 - 180 << "deg:" << predicted << "/" << box2d;
            }
        }
        std::printf("%s: %d of %d compared agree with Box2D, %d more where Box2D alone differs from query and every "
                    "LCP solution; %d directions not compared%s\n",
                    name, agree, compared, box2d_wrong, not_compared, disagreements.str().c_str());
        EXPECT_GE(compared, 40) << name;
        EXPECT_EQ(agree + box2d_wrong, compared) << name << disagreements.str();
    }
}

}  // namespace
}  // namespace momentlab
