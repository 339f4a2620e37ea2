// momentlab stand against engines that share nothing with it: random assemblies, arches and
// walls against the exact oracle (assembly_oracle.hpp: cddlib on the raw numbers), and one
// body's modes against query.
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

// The exact direction (x, y) of a tilt end, from its text.
std::array<Q, 2> exact(const ExactDirection& d) { return {Q(d.exact[0]), Q(d.exact[1])}; }

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
        const Equilibrium e = equilibrium(g.assembly, rational(gravity));
        ASSERT_EQ(e.can_stand, assembly_oracle::can_stand(q, 0, -1)) << what;
        stand_count += e.can_stand;
        expect_same_tilt(q, tilt_cone(g.assembly), what);
        ++tilts;
        if (g.assembly.contacts.size() <= 6) {
            const AssemblyModes m = assembly_modes(g.assembly, rational(gravity));
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
        EXPECT_EQ(equilibrium(a, rational(g)).can_stand, expected) << what << ", gravity " << g.transpose();
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
        const AssemblyModes got = assembly_modes(assembly_of(s), rational(Vec2(0, -1)));
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

}  // namespace
}  // namespace momentlab
