// polygon_problem against a brute-force oracle in integer arithmetic on small grids, where
// degeneracies (collinear, touching, repeated vertices) are the rule.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>

#include "momentlab/geometry/polygon.hpp"

namespace momentlab {
namespace {

using P = std::array<long, 2>;

long cross(const P& o, const P& a, const P& b) { return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]); }
long dot(const P& o, const P& a, const P& b) { return (a[0] - o[0]) * (b[0] - o[0]) + (a[1] - o[1]) * (b[1] - o[1]); }

// Closed segments ab and cd share a point: solve a + t (b - a) = c + u (d - c) for t, u in
// [0, 1] by Cramer's rule; parallel segments share a point iff collinear and their projections
// on the common line overlap.
bool meet(const P& a, const P& b, const P& c, const P& d) {
    const long den = (b[0] - a[0]) * (d[1] - c[1]) - (b[1] - a[1]) * (d[0] - c[0]);
    const long tn = (c[0] - a[0]) * (d[1] - c[1]) - (c[1] - a[1]) * (d[0] - c[0]);
    const long un = (c[0] - a[0]) * (b[1] - a[1]) - (c[1] - a[1]) * (b[0] - a[0]);
    if (den != 0) {
        auto in01 = [den](long num) { return den > 0 ? (num >= 0 && num <= den) : (num <= 0 && num >= den); };
        return in01(tn) && in01(un);
    }
    if (cross(a, b, c) != 0) return false;  // parallel, not collinear
    const long len = dot(a, b, b);             // project onto ab
    const long pc = dot(a, b, c), pd = dot(a, b, d);
    return std::max(std::min(pc, pd), 0L) <= std::min(std::max(pc, pd), len);
}

bool simple(const std::vector<P>& v) {
    const std::size_t n = v.size();
    if (n < 3) return false;
    for (std::size_t i = 0; i < n; ++i) {
        if (v[i] == v[(i + 1) % n]) return false;
    }
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            const P &a = v[i], &b = v[(i + 1) % n], &c = v[j], &d = v[(j + 1) % n];
            if (j == i + 1 || (i == 0 && j == n - 1)) {
                // Adjacent: only the shared vertex may be common, so the edges must not be
                // collinear and pointing the same way from it.
                const P& s = j == i + 1 ? b : a;
                const P& x = j == i + 1 ? a : b;
                const P& y = j == i + 1 ? d : c;
                if (cross(s, x, y) == 0 && dot(s, x, y) > 0) return false;
                continue;
            }
            if (meet(a, b, c, d)) return false;
        }
    }
    return true;
}

TEST(Polygon, ProblemAgreesWithBruteForceOnSmallGrids) {
    std::mt19937 rng(99);
    int simple_count = 0, problem_count = 0;
    for (int t = 0; t < 20000; ++t) {
        const int n = 3 + static_cast<int>(rng() % 5);
        const long grid = 2 + static_cast<long>(rng() % 3);
        std::vector<P> v;
        std::vector<Vec2> poly;
        for (int i = 0; i < n; ++i) {
            v.push_back({static_cast<long>(rng() % (grid + 1)), static_cast<long>(rng() % (grid + 1))});
            poly.emplace_back(static_cast<double>(v.back()[0]) * 0.5 - 1.0, static_cast<double>(v.back()[1]) * 0.5 + 3.0);
        }
        const bool expected = simple(v);
        const std::string problem = polygon_problem(poly);
        ASSERT_EQ(problem.empty(), expected) << "polygon " << t << ": " << problem;
        (expected ? simple_count : problem_count)++;
    }
    std::cout << "[Polygon] " << simple_count << " simple, " << problem_count << " not\n";
    EXPECT_GE(simple_count, 1000);
    EXPECT_GE(problem_count, 1000);
}

// Larger polygons for the sweep line: star-shaped outlines about a centre on a small grid (radii
// from the grid, so vertices often land on other edges, repeat, or line up), either orientation;
// a named pair of edges must really meet.
TEST(Polygon, StarPolygonsAgreeWithTheOracle) {
    std::mt19937 rng(2026);
    int simple_count = 0, problem_count = 0;
    for (int t = 0; t < 3000; ++t) {
        const int n = 8 + static_cast<int>(rng() % 60);
        std::vector<std::pair<double, P>> around;
        for (int i = 0; i < n; ++i) {
            const double angle = 2 * M_PI * (i + 0.3 * (rng() % 4) / 4.0) / n;
            const long r = 2 + static_cast<long>(rng() % (t % 3 == 0 ? 3 : 8));
            around.push_back({angle, {std::lround(r * std::cos(angle) * 2), std::lround(r * std::sin(angle) * 2)}});
        }
        std::vector<P> v;
        for (const auto& [a, q] : around) v.push_back(q);
        if (t % 2) std::reverse(v.begin(), v.end());
        if (t % 7 == 0) std::swap(v[rng() % n], v[rng() % n]);  // now and then a crossing
        std::vector<Vec2> poly;
        for (const P& q : v) poly.emplace_back(static_cast<double>(q[0]) * 0.25, static_cast<double>(q[1]) * 0.25 - 3.0);
        const bool expected = simple(v);
        const std::string problem = polygon_problem(poly);
        ASSERT_EQ(problem.empty(), expected) << "polygon " << t << ": " << problem;
        (expected ? simple_count : problem_count)++;
        std::size_t i = 0, j = 0;
        if (std::sscanf(problem.c_str(), "edges %zu and %zu cross", &i, &j) == 2) {
            ASSERT_TRUE(meet(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n])) << "polygon " << t << ": " << problem;
        }
    }
    std::cout << "[Polygon] stars: " << simple_count << " simple, " << problem_count << " not\n";
    EXPECT_GE(simple_count, 300);
    EXPECT_GE(problem_count, 300);
}

// orient2d against GMP rationals from the raw doubles: random points at scales 2^-1074..2^1000,
// nearly collinear ones (a rounded point of the line ab, nudged by one unit in the last place),
// exactly collinear ones on grids and along axis-parallel lines, and differences that round.
TEST(Polygon, Orient2dIsExactAtEveryMagnitude) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-1074, 1000);
    auto oracle = [](const Vec2& a, const Vec2& b, const Vec2& c) {
        const mpq_class d = (mpq_class(b.x()) - a.x()) * (mpq_class(c.y()) - a.y()) -
                            (mpq_class(b.y()) - a.y()) * (mpq_class(c.x()) - a.x());
        return sgn(d);
    };
    int zeros = 0, nonzero = 0;
    for (int i = 0; i < 200000; ++i) {
        const int k = exponent(rng) % (i % 4 == 0 ? 1075 : 60);
        const double s = std::ldexp(1.0, k);
        Vec2 a(unit(rng) * s, unit(rng) * s), b(unit(rng) * s, unit(rng) * s), c;
        switch (i % 6) {
            case 0: c = Vec2(unit(rng) * s, unit(rng) * s); break;
            case 1: c = a + unit(rng) * (b - a); break;  // on the line, rounded
            case 2: {
                c = a + unit(rng) * (b - a);
                c.x() = std::nextafter(c.x(), (rng() & 1) ? 1e308 : -1e308);
                break;
            }
            case 3: {  // a grid of step s: exact differences, collinear one time in a few
                auto g = [&] { return std::ldexp(static_cast<double>(static_cast<int>(rng() % 5)), k); };
                a = Vec2(g(), g()), b = Vec2(g(), g()), c = Vec2(g(), g());
                break;
            }
            case 4: c = Vec2(unit(rng) * s, a.y()), b.y() = a.y(); break;  // along y = a.y
            default: c = 2.0 * b - a; break;                               // often exactly collinear
        }
        if (!c.allFinite()) continue;
        const int expected = oracle(a, b, c);
        (expected == 0 ? zeros : nonzero)++;
        ASSERT_EQ(to_int(orient2d(a, b, c)), expected) << i << " " << a.transpose() << " | " << b.transpose() << " | " << c.transpose();
        ASSERT_EQ(to_int(orient2d(b, c, a)), expected) << i;
        ASSERT_EQ(to_int(orient2d(b, a, c)), -expected) << i;
    }
    std::cout << "[Polygon] orient2d: " << zeros << " collinear, " << nonzero << " not\n";
    EXPECT_GT(zeros, 20000);
    EXPECT_GT(nonzero, 100000);
}

TEST(Polygon, NamesTheProblem) {
    EXPECT_EQ(polygon_problem(std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}}), "");
    EXPECT_EQ(polygon_problem(std::vector<Vec2>{{0, 0}, {0, 1}, {1, 0}}), "");  // clockwise
    EXPECT_NE(polygon_problem(std::vector<Vec2>{{0, 0}, {1, 1}, {1, 0}, {0, 1}}).find("edges 0 and 2 cross"), std::string::npos);
    EXPECT_NE(polygon_problem(std::vector<Vec2>{{0, 0}, {1, 0}}).find("at least 3"), std::string::npos);
    EXPECT_NE(polygon_problem(std::vector<Vec2>{{0, 0}, {1, 0}, {2, 0}}).find("fold back"), std::string::npos);
    // A vertex touching a non-adjacent edge 2^-60 inside it is found; 2^-60 outside is not.
    const double h = 0x1p-60;
    EXPECT_NE(polygon_problem(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {1, -h}, {0, 2}}), "");
    EXPECT_EQ(polygon_problem(std::vector<Vec2>{{0, 0}, {2, 0}, {2, 2}, {1, h}, {0, 2}}), "");
}

}  // namespace
}  // namespace momentlab
