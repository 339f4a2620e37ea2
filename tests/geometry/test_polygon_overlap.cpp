// polygons_overlap against an oracle in integer arithmetic that shares nothing with it: each
// polygon cut into triangles by ear clipping, and two triangles' interiors meet unless an edge
// line of one has the other wholly on its closed outer side (separating axes). Small grids make
// touching, shared edges, collinear overlaps and vertices on edges the rule. The point returned
// is checked strictly inside both in exact rationals (GMP).
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "momentlab/geometry/polygon.hpp"

namespace momentlab {
namespace {

using P = std::array<long, 2>;
using Triangle = std::array<P, 3>;

long cross(const P& o, const P& a, const P& b) { return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]); }

// x in the closed triangle abc (counter-clockwise).
bool in_closed_triangle(const P& x, const Triangle& t) {
    return cross(t[0], t[1], x) >= 0 && cross(t[1], t[2], x) >= 0 && cross(t[2], t[0], x) >= 0;
}

// Ear clipping of a simple polygon (counter-clockwise, vertices distinct): straight vertices
// dropped (they change no point), then a convex vertex whose closed triangle holds no other
// vertex is cut off, until three are left.
std::vector<Triangle> triangles(std::vector<P> v) {
    long area2 = 0;
    for (std::size_t i = 0; i < v.size(); ++i) area2 += cross({0, 0}, v[i], v[(i + 1) % v.size()]);
    if (area2 < 0) std::reverse(v.begin(), v.end());
    std::vector<Triangle> out;
    while (true) {
        for (std::size_t i = 0; i < v.size() && v.size() > 3;) {
            const std::size_t n = v.size();
            if (cross(v[(i + n - 1) % n], v[i], v[(i + 1) % n]) == 0) {
                v.erase(v.begin() + static_cast<long>(i));
            } else {
                ++i;
            }
        }
        const std::size_t n = v.size();
        if (n == 3) {
            out.push_back({v[0], v[1], v[2]});
            return out;
        }
        bool cut = false;
        for (std::size_t i = 0; i < n && !cut; ++i) {
            const Triangle t{v[(i + n - 1) % n], v[i], v[(i + 1) % n]};
            if (cross(t[0], t[1], t[2]) <= 0) continue;
            bool empty = true;
            for (std::size_t j = 0; j < n && empty; ++j) {
                if (j != i && j != (i + 1) % n && j != (i + n - 1) % n && in_closed_triangle(v[j], t)) empty = false;
            }
            if (!empty) continue;
            out.push_back(t);
            v.erase(v.begin() + static_cast<long>(i));
            cut = true;
        }
        if (!cut) throw std::logic_error("no ear");
    }
}

// Interiors of two counter-clockwise triangles meet: no edge of either separates them.
bool triangles_overlap(const Triangle& a, const Triangle& b) {
    const auto separates = [](const Triangle& s, const Triangle& t) {
        for (int k = 0; k < 3; ++k) {
            const P &p = s[k], &q = s[(k + 1) % 3];
            if (cross(p, q, t[0]) <= 0 && cross(p, q, t[1]) <= 0 && cross(p, q, t[2]) <= 0) return true;
        }
        return false;
    };
    return !separates(a, b) && !separates(b, a);
}

bool oracle_overlap(const std::vector<P>& a, const std::vector<P>& b) {
    for (const Triangle& s : triangles(a)) {
        for (const Triangle& t : triangles(b)) {
            if (triangles_overlap(s, t)) return true;
        }
    }
    return false;
}

// Where x lies from the polygon, in rationals: 1 inside, 0 on the boundary, -1 outside (the
// winding number of exact crossings).
int locate(const std::vector<P>& v, const mpq_class& px, const mpq_class& py) {
    int winding = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const P &a = v[i], &b = v[(i + 1) % v.size()];
        const mpq_class side = (mpq_class(b[0]) - a[0]) * (py - a[1]) - (mpq_class(b[1]) - a[1]) * (px - a[0]);
        const bool in_box = px >= std::min(a[0], b[0]) && px <= std::max(a[0], b[0]) && py >= std::min(a[1], b[1]) &&
                            py <= std::max(a[1], b[1]);
        if (side == 0 && in_box) return 0;
        if (a[1] <= py) {
            if (b[1] > py && side > 0) ++winding;
        } else if (b[1] <= py && side < 0) {
            --winding;
        }
    }
    return winding != 0 ? 1 : -1;
}

std::vector<Vec2> doubles(const std::vector<P>& v, double scale, const Vec2& shift) {
    std::vector<Vec2> out;
    for (const P& p : v) out.push_back(Vec2(static_cast<double>(p[0]), static_cast<double>(p[1])) * scale + shift);
    return out;
}

TEST(PolygonOverlap, AgreesWithTrianglesOnSmallGrids) {
    std::mt19937 rng(46);
    const auto random_simple = [&](long grid) {
        while (true) {
            std::vector<P> v;
            const int n = 3 + static_cast<int>(rng() % 5);
            for (int i = 0; i < n; ++i) v.push_back({static_cast<long>(rng() % (grid + 1)), static_cast<long>(rng() % (grid + 1))});
            if (polygon_problem(doubles(v, 1.0, Vec2::Zero())).empty()) return v;
        }
    };
    int overlapping = 0, apart = 0, touching = 0;
    for (int t = 0; t < 6000; ++t) {
        const long grid = 2 + static_cast<long>(rng() % 3);
        const std::vector<P> a = random_simple(grid), b = random_simple(grid);
        const bool expected = oracle_overlap(a, b);
        // Scaled by 1/4 and moved by a dyadic offset: still exact doubles, the same answer.
        const Vec2 shift(-1.25, 3.5);
        const std::vector<Vec2> da = doubles(a, 0.25, shift), db = doubles(b, 0.25, shift);
        const std::optional<Vec2> got = polygons_overlap(da, db);
        ASSERT_EQ(got.has_value(), expected) << "pair " << t;
        ASSERT_EQ(polygons_overlap(db, da).has_value(), expected) << "pair " << t << " swapped";
        if (expected) {
            ++overlapping;
            const mpq_class x = (mpq_class(got->x()) - shift.x()) * 4, y = (mpq_class(got->y()) - shift.y()) * 4;
            ASSERT_TRUE(locate(a, x, y) == 1 && locate(b, x, y) == 1) << "pair " << t << ": " << got->transpose();
        } else {
            ++apart;
            // Touching: a vertex of one on the other's outline.
            touching += std::any_of(a.begin(), a.end(), [&](const P& p) { return locate(b, p[0], p[1]) == 0; }) ? 1 : 0;
        }
    }
    std::cout << "[PolygonOverlap] " << overlapping << " overlapping, " << apart << " not (" << touching << " touching)\n";
    EXPECT_GE(overlapping, 1000);
    EXPECT_GE(touching, 300);
}

// The ladder: drawn 0.1 into its wall it overlaps; exactly against the wall it touches; a
// vertex one unit in the last place into the wall (far below any contact tolerance) overlaps, one
// short does not.
TEST(PolygonOverlap, LadderAgainstItsWall) {
    const std::vector<Vec2> wall{{2, 0}, {3, 0}, {3, 5}, {2, 5}};
    const auto ladder = [](double top_x) {
        return std::vector<Vec2>{{0, 0}, {0.125, 0}, {top_x, 4}, {top_x - 0.125, 4}};
    };
    const std::optional<Vec2> into = polygons_overlap(ladder(2.1), wall);
    ASSERT_TRUE(into.has_value());
    EXPECT_GT(into->x(), 2.0);
    EXPECT_LT(into->x(), 2.1);
    EXPECT_FALSE(polygons_overlap(ladder(2.0), wall).has_value());
    EXPECT_TRUE(polygons_overlap(ladder(std::nextafter(2.0, 3.0)), wall).has_value());
    EXPECT_FALSE(polygons_overlap(ladder(std::nextafter(2.0, 0.0)), wall).has_value());
}

// A body inside an obstacle, an obstacle inside a body (no edges meet), and equal polygons.
TEST(PolygonOverlap, NestedAndEqual) {
    const std::vector<Vec2> big{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, small{{1, 1}, {2, 1}, {1, 2}};
    EXPECT_TRUE(polygons_overlap(big, small).has_value());
    EXPECT_TRUE(polygons_overlap(small, big).has_value());
    EXPECT_TRUE(polygons_overlap(big, big).has_value());
    const std::vector<Vec2> far{{10, 10}, {11, 10}, {10, 11}};
    EXPECT_FALSE(polygons_overlap(big, far).has_value());
}

}  // namespace
}  // namespace momentlab
