// The laws of DESIGN.md on 10,000 seeded random cone pairs (half of them exactly degenerate),
// every result checked against cddlib in exact rational mode.
#include <gtest/gtest.h>

#include <map>

#include "../common/random_inputs.hpp"
#include "cone_checks.hpp"
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

}  // namespace
}  // namespace momentlab
