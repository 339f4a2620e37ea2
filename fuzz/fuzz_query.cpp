// Fuzz target: query. A small scene (1-4 contacts on a grid of eighths, so degenerate
// configurations are common) and wrenches from raw doubles; the compiled QueryIndex must give
// exactly the modes of the per-mode exact test, for every finite wrench and its scalings
// (which cross the range of the index's float filter), and reject non-finite wrenches. The
// first finite wrench is also checked independently: mode by mode against the exact LP oracle
// (reference/mode_oracle.hpp), which reads the scene's raw numbers. query(scene, e) must give the
// same modes for every wrench and scaling, whether its certified doubles decide or not.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "fuzz_check.hpp"
#include "mode_oracle.hpp"
#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/mechanics/query_index.hpp"

using namespace momentlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 4) return 0;
    std::size_t at = 0;
    auto byte = [&]() -> int { return at < size ? data[at++] : 0; };
    auto small = [&]() { return static_cast<double>(static_cast<std::int8_t>(byte())) / 8.0; };
    Scene scene;
    scene.body = Body{1.0 + byte() % 4, Vec2(small(), small()), 0.125 * (1 + byte() % 8), {}};
    const int n = 1 + byte() % 4;
    for (int j = 0; j < n; ++j) {
        const Vec2 p(small(), small());
        Vec2 normal(small(), small());
        if (normal.x() == 0.0 && normal.y() == 0.0) normal = Vec2(0, 1);
        const double mu = 0.25 * (byte() % 9);
        scene.contacts.push_back(Contact::make(p, normal, mu, byte() % 2 ? mu : 0.125 * (byte() % 9)));
    }
    const auto analysis = analyze(scene);
    const QueryIndex index(analysis);
    std::vector<std::size_t> modes;
    bool checked = false;
    for (int count = 0; at + 24 <= size && count < 16; at += 24, ++count) {
        double x[3];
        std::memcpy(x, data + at, sizeof x);
        const Vec3 e(x[0], x[1], x[2]);
        if (!e.allFinite()) {
            bool threw = false;
            try {
                (void)index.query(e, modes);
            } catch (const std::invalid_argument&) {
                threw = true;
            }
            FUZZ_REQUIRE(threw);
            continue;
        }
        if (!checked && e.cwiseAbs().maxCoeff() < 1e100 && e.cwiseAbs().maxCoeff() > 1e-100) {
            checked = true;
            const QueryResult r = query(analysis, e);
            std::size_t k = 0;
            for (std::size_t i = 0; i < analysis.size(); ++i) {
                const bool in = k < r.modes.size() && r.modes[k] == i;
                k += in;
                FUZZ_REQUIRE(in == testing::exact_lp_applied_in_mode(scene, analysis[i].mode.letters, e));
            }
        }
        for (double k : {1.0, 0x1p-64, 0x1p64, 0x1p-700, 0x1p700}) {
            const Vec3 w = e * k;
            if (!w.allFinite()) continue;
            const Verdict v = index.query(w, modes);
            const QueryResult expected = query(analysis, w);
            FUZZ_REQUIRE(modes == expected.modes);
            FUZZ_REQUIRE(v == expected.verdict);
            // query(scene, e) (certified doubles, or the exact path): the same modes, sorted.
            std::vector<std::string> letters;
            for (std::size_t i : expected.modes) letters.push_back(analysis[i].mode.letters);
            std::sort(letters.begin(), letters.end());
            const QueryAnswer once = query(scene, w);
            FUZZ_REQUIRE(once.letters == letters);
            FUZZ_REQUIRE(once.verdict == expected.verdict);
        }
    }
    return 0;
}
