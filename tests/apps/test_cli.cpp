// The command-line tool as a user runs it: output of `label`, exit codes, one-line errors.
#include <gtest/gtest.h>

#include <array>
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

}  // namespace
