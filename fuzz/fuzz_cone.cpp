// Fuzz target: cone construction from raw doubles (any bit pattern). Non-finite input must be
// rejected with std::invalid_argument; finite input must give a cone that contains every
// generator, whose dual's dual is itself, and whose half-space reading satisfies each normal.
// For up to six vectors an independent check: membership of the generators, their negations,
// sums and differences (as doubles) against a brute-force exact oracle
// (reference/cone_membership.hpp), for the cone and for the half-space reading.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "fuzz_check.hpp"
#include "cone_membership.hpp"
#include "momentlab/geometry/cone.hpp"

using namespace momentlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<Vec3> vectors;
    bool finite = true;
    for (std::size_t at = 0; at + 24 <= size && vectors.size() < 12; at += 24) {
        double x[3];
        std::memcpy(x, data + at, sizeof x);
        vectors.emplace_back(x[0], x[1], x[2]);
        finite = finite && vectors.back().allFinite();
    }
    if (!finite) {
        bool threw = false;
        try {
            (void)Cone::from_generators(vectors);
        } catch (const std::invalid_argument&) {
            threw = true;
        }
        FUZZ_REQUIRE(threw);
        return 0;
    }
    const Cone c = Cone::from_generators(vectors);
    for (const Vec3& g : vectors) FUZZ_REQUIRE(c.has(g));
    for (const ExactVector& r : c.rays()) FUZZ_REQUIRE(c.has(r));
    FUZZ_REQUIRE(c.dual().dual() == c);
    const Cone h = Cone::from_halfspaces(vectors);
    for (const ExactVector& r : h.rays()) {
        for (const Vec3& n : vectors) FUZZ_REQUIRE(r.dot_sign(n) != Sign::Negative);
    }
    for (const ExactVector& l : h.lineality()) {
        for (const Vec3& n : vectors) FUZZ_REQUIRE(l.dot_sign(n) == Sign::Zero);
    }
    FUZZ_REQUIRE(h == c.dual());
    if (vectors.size() > 6) return 0;
    std::vector<reference::QVec> exact;
    for (const Vec3& v : vectors) exact.push_back(reference::q(v));
    std::vector<Vec3> probes;
    for (std::size_t i = 0; i < vectors.size(); ++i) {
        probes.push_back(vectors[i]);
        probes.push_back(-vectors[i]);
        for (std::size_t j = i + 1; j < vectors.size(); ++j) {
            probes.push_back(vectors[i] + vectors[j]);
            probes.push_back(vectors[i] - vectors[j]);
        }
    }
    for (const Vec3& w : probes) {
        if (!w.allFinite()) continue;
        const reference::QVec qw = reference::q(w);
        FUZZ_REQUIRE(c.has(w) == reference::in_cone(exact, qw));
        bool in_h = true;
        for (const auto& n : exact) in_h = in_h && reference::sign(reference::dot(n, qw)) >= 0;
        FUZZ_REQUIRE(h.has(w) == in_h);
    }
    return 0;
}
