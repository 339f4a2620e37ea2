// Per-mode force sets and queries: known answers, and agreement with an exact LP oracle.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "../common/random_inputs.hpp"
#include "../common/mode_oracle.hpp"
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

// A contact on [-2, 2] x [-1, 1] with mu in {0, 0.25, .., 1}; integral scenes use small integers
// (exact arithmetic end to end, many exact degeneracies).
Contact random_contact(testing::Random& rnd, bool integral) {
    const Vec2 p = integral ? Vec2(rnd.integer(-2, 2), rnd.integer(-1, 1)) : Vec2(rnd.uniform(-2, 2), rnd.uniform(-1, 1));
    const Vec2 nrm = integral ? Vec2(rnd.integer(-1, 1), 1) : Vec2(rnd.uniform(-1, 1), rnd.uniform(-1, 1));
    return Contact::make(p, nrm.norm() > 0 ? nrm : Vec2(0, 1), rnd.integer(0, 4) * 0.25);
}

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
            scene.contacts.push_back(random_contact(rnd, integral));
        }
        const auto a = analyze(scene);
        const Mat3 m = inertia_at_origin(*scene.body);
        for (int w = 0; w < 90; ++w) {
            const Vec3 e = rnd.vec3(10.0);
            std::set<std::string> expected;
            for (const ModeForces& mf : a) {
                if (testing::exact_lp_applied_in_mode(scene, m, mf.mode.letters, e)) expected.insert(mf.mode.letters);
            }
            const auto ours = answer(a, e);
            const QueryIndex index(a);
            std::set<std::string> indexed;
            for (std::size_t i : index.query(e).modes) indexed.insert(a[i].mode.letters);
            EXPECT_EQ(indexed, expected) << "QueryIndex, scene " << s << " wrench " << e.transpose();
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

// QueryIndex against the per-mode test (query, checked against the oracle above) where its
// filter is weakest: wrenches on and next to the planes of the E_i, at extreme magnitudes, and
// scenes with more than the 32 modes of its filtered path.
TEST(Dynamics, QueryIndexAgreesWithPerModeQueryOnHardWrenches) {
    testing::Random rnd(31415);
    int checked = 0, on_boundary = 0, exact_path_scenes = 0;
    for (int s = 0; s < 80; ++s) {
        Scene scene;
        const bool integral = s % 2 == 0;
        scene.body = Body{1.0, integral ? Vec2(rnd.integer(-1, 1), rnd.integer(0, 1)) : Vec2(rnd.uniform(-1, 1), rnd.uniform(0, 1)),
                          integral ? 1.0 : rnd.uniform(0.1, 1), {}};
        const int n = s % 10 == 9 ? rnd.integer(16, 20) : rnd.integer(1, 5);
        for (int j = 0; j < n; ++j) {
            if (n >= 16) {
                // A twisted cradle: points on a half circle, normals turned 0.2 rad off its centre,
                // so every normal wrench is extreme and there are 2n + 4 > 32 modes.
                const double t = M_PI * (1.0 + (j + 0.5) / n);
                const Vec2 p(std::cos(t), std::sin(t));
                scene.contacts.push_back(Contact::make(p, -(Eigen::Rotation2Dd(0.2) * p), 0.3));
                continue;
            }
            scene.contacts.push_back(random_contact(rnd, integral));
        }
        const auto a = analyze(scene);
        const QueryIndex index(a);
        exact_path_scenes += a.size() > 32;
        std::vector<Vec3> wrenches = {Vec3::Zero()};
        for (const ModeForces& mf : a) {
            const std::vector<Vec3> g = mf.applied.generator_values();
            for (std::size_t i = 0; i < g.size(); ++i) {
                wrenches.push_back(g[i]);                          // on the boundary (exactly, for integral scenes)
                wrenches.push_back(g[i] + g[(i + 1) % g.size()]);  // on a facet, or inside
                Vec3 next = g[i];
                next.x() = std::nextafter(next.x(), 1e300);  // one ulp off
                wrenches.push_back(next);
            }
        }
        for (int w = 0; w < 40; ++w) wrenches.push_back(rnd.vec3(10.0));
        const std::size_t base = wrenches.size();
        for (std::size_t i = 0; i < base; i += 3) {
            for (double k : {0x1p-70, 0x1p-59, 0x1p59, 0x1p70, 0x1p-1040, 0x1p1000}) wrenches.push_back(wrenches[i] * k);
        }
        std::vector<std::size_t> modes;
        for (const Vec3& e : wrenches) {
            const QueryResult expected = query(a, e);
            const Verdict v = index.query(e, modes);
            ASSERT_EQ(modes, expected.modes) << "scene " << s << " wrench " << e.transpose();
            ASSERT_EQ(v, expected.verdict);
            on_boundary += expected.modes.size() > 1;
            ++checked;
        }
    }
    std::cout << "[Dynamics] QueryIndex: " << checked << " wrenches (" << on_boundary << " in several modes), "
              << exact_path_scenes << " scenes with > 32 modes\n";
    EXPECT_GE(exact_path_scenes, 5);
    EXPECT_GE(on_boundary, 1000);
}

TEST(Dynamics, QueryIndexRejectsNonFiniteWrenches) {
    Scene s;
    s.body = Body{1.0, Vec2(0, 0.5), 0.1, {}};
    s.contacts = {Contact::make(Vec2(0, 0), Vec2(0, 1), 0.5)};
    const QueryIndex index(analyze(s));
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (const Vec3& e : {Vec3(nan, 0, 0), Vec3(1, nan, 1), Vec3(0, 0, inf), Vec3(-inf, 1, 1)}) {
        EXPECT_THROW((void)index.query(e), std::invalid_argument) << e.transpose();
    }
}

}  // namespace
}  // namespace momentlab
