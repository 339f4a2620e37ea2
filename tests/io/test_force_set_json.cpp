// Reading force sets: the builders by name, combinations, and errors that name the field.
#include <gtest/gtest.h>

#include "momentlab/geometry/force_sets.hpp"
#include "momentlab/io/force_set_json.hpp"

namespace momentlab {
namespace {

std::string error_path(const std::string& text) {
    try {
        (void)read_force_set_text(text);
    } catch (const InputError& e) {
        return e.path();
    }
    return "(no error)";
}

TEST(ForceSetJson, ReadsEachType) {
    EXPECT_TRUE(read_force_set_text(R"([{"type": "force", "point": [0, 1], "direction": [1, 0]}])") ==
                force_ray(Vec2(0, 1), Vec2(1, 0)));
    EXPECT_TRUE(read_force_set_text(R"([{"type": "point", "point": [2, 3]}])") ==
                forces_through_point(Vec2(2, 3)));
    EXPECT_TRUE(read_force_set_text(R"([{"type": "friction_cone", "point": [0, 0], "normal": [0, 2], "mu": 0.5}])") ==
                friction_cone(Vec2(0, 0), Vec2(0, 1), 0.5));
    EXPECT_EQ(read_force_set_text(R"([{"type": "moment", "sign": 0}])").kind(), "line");
    EXPECT_EQ(read_force_set_text(R"([{"type": "halfspaces", "normals": [[0, 0, 1]]}])").kind(), "half-space");
    const std::string two = R"({"combine": "intersection", "sets": [
        {"type": "force", "point": [0, 0], "direction": [1, 0]},
        {"type": "force", "point": [0, 1], "direction": [1, 0]}]})";
    EXPECT_EQ(read_force_set_text(two).kind(), "{0}");
}

TEST(ForceSetJson, ErrorsNameTheField) {
    EXPECT_EQ(error_path("[{"), "$");
    EXPECT_EQ(error_path("42"), "$");
    EXPECT_EQ(error_path(R"([{"point": [0, 0]}])"), "$[0]");
    EXPECT_EQ(error_path(R"([{"type": "friction_cone", "point": [0, 0], "normal": [0, 1], "mu": -1}])"), "$[0].mu");
    EXPECT_EQ(error_path(R"([{"type": "force", "point": [0, "a"], "direction": [1, 0]}])"), "$[0].point[1]");
    EXPECT_EQ(error_path(R"([{"type": "force", "point": [0, 0], "direction": [0, 0]}])"), "$[0].direction");
    EXPECT_EQ(error_path(R"({"combine": "union", "sets": []})"), "$.combine");
    EXPECT_EQ(error_path(R"([{"type": "spring"}])"), "$[0].type");
    EXPECT_EQ(error_path(R"([{"type": "wrenches", "generators": [[1, 2]]}])"), "$[0].generators[0]");
}

// Nesting by sum/intersection is read recursively: deep nesting must be an error, not a
// stack overflow (100,000 levels crashed before the limit).
TEST(ForceSetJson, DeepNestingIsAnErrorNotACrash) {
    auto nested = [](int levels) {
        std::string s;
        for (int i = 0; i < levels; ++i) s += R"({"type": "sum", "sets": [)";
        s += R"({"type": "point", "point": [1, 2]})";
        for (int i = 0; i < levels; ++i) s += "]}";
        return "[" + s + "]";
    };
    EXPECT_EQ(read_force_set_text(nested(64)).kind(), "plane");  // forces through (1, 2)
    try {
        (void)read_force_set_text(nested(100000));
        ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("sets nested more than 64 deep"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace momentlab
