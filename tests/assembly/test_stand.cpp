// momentlab stand: the bundled examples against their hand derivations (docs/assemblies.md),
// exact transforms, bad input and the command (the agreement with the exact oracle and with one
// body's query: test_stand_agreement.cpp).
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
    // gamma* = k (5 mu - k) / (5 k - mu), k = (2 - mu) / (1 + 2 mu): 595/6416 for mu = 3/10, the
    // file's 0.3 as typed.
    const auto end_of = [](const Q& mu) {
        const Q k = (2 - mu) / (1 + 2 * mu);
        return Q(k * (5 * mu - k) / (5 * k - mu));
    };
    EXPECT_EQ(end_of(Q(3, 10)), Q(595, 6416));
    const Assembly a = example("assembly-arch.json");
    expect_wedge(tilt_cone(a), -Q(595, 6416), -1, Q(595, 6416), -1);
    // The same arch with the double 0.3, a little below 3/10: so is its end.
    Assembly b = a;
    for (AssemblyContact& c : b.contacts) c.contact = Contact::make(c.contact.point, c.contact.normal, 0.3);
    const Q binary = end_of(Q(0.3));
    EXPECT_LT(binary, Q(595, 6416));
    expect_wedge(tilt_cone(b), -binary, -1, binary, -1);
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
        const StandResult r = stand(a, {.gravity = rational(Vec2(0, -1))});
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
// Exact transforms: a quarter turn (gravity turned too), a dyadic translation, a mirror (r <-> l).

// The transforms are exact on the examples' points, normals and coms (doubles); their decimals
// (mu = 0.3, an inertia) are kept as read.
Assembly transformed(const Assembly& a, auto&& point, auto&& vector) {
    Assembly b = a;
    b.exact_polygons = nullptr;  // overlap on the doubles (the ladder's decimal corners touch nothing)
    for (AssemblyBody& body : b.bodies) {
        body.com = point(body.com);
        for (Vec2& v : body.polygon) v = point(v);
        if (const BodyValues* v = a.bodies[&body - b.bodies.data()].exact_values()) {
            BodyValues moved = *v;
            EXPECT_TRUE(is_double(moved.com));
            moved.com = rational(body.com);
            moved.com_double = body.com;
            body.exact = std::make_shared<const BodyValues>(std::move(moved));
        }
    }
    for (Polygon& o : b.obstacles) {
        for (Vec2& v : o) v = point(v);
    }
    for (AssemblyContact& c : b.contacts) {
        const ContactValues* v = c.contact.exact_values();
        EXPECT_TRUE(!v || (is_double(v->point) && is_double(v->normal)));
        const Rational mu = v ? v->mu : Rational(c.contact.mu), kinetic = v ? v->mu_kinetic : Rational(c.contact.mu_kinetic);
        c.contact = Contact::make(rational(point(c.contact.point)), rational(vector(c.contact.normal)), mu, kinetic, c.contact.name);
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
        const StandResult base = stand(a, {.gravity = rational(g), .tilt = true});
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
            const StandResult r = stand(c.assembly, {.gravity = rational(c.gravity), .tilt = true});
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

// Two blocks on a floor, written with decimals of 20 digits (their scaled integers pass 2^53:
// decided on the exact points): the upper block's bottom at y1 = 2.12345678901234567890, the
// lower's top there too, touching along the edge (two contacts, normal exactly (0, 1)) with a
// contact distance of 0; 1e-20 higher they do not touch, 1e-20 lower they overlap, refused
// naming the body.
TEST(StandInput, BodiesOfLongDecimalsTouchAndOverlapAsTyped) {
    const auto text = [](const std::string& upper_bottom) {
        return R"({"bodies": [{"mass": 1, "com": [0, 1], "polygon": [[-1, 0], [1, 0], [1, 2.12345678901234567890], [-1, 2.12345678901234567890]]},
                              {"mass": 1, "com": [0, 3], "polygon": [[-1, )" + upper_bottom + R"(], [1, )" + upper_bottom +
               R"(], [1, 4], [-1, 4]]}], "obstacles": [{"polygon": [[-5, -1], [5, -1], [5, 0], [-5, 0]]}], "contact_distance": 0})";
    };
    const Assembly a = read_assembly_text(text("2.12345678901234567890"));
    std::size_t between = 0;
    for (const AssemblyContact& c : a.contacts) {
        if (c.a != 2 || c.b != 1) continue;
        ++between;
        const ContactValues* v = c.contact.exact_values();
        ASSERT_NE(v, nullptr);
        EXPECT_EQ(v->normal[0], Rational());
        EXPECT_EQ(v->normal[1], *Rational::parse("1"));
        EXPECT_EQ(v->point[1], *Rational::parse("2.12345678901234567890"));
    }
    EXPECT_EQ(between, 2U);
    EXPECT_EQ(read_assembly_text(text("2.12345678901234567891")).contacts.size(), 2U);  // 1e-20 apart: the floor's only
    expect_error(text("2.12345678901234567889"), "$.bodies[1].polygon");
}

// Review-31: a block resting exactly on a ramp of slope 1/3 (its corner written with 36 digits,
// contact distance 0) touches it at both corners and stands with mu = 1/2 > 1/3, its centre of
// mass above the support (it was once found touching at no corner and "falls").
TEST(StandInput, BlockExactlyOnARampOfLongDecimalsStands) {
    const Assembly a = read_assembly_text(
        R"({"bodies": [{"mass": 1, "com": [1.5, 1.2], "inertia": 1, "polygon": [[0.9, 0.3],
              [2.100000000000000000000000000000000003, 0.700000000000000000000000000000000001],
              [2.100000000000000000000000000000000003, 2], [0.9, 2]]}],
            "obstacles": [{"polygon": [[-3, -1], [3, 1], [3, -3], [-3, -3]]}], "mu": 0.5, "contact_distance": 0})");
    EXPECT_EQ(a.contacts.size(), 2U);
    EXPECT_TRUE(stand(a).equilibrium.can_stand);
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
