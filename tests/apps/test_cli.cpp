// The command-line tool as a user runs it: output of `label`, exit codes, one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <sstream>
#include <vector>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace {

struct Result {
    int status;
    std::string out;
};

Result run(const std::string& args) {
    const std::string cmd = std::string(MOMENTLAB_BIN) + " " + args + " 2>/tmp/momentlab_test_stderr";
    FILE* p = popen(cmd.c_str(), "r");
    std::string out;
    std::array<char, 4096> buf{};
    while (std::fgets(buf.data(), buf.size(), p)) out += buf.data();
    const int status = pclose(p);
    return {WEXITSTATUS(status), out};
}

std::string stderr_text() {
    std::ifstream in("/tmp/momentlab_test_stderr");
    return std::string(std::istreambuf_iterator<char>(in), {});
}

const std::string kExamples = MOMENTLAB_EXAMPLES;

TEST(Cli, LabelJsonForFigure1a) {
    const Result r = run("label " + kExamples + "/figure-1a-force.json --json --at 0 1 --at 0 -1 --at 2 0");
    ASSERT_EQ(r.status, 0);
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["cone"]["kind"], "ray");
    EXPECT_EQ(j["labels"]["plus"]["kind"], "half-plane");
    EXPECT_EQ(j["at"][0]["label"], "+");
    EXPECT_EQ(j["at"][1]["label"], "-");
    EXPECT_EQ(j["at"][2]["label"], "+-");
}

TEST(Cli, LabelPlainForFigure2) {
    const Result r = run("label " + kExamples + "/figure-2-two-friction-cones.json");
    ASSERT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("force set: pointed cone"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("+ region: unbounded"), std::string::npos) << r.out;
}

TEST(Cli, BadInputExitsTwoWithOneLineNamingTheField) {
    std::ofstream("/tmp/momentlab_bad.json") << R"([{"type": "friction_cone", "point": [0, 0], "normal": [0, 1], "mu": -0.5}])";
    const Result r = run("label /tmp/momentlab_bad.json");
    EXPECT_EQ(r.status, 2);
    const std::string err = stderr_text();
    EXPECT_NE(err.find("$[0].mu"), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_EQ(run("label /nonexistent.json").status, 2);
    EXPECT_EQ(run("label").status, 2);
}

TEST(Cli, ModesJsonForThreeFloorContacts) {
    std::ofstream("/tmp/momentlab_floor.json") << R"({"contacts": [{"point": [0, 0], "normal": [0, 1]},
        {"point": [1, 0], "normal": [0, 1]}, {"point": [2, 0], "normal": [0, 1]}]})";
    const Result r = run("modes /tmp/momentlab_floor.json --json");
    ASSERT_EQ(r.status, 0);
    auto modes = nlohmann::json::parse(r.out)["modes"].get<std::vector<std::string>>();
    std::vector<std::string> expected = {"fff", "sss", "fss", "ssf", "rss", "lss", "ssr", "ssl", "rrr", "lll"};
    std::sort(modes.begin(), modes.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(modes, expected);
}

TEST(Cli, QueryJsonAndJsonLines) {
    const std::string scene = kExamples + "/block-on-table.json";
    Result r = run("query " + scene + " --wrench 0 -9.81 -4.905 --json");
    ASSERT_EQ(r.status, 0);
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["verdict"], "unique");
    EXPECT_EQ(j["modes"], nlohmann::json::array({"ff"}));
    std::ofstream("/tmp/momentlab_wrenches.txt") << "[0, -9.81, -4.905]\n[20, -9.81, -5.105]\n\n[0, 9.81, 4.905]\n";
    r = run("query " + scene + " --wrenches /tmp/momentlab_wrenches.txt");
    ASSERT_EQ(r.status, 0);
    std::istringstream lines(r.out);
    std::vector<nlohmann::json> answers;
    for (std::string line; std::getline(lines, line);) answers.push_back(nlohmann::json::parse(line));
    ASSERT_EQ(answers.size(), 3u);
    EXPECT_EQ(answers[0]["modes"], nlohmann::json::array({"ff"}));
    EXPECT_EQ(answers[1]["modes"], nlohmann::json::array({"rr"}));  // 20 N along the base
    EXPECT_EQ(answers[2]["modes"], nlohmann::json::array({"ss"}));  // net force up through the centre
    std::ofstream("/tmp/momentlab_bad_wrenches.txt") << "[1, 2]\n";
    EXPECT_EQ(run("query " + scene + " --wrenches /tmp/momentlab_bad_wrenches.txt").status, 2);
    EXPECT_NE(stderr_text().find("momentlab_bad_wrenches.txt:1"), std::string::npos) << stderr_text();
}

TEST(Cli, AnalyzeJsonHasEveryModeWithItsCones) {
    const Result r = run("analyze " + kExamples + "/figure-3-block-along-wall.json --json");
    ASSERT_EQ(r.status, 0);
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["modes"].size(), 10u);
    for (const auto& m : j["modes"]) {
        for (const char* set : {"F", "T", "E"}) {
            EXPECT_TRUE(m[set].contains("cone") && m[set].contains("labels")) << m["mode"];
        }
        EXPECT_TRUE(m["A"].contains("rays"));
    }
}

TEST(Cli, SceneErrorsNameTheField) {
    std::ofstream("/tmp/momentlab_bad_scene.json") << R"({"body": {"mass": -1, "com": [0, 0], "inertia": 1},
        "contacts": [{"point": [0, 0], "normal": [0, 1]}]})";
    EXPECT_EQ(run("modes /tmp/momentlab_bad_scene.json").status, 2);
    EXPECT_NE(stderr_text().find("$.body.mass"), std::string::npos) << stderr_text();
    std::ofstream("/tmp/momentlab_bad_scene.json") << R"({"contacts": [{"point": [0, 0], "normal": [0, 0]}]})";
    EXPECT_EQ(run("modes /tmp/momentlab_bad_scene.json").status, 2);
    EXPECT_NE(stderr_text().find("$.contacts[0].normal"), std::string::npos) << stderr_text();
}

}  // namespace
