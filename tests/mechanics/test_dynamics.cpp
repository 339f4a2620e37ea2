// Per-mode force sets and queries: known answers, and agreement with an exact LP oracle.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "../common/random_inputs.hpp"
#include "../oracle/lp_oracle.hpp"
#include "momentlab/mechanics/dynamics.hpp"

namespace momentlab {
namespace {

std::set<std::string> answer(const std::vector<ModeForces>& a, const Vec3& e) {
    std::set<std::string> out;
    for (std::size_t i : query(a, e).modes) out.insert(a[i].mode.letters);
    return out;
}

// A 1 x 0.5 block on a table (contacts at its bottom corners), mass 1, mu 0.5.
Scene block_on_table(double mu) {
    Scene s;
    s.body = Body{1.0, Vec2(0.5, 0.25), 1.0 / 12.0 * (1.0 + 0.25), {}};
    s.contacts = {Contact::make(Vec2(0, 0), Vec2(0, 1), mu), Contact::make(Vec2(1, 0), Vec2(0, 1), mu)};
    return s;
}

Vec3 force_at(const Vec2& p, const Vec2& f) { return wrench_at(p, f); }

TEST(Dynamics, BlockOnATable) {
    const auto a = analyze(block_on_table(0.5));
    const double g = 9.81;
    const Vec3 weight = force_at(Vec2(0.5, 0.25), Vec2(0, -g));
    // At rest under gravity: only ff (the contacts can hold the weight).
    EXPECT_EQ(answer(a, weight), (std::set<std::string>{"ff"}));
    // Pushed hard (20 N, friction can give at most mu m g = 4.9 N) along the base: slides, rr.
    EXPECT_EQ(answer(a, weight + force_at(Vec2(0, 0.01), Vec2(20, 0))), (std::set<std::string>{"rr"}));
    // Pushed hard near the top: the moment of the push about the front corner (20 N x 0.49 m)
    // beats that of the weight (9.81 N x 0.5 m): it tips forward about the front corner,
    // which slides since mu = 0.5 cannot stop 20 N: sr.
    EXPECT_EQ(answer(a, weight + force_at(Vec2(0, 0.49), Vec2(20, 0))), (std::set<std::string>{"sr"}));
    // Lifted by more than its weight through the centre of mass: flies off, ss.
    EXPECT_EQ(answer(a, weight + force_at(Vec2(0.5, 0.25), Vec2(0, 2 * g))), (std::set<std::string>{"ss"}));
}

TEST(Dynamics, AllFixedModeResistsTheNegatedMultiContactFrictionCone) {
    const auto a = analyze(block_on_table(0.5));
    ASSERT_EQ(a.front().mode.letters, "ff");
    EXPECT_EQ(a.front().total.kind(), "{0}");
    EXPECT_TRUE(a.front().applied == a.front().contact.negated());
}

// Random scenes: body and 1..4 contacts; every query checked against the LP oracle.
TEST(Dynamics, QueryAgreesWithExactLpOracle) {
    testing::Random rnd(2718);
    int wrenches = 0, failures = 0;
    std::map<std::string, int> verdicts;
    for (int s = 0; s < 120 && failures < 10; ++s) {
        Scene scene;
        scene.body = Body{rnd.uniform(0.5, 2), Vec2(rnd.uniform(-1, 1), rnd.uniform(0, 1)), rnd.uniform(0.1, 1), {}};
        const int n = rnd.integer(1, 4);
        for (int j = 0; j < n; ++j) {
            const bool integral = s % 2 == 1;
            const Vec2 p = integral ? Vec2(rnd.integer(-2, 2), rnd.integer(-1, 1)) : Vec2(rnd.uniform(-2, 2), rnd.uniform(-1, 1));
            const Vec2 nrm = integral ? Vec2(rnd.integer(-1, 1), 1) : Vec2(rnd.uniform(-1, 1), rnd.uniform(-1, 1));
            scene.contacts.push_back(Contact::make(p, nrm.norm() > 0 ? nrm : Vec2(0, 1), rnd.integer(0, 4) * 0.25));
        }
        const auto a = analyze(scene);
        const Mat3 m = inertia_at_origin(*scene.body);
        std::vector<Vec3> nn, tt;
        for (const Contact& c : scene.contacts) {
            nn.push_back(c.normal_wrench());
            tt.push_back(c.tangent_wrench());
        }
        for (int w = 0; w < 90; ++w) {
            const Vec3 e = rnd.vec3(10.0);
            std::set<std::string> expected;
            for (const ModeForces& mf : a) {
                std::vector<std::vector<Vec3>> gens(scene.contacts.size());
                for (std::size_t j = 0; j < scene.contacts.size(); ++j) {
                    const Contact& c = scene.contacts[j];
                    const Vec2 nv = c.normal, tv = c.tangent();
                    const char l = mf.mode.letters[j];
                    if (l == 'f') gens[j] = {force_at(c.point, nv + c.mu * tv), force_at(c.point, nv - c.mu * tv)};
                    if (l == 'r') gens[j] = {force_at(c.point, nv - c.mu_kinetic * tv)};
                    if (l == 'l') gens[j] = {force_at(c.point, nv + c.mu_kinetic * tv)};
                }
                if (oracle::applied_in_mode(m, nn, tt, gens, mf.mode.letters, e)) expected.insert(mf.mode.letters);
            }
            const auto ours = answer(a, e);
            ++wrenches;
            ++verdicts[to_string(query(a, e).verdict)];
            if (ours != expected) {
                ++failures;
                std::string x, y;
                for (const auto& q : ours) x += q + " ";
                for (const auto& q : expected) y += q + " ";
                ADD_FAILURE() << "scene " << s << " wrench " << e.transpose() << ": ours {" << x << "} oracle {" << y << "}";
            }
        }
    }
    std::cout << "[Dynamics] " << wrenches << " random wrenches, " << failures << " disagreements; verdicts:";
    for (const auto& [k, v] : verdicts) std::cout << " " << k << "=" << v;
    std::cout << "\n";
    EXPECT_EQ(failures, 0);
    EXPECT_GE(wrenches, 10000);
}

}  // namespace
}  // namespace momentlab
