// The streaming writer writes what nlohmann::json's dump(2) writes for the same document: the
// oracle is nlohmann's own serializer, given the documents of json_output.hpp (to_json).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "momentlab/io/json_output.hpp"
#include "momentlab/io/json_writer.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/mechanics/analysis.hpp"

namespace momentlab {
namespace {

template <class T>
std::string written(const T& x, int indent = 0) {
    std::ostringstream out;
    {
        JsonWriter w(out, indent);
        write_json(w, x);
    }
    return out.str();
}

TEST(JsonWriter, ScalarsContainersAndEscapesAsDump) {
    std::ostringstream out;
    {
        JsonWriter w(out);
        w.begin_object();
        w.key("a\"b\\c\n\t\x01\x1f");
        w.begin_array();
        w.value(1.0);
        w.value(-0.0);
        w.value(0.1);
        w.value(1e300);
        w.value(-2.5e-300);
        w.value(123456789.0);
        w.value(std::numeric_limits<double>::denorm_min());
        w.value(-7);
        w.value(true);
        w.value(false);
        w.value("x\r\b\fy");
        w.begin_array();
        w.end_array();
        w.begin_object();
        w.end_object();
        w.begin_array();
        w.begin_object();
        w.key("k");
        w.value(Vec2(0.5, -3.0));
        w.end_object();
        w.end_array();
        w.end_array();
        w.key("b");
        w.value(Vec3(1.0 / 3.0, 2e-17, 4.0));
        w.end_object();
    }
    const nlohmann::json doc = {
        {"a\"b\\c\n\t\x01\x1f",
         {1.0, 0.0, 0.1, 1e300, -2.5e-300, 123456789.0, std::numeric_limits<double>::denorm_min(), -7, true, false,
          "x\r\b\fy", nlohmann::json::array(), nlohmann::json::object(),
          nlohmann::json::array({{{"k", {0.5, -3.0}}}})}},
        {"b", {1.0 / 3.0, 2e-17, 4.0}}};
    EXPECT_EQ(out.str(), doc.dump(2));
}

TEST(JsonWriter, NonFiniteValuesAreRefusedNotWritten) {
    std::ostringstream out;
    JsonWriter w(out);
    w.begin_array();
    EXPECT_THROW(w.value(std::numeric_limits<double>::infinity()), UnrepresentableError);
    EXPECT_THROW(w.value(std::nan("")), UnrepresentableError);
}

TEST(JsonWriter, WritesNothingWhenAnExceptionLeavesIt) {
    std::ostringstream out;
    try {
        JsonWriter w(out);
        w.begin_array();
        w.value(1.0);
        w.value(std::numeric_limits<double>::infinity());
    } catch (const UnrepresentableError&) {
    }
    EXPECT_EQ(out.str(), "");
}

TEST(JsonWriter, MisuseIsALogicError) {
    std::ostringstream out;
    JsonWriter w(out);
    EXPECT_THROW(w.end_object(), std::logic_error);
    EXPECT_THROW(w.key("k"), std::logic_error);
    w.begin_object();
    EXPECT_THROW(w.value(1.0), std::logic_error);  // no key
    EXPECT_THROW(w.end_array(), std::logic_error);
    w.key("k");
    EXPECT_THROW(w.key("again"), std::logic_error);
    EXPECT_THROW(w.end_object(), std::logic_error);  // the key's value is missing
    w.begin_array();
    EXPECT_THROW(w.key("in an array"), std::logic_error);
    w.end_array();
    w.end_object();
    EXPECT_THROW(w.value(2.0), std::logic_error);  // a second top-level value
    w.flush();
    EXPECT_EQ(out.str(), "{\n  \"k\": []\n}");
}

TEST(JsonWriter, IndentedValueContinuesTheDocumentAroundIt) {
    const std::vector<Vec3> g = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    const Cone c = Cone::from_generators(g);
    std::string expected = to_json(c).dump(2);
    for (std::size_t at = expected.find('\n'); at != std::string::npos; at = expected.find('\n', at + 1)) {
        expected.insert(at + 1, "    ");
    }
    EXPECT_EQ(written(c, 4), expected);
}

// Every kind of cone: random generators in few and many directions, with repeated, opposite and
// coplanar ones, and every mode's sets of the bundled scenes.
TEST(JsonWriter, ConesAndLabelsAsToJson) {
    std::mt19937_64 rng(16);
    std::uniform_int_distribution<int> coordinate(-3, 3);
    std::uniform_int_distribution<int> count(0, 9);
    int checked = 0;
    for (int trial = 0; trial < 400; ++trial) {
        std::vector<Vec3> g;
        const int n = count(rng);
        const bool planar = trial % 3 == 0;
        for (int i = 0; i < n; ++i) {
            g.emplace_back(coordinate(rng) * 0.5, coordinate(rng) / 3.0, planar ? 0.0 : coordinate(rng) * 1e-3);
        }
        const Cone c = trial % 2 ? Cone::from_generators(g) : Cone::from_halfspaces(g);
        ASSERT_EQ(written(c), to_json(c).dump(2)) << trial;
        const Labels l(c);
        ASSERT_EQ(written(l), to_json(l).dump(2)) << trial;
        ++checked;
    }
    for (const auto& entry : std::filesystem::directory_iterator(MOMENTLAB_EXAMPLES)) {
        if (entry.path().extension() != ".json") continue;
        std::ifstream in(entry.path());
        const nlohmann::json doc = nlohmann::json::parse(in, nullptr, false);
        if (doc.is_discarded() || !doc.is_object() || !doc.contains("contacts") || doc.contains("bodies")) continue;  // assemblies: stand
        for (const ModeForces& m : analyze(read_scene(doc))) {
            for (const Cone* c : {&m.mode.twists, &m.total, &m.contact, &m.applied}) {
                ASSERT_EQ(written(*c), to_json(*c).dump(2)) << entry.path() << " " << m.mode.letters;
                ASSERT_EQ(written(Labels(*c)), to_json(Labels(*c)).dump(2)) << entry.path() << " " << m.mode.letters;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 500);
}

}  // namespace
}  // namespace momentlab
