// The laws of docs/design.md on 10,000 seeded random cone pairs (half of them exactly
// degenerate), every result checked against cddlib in exact rational mode. The oracle's inputs
// are the raw generators only: combinations (F n G, F* + G*) are built by cddlib from its own
// representations of F and G, never from momentlab's.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <string>

#include "../common/sizes.hpp"
#include "cone_checks.hpp"
#include "cone_membership.hpp"
#include "random_inputs.hpp"
#include "geometry/cone_build.hpp"
#include "geometry/held_cone.hpp"
#include "momentlab/geometry/labels.hpp"

namespace momentlab {
namespace {

using testing::Family;

const int kPairs = testing::sized(5000);  // two cones each: 10,000 random cones

Family family_of(int i) {
    static const Family integral[] = {Family::SmallIntegers, Family::Coplanar, Family::Collinear,
                                      Family::Antipodal, Family::PureMoments, Family::Mixed};
    if (i % 2 == 0) return i % 4 == 0 ? Family::GeneralDoubles : Family::HalfSpaceDoubles;
    return integral[(i / 2) % 6];
}

std::vector<Vec3> concat(std::vector<Vec3> a, const std::vector<Vec3>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

Label swapped(Label l) {
    if (l == Label::Plus) return Label::Minus;
    if (l == Label::Minus) return Label::Plus;
    return l;
}

// The label of p from the definition, over the generators, in exact rationals.
Label oracle_label(const std::vector<Vec3>& generators, const Vec2& p) {
    bool plus = true, minus = true;
    const mpq_class x(p.x()), y(p.y());
    for (const Vec3& g : generators) {
        const mpq_class m = y * mpq_class(g.x()) - x * mpq_class(g.y()) + mpq_class(g.z());
        if (sgn(m) < 0) plus = false;
        if (sgn(m) > 0) minus = false;
    }
    return plus && minus ? Label::Both : (plus ? Label::Plus : (minus ? Label::Minus : Label::None));
}

struct Tally {
    int cases = 0;
    int failures = 0;
};

TEST(ConeLaws, AgreeWithExactOracleOnRandomAndDegenerateCones) {
    testing::Random rnd(20261121);
    Tally tally;
    std::map<std::string, int> kinds;
    for (int i = 0; i < kPairs; ++i) {
        const Family family = family_of(i);
        const auto gf = testing::random_generators(rnd, family, 8);
        const auto gg = testing::random_generators(rnd, family, 8);
        const std::string where = std::string(testing::family_name(family)) + " F=" +
                                  testing::describe(gf) + " G=" + testing::describe(gg);
        const Cone f = Cone::from_generators(gf);
        const Cone g = Cone::from_generators(gg);
        ++kinds[f.kind()];
        ++kinds[g.kind()];
        auto check = [&](const char* what, const Cone& ours, const oracle::OracleCone& o) {
            ++tally.cases;
            const std::string why = testing::compare_with_oracle(ours, o);
            if (!why.empty()) {
                ++tally.failures;
                ADD_FAILURE() << what << ": " << why << " in " << where;
            }
        };
        // F and F*; F** = F.
        const oracle::OracleCone of = oracle::from_generators(gf), og = oracle::from_generators(gg);
        check("F", f, of);
        check("F*", f.dual(), oracle::from_halfspaces(gf));
        EXPECT_TRUE(f.dual().dual() == f) << where;
        // (F + G)* = F* n G*.
        const auto gfg = concat(gf, gg);
        const Cone s = sum(f, g);
        check("F+G", s, oracle::from_generators(gfg));
        const Cone dual_meet = intersection(f.dual(), g.dual());
        check("F* n G*", dual_meet, oracle::from_halfspaces(gfg));
        EXPECT_TRUE(s.dual() == dual_meet) << "(F+G)* != F* n G* for " << where;
        // (F n G)* = F* + G*: the oracle intersects its own H-representations of F and G, and
        // sums the generators of its own F* and G*.
        const Cone meet = intersection(f, g);
        auto h = testing::oracle_halfspaces(of);
        const auto hg = testing::oracle_halfspaces(og);
        h.insert(h.end(), hg.begin(), hg.end());
        check("F n G", meet, oracle::from_halfspaces(h));
        const Cone dual_sum = sum(f.dual(), g.dual());
        auto d = testing::oracle_generators(oracle::from_halfspaces(gf));
        const auto dg = testing::oracle_generators(oracle::from_halfspaces(gg));
        d.insert(d.end(), dg.begin(), dg.end());
        check("F* + G*", dual_sum, oracle::from_generators(d));
        EXPECT_TRUE(meet.dual() == dual_sum) << "(F n G)* != F* + G* for " << where;

        // Labels: exact labels agree with the definition; -F swaps + and -.
        const Labels labels(f);
        const Labels negated(f.negated());
        std::vector<Vec2> points;
        for (int k = 0; k < 6; ++k) points.emplace_back(rnd.uniform(-3, 3), rnd.uniform(-3, 3));
        for (int k = 0; k < 3; ++k) points.emplace_back(rnd.integer(-2, 2), rnd.integer(-2, 2));
        for (const Vec2& v : labels.plus().vertices) points.push_back(v);
        for (const Vec2& v : labels.minus().vertices) points.push_back(v);
        for (const Vec2& p : points) {
            const Label expected = oracle_label(gf, p);
            EXPECT_EQ(labels.at(p), expected) << "label at (" << p.x() << ", " << p.y() << ") of " << where;
            EXPECT_EQ(negated.at(p), swapped(expected)) << "labels(-F) at (" << p.x() << ", " << p.y() << ") of " << where;
        }
        EXPECT_EQ(negated.plus().kind(), labels.minus().kind()) << where;
        EXPECT_EQ(negated.minus().kind(), labels.plus().kind()) << where;
        // Labels -> cone round trip, wherever the labels determine the cone.
        if (labels.plus().is_empty && labels.minus().is_empty) {
            EXPECT_TRUE(f.has(Vec3(0, 0, 1)) && f.has(Vec3(0, 0, -1)))
                << "empty labels but F lacks the pure moments: " << where;
        } else {
            const Cone back = Labels::forces_from_regions(labels.plus(), labels.minus());
            if (testing::is_integral(family)) {
                EXPECT_TRUE(back == f) << "round trip changed the cone: " << where;
            } else {
                EXPECT_EQ(back.kind(), f.kind()) << "round trip changed the kind: " << where;
            }
        }
        if (tally.failures > 20) break;
    }
    std::cout << "[ConeLaws] " << tally.cases << " oracle comparisons, " << tally.failures
              << " disagreements; cone kinds seen:";
    for (const auto& [k, n] : kinds) std::cout << " " << k << "=" << n;
    std::cout << "\n";
    EXPECT_EQ(tally.failures, 0);
    EXPECT_EQ(tally.cases, 6 * kPairs);  // 30,000 in the release build, the count README.md states
    // Every kind of cone must have been exercised.
    for (const char* k : {"{0}", "ray", "line", "wedge", "half-plane", "plane", "pointed cone",
                          "wedge x line", "half-space", "R^3"}) {
        if (testing::kFullSize) EXPECT_GT(kinds[k], 0) << "no random cone of kind " << k;
    }
}

// Every face of 2,000 cones: its cone has the stated dimension, and a point of its relative
// interior (the sum of its rays, in exact rationals) lies exactly on the facets the face lists
// and strictly inside the others.
TEST(ConeLaws, FacesAreConsistentWithExactIncidence) {
    testing::Random rnd(11);
    int checked = 0, cones = 0;
    for (int i = 0; i < testing::sized(2000); ++i) {
        const auto g = testing::random_generators(rnd, family_of(i), 8);
        const Cone c = Cone::from_generators(g);
        ++cones;
        for (const Face& face : c.faces()) {
            const Cone fc = c.face_cone(face);
            ASSERT_EQ(fc.dimension(), face.dimension) << testing::describe(g);
            ASSERT_TRUE(subset(fc, c)) << testing::describe(g);
            reference::QVec x{0, 0, 0};
            for (int r : face.rays) x = reference::add(x, reference::to_q(c.rays()[static_cast<std::size_t>(r)]));
            for (std::size_t j = 0; j < c.facets().size(); ++j) {
                const bool listed = std::find(face.facets.begin(), face.facets.end(), static_cast<int>(j)) != face.facets.end();
                const int s = reference::sign(reference::dot(reference::to_q(c.facets()[j]), x));
                EXPECT_EQ(s == 0, listed) << "facet " << j << " of " << testing::describe(g);
                EXPECT_GE(s, 0) << testing::describe(g);
                ++checked;
            }
        }
    }
    EXPECT_EQ(cones, testing::sized(2000));
    EXPECT_GT(checked, testing::floor_of(10000));
}

// More than 64 generators: the construction then starts from a floating-point guess of an
// extreme ray, and its other paths (retries, the exact dual clip) are taken.
TEST(ConeLaws, ManyGeneratorsAgreeWithExactOracle) {
    testing::Random rnd(7);
    ConeBuilder::stats() = {};
    int failures = 0;
    std::map<std::string, int> kinds;
    for (int i = 0; i < testing::sized(600); ++i) {
        const Family family = family_of(i);
        std::vector<Vec3> g;
        const int target = rnd.integer(65, 160);
        while (static_cast<int>(g.size()) < target) {
            const auto more = testing::random_generators(rnd, family, 12);
            g.insert(g.end(), more.begin(), more.end());
        }
        if (i % 5 == 0) {  // a pointed cone of many generators with one far outlier
            for (Vec3& v : g) v = Vec3(v.x(), v.y(), std::fabs(v.z()) + 1.0);
            g.push_back(Vec3(rnd.integer(-3, 3), rnd.integer(-3, 3), 1));
        }
        if (i % 5 == 1) {  // generators in z >= 0 with a line on z = 0: wedge x line or half-space
            for (Vec3& v : g) v = Vec3(v.x(), v.y(), std::fabs(v.z()));
            const Vec3 line(rnd.integer(-2, 2), rnd.integer(1, 2), 0);
            g.push_back(line);
            g.push_back(-line);
        }
        const Cone f = Cone::from_generators(g);
        ++kinds[f.kind()];
        const std::string why = testing::compare_with_oracle(f, oracle::from_generators(g));
        if (!why.empty()) {
            ++failures;
            ADD_FAILURE() << why << " for " << testing::family_name(family) << " " << testing::describe(g);
        }
        if (failures > 5) break;
    }
    const ConePathStats paths = ConeBuilder::stats();
    std::cout << "[ConeLaws] many generators, kinds:";
    for (const auto& [k, n] : kinds) std::cout << " " << k << "=" << n;
    std::cout << "; rank-3 paths: by pivot " << paths.by_pivot << ", retries " << paths.retries
              << ", dual clip " << paths.dual_clip << "\n";
    EXPECT_GE(kinds["pointed cone"], testing::floor_of(50));
    EXPECT_GE(kinds["wedge x line"] + kinds["half-space"], testing::floor_of(20));
}

// Pointed cones of 3 .. 128 generators are found as a convex hull in a chart d . x = 1
// (pointed_by_chart, src/geometry/cone_build.cpp). Against the pivot path (use_chart() false) and
// the exact oracle (cddlib in GMP rationals, on the raw numbers): the same representation, ray
// for ray and facet for facet, the generator given first standing for parallel ones: the rays
// are exactly such generators, and the cycle starts at the first of them. Families:
// doubles in a cone around a random axis, wide flat cones (where the pivot path often ends in the
// dual clip, whose cycle now starts at the generator given first too), integer points on a
// pyramid's faces (ties in the
// chart, collinear points, parallel copies of different lengths), narrow cones 2^20 .. 2^40
// high and cones 2^-40 small, and contact wrenches of forces in a half-plane (constructions,
// some 10^3 from the origin).
// Empty when each ray of the pointed cone c is exactly the generator given first along its
// direction (raw: the generators' exact numbers) and ray 0 the first of those; else why not.
std::string rays_are_first_given(const Cone& c, const std::vector<reference::QVec>& raw) {
    const auto along = [](const reference::QVec& a, const reference::QVec& b) {
        return a[1] * b[2] == a[2] * b[1] && a[2] * b[0] == a[0] * b[2] && a[0] * b[1] == a[1] * b[0] &&
               a[0] * b[0] + a[1] * b[1] + a[2] * b[2] > 0;
    };
    std::size_t ray0_first = raw.size();
    for (std::size_t r = 0; r < c.rays().size(); ++r) {
        const reference::QVec ray = reference::to_q(c.rays()[r]);
        std::size_t first = 0;
        while (first < raw.size() && !along(raw[first], ray)) ++first;
        if (first == raw.size()) return "ray " + std::to_string(r) + " is along no generator";
        if (!(raw[first] == ray)) return "ray " + std::to_string(r) + " is not generator " + std::to_string(first);
        if (r == 0) ray0_first = first;
        if (first < ray0_first) return "the cycle does not start at the generator given first";
    }
    return "";
}

TEST(ConeLaws, PointedConesFoundInAChartEqualThoseFromAPivot) {
    testing::Random rnd(1991);
    const long chart_before = ConeBuilder::stats().by_chart;
    int cases = 0, identical = 0, with_parallel = 0;
    auto parallel_pair = [](const std::vector<Vec3>& g) {
        for (std::size_t i = 0; i < g.size(); ++i) {
            for (std::size_t j = i + 1; j < g.size(); ++j) {
                if (parallel(g[i], g[j])) return true;
            }
        }
        return false;
    };
    auto same = [](const std::vector<ExactVector>& a, const std::vector<ExactVector>& b) {
        if (a.size() != b.size()) return false;
        for (std::size_t i = 0; i < a.size(); ++i) {
            // (Computed vectors of two builds hold equal numbers in different blocks.)
            if (a[i].value() != b[i].value() || reference::to_q(a[i]) != reference::to_q(b[i])) return false;
        }
        return true;
    };
    long clipped = 0;  // cones the pivot path built by the dual clip
    for (int i = 0; i < testing::sized(1500); ++i) {
        const int kind = i % 6;
        const int n = i % 100 == 0 ? rnd.integer(41, 128) : rnd.integer(3, 30);
        std::vector<Vec3> g;
        std::vector<ExactVector> wrenches;
        std::vector<reference::QVec> exact_wrenches;  // from the raw numbers, for the oracle
        if (i == 0) {  // a helper's case: the pivot path's clip started the cycle at ray 2
            g = {Vec3(10, 11, 1), Vec3(1, -4, 1), Vec3(-1, -10, 1), Vec3(-7, 5, 1), Vec3(-8, 19, 3)};
        } else if (kind == 0) {  // doubles within about 60 degrees of a random axis
            const Vec3 axis = rnd.vec3(1).normalized();
            for (int j = 0; j < n; ++j) g.push_back(axis + 0.8 * rnd.vec3(1));
        } else if (kind == 5) {  // wide and flat: (x, y) in a square over heights 0.02 .. 0.3
            for (int j = 0; j < n; ++j) g.emplace_back(rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(0.02, 0.3));
        } else if (kind == 1) {  // integer points on the faces |x|, |y| <= m z, some scaled
            const int m = rnd.integer(1, 4);
            for (int j = 0; j < n; ++j) {
                const int k = rnd.integer(-m, m);
                Vec3 v = j % 4 == 0 ? Vec3(k, m, m) : j % 4 == 1 ? Vec3(m, k, m) : j % 4 == 2 ? Vec3(-m, k, m) : Vec3(k, -m, m);
                if (j % 7 == 3) v = Vec3(k / 2, rnd.integer(-m + 1, m - 1), m);  // inside or on a face
                g.push_back(v * rnd.integer(1, 3));
            }
        } else if (kind == 2 || kind == 3) {  // narrow and high, or small
            const double height = std::ldexp(1.0, kind == 2 ? rnd.integer(20, 40) : -40);
            const double r = kind == 2 ? 1.0 : 0x1p-41;
            for (int j = 0; j < n; ++j) {
                const double t = rnd.uniform(0, 6.283185307179586);
                g.emplace_back(r * std::cos(t), r * std::sin(t), height);
            }
        } else {  // wrenches of forces within 70 degrees of +x, at points near the origin or 10^3 away
            const double far = i % 12 == 11 ? 1000.0 : 0.0;
            for (int j = 0; j < n; ++j) {
                const double t = rnd.uniform(-1.2, 1.2);
                const Vec2 p(far + rnd.uniform(-1, 1), rnd.uniform(-1, 1));
                const Vec2 d(std::cos(t), std::sin(t));
                wrenches.push_back(ExactVector::wrench(p, d));
                g.push_back(wrenches.back().value());
                const mpq_class px(p.x()), py(p.y()), dx(d.x()), dy(d.y());
                exact_wrenches.push_back({dx, dy, px * dy - py * dx});
            }
        }
        const long chart_count = ConeBuilder::stats().by_chart;
        const Cone chart = wrenches.empty() ? Cone::from_generators(g) : Cone::from_generators(wrenches);
        const bool took_chart = ConeBuilder::stats().by_chart > chart_count;
        ConeBuilder::use_chart() = false;
        const long clips = ConeBuilder::stats().dual_clip;
        const Cone pivot = wrenches.empty() ? Cone::from_generators(g) : Cone::from_generators(wrenches);
        clipped += ConeBuilder::stats().dual_clip > clips;
        ConeBuilder::use_chart() = true;
        ++cases;
        if (!took_chart) continue;
        const oracle::OracleCone o = wrenches.empty() ? oracle::from_generators(g)
                                                      : oracle::from_generators(exact_wrenches);
        const std::string why = testing::compare_with_oracle(chart, o);
        ASSERT_TRUE(why.empty()) << why << " for case " << i << ": " << testing::describe(g);
        // (Rounded wrenches may be parallel where the exact ones are not: parallel_pair only
        // counts the cases.)
        with_parallel += parallel_pair(g);
        ASSERT_EQ(chart.kind(), "pointed cone");
        // Each ray is, exactly, the generator given first along its direction (raw numbers), and
        // ray 0 the first of those: on both paths (the pivot's scan and its dual clip kept a later
        // copy of a generator given twice, and started there; helper-13).
        const std::vector<reference::QVec> raw = wrenches.empty() ? testing::exact_list(g) : exact_wrenches;
        for (const Cone* c : {&chart, &pivot}) {
            const std::string first_given = rays_are_first_given(*c, raw);
            ASSERT_TRUE(first_given.empty()) << "case " << i << ": " << first_given << ": " << testing::describe(g);
        }
        ASSERT_TRUE(same(chart.rays(), pivot.rays())) << "case " << i << ": " << testing::describe(g);
        ASSERT_TRUE(same(chart.facets(), pivot.facets())) << "case " << i;
        ASSERT_EQ(chart.facet_rays().size(), pivot.facet_rays().size());
        for (std::size_t j = 0; j < chart.facet_rays().size(); ++j) {
            const auto a = chart.facet_rays().row(j), b = pivot.facet_rays().row(j);
            ASSERT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << "case " << i << ", facet " << j;
        }
        ++identical;
    }
    const long by_chart = ConeBuilder::stats().by_chart - chart_before;
    std::cout << "[ConeLaws] chart: " << by_chart << " of " << cases << " cones, " << identical
              << " identical to the pivot path's (" << clipped << " of its cones by the dual clip), "
              << with_parallel << " with parallel generators\n";
    EXPECT_GT(clipped, 0);
    // (The cones of wrenches 10^3 from the origin, a twelfth, are flat: most have a generator
    // behind the guessed direction d and go to the pivot path.)
    EXPECT_GT(by_chart, cases * 8 / 10);
    EXPECT_GT(identical, cases / 2);
    EXPECT_GT(with_parallel, cases / 10);
}

// The chart decides d . g > 0, the order of its x keys and the chain's turns on rounded chart
// points with certified error bounds, and takes the exact predicates only where those cannot
// decide. Generators whose chart points lie on a line (exactly, or off it by a few units in the
// last place of the generators), points a few ulps apart, each generator at its own length
// (times 2^k, some also times 3, which rounds: their chart points round differently), the
// whole at 2^-300, 1 and 2^300, and wrenches of forces through points on a line or about a common point (chart
// points of exact vectors, known up to their approximations' errors): the cone is the GMP oracle's
// of the raw numbers and the pivot path's, rays and facets alike.
TEST(ConeLaws, ChartFiltersDecideNearlyDegenerateCharts) {
    testing::Random rnd(1126);
    const long chart_before = ConeBuilder::stats().by_chart;
    int cases = 0;
    for (int i = 0; i < testing::sized(900); ++i) {
        const int n = rnd.integer(4, 40);
        std::vector<Vec3> g;
        std::vector<ExactVector> wrenches;
        std::vector<reference::QVec> exact_wrenches;
        if (i % 3 == 2) {  // forces through points on a line, or about a common point
            const Vec2 base(rnd.uniform(-1, 1), rnd.uniform(-1, 1)), along(rnd.uniform(-1, 1), rnd.uniform(-1, 1));
            for (int j = 0; j < n; ++j) {
                const double t = rnd.uniform(-1.2, 1.2);
                const Vec2 d(std::cos(t), std::sin(t));
                Vec2 p = i % 2 ? base : base + rnd.uniform(0, 1) * along;
                if (j % 5 == 1) p.x() = std::nextafter(p.x(), 2.0);  // a few ulps off
                wrenches.push_back(ExactVector::wrench(p, d));
                g.push_back(wrenches.back().value());
                const mpq_class px(p.x()), py(p.y()), dx(d.x()), dy(d.y());
                exact_wrenches.push_back({dx, dy, px * dy - py * dx});
            }
        } else {  // chart points on a segment and a few above it, z > 0
            const Vec3 a(rnd.uniform(-1, 1), rnd.uniform(-1, 1), 1), b(rnd.uniform(-1, 1), rnd.uniform(-1, 1), 0);
            const double scale = std::ldexp(1.0, i % 3 == 0 ? 0 : (i % 2 ? 300 : -300));
            for (int j = 0; j < n; ++j) {
                Vec3 v = j < 3 ? Vec3(rnd.uniform(-2, 2), rnd.uniform(-2, 2), 1) : Vec3(a + rnd.uniform(0, 1) * b);
                const int ulps = j % 4 == 0 ? 0 : rnd.integer(-3, 3);
                for (int k = 0; k < std::abs(ulps); ++k) v.y() = std::nextafter(v.y(), ulps > 0 ? 4.0 : -4.0);
                if (j % 6 == 5) v = g.back();  // the same point, then a few ulps from it
                if (j % 6 == 0 && !g.empty()) v.x() = std::nextafter(g.back().x(), 4.0);
                // Its own length: the chart point is the same, its rounding is not.
                v *= std::ldexp(1.0, rnd.integer(-20, 20)) * (j % 3 == 0 ? 3.0 : 1.0);
                g.push_back(v * scale);
            }
        }
        const long chart_count = ConeBuilder::stats().by_chart;
        const Cone chart = wrenches.empty() ? Cone::from_generators(g) : Cone::from_generators(wrenches);
        const bool took_chart = ConeBuilder::stats().by_chart > chart_count;
        const oracle::OracleCone o = wrenches.empty() ? oracle::from_generators(g) : oracle::from_generators(exact_wrenches);
        const std::string why = testing::compare_with_oracle(chart, o);
        ASSERT_TRUE(why.empty()) << why << " for case " << i << ": " << testing::describe(g);
        if (!took_chart) continue;
        ++cases;
        ConeBuilder::use_chart() = false;
        const Cone pivot = wrenches.empty() ? Cone::from_generators(g) : Cone::from_generators(wrenches);
        ConeBuilder::use_chart() = true;
        ASSERT_EQ(chart.rays().size(), pivot.rays().size()) << "case " << i;
        for (std::size_t j = 0; j < chart.rays().size(); ++j) {
            ASSERT_EQ(reference::to_q(chart.rays()[j]), reference::to_q(pivot.rays()[j])) << "case " << i << ", ray " << j;
            ASSERT_EQ(reference::to_q(chart.facets()[j]), reference::to_q(pivot.facets()[j])) << "case " << i << ", facet " << j;
        }
    }
    std::cout << "[ConeLaws] nearly degenerate charts: " << cases << " cones by the chart\n";
    EXPECT_EQ(ConeBuilder::stats().by_chart - chart_before, cases);
    EXPECT_GT(cases, testing::floor_of(900) / 2);
}

// Cones the chart does not take (more than 128 generators, or a guessed direction with some
// generator behind it) go to the pivot path, and from there sometimes to the dual clip; there
// too the generator given first stands for parallel copies, and the cycle starts at the first
// such generator that is extreme (helper-13: both kept a later copy of a generator given twice
// and started the cycle there). Integer points z = 1 of a few hull shapes, each point given up
// to three times at lengths 1-3, in random order, with zero vectors among them; the cone is
// cddlib's of the raw numbers and each ray is exactly the first generator along it.
TEST(ConeLaws, TheGeneratorGivenFirstStandsForParallelCopiesOnEveryPath) {
    testing::Random rnd(2026);
    const ConePathStats before = ConeBuilder::stats();
    for (int i = 0; i < testing::sized(300); ++i) {
        std::vector<Vec3> g;
        if (i == 0) {  // helper-13's case: the pivot path started at the second (330, 600, 1)
            g = {Vec3(330, 600, 1), Vec3(-424, -910, 1), Vec3(330, 600, 1), Vec3(-65, -546, 1)};
        } else {
            const int points = i % 3 == 0 ? rnd.integer(3, 8) : rnd.integer(40, 90);
            const int range = rnd.integer(2, 1000);
            for (int j = 0; j < points; ++j) {
                const Vec3 v(rnd.integer(-range, range), rnd.integer(-range, range), 1);
                for (int copies = rnd.integer(1, 3); copies > 0; --copies) g.push_back(v * rnd.integer(1, 3));
                if (rnd.integer(0, 9) == 0) g.push_back(Vec3::Zero());
            }
            for (std::size_t j = g.size(); j > 1; --j) std::swap(g[j - 1], g[static_cast<std::size_t>(rnd.integer(0, static_cast<int>(j) - 1))]);
        }
        const Cone c = Cone::from_generators(g);
        const oracle::OracleCone o = oracle::from_generators(g);
        const std::string why = testing::compare_with_oracle(c, o);
        ASSERT_TRUE(why.empty()) << why << " for case " << i << ": " << testing::describe(g);
        if (c.kind() != "pointed cone") continue;
        const std::string first_given = rays_are_first_given(c, testing::exact_list(g));
        ASSERT_TRUE(first_given.empty()) << "case " << i << ": " << first_given << ": " << testing::describe(g);
    }
    const ConePathStats& after = ConeBuilder::stats();
    std::cout << "[ConeLaws] parallel copies: by chart " << after.by_chart - before.by_chart << ", by pivot "
              << after.by_pivot - before.by_pivot << ", dual clip " << after.dual_clip - before.dual_clip << "\n";
    EXPECT_GT(after.by_pivot - before.by_pivot, 0);
    EXPECT_GT(after.dual_clip - before.dual_clip, 0);
}

// Every signed permutation P (48, half of them reflections) keeps a pointed cone's cycle
// counter-clockwise (a helper found a reflection left it clockwise): det(r_i, r_i+1, r_i+2) > 0,
// facet i on rays i and i+1 (built from generators) or i-1 and i (from half-spaces), exactly
// zero on them and positive on every other ray; and the cone is cddlib's of the permuted raw
// generators.
TEST(ConeLaws, SignedPermutationsKeepTheCycleCounterClockwise) {
    testing::Random rnd(48);
    std::vector<Mat3> perms;
    const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& o : orders) {
        for (int signs = 0; signs < 8; ++signs) {
            Mat3 p = Mat3::Zero();
            for (int r = 0; r < 3; ++r) p(r, o[r]) = (signs >> r) & 1 ? -1.0 : 1.0;
            perms.push_back(p);
        }
    }
    int checked = 0;
    for (int i = 0; i < testing::sized(200); ++i) {
        std::vector<Vec3> g;
        const int n = rnd.integer(3, 12);
        for (int j = 0; j < n; ++j) g.emplace_back(rnd.integer(-5, 5), rnd.integer(-5, 5), rnd.integer(2, 6));
        const Cone base = i % 2 ? Cone::from_generators(g) : Cone::from_generators(g).dual().dual();
        if (base.kind() != "pointed cone") continue;
        for (const Mat3& p : perms) {
            const Cone c = base.signed_permuted(p);
            std::vector<reference::QVec> raw;
            for (const Vec3& v : g) raw.push_back(reference::q(Vec3(p * v)));
            const std::string why = testing::compare_with_oracle(c, oracle::from_generators(raw));
            ASSERT_TRUE(why.empty()) << why;
            const std::size_t k = c.rays().size();
            const bool from_generators = c.exact_representation() == Representation::Generators;
            for (std::size_t j = 0; j < k; ++j) {
                const auto r = [&](std::size_t t) { return reference::to_q(c.rays()[(j + t) % k]); };
                ASSERT_GT(reference::det(r(0), r(1), r(2)), 0) << "case " << i << ", det P " << p.determinant();
                const std::size_t a = from_generators ? j : (j + k - 1) % k, b = from_generators ? (j + 1) % k : j;
                const auto row = c.facet_rays().row(j);
                ASSERT_EQ(row.size(), 2u);
                ASSERT_EQ(row[0], static_cast<int>(std::min(a, b)));
                ASSERT_EQ(row[1], static_cast<int>(std::max(a, b)));
                const reference::QVec f = reference::to_q(c.facets()[j]);
                for (std::size_t t = 0; t < k; ++t) {
                    const reference::Q value = reference::dot(f, reference::to_q(c.rays()[t]));
                    if (t == a || t == b) {
                        ASSERT_EQ(value, 0);
                    } else {
                        ASSERT_GT(value, 0);
                    }
                }
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, testing::floor_of(200) * 48 / 2);
}

// Pointed cones all of whose generators lie within 2^-20 .. 2^-40 rad of one axis: the wrenches
// of a scene far larger than 1 (a torque 2^40 times the force). The floating-point guess of an
// extreme ray measures angles by chords, whose precision holds at small angles (cosines all
// round to 1 there), so each cone is found from a pivot, never by the dual clip; and equals the
// exact oracle's.
TEST(ConeLaws, NarrowConesAreFoundFromAnExtremePivot) {
    testing::Random rnd(2040);
    int built = 0;
    for (int i = 0; i < testing::sized(40); ++i) {
        const double height = std::ldexp(1.0, rnd.integer(20, 40));
        std::vector<Vec3> g;
        const int n = rnd.integer(65, 140);
        for (int j = 0; j < n; ++j) {
            const double t = rnd.uniform(0, 6.283185307179586);
            const double r = j % 3 == 0 ? rnd.uniform(0.1, 0.9) : 1.0;  // every third inside
            g.emplace_back(r * std::cos(t), r * std::sin(t), height);
        }
        const long clips = ConeBuilder::stats().dual_clip;
        const Cone f = Cone::from_generators(g);
        EXPECT_EQ(ConeBuilder::stats().dual_clip, clips) << "cone " << i << ", height 2^" << std::ilogb(height);
        const std::string why = testing::compare_with_oracle(f, oracle::from_generators(g));
        EXPECT_TRUE(why.empty()) << why << " for cone " << i;
        EXPECT_EQ(f.kind(), "pointed cone");
        ++built;
    }
    EXPECT_EQ(built, testing::sized(40));
}

// The wrenches of one scene at lengths 1, 2^40 and 2^-40 (points scaled, torques with them):
// the same cone (as many rays and facets, the same generators extreme) for as many exact-vector
// predicates within 25%. The floating-point hints are taken with the torque coordinate brought
// back to the forces' size (balance, src/geometry/cone_build.cpp): on the raw coordinates every
// wrench of the long scene rounds to nearly one direction, the sort keys are noise, and the
// exact sort that takes over made several times as many predicates.
TEST(ConeLaws, ScalingTheTorquesCostsNoMorePredicates) {
    testing::Random rnd(4040);
    for (int i = 0; i < 6; ++i) {
        const int n = rnd.integer(200, 600);
        std::vector<Vec2> points, normals;
        for (int j = 0; j < n; ++j) {  // a cradle: points on a half ring, normals tilted inwards
            const double t = rnd.uniform(3.3, 6.1), tilt = i % 2 ? rnd.uniform(0.15, 0.25) : rnd.uniform(-0.3, 0.3);
            points.emplace_back(std::cos(t), std::sin(t));
            normals.emplace_back(-std::cos(t + tilt), -std::sin(t + tilt));
        }
        std::vector<long> predicates;
        std::vector<std::vector<int>> extreme;
        std::vector<std::size_t> facets;
        std::vector<std::string> kinds;
        for (const int k : {0, 40, -40}) {
            std::vector<ExactVector> g;
            for (int j = 0; j < n; ++j) g.push_back(ExactVector::wrench(std::ldexp(1.0, k) * points[j], normals[j]));
            exact_stats() = {};
            const Cone c = Cone::from_generators(g);
            predicates.push_back(exact_stats().filtered + exact_stats().exact);
            // Which generators are extreme: each ray is a positive multiple of one (exact test).
            std::vector<int> which;
            for (const ExactVector& r : c.rays()) {
                for (int j = 0; j < n; ++j) {
                    if (parallel(r, g[static_cast<std::size_t>(j)]) && dot_sign(r, g[static_cast<std::size_t>(j)]) == Sign::Positive) which.push_back(j);
                }
            }
            std::sort(which.begin(), which.end());
            extreme.push_back(which);
            facets.push_back(c.facets().size());
            kinds.push_back(c.kind());
        }
        std::cout << "cone " << i << " (" << kinds[0] << ", " << extreme[0].size() << " rays of " << n
                  << "): exact-vector predicates at lengths 1, 2^40, 2^-40: " << predicates[0] << ", " << predicates[1]
                  << ", " << predicates[2] << "\n";
        for (std::size_t s = 1; s < 3; ++s) {
            EXPECT_EQ(extreme[s], extreme[0]) << "cone " << i;
            EXPECT_EQ(facets[s], facets[0]) << "cone " << i;
            EXPECT_EQ(kinds[s], kinds[0]) << "cone " << i;
            EXPECT_LE(predicates[s], predicates[0] * 5 / 4) << "cone " << i << ": " << predicates[s] << " predicates against " << predicates[0];
        }
    }
}

// cone_holds (no facets built for a pointed full-dimensional cone) against brute-force exact
// membership (reference/cone_membership.hpp, Caratheodory over every subset) on the random and
// degenerate families, with generators as stored doubles and as exact constructions u x v of
// small integer vectors (the exact path); wrenches random, integer, and 0/1 sums of generators
// (on the boundary). Each certificate is checked in rationals: a separator h has h . g >= 0 for
// every generator and h . w < 0; a triangle's three generators hold w.
TEST(ConeLaws, ConeHoldsAgreesWithBruteForceMembership) {
    testing::Random rnd(20261125);
    int members = 0, outside = 0, triangles = 0;
    for (int i = 0; i < testing::sized(3000); ++i) {
        const bool constructed = i % 3 == 2;
        std::vector<ExactVector> g;
        std::vector<reference::QVec> raw;
        if (constructed) {  // u x v for small integer u, v: the oracle multiplies them itself
            const int n = rnd.integer(1, 12);
            for (int k = 0; k < n; ++k) {
                const Vec3 u(rnd.integer(-3, 3), rnd.integer(-3, 3), rnd.integer(-3, 3));
                const Vec3 v(rnd.integer(-3, 3), rnd.integer(-3, 3), rnd.integer(-3, 3));
                g.push_back(ExactVector::cross(ExactVector::input(u), ExactVector::input(v)));
                raw.push_back(reference::cross(reference::q(u), reference::q(v)));
            }
        } else {
            for (const Vec3& v : testing::random_generators(rnd, family_of(i), 12)) {
                g.push_back(ExactVector::input(v));
                raw.push_back(reference::q(v));
            }
        }
        if (i % 5 == 0) {  // a zero generator among them: certificates name the given indices
            const int at = rnd.integer(0, static_cast<int>(g.size()));
            g.insert(g.begin() + at, ExactVector::input(Vec3::Zero()));
            raw.insert(raw.begin() + at, reference::QVec{0, 0, 0});
        }
        const HeldCone kept(g);
        for (int k = 0; k < 6; ++k) {
            reference::QVec w = reference::q(rnd.vec3(3.0));
            if (k == 1) w = reference::q(Vec3(rnd.integer(-2, 2), rnd.integer(-2, 2), rnd.integer(-2, 2)));
            if (k >= 2) {
                w = {0, 0, 0};
                for (const reference::QVec& r : raw) w = reference::add(w, reference::scale(rnd.integer(0, 1), r));
            }
            const Vec3 wd = reference::to_vec3(w);
            if (reference::q(wd) != w) continue;
            const bool expected = reference::in_cone(raw, w);
            // cone_holds, and the HeldCone kept for all the wrenches of this set.
            for (const Held& held : {cone_holds(g, wd), kept.holds(wd)}) {
                ASSERT_EQ(held.member, expected) << "w = " << wd.transpose() << ", generator set " << i;
                if (!held.member) {
                    ++outside;
                    const reference::QVec h = reference::to_q(held.separator);
                    EXPECT_LT(reference::sign(reference::dot(h, w)), 0) << "separator, set " << i;
                    for (const reference::QVec& r : raw) EXPECT_GE(reference::sign(reference::dot(h, r)), 0) << "separator, set " << i;
                    continue;
                }
                ++members;
                if (held.triangle) {
                    ++triangles;
                    const auto& t = *held.triangle;
                    ASSERT_TRUE(t[0] < raw.size() && t[1] < raw.size() && t[2] < raw.size());
                    EXPECT_TRUE(reference::in_cone({raw[t[0]], raw[t[1]], raw[t[2]]}, w)) << "triangle, set " << i;
                }
            }
        }
    }
    std::cout << "[ConeLaws] cone_holds: " << members << " members (" << triangles << " with a triangle), " << outside
              << " outside\n";
    EXPECT_GE(triangles, testing::floor_of(3000));
    EXPECT_GE(outside, testing::floor_of(3000));
}

// The same cone, vector for vector: exact coordinates, printed values, order and incidence.
// The same lists in the same order, vector for vector; rays up to a positive factor when
// `rays_up_to_scale` (exact: x X y = 0 and x . y > 0 in rationals).
std::string identical(const Cone& a, const Cone& b, bool rays_up_to_scale = false) {
    const auto same_list = [](const std::vector<ExactVector>& x, const std::vector<ExactVector>& y, bool up_to_scale) {
        if (x.size() != y.size()) return false;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const reference::QVec p = reference::to_q(x[i]), q = reference::to_q(y[i]);
            if (up_to_scale) {
                if (reference::cross(p, q) != reference::QVec{0, 0, 0} || reference::sign(reference::dot(p, q)) <= 0) return false;
            } else if (p != q || x[i].value() != y[i].value()) {
                return false;
            }
        }
        return true;
    };
    if (!same_list(a.rays(), b.rays(), rays_up_to_scale)) return "rays differ";
    if (!same_list(a.facets(), b.facets(), false)) return "facets differ";
    if (!same_list(a.lineality(), b.lineality(), false) || !same_list(a.equations(), b.equations(), false)) return "spans differ";
    if (a.facet_rays().size() != b.facet_rays().size()) return "incidence differs";
    for (std::size_t j = 0; j < a.facet_rays().size(); ++j) {
        const auto x = a.facet_rays().row(j), y = b.facet_rays().row(j);
        if (!std::equal(x.begin(), x.end(), y.begin(), y.end())) return "incidence differs";
    }
    return a.exact_representation() == b.exact_representation() ? "" : "exact representation differs";
}

// intersection(F, half-space) cuts a pointed F's cycle of facets (ConeBuilder::cut) instead of
// building the cone of all half-spaces again: against cddlib (exact, from the raw generators and
// h), and vector for vector against the cone of all the half-spaces (its rays up to a positive
// factor: the cut keeps F's own rays). Cones of stored doubles and
// of exact constructions (u x v: the shared rays), negated and signed-permuted as labels use them;
// h random, an axis, through rays of F (exactly on the boundary), and +-a facet of F.
TEST(ConeLaws, CutByHalfSpaceIsTheConeOfAllHalfSpaces) {
    testing::Random rnd(20261126);
    int cut = 0, other = 0, through_rays = 0, through_facets = 0, clipped = 0;
    Mat3 rotation;
    rotation << 0, -1, 0, 1, 0, 0, 0, 0, 1;  // labels' points -> functionals, a signed permutation
    for (int i = 0; i < testing::sized(3000); ++i) {
        std::vector<ExactVector> g;
        std::vector<reference::QVec> raw;
        const int n = rnd.integer(3, 14);
        const bool constructed = i % 3 == 2;
        const Family family = family_of(i);
        const auto doubles = testing::random_generators(rnd, family, n);
        for (std::size_t k = 0; k < doubles.size(); ++k) {
            if (constructed) {  // u x v with u a generator, v a small integer vector
                const Vec3 v(rnd.integer(-3, 3), rnd.integer(-3, 3), rnd.integer(1, 3));
                g.push_back(ExactVector::cross(ExactVector::input(doubles[k]), ExactVector::input(v)));
                raw.push_back(reference::cross(reference::q(doubles[k]), reference::q(v)));
            } else {
                g.push_back(ExactVector::input(doubles[k]));
                raw.push_back(reference::q(doubles[k]));
            }
        }
        Cone f = Cone::from_generators(g);
        if (i % 4 == 1) {  // as labels cut -K
            f = f.negated();
            for (auto& r : raw) r = reference::scale(-1, r);
        }
        if (i % 4 == 2) {
            f = f.signed_permuted(rotation);
            for (auto& r : raw) r = {-r[1], r[0], r[2]};
        }
        if (i % 4 == 3) f = f.dual().dual();
        for (int k = 0; k < 4; ++k) {
            Vec3 h = rnd.vec3(2.0);
            if (k == 1) h = Vec3::Unit(rnd.integer(0, 2)) * (rnd.integer(0, 1) ? 1.0 : -1.0);
            if (k == 2 && f.rays().size() >= 2 && !f.rays()[0].is_constructed()) {
                // through two rays of F (exactly on the boundary), when the product is exact
                const Vec3 a = f.rays()[0].value(), b = f.rays()[1].value();
                if (reference::q(Vec3(a.cross(b))) == reference::cross(reference::q(a), reference::q(b))) {
                    h = a.cross(b);
                    ++through_rays;
                }
            }
            if (k == 3 && !f.facets().empty() && !f.facets()[0].is_constructed()) h = f.facets()[0].value() * (i % 2 ? 1.0 : -1.0);
            if (h.isZero()) continue;
            const Cone half = Cone::half_space(h);
            const Cone ours = intersection(f, half);
            std::vector<ExactVector> normals = f.halfspaces();
            normals.push_back(ExactVector::input(h));
            const long clips = ConeBuilder::stats().dual_clip;
            const Cone general = Cone::from_halfspaces(normals);
            const bool took_cut = ConeBuilder::cut(f, ExactVector::input(h)).has_value();
            (took_cut ? cut : other) += 1;
            // cddlib: F's H-representation from the raw generators, and h.
            auto hs = testing::oracle_halfspaces(oracle::from_generators(raw));
            hs.push_back(reference::q(h));
            const std::string why = testing::compare_with_oracle(ours, oracle::from_halfspaces(hs));
            ASSERT_TRUE(why.empty()) << why << ", set " << i << ", h = " << h.transpose();
            // h along a facet of F (F itself): the cone of all half-spaces, given that facet twice,
            // may start its cycle at another facet; cddlib above decides.
            bool along_facet = false;
            for (const ExactVector& facet : f.facets()) along_facet = along_facet || parallel(facet, ExactVector::input(h));
            through_facets += along_facet && took_cut;
            clipped += ConeBuilder::stats().dual_clip > clips;
            if (!along_facet) {  // (the dual clip, too, starts the cycle at the generator given first)
                const std::string diff = identical(ours, general, true);
                ASSERT_TRUE(diff.empty()) << diff << ", set " << i << ", h = " << h.transpose() << ", " << f.kind();
            }
        }
    }
    std::cout << "[ConeLaws] cut by a half-space: " << cut << " cut, " << other << " built from all half-spaces; "
              << through_rays << " through two rays, " << through_facets << " along a facet, " << clipped
              << " of the cones of all half-spaces by the dual clip\n";
    EXPECT_GE(cut, testing::floor_of(3000));
    EXPECT_GE(through_rays, testing::floor_of(100));
    EXPECT_GE(through_facets, testing::floor_of(100));
}

// A pointed cone of many generators plus a few (a mode's E = F + (-T): F's one or two rays added
// to a contact cone of up to 2n; 64 rays or more) is the dual of its dual cut by each one's
// half-space: against cddlib from the raw generators of both, with the few random, opposite to a
// ray of F, along a ray or a facet of F, inside F, or a line.
TEST(ConeLaws, SumOfAConeAndAFewGeneratorsAgreesWithExactOracle) {
    testing::Random rnd(20261125);
    int sums = 0, eligible = 0, via_cuts = 0;
    for (int i = 0; i < testing::sized(1000); ++i) {
        std::vector<ExactVector> g;
        std::vector<reference::QVec> raw;
        const int n = rnd.integer(5, 40);
        const bool constructed = i % 3 == 2;
        std::vector<Vec3> doubles = testing::random_generators(rnd, family_of(i), n);
        if (i % 2 == 0) {  // every other one pointed with many rays: a parabola above the plane z = 0
            const int half = rnd.integer(32, 60), shift = rnd.integer(-5, 5), z = rnd.integer(1, 3) * 100;
            doubles.clear();
            for (int t = -half; t <= half; ++t) doubles.emplace_back(t + shift, t * t - 900, z);
        }
        for (const Vec3& d : doubles) {
            if (constructed) {
                const Vec3 v(rnd.integer(-3, 3), rnd.integer(-3, 3), rnd.integer(1, 3));
                g.push_back(ExactVector::cross(ExactVector::input(d), ExactVector::input(v)));
                raw.push_back(reference::cross(reference::q(d), reference::q(v)));
            } else {
                g.push_back(ExactVector::input(d));
                raw.push_back(reference::q(d));
            }
        }
        const Cone f = Cone::from_generators(g);
        std::vector<Vec3> few, lines;
        const int k = rnd.integer(1, 3);
        for (int j = 0; j < k; ++j) {
            const int what = rnd.integer(0, 5);
            const Vec3 random(rnd.integer(-9, 9), rnd.integer(-9, 9), rnd.integer(-9, 9));
            const bool plain_rays = !f.rays().empty() && !f.rays()[0].is_constructed();
            const bool plain_facets = !f.facets().empty() && !f.facets()[0].is_constructed();
            Vec3 v = random;
            if (what == 1 && plain_rays) v = -f.rays()[0].value();
            if (what == 2 && plain_rays) v = f.rays()[0].value() * 2.0;
            if (what == 3 && plain_facets) v = f.facets()[0].value();
            if (what == 4 && plain_rays && f.rays().size() >= 2) v = f.rays()[0].value() + f.rays()[1].value();
            if (v.isZero()) continue;
            (what == 5 ? lines : few).push_back(v);
        }
        const Cone small = Cone::from_generators(few, lines);
        const long cuts_before = ConeBuilder::stats().cuts;
        const Cone ours = sum(f, small);
        eligible += f.dimension() == 3 && f.is_pointed() && f.rays().size() >= 64;
        via_cuts += ConeBuilder::stats().cuts > cuts_before;
        const Cone reversed = sum(small, f);
        for (const Vec3& v : few) raw.push_back(reference::q(v));
        for (const Vec3& v : lines) {
            raw.push_back(reference::q(v));
            raw.push_back(reference::q(Vec3(-v)));
        }
        const auto oracle_cone = oracle::from_generators(raw);
        const std::string why = testing::compare_with_oracle(ours, oracle_cone);
        ASSERT_TRUE(why.empty()) << why << ", set " << i << ", " << f.kind() << " + " << small.kind();
        const std::string why_reversed = testing::compare_with_oracle(reversed, oracle_cone);
        ASSERT_TRUE(why_reversed.empty()) << why_reversed << ", set " << i << " (reversed)";
        ++sums;
    }
    std::cout << "[ConeLaws] a cone plus a few generators: " << sums << " sums, " << eligible
              << " of a pointed 3-dimensional cone, " << via_cuts << " of them through cuts\n";
    EXPECT_GE(via_cuts, eligible / 2);
}

}  // namespace
}  // namespace momentlab
