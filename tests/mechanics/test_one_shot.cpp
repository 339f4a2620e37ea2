// query(scene, e)'s one-shot path (mechanics/one_shot.cpp) where its error bounds decide: inputs within a few ulps of
// exact degeneracies, in numbers that are not dyadic (so that double arithmetic rounds and its
// rounding, not the scene, would pick a sign), and wrenches within a few ulps of the boundaries
// between modes. Every answer is the exact oracle's (reference/: the doubles read as exact
// rationals; the modes by brute force over {s, f, r, l}^n with an exact LP per prefix, never the
// library's list; each mode's E by one exact LP). Every question made is asked and counted: none
// is dropped. One_shot.cpp with its bounds shrunk (kUnit = 0, every bound / 64, kUnderflow = 0)
// fails here: docs/validation.md, "Mutations", and tools/mutations.sh.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "mode_oracle.hpp"
#include "random_inputs.hpp"
#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/mechanics/analysis.hpp"

namespace momentlab {
namespace {

using reference::QVec;

// The answers of one family of questions.
struct Tally {
    int questions = 0, filtered = 0, wrong = 0;
};

// Asks query(scene, e) and compares with the oracle's answer, `expected`.
void check(const Scene& scene, const Vec3& e, bool quasi_static, const std::vector<std::string>& expected, Tally& t,
           const std::string& what) {
    QueryDiagnostics how;
    const QueryAnswer once = query(scene, e, AnalysisOptions{quasi_static}, how);
    ++t.questions;
    t.filtered += how.filtered;
    if (once.letters != expected || once.verdict != verdict_of(expected.size())) {
        ++t.wrong;
        std::string got, want;
        for (const std::string& m : once.letters) got += m + " ";
        for (const std::string& m : expected) want += m + " ";
        ADD_FAILURE() << what << " (" << scene.contacts.size() << " contacts, " << (quasi_static ? "quasi-static, " : "")
                      << (how.filtered ? "filtered" : "exact path") << ") wrench " << e.transpose() << ": query {"
                      << got << "} oracle {" << want << "}";
    }
}

// The same, with the oracle asked here.
void ask(const Scene& scene, const std::set<std::string>& modes, const Vec3& e, bool quasi_static, Tally& t,
         const std::string& what) {
    check(scene, e, quasi_static, testing::exact_answer(scene, modes, reference::q(e), quasi_static), t, what);
}

// e = 0 is in every closed E: the answer is every mode, so this checks the filtered enumeration
// against the brute force.
void ask_zero(const Scene& scene, const std::set<std::string>& modes, bool quasi_static, Tally& t, const std::string& what) {
    check(scene, Vec3::Zero(), quasi_static, std::vector<std::string>(modes.begin(), modes.end()), t, what);
}

// x moved by k ulps (k < 0: down).
double ulps(double x, int k) {
    for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
    for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
    return x;
}

Body random_body(testing::Random& rnd) {
    return Body{rnd.uniform(0.5, 2), Vec2(rnd.uniform(-0.5, 0.5), rnd.uniform(0, 1)), rnd.uniform(0.1, 1), {}};
}

// Points on an ellipse about the origin (cos and sin: not dyadic) with normals aimed at q, rounded:
// every normal line passes within rounding of q, so every three N_j are within rounding of
// dependent (exactly they are not, in general).
Scene nearly_concurrent(testing::Random& rnd, int n) {
    Scene s;
    s.body = random_body(rnd);
    const Vec2 q(rnd.uniform(-0.5, 0.5), rnd.uniform(0, 1));
    for (int j = 0; j < n; ++j) {
        const double a = M_PI * (1.0 + rnd.unit());
        const Vec2 p(1.2 * std::cos(a), 0.8 * std::sin(a));
        const double mu = rnd.uniform(0.1, 1.0);
        s.contacts.push_back(Contact::make(p, q - p, mu, j % 2 ? mu : rnd.uniform(0.1, 1.0)));
    }
    return s;
}

// Points (x, x / 3 rounded) on the line y = x / 3; every other contact has its normal along the
// line, +-(0.3, 0.1) rounded, so that its normal line passes within rounding of every contact
// point, the others a normal of their own: moments of one contact's normal about another's point,
// and sliding directions on the rays of A (T_a . (N_b x N_c)), are then within rounding of zero.
Scene on_a_rounded_line(testing::Random& rnd, int n) {
    Scene s;
    s.body = random_body(rnd);
    for (int j = 0; j < n; ++j) {
        const double x = rnd.uniform(-2, 2);
        const double mu = rnd.uniform(0.1, 1.0);
        const Vec2 normal = j % 2 ? Vec2(rnd.uniform(-1, 1), 1.0) : (j % 4 ? Vec2(0.3, 0.1) : Vec2(-0.3, -0.1));
        s.contacts.push_back(Contact::make(Vec2(x, x / 3.0), normal, mu, mu));
    }
    return s;
}

// Random doubles: points on an ellipse, normals towards its centre give or take 0.4.
Scene generic(testing::Random& rnd, int n) {
    Scene s;
    s.body = random_body(rnd);
    for (int j = 0; j < n; ++j) {
        const double a = M_PI * (1.0 + rnd.unit());
        const Vec2 p(1.2 * std::cos(a), 0.8 * std::sin(a));
        s.contacts.push_back(Contact::make(p, -p + Vec2(rnd.uniform(-0.4, 0.4), rnd.uniform(-0.4, 0.4)), rnd.uniform(0.1, 1.0)));
    }
    return s;
}

// Wrenches near the boundaries of the contact sets, in doubles: the force of contact j along a
// friction edge d = n +- mu t (or along n), negated, at its point, with the torque p x d as doubles
// compute it (the rounded product), and that torque moved by -2 .. 2 ulps.
std::vector<Vec3> through_a_contact(const Scene& scene, testing::Random& rnd) {
    std::vector<Vec3> out;
    const Contact& c = scene.contacts[static_cast<std::size_t>(rnd.integer(0, static_cast<int>(scene.contacts.size()) - 1))];
    const int side = rnd.integer(-1, 1);
    const Vec2 d = c.normal + side * c.mu * c.tangent();
    const double tau = c.point.x() * d.y() - c.point.y() * d.x();
    for (int k = -2; k <= 2; ++k) out.push_back(-Vec3(d.x(), d.y(), ulps(tau, k)));
    return out;
}

// A wrench on the boundaries between modes, exactly (rationals from the scene's raw numbers):
// M xi, xi = 0 or +-(N_a x N_b), minus a 0/1 combination of random letters' contact generators;
// rounded to doubles and then moved by -1, +1 ulps in each coordinate in turn.
std::vector<Vec3> rounded_boundary(const Scene& scene, bool quasi_static, testing::Random& rnd) {
    const testing::ExactContacts c(scene.contacts);
    const int n = static_cast<int>(scene.contacts.size());
    QVec e{0, 0, 0};
    if (!quasi_static && rnd.integer(0, 1)) {
        const auto a = static_cast<std::size_t>(rnd.integer(0, n - 1)), b = static_cast<std::size_t>(rnd.integer(0, n - 1));
        QVec xi = reference::cross(c.n[a], c.n[b]);
        if (rnd.integer(0, 1)) xi = reference::neg(xi);
        e = reference::mul(reference::inertia(*scene.body), xi);
    }
    for (int j = 0; j < n; ++j) {
        for (const QVec& g : c.raw[static_cast<std::size_t>(j)].generators("sfrl"[rnd.integer(0, 3)])) {
            if (rnd.integer(0, 1)) e = reference::add(e, reference::neg(g));
        }
    }
    const Vec3 rounded = reference::to_vec3(e);
    std::vector<Vec3> out = {rounded};
    for (int i = 0; i < 3; ++i) {
        for (int k : {-1, 1}) {
            Vec3 moved = rounded;
            moved[i] = ulps(moved[i], k);
            out.push_back(moved);
        }
    }
    return out;
}

// The families of near degeneracies, each with every kind of question: e = 0 (the enumeration),
// random wrenches, wrenches through a contact with a rounded torque, rounded boundary wrenches.
void run_family(const char* name, Scene (*make)(testing::Random&, int), std::uint64_t seed, int scenes, int first_n,
                int last_n, int min_exact_path) {
    testing::Random rnd(seed);
    Tally t;
    for (int s = 0; s < scenes; ++s) {
        const int n = first_n + s % (last_n - first_n + 1);
        const bool quasi_static = s % 4 == 3;
        const Scene scene = make(rnd, n);
        const std::set<std::string> modes = testing::exact_modes(scene.contacts);
        const std::string what = std::string(name) + ", scene " + std::to_string(s);
        ask_zero(scene, modes, quasi_static, t, what);
        ask(scene, modes, rnd.vec3(2.0), quasi_static, t, what);
        for (int k = 0; k < 2; ++k) {
            for (const Vec3& e : through_a_contact(scene, rnd)) ask(scene, modes, e, quasi_static, t, what + ", through a contact");
            for (const Vec3& e : rounded_boundary(scene, quasi_static, rnd)) ask(scene, modes, e, quasi_static, t, what + ", boundary");
        }
    }
    std::cout << "[OneShot] " << name << ": " << t.questions << " questions, " << t.filtered << " decided in certified doubles, "
              << t.wrong << " disagreements\n";
    EXPECT_EQ(t.wrong, 0);
    EXPECT_EQ(t.questions, scenes * 26);  // 1 + 1 + 2 (5 + 7) per scene: none dropped
    EXPECT_GE(t.questions - t.filtered, min_exact_path);  // the bounds sent these to the exact path
}

TEST(OneShot, NormalsConcurrentUpToRounding) { run_family("nearly concurrent", nearly_concurrent, 9001, 16, 3, 4, 200); }

TEST(OneShot, PointsOnARoundedLine) { run_family("on y = x / 3 rounded", on_a_rounded_line, 9002, 16, 2, 5, 60); }

TEST(OneShot, GenericScenesNearTheirBoundaries) { run_family("generic", generic, 9003, 16, 2, 5, 40); }

// Generic scenes of 7 to 12 contacts, decided in certified doubles: every mode the brute force
// finds, and no other (e = 0 lists them all), and random wrenches' answers.
TEST(OneShot, SevenToTwelveContactsListEveryModeOfTheBruteForce) {
    testing::Random rnd(9004);
    Tally t;
    for (int s = 0; s < 6; ++s) {
        const int n = 7 + s;
        const bool quasi_static = s % 3 == 2;
        const Scene scene = generic(rnd, n);
        const std::set<std::string> modes = testing::exact_modes(scene.contacts);
        ask_zero(scene, modes, quasi_static, t, "scene " + std::to_string(s));
        for (int w = 0; w < 2; ++w) ask(scene, modes, rnd.vec3(2.0), quasi_static, t, "scene " + std::to_string(s));
    }
    std::cout << "[OneShot] 7-12 contacts: " << t.questions << " questions, " << t.filtered << " decided in certified doubles\n";
    EXPECT_EQ(t.wrong, 0);
    EXPECT_EQ(t.questions, 18);
    EXPECT_GE(t.filtered, 16);  // the filtered enumeration itself, not the exact path
}

// Normals exactly through one point on the 1/8 grid (every three N_j dependent: their
// determinants are exactly 0, and so is their evaluation in doubles).
Scene exactly_concurrent(testing::Random& rnd, int n) {
    Scene s;
    s.body = random_body(rnd);
    const Vec2 q(rnd.integer(-4, 4) * 0.125, rnd.integer(0, 8) * 0.125);
    for (int j = 0; j < n; ++j) {
        const Vec2 p(rnd.integer(-16, 16) * 0.125, rnd.integer(-16, 0) * 0.125 - 0.125);
        s.contacts.push_back(Contact::make(p, q - p, rnd.integer(1, 6) * 0.125));
    }
    return s;
}

// Normals scaled by 2^-k (exact; the modes and every E stay as they were): products of three normal
// coordinates (the enumeration's determinants) fall into the subnormal range at k = 341 .. 358, and
// those of one normal coordinate and two images of twists (a dynamic E's determinants) too; there
// a product keeps a few bits, and the bounds' relative terms underflow with it. Their underflow
// term (2^-1000 per operation) sends those questions to the exact path. Three contacts, exactly
// and nearly concurrent (where the signs in question are 0 or within rounding of it), the whole
// mode list (e = 0) at every k; a few wrenches on generic scenes. The oracle answers each
// unscaled scene once.
TEST(OneShot, TinyNormalsWhoseProductsUnderflow) {
    testing::Random rnd(9005);
    Tally t;
    for (int s = 0; s < 64; ++s) {
        const bool quasi_static = s % 4 >= 2;
        const Scene scene = s % 2 ? nearly_concurrent(rnd, 3) : exactly_concurrent(rnd, 3);
        const std::set<std::string> modes = testing::exact_modes(scene.contacts);
        for (int k = 340; k <= 360; ++k) {
            Scene tiny = scene;
            for (Contact& c : tiny.contacts) c.normal *= std::ldexp(1.0, -k);
            ask_zero(tiny, modes, quasi_static, t, "scene " + std::to_string(s) + ", normals times 2^-" + std::to_string(k));
        }
    }
    for (int s = 0; s < 4; ++s) {
        const bool quasi_static = s % 2 == 1;
        const Scene scene = generic(rnd, 3 + s);
        const std::set<std::string> modes = testing::exact_modes(scene.contacts);
        std::vector<Vec3> wrenches = {rnd.vec3(2.0)};
        for (const Vec3& e : through_a_contact(scene, rnd)) wrenches.push_back(e);
        for (const Vec3& e : wrenches) {
            const std::vector<std::string> expected = testing::exact_answer(scene, modes, reference::q(e), quasi_static);
            for (int k = 340; k <= 360; k += 2) {
                Scene tiny = scene;
                for (Contact& c : tiny.contacts) c.normal *= std::ldexp(1.0, -k);
                check(tiny, e, quasi_static, expected, t, "generic scene " + std::to_string(s) + ", normals times 2^-" + std::to_string(k));
            }
        }
    }
    std::cout << "[OneShot] tiny normals: " << t.questions << " questions, " << t.filtered << " decided in certified doubles\n";
    EXPECT_EQ(t.wrong, 0);
    EXPECT_EQ(t.questions, 64 * 21 + 4 * 6 * 11);
}

}  // namespace
}  // namespace momentlab
