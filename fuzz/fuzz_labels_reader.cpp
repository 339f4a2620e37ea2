// Fuzz target: the force-set reader and labels. Any text is rejected with an InputError or
// gives a cone whose labels can be built, printed and evaluated; every extreme ray must be in
// the cone, and the label of a point must match the definition evaluated on the rays.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"
#include "momentlab/geometry/labels.hpp"
#include "momentlab/io/force_set_json.hpp"
#include "momentlab/io/json_output.hpp"

using namespace momentlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    Cone cone;
    try {
        cone = read_force_set_text(text);
    } catch (const InputError&) {
        return 0;
    }
    for (const ExactVector& r : cone.rays()) FUZZ_REQUIRE(cone.has(r));
    const Labels labels(cone);
    (void)to_json(labels);
    for (const Vec2& p : {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(-1, -1), Vec2(0.5, 0.25)}) {
        const Label l = labels.at(p);
        // The definition (docs/design.md): + at p when every force of the cone has moment >= 0 about
        // p, (y, -x, 1) . w >= 0; - when every one has moment <= 0; both when all are zero.
        const Vec3 moment(p.y(), -p.x(), 1.0);
        bool plus = true, minus = true;
        for (const ExactVector& r : cone.rays()) {
            plus = plus && r.dot_sign(moment) != Sign::Negative;
            minus = minus && r.dot_sign(moment) != Sign::Positive;
        }
        for (const ExactVector& r : cone.lineality()) {
            const bool zero = r.dot_sign(moment) == Sign::Zero;
            plus = plus && zero;
            minus = minus && zero;
        }
        const Label expected = plus && minus ? Label::Both : plus ? Label::Plus : minus ? Label::Minus : Label::None;
        FUZZ_REQUIRE(l == expected);
    }
    return 0;
}
