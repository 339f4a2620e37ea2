// Writing a scene back: read_scene(to_json(scene)) is the same scene, number for number (the
// numbers compared are the file's own: 3, 4, 0.3, ...), with normals as written and the radius
// of gyration kept, so that the modes and the exact inertia do not change.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "momentlab/io/input_error.hpp"
#include "momentlab/core/rational.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/mechanics/modes.hpp"

namespace momentlab {
namespace {

TEST(SceneJson, WritesBackTheSceneAsGiven) {
    const std::string text = R"({"body": {"mass": 2, "com": [0.25, 0.5], "radius_of_gyration": 0.3,
                                          "polygon": [[-1, 0], [1, 0], [1, 1], [-1, 1]]},
                                 "contacts": [{"point": [-1, 0], "normal": [3, 4], "mu": 0.5, "mu_kinetic": 0.25, "name": "a"},
                                              {"point": [1, 0], "normal": [0, 1e-3], "mu": 0.1}],
                                 "obstacles": [{"polygon": [[-2, -1], [2, -1], [2, 0], [-2, 0]]}]})";
    const Scene scene = read_scene_text(text);
    const nlohmann::json written = to_json(scene);
    EXPECT_FALSE(written["body"].contains("inertia")) << written.dump();
    EXPECT_EQ(written["body"]["radius_of_gyration"].get<double>(), 0.3);
    EXPECT_EQ(written["contacts"][0]["normal"], nlohmann::json::array({3.0, 4.0}));
    EXPECT_EQ(written["contacts"][1]["normal"], nlohmann::json::array({0.0, 1e-3}));

    // Read back as a file is: its text (0.3 written as 0.3 is 3/10 again, not the double nearest).
    const Scene back = read_scene_text(written.dump());
    ASSERT_TRUE(back.body.has_value());
    EXPECT_EQ(back.body->mass, 2.0);
    EXPECT_EQ(back.body->com, Vec2(0.25, 0.5));
    EXPECT_EQ(back.body->radius_of_gyration, std::optional<double>(0.3));
    EXPECT_EQ(back.body->polygon.size(), 4U);
    ASSERT_EQ(back.contacts.size(), 2U);
    EXPECT_EQ(back.contacts[0].normal, Vec2(3, 4));
    EXPECT_EQ(back.contacts[0].mu, 0.5);
    EXPECT_EQ(back.contacts[0].mu_kinetic, 0.25);
    EXPECT_EQ(back.contacts[0].name, "a");
    EXPECT_EQ(back.contacts[1].normal, Vec2(0, 1e-3));
    EXPECT_EQ(back.contacts[1].mu_kinetic, 0.1);
    EXPECT_EQ(back.obstacles.size(), 1U);
    EXPECT_TRUE(inertia_at_origin(*back.body) == inertia_at_origin(*scene.body));

    std::vector<std::string> before, after;
    for (const Mode& m : enumerate_modes(scene.contacts).modes) before.push_back(m.letters);
    for (const Mode& m : enumerate_modes(back.contacts).modes) after.push_back(m.letters);
    EXPECT_EQ(before, after);
}

TEST(SceneJson, WritesTheInertiaWhenGivenOne) {
    const Scene scene = read_scene_text(R"({"body": {"mass": 1, "com": [0, 0], "inertia": 0.125},
                                            "contacts": [{"point": [0, 0], "normal": [0, 1]}]})");
    const nlohmann::json written = to_json(scene);
    EXPECT_EQ(written["body"]["inertia"].get<double>(), 0.125);
    EXPECT_FALSE(written["body"].contains("radius_of_gyration"));
}

// Contacts found from polygons at the edge of the contact distance (docs/reliability.md): a
// block's corner raised exactly the distance above the floor touches it, one unit in the last
// place higher does not; a corner below the floor by any amount, even 2^-60, is an overlap,
// refused with both polygons' paths. (Each corner written with all its digits: the text is read
// as the decimal it spells, and the distance is the double 1e-9.)
TEST(SceneJson, ContactsFromPolygonsAtTheToleranceEdge) {
    const auto scene = [](double corner_y, const std::string& distance) {
        char text[1200];
        std::snprintf(text, sizeof text,
                      R"({"body": {"mass": 1, "com": [0.5, 0.5], "inertia": 0.1, "polygon": [[0, 0], [1, %.800g], [1, 1], [0, 1]]},
                          "obstacles": [{"polygon": [[-1, -1], [2, -1], [2, 0], [-1, 0]]}]%s})",
                      corner_y, distance.c_str());
        return read_scene_text(text);
    };
    EXPECT_EQ(scene(1e-9, "").contacts.size(), 2u);
    EXPECT_EQ(scene(std::nextafter(1e-9, 1.0), "").contacts.size(), 1u);
    EXPECT_EQ(scene(0.25, R"(, "contact_distance": 0.25)").contacts.size(), 2u);
    EXPECT_EQ(scene(std::nextafter(0.25, 1.0), R"(, "contact_distance": 0.25)").contacts.size(), 1u);
    EXPECT_EQ(scene(0.0, "").contacts.size(), 2u);
    for (const double below : {-0x1p-60, -0.25}) {
        try {
            (void)scene(below, R"(, "contact_distance": 0.25)");
            ADD_FAILURE() << "a corner " << below << " into the floor was accepted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("$.obstacles[0].polygon: overlaps the body polygon ($.body.polygon)"), std::string::npos)
                << e.what();
        }
    }
}

// The same decided on decimals of 20 digits, which scaled to integers pass 2^53 (the polygons'
// exact points, not their doubles): the floor's top at y0 = 0.12345678901234567890, a block
// with contact_distance 0.25. Expected values come from the decimals as written: the corner
// exactly 0.25 above y0 touches, 1e-20 higher does not; 1e-20 below the floor is an overlap;
// on a floor of slope 1/10 written with 20 digits the normal is exactly (-1/10, 1) and the point
// the vertex as typed.
TEST(SceneJson, ContactsFromPolygonsOfLongDecimalsAreDecidedExactly) {
    const auto scene = [](const std::string& corner_y, const std::string& floor_right_y = "0.12345678901234567890") {
        const std::string text =
            R"({"body": {"mass": 1, "com": [0.5, 0.9], "inertia": 0.1, "polygon": [[0, 0.12345678901234567890], [1, )" + corner_y +
            R"(], [1, 2], [0, 2]]}, "obstacles": [{"polygon": [[-1, -1], [2, -1], [2, )" + floor_right_y +
            R"(], [-1, 0.12345678901234567890]]}], "contact_distance": 0.25})";
        return read_scene_text(text);
    };
    EXPECT_EQ(scene("0.37345678901234567890").contacts.size(), 2u);  // y0 + 0.25: on the edge
    EXPECT_EQ(scene("0.37345678901234567891").contacts.size(), 1u);  // 1e-20 beyond
    EXPECT_EQ(scene("0.12345678901234567891").contacts.size(), 2u);
    for (const std::string below : {"0.12345678901234567889", "0.1234567890123456788999"}) {
        try {
            (void)scene(below);
            ADD_FAILURE() << "a corner 1e-20 into the floor was accepted: " << below;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("$.obstacles[0].polygon: overlaps the body polygon ($.body.polygon)"), std::string::npos)
                << e.what();
        }
    }
    // A floor of slope 1/10 (from (-1, y0 - 0.1) to (2, y0 + 0.2)), the block's bottom corners on it.
    const Scene slanted = read_scene_text(
        R"({"body": {"mass": 1, "com": [0.5, 0.9], "inertia": 0.1,
                     "polygon": [[0, 0.12345678901234567890], [1, 0.22345678901234567890], [1, 2], [0, 2]]},
            "obstacles": [{"polygon": [[-1, 0.02345678901234567890], [2, 0.32345678901234567890], [2, -1], [-1, -1]]}]})");
    ASSERT_EQ(slanted.contacts.size(), 2u);
    for (const Contact& c : slanted.contacts) {
        const ContactValues* v = c.exact_values();
        ASSERT_NE(v, nullptr);
        EXPECT_EQ(v->normal[0], *Rational::parse("-0.1"));
        EXPECT_EQ(v->normal[1], *Rational::parse("1"));
        const bool left = v->point[0] == Rational();
        EXPECT_EQ(v->point[1], *Rational::parse(left ? "0.12345678901234567890" : "0.22345678901234567890"));
    }
}

// A polygon simple in doubles but not in the decimals typed: its vertex (1, y) with y =
// 0.10000000000000000001 lies exactly on its edge from (0, 0) to (3, 3y) (the doubles put it
// 9e-18 above that edge's double line). Refused when contacts are found from the polygons.
TEST(SceneJson, PolygonsOfLongDecimalsAreSimpleAsTyped) {
    const std::string text = R"({"body": {"mass": 1, "com": [1.5, 1.5], "inertia": 0.1,
        "polygon": [[0, 0], [3, 0.30000000000000000003], [3, 2], [2, 2], [1, 0.10000000000000000001], [0, 2]]},
        "obstacles": [{"polygon": [[-1, -1], [4, -1], [4, 0], [-1, 0]]}]})";
    try {
        (void)read_scene_text(text);
        ADD_FAILURE() << "a polygon whose vertex lies on its own edge was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("$.body.polygon: edges"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("cross or touch"), std::string::npos) << e.what();
    }
}

// Review-31's cases, the expectations from the decimals as written: a block resting exactly on a
// ramp of slope 1/3 whose corner has 36 digits, with a contact distance of 0 (both corners touch,
// normals exactly (-1/3, 1)); an obstacle's apex 1e-20 beside the block's corner on its bottom
// edge, distance 0 (one contact there, normal (0, 1)); a floor at 0.111...1 of 300 and 415
// digits (two contacts, exactly there: the exact points' doubles stay finite).
TEST(SceneJson, ExactTouchesOfLongDecimalsAreFound) {
    const Scene ramp = read_scene_text(
        R"({"body": {"mass": 1, "com": [1, 1], "inertia": 0.1, "polygon": [[0.9, 0.3],
              [2.100000000000000000000000000000000003, 0.700000000000000000000000000000000001],
              [2.100000000000000000000000000000000003, 2], [0.9, 2]]},
            "obstacles": [{"polygon": [[-3, -1], [3, 1], [3, -3], [-3, -3]]}], "contact_distance": 0})");
    ASSERT_EQ(ramp.contacts.size(), 2u);
    for (const Contact& c : ramp.contacts) {
        const ContactValues* v = c.exact_values();
        ASSERT_NE(v, nullptr);
        EXPECT_EQ(v->normal[0], *Rational::parse("-1") * Rational::quotient(Dyadic(1.0), Dyadic(3.0)));
        EXPECT_EQ(v->normal[1], Rational(1.0));
    }
    const Scene apex = read_scene_text(
        R"({"body": {"mass": 1, "com": [1.5, 0.5], "inertia": 0.1, "polygon": [[1, 0], [2, 0], [2, 1], [1, 1]]},
            "obstacles": [{"polygon": [[1.00000000000000000001, 0], [0, -1], [3, -1]]}], "contact_distance": 0})");
    ASSERT_EQ(apex.contacts.size(), 1u);
    ASSERT_NE(apex.contacts[0].exact_values(), nullptr);
    EXPECT_EQ(apex.contacts[0].exact_values()->point[0], *Rational::parse("1.00000000000000000001"));
    EXPECT_EQ(apex.contacts[0].exact_values()->normal[1], Rational(1.0));
    for (const std::size_t digits : {300u, 415u}) {
        const std::string y = "0." + std::string(digits, '1'), top = "1." + std::string(digits, '1');
        const Scene floor = read_scene_text(R"({"body": {"mass": 1, "com": [0.5, 1], "inertia": 0.1, "polygon": [[0, )" + y +
                                            "], [1, " + y + "], [1, " + top + "], [0, " + top +
                                            R"(]]}, "obstacles": [{"polygon": [[-1, -1], [2, -1], [2, )" + y + "], [-1, " + y + "]]}]}");
        ASSERT_EQ(floor.contacts.size(), 2u) << digits;
        for (const Contact& c : floor.contacts) EXPECT_EQ(c.exact_values()->point[1], *Rational::parse(y)) << digits;
    }
}

// Review-32: a block's corner on an obstacle's corner gets a contact for each obstacle edge ending
// there (docs/formats.md) when written with 14-digit decimals as with doubles: on the scaled
// polygons the unit normals are compared with the distance as given, not scaled with the points.
TEST(SceneJson, CornerContactsOfDecimalsAreKeptApart) {
    const auto count = [](const std::string& x0, const std::string& x1, const std::string& x2) {
        return read_scene_text(R"({"body": {"mass": 1, "com": [0.6, 0.7], "inertia": 0.1, "polygon": [[)" + x0 + ", 0.2], [" + x1 +
                               ", 0.2], [" + x1 + ", 1.2], [" + x0 + R"(, 1.2]]}, "obstacles": [{"polygon": [[)" + x2 + ", -0.8], [" +
                               x0 + ", -0.8], [" + x0 + ", 0.2], [" + x2 + ", 0.2]]}]}")
            .contacts.size();
    };
    EXPECT_EQ(count("0.5", "1.5", "-0.5"), 2u);
    EXPECT_EQ(count("0.12345678912341", "1.12345678912341", "-0.87654321087659"), 2u);
}

// Review-32: at contact distance 0, the body's corner on the floor and the floor's corner 1e-30
// beyond it on the body's bottom edge are two contacts (their points differ), although their
// doubles are equal: the merge compares the points themselves.
TEST(SceneJson, ContactsOfDistinctExactPointsAreNotMerged) {
    const Scene s = read_scene_text(R"({"body": {"mass": 1, "com": [1.2777777777777777777777777, 0.8333333333333333333333333],
        "inertia": 0.1, "polygon": [[0.7777777777777777777777777, 0.3333333333333333333333333],
        [1.7777777777777777777777777, 0.3333333333333333333333333], [1.7777777777777777777777777, 1.3333333333333333333333333],
        [0.7777777777777777777777777, 1.3333333333333333333333333]]}, "obstacles": [{"polygon": [
        [-0.2222222222222222222222223, -0.6666666666666666666666667], [0.777777777777777777777777700001, -0.6666666666666666666666667],
        [0.777777777777777777777777700001, 0.3333333333333333333333333], [-0.2222222222222222222222223, 0.3333333333333333333333333]]}],
        "contact_distance": 0})");
    ASSERT_EQ(s.contacts.size(), 2u);
    EXPECT_NE(s.contacts[0].exact_values()->point[0], s.contacts[1].exact_values()->point[0]);
}

// A corner exactly on an obstacle's corner whose two edges differ in slope by 1e-20 (-1 and
// -(1 + 1e-20)): at contact distance 0 two contacts, as their normals differ (the edges are not
// parallel: the cross product of their directions (1, -1) and (1, -1 - 1e-20) is -1e-20 != 0),
// although their doubles are equal; within 1e-10 one. The merge compares the exact unit normals.
TEST(SceneJson, ContactsOfDistinctExactNormalsAreNotMerged) {
    const auto contacts = [](const std::string& distance) {
        return read_scene_text(R"({"body": {"mass": 1, "com": [0.3, 0.3], "inertia": 0.1, "polygon": [[0, 0], [1, 0], [0, 1]]},
            "obstacles": [{"polygon": [[-1, 1], [0, 0], [1, -1.00000000000000000001], [-2, -2]]}], "contact_distance": )" +
                               distance + "}")
            .contacts;
    };
    const std::vector<Contact> apart = contacts("0");
    ASSERT_EQ(apart.size(), 2u);
    EXPECT_EQ(apart[0].normal, apart[1].normal);  // (as doubles)
    const auto exact_normal = [](const Contact& c) {  // (no exact values: the doubles are exact)
        return c.exact_values() != nullptr ? c.exact_values()->normal : Rational2{Rational(c.normal.x()), Rational(c.normal.y())};
    };
    for (const Contact& c : apart) EXPECT_EQ(c.point, Vec2(0, 0));
    const Rational2 n0 = exact_normal(apart[0]), n1 = exact_normal(apart[1]);
    EXPECT_NE(n0[0] * n1[1] - n0[1] * n1[0], Rational(0.0));
    EXPECT_EQ(contacts("1e-10").size(), 1u);
}

}  // namespace
}  // namespace momentlab
