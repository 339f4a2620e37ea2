// The paper's Figure 1 and 2 force sets, worked by hand, and the counterexample of docs/design.md
// to the paper's "convex hull of the + regions" shorthand for intersections.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "../common/label_checks.hpp"
#include "momentlab/geometry/force_sets.hpp"
#include "momentlab/geometry/labels.hpp"

namespace momentlab {
namespace {

using testing::has_direction;
using testing::has_vertex;

TEST(Labels, Figure1aLineOfForce) {
    // A force along +x through the origin: + to its left (y > 0), - to its right, both on it.
    const Labels l(force_ray(Vec2(0, 0), Vec2(1, 0)));
    EXPECT_EQ(l.plus().kind(), "half-plane");
    EXPECT_EQ(l.minus().kind(), "half-plane");
    EXPECT_EQ(l.at(Vec2(3, 1)), Label::Plus);
    EXPECT_EQ(l.at(Vec2(-3, -1)), Label::Minus);
    EXPECT_EQ(l.at(Vec2(7, 0)), Label::Both);
    EXPECT_TRUE(has_direction(l.plus().rays, Vec2(0, 1)));
    EXPECT_TRUE(has_direction(l.minus().rays, Vec2(0, -1)));
    // Both senses: every point of the line is +-, no other point is labelled.
    const Labels both(line_of_force(Vec2(0, 0), Vec2(1, 0)));
    EXPECT_EQ(both.plus().kind(), "line");
    EXPECT_EQ(both.at(Vec2(5, 0)), Label::Both);
    EXPECT_EQ(both.at(Vec2(5, 1)), Label::None);
}

TEST(Labels, Figure1bForcesThroughAPoint) {
    const Labels l(forces_through_point(Vec2(1, 2)));
    EXPECT_EQ(l.plus().kind(), "point");
    EXPECT_EQ(l.minus().kind(), "point");
    EXPECT_TRUE(has_vertex(l.plus(), Vec3(1, 2, 1)));
    EXPECT_TRUE(has_vertex(l.minus(), Vec3(1, 2, 1)));
    EXPECT_EQ(l.at(Vec2(1, 2)), Label::Both);
    EXPECT_EQ(l.at(Vec2(1, 2.5)), Label::None);
}

TEST(Labels, Figure1cFrictionCone) {
    // Contact at the origin, normal +y, mu = 1/2: edges (+-1/2, 1). The moment of (fx, fy)
    // at the origin about (x, y) is y fx - x fy, so + needs y/2 - x >= 0 and -y/2 - x >= 0:
    // the wedge x <= -|y|/2 to the left; - is x >= |y|/2. The apex is in both.
    const Labels l(friction_cone(Vec2(0, 0), Vec2(0, 1), 0.5));
    EXPECT_EQ(l.plus().kind(), "unbounded");
    EXPECT_TRUE(has_vertex(l.plus(), Vec3(0, 0, 1)));
    EXPECT_TRUE(has_direction(l.plus().rays, Vec2(-1, 2)));
    EXPECT_TRUE(has_direction(l.plus().rays, Vec2(-1, -2)));
    EXPECT_TRUE(has_direction(l.minus().rays, Vec2(1, 2)));
    EXPECT_TRUE(has_direction(l.minus().rays, Vec2(1, -2)));
    EXPECT_EQ(l.at(Vec2(0, 0)), Label::Both);
    EXPECT_EQ(l.at(Vec2(-1, 2)), Label::Plus);     // on the boundary y = -2x
    EXPECT_EQ(l.at(Vec2(-1, 2.001)), Label::None);
    EXPECT_EQ(l.at(Vec2(4, 1)), Label::Minus);
}

TEST(Labels, Figure2TwoFrictionCones) {
    // A: (0,0), normal (0,1), mu 1/2 (see Figure1c). B: (2,0), normal (-1,1), mu 1/2: edges
    // (-1/2, 3/2) and (-3/2, 1/2); + needs 3x + y <= 6 and x + 3y <= 2. The + region of the
    // resultants is x <= -|y|/2, x + 3y <= 2 (3x + y <= 6 is implied): vertices (0,0) and
    // y = -2x meets x + 3y = 2 at (-2/5, 4/5); rays along (-3, 1) and (-1, -2).
    // The - region: x >= |y|/2, 3x + y >= 6, x + 3y >= 2: vertices (2, 0) and (6/5, 12/5)
    // (y = 2x meets 3x + y = 6); rays along (3, -1) and (1, 2).
    const Cone a = friction_cone(Vec2(0, 0), Vec2(0, 1), 0.5);
    const Cone b = friction_cone(Vec2(2, 0), Vec2(-1, 1), 0.5);
    const Labels la(a), lb(b), l(sum(a, b));
    EXPECT_EQ(l.plus().vertices.size(), 2u);
    EXPECT_TRUE(has_vertex(l.plus(), Vec3(0, 0, 1)));
    EXPECT_TRUE(has_vertex(l.plus(), Vec3(-2, 4, 5)));
    EXPECT_TRUE(has_direction(l.plus().rays, Vec2(-3, 1)));
    EXPECT_TRUE(has_direction(l.plus().rays, Vec2(-1, -2)));
    EXPECT_EQ(l.minus().vertices.size(), 2u);
    EXPECT_TRUE(has_vertex(l.minus(), Vec3(2, 0, 1)));
    EXPECT_TRUE(has_vertex(l.minus(), Vec3(6, 12, 5)));
    EXPECT_TRUE(has_direction(l.minus().rays, Vec2(3, -1)));
    EXPECT_TRUE(has_direction(l.minus().rays, Vec2(1, 2)));
    // The paper's rule for resultants: intersect the labels, point by point.
    for (double x = -4; x <= 4; x += 0.25) {
        for (double y = -4; y <= 4; y += 0.25) {
            const Vec2 p(x, y);
            const Label pa = la.at(p), pb = lb.at(p), pl = l.at(p);
            const bool plus = (pa == Label::Plus || pa == Label::Both) && (pb == Label::Plus || pb == Label::Both);
            const bool minus = (pa == Label::Minus || pa == Label::Both) && (pb == Label::Minus || pb == Label::Both);
            EXPECT_EQ(pl == Label::Plus || pl == Label::Both, plus) << x << " " << y;
            EXPECT_EQ(pl == Label::Minus || pl == Label::Both, minus) << x << " " << y;
        }
    }
}

TEST(Labels, ParallelRaysCounterexampleToHullShorthand) {
    // Two forces along +x, on y = 0 and on y = 1: the only common wrench is 0.
    const Cone f = force_ray(Vec2(0, 0), Vec2(1, 0));
    const Cone g = force_ray(Vec2(0, 1), Vec2(1, 0));
    const Cone meet = intersection(f, g);
    EXPECT_EQ(meet.kind(), "{0}");
    const Labels l(meet);
    EXPECT_EQ(l.plus().kind(), "plane");  // labels of {0}: the whole plane, twice
    EXPECT_EQ(l.minus().kind(), "plane");
    // The paper's shorthand would take the planar hull of F+ = {y >= 0} and G+ = {y >= 1}:
    // the half-plane y >= 0, which misses (0, -1). The true label there is +-.
    const Labels lf(f), lg(g);
    EXPECT_EQ(lf.at(Vec2(0, -1)), Label::Minus);
    EXPECT_EQ(lg.at(Vec2(0, -1)), Label::Minus);
    EXPECT_EQ(l.at(Vec2(0, -1)), Label::Both);
}

TEST(Labels, DegenerateForceSets) {
    EXPECT_EQ(Labels(Cone()).plus().kind(), "plane");
    EXPECT_EQ(Labels(Cone::whole_space()).plus().kind(), "empty");
    const Labels moments(pure_moments(0));
    EXPECT_TRUE(moments.plus().is_empty && moments.minus().is_empty);
    const Labels ccw(pure_moments(1));  // a positive moment is + about every point
    EXPECT_EQ(ccw.plus().kind(), "plane");
    EXPECT_EQ(ccw.minus().kind(), "empty");
    EXPECT_EQ(ccw.at(Vec2(5, -3)), Label::Plus);
}

// F = {w : the moment of w about each listed point is >= 0}. Then F* is generated by those
// moment functionals, so the + region is the convex hull of the points (plus directions at
// infinity for functionals (y, -x, 0) given as directions).
Cone nonnegative_moments_about(std::initializer_list<Vec3> homogeneous_points) {
    std::vector<Vec3> normals;
    for (const Vec3& x : homogeneous_points) normals.emplace_back(x.y(), -x.x(), x.z());
    return Cone::from_halfspaces(normals);
}

TEST(Labels, RegionKindsBuiltFromMomentConditions) {
    const Labels segment(nonnegative_moments_about({Vec3(0, 0, 1), Vec3(2, 1, 1)}));
    EXPECT_EQ(segment.plus().kind(), "segment");
    EXPECT_EQ(segment.minus().kind(), "empty");
    EXPECT_EQ(segment.at(Vec2(1, 0.5)), Label::Plus);   // on the segment
    EXPECT_EQ(segment.at(Vec2(4, 2)), Label::None);     // on its line, beyond b
    const Labels ray(nonnegative_moments_about({Vec3(1, 1, 1), Vec3(1, 0, 0)}));
    EXPECT_EQ(ray.plus().kind(), "ray");
    EXPECT_EQ(ray.at(Vec2(5, 1)), Label::Plus);
    EXPECT_EQ(ray.at(Vec2(0, 1)), Label::None);
    const Labels triangle(nonnegative_moments_about({Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1)}));
    EXPECT_EQ(triangle.plus().kind(), "polygon");
    EXPECT_EQ(triangle.plus().vertices.size(), 3u);
    EXPECT_EQ(triangle.at(Vec2(0.25, 0.25)), Label::Plus);
    EXPECT_EQ(triangle.at(Vec2(0.75, 0.75)), Label::None);
    // Two points and both directions of a line: the strip between two parallel lines.
    const Labels strip(nonnegative_moments_about({Vec3(0, 0, 1), Vec3(0, 1, 1), Vec3(1, 0, 0), Vec3(-1, 0, 0)}));
    EXPECT_EQ(strip.plus().kind(), "strip");
    EXPECT_EQ(strip.at(Vec2(100, 0.5)), Label::Plus);
    EXPECT_EQ(strip.at(Vec2(0, 1.5)), Label::None);
    // The round trip recovers each of these force sets exactly.
    for (const Labels* l : {&segment, &ray, &triangle, &strip}) {
        EXPECT_TRUE(Labels::forces_from_regions(l->plus(), l->minus()) == l->forces()) << l->plus().kind();
    }
}

// Regression: a point or a line was cut out of the box by two opposite half-planes, and a box
// not symmetric about it rounded the cut to nothing (the apex of Figure 2's first cone vanished).
TEST(Labels, ClippedPointsAndLinesSurviveAsymmetricBoxes) {
    // The span of a friction cone at (0, 0) and of a slanted line of force through it: their
    // labels are the point (0, 0) and the line y = 2 x, cut by boxes around them.
    const std::vector<Vec3> cone_span = {Vec3(0.5, 1, 0), Vec3(-0.5, 1, 0)};
    const Region point = Labels(Cone::from_generators(std::span<const Vec3>(), cone_span)).plus();
    const Region line = Labels(line_of_force(Vec2(0, 0), Vec2(1, 2))).plus();
    ASSERT_EQ(point.kind(), "point");
    ASSERT_EQ(line.kind(), "line");
    std::mt19937_64 rng(7);
    auto coordinate = [&](double lo, double hi) { return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1p-53; };
    for (int i = 0; i < 2000; ++i) {
        const Box box{Vec2(coordinate(-9, -0.1), coordinate(-9, -0.1)), Vec2(coordinate(0.1, 9), coordinate(0.1, 9))};
        const std::vector<Vec2> p = point.clipped(box);
        ASSERT_EQ(p.size(), 1u) << i;
        EXPECT_EQ(p[0], Vec2(0, 0));
        const std::vector<Vec2> l = line.clipped(box);
        ASSERT_EQ(l.size(), 2u) << i;
        for (const Vec2& q : l) EXPECT_NEAR(q.y(), 2 * q.x(), 1e-12 * box.max.norm());
    }
    EXPECT_TRUE(point.clipped(Box{Vec2(1, 1), Vec2(2, 2)}).empty());
}

TEST(Labels, ClippedRegionsStayInTheBox) {
    const Labels l(friction_cone(Vec2(0, 0), Vec2(0, 1), 0.5));
    const Box box{Vec2(-2, -2), Vec2(2, 2)};
    const auto poly = l.plus().clipped(box);
    ASSERT_GE(poly.size(), 3u);
    for (const Vec2& p : poly) {
        EXPECT_LE(p.x(), 1e-12);  // the + region lies left of the apex
        EXPECT_GE(p.x(), -2.0);
        EXPECT_LE(std::abs(p.y()), 2.0);
    }
    EXPECT_TRUE(Labels(forces_through_point(Vec2(5, 5))).plus().clipped(box).empty());
}

}  // namespace
}  // namespace momentlab
