// The instruction counts of docs/benchmarks.md ("Nearly degenerate scenes"): a scene's
// SceneQuestions set-up, then six wrenches asked one by one (one walk each), the first alone and
// the other five in one batch, or all six in one batch. Run under valgrind's callgrind, whose
// counts this machine's noise does not move (`make instructions` runs it on the cradle and the
// tangent of 10^4 contacts); alone it prints the wall time of each part. With `doubles`, the
// file's numbers are taken as the doubles nearest them once read (the scene of before decimals
// were read as typed), so that the same scenes are counted both ways. It also prints how many
// signs of exact vectors the certified approximations decided and how many needed Dyadic
// arithmetic (exact_stats, core/exact.hpp).
// Usage: bench_instructions SCENE.json one|split|all [doubles]
#include <chrono>
#include <cstdio>
#include <cstring>
#include <span>
#include <vector>

#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/momentlab.hpp"

int main(int argc, char** argv) {
    using namespace momentlab;
    using Clock = std::chrono::steady_clock;
    const bool doubles = argc == 4 && std::strcmp(argv[3], "doubles") == 0;
    if ((argc != 3 && !doubles) ||
        (std::strcmp(argv[2], "one") != 0 && std::strcmp(argv[2], "split") != 0 && std::strcmp(argv[2], "all") != 0)) {
        std::fprintf(stderr, "usage: %s SCENE.json one|split|all [doubles]\n", argv[0]);
        return 2;
    }
    // With `doubles`, the same reading and then the exact values dropped: the doubles nearest the
    // file's numbers are the scene (what the query path did before decimals were read as typed).
    Scene scene = read_scene_text(read_json_file(argv[1]));
    if (doubles) {
        for (Contact& c : scene.contacts) c.exact = nullptr;
        if (scene.body) scene.body->exact = nullptr;
    }
    // The six wrenches of tools/degenerate_table.sh (six_wrenches.jsonl).
    const std::vector<Vec3> wrenches = {{0.1, 1, 0.2}, {0.5, 2, 0.1}, {1, 1, 0.5}, {0.2, -1, 0.3}, {2, 0.5, -0.4}, {0, 0, 1}};
    exact_stats() = {};
    const auto t0 = Clock::now();
    SceneQuestions questions(scene, AnalysisOptions{});
    const auto t1 = Clock::now();
    std::size_t modes = 0;
    const std::span<const Vec3> all(wrenches);
    if (std::strcmp(argv[2], "one") == 0) {
        for (const Vec3& w : wrenches) modes += questions.answer(w).modes.size();
    } else if (std::strcmp(argv[2], "split") == 0) {
        modes += questions.answer(wrenches[0]).modes.size();
        for (const SceneAnswer& a : questions.answer(all.subspan(1))) modes += a.modes.size();
    } else {
        for (const SceneAnswer& a : questions.answer(all)) modes += a.modes.size();
    }
    const auto t2 = Clock::now();
    const ExactStats signs = exact_stats();
    std::printf("%zu contacts, %s: set-up %.3f s, answers %.3f s, %zu modes in the six answers; signs: %ld filtered, %ld exact\n",
                scene.contacts.size(), argv[2], std::chrono::duration<double>(t1 - t0).count(),
                std::chrono::duration<double>(t2 - t1).count(), modes, signs.filtered, signs.exact);
    return 0;
}
