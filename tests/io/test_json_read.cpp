// The plain reader (json_read::parse_plain) against the JSON library's own reader, the
// oracle: on every text, the plain reader either declines or gives the library's document,
// value for value and type for type (an integer stays an integer, unsigned unless negative; a
// double is the same bits). Texts come from random documents written with random spacing and
// number spellings, and from damaging them one character at a time. The scene reader, which
// takes a plain text's contacts without a document, against reading the library's document:
// the same scene, or the same error, and the same warnings.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <fstream>
#include <random>
#include <sstream>

#include "io/json_read.hpp"
#include "momentlab/io/scene_json.hpp"

namespace momentlab {
namespace {

using nlohmann::json;

// Whether a and b are the same document: same types at every place, doubles bit for bit.
bool same(const json& a, const json& b) {
    if (a.type() != b.type()) return false;
    switch (a.type()) {
        case json::value_t::object: {
            if (a.size() != b.size()) return false;
            for (auto i = a.begin(), j = b.begin(); i != a.end(); ++i, ++j) {
                if (i.key() != j.key() || !same(*i, *j)) return false;
            }
            return true;
        }
        case json::value_t::array: {
            if (a.size() != b.size()) return false;
            for (std::size_t k = 0; k < a.size(); ++k) {
                if (!same(a[k], b[k])) return false;
            }
            return true;
        }
        case json::value_t::number_float:
            return std::bit_cast<std::uint64_t>(a.get<double>()) == std::bit_cast<std::uint64_t>(b.get<double>());
        default:
            return a == b;
    }
}

std::optional<json> by_library(const std::string& text) {
    try {
        return json_read::parse_by_library(text);
    } catch (const InputError&) {
        return std::nullopt;
    }
}

// Writes random JSON texts: nested objects and arrays, strings (sometimes with escapes or
// non-ASCII bytes), and numbers spelt as people and programs spell them, including ones too
// big for 64 bits, too small or too large for a double, and leading zeros.
class TextMaker {
public:
    explicit TextMaker(unsigned seed) : rng_(seed) {}

    std::string document() {
        std::string out;
        value(out, 0);
        space(out);
        return out;
    }

private:
    int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }

    void space(std::string& out) {
        static const char* const kSpaces[] = {"", "", "", " ", "\n  ", "\t", "\r\n"};
        out += kSpaces[below(7)];
    }

    void value(std::string& out, int depth) {
        space(out);
        const int kind = depth > 4 ? 2 + below(4) : below(6);
        if (kind == 0) {
            out += '{';
            const int n = below(5);
            for (int k = 0; k < n; ++k) {
                if (k > 0) out += ',';
                space(out);
                string(out, below(8) == 0);  // short keys: some repeat
                space(out);
                out += ':';
                value(out, depth + 1);
            }
            space(out);
            out += '}';
        } else if (kind == 1) {
            out += '[';
            const int n = below(6);
            for (int k = 0; k < n; ++k) {
                if (k > 0) out += ',';
                value(out, depth + 1);
            }
            space(out);
            out += ']';
        } else if (kind == 2) {
            string(out, true);
        } else if (kind == 3) {
            static const char* const kWords[] = {"true", "false", "null"};
            out += kWords[below(3)];
        } else {
            number(out);
        }
    }

    void string(std::string& out, bool long_one) {
        static const char* const kPieces[] = {"a", "b", "mu", "x", " ", "\\n", "\\\"", "\\u00e9", "\xc3\xa9", "~", "\x7f"};
        out += '"';
        const int n = long_one ? below(6) : 1;
        for (int k = 0; k < n; ++k) out += kPieces[below(8) == 0 ? 5 + below(6) : below(5)];
        out += '"';
    }

    void number(std::string& out) {
        static const char* const kSpecial[] = {"0",     "-0",    "-0.0",   "0.0",  "1e-400", "1e400",  "-1e-400", "4.9e-324",
                                               "1e-310", "1e308", "1.8e308", "01",   "1.",     ".5",     "-",       "1e",
                                               "1E+05", "2e-05", "+1",     "0x10", "1.5e-60", "1e60",  "1e-61",   "-1e61"};
        const int kind = below(6);
        if (kind == 0) {
            out += kSpecial[below(static_cast<int>(std::size(kSpecial)))];
            return;
        }
        if (below(3) == 0) out += '-';
        if (kind == 1) {  // an integer of up to 22 digits: past 2^64 too
            const int digits = 1 + below(22);
            out += static_cast<char>('1' + below(9));
            for (int k = 1; k < digits; ++k) out += static_cast<char>('0' + below(10));
            return;
        }
        const int int_digits = 1 + below(3);
        out += static_cast<char>(int_digits == 1 ? '0' + below(10) : '1' + below(9));
        for (int k = 1; k < int_digits; ++k) out += static_cast<char>('0' + below(10));
        if (kind != 2) {
            out += '.';
            const int frac = 1 + below(20);
            for (int k = 0; k < frac; ++k) out += static_cast<char>('0' + below(10));
        }
        if (kind != 3) {
            out += below(2) == 0 ? 'e' : 'E';
            if (below(2) == 0) out += below(2) == 0 ? '-' : '+';
            out += std::to_string(below(330));
        }
    }

    std::mt19937 rng_;
};

TEST(JsonRead, PlainReaderGivesTheLibrarysDocumentOrDeclines) {
    TextMaker maker(20261125);
    std::mt19937 rng(7);
    int accepted = 0;
    int damaged_accepted = 0;
    constexpr int kTexts = 20000;
    for (int t = 0; t < kTexts; ++t) {
        std::string text = maker.document();
        for (int damaged = 0; damaged < 2; ++damaged) {
            const std::optional<json> plain = json_read::parse_plain(text);
            const std::optional<json> library = by_library(text);
            if (plain) {
                ASSERT_TRUE(library.has_value()) << "the plain reader accepted a text the library rejects: " << text;
                ASSERT_TRUE(same(*plain, *library)) << text << "\nplain:   " << plain->dump() << "\nlibrary: " << library->dump();
                (damaged ? damaged_accepted : accepted) += 1;
            }
            if (text.empty()) break;
            // One character replaced, deleted or doubled.
            const std::size_t at = std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(rng);
            static const char kChars[] = "{}[]\",:0123456789.eE+- \\atfnul";
            switch (rng() % 3) {
                case 0: text[at] = kChars[rng() % (sizeof kChars - 1)]; break;
                case 1: text.erase(at, 1); break;
                default: text.insert(at, 1, text[at]); break;
            }
        }
    }
    // The reader is used: most texts are plain (the rest have escapes, non-ASCII, repeated
    // keys or numbers that do not convert cleanly, which it leaves to the library).
    EXPECT_GT(accepted, kTexts / 4);
    EXPECT_GT(damaged_accepted, 0);
}

TEST(JsonRead, PlainReaderDeclinesWhatTheLibraryMustReport) {
    for (const char* text : {R"({"mu": 0.3, "mu": 0.4})", "[1e-400]", "[1e400]", "[0.3,]", "[01]", "[1.]", R"(["a\n"])",
                             "\xef\xbb\xbf[1]", "[1] x", "", " ", "[true false]", "{\"a\" 1}", "[nul]"}) {
        EXPECT_FALSE(json_read::parse_plain(text).has_value()) << text;
    }
    // A repeated key is named by the library path; an underflowing number is an error.
    EXPECT_THROW(json_read::parse(R"({"contacts": [{"mu": 0.3, "mu": 0.4}]})"), InputError);
    try {
        json_read::parse(R"({"contacts": [{"mu": 0.3, "mu": 0.4}]})");
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("$.contacts[0].mu"), std::string::npos) << e.what();
    }
    EXPECT_THROW(json_read::parse("[1e-400]"), InputError);
    // Deeply nested: declined past 64 levels, read by the library.
    const std::string deep = std::string(200, '[') + std::string(200, ']');
    EXPECT_FALSE(json_read::parse_plain(deep).has_value());
    EXPECT_EQ(json_read::parse(deep).dump(), by_library(deep)->dump());
}

TEST(JsonRead, RepeatedKeyOfABigObjectIsFound) {
    // An escape sends the text to the library's reader, whose check of repeated keys goes from
    // a list to a set past 16 keys: found in either, at the key's place.
    for (const int keys : {5, 16, 17, 50000}) {
        std::string text = R"({"a\n": 1)";
        for (int k = 0; k < keys; ++k) text += ", \"k" + std::to_string(k) + "\": " + std::to_string(k);
        EXPECT_EQ(json_read::parse(text + "}").size(), static_cast<std::size_t>(keys) + 1);
        try {
            json_read::parse(text + ", \"k" + std::to_string(keys - 1) + "\": 0}");
            ADD_FAILURE() << "a repeated key among " << keys << " was not reported";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("$.k" + std::to_string(keys - 1) + ": duplicate key"), std::string::npos) << e.what();
        }
    }
}

TEST(JsonRead, AVectorsFirstBadCoordinateIsNamed) {
    // Both coordinates bad: the error is the first one's, whichever reader took the text.
    for (const char* text : {R"({"contacts": [{"point": ["a", "b"], "normal": [0, 1]}]})",
                             R"({"contacts": [{"point": ["a", "b"], "normal": [0, 1], "x\n": 1}]})"}) {
        try {
            (void)read_scene_text(text);
            ADD_FAILURE() << text;
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("$.contacts[0].point[0]: expected a number", 0), 0U) << e.what();
        }
    }
}

TEST(JsonRead, EveryExampleIsPlain) {
    int files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(MOMENTLAB_EXAMPLES)) {
        if (entry.path().extension() != ".json") continue;
        std::ifstream in(entry.path());
        std::ostringstream s;
        s << in.rdbuf();
        const std::optional<json> plain = json_read::parse_plain(s.str());
        ASSERT_TRUE(plain.has_value()) << entry.path();
        EXPECT_TRUE(same(*plain, *by_library(s.str()))) << entry.path();
        ++files;
    }
    EXPECT_GT(files, 10);
}

// Scene texts: a few contacts with their fields in random order, some optional ones left out,
// now and then a value of the wrong kind or out of range, an unknown or repeated field, and a
// body whose outline the contacts may miss.
std::string scene_text(std::mt19937& rng) {
    const auto below = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
    const auto number = [&]() -> std::string {
        static const char* const kOdd[] = {"-0.3", "0", "1e-70", "1e70", "\"1\"", "null", "[1]", "3", "-1"};
        if (below(12) == 0) return kOdd[below(9)];
        return std::to_string(below(2001) - 1000) + "e-3";
    };
    std::string text = "{";
    // An outline: the square around the origin, now and then with a vertex off it, of the
    // wrong kind or of three coordinates, or not a list of vertices at all.
    const auto outline_text = [&](double half) {
        static const char* const kOdd[] = {"[]", "3", "[[0, 0], [1, 1]]", "[[-1, -1], [1, -1], [1, 1, 1], [-1, 1]]",
                                           R"([[-1, -1], [1, -1], ["1", 1], [-1, 1]])", "[[-1, -1], [1, -1], [1, 1], [-1, 1e-400]]",
                                           "[[-1, -1], [1, 1], [1, -1], [-1, 1]]", "[[-1, -1], [1, -1], [1, 1], [-1, 1e70]]"};
        if (below(6) == 0) return std::string(kOdd[below(8)]);
        const std::string h = std::to_string(half), m = std::to_string(-half);
        return "[[" + m + ", " + m + "], [" + h + ", " + m + "], [" + h + ", " + h + "], [" + m + ", " + h + "]]";
    };
    const bool outline = below(3) == 0;
    if (below(6) != 0) {
        text += R"("body": {"mass": 1, "com": [0, 0], "inertia": 0.5)";
        if (outline) text += R"(, "polygon": )" + outline_text(1);
        text += "}, ";
    }
    if (below(4) == 0) {  // obstacles, some not objects or without a polygon
        text += R"("obstacles": [)";
        for (int k = below(3); k >= 0; --k) {
            const int kind = below(8);
            text += kind == 0 ? "3" : kind == 1 ? "{}" : R"({"polygon": )" + outline_text(2 + k) + "}";
            if (k > 0) text += ", ";
        }
        text += "], ";
    }
    if (below(10) == 0) {  // no contacts: they are found from the polygons, if any
        text += R"("mu": 0.25})";
        return text;
    }
    text += R"("contacts": [)";
    const int contacts = below(5);
    for (int k = 0; k < contacts; ++k) {
        std::vector<std::string> fields;
        const std::string x = outline ? std::to_string(below(3) - 1) : number();
        if (below(15) != 0) fields.push_back(R"("point": [)" + x + ", " + (outline ? "-1" : number()) + "]");
        if (below(15) != 0) fields.push_back(R"("normal": [)" + number() + ", " + (below(8) == 0 ? "0" : number()) + "]");
        if (below(2) == 0) fields.push_back(R"("mu": )" + number());
        if (below(4) == 0) fields.push_back(R"("mu_kinetic": )" + number());
        if (below(4) == 0) fields.push_back(below(6) == 0 ? R"("name": 3)" : R"("name": "c)" + std::to_string(k) + "\"");
        if (below(20) == 0) fields.push_back(R"("colour": "red")");
        if (below(20) == 0) fields.push_back(R"("mu": 0.1)");
        if (below(20) == 0) fields.push_back(R"("point": [1, 2, 3])");
        std::shuffle(fields.begin(), fields.end(), rng);
        text += k > 0 ? ", {" : "{";
        for (std::size_t f = 0; f < fields.size(); ++f) text += (f > 0 ? ", " : "") + fields[f];
        text += "}";
    }
    text += "]";
    if (below(8) == 0) text += R"(, "mu": 0.2)";
    if (below(8) == 0) text += R"(, "contact_distance": 0.01)";
    return text + "}";
}

// What reading gives: the scene written back and the warnings, or the error.
std::string outcome(const std::function<Scene(InputWarnings*)>& read) {
    InputWarnings warnings;
    try {
        const Scene scene = read(&warnings);
        std::string out = to_json(scene).dump();
        for (const std::string& w : warnings) out += "\nwarning: " + w;
        return out;
    } catch (const InputError& e) {
        return std::string("error: ") + e.what();
    }
}

TEST(JsonRead, SceneReaderGivesWhatTheLibrarysDocumentGives) {
    std::mt19937 rng(11);
    int plain_scenes = 0, plain_errors = 0, polygon_scenes = 0, polygon_errors = 0, scenes = 0;
    for (int t = 0; t < 6000; ++t) {
        std::string text = scene_text(rng);
        for (int damaged = 0; damaged < 2; ++damaged) {
            const std::string fast = outcome([&](InputWarnings* w) { return read_scene_text(text, w); });
            const std::string slow = outcome([&](InputWarnings* w) {
                return read_scene(json_read::parse_by_library(text), w);
            });
            ASSERT_EQ(fast, slow) << text;
            const std::optional<json_read::PlainScene> plain = json_read::parse_plain_scene(text);
            const bool read = fast.rfind("error", 0) != 0;
            if (plain && !plain->contacts.empty()) (read ? plain_scenes : plain_errors) += 1;
            const bool plain_polygon = plain && (plain->body_polygon || std::any_of(plain->obstacle_polygons.begin(),
                                                                                   plain->obstacle_polygons.end(),
                                                                                   [](const auto& p) { return p.has_value(); }));
            if (plain_polygon) (read ? polygon_scenes : polygon_errors) += 1;
            if (read) ++scenes;
            const std::size_t at = rng() % text.size();
            text[at] = "{}[]\",:0-. e"[rng() % 13];
        }
    }
    // Both paths are exercised, and the contacts and polygons taken apart give scenes and errors.
    EXPECT_GT(plain_scenes, 500);
    EXPECT_GT(polygon_scenes, 100);
    EXPECT_GT(polygon_errors, 100);
    EXPECT_GT(plain_errors, 500);
    EXPECT_GT(scenes, 600);
}

}  // namespace
}  // namespace momentlab
