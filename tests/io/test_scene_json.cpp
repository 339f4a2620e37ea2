// Writing a scene back: read_scene(to_json(scene)) is the same scene, number for number (the
// numbers compared are the file's own: 3, 4, 0.3, ...), with normals as written and the radius
// of gyration kept, so that the modes and the exact inertia do not change.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace momentlab
