// Named cones whose answers are known by hand, one of every kind, plus exactness cases that
// a tolerance-based hull gets wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "momentlab/geometry/cone.hpp"

namespace momentlab {
namespace {

Cone gen(std::initializer_list<Vec3> g) { return Cone::from_generators(std::vector<Vec3>(g)); }

// True when `v` is a positive multiple of one of `list` (exactly).
bool has_direction(const std::vector<ExactVector>& list, const Vec3& v) {
    return std::any_of(list.begin(), list.end(), [&](const ExactVector& e) {
        return parallel(e.value(), v) && dot_sign(e.value(), v) == Sign::Positive;
    });
}

const Vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);

TEST(Cone, EveryKindFromGenerators) {
    struct Case {
        Cone cone;
        const char* kind;
        int dim, lin, rays, facets;
    };
    const Case cases[] = {
        {gen({}), "{0}", 0, 0, 0, 0},
        {gen({Vec3::Zero()}), "{0}", 0, 0, 0, 0},
        {gen({X, 2 * X}), "ray", 1, 0, 1, 1},
        {gen({X, -2 * X}), "line", 1, 1, 0, 0},
        {gen({X, Y, X + Y}), "wedge", 2, 0, 2, 2},
        {gen({X, -X, Y}), "half-plane", 2, 1, 1, 1},
        {gen({X, Y, -X - Y}), "plane", 2, 2, 0, 0},
        {gen({X, Y, Z}), "pointed cone", 3, 0, 3, 3},
        {gen({X, -X, Y, Z}), "wedge x line", 3, 1, 2, 2},
        {gen({X, -X, Y, -Y, Z}), "half-space", 3, 2, 1, 1},
        {gen({X, Y, Z, -X - Y - Z}), "R^3", 3, 3, 0, 0},
        {gen({X, -X, Y, -Y, Z, -Z}), "R^3", 3, 3, 0, 0},
    };
    for (const Case& c : cases) {
        EXPECT_EQ(c.cone.kind(), c.kind);
        EXPECT_EQ(c.cone.dimension(), c.dim) << c.kind;
        EXPECT_EQ(c.cone.lineality_dimension(), c.lin) << c.kind;
        EXPECT_EQ(c.cone.rays().size(), static_cast<std::size_t>(c.rays)) << c.kind;
        EXPECT_EQ(c.cone.facets().size(), static_cast<std::size_t>(c.facets)) << c.kind;
        // Duality is an involution and swaps the dimension with the codimension of lineality.
        EXPECT_TRUE(c.cone.dual().dual() == c.cone) << c.kind;
        EXPECT_EQ(c.cone.dual().dimension(), 3 - c.lin) << c.kind;
    }
}

TEST(Cone, OrthantHasCoordinateFacets) {
    const Cone c = gen({X, Y, Z, X + Y + Z, X + Y});  // two non-extreme generators
    ASSERT_EQ(c.rays().size(), 3u);
    for (const Vec3& v : {X, Y, Z}) {
        EXPECT_TRUE(has_direction(c.rays(), v));
        EXPECT_TRUE(has_direction(c.facets(), v));  // the facets of the orthant are x,y,z >= 0
    }
    EXPECT_EQ(c.faces().size(), 8u);  // itself, 3 facets, 3 rays, {0}
}

TEST(Cone, FaceLatticeOfEveryKind) {
    // Faces of a cone with lineality L are L + the faces of the pointed cone C / L.
    struct Case {
        Cone cone;
        std::size_t faces;
    };
    const Case cases[] = {
        {gen({}), 1},                       // {0}
        {gen({X}), 2},                      // ray: itself, {0}
        {gen({X, -X}), 1},                  // line
        {gen({X, Y}), 4},                   // wedge: itself, 2 rays, {0}
        {gen({X, -X, Y}), 2},               // half-plane: itself, its line
        {gen({X, Y, -X - Y}), 1},           // plane
        {gen({X, Y, Z, Vec3(1, 1, -1)}), 10},  // 4 rays: itself, 4 facets, 4 rays, {0}
        {gen({X, -X, Y, Z}), 4},            // wedge x line: itself, 2 facets, the line
        {gen({X, -X, Y, -Y, Z}), 2},        // half-space: itself, its plane
        {Cone::whole_space(), 1},
    };
    for (const Case& c : cases) {
        const auto faces = c.cone.faces();
        EXPECT_EQ(faces.size(), c.faces) << c.cone.kind();
        EXPECT_EQ(faces.front().dimension, c.cone.dimension());
        EXPECT_EQ(faces.back().dimension, c.faces == 1 ? c.cone.dimension() : c.cone.lineality_dimension());
    }
}

TEST(Cone, HalfSpaceAndWedgeTimesLineHaveTheirHandNormals) {
    const Cone h = gen({X, -X, Y, -Y, 3 * Z + X});
    ASSERT_EQ(h.facets().size(), 1u);
    EXPECT_TRUE(has_direction(h.facets(), Z));
    const Cone w = gen({X, -X, Y, Z});
    EXPECT_TRUE(has_direction(w.facets(), Y));
    EXPECT_TRUE(has_direction(w.facets(), Z));
}

TEST(Cone, GeneratorJustBelowAFacetIsExtreme) {
    // (1, 1, 0) lies on the facet z = 0 of the orthant; (1, 1, -2^-60) lies just outside and
    // is an extreme ray. A tolerance of 1e-12 would call both coplanar.
    EXPECT_EQ(gen({X, Y, Z, Vec3(1, 1, 0)}).rays().size(), 3u);
    EXPECT_EQ(gen({X, Y, Z, Vec3(1, 1, -0x1p-60)}).rays().size(), 4u);
    EXPECT_EQ(gen({X, Y, Z, Vec3(1, 1, 0x1p-60)}).rays().size(), 3u);
}

TEST(Cone, ScaleInvariantAcrossExponents) {
    // (-1, -1, 1e-3) + X + Y = (0, 0, 1e-3): Z is not extreme, the rays are X, Y, W.
    for (double s : {1e-300, 1e-150, 1.0, 1e150, 1e300}) {
        const Vec3 w(-1, -1, 1e-3);
        const Cone c = gen({s * X, s * Y, s * Z, s * Vec3(1, 1, 0), s * w});
        EXPECT_EQ(c.kind(), "pointed cone") << s;
        EXPECT_EQ(c.rays().size(), 3u) << s;
        EXPECT_TRUE(has_direction(c.rays(), s * w)) << s;  // the stored (rounded) generator
        EXPECT_TRUE(c.has(Vec3(1, 1, 1))) << s;
        EXPECT_EQ(gen({s * X, s * Y, s * Z, s * Vec3(1, 1, -0x1p-60)}).rays().size(), 4u) << s;
    }
}

TEST(Cone, ManyGeneratorsOnFacetsOfAPyramid) {
    std::vector<Vec3> g;
    for (int i = -20; i <= 20; ++i) {
        g.emplace_back(i, 20, 20);
        g.emplace_back(i, -20, 20);
        g.emplace_back(20, i, 20);
        g.emplace_back(-20, i, 20);
        g.emplace_back(i / 2, i / 3, 20);  // interior
    }
    const Cone c = Cone::from_generators(g);
    EXPECT_EQ(c.rays().size(), 4u);
    EXPECT_EQ(c.facets().size(), 4u);
    for (const Vec3& corner : {Vec3(1, 1, 1), Vec3(-1, 1, 1), Vec3(1, -1, 1), Vec3(-1, -1, 1)}) {
        EXPECT_TRUE(has_direction(c.rays(), corner));
    }
}

TEST(Cone, ContainsGivesCertificates) {
    const Cone c = gen({X, Y, Z});
    const Vec3 w(1, 2, 3);
    const Membership in = c.contains(w);
    ASSERT_TRUE(in.member);
    Vec3 sum = Vec3::Zero();
    for (const auto& [v, k] : in.combination) {
        EXPECT_GE(k, 0.0);
        sum += k * v;
    }
    EXPECT_NEAR((sum - w).norm(), 0.0, 1e-12);
    const Membership out = c.contains(Vec3(-1, 2, 3));
    ASSERT_FALSE(out.member);
    EXPECT_EQ(out.separator.dot_sign(Vec3(-1, 2, 3)), Sign::Negative);
    for (const Vec3& v : {X, Y, Z}) EXPECT_NE(out.separator.dot_sign(v), Sign::Negative);
    EXPECT_TRUE(c.in_relative_interior(Vec3(1, 1, 1)));
    EXPECT_FALSE(c.in_relative_interior(Vec3(1, 1, 0)));
    // Outside the span of a lower-dimensional cone the separator is an equation.
    const Cone wedge = gen({X, Y});
    const Membership off = wedge.contains(Z);
    ASSERT_FALSE(off.member);
    EXPECT_EQ(off.separator.dot_sign(Z), Sign::Negative);
}

TEST(Cone, SumIntersectionAndNegation) {
    const Cone a = gen({X, Y, Z});
    const Cone b = a.negated();
    EXPECT_EQ(sum(a, b).kind(), "R^3");
    EXPECT_EQ(intersection(a, b).kind(), "{0}");
    EXPECT_TRUE(intersection(a, gen({X, Y, -Z})) == gen({X, Y}));
    EXPECT_TRUE(sum(gen({X}), gen({-X})) == gen({X, -X}));
    Mat3 shear;
    shear << 1, 2, 0, 0, 1, 0, 0, 0, 1;
    EXPECT_TRUE(a.linear_image(shear) == gen({X, Vec3(2, 1, 0), Z}));
    EXPECT_THROW((void)a.linear_image(Mat3::Zero()), std::invalid_argument);
    EXPECT_THROW((void)gen({Vec3(std::nan(""), 0, 0)}), std::invalid_argument);
}

TEST(Cone, FromHalfspaces) {
    const std::vector<Vec3> n = {X, Y, Z};
    const Cone c = Cone::from_halfspaces(n);
    EXPECT_EQ(c.exact_representation(), Representation::Halfspaces);
    EXPECT_TRUE(c == gen({X, Y, Z}));
    EXPECT_TRUE(Cone::from_halfspaces(std::vector<Vec3>{}) == Cone::whole_space());
    EXPECT_TRUE(Cone::from_halfspaces(std::vector<Vec3>{X, -X}) == gen({Y, -Y, Z, -Z}));
}


// The documented order of a full-dimensional pointed cone: rays counter-clockwise; built from
// generators, facet i holds rays i and i+1 and the cycle starts at the extreme generator given
// first; built from half-spaces, facet i holds rays i-1 and i. The extreme generators come from
// a brute force on the core's exact determinant signs: g_j is extreme when some plane through
// g_j and g_k has every other generator strictly on one side (generic random doubles).
TEST(Cone, CyclicOrderOfPointedCones) {
    std::mt19937_64 rng(2027);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        const int n = 3 + trial % 40;
        std::vector<Vec3> g;
        for (int i = 0; i < n; ++i) g.emplace_back(u(rng), u(rng), 0.1 + std::abs(u(rng)));
        std::set<int> extreme;
        for (int j = 0; j < n; ++j) {
            for (int k = 0; k < n && !extreme.count(j); ++k) {
                if (k == j) continue;
                int plus = 0, minus = 0;
                for (int l = 0; l < n; ++l) {
                    if (l == j || l == k) continue;
                    const Sign s = det_sign(g[static_cast<std::size_t>(j)], g[static_cast<std::size_t>(k)],
                                            g[static_cast<std::size_t>(l)]);
                    plus += s == Sign::Positive;
                    minus += s == Sign::Negative;
                }
                if (plus == n - 2 || minus == n - 2) extreme.insert(j);
            }
        }
        for (int side = 0; side < 2; ++side) {
            const Cone c = side == 0 ? Cone::from_generators(g) : Cone::from_halfspaces(g);
            const std::size_t k = c.rays().size();
            ASSERT_EQ(c.kind(), "pointed cone") << "trial " << trial;
            ASSERT_EQ(c.facets().size(), k);
            if (side == 0) {
                ASSERT_EQ(k, extreme.size()) << "trial " << trial;
                EXPECT_EQ(c.rays()[0].value(), g[static_cast<std::size_t>(*extreme.begin())]) << "trial " << trial;
            }
            for (std::size_t i = 0; i < k; ++i) {
                EXPECT_EQ(det_sign(c.rays()[i], c.rays()[(i + 1) % k], c.rays()[(i + 2) % k]), Sign::Positive)
                    << "trial " << trial << " side " << side;
                const std::size_t a = side == 0 ? i : (i + k - 1) % k, b = side == 0 ? (i + 1) % k : i;
                const auto row = c.facet_rays().row(i);
                ASSERT_EQ(row.size(), 2u);
                EXPECT_EQ(std::set<int>(row.begin(), row.end()), (std::set<int>{static_cast<int>(a), static_cast<int>(b)}))
                    << "trial " << trial << " side " << side << " facet " << i;
            }
        }
    }
}

}  // namespace
}  // namespace momentlab
