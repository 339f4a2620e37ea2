// The laws of DESIGN.md on 10,000 seeded random cone pairs (half of them exactly degenerate),
// every result checked against cddlib in exact rational mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "../common/random_inputs.hpp"
#include "cone_checks.hpp"
#include "geometry/cone_build.hpp"
#include "momentlab/geometry/labels.hpp"

namespace momentlab {
namespace {

using testing::Family;

constexpr int kPairs = 5000;  // two cones each: 10,000 random cones

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
        auto check = [&](const char* what, const Cone& ours, const oracle::OracleCone& o,
                         const std::vector<Vec3>& inputs, Representation primary) {
            ++tally.cases;
            const std::string why = testing::compare_with_oracle(ours, o, inputs, primary);
            if (!why.empty()) {
                ++tally.failures;
                ADD_FAILURE() << what << ": " << why << " in " << where;
            }
        };
        // F and F*; F** = F.
        check("F", f, oracle::from_generators(gf), gf, Representation::Generators);
        check("F*", f.dual(), oracle::from_halfspaces(gf), gf, Representation::Halfspaces);
        EXPECT_TRUE(f.dual().dual() == f) << where;
        // (F + G)* = F* n G*.
        const auto gfg = concat(gf, gg);
        const Cone s = sum(f, g);
        check("F+G", s, oracle::from_generators(gfg), gfg, Representation::Generators);
        const Cone dual_meet = intersection(f.dual(), g.dual());
        const auto dual_normals = concat(f.dual().halfspace_values(), g.dual().halfspace_values());
        check("F* n G*", dual_meet, oracle::from_halfspaces(dual_normals), dual_normals,
              Representation::Halfspaces);
        EXPECT_TRUE(s.dual() == dual_meet) << "(F+G)* != F* n G* for " << where;
        // (F n G)* = F* + G*.
        const Cone meet = intersection(f, g);
        const auto normals = concat(f.halfspace_values(), g.halfspace_values());
        check("F n G", meet, oracle::from_halfspaces(normals), normals, Representation::Halfspaces);
        const Cone dual_sum = sum(f.dual(), g.dual());
        const auto dual_gens = concat(f.dual().generator_values(), g.dual().generator_values());
        check("F* + G*", dual_sum, oracle::from_generators(dual_gens), dual_gens,
              Representation::Generators);
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
    // Every kind of cone must have been exercised.
    for (const char* k : {"{0}", "ray", "line", "wedge", "half-plane", "plane", "pointed cone",
                          "wedge x line", "half-space", "R^3"}) {
        EXPECT_GT(kinds[k], 0) << "no random cone of kind " << k;
    }
}

// Every face: its cone has the stated dimension, and a point of its relative interior (the sum
// of its rays) lies exactly on the facets the face lists and strictly inside the others.
TEST(ConeLaws, FacesAreConsistentWithExactIncidence) {
    testing::Random rnd(11);
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const auto g = testing::random_generators(rnd, family_of(i), 8);
        const Cone c = Cone::from_generators(g);
        for (const Face& face : c.faces()) {
            const Cone fc = c.face_cone(face);
            ASSERT_EQ(fc.dimension(), face.dimension) << testing::describe(g);
            ASSERT_TRUE(subset(fc, c)) << testing::describe(g);
            Vec3 x = Vec3::Zero();
            for (int r : face.rays) x += c.rays()[static_cast<std::size_t>(r)].value();
            for (std::size_t j = 0; j < c.facets().size(); ++j) {
                const bool listed = std::find(face.facets.begin(), face.facets.end(), static_cast<int>(j)) != face.facets.end();
                const Sign s = c.facets()[j].dot_sign(x);
                // x is exact only for small integers (a sum of doubles rounds otherwise).
                if (!testing::is_integral(family_of(i))) continue;
                EXPECT_EQ(s == Sign::Zero, listed) << "facet " << j << " of " << testing::describe(g);
                EXPECT_NE(s, Sign::Negative) << testing::describe(g);
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 5000);
}

// More than 64 generators: the construction then starts from a floating-point guess of an
// extreme ray, and its other paths (retries, the exact dual clip) are taken.
TEST(ConeLaws, ManyGeneratorsAgreeWithExactOracle) {
    testing::Random rnd(7);
    ConeBuilder::stats() = {};
    int failures = 0;
    std::map<std::string, int> kinds;
    for (int i = 0; i < 600; ++i) {
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
        const std::string why = testing::compare_with_oracle(f, oracle::from_generators(g), g,
                                                             Representation::Generators);
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
    EXPECT_GE(kinds["pointed cone"], 50);
    EXPECT_GE(kinds["wedge x line"] + kinds["half-space"], 20);
}

}  // namespace
}  // namespace momentlab
