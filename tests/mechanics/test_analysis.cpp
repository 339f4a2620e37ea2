// Per-mode force sets and queries: known answers, and agreement with an exact LP oracle.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "../common/examples.hpp"
#include "../common/scenes.hpp"
#include "../common/sizes.hpp"
#include "mode_oracle.hpp"
#include "random_inputs.hpp"
#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/mechanics/query_index.hpp"

namespace momentlab {
namespace {

std::set<std::string> answer(const std::vector<ModeForces>& a, const Vec3& e) {
    std::set<std::string> out;
    for (std::size_t i : query(a, e).modes) out.insert(a[i].mode.letters);
    return out;
}

// e minus a random 0/1 combination of the generators of every stride-th contact's set for a
// random letter: with e = 0, a wrench on the boundaries between modes.
reference::QVec minus_contact_generators(reference::QVec e, const testing::ExactContacts& c, int n, testing::Random& rnd,
                                         int stride = 1) {
    for (int j = 0; j < n; j += stride) {
        for (const auto& g : c.raw[static_cast<std::size_t>(j)].generators("sfrl"[rnd.integer(0, 3)])) {
            e = reference::add(e, reference::scale(reference::Q(-rnd.integer(0, 1)), g));
        }
    }
    return e;
}

// The modes query_scene (the direct path) says e produces.
std::set<std::string> direct(const Scene& scene, const Vec3& e, bool quasi_static = false, std::size_t* built = nullptr,
                             std::size_t* modes = nullptr) {
    QueryDiagnostics work;
    const SceneAnswer a = query_scene(scene, e, AnalysisOptions{quasi_static}, &work);
    EXPECT_LE(work.built, a.mode_count);
    if (built) *built += work.built;
    if (modes) *modes += a.mode_count;
    // The indices are enumerate_modes' (and analyze's): the same letters there.
    const ModeSet all = enumerate_modes(scene.contacts);
    EXPECT_EQ(a.mode_count, all.modes.size());
    std::size_t closed = 0;  // the letters that are not 's', over every mode
    for (const Mode& mode : all.modes) closed += static_cast<std::size_t>(std::count_if(mode.letters.begin(), mode.letters.end(), [](char c) { return c != 's'; }));
    EXPECT_EQ(work.closed_letters, closed);
    EXPECT_GE(work.tested_generators, work.built);
    EXPECT_EQ(a.modes.size(), a.result.modes.size());
    EXPECT_TRUE(std::is_sorted(a.result.modes.begin(), a.result.modes.end()));
    std::set<std::string> out;
    for (std::size_t k = 0; k < a.modes.size() && k < a.result.modes.size(); ++k) {
        out.insert(a.modes[k].letters);
        EXPECT_EQ(a.modes[k].letters, all.modes.at(a.result.modes[k]).letters) << "mode index " << a.result.modes[k];
        EXPECT_TRUE(a.modes[k].twists == all.modes.at(a.result.modes[k]).twists) << "mode index " << a.result.modes[k];
    }
    EXPECT_EQ(a.result.verdict, verdict_of(out.size()));
    // query(scene, e) gives the same modes, sorted, whichever path it took.
    QueryDiagnostics how;
    const QueryAnswer once = query(scene, e, AnalysisOptions{quasi_static}, how);
    EXPECT_TRUE(std::is_sorted(once.letters.begin(), once.letters.end()));
    EXPECT_EQ(std::set<std::string>(once.letters.begin(), once.letters.end()), out)
        << "query (" << (how.filtered ? "filtered" : "exact") << ") wrench " << e.transpose();
    EXPECT_EQ(once.letters.size(), out.size());
    EXPECT_EQ(once.verdict, a.result.verdict);
    return out;
}

// The indices of the modes whose E holds e, by the exact LP mode by mode.
std::vector<std::size_t> exact_lp_modes(const Scene& scene, const ModeSet& modes, const reference::QVec& e, bool quasi_static) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < modes.modes.size(); ++i) {
        const std::string& letters = modes.modes[i].letters;
        const bool in = quasi_static ? testing::exact_lp_quasi_static_in_mode(scene, letters, e)
                                     : testing::exact_lp_applied_in_mode(scene, letters, e);
        if (in) out.push_back(i);
    }
    return out;
}

// The scene's modes by brute force (the oracle's list: every labelling in {s, f, r, l}^n realisable
// as an open cell, by an exact LP per prefix), after checking that enumerate_modes lists exactly
// these, each once: every listed mode is realisable and every realisable cell is listed. The
// expected answers below then come from the oracle's list, not from the library's.
std::set<std::string> brute_force_modes(const Scene& scene) {
    // The modes depend on the points and normals alone (not on mu or the body): scenes that share
    // them share one brute force.
    static std::map<std::vector<double>, std::set<std::string>> known;
    std::vector<double> key;
    for (const Contact& c : scene.contacts) key.insert(key.end(), {c.point.x(), c.point.y(), c.normal.x(), c.normal.y()});
    auto it = known.find(key);
    if (it == known.end()) it = known.emplace(key, testing::exact_modes(scene.contacts)).first;
    const std::set<std::string>& expected = it->second;
    const ModeSet listed = enumerate_modes(scene.contacts);
    std::set<std::string> letters;
    for (const Mode& m : listed.modes) letters.insert(m.letters);
    EXPECT_EQ(letters.size(), listed.modes.size()) << "a mode listed twice";
    EXPECT_EQ(letters, expected) << "enumerate_modes against the brute force (" << scene.contacts.size() << " contacts)";
    return expected;
}

// The indices (into enumerate_modes' list) of the modes whose E holds e, by the exact LP over the
// brute force's modes.
std::vector<std::size_t> oracle_indices(const Scene& scene, const ModeSet& listed, const std::set<std::string>& modes,
                                        const reference::QVec& e, bool quasi_static) {
    std::vector<std::size_t> out;
    for (const std::string& letters : testing::exact_answer(scene, modes, e, quasi_static)) {
        for (std::size_t i = 0; i < listed.modes.size(); ++i) {
            if (listed.modes[i].letters == letters) out.push_back(i);
        }
    }
    std::sort(out.begin(), out.end());
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
    const Vec2 nrm = integral ? testing::slanted_direction(rnd) : Vec2(rnd.uniform(-1, 1), rnd.uniform(-1, 1));
    const auto [mu, mk] = testing::random_mu(rnd);
    return Contact::make(p, nrm.norm() > 0 ? nrm : Vec2(0, 1), mu, mk);
}

TEST(Analysis, BlockOnATable) {
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

TEST(Analysis, AllFixedModeResistsTheNegatedMultiContactFrictionCone) {
    const auto a = analyze(block_on_table(0.5));
    ASSERT_EQ(a.front().mode.letters, "ff");
    EXPECT_EQ(a.front().total.kind(), "{0}");
    EXPECT_TRUE(a.front().applied == a.front().contact.negated());
}

// Random scenes: body and 1..4 contacts; every query checked against the LP oracle.
TEST(Analysis, QueryAgreesWithExactLpOracle) {
    testing::Random rnd(2718);
    int wrenches = 0, failures = 0;
    std::map<std::string, int> verdicts;
    for (int s = 0; s < testing::sized(120) && failures < 10; ++s) {
        Scene scene;
        scene.body = Body{rnd.uniform(0.5, 2), Vec2(rnd.uniform(-1, 1), rnd.uniform(0, 1)), rnd.uniform(0.1, 1), {}};
        const int n = rnd.integer(1, 4);
        for (int j = 0; j < n; ++j) {
            const bool integral = s % 2 == 1;
            scene.contacts.push_back(random_contact(rnd, integral));
        }
        const auto a = analyze(scene);
        for (int w = 0; w < 90; ++w) {
            const Vec3 e = rnd.vec3(10.0);
            std::set<std::string> expected;
            for (const ModeForces& mf : a) {
                if (testing::exact_lp_applied_in_mode(scene, mf.mode.letters, e)) expected.insert(mf.mode.letters);
            }
            const auto ours = answer(a, e);
            EXPECT_EQ(direct(scene, e), expected) << "query_scene, scene " << s << " wrench " << e.transpose();
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
    std::cout << "[Analysis] " << wrenches << " random wrenches, " << failures << " disagreements; verdicts:";
    for (const auto& [k, v] : verdicts) std::cout << " " << k << "=" << v;
    std::cout << "\n";
    EXPECT_EQ(failures, 0);
    EXPECT_GE(wrenches, testing::floor_of(10000));
}

// Quasi-static (inertia neglected): E_i = -T_i, decided against the exact LP with the inertia
// matrix set to zero, on scenes without a body, for random wrenches and for wrenches that are
// sums of the contacts' generators (on the boundaries of the T_i by construction).
TEST(Analysis, QuasiStaticAgreesWithExactLpWithoutInertia) {
    testing::Random rnd(4242);
    int wrenches = 0, several = 0, none = 0, failures = 0;
    for (int s = 0; s < testing::sized(120) && failures < 10; ++s) {
        Scene scene;  // no body: the quasi-static model needs none
        const int n = rnd.integer(1, 3);
        for (int j = 0; j < n; ++j) {
            const Vec2 p(rnd.integer(-2, 2), rnd.integer(-2, 2));
            const auto [mu, mk] = testing::random_mu(rnd);
            scene.contacts.push_back(Contact::make(p, testing::slanted_direction(rnd), mu, mk));
        }
        const auto a = analyze(scene, AnalysisOptions{true});
        const QueryIndex index(a);
        const testing::ExactContacts c(scene.contacts);
        for (int w = 0; w < 30; ++w) {
            reference::QVec e{0, 0, 0};
            if (w % 2 == 0) {
                e = reference::q(Vec3(rnd.integer(-4, 4), rnd.integer(-4, 4), rnd.integer(-4, 4)));
            } else {
                for (int j = 0; j < n; ++j) {
                    const char letter = "sfrl"[rnd.integer(0, 3)];
                    for (const auto& g : c.raw[static_cast<std::size_t>(j)].generators(letter)) {
                        e = reference::add(e, reference::scale(reference::Q(-rnd.integer(0, 2)), g));
                    }
                }
            }
            // (small integers: every such sum is a double, so none is rounded off its boundary)
            const Vec3 ed = reference::to_vec3(e);
            ASSERT_EQ(reference::q(ed), e) << "scene " << s;
            std::set<std::string> expected;
            for (const ModeForces& mf : a) {
                EXPECT_TRUE(mf.total.is_zero()) << mf.mode.letters;
                if (testing::exact_lp_quasi_static_in_mode(scene, mf.mode.letters, e)) expected.insert(mf.mode.letters);
            }
            std::set<std::string> indexed;
            for (std::size_t i : index.query(ed).modes) indexed.insert(a[i].mode.letters);
            ++wrenches;
            several += expected.size() > 1;
            none += expected.empty();
            if (answer(a, ed) != expected || indexed != expected || direct(scene, ed, true) != expected) {
                ++failures;
                ADD_FAILURE() << "scene " << s << " wrench " << ed.transpose();
            }
        }
    }
    std::cout << "[Analysis] quasi-static: " << wrenches << " wrenches (" << several << " in several modes, " << none
              << " in none), " << failures << " disagreements\n";
    EXPECT_EQ(failures, 0);
    EXPECT_EQ(wrenches, testing::sized(120) * 30);
    EXPECT_GE(several, testing::floor_of(100));
    EXPECT_GE(none, testing::floor_of(100));
}

// By hand, the block on the floor (contacts (0, 0) and (1, 0), normal +y, mu 1/2) held
// quasi-statically: gravity through the centre of mass (1/2, 1/4), (0, -1, -1/2), is balanced by
// the floor at rest (ff), and only there. A horizontal push (1, 0) through it (torque
// -1/4) is balanced by no contact force: with no load on the floor there is no friction, so it
// cannot stay quasi-static (inconsistent), where the dynamic analysis lets it accelerate.
TEST(Analysis, QuasiStaticBlockOnTheFloorByHand) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const auto a = analyze(scene, AnalysisOptions{true});
    EXPECT_EQ(answer(a, Vec3(0, -1, -0.5)), (std::set<std::string>{"ff"}));
    EXPECT_TRUE(answer(a, Vec3(1, 0, -0.25)).empty());
    EXPECT_TRUE(answer(analyze(scene), Vec3(1, 0, -0.25)).count("rr"));
    // Pressed down with 1 and pushed right with exactly mu = 1/2 through the centre of mass
    // (torque 1/2 * -1 - 1/4 * 1/2 = -5/8): the contact force -e = (-1/2, 1, 5/8) is
    // l_1 (-1/2, 1) at (0, 0) plus l_2 (-1/2, 1) at (1, 0) with l_1 + l_2 = 1 and torque l_2 = 5/8:
    // both on the edge n - mu t, so at rest (ff) or sliding right (rr), nothing else.
    EXPECT_EQ(answer(a, Vec3(0.5, -1, -0.625)), (std::set<std::string>{"ff", "rr"}));
}

// QueryIndex against the per-mode test (query, checked against the oracle above) where its
// filter is weakest: wrenches on and next to the planes of the E_i, at extreme magnitudes, and
// scenes with more than the 32 modes of its filtered path.
TEST(Analysis, QueryIndexAgreesWithPerModeQueryOnHardWrenches) {
    testing::Random rnd(31415);
    int checked = 0, on_boundary = 0, exact_path_scenes = 0;
    for (int s = 0; s < testing::sized(80); ++s) {
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
            if (s % 7 == 3) {  // friction cones 1e-17 wide: the E_i's planes nearly parallel in pairs
                const Contact c = scene.contacts.back();
                scene.contacts.back() = Contact::make(c.point, c.normal, 1e-17);
            }
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
    std::cout << "[Analysis] QueryIndex: " << checked << " wrenches (" << on_boundary << " in several modes), "
              << exact_path_scenes << " scenes with > 32 modes\n";
    EXPECT_GE(exact_path_scenes, testing::floor_of(5));
    EXPECT_GE(on_boundary, testing::floor_of(1000));
}

TEST(Analysis, QueryIndexRejectsNonFiniteWrenches) {
    Scene s;
    s.body = Body{1.0, Vec2(0, 0.5), 0.1, {}};
    s.contacts = {Contact::make(Vec2(0, 0), Vec2(0, 1), 0.5)};
    const QueryIndex index(analyze(s));
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (const Vec3& e : {Vec3(nan, 0, 0), Vec3(1, nan, 1), Vec3(0, 0, inf), Vec3(-inf, 1, 1)}) {
        EXPECT_THROW((void)index.query(e), std::invalid_argument) << e.transpose();
    }
}

// Wrenches on the boundaries of the E_i, built in exact rationals from the scene's raw numbers:
// e = M xi - sum of lambda_k g_k with xi = 0, +-N_a x N_b (closing two contacts) or +-N_a x T_1
// (closing one and fixing the first), and integer lambda on the friction generators of a random
// labelling. Such wrenches lie on the faces where modes meet; integer scenes make each an exact
// double, so query and QueryIndex are compared with the exact LP oracle where it matters most.
TEST(Analysis, BoundaryWrenchesAgreeWithExactLpOracle) {
    testing::Random rnd(1618);
    int wrenches = 0, several = 0, failures = 0;
    for (int s = 0; s < testing::sized(160) && failures < 10; ++s) {
        Scene scene;
        scene.body = Body{static_cast<double>(rnd.integer(1, 3)), Vec2(rnd.integer(-2, 2), rnd.integer(-1, 2)),
                          static_cast<double>(rnd.integer(1, 4)), {}};
        const int n = rnd.integer(1, 3);
        for (int j = 0; j < n; ++j) {
            const Vec2 p(rnd.integer(-2, 2), rnd.integer(-2, 2));
            const auto [mu, mk] = testing::random_mu(rnd);
            scene.contacts.push_back(Contact::make(p, testing::slanted_direction(rnd), mu, mk));
        }
        const auto a = analyze(scene);
        const QueryIndex index(a);
        const testing::ExactContacts c(scene.contacts);
        const reference::QMat m = reference::inertia(*scene.body);
        for (int w = 0; w < 24; ++w) {
            reference::QVec xi{0, 0, 0};
            const int kind = rnd.integer(0, 2);
            if (kind == 1 && n >= 2) xi = reference::cross(c.n[0], c.n[1]);
            if (kind == 2) xi = reference::cross(c.n[static_cast<std::size_t>(rnd.integer(0, n - 1))], c.t[0]);
            if (rnd.integer(0, 1)) xi = reference::neg(xi);
            reference::QVec e = reference::mul(m, xi);
            for (int j = 0; j < n; ++j) {
                const char letter = "sfrl"[rnd.integer(0, 3)];
                for (const auto& g : c.raw[static_cast<std::size_t>(j)].generators(letter)) {
                    e = reference::add(e, reference::scale(reference::Q(-rnd.integer(0, 2)), g));
                }
            }
            const Vec3 ed = reference::to_vec3(e);
            ASSERT_EQ(reference::q(ed), e) << "scene " << s;  // (small integers: exact doubles, on the boundaries)
            std::set<std::string> expected;
            for (const ModeForces& mf : a) {
                if (testing::exact_lp_applied_in_mode(scene, mf.mode.letters, e)) expected.insert(mf.mode.letters);
            }
            std::set<std::string> indexed;
            for (std::size_t i : index.query(ed).modes) indexed.insert(a[i].mode.letters);
            ++wrenches;
            several += expected.size() > 1;
            if (answer(a, ed) != expected || indexed != expected || direct(scene, ed) != expected) {
                ++failures;
                ADD_FAILURE() << "scene " << s << " wrench " << ed.transpose();
            }
        }
    }
    std::cout << "[Analysis] " << wrenches << " boundary wrenches (" << several << " in several modes), " << failures
              << " disagreements\n";
    EXPECT_EQ(failures, 0);
    EXPECT_EQ(wrenches, testing::sized(160) * 24);
    EXPECT_GE(several, testing::floor_of(1000));
}

// The direct path on scenes of many contacts, where it rules most modes out by planes and takes
// most members from three generators of an earlier mode: every mode's answer against the exact
// LP (the scene's rationals), for wrenches on the modes' boundaries (sums of contact generators
// and an image of the inertia) and at random, on integral slanted scenes and on contacts whose
// normals lie on one line (every normal wrench the same up to sign). The modes against the brute
// force (so that a mode missing from both the list and the answers, or listed spuriously, fails).
TEST(Analysis, DirectQueryAgreesWithExactLpOnManyContacts) {
    testing::Random rnd(5150);
    int wrenches = 0, members = 0, failures = 0;
    std::size_t built = 0, tested = 0;
    for (int s = 0; s < testing::sized(24) && failures < 5; ++s) {
        Scene scene;
        scene.body = Body{static_cast<double>(rnd.integer(1, 3)), Vec2(rnd.integer(-2, 2), rnd.integer(-1, 2)),
                          static_cast<double>(rnd.integer(1, 4)), {}};
        const int n = rnd.integer(6, 9);
        for (int j = 0; j < n; ++j) {
            const auto [mu, mk] = testing::random_mu(rnd);
            if (s % 2 == 0) {
                scene.contacts.push_back(Contact::make(Vec2(rnd.integer(-2, 2), rnd.integer(-2, 2)), testing::slanted_direction(rnd), mu, mk));
            } else {  // on the x axis, normals +x and -x
                scene.contacts.push_back(Contact::make(Vec2(j - n / 2, 0), Vec2(j % 2 == 0 ? 1 : -1, 0), mu, mk));
            }
        }
        const auto a = analyze(scene);
        const std::set<std::string> modes = brute_force_modes(scene);
        const testing::ExactContacts c(scene.contacts);
        const reference::QMat m = reference::inertia(*scene.body);
        for (int w = 0; w < 12; ++w) {
            reference::QVec e{0, 0, 0};
            if (w % 3 == 0) {
                e = reference::q(Vec3(rnd.integer(-6, 6), rnd.integer(-6, 6), rnd.integer(-6, 6)));
            } else {
                e = reference::mul(m, reference::cross(c.n[0], c.t[static_cast<std::size_t>(rnd.integer(0, n - 1))]));
                if (rnd.integer(0, 1)) e = reference::neg(e);
                e = minus_contact_generators(e, c, n, rnd);
            }
            const Vec3 ed = reference::to_vec3(e);
            ASSERT_EQ(reference::q(ed), e) << "scene " << s;  // (small integers: exact doubles, on the boundaries)
            const std::vector<std::string> answer = testing::exact_answer(scene, modes, e, false);
            const std::set<std::string> expected(answer.begin(), answer.end());
            ++wrenches;
            members += static_cast<int>(expected.size());
            if (direct(scene, ed, false, &built, &tested) != expected) {
                ++failures;
                ADD_FAILURE() << "scene " << s << " (" << a.size() << " modes) wrench " << ed.transpose();
            }
        }
    }
    std::cout << "[Analysis] query_scene: " << wrenches << " wrenches on 6-9 contacts, " << members << " mode answers 'yes', "
              << failures << " disagreements; E built for " << built << " of " << tested << " modes\n";
    EXPECT_EQ(failures, 0);
    if (testing::kFullSize) EXPECT_LT(built, tested);  // the certificates decide some modes
    EXPECT_EQ(wrenches, testing::sized(24) * 12);
    EXPECT_GE(members, testing::floor_of(400));
}

// query_once on scenes of 2 to 12 contacts: generic ones (random doubles), nearly degenerate ones
// (every normal aimed at one point, then moved by about 1e-13, so that triples of N_j are within
// rounding of dependent) and exactly degenerate ones (normals q - p exactly, all N_j in one
// plane), dynamic and quasi-static; random wrenches and sums of contact generators (on the
// boundaries of the sets where the scene is dyadic; rounded to doubles, within rounding of them,
// where it is not). Every answer against the exact LP over the brute force's modes, for the
// doubles asked; e = 0 lists every mode (the enumeration alone, against the brute force). The
// certified doubles must decide the generic questions and must not decide the exactly degenerate
// ones. (Inputs within a few ulps of degeneracies: tests/mechanics/test_one_shot.cpp.)
TEST(Analysis, OneShotAgreesWithExactLp) {
    testing::Random rnd(8086);
    int questions = 0, failures = 0, on_boundary = 0;
    std::map<int, std::pair<int, int>> filtered;  // kind -> (filtered, questions)
    for (int s = 0; s < testing::sized(72) && failures < 5; ++s) {
        const int kind = s % 3;  // 0 generic, 1 nearly degenerate, 2 exactly degenerate
        const bool quasi_static = s % 4 == 3;
        const int n = 2 + (s / 3) % 11;
        Scene scene;
        scene.body = Body{rnd.uniform(0.5, 2), Vec2(rnd.uniform(-0.5, 0.5), rnd.uniform(0, 1)), rnd.uniform(0.1, 1), {}};
        const Vec2 q(rnd.integer(-4, 4) * 0.25, rnd.integer(0, 4) * 0.25);
        for (int j = 0; j < n; ++j) {
            const double a = M_PI * (1.0 + rnd.unit());
            const auto [mu, mk] = testing::random_mu(rnd);
            if (kind == 2) {  // dyadic points and normals q - p, exactly
                const Vec2 p(rnd.integer(-16, 16) * 0.125, rnd.integer(-16, 0) * 0.125 - 0.125);
                scene.contacts.push_back(Contact::make(p, q - p, mu, mk));
                continue;
            }
            const Vec2 p(1.2 * std::cos(a), 0.8 * std::sin(a));
            Vec2 nrm = q - p;
            if (kind == 0) nrm += Vec2(rnd.uniform(-0.4, 0.4), rnd.uniform(-0.4, 0.4));
            if (kind == 1) nrm += Vec2(rnd.uniform(-1e-13, 1e-13), rnd.uniform(-1e-13, 1e-13));
            scene.contacts.push_back(Contact::make(p, nrm, mu, mk));
        }
        const std::set<std::string> modes = brute_force_modes(scene);
        // e = 0 is in every closed E: the answer is every mode.
        const std::vector<std::string> every(modes.begin(), modes.end());
        EXPECT_EQ(query(scene, Vec3::Zero(), AnalysisOptions{quasi_static}).letters, every) << "scene " << s;
        const testing::ExactContacts c(scene.contacts);
        for (int w = 0; w < 10; ++w) {
            reference::QVec e = reference::q(rnd.vec3(10.0));
            if (w % 5 == 4) {  // a sum of generators of the contacts' sets: on boundaries (rounded)
                e = minus_contact_generators({0, 0, 0}, c, n, rnd);
            }
            const Vec3 ed = reference::to_vec3(e);
            on_boundary += reference::q(ed) == e && w % 5 == 4;
            const std::vector<std::string> expected = testing::exact_answer(scene, modes, reference::q(ed), quasi_static);
            QueryDiagnostics how;
            const QueryAnswer once = query(scene, ed, AnalysisOptions{quasi_static}, how);
            ++questions;
            if (w % 5 != 4 && n >= 3) {
                ++filtered[kind].second;
                filtered[kind].first += how.filtered;
            }
            if (once.letters != expected || once.verdict != verdict_of(expected.size())) {
                ++failures;
                ADD_FAILURE() << "scene " << s << " (kind " << kind << ", " << n << " contacts, "
                              << (how.filtered ? "filtered" : "exact") << ") wrench " << ed.transpose();
            }
        }
    }
    std::cout << "[Analysis] query_once: " << questions << " questions (" << on_boundary << " exactly on boundaries), " << failures
              << " disagreements; decided in certified doubles:";
    for (const auto& [kind, f] : filtered) std::cout << " kind " << kind << " " << f.first << "/" << f.second;
    std::cout << "\n";
    EXPECT_EQ(failures, 0);
    EXPECT_EQ(questions, testing::sized(72) * 10);
    EXPECT_GE(on_boundary, testing::floor_of(72) / 3 * 2);  // the exactly degenerate (dyadic) scenes' sums
    EXPECT_GE(filtered[0].first * 10, filtered[0].second * 9);  // generic: at least 90% without the exact path
    EXPECT_EQ(filtered[2].first, 0);                             // exactly degenerate: never
}

// query_once on scaled copies of generic scenes: lengths by 2^k (points, com; inertia by 2^2k;
// torques by 2^k) and forces and mass by 2^j, exact in doubles, leave every mode's letters and
// E (up to diag(1, 1, 2^k)) as they were. The answers stay those of the unscaled scene's exact
// analysis at every scale, the certified doubles decide at moderate scales, and where products
// overflow or underflow the bounds send the question to the exact path.
TEST(Analysis, OneShotAtExtremeMagnitudes) {
    testing::Random rnd(1955);
    int questions = 0, filtered = 0, moderate = 0;
    for (int s = 0; s < testing::sized(24); ++s) {
        Scene scene;
        scene.body = Body{rnd.uniform(0.5, 2), Vec2(rnd.uniform(-0.5, 0.5), rnd.uniform(0, 1)), rnd.uniform(0.1, 1), {}};
        const int n = 2 + s % 5;
        for (int j = 0; j < n; ++j) {
            const double a = M_PI * (1.0 + rnd.unit());
            const Vec2 p(1.2 * std::cos(a), 0.8 * std::sin(a));
            scene.contacts.push_back(Contact::make(p, -p + Vec2(rnd.uniform(-0.4, 0.4), rnd.uniform(-0.4, 0.4)), rnd.uniform(0.1, 1)));
        }
        const auto a = analyze(scene);
        for (int w = 0; w < 6; ++w) {
            const Vec3 e = rnd.vec3(10.0);
            const auto base = answer(a, e);
            for (int k : {-200, -60, 0, 60, 200}) {
                for (int f : {-400, 0, 400}) {  // the inertia (2^(f+2k)) stays a normal double
                    const double len = std::ldexp(1.0, k), force = std::ldexp(1.0, f);
                    Scene t = scene;
                    t.body->mass *= force;
                    t.body->com *= len;
                    t.body->inertia *= force * len * len;
                    for (Contact& c : t.contacts) c.point *= len;
                    QueryDiagnostics how;
                    const QueryAnswer once = query(t, Vec3(force * e.x(), force * e.y(), force * len * e.z()), {}, how);
                    EXPECT_EQ(std::set<std::string>(once.letters.begin(), once.letters.end()), base)
                        << "scene " << s << " lengths 2^" << k << " forces 2^" << f << " wrench " << e.transpose();
                    ++questions;
                    filtered += how.filtered;
                    if (std::abs(k) <= 60 && f == 0) moderate += !how.filtered;
                }
            }
        }
    }
    std::cout << "[Analysis] query_once at extreme magnitudes: " << questions << " questions, " << filtered
              << " decided in certified doubles\n";
    EXPECT_EQ(moderate, 0);  // lengths within 2^+-60 of the unit: never the exact path
    EXPECT_LT(filtered, questions);  // the extremes reach the exact path
}

// Every E_i is a cone, so scaling the wrench by any positive number leaves the answer as it is;
// a tiny wrench is not the zero wrench (which is in every mode's set). Down to the smallest
// subnormal, through the per-mode query, the direct path, query_once and QueryIndex. (Eigen's
// isZero() took coordinates below 1e-12 for zero: (1e-13, 0, 0) gave every mode.)
TEST(Analysis, TinyWrenchesAreNotZero) {
    testing::Random rnd(1013);
    for (int s = 0; s < 6; ++s) {
        Scene scene;
        scene.body = Body{rnd.uniform(0.5, 2), Vec2(rnd.uniform(-0.5, 0.5), rnd.uniform(0, 1)), rnd.uniform(0.1, 1), {}};
        for (int j = 0; j < 2 + s % 3; ++j) {
            const double a = M_PI * (1.0 + rnd.unit());
            const Vec2 p(std::cos(a), std::sin(a));
            scene.contacts.push_back(Contact::make(p, -p + Vec2(rnd.uniform(-0.3, 0.3), rnd.uniform(-0.3, 0.3)), 0.4));
        }
        const auto a = analyze(scene);
        const QueryIndex index(a);
        for (int w = 0; w < 8; ++w) {
            Vec3 e = Vec3::Zero();
            e[w % 3] = w % 2 ? 1.0 : -1.0;  // on one axis, so the tiny copies are exact
            if (w >= 6) e = Vec3(1.0, -0.5, 0.25);
            const auto base = answer(a, e);
            ASSERT_LT(base.size(), a.size()) << "scene " << s;  // not every mode: the test can fail
            for (double scale : {1e-13, 1e-300, 0x1p-1072, 0x1p-1074, 1e300}) {
                const Vec3 t = scale * e;
                if (t / scale != e) continue;  // rounded (subnormal): not a scaled copy
                EXPECT_EQ(answer(a, t), base) << "scene " << s << " scale " << scale;
                EXPECT_EQ(direct(scene, t), base) << "scene " << s << " scale " << scale;
                std::set<std::string> indexed;
                for (std::size_t i : index.query(t).modes) indexed.insert(a[i].mode.letters);
                EXPECT_EQ(indexed, base) << "scene " << s << " scale " << scale;
            }
        }
    }
}

// Scenes large enough (modes x contacts >= 2000; 20 contacts or more) that analyze shares its
// modes out to two threads and query_scene decides the all-f mode beside its walk: the same
// answers as the exact LP over the brute force's modes. Contacts on a line whose normals lie on it
// (+x and -x in turn), random mu: about 4n modes.
TEST(Analysis, LargeScenesOnTwoThreadsAgreeWithExactLp) {
    testing::Random rnd(6021);
    int wrenches = 0, members = 0;
    for (int s = 0; s < 2; ++s) {
        Scene scene;
        scene.body = Body{2.0, Vec2(0, 1), 3.0, {}};
        const int n = 24;
        for (int j = 0; j < n; ++j) {
            const auto [mu, mk] = testing::random_mu(rnd);
            scene.contacts.push_back(Contact::make(Vec2(j - n / 2, 0), Vec2(j % 2 == 0 ? 1 : -1, 0), mu, mk));
        }
        const auto a = analyze(scene);
        ASSERT_GE(a.size() * scene.contacts.size(), 2000u) << "scene " << s << " is not large";
        const std::set<std::string> modes = brute_force_modes(scene);
        const testing::ExactContacts c(scene.contacts);
        for (int w = 0; w < 2; ++w) {
            const reference::QVec e = minus_contact_generators({0, 0, 0}, c, n, rnd, 5);
            const Vec3 ed = reference::to_vec3(e);
            ASSERT_EQ(reference::q(ed), e);
            const std::vector<std::string> answer_of_oracle = testing::exact_answer(scene, modes, e, false);
            const std::set<std::string> expected(answer_of_oracle.begin(), answer_of_oracle.end());
            EXPECT_EQ(answer(a, ed), expected) << "analyze, scene " << s << " wrench " << ed.transpose();
            EXPECT_EQ(direct(scene, ed), expected) << "query_scene, scene " << s << " wrench " << ed.transpose();
            ++wrenches;
            members += static_cast<int>(expected.size());
        }
        std::cout << "[Analysis] large scene " << s << ": " << a.size() << " modes of " << n << " contacts\n";
    }
    std::cout << "[Analysis] " << wrenches << " wrenches on large scenes, " << members << " mode answers 'yes'\n";
    EXPECT_GE(members, 4);
}

// Faces whose every step changes an extreme generator of E: contacts on a line with normals
// along it (at decimal abscissae, whose differences are not doubles, and at integers), a mu of
// its own for each contact and random mu, mu_k (so that no face is grouped: see
// GroupedFacesAgreeWithExactLp); dynamic and quasi-static. Along such a face the certificate of one cell
// breaks at the next, and is mended (a triangle's lost corner replaced or bridged, a plane
// turned about the generator that broke it) instead of testing e against E. Every answer
// against the exact LP over the brute force's modes; the mends must decide most cells. The sums of
// generators are on the boundaries at integer abscissae and dyadic mu; at decimal ones they are
// rounded to doubles (within rounding of the boundaries), and the oracle reads the doubles asked.
TEST(Analysis, MendedCertificatesOnLongFacesAgreeWithExactLp) {
    testing::Random rnd(7331);
    std::size_t built = 0, modes_seen = 0;
    int wrenches = 0, members = 0, on_boundary = 0;
    for (int s = 0; s < 4; ++s) {
        const bool quasi_static = s == 3;
        const int n = 20;
        Scene scene;
        scene.body = Body{1.0, Vec2(0.0, 0.0), 0.5, {}};
        for (int j = 0; j < n; ++j) {
            // (mu of its own for each contact: edges of as many forces, so that no face is grouped)
            const auto [mu, mk] = s == 0 || s == 3 ? std::pair{0.3 + 0.01 * j, 0.3 + 0.01 * j} : testing::random_mu(rnd);
            const double x = s == 1 ? static_cast<double>(j - n / 2) : -1.998 + 0.004 * j * 37;  // (decimal steps)
            scene.contacts.push_back(Contact::make(Vec2(x, 0.0), Vec2(j % 2 == 0 ? 1.0 : -1.0, 0.0), mu, mk));
        }
        const ModeSet modes = enumerate_modes(scene.contacts);
        const std::set<std::string> brute = brute_force_modes(scene);
        const testing::ExactContacts c(scene.contacts);
        for (int w = 0; w < 6; ++w) {
            reference::QVec e = w == 0 ? reference::q(Vec3(0.1, 1, 0.2))
                                : w % 2 == 1 ? reference::q(Vec3(rnd.integer(-3, 3), rnd.integer(-3, 3), rnd.integer(-3, 3)))
                                             : minus_contact_generators({0, 0, 0}, c, n, rnd, 3);
            const Vec3 ed = reference::to_vec3(e);
            on_boundary += w % 2 == 0 && w != 0 && reference::q(ed) == e;
            const std::vector<std::size_t> expected = oracle_indices(scene, modes, brute, reference::q(ed), quasi_static);
            QueryDiagnostics work;
            const SceneAnswer a = query_scene(scene, ed, AnalysisOptions{quasi_static}, &work);
            EXPECT_EQ(a.result.modes, expected) << "scene " << s << ", wrench " << ed.transpose();
            built += work.built;
            modes_seen += a.mode_count;
            ++wrenches;
            members += static_cast<int>(expected.size());
        }
    }
    std::cout << "[Analysis] long faces: " << wrenches << " wrenches (" << on_boundary << " sums exactly on boundaries), " << members
              << " mode answers 'yes'; E built for " << built << " of " << modes_seen << " modes\n";
    EXPECT_EQ(wrenches, 24);
    EXPECT_GE(on_boundary, 2);
    EXPECT_GE(members, 400);
    EXPECT_LT(built * 10, modes_seen);  // (without the mends about half the cells build E)
}

// Rings of contacts whose faces close one contact each (a body in a cradle: normals tilted from
// the radius; normal lines tangent to a circle), where the cells' sets turn a little from one face
// to the next. A facet of E as the certificate has generators on it, which the next cell's turned
// generators cross; a wide plane (room on both sides, exactly checked) lasts. Every answer of a
// batch against the exact LP over the brute force's modes; the batch's answers and counts the same when asked
// again (the walk's parts have certificates of their own, whichever thread takes them), as
// single questions and for e times 2^600 and 2^-600 (the same work); E built for few cells.
TEST(Analysis, WidePlanesOnRingsAgreeWithExactLp) {
    testing::Random rnd(4409);
    std::size_t built = 0, modes_seen = 0;
    std::array<std::size_t, 2> built_scaled{};  // lengths times 2^40, 2^-40
    int wrenches = 0, members = 0;
    for (int s = 0; s < 4; ++s) {
        const bool quasi_static = s == 3;
        const int n = 30;
        Scene scene;
        scene.body = Body{1.0, Vec2(0.0, 0.0), 0.5, {}};
        for (int k = 0; k < n; ++k) {
            const double a = 3.141592653589793 * (1.0 + (k + 0.5) / n), c = std::cos(a), sn = std::sin(a), t = 0.2;
            const Vec2 normal = s % 2 == 0 ? Vec2(-(c * std::cos(t) - sn * std::sin(t)), -(c * std::sin(t) + sn * std::cos(t)))
                                           : Vec2(-sn, c);
            const auto [mu, mk] = s == 2 ? testing::random_mu(rnd) : std::pair{0.3, 0.3};
            scene.contacts.push_back(Contact::make(Vec2(c, sn), normal, mu, mk));
        }
        const ModeSet modes = enumerate_modes(scene.contacts);
        const std::set<std::string> brute = brute_force_modes(scene);
        const testing::ExactContacts c(scene.contacts);
        std::vector<Vec3> asked;
        for (int w = 0; w < 6; ++w) {
            const reference::QVec e = w % 2 == 0 ? reference::q(Vec3(rnd.integer(-3, 3), rnd.integer(-3, 3), rnd.integer(-3, 3)))
                                                 : minus_contact_generators({0, 0, 0}, c, n, rnd, 7);
            // (the sums rounded to doubles: the ring's numbers are not dyadic, so these lie within
            // rounding of the boundaries, not on them; the oracle reads the doubles asked)
            asked.push_back(reference::to_vec3(e));
        }
        // The same ring with every length times 2^40 and 2^-40 (inertia times 2^80 and 2^-80),
        // asked each wrench with its torque scaled alike: the same modes, and E built for under
        // 1/20 of the modes there too (the wide planes' points balanced coordinate by coordinate;
        // without that, torques 2^-40 times the forces left every wide plane's margin below its
        // threshold).
        std::vector<Scene> scaled_scenes;
        for (const int p : {40, -40}) {
            Scene t = scene;
            const double f = std::ldexp(1.0, p);
            t.body = Body{1.0, scene.body->com * f, scene.body->inertia * f * f, {}};
            for (Contact& k : t.contacts) k = Contact::make(k.point * f, k.normal, k.mu, k.mu_kinetic);
            scaled_scenes.push_back(std::move(t));
        }
        SceneQuestions first(scene, AnalysisOptions{quasi_static}), again(scene, AnalysisOptions{quasi_static});
        std::vector<QueryDiagnostics> batch_work, repeated_work;
        const std::vector<SceneAnswer> batch = first.answer(std::span<const Vec3>(asked), &batch_work);
        const std::vector<SceneAnswer> repeated = again.answer(std::span<const Vec3>(asked), &repeated_work);
        ASSERT_EQ(batch.size(), asked.size());
        for (std::size_t w = 0; w < asked.size(); ++w) {
            const std::vector<std::size_t> expected = oracle_indices(scene, modes, brute, reference::q(asked[w]), quasi_static);
            EXPECT_EQ(batch[w].result.modes, expected) << "scene " << s << ", wrench " << asked[w].transpose();
            QueryDiagnostics single_work;
            const SceneAnswer single = query_scene(scene, asked[w], AnalysisOptions{quasi_static}, &single_work);
            EXPECT_EQ(single.result.modes, expected) << "scene " << s;
            // The same work for e times 2^600 and 2^-600 (|e|^2 out of range: wide planes all the same).
            for (const int p : {600, -600}) {
                QueryDiagnostics scaled_work;
                const SceneAnswer scaled = query_scene(scene, asked[w] * std::ldexp(1.0, p), AnalysisOptions{quasi_static}, &scaled_work);
                EXPECT_EQ(scaled.result.modes, expected) << "scene " << s << ", 2^" << p;
                EXPECT_EQ(scaled_work.built, single_work.built) << "scene " << s << ", 2^" << p;
            }
            for (std::size_t k = 0; k < scaled_scenes.size(); ++k) {
                const Vec3 e(asked[w].x(), asked[w].y(), asked[w].z() * std::ldexp(1.0, k == 0 ? 40 : -40));
                QueryDiagnostics longer_work;
                const SceneAnswer longer = query_scene(scaled_scenes[k], e, AnalysisOptions{quasi_static}, &longer_work);
                EXPECT_EQ(longer.result.modes, expected) << "scene " << s << ", lengths times 2^" << (k == 0 ? 40 : -40);
                built_scaled[k] += longer_work.built;
            }
            EXPECT_EQ(repeated[w].result.modes, expected) << "scene " << s;
            EXPECT_EQ(repeated_work[w].built, batch_work[w].built) << "scene " << s;
            EXPECT_EQ(repeated_work[w].tested_generators, batch_work[w].tested_generators) << "scene " << s;
            built += batch_work[w].built;
            modes_seen += batch[w].mode_count;
            ++wrenches;
            members += static_cast<int>(expected.size());
        }
    }
    std::cout << "[Analysis] rings: " << wrenches << " wrenches, " << members << " mode answers 'yes'; E built for " << built
              << " of " << modes_seen << " modes (lengths times 2^40: " << built_scaled[0] << ", 2^-40: " << built_scaled[1]
              << ")\n";
    EXPECT_EQ(wrenches, 24);
    EXPECT_GE(members, 24);
    EXPECT_LT(built * 20, modes_seen);
    for (const std::size_t b : built_scaled) EXPECT_LT(b * 20, modes_seen);
}

// Contacts on a line with normals along it and few distinct forces among their edges (one mu;
// two; mu_k != mu), at decimal and integer abscissae, dynamic and quasi-static: the face's edges
// fall into at most eight groups of one force, each given by its edges of least and greatest
// torque. Every answer against the exact LP over the brute force's modes, and most built E grouped.
// The sums of generators are exact at integer abscissae; at decimal ones (with mu 0.3) they are
// rounded to doubles, within rounding of the boundaries, and the oracle reads the doubles asked.
TEST(Analysis, GroupedFacesAgreeWithExactLp) {
    testing::Random rnd(2718);
    std::size_t built = 0, grouped = 0, scanned = 0;
    int wrenches = 0, members = 0, on_boundary = 0;
    for (int s = 0; s < 4; ++s) {
        const bool quasi_static = s == 3;
        const int n = 20;
        Scene scene;
        scene.body = Body{1.0, Vec2(0.25, 0.5), 0.5, {}};
        for (int j = 0; j < n; ++j) {
            const auto [mu, mk] = s == 1 ? std::pair{j % 3 == 0 ? 0.5 : 0.3, j % 3 == 0 ? 0.5 : 0.3}
                                  : s == 2 ? std::pair{0.5, 0.25}
                                           : std::pair{0.3, 0.3};
            const double x = s == 1 ? static_cast<double>(j - n / 2) : -1.998 + 0.004 * j * 37;  // (decimal steps)
            scene.contacts.push_back(Contact::make(Vec2(x, 0.0), Vec2(j % 2 == 0 ? 1.0 : -1.0, 0.0), mu, mk));
        }
        const ModeSet modes = enumerate_modes(scene.contacts);
        const std::set<std::string> brute = brute_force_modes(scene);
        const testing::ExactContacts c(scene.contacts);
        std::vector<Vec3> asked;
        for (int w = 0; w < 6; ++w) {
            const reference::QVec e = w % 2 == 1 ? reference::q(Vec3(rnd.integer(-3, 3), rnd.integer(-3, 3), rnd.integer(-3, 3)))
                                                 : minus_contact_generators({0, 0, 0}, c, n, rnd, 3);
            const Vec3 ed = reference::to_vec3(e);
            on_boundary += w % 2 == 0 && reference::q(ed) == e;
            asked.push_back(ed);
        }
        SceneQuestions questions(scene, AnalysisOptions{quasi_static});
        std::vector<QueryDiagnostics> work;
        const std::vector<SceneAnswer> answers = questions.answer(std::span<const Vec3>(asked), &work);
        for (std::size_t w = 0; w < asked.size(); ++w) {
            const std::vector<std::size_t> expected = oracle_indices(scene, modes, brute, reference::q(asked[w]), quasi_static);
            EXPECT_EQ(answers[w].result.modes, expected) << "scene " << s << ", wrench " << asked[w].transpose();
            EXPECT_EQ(query_scene(scene, asked[w], AnalysisOptions{quasi_static}).result.modes, expected) << "scene " << s;
            built += work[w].built;
            grouped += work[w].grouped;
            scanned += work[w].scanned_generators;
            ++wrenches;
            members += static_cast<int>(expected.size());
        }
    }
    std::cout << "[Analysis] grouped faces: " << wrenches << " wrenches (" << on_boundary << " sums exactly on boundaries), "
              << members << " mode answers 'yes'; E built for " << built << " cells, " << grouped << " of them grouped; "
              << scanned << " generators scanned by mends\n";
    EXPECT_EQ(wrenches, 24);
    EXPECT_GE(on_boundary, 3);
    EXPECT_GE(members, 200);
    EXPECT_GT(grouped * 2, built);
}

// One SceneQuestions asked many wrenches in a row (the first answer walks with no all-f cone, the
// second builds it, the rest test against it; every answer reuses the walk's set-up), then the same
// wrenches in batches on fresh objects: each answer, with its indices, against the exact LP mode
// by mode. Exactly degenerate scenes (normals q - p),
// dynamic and quasi-static, 1-5 contacts and 24 (two threads); wrenches random, zero, on the
// boundaries of the contacts' sets, and in the all-f mode's E (minus fixed generators of every
// contact).
TEST(Analysis, SceneQuestionsAnswersEveryWrenchOfASequenceAsTheExactLp) {
    testing::Random rnd(1913);
    int questions = 0, members = 0, fixed_members = 0, batched = 0, bounded = 0;
    for (int s = 0; s < testing::sized(24); ++s) {
        const bool quasi_static = s % 3 == 2;
        const int n = s % 6 == 5 ? 24 : 1 + s % 5;
        Scene scene;
        scene.body = Body{rnd.uniform(0.5, 2), Vec2(rnd.uniform(-0.5, 0.5), rnd.uniform(0, 1)), rnd.uniform(0.1, 1), {}};
        const Vec2 q(rnd.integer(-4, 4) * 0.25, rnd.integer(0, 4) * 0.25);
        for (int j = 0; j < n; ++j) {
            const auto [mu, mk] = testing::random_mu(rnd);
            const Vec2 p(rnd.integer(-16, 16) * 0.125, rnd.integer(-16, 0) * 0.125 - 0.125);
            scene.contacts.push_back(Contact::make(p, s % 2 == 0 ? q - p : testing::slanted_direction(rnd), mu, mk));
        }
        const ModeSet modes = enumerate_modes(scene.contacts);
        const testing::ExactContacts c(scene.contacts);
        SceneQuestions questions_of(scene, AnalysisOptions{quasi_static});
        // The bound known before any answer, against the modes found by brute force with exact
        // LPs (up to 3 contacts) and by the walk.
        const std::size_t at_least = questions_of.modes_at_least();
        EXPECT_LE(at_least, modes.modes.size()) << "scene " << s;
        if (n <= 3) {
            EXPECT_LE(at_least, testing::exact_modes(scene.contacts).size()) << "scene " << s;
        }
        bounded += at_least > 1;
        std::vector<Vec3> asked;  // the questions, for the batches below
        std::vector<std::vector<std::size_t>> answers;
        for (int w = 0; w < 8; ++w) {
            reference::QVec e = reference::q(rnd.vec3(10.0));
            if (w % 4 == 1) e = minus_contact_generators({0, 0, 0}, c, n, rnd, n > 8 ? 4 : 1);
            if (w % 4 == 3) {  // minus a 0/1 combination of every contact's static edges
                e = {0, 0, 0};
                for (int j = 0; j < n; ++j) {
                    for (const auto& g : c.raw[static_cast<std::size_t>(j)].generators('f')) {
                        e = reference::add(e, reference::scale(reference::Q(-rnd.integer(0, 1)), g));
                    }
                }
            }
            if (w == 6) e = {0, 0, 0};
            const Vec3 ed = reference::to_vec3(e);
            ASSERT_EQ(reference::q(ed), e) << "scene " << s;  // (the 1/8 grid, dyadic mu: exact doubles)
            const std::vector<std::size_t> expected = exact_lp_modes(scene, modes, e, quasi_static);
            const SceneAnswer a = questions_of.answer(ed);
            ++questions;
            EXPECT_EQ(a.result.modes, expected) << "scene " << s << " (" << n << " contacts), question " << w << ", wrench "
                                                << ed.transpose();
            EXPECT_EQ(a.mode_count, modes.modes.size());
            ASSERT_EQ(a.modes.size(), a.result.modes.size());
            for (std::size_t k = 0; k < a.modes.size(); ++k) {
                EXPECT_EQ(a.modes[k].letters, modes.modes.at(a.result.modes[k]).letters);
            }
            EXPECT_EQ(a.result.verdict, verdict_of(expected.size()));
            members += static_cast<int>(expected.size());
            fixed_members += !expected.empty() && expected.front() == 0;
            asked.push_back(ed);
            answers.push_back(expected);
        }
        // The same questions in batches (one walk for several wrenches), on fresh objects: all at
        // once (the all-f mode's E first without the twists, then with them) and, as the CLI
        // asks a file, the first alone and the rest together.
        if (asked.empty()) continue;
        SceneQuestions all_at_once(scene, AnalysisOptions{quasi_static});
        SceneQuestions first_then_rest(scene, AnalysisOptions{quasi_static});
        const std::vector<SceneAnswer> together = all_at_once.answer(std::span<const Vec3>(asked));
        std::vector<SceneAnswer> split = {first_then_rest.answer(asked.front())};
        for (SceneAnswer& a : first_then_rest.answer(std::span<const Vec3>(asked).subspan(1))) split.push_back(std::move(a));
        ASSERT_EQ(together.size(), asked.size());
        ASSERT_EQ(split.size(), asked.size());
        for (std::size_t k = 0; k < asked.size(); ++k) {
            for (const SceneAnswer* a : std::array<const SceneAnswer*, 2>{&together[k], &split[k]}) {
                EXPECT_EQ(a->result.modes, answers[k]) << "scene " << s << ", batch, wrench " << asked[k].transpose();
                EXPECT_EQ(a->mode_count, modes.modes.size());
                ASSERT_EQ(a->modes.size(), a->result.modes.size());
                for (std::size_t i = 0; i < a->modes.size(); ++i) {
                    EXPECT_EQ(a->modes[i].letters, modes.modes.at(a->result.modes[i]).letters);
                }
            }
            ++batched;
        }
    }
    std::cout << "[Analysis] SceneQuestions: " << questions << " questions, " << members << " mode answers 'yes', "
              << fixed_members << " with the all-f mode; " << batched << " asked again in batches; "
              << bounded << " scenes bounded above 1 mode before any answer\n";
    EXPECT_EQ(batched, questions);
    EXPECT_GE(bounded, testing::floor_of(24) / 2);  // the bound says more than the all-f mode
    EXPECT_EQ(questions, testing::sized(24) * 8);
    EXPECT_GE(fixed_members, testing::floor_of(24) * 2);
}

// The verdicts of random wrenches on the slanted-normal families are the same after an exact
// transform of the scene and the wrench (modes renamed).
TEST(Analysis, QueriesAreInvariantUnderExactTransforms) {
    testing::Random rnd(4242);
    const testing::SceneFamily families[] = {testing::SceneFamily::Concurrent, testing::SceneFamily::OnACircle,
                                             testing::SceneFamily::Parallel, testing::SceneFamily::Collinear,
                                             testing::SceneFamily::SlantedIntegers};
    int checked = 0;
    for (int s = 0; s < testing::sized(300); ++s) {
        const Scene scene = testing::random_scene(rnd, families[s % 5], 4, s % 3 == 2);
        const testing::Transform t = testing::random_transform(rnd, scene.contacts.size());
        if (!testing::exactly_representable(t, scene)) continue;
        const auto a = analyze(scene);
        const auto b = analyze(t.apply(scene));
        for (int w = 0; w < 20; ++w) {
            const Vec2 point = scene.body->com + Vec2(rnd.integer(-4, 4) * 0.25, rnd.integer(-4, 4) * 0.25);
            const Vec2 force(rnd.integer(-4, 4), rnd.integer(-4, 4));
            const Dyadic tau = Dyadic(point.x()) * Dyadic(force.y()) - Dyadic(point.y()) * Dyadic(force.x()) +
                               Dyadic(static_cast<double>(rnd.integer(-2, 2)));
            if (!tau.fits_double()) continue;
            const Vec3 e(force.x(), force.y(), tau.to_double());
            const Vec3 et = t.wrench(e);
            // The transformed torque must be exact too.
            const Vec2 ft(et.x(), et.y());
            const double det = t.linear.topLeftCorner<2, 2>().determinant();
            const Dyadic exact_tau = Dyadic(det) * Dyadic(t.scale) * Dyadic(e.z()) + Dyadic(t.offset.x()) * Dyadic(ft.y()) -
                                     Dyadic(t.offset.y()) * Dyadic(ft.x());
            if (!exact_tau.fits_double() || exact_tau.to_double() != et.z()) continue;
            std::set<std::string> renamed;
            for (const std::string& m : answer(a, e)) renamed.insert(t.letters(m));
            EXPECT_EQ(answer(b, et), renamed) << t.name << " of scene " << s << ", wrench " << e.transpose();
            ++checked;
        }
    }
    std::cout << "[Analysis] " << checked << " wrenches compared under exact transforms\n";
    EXPECT_GE(checked, testing::floor_of(3000));
}

// Far from the origin: the block on a table moved by (1e8, 0) gives the same answers for the
// same forces (the inertia at the origin, I_c + m |c|^2, keeps I_c exactly), and a mass of 1e16
// is an ordinary input.
TEST(Analysis, FarFromTheOriginAndHeavy) {
    Scene near = block_on_table(0.5);
    Scene far = near;
    const Vec2 d(1e8, 0);
    far.body->com += d;
    for (Contact& c : far.contacts) c.point += d;
    const auto a = analyze(near), b = analyze(far);
    const Vec2 weight(0, -10), push(20, 0);
    const Vec2 com = near.body->com, top(0, 0.5);
    EXPECT_EQ(answer(a, force_at(com, weight)), (std::set<std::string>{"ff"}));
    EXPECT_EQ(answer(b, force_at(com + d, weight)), (std::set<std::string>{"ff"}));
    // Weight plus a push at the top corner: tips forward about the front corner, which slides.
    const Vec3 tip = force_at(com, weight) + force_at(top, push);
    const Vec3 tip_far = force_at(com + d, weight) + force_at(top + d, push);
    EXPECT_EQ(answer(a, tip), (std::set<std::string>{"sr"}));
    EXPECT_EQ(answer(b, tip_far), (std::set<std::string>{"sr"}));
    Scene heavy = near;
    heavy.body->mass = 1e16;
    heavy.body->inertia = 1e16 / 12.0 * 1.25;
    const auto h = analyze(heavy);
    EXPECT_EQ(answer(h, force_at(com, Vec2(0, -1e17))), (std::set<std::string>{"ff"}));
}

}  // namespace
}  // namespace momentlab
