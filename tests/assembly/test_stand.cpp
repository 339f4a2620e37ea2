// momentlab stand: the bundled examples against their hand derivations (docs/assemblies.md),
// random assemblies against an exact oracle that shares nothing with the library
// (assembly_oracle.hpp: cddlib on the raw numbers), one body against query_scene, exact
// transforms, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "../common/sizes.hpp"
#include "assembly_oracle.hpp"
#include "assembly_scenes.hpp"
#include "momentlab/assembly/assembly_json.hpp"
#include "momentlab/io/files.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/mechanics/analysis.hpp"

namespace momentlab {
namespace {

using assembly_oracle::Q;
using testing::sized;

Assembly example(const std::string& name) {
    return read_assembly_text(read_json_file(std::string(MOMENTLAB_EXAMPLES) + "/" + name));
}

// The exact direction (x, y) of a tilt end, from its text.
std::array<Q, 2> exact(const ExactDirection& d) { return {Q(d.exact[0]), Q(d.exact[1])}; }

void expect_wedge(const TiltCone& t, const Q& x1, const Q& y1, const Q& x2, const Q& y2) {
    ASSERT_EQ(t.kind, TiltCone::Kind::Wedge);
    ASSERT_EQ(t.directions.size(), 2U);
    // Directions are scaled so that the larger coordinate is +-1.
    const auto normal = [](Q x, Q y) {
        const Q s = abs(x) > abs(y) ? Q(abs(x)) : Q(abs(y));
        return std::array<Q, 2>{x / s, y / s};
    };
    EXPECT_EQ(exact(t.directions[0]), normal(x1, y1)) << t.directions[0].exact[0] << " " << t.directions[0].exact[1];
    EXPECT_EQ(exact(t.directions[1]), normal(x2, y2)) << t.directions[1].exact[0] << " " << t.directions[1].exact[1];
}

// ---------------------------------------------------------------------------------------------
// The examples, as derived by hand in docs/assemblies.md.

TEST(StandExamples, ModernRoboticsTwoBlocksCannotStand) {
    const StandResult r = stand(example("assembly-modern-robotics.json"), {.tilt = true});
    EXPECT_FALSE(r.equilibrium.can_stand);
    ASSERT_EQ(r.equilibrium.mechanism.size(), 2U);
    ASSERT_TRUE(r.outcome);
    EXPECT_EQ(*r.outcome, Outcome::Falls);
    EXPECT_EQ(r.tilt->kind, TiltCone::Kind::Empty);  // mu = 0.1 at the floor: no tilt helps
}

Assembly modern_robotics(double mass2) {
    Assembly a = example("assembly-modern-robotics.json");
    a.contacts[0].contact.mu = a.contacts[0].contact.mu_kinetic = 0.5;
    a.bodies[1].mass = mass2;
    return a;
}

TEST(StandExamples, ModernRoboticsStandsWithMuHalfAndMassTen) {
    const StandResult r = stand(modern_robotics(10), {.tilt = true});
    EXPECT_TRUE(r.equilibrium.can_stand);
    EXPECT_EQ(*r.outcome, Outcome::Stands);
    expect_wedge(*r.tilt, Q(-13, 59), -1, Q(5, 77), -1);
}

TEST(StandExamples, ModernRoboticsMassFiveIsExactlyOnTheBoundary) {
    const StandResult r = stand(modern_robotics(5), {.tilt = true});
    EXPECT_TRUE(r.equilibrium.can_stand);
    // The block is about to tip about its right corner: no force at its left corner.
    EXPECT_EQ(r.equilibrium.forces[2], Vec2(0, 0));
    expect_wedge(*r.tilt, Q(-5, 19), -1, 0, -1);  // gravity (0, -1) is an end
    // A little lighter and it falls; a little heavier and (0, -1) is inside.
    EXPECT_FALSE(equilibrium(modern_robotics(4.999)).can_stand);
    EXPECT_TRUE(equilibrium(modern_robotics(5.001)).can_stand);
}

TEST(StandExamples, ModernRoboticsFloorFrictionThreshold) {
    // mu at the floor >= 10/31 for mu = 1/2 at the block (and its mass >= 5).
    Assembly a = modern_robotics(10);
    a.contacts[0].contact.mu = a.contacts[0].contact.mu_kinetic = 10.0 / 31.0 * (1 + 1e-12);
    EXPECT_TRUE(equilibrium(a).can_stand);
    a.contacts[0].contact.mu = a.contacts[0].contact.mu_kinetic = 10.0 / 31.0 * (1 - 1e-12);
    EXPECT_FALSE(equilibrium(a).can_stand);
}

TEST(StandExamples, LadderAtTheSlipLimit) {
    const StandResult r = stand(example("assembly-ladder.json"), {.tilt = true});
    EXPECT_TRUE(r.equilibrium.can_stand);
    EXPECT_EQ(*r.outcome, Outcome::Stands);
    expect_wedge(*r.tilt, 0, -1, Q(3, 2), -1);  // gravity (0, -1) is an end
    Assembly a = example("assembly-ladder.json");
    a.contacts[0].contact.mu = a.contacts[0].contact.mu_kinetic = 0.375 - 0x1p-40;
    EXPECT_FALSE(equilibrium(a).can_stand);
    a.contacts[0].contact.mu = a.contacts[0].contact.mu_kinetic = 0.5;
    expect_wedge(tilt_cone(a), Q(-1, 4), -1, Q(7, 4), -1);
    // The classical condition with wall friction: slips when tan(alpha) < (1 - mu_f mu_w) / (2 mu_f).
    a.contacts[1].contact.mu = a.contacts[1].contact.mu_kinetic = 0.25;  // mu_f* = 12/35
    a.contacts[0].contact.mu = a.contacts[0].contact.mu_kinetic = 12.0 / 35.0 * (1 + 1e-12);
    EXPECT_TRUE(equilibrium(a).can_stand);
    a.contacts[0].contact.mu = a.contacts[0].contact.mu_kinetic = 12.0 / 35.0 * (1 - 1e-12);
    EXPECT_FALSE(equilibrium(a).can_stand);
}

TEST(StandExamples, HarmonicStackExactlyAtTheOverhangLimit) {
    const Assembly a = example("assembly-harmonic-stack.json");
    ASSERT_EQ(a.contacts.size(), 8U);
    const StandResult r = stand(a, {.tilt = true});
    EXPECT_TRUE(r.equilibrium.can_stand);
    EXPECT_EQ(*r.outcome, Outcome::Stands);  // an equilibrium of normal forces alone: nothing moves
    expect_wedge(*r.tilt, Q(-1, 2), -1, 0, -1);
    // Each level's load rests on the outer end of its support alone.
    for (std::size_t j = 0; j < 8; j += 2) EXPECT_EQ(r.equilibrium.forces[j], Vec2(0, 0)) << j;
    // The top brick a little further out: it falls.
    Assembly b = a;
    for (Vec2& v : b.bodies[3].polygon) v.x() += 0x1p-20;
    b.bodies[3].com.x() += 0x1p-20;
    b.contacts = find_assembly_contacts(b.bodies, b.obstacles, {.distance = 1e-9, .mu = 0.5, .mu_kinetic = 0.5});
    EXPECT_FALSE(equilibrium(b).can_stand);
}

TEST(StandExamples, ThreeBlockArch) {
    const StandResult r = stand(example("assembly-arch.json"), {.tilt = true});
    EXPECT_TRUE(r.equilibrium.can_stand);
    EXPECT_EQ(*r.outcome, Outcome::Stands);
    // Symmetric: the wedge's ends are mirror images.
    ASSERT_EQ(r.tilt->kind, TiltCone::Kind::Wedge);
    const auto d1 = exact(r.tilt->directions[0]), d2 = exact(r.tilt->directions[1]);
    EXPECT_EQ(d1[0], -d2[0]);
    EXPECT_EQ(d1[1], d2[1]);
    // It stands for mu >= (sqrt(29) - 3) / 10 = 0.23851...
    for (const auto& [mu, stands] : {std::pair{0.2385, false}, std::pair{0.2386, true}}) {
        Assembly a = example("assembly-arch.json");
        for (AssemblyContact& c : a.contacts) c.contact.mu = c.contact.mu_kinetic = mu;
        EXPECT_EQ(equilibrium(a).can_stand, stands) << mu;
    }
}

TEST(StandExamples, ArchTiltEndsAreTheHandDerivedOnes) {
    // gamma* = k (5 mu - k) / (5 k - mu), k = (2 - mu) / (1 + 2 mu), for mu the double read.
    const Assembly a = example("assembly-arch.json");
    const Q mu(a.contacts[0].contact.mu);
    const Q k = (2 - mu) / (1 + 2 * mu);
    const Q end = k * (5 * mu - k) / (5 * k - mu);
    expect_wedge(tilt_cone(a), -end, -1, end, -1);
    // At mu = 3/10 exactly that is 595/6416; the double 0.3 is a little below 3/10, and so is its end.
    const Q k3 = Q(17, 16);
    EXPECT_EQ(k3 * (5 * Q(3, 10) - k3) / (5 * k3 - Q(3, 10)), Q(595, 6416));
    EXPECT_LT(mu, Q(3, 10));
    EXPECT_LT(end, Q(595, 6416));
}

// The examples' modes, motions and outcomes against the oracle (assembly_oracle.hpp), with the
// variants of the hand derivations.
TEST(StandExamples, ModesAndMotionsAgreeWithTheOracle) {
    std::vector<std::pair<std::string, Assembly>> cases;
    for (const char* name : {"assembly-modern-robotics.json", "assembly-ladder.json", "assembly-harmonic-stack.json",
                             "assembly-arch.json"}) {
        cases.push_back({name, example(name)});
    }
    cases.push_back({"modern robotics, mass 10", modern_robotics(10)});
    cases.push_back({"modern robotics, mass 5", modern_robotics(5)});
    for (const auto& [what, a] : cases) {
        const assembly_oracle::QAssembly q = assembly_oracle::exact(a);
        const StandResult r = stand(a, {.gravity = Vec2(0, -1)});
        ASSERT_TRUE(r.modes) << what;
        const std::set<std::string> modes = assembly_oracle::modes(q, 0, -1);
        EXPECT_EQ(std::set<std::string>(r.modes->modes.begin(), r.modes->modes.end()), modes) << what;
        std::set<std::string> motions;
        for (const std::string& m : modes) {
            if (assembly_oracle::has_motion(q, m, 0, -1)) motions.insert(m);
        }
        EXPECT_EQ(std::set<std::string>(r.modes->motions.begin(), r.modes->motions.end()), motions) << what;
        EXPECT_EQ(r.equilibrium.can_stand, assembly_oracle::can_stand(q, 0, -1)) << what;
    }
}

// ---------------------------------------------------------------------------------------------
// Random assemblies against the oracle.

class Rng {
public:
    explicit Rng(std::uint64_t seed) : rng_(seed) {}
    int integer(int lo, int hi) { return lo + static_cast<int>(rng_() % static_cast<std::uint64_t>(hi - lo + 1)); }
    template <class T>
    const T& pick(const std::vector<T>& v) { return v[static_cast<std::size_t>(integer(0, static_cast<int>(v.size()) - 1))]; }

private:
    std::mt19937_64 rng_;
};

Polygon rectangle(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

AssemblyBody brick(double x0, double y0, double w, double h) {
    AssemblyBody b;
    b.mass = w * h;
    b.com = Vec2(x0 + w / 2, y0 + h / 2);
    b.inertia = b.mass * (w * w + h * h) / 16;  // any positive inertia (a dyadic one)
    b.polygon = rectangle(x0, y0, x0 + w, y0 + h);
    return b;
}

struct Generated {
    Assembly assembly;
    bool boundary = false;  // built exactly on a boundary
    const char* family = "";
};

// A stack of 2-4 bricks on a floor; a brick's load (the bricks above) may sit exactly over the
// end of its support (boundary), inside, or beyond.
Generated stack(Rng& r) {
    Generated g{{}, false, "stack"};
    const int n = r.integer(2, 4);
    std::vector<double> width(static_cast<std::size_t>(n));
    for (double& w : width) w = r.pick(std::vector<double>{2, 4, 6});
    // From the top down: each brick placed under the bricks above so that their centre of mass
    // is at `where` along its top (0 left end, 1 right end; beyond falls).
    std::vector<double> left(static_cast<std::size_t>(n), 0.0);
    double mass_above = 0.0, moment_above = 0.0;
    for (int k = n - 1; k >= 0; --k) {
        const auto i = static_cast<std::size_t>(k);
        if (k == n - 1) {
            left[i] = 0;
        } else {
            const double com = moment_above / mass_above;
            const int kind = r.integer(0, 5);
            const double where = kind == 0 ? 1.0 : kind == 1 ? 0.0 : kind == 2 ? 1.25 : 0.5;
            g.boundary = g.boundary || kind <= 1;
            left[i] = com - where * width[i];
        }
        mass_above += width[i];
        moment_above += width[i] * (left[i] + width[i] / 2);
    }
    const double mu = r.pick(std::vector<double>{0.25, 0.5, 1.0});
    for (int k = 0; k < n; ++k) g.assembly.bodies.push_back(brick(left[static_cast<std::size_t>(k)], k, width[static_cast<std::size_t>(k)], 1));
    const double floor_left = left[0] + (r.integer(0, 1) ? 0.0 : width[0] / 2);  // the floor may end under the bottom brick
    g.assembly.obstacles = {rectangle(floor_left - 20, -1, floor_left + (floor_left == left[0] ? 40.0 : 0.0), 0)};
    g.assembly.contacts = find_assembly_contacts(g.assembly.bodies, g.assembly.obstacles, {.distance = 1e-9, .mu = mu, .mu_kinetic = mu});
    return g;
}

// A rod leaning from the floor against a block standing on the floor (the block may slide or
// tip). With no friction at the block, the rod slips exactly when mu_f < w / (2 h); h a power of
// two makes that threshold a double.
Generated leaning(Rng& r) {
    Generated g{{}, false, "leaning"};
    const double h = r.pick(std::vector<double>{2, 4, 8});
    const double w = r.integer(1, 6);
    const double threshold = w / (2 * h);
    AssemblyBody rod;
    rod.mass = 1;
    rod.com = Vec2(w / 2, h / 2);
    rod.inertia = 1;
    AssemblyBody block = brick(w, 0, r.pick(std::vector<double>{2, 4}), h + r.integer(0, 2));
    block.mass = r.pick(std::vector<double>{1, 4, 16});
    g.assembly.bodies = {rod, block};
    const int kind = r.integer(0, 2);
    const double mu_f = kind == 0 ? threshold : kind == 1 ? threshold * 2 : threshold / 2;
    g.boundary = kind == 0;
    const double mu_w = kind == 0 ? 0.0 : r.pick(std::vector<double>{0.0, 0.5});
    const double mu_b = r.pick(std::vector<double>{0.25, 1.0});
    g.assembly.contacts = {
        {1, 0, Contact::make(Vec2(0, 0), Vec2(0, 1), mu_f)},
        {1, 2, Contact::make(Vec2(w, h), Vec2(-1, 0), mu_w)},
        {2, 0, Contact::make(Vec2(w, 0), Vec2(0, 1), mu_b, mu_b / 2)},
        {2, 0, Contact::make(Vec2(w + (block.polygon[1].x() - w), 0), Vec2(0, 1), mu_b)},
    };
    return g;
}

// Two or three bodies and random contacts among them and the world: integer points and normals,
// friction 0, 1/2, 1, 2 or 4 (kinetic sometimes half; the high values give cases that may fall);
// centres of mass often straight above a contact (a boundary).
Generated random_contacts(Rng& r) {
    Generated g{{}, false, "random"};
    const int n = r.integer(2, 3);
    for (int k = 0; k < n; ++k) {
        AssemblyBody b;
        b.mass = r.integer(1, 3);
        b.com = Vec2(r.integer(-2, 2), r.integer(0, 3));
        b.inertia = r.integer(1, 4);
        g.assembly.bodies.push_back(b);
    }
    const int m = r.integer(3, 5);
    for (int j = 0; j < m; ++j) {
        const int a = r.integer(1, n);
        int b = r.integer(0, n - 1);
        if (b >= a) b = 0;
        Vec2 normal(r.integer(-2, 2), r.integer(-1, 3));
        if (normal == Vec2(0, 0)) normal = Vec2(0, 1);
        const double mu = r.pick(std::vector<double>{0.0, 0.5, 1.0, 2.0, 4.0});
        const double muk = r.integer(0, 3) == 0 ? mu / 2 : mu;
        const Vec2 point(r.integer(-2, 2), r.integer(-1, 2));
        g.boundary = g.boundary || point.x() == g.assembly.bodies[static_cast<std::size_t>(a - 1)].com.x();
        g.assembly.contacts.push_back({static_cast<std::size_t>(a), static_cast<std::size_t>(b), Contact::make(point, normal, mu, muk)});
    }
    return g;
}

// The oracle's tilt cone: whether some gravity stands, and its boundary rays (each once).
using D = std::array<Q, 2>;
std::vector<D> oracle_tilt_ends(const assembly_oracle::QAssembly& q, bool& feasible) {
    std::vector<D> ends;
    feasible = false;
    const int charts[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    for (const auto& u : charts) {
        const assembly_oracle::Chart c = assembly_oracle::tilt_chart(q, u[0], u[1]);
        feasible = feasible || c.feasible;
        for (const D& d : c.ends) {
            bool known = false;
            for (const D& e : ends) known = known || (d[0] * e[1] - d[1] * e[0] == 0 && d[0] * e[0] + d[1] * e[1] > 0);
            if (!known) ends.push_back(d);
        }
    }
    return ends;
}

// The oracle's tilt cone against the library's: the same boundary rays, exactly.
void expect_same_tilt(const assembly_oracle::QAssembly& q, const TiltCone& t, const std::string& what) {
    bool feasible = false;
    const std::vector<D> ends = oracle_tilt_ends(q, feasible);
    if (!feasible) {
        EXPECT_EQ(t.kind, TiltCone::Kind::Empty) << what;
        return;
    }
    if (ends.empty()) {
        EXPECT_EQ(t.kind, TiltCone::Kind::Plane) << what;
        return;
    }
    ASSERT_EQ(t.directions.size(), ends.size()) << what << " kind " << to_string(t.kind);
    for (const ExactDirection& d : t.directions) {
        const D v = exact(d);
        bool found = false;
        for (const D& e : ends) found = found || (v[0] * e[1] - v[1] * e[0] == 0 && v[0] * e[0] + v[1] * e[1] > 0);
        EXPECT_TRUE(found) << what << ": " << d.exact[0] << ", " << d.exact[1];
    }
    if (t.kind == TiltCone::Kind::Wedge) {
        const D a = exact(t.directions[0]), b = exact(t.directions[1]);
        EXPECT_GT(a[0] * b[1] - a[1] * b[0], 0) << what;  // counter-clockwise
    }
    if (t.kind == TiltCone::Kind::HalfPlane || t.kind == TiltCone::Kind::Line) {
        const D a = exact(t.directions[0]);
        const bool left = assembly_oracle::can_stand(q, -a[1], a[0]);
        const bool right = assembly_oracle::can_stand(q, a[1], -a[0]);
        EXPECT_EQ(t.kind == TiltCone::Kind::HalfPlane, left) << what;
        EXPECT_FALSE(right) << what;
    }
}

TEST(StandOracle, RandomAssembliesAgreeWithExactOracle) {
    Rng r(4711);
    int cases = 0, boundary = 0, stand_count = 0, modes_compared = 0, tilts = 0;
    std::array<int, 4> outcomes{};  // stands, may fall, falls, inconsistent
    const int count = sized(90);
    for (int k = 0; k < count; ++k) {
        const int family = k % 3;
        const Generated g = family == 0 ? stack(r) : family == 1 ? leaning(r) : random_contacts(r);
        const std::string what = std::string(g.family) + " case " + std::to_string(k);
        const assembly_oracle::QAssembly q = assembly_oracle::exact(g.assembly);
        const Vec2 gravity(0, -1);
        const Equilibrium e = equilibrium(g.assembly, gravity);
        ASSERT_EQ(e.can_stand, assembly_oracle::can_stand(q, 0, -1)) << what;
        stand_count += e.can_stand;
        expect_same_tilt(q, tilt_cone(g.assembly), what);
        ++tilts;
        if (g.assembly.contacts.size() <= 6) {
            const AssemblyModes m = assembly_modes(g.assembly, gravity);
            const std::set<std::string> expected = assembly_oracle::modes(q, 0, -1);
            ASSERT_EQ(std::set<std::string>(m.modes.begin(), m.modes.end()), expected) << what;
            EXPECT_EQ(m.verdict, verdict_of(expected.size())) << what;
            std::set<std::string> motions;
            for (const std::string& mode : expected) {
                if (assembly_oracle::has_motion(q, mode, 0, -1)) motions.insert(mode);
            }
            ASSERT_EQ(std::set<std::string>(m.motions.begin(), m.motions.end()), motions) << what;
            const Outcome outcome = expected.empty() ? Outcome::Inconsistent
                                    : !e.can_stand    ? Outcome::Falls
                                    : motions.empty() ? Outcome::Stands
                                                      : Outcome::MayFall;
            outcomes[static_cast<std::size_t>(outcome)] += 1;
            EXPECT_EQ(outcome_of(e, m), outcome) << what;
            ++modes_compared;
        }
        boundary += g.boundary;
        ++cases;
    }
    std::printf("assemblies: %d (%d on a boundary, %d stand), modes compared on %d (outcomes: %d stands, %d may fall, "
                "%d falls, %d inconsistent), tilt cones on %d\n",
                cases, boundary, stand_count, modes_compared, outcomes[0], outcomes[1], outcomes[2], outcomes[3], tilts);
    // How often each kind of case came up: asserted at full size (the sanitizers' runs are smaller).
    EXPECT_GE(3 * boundary, cases);
    if (testing::kFullSize) {
        EXPECT_GT(outcomes[1], 0);  // may fall: an equilibrium and a motion (high friction)
        EXPECT_GT(stand_count, cases / 4);
        EXPECT_LT(stand_count, cases * 3 / 4);
    }
}

// ---------------------------------------------------------------------------------------------
// Arches and walls (the benchmark's scenes, assembly_scenes.hpp, small enough for the oracle):
// can_stand and the tilt cone against the oracle. Boundaries: gravity along each end of the
// oracle's tilt cone (integer vectors: only the direction matters); walls whose top brick
// overhangs its support by exactly half its length, and walls tilted by gamma with friction
// exactly gamma (each joint's resultant on the edge of its cone); each with a variant just
// beyond (the brick 2^-20 further out, the friction 2^-30 less), which falls.

// A rational direction as integers (exact doubles), when they fit in 53 bits.
std::optional<Vec2> integer_direction(const D& d) {
    const Q scale(mpz_class(d[0].get_den() * d[1].get_den()));
    const Q x = d[0] * scale, y = d[1] * scale;
    for (const Q& v : {x, y}) {
        if (v.get_den() != 1 || mpz_sizeinbase(v.get_num().get_mpz_t(), 2) > 53) return std::nullopt;
    }
    return Vec2(x.get_d(), y.get_d());
}

TEST(StandOracle, ArchesAndWallsAgreeWithExactOracle) {
    Rng r(1789);
    int scenes = 0, decisions = 0, boundary = 0, stands = 0, at_tilt_ends = 0, overhangs = 0, thresholds = 0,
        beyond = 0, skipped = 0;
    const auto decide = [&](const Assembly& a, const assembly_oracle::QAssembly& q, const Vec2& g, bool on_boundary,
                            const std::string& what) {
        const bool expected = assembly_oracle::can_stand(q, Q(g.x()), Q(g.y()));
        EXPECT_EQ(equilibrium(a, g).can_stand, expected) << what << ", gravity " << g.transpose();
        ++decisions;
        boundary += on_boundary;
        stands += expected;
        return expected;
    };
    const int count = sized(40);
    for (int k = 0; k < count; ++k) {
        Assembly a;
        Vec2 gravity(0, -1);
        std::string what;
        int kind = -1;  // walls: 0 upright, 1 upright with the overhang, 2 tilted with friction gamma
        if (k % 2 == 0) {
            const int voussoirs = r.integer(2, 5);
            const double thickness = r.pick(std::vector<double>{0.5, 1.0, 1.5}), mu = r.pick(std::vector<double>{0.25, 0.5, 1.0});
            a = assembly_scenes::dyadic_arch(voussoirs, thickness, mu);
            what = "arch of " + std::to_string(voussoirs) + ", thickness " + std::to_string(thickness) + ", mu " + std::to_string(mu);
        } else {
            const int per_row = r.integer(1, 3);
            kind = r.integer(0, 2);
            const double gamma = r.pick(std::vector<double>{0.125, 0.25});
            const double mu = kind == 2 ? gamma : r.pick(std::vector<double>{0.25, 0.5});
            // With the overhang, whole pairs of rows: the top brick is the last of an odd row.
            const int bricks = kind == 1 ? 2 * per_row * r.integer(1, 2) : r.integer(2, 8);
            a = assembly_scenes::running_bond_wall(bricks, per_row, mu, kind == 1, kind == 1 ? std::optional(0.0) : std::nullopt);
            if (kind == 2) gravity = Vec2(gamma, -1);
            what = "wall of " + std::to_string(bricks) + ", " + std::to_string(per_row) + " a row, kind " + std::to_string(kind);
        }
        // The scene's contacts are those where its polygons touch (in another order; the normals
        // found are unit vectors, rounded: compared as directions to within rounding).
        const std::vector<AssemblyContact> found = find_assembly_contacts(a.bodies, a.obstacles, {.distance = 1e-9});
        ASSERT_EQ(found.size(), a.contacts.size()) << what;
        for (const AssemblyContact& c : a.contacts) {
            EXPECT_TRUE(std::any_of(found.begin(), found.end(), [&](const AssemblyContact& f) {
                const Vec2 n = c.contact.normal.normalized(), m = f.contact.normal;
                return f.a == c.a && f.b == c.b && f.contact.point == c.contact.point && std::abs(n.x() * m.y() - n.y() * m.x()) < 1e-12 &&
                       n.dot(m) > 0;
            })) << what << ": contact at " << c.contact.point.transpose();
        }
        const assembly_oracle::QAssembly q = assembly_oracle::exact(a);
        const bool upright = decide(a, q, gravity, false, what);
        if (kind == 1) {
            ASSERT_TRUE(upright) << what;  // exactly on the boundary: it stands
            ++overhangs;
            ++boundary;
            Assembly out = a;
            out.bodies.back().com.x() += 0x1p-20;
            EXPECT_FALSE(decide(out, assembly_oracle::exact(out), gravity, false, what + ", brick further out")) << what;
            ++beyond;
        }
        if (kind == 2 && upright) {  // the friction at the threshold: on the boundary
            ++thresholds;
            ++boundary;
            Assembly less = a;
            for (AssemblyContact& c : less.contacts) c.contact.mu = c.contact.mu_kinetic = gravity.x() - 0x1p-30;
            EXPECT_FALSE(decide(less, assembly_oracle::exact(less), gravity, false, what + ", less friction")) << what;
            ++beyond;
        }
        expect_same_tilt(q, tilt_cone(a), what);
        bool feasible = false;
        for (const D& end : oracle_tilt_ends(q, feasible)) {
            const std::optional<Vec2> g = integer_direction(end);
            if (!g) {
                ++skipped;
                continue;
            }
            EXPECT_TRUE(decide(a, q, *g, true, what + ", at a tilt end")) << what;  // the cone is closed
            ++at_tilt_ends;
        }
        ++scenes;
    }
    std::printf("arches and walls: %d scenes, %d can_stand decisions (%d exactly on a boundary: %d at tilt ends, %d overhangs, "
                "%d friction thresholds; %d just beyond one), %d stand; %d tilt ends too large for doubles\n",
                scenes, decisions, boundary, at_tilt_ends, overhangs, thresholds, beyond, stands, skipped);
    EXPECT_GE(3 * boundary, decisions);
    EXPECT_GE(at_tilt_ends, testing::floor_of(count / 2));
    EXPECT_GE(overhangs, testing::floor_of(count / 40));
    EXPECT_GE(thresholds, testing::floor_of(count / 40));
    EXPECT_GE(decisions - stands, testing::floor_of(count / 8));  // some fall
}

// ---------------------------------------------------------------------------------------------
// One body: the modes and the verdict of query (the gravity wrench).

TEST(StandOneBody, ModesAreThoseOfQueryOnRandomScenes) {
    Rng r(2024);
    int cases = 0, boundary = 0, ambiguous = 0;
    const int count = sized(300);
    for (int k = 0; k < count; ++k) {
        Scene s;
        Body body;
        body.mass = r.integer(1, 3);
        body.com = Vec2(r.integer(-2, 2), r.integer(0, 3));
        body.inertia = r.integer(1, 4);
        s.body = body;
        const int m = r.integer(1, 5);
        bool on_boundary = false;
        for (int j = 0; j < m; ++j) {
            Vec2 normal(r.integer(-2, 2), r.integer(-1, 3));
            if (normal == Vec2(0, 0)) normal = Vec2(0, 1);
            const Vec2 point(r.integer(-2, 2), r.integer(-1, 1));
            on_boundary = on_boundary || point.x() == body.com.x();
            const double mu = r.pick(std::vector<double>{0.0, 0.5, 1.0});
            s.contacts.push_back(Contact::make(point, normal, mu, r.integer(0, 3) == 0 ? mu / 2 : mu));
        }
        // Gravity (0, -1): the wrench (0, -m, -m c.x), exact in doubles.
        const Vec3 wrench(0, -body.mass, -body.mass * body.com.x());
        const SceneAnswer answer = query_scene(s, wrench);
        std::vector<std::string> expected;
        for (const Mode& mode : answer.modes) expected.push_back(mode.letters);
        std::sort(expected.begin(), expected.end());
        const AssemblyModes got = assembly_modes(assembly_of(s), Vec2(0, -1));
        std::vector<std::string> letters = got.modes;
        std::sort(letters.begin(), letters.end());
        ASSERT_EQ(letters, expected) << "case " << k;
        ASSERT_EQ(got.verdict, answer.result.verdict) << "case " << k;
        boundary += on_boundary;
        ambiguous += got.verdict == Verdict::Ambiguous;
        ++cases;
    }
    std::printf("one body: %d scenes (%d with the centre of mass above a contact, %d ambiguous)\n", cases, boundary, ambiguous);
    EXPECT_GE(3 * boundary, cases);
}

// ---------------------------------------------------------------------------------------------
// Exact transforms: a quarter turn (gravity turned too), a dyadic translation, a mirror (r <-> l).

Assembly transformed(const Assembly& a, auto&& point, auto&& vector) {
    Assembly b = a;
    for (AssemblyBody& body : b.bodies) {
        body.com = point(body.com);
        for (Vec2& v : body.polygon) v = point(v);
    }
    for (Polygon& o : b.obstacles) {
        for (Vec2& v : o) v = point(v);
    }
    for (AssemblyContact& c : b.contacts) {
        c.contact.point = point(c.contact.point);
        c.contact.normal = vector(c.contact.normal);
    }
    return b;
}

std::string swapped(std::string letters) {
    for (char& c : letters) c = c == 'r' ? 'l' : (c == 'l' ? 'r' : c);
    return letters;
}

TEST(StandTransforms, QuarterTurnsTranslationsAndMirrorsGiveTheSameAnswers) {
    int checked = 0;
    for (const char* name : {"assembly-modern-robotics.json", "assembly-ladder.json", "assembly-harmonic-stack.json",
                             "assembly-arch.json"}) {
        const Assembly a = example(name);
        const Vec2 g(0, -1);
        const StandResult base = stand(a, {.gravity = g, .tilt = true});
        const auto turn = [](const Vec2& v) { return Vec2(-v.y(), v.x()); };
        const auto shift = [](const Vec2& v) { return Vec2(v.x() + 0.75, v.y() - 1024.5); };
        const auto mirror = [](const Vec2& v) { return Vec2(-v.x(), v.y()); };
        const auto same = [](const Vec2& v) { return v; };
        struct Case {
            Assembly assembly;
            Vec2 gravity;
            bool mirrored;
            std::function<Vec2(const Vec2&)> direction;
        };
        const std::vector<Case> cases = {
            {transformed(a, turn, turn), turn(g), false, turn},
            {transformed(a, shift, same), g, false, same},
            {transformed(a, mirror, mirror), mirror(g), true, mirror},
        };
        for (const Case& c : cases) {
            const StandResult r = stand(c.assembly, {.gravity = c.gravity, .tilt = true});
            EXPECT_EQ(r.equilibrium.can_stand, base.equilibrium.can_stand) << name;
            ASSERT_TRUE(r.modes && base.modes);
            std::vector<std::string> expected = base.modes->modes, got = r.modes->modes;
            if (c.mirrored) {
                for (std::string& m : expected) m = swapped(m);
            }
            std::sort(expected.begin(), expected.end());
            std::sort(got.begin(), got.end());
            EXPECT_EQ(got, expected) << name;
            EXPECT_EQ(*r.outcome, *base.outcome) << name;
            ASSERT_EQ(r.tilt->kind, base.tilt->kind) << name;
            ASSERT_EQ(r.tilt->directions.size(), base.tilt->directions.size()) << name;
            // The directions moved by the transform (a mirror reverses the counter-clockwise order).
            const std::size_t n = base.tilt->directions.size();
            for (std::size_t i = 0; i < n; ++i) {
                const std::size_t k = c.mirrored && r.tilt->kind == TiltCone::Kind::Wedge ? n - 1 - i : i;
                const auto v = exact(base.tilt->directions[k]);
                const Vec2 moved = c.direction(Vec2(1, 2));  // the transform's linear part on (x, y)
                (void)moved;
                std::array<Q, 2> w;
                const Vec2 ex = c.direction(Vec2(1, 0)), ey = c.direction(Vec2(0, 1));
                w[0] = v[0] * Q(ex.x()) + v[1] * Q(ey.x());
                w[1] = v[0] * Q(ex.y()) + v[1] * Q(ey.y());
                const auto got_d = exact(r.tilt->directions[i]);
                EXPECT_EQ(got_d[0] * w[1] - got_d[1] * w[0], 0) << name;
                EXPECT_GT(got_d[0] * w[0] + got_d[1] * w[1], 0) << name;
            }
            ++checked;
        }
    }
    EXPECT_EQ(checked, 12);
}

// ---------------------------------------------------------------------------------------------
// Bad input: one InputError naming the field.

void expect_error(const std::string& text, const std::string& path) {
    try {
        (void)read_assembly_text(text);
        ADD_FAILURE() << "no error for " << text;
    } catch (const InputError& e) {
        EXPECT_EQ(e.path(), path) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
}

TEST(StandInput, BadAssembliesNameTheField) {
    const std::string bodies = R"("bodies": [{"mass": 1, "com": [0, 1], "polygon": [[-1, 0], [1, 0], [1, 2], [-1, 2]]},
                                             {"mass": 1, "com": [0, 3], "polygon": [[-1, 2], [1, 2], [1, 4], [-1, 4]]}])";
    expect_error("{" + bodies + R"(, "contacts": [{"bodies": [3, 0], "point": [0, 0], "normal": [0, 1]}]})",
                 "$.contacts[0].bodies");
    expect_error("{" + bodies + R"(, "contacts": [{"bodies": [1, 5], "point": [0, 0], "normal": [0, 1]}]})",
                 "$.contacts[0].bodies");
    expect_error("{" + bodies + R"(, "contacts": [{"bodies": [0, 1], "point": [0, 0], "normal": [0, 1]}]})",
                 "$.contacts[0].bodies");
    expect_error("{" + bodies + R"(, "contacts": [{"bodies": [2, 2], "point": [0, 2], "normal": [0, 1]}]})",
                 "$.contacts[0].bodies");
    expect_error(R"({"bodies": [{"com": [0, 1]}], "contacts": []})", "$.bodies[0]");
    expect_error(R"({"bodies": [{"mass": 0, "com": [0, 1]}], "contacts": []})", "$.bodies[0].mass");
    expect_error(R"({"bodies": [{"mass": 1, "com": [0, 1], "polygon": [[-1, 0], [1, 0], [1, 2], [-1, 2]]},
                                {"mass": 1, "com": [0, 3], "polygon": [[-1, 1], [1, 1], [1, 4], [-1, 4]]}]})",
                 "$.bodies[1].polygon");
    expect_error("{" + bodies + R"(, "contacts": [{"bodies": [1, 0], "point": [0, 0], "normal": [0, 0]}]})",
                 "$.contacts[0].normal");
    expect_error("{" + bodies + R"(, "contacts": [{"bodies": [1, 0], "point": [5, 0], "normal": [0, 1]}]})",
                 "$.contacts[0].point");
    expect_error(R"({"bodies": [], "contacts": []})", "$.bodies");
    // The modes need every body's inertia.
    const Assembly no_inertia = read_assembly_text("{" + bodies + R"(, "obstacles": [{"polygon": [[-5, -1], [5, -1], [5, 0], [-5, 0]]}]})");
    EXPECT_THROW((void)assembly_modes(no_inertia), InputError);
    const StandResult r = stand(no_inertia);
    EXPECT_FALSE(r.modes);
    EXPECT_FALSE(r.modes_reason.empty());
    EXPECT_TRUE(r.equilibrium.can_stand);
}

TEST(StandInput, OneBodySceneIsAnAssemblyOfOne) {
    const Assembly a = read_assembly_text(read_json_file(std::string(MOMENTLAB_EXAMPLES) + "/figure-3-block-along-wall.json"));
    ASSERT_EQ(a.bodies.size(), 1U);
    for (const AssemblyContact& c : a.contacts) {
        EXPECT_EQ(c.a, 1U);
        EXPECT_EQ(c.b, 0U);
    }
}

// The command: JSON fields, and one line with exit status 2 for bad input.
struct CommandRun {
    int status;
    std::string out, err;
};

CommandRun run(const std::string& args) {
    const std::string cmd = std::string(MOMENTLAB_BIN) + " " + args + " 2>/tmp/momentlab_stand_stderr";
    FILE* p = popen(cmd.c_str(), "r");
    std::string out;
    char buf[4096];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    const int status = pclose(p);
    std::ifstream in("/tmp/momentlab_stand_stderr");
    return {WEXITSTATUS(status), out, std::string(std::istreambuf_iterator<char>(in), {})};
}

TEST(StandCommand, JsonFieldsAndErrors) {
    CommandRun r = run("stand " + std::string(MOMENTLAB_EXAMPLES) + "/assembly-ladder.json --tilt --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["can_stand"], true);
    EXPECT_EQ(j["forces"].size(), 2U);
    EXPECT_EQ(j["outcome"], "stands");
    EXPECT_EQ(j["verdict"], "ambiguous");
    EXPECT_EQ(j["tilt"]["kind"], "wedge");
    EXPECT_EQ(j["tilt"]["directions"], nlohmann::json::parse(R"([[0, -1], [1, "-2/3"]])"));
    r = run("stand " + std::string(MOMENTLAB_EXAMPLES) + "/assembly-modern-robotics.json --json");
    ASSERT_EQ(r.status, 0);
    const nlohmann::json k = nlohmann::json::parse(r.out);
    EXPECT_EQ(k["can_stand"], false);
    EXPECT_EQ(k["mechanism"].size(), 2U);
    EXPECT_EQ(k["outcome"], "falls");
    std::ofstream("/tmp/momentlab_stand_bad.json") << R"({"bodies": [{"mass": 1, "com": [0, 1]}],
        "contacts": [{"bodies": [1, 1], "point": [0, 0], "normal": [0, 1]}]})";
    r = run("stand /tmp/momentlab_stand_bad.json");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("$.contacts[0].bodies"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace momentlab
