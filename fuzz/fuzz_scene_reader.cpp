// Fuzz target: the scene reader. The plain JSON reader either declines a text or reads the
// document the JSON library's SAX parser reads from it (node for node: numbers' bits and the
// exact values of their texts), or raises the library's error, and the scene read from the text
// is the one read from the library's document (or the same error). Any text is either rejected
// with an InputError or accepted; an accepted scene (of at most 6 contacts, to keep runs
// short) must go through mode enumeration, analysis and queries without any exception, and
// survive a JSON round trip.
// Scenes of up to three contacts are checked independently: their modes against the
// brute-force exact LP oracle (reference/mode_oracle.hpp) on the raw numbers.
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>

#include "../tests/io/json_documents.hpp"
#include "fuzz_check.hpp"
#include "io/json_read.hpp"
#include "mode_oracle.hpp"
#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/mechanics/query_index.hpp"

using namespace momentlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::string library;
    try {
        library = testing::describe(json_read::read_by_library(text, json_read::kEverything));
    } catch (const InputError& e) {
        library = e.what();
    }
    try {
        if (const std::optional<json_read::Document> plain = json_read::read_plain(text, json_read::kEverything)) {
            FUZZ_REQUIRE(testing::describe(*plain) == library);
        }
    } catch (const InputError& e) {  // a repeated key or an underflow: the library's error too
        FUZZ_REQUIRE(e.what() == library);
    }
    Scene scene;
    InputWarnings warnings;
    std::string error;
    try {
        scene = read_scene_text(text, &warnings);
    } catch (const InputError& e) {
        error = e.what();
    }
    // The scene reader on the library's document of the text.
    {
        Scene slow;
        InputWarnings slow_warnings;
        std::string slow_error;
        try {
            slow = json_read::scene_of(json_read::read_by_library(text, json_read::scene_schema()), &slow_warnings);
        } catch (const InputError& e) {
            slow_error = e.what();
        }
        FUZZ_REQUIRE(error == slow_error);
        FUZZ_REQUIRE(warnings == slow_warnings);
        if (error.empty()) FUZZ_REQUIRE(to_json(scene).dump() == to_json(slow).dump());
    }
    if (!error.empty()) return 0;
    FUZZ_REQUIRE(!scene.contacts.empty());
    if (scene.contacts.size() > 6) return 0;
    const ModeSet modes = enumerate_modes(scene.contacts);
    FUZZ_REQUIRE(!modes.modes.empty());
    FUZZ_REQUIRE(modes.modes.front().letters == std::string(scene.contacts.size(), 'f'));
    if (scene.contacts.size() <= 3) {
        std::set<std::string> ours;
        for (const Mode& m : modes.modes) ours.insert(m.letters);
        FUZZ_REQUIRE(ours == testing::exact_modes(scene.contacts));
    }
    const Scene again = read_scene(to_json(scene));
    FUZZ_REQUIRE(again.contacts.size() == scene.contacts.size());
    for (std::size_t j = 0; j < scene.contacts.size(); ++j) {
        FUZZ_REQUIRE(again.contacts[j].point == scene.contacts[j].point);
        FUZZ_REQUIRE(again.contacts[j].mu == scene.contacts[j].mu);
    }
    if (!scene.body) return 0;
    const auto analysis = analyze(scene);
    FUZZ_REQUIRE(analysis.size() == modes.modes.size());
    const QueryIndex index(analysis);
    for (const ModeForces& m : analysis) {
        for (const Vec3& e : m.applied.generator_values()) {
            const QueryResult slow = query(analysis, e);
            FUZZ_REQUIRE(index.query(e).modes == slow.modes);
        }
    }
    return 0;
}
