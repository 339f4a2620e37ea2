// The plain reader (json_read::read_plain) against the JSON library's SAX parser (the oracle),
// both feeding the same document builder: on every text the plain reader either declines or
// gives the library's document, node for node (kinds, keys, strings, doubles bit for bit, the
// exact value of each number's text). Texts come from random documents written with random
// spacing and number spellings, and from damaging them one character at a time. Then what a
// Schema keeps (memory follows the fields read, not the text), the scene reader by every road
// to a document, and exact_decimal against Python's fractions.Fraction.
#include <gtest/gtest.h>

#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <unistd.h>

#include "io/json_read.hpp"
#include "json_documents.hpp"
#include "momentlab/io/printable.hpp"
#include "momentlab/io/scene_json.hpp"
#include "../common/sizes.hpp"

namespace momentlab {
namespace {

using json_read::Document;
using json_read::Value;
using testing::describe;

// The library's document, or its error.
std::string by_library(const std::string& text, const json_read::Schema& schema = json_read::kEverything) {
    try {
        return describe(json_read::read_by_library(text, schema));
    } catch (const InputError& e) {
        return std::string("error: ") + e.what();
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
                                               "1E+05", "2e-05", "+1",     "0x10", "1.5e-60", "1e60",  "1e-61",   "-1e61",
                                               "18446744073709551615", "18446744073709551616", "-9223372036854775808",
                                               "-9223372036854775809", "9007199254740993", "1e-0", "0e-400"};
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
    int accepted = 0, damaged_accepted = 0, errors_alike = 0;
    constexpr int kTexts = testing::sized(20000);
    for (int t = 0; t < kTexts; ++t) {
        std::string text = maker.document();
        for (int damaged = 0; damaged < 2; ++damaged) {
            const std::string library = by_library(text);
            std::string plain;
            try {
                const std::optional<Document> doc = json_read::read_plain(text, json_read::kEverything);
                if (doc) plain = describe(*doc);
            } catch (const InputError& e) {  // a repeated key or an underflow: the library's error too
                plain = std::string("error: ") + e.what();
                ++errors_alike;
            }
            if (!plain.empty()) {
                ASSERT_EQ(plain, library) << text;
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
    // The reader is used: most texts are plain (the rest have escapes, non-ASCII or numbers that
    // do not convert, which it leaves to the library).
    EXPECT_GT(accepted, kTexts / 4);
    EXPECT_GT(damaged_accepted, 0);
    EXPECT_GT(errors_alike, testing::floor_of(100));
}

// end_of_digits against the byte-by-byte definition: every byte after runs of 0-20 digits,
// at every alignment (the eight-byte test sees the byte in each of its lanes).
TEST(JsonRead, EndOfDigitsStopsAtTheFirstByteThatIsNoDigit) {
    for (int length = 0; length <= 20; ++length) {
        for (int end = 0; end < 256; ++end) {
            for (int tail = 0; tail < 9; ++tail) {
                std::string text;
                for (int k = 0; k < length; ++k) text += static_cast<char>('0' + (k * 3 + end) % 10);
                text += static_cast<char>(end);
                text += std::string(static_cast<std::size_t>(tail), '7');
                const std::size_t expected = (end >= '0' && end <= '9') ? text.size() : static_cast<std::size_t>(length);
                ASSERT_EQ(json_read::end_of_digits(text.data(), text.data() + text.size()) - text.data(),
                          static_cast<std::ptrdiff_t>(expected))
                    << length << " " << end << " " << tail;
            }
        }
    }
}

// The plain reader skips the digits beyond the 19th eight bytes at a time: a run of 20-60
// digits ended, at every offset, by every byte (the ones next to '0'..'9' among them: '/' and
// ':', and those whose high nibble is 3), in the integer part, the fraction and the exponent's
// mantissa; what the plain reader accepts is the library's document, and it accepts the runs
// ended by a comma.
TEST(JsonRead, PlainReaderEndsLongRunsOfDigitsWhereTheLibraryDoes) {
    int accepted = 0;
    for (int length = 20; length <= 60; length += 3) {
        for (int end = 0; end < 256; ++end) {
            for (const char* form : {"I", "0.I", "1.I", "0.0000I", "I.5", "0.Ie-3"}) {
                std::string digits;
                for (int k = 0; k < length; ++k) digits += static_cast<char>('1' + (k * 7 + length) % 9);
                std::string number = form;
                number.replace(number.find('I'), 1, digits + std::string(1, static_cast<char>(end)));
                const std::string text = "[" + number + ",2]";
                std::string plain;
                try {
                    const std::optional<Document> doc = json_read::read_plain(text, json_read::kEverything);
                    if (!doc) continue;
                    plain = describe(*doc);
                } catch (const InputError& e) {
                    plain = std::string("error: ") + e.what();
                }
                ASSERT_EQ(plain, by_library(text)) << text;
                ++accepted;
            }
        }
    }
    EXPECT_GE(accepted, 14 * 6);  // at least every run ended by the comma
}

TEST(JsonRead, PlainReaderDeclinesWhatTheLibraryMustReport) {
    for (const char* text : {"[1e400]", "[0.3,]", "[01]", "[1.]", R"(["a\n"])", "\xef\xbb\xbf[1]", "[1] x", "", " ",
                             "[true false]", "{\"a\" 1}", "[nul]", "[\"\xc3\xa9\"]"}) {
        EXPECT_FALSE(json_read::read_plain(text, json_read::kEverything).has_value()) << text;
    }
    EXPECT_EQ(by_library("[1e400]").rfind("error: $[0]: a number beyond the doubles is out of range", 0), 0U) << by_library("[1e400]");
    // named by its path, in an object and in a nested array (review of issue 46: it was "$")
    EXPECT_EQ(by_library("{\"a\": [0, {\"b\": [1, -1e999]}]}").rfind("error: $.a[1].b[1]: a number beyond the doubles", 0), 0U)
        << by_library("{\"a\": [0, {\"b\": [1, -1e999]}]}");
    EXPECT_EQ(by_library("[0.3,]").rfind("error: $: malformed JSON", 0), 0U);
    // A repeated key and an underflowing number are named by their path, by either reader.
    for (const auto& read : {std::function<Document(const std::string&)>([](const std::string& t) {
                                 return json_read::read(t, json_read::kEverything);
                             }),
                             std::function<Document(const std::string&)>([](const std::string& t) {
                                 return json_read::read_by_library(t, json_read::kEverything);
                             })}) {
        for (const auto& [text, error] : std::vector<std::pair<std::string, std::string>>{
                 {R"({"contacts": [{"mu": 0.3, "mu": 0.4}]})", "$.contacts[0].mu: duplicate key"},
                 {R"({"contacts": [{"mu": 0.3, "mu": "\n"}]})", "$.contacts[0].mu: duplicate key"},
                 // (no range of magnitudes after it, which a vector's tiny coordinate need not meet)
                 {"[0, [1e-400]]", "$[1][0]: a number too small for a double: it would be taken as 0"},
                 {R"({"a": -2e-324})", "$.a: a number too small for a double"}}) {
            try {
                (void)read(text);
                ADD_FAILURE() << text;
            } catch (const InputError& e) {
                EXPECT_EQ(std::string(e.what()).rfind(error, 0), 0U) << e.what();
            }
        }
    }
}

TEST(JsonRead, DeepNestingIsReadWithoutRecursion) {
    for (const int depth : {200, 100000}) {
        const std::string deep = std::string(depth, '[') + std::string(depth, ']');
        const std::optional<Document> plain = json_read::read_plain(deep, json_read::kEverything);
        ASSERT_TRUE(plain.has_value());
        EXPECT_EQ(plain->nodes(), static_cast<std::size_t>(depth));
        if (depth == 200) {
            EXPECT_EQ(describe(*plain), by_library(deep));
        }
    }
}

TEST(JsonRead, RepeatedKeyOfABigObjectIsFound) {
    // An escape sends the text to the library's reader; the check of repeated keys goes from a
    // list to a set past 16 keys: found in either reader, at the key's place, where the value is
    // read. In an object the scene reader skips (an unknown field) a repeat changes nothing and
    // is not looked for: its keys would cost memory that follows the text (issue 44, item 5).
    for (const bool escaped : {false, true}) {
        for (const int keys : {5, 16, 17, 50000}) {
            std::string text = escaped ? R"({"notes": {"a\n": 1)" : R"({"notes": {"a": 1)";
            for (int k = 0; k < keys; ++k) text += ", \"k" + std::to_string(k) + "\": " + std::to_string(k);
            for (const json_read::Schema* schema : {&json_read::kEverything, &json_read::scene_schema()}) {
                EXPECT_EQ(json_read::read(text + "}}", *schema).root().size(), 1U);
                if (schema == &json_read::scene_schema()) {
                    EXPECT_NO_THROW((void)json_read::read(text + ", \"k" + std::to_string(keys - 1) + "\": 0}}", *schema));
                    continue;
                }
                try {
                    (void)json_read::read(text + ", \"k" + std::to_string(keys - 1) + "\": 0}}", *schema);
                    ADD_FAILURE() << "a repeated key among " << keys << " was not reported";
                } catch (const InputError& e) {
                    EXPECT_EQ(std::string(e.what()).rfind("$.notes.k" + std::to_string(keys - 1) + ": duplicate key", 0), 0U)
                        << e.what();
                }
            }
        }
    }
}

TEST(JsonRead, NumbersKeepTheirTextAsTyped) {
    const std::string text = R"([0.1, 1E+2, -0.0, -0, 123456789012345678901234567890, 2.943, 7])";
    std::vector<std::string> typed = {"0.1", "1E+2", "-0.0", "-0", "123456789012345678901234567890", "2.943", "7"};
    const Document plain = *json_read::read_plain(text, json_read::kEverything);
    const Document library = json_read::read_by_library(text, json_read::kEverything);
    std::vector<std::string> plain_texts, library_texts;
    plain.root().for_each_element([&](std::size_t, const Value& v) { plain_texts.emplace_back(v.number().text); });
    library.root().for_each_element([&](std::size_t, const Value& v) { library_texts.emplace_back(v.number().text); });
    EXPECT_EQ(plain_texts, typed);
    // The library gives an integer's value, not its text: its digits (the same number; "-0" is 0).
    typed[3] = "0";
    EXPECT_EQ(library_texts, typed);
    // A document built in memory: integers get their digits, doubles no text (binary, exact).
    const nlohmann::json doc = {1, 0.1, -7};
    const Document built = json_read::document_of(doc, json_read::kEverything);
    std::vector<std::string> built_texts;
    built.root().for_each_element([&](std::size_t, const Value& v) { built_texts.emplace_back(v.number().text); });
    EXPECT_EQ(built_texts, (std::vector<std::string>{"1", "", "-7"}));
}

// The plain reader's spelling (whether a text is exactly its double, found while reading it)
// and its double, against GMP: the text as an exact fraction (mpq_class of the decimal) against
// the double's exact value, and the double against glibc's correctly rounded strtod. Texts sit
// on the reader's bounds: digits below and above 2^53 (the Clinger fast path's bound), odd
// factors at 2^53 - 1 and 2^53 + 1, exponents +-22, +-27 and +-28, 19 and 20 digits, exact
// doubles written with their exact digits (and trailing zeros) beside ones a digit away.
mpq_class exact_of_text(std::string t) {
    bool negative = !t.empty() && t[0] == '-';
    if (negative) t.erase(0, 1);
    std::int64_t e = 0;
    if (const auto at = t.find_first_of("eE"); at != std::string::npos) {
        e = std::stoll(t.substr(at + 1));
        t.erase(at);
    }
    if (const auto at = t.find('.'); at != std::string::npos) {
        e -= static_cast<std::int64_t>(t.size() - at - 1);
        t.erase(at, 1);
    }
    mpz_class digits(t, 10), ten = 1;
    mpz_ui_pow_ui(ten.get_mpz_t(), 10, static_cast<unsigned long>(e >= 0 ? e : -e));
    mpq_class q = e >= 0 ? mpq_class(digits * ten) : mpq_class(digits, ten);
    q.canonicalize();
    return negative ? mpq_class(-q) : q;
}

TEST(JsonRead, PlainReaderKnowsWhichTextsAreExactlyDoubles) {
    std::mt19937_64 rng(20261129);
    std::vector<std::string> texts = {"0", "-0", "0.0", "-0.000", "9007199254740992", "9007199254740993",
                                      "9007199254740991", "18014398509481983", "0.5", "-0.25", "0.1", "2.943",
                                      "1e22", "1e23", "1e-22", "5e-22", "2384185791015625e-27", "2384185791015625e-28",
                                      "7450580596923828125e-27", "9999999999999999999", "12345678901234567890",
                                      "0.30000000000000004", "0.98004150390625", "1.0000000000000000000"};
    const auto with_digits = [](const mpq_class& q, int fraction_digits, bool trailing) {
        // q (a dyadic) written with exactly `fraction_digits` digits after the point.
        mpz_class ten = 1;
        mpz_ui_pow_ui(ten.get_mpz_t(), 10, static_cast<unsigned long>(fraction_digits));
        const mpz_class scaled = q.get_num() * ten / q.get_den();  // truncated: exact when enough digits
        std::string s = mpz_class(abs(scaled)).get_str();
        if (static_cast<int>(s.size()) <= fraction_digits) s.insert(0, static_cast<std::size_t>(fraction_digits + 1) - s.size(), '0');
        if (fraction_digits > 0) s.insert(s.size() - static_cast<std::size_t>(fraction_digits), ".");
        if (trailing) s += "00";
        return (sgn(scaled) < 0 ? "-" : "") + s;
    };
    for (int k = 0; k < testing::sized(20000); ++k) {
        // A double m 2^-j with m of 1..54 bits, written with its exact digits, one digit fewer
        // (rounded down: not exact), and in exponent form.
        const int bits = 1 + static_cast<int>(rng() % 54), j = static_cast<int>(rng() % 30) - 4;
        const std::uint64_t m = (rng() >> (64 - bits)) | (std::uint64_t{1} << (bits - 1));
        mpq_class q(mpz_class(std::to_string(m)), 1);
        if (j > 0) q /= mpq_class(mpz_class(1) << j);
        if (j < 0) q *= mpq_class(mpz_class(1) << -j);
        q.canonicalize();
        if (rng() % 2) q = -q;
        const int exact_digits = j > 0 ? j : 0;
        texts.push_back(with_digits(q, exact_digits, rng() % 4 == 0));
        if (exact_digits > 0) texts.push_back(with_digits(q, exact_digits - 1, false));
        const std::string plain = with_digits(q, exact_digits, false);
        std::string digits = plain;
        digits.erase(std::remove(digits.begin(), digits.end(), '.'), digits.end());
        const std::size_t sign = digits[0] == '-' ? 1 : 0;  // (JSON: no leading zeros)
        while (digits.size() > sign + 1 && digits[sign] == '0') digits.erase(sign, 1);
        texts.push_back(digits + "e-" + std::to_string(exact_digits));
        texts.push_back(digits + "1e" + std::to_string(static_cast<int>(rng() % 60) - 30));
    }
    int exact = 0, decided = 0;
    for (const std::string& t : texts) {
        const std::string text = "[" + t + "]";  // (the document reads its numbers' texts there)
        const std::optional<Document> doc = json_read::read_plain(text, json_read::kEverything);
        ASSERT_TRUE(doc) << t;
        std::optional<Value> element;
        doc->root().for_each_element([&](std::size_t, const Value& e) { element = e; });
        const Value v = *element;
        const json_read::JsonNumber n = v.number();
        ASSERT_EQ(n.value, std::strtod(t.c_str(), nullptr)) << t;
        const bool is_exact = exact_of_text(t) == mpq_class(n.value);
        if (n.spelling != json_read::JsonNumber::Spelling::Unknown) {
            ++decided;
            ASSERT_EQ(n.spelling == json_read::JsonNumber::Spelling::Exact, is_exact) << t;
        }
        ASSERT_EQ(v.spells_doubles(), n.spelling == json_read::JsonNumber::Spelling::Exact) << t;
        ASSERT_EQ(json_read::exact_number(v) == Rational(n.value), is_exact) << t;
        exact += is_exact ? 1 : 0;
    }
    // Both kinds, and the reader decides the texts of at most 19 digits and exponents within
    // +-27 (it leaves the rest to Rational::spells): most of these.
    EXPECT_GT(exact, static_cast<int>(texts.size()) / 3);
    EXPECT_LT(exact, static_cast<int>(texts.size()) * 3 / 4);
    EXPECT_GT(decided, static_cast<int>(texts.size()) / 2);
}

// Texts of more than 19 digits, or exponents past -27, are decided while they are read too:
// every double m 2^-j (m of 1..60 bits, j up to the subnormals) written with its exact digits
// (up to 767 significant), in exponent form, with zeros after it, with its last digit changed
// and with a digit more; GMP tells which are exactly their double. Fails when the odd part's
// bound (2^53), the remainder test of the division by 5^-e or the 767 digits are changed.
TEST(JsonRead, PlainReaderDecidesLongTexts) {
    std::mt19937_64 rng(20261130);
    std::vector<std::string> texts;
    const auto exact_text = [](const mpz_class& m, int j) {  // m 2^-j, j >= 0, in j fraction digits
        mpz_class five;
        mpz_ui_pow_ui(five.get_mpz_t(), 5, static_cast<unsigned long>(j));
        std::string s = mpz_class(m * five).get_str();
        if (static_cast<int>(s.size()) <= j) s.insert(0, static_cast<std::size_t>(j + 1) - s.size(), '0');
        if (j > 0) s.insert(s.size() - static_cast<std::size_t>(j), ".");
        return s;
    };
    const auto add = [&](const mpz_class& m, int j) {
        const std::string t = exact_text(m, j);
        texts.push_back(t);
        texts.push_back(t + "000");
        std::string changed = t;
        changed.back() = changed.back() == '9' ? '8' : static_cast<char>(changed.back() + 1);
        texts.push_back(changed);
        texts.push_back(t + "1");
        std::string digits = t;
        digits.erase(std::remove(digits.begin(), digits.end(), '.'), digits.end());
        while (digits.size() > 1 && digits[0] == '0') digits.erase(0, 1);
        texts.push_back("-" + digits + "e-" + std::to_string(j));
    };
    add((mpz_class(1) << 53) - 1, 1074);  // the longest: 767 significant digits
    add(mpz_class(1), 1074);              // the least subnormal
    add((mpz_class(1) << 53) + 1, 1074);  // 54 bits: no double
    for (int k = 0; k < testing::sized(3000); ++k) {
        const int bits = 1 + static_cast<int>(rng() % 60);
        mpz_class m = mpz_class(static_cast<unsigned long>(rng() >> (64 - bits))) | (mpz_class(1) << (bits - 1));
        if (m % 2 == 0) m += 1;
        const int j = 20 + static_cast<int>(rng() % static_cast<std::uint64_t>(1074 - 20 + bits - 1));
        add(m, j);
    }
    std::size_t exact = 0, decided = 0;
    for (const std::string& t : texts) {
        const std::string text = "[" + t + "]";
        const std::optional<Document> doc = json_read::read_plain(text, json_read::kEverything);
        ASSERT_TRUE(doc) << t;
        std::optional<Value> element;
        doc->root().for_each_element([&](std::size_t, const Value& e) { element = e; });
        const json_read::JsonNumber n = element->number();
        ASSERT_EQ(n.value, std::strtod(t.c_str(), nullptr)) << t;
        const bool is_exact = exact_of_text(t) == mpq_class(n.value);
        if (n.spelling != json_read::JsonNumber::Spelling::Unknown) {
            ++decided;
            ASSERT_EQ(n.spelling == json_read::JsonNumber::Spelling::Exact, is_exact) << t;
        }
        ASSERT_EQ(json_read::exact_number(*element) == Rational(n.value), is_exact) << t;
        exact += is_exact ? 1 : 0;
    }
    EXPECT_GT(exact, texts.size() / 4);
    EXPECT_LT(exact, texts.size() * 3 / 4);
    EXPECT_EQ(decided, texts.size());  // (every one has a negative exponent and a quotient below 2^128)
}

// An exponent longer than any held count: 0.000...01e1000000 (99,999 zeros) is 10^900000, not
// 1 (review-31: the plain reader once held the exponent at 10^5, below the fraction's length).
TEST(JsonRead, LongExponentsAreNotHeldBelowTheFraction) {
    const std::string text = "[0." + std::string(99999, '0') + "1e1000000]";
    EXPECT_FALSE(json_read::read_plain(text, json_read::kEverything).has_value());  // not a finite double
    EXPECT_THROW((void)json_read::read(text, json_read::kEverything), InputError);
    const std::string fits = "[0." + std::string(99999, '0') + "3e99999]";  // 0.3
    const std::optional<Document> doc = json_read::read_plain(fits, json_read::kEverything);
    ASSERT_TRUE(doc.has_value());
    doc->root().for_each_element([&](std::size_t, const Value& v) {
        EXPECT_EQ(v.number().value, 0.3);
        EXPECT_EQ(json_read::exact_number(v), *Rational::parse("0.3"));
    });
    // Rational::parse alike: 999,998 zeros against an exponent of 9,999,999 is 10^9000001, refused.
    EXPECT_FALSE(Rational::parse("0." + std::string(999998, '0') + "1e9999999").has_value());
}

TEST(JsonRead, EveryExampleIsPlain) {
    int files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(MOMENTLAB_EXAMPLES)) {
        if (entry.path().extension() != ".json") continue;
        std::ifstream in(entry.path());
        std::ostringstream s;
        s << in.rdbuf();
        const std::string text = s.str();  // the document's texts lie in it: kept while it is read
        const std::optional<Document> plain = json_read::read_plain(text, json_read::kEverything);
        ASSERT_TRUE(plain.has_value()) << entry.path();
        EXPECT_EQ(describe(*plain), by_library(text)) << entry.path();
        ++files;
    }
    EXPECT_GT(files, 10);
}

// What a Schema does not name costs a node whatever its size (memory follows the fields read);
// an array longer than its place keeps (a point of three numbers) is its kind and length.
TEST(JsonRead, WhatTheSchemaDoesNotReadIsSkipped) {
    const std::string scene = R"({"body": {"mass": 1, "com": [0, 0], "inertia": 1}, "contacts": [
        {"point": [0, -1], "normal": [0, 1], "mu": 0.5, "colour": "red"}], "notes": )";
    std::string big = "[";
    for (int k = 0; k < 100000; ++k) big += R"({"k": [1, 2, "x"]}, )";
    big += "0]";
    const std::string text = scene + big + "}";
    const Document small = json_read::read(scene + "0}", json_read::scene_schema());
    for (const auto& read : {json_read::read_by_library, json_read::read}) {
        const Document doc = read(text, json_read::scene_schema());
        EXPECT_EQ(doc.nodes(), small.nodes());  // "notes" is one node, however long
        const Value notes = *doc.root().find("notes");
        EXPECT_FALSE(notes.kept());
        EXPECT_TRUE(notes.is_array());
        EXPECT_EQ(notes.size(), 100001U);
    }
    EXPECT_GT(json_read::read(text, json_read::kEverything).nodes(), 100000U * 6);
    InputWarnings warnings;
    EXPECT_EQ(read_scene_text(text, &warnings).contacts.size(), 1U);
    EXPECT_EQ(warnings, (InputWarnings{"$.notes: unknown field, ignored (expected body, contacts, obstacles, contact_distance, mu)",
                                       "$.contacts[0].colour: unknown field, ignored (expected point, normal, mu, mu_kinetic, name)"}));
    const std::string long_point = R"({"contacts": [{"point": [0, -1, 5, 6], "normal": [0, 1]}]})";
    try {
        (void)read_scene_text(long_point);
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "$.contacts[0].point: expected [x, y]");
    }
}

// Millions of unknown fields (issue 44, item 5: a 65 MB file of them took 1.4 GB and 70 s, and
// printed 6 million lines): the first 20 are listed, the rest counted in one line, across
// objects; their repeated keys are not looked for.
TEST(JsonRead, ManyUnknownFieldsGiveAFewLines) {
    for (const bool escaped : {false, true}) {
        std::string text = R"({"contacts": [{"point": [0, 0], "normal": [0, 1])";
        for (int k = 0; k < 30; ++k) text += ", \"c" + std::to_string(k) + "\": 0";
        text += "}]";
        for (int k = 0; k < 50000; ++k) text += std::string(", \"") + (escaped ? "\\u0074" : "t") + std::to_string(k % 40000) + "\": 0";
        text += "}";
        InputWarnings warnings;
        EXPECT_EQ(read_scene_text(text, &warnings).contacts.size(), 1U);
        ASSERT_EQ(warnings.size(), 21U);
        const std::string t0 = "$.t0: unknown field, ignored (expected body, contacts, obstacles, contact_distance, mu)";
        EXPECT_EQ(warnings[0], t0);
        EXPECT_EQ(warnings[1], t0);  // a repeated unknown field: not an error
        EXPECT_EQ(warnings[20], "$: 50010 more unknown fields, ignored (the first 20 are listed)");
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

// Scene texts: a few contacts with their fields in random order, some optional ones left out,
// now and then a value of the wrong kind or out of range, an unknown or repeated field, and a
// body whose outline the contacts may miss.
std::string scene_text(std::mt19937& rng) {
    const auto below = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
    const auto number = [&]() -> std::string {
        static const char* const kOdd[] = {"-0.3", "0", "1e-70", "1e70", "\"1\"", "null", "[1]", "3", "-1", "[1, 2]", "{}"};
        if (below(12) == 0) return kOdd[below(11)];
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
        if (below(20) == 0) fields.push_back(R"("note\n": [1, {"a": 2}])");
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

// Every road to a scene's document gives the same scene, warnings or error: the text by the
// plain reader (read_scene_text), by the library's SAX parser, and (where the library's DOM
// reads the text the same: no repeated key or underflow) the DOM through document_of.
TEST(JsonRead, SceneReaderGivesTheSameByEveryRoad) {
    std::mt19937 rng(11);
    int scenes = 0, errors = 0, by_dom = 0;
    for (int t = 0; t < testing::sized(6000); ++t) {
        std::string text = scene_text(rng);
        for (int damaged = 0; damaged < 2; ++damaged) {
            const std::string fast = outcome([&](InputWarnings* w) { return read_scene_text(text, w); });
            const std::string slow = outcome([&](InputWarnings* w) {
                return json_read::scene_of(json_read::read_by_library(text, json_read::scene_schema()), w);
            });
            ASSERT_EQ(fast, slow) << text;
            const nlohmann::json dom = nlohmann::json::parse(text, nullptr, false);
            if (!dom.is_discarded() && fast.find("duplicate key") == std::string::npos &&
                fast.find("too small for a double") == std::string::npos) {
                ASSERT_EQ(fast, outcome([&](InputWarnings* w) { return read_scene(dom, w); })) << text;
                ++by_dom;
            }
            (fast.rfind("error", 0) == 0 ? errors : scenes) += 1;
            const std::size_t at = rng() % text.size();
            text[at] = "{}[]\",:0-. e"[rng() % 13];
        }
    }
    EXPECT_GT(scenes, testing::floor_of(600));
    EXPECT_GT(errors, testing::floor_of(3000));
    EXPECT_GT(by_dom, testing::floor_of(5000));
}

// exact_decimal against Python's fractions.Fraction(text), written as sign, digits without
// trailing zeros and a power of ten: random texts of JSON's grammar (up to 40 digits on either
// side of the point, exponents up to +-2000) and edge texts, and texts outside the grammar,
// which Python must reject too (or, for those JSON forbids but Python allows, exact_decimal alone).
TEST(JsonRead, ExactDecimalIsPythonsFraction) {
    std::vector<std::string> texts = {"0.1", "1e-400", "123456789012345678901234567890", "-0.0", "1E+2", "0", "-0",
                                      "2.943", "1e400", "0.000", "100", "-1.50e-3", "9007199254740993", "5e-324",
                                      "0e99", "1.0e0", "10e-1", "0.1e+0001", "123.456e-00789"};
    std::mt19937_64 rng(46);
    const auto digits = [&](std::size_t n, bool lead) {
        std::string s;
        for (std::size_t k = 0; k < n; ++k) s += static_cast<char>('0' + (k == 0 && lead ? 1 + rng() % 9 : rng() % 10));
        return s;
    };
    for (int t = 0; t < 3000; ++t) {
        std::string s = rng() % 3 == 0 ? "-" : "";
        const std::size_t whole = rng() % 41;
        s += whole <= 1 ? std::string(1, static_cast<char>('0' + rng() % 10)) : digits(whole, true);
        if (rng() % 2) s.append(1, '.').append(digits(1 + rng() % 40, false));
        if (rng() % 2) {
            s += rng() % 2 ? "e" : "E";
            if (rng() % 2) s += rng() % 2 ? "+" : "-";
            s += std::to_string(rng() % 2001);
        }
        texts.push_back(s);
    }
    const std::vector<std::string> outside = {"", "-", "+1", "01", "1.", ".5", "1e", "1e+", "0x10", "1 ", "inf", "1e1234567890123456789"};
    const std::string dir = ::testing::TempDir() + "momentlab_decimal_" + std::to_string(getpid());
    std::filesystem::create_directories(dir);
    {
        std::ofstream out(dir + "/texts");
        for (const std::string& s : texts) out << s << "\n";
    }
    const std::string script =
        "import sys\nfrom fractions import Fraction\n"
        "for line in open(sys.argv[1]):\n"
        "    f = Fraction(line.strip())\n"
        "    sign, f = ('-' if f < 0 else ''), abs(f)\n"
        "    d, a, b = f.denominator, 0, 0\n"
        "    while d % 2 == 0: d, a = d // 2, a + 1\n"
        "    while d % 5 == 0: d, b = d // 5, b + 1\n"
        "    assert d == 1\n"
        "    e = -max(a, b)\n"
        "    n = f.numerator * 10 ** -e // f.denominator\n"
        "    while n and n % 10 == 0: n, e = n // 10, e + 1\n"
        "    print(sign + str(n) + 'e' + str(e) if n else 'e0')\n";
    std::ofstream(dir + "/oracle.py") << script;
    FILE* pipe = ::popen(("/usr/bin/python3 " + dir + "/oracle.py " + dir + "/texts").c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::vector<std::string> expected;
    char line[20000];
    while (std::fgets(line, sizeof line, pipe)) expected.emplace_back(line, std::strlen(line) - 1);
    ASSERT_EQ(::pclose(pipe), 0);
    ASSERT_EQ(expected.size(), texts.size());
    for (std::size_t i = 0; i < texts.size(); ++i) {
        const std::optional<json_read::Decimal> d = json_read::exact_decimal(texts[i]);
        ASSERT_TRUE(d.has_value()) << texts[i];
        EXPECT_EQ((d->negative ? "-" : "") + d->digits + "e" + std::to_string(d->exponent), expected[i]) << texts[i];
    }
    for (const std::string& s : outside) EXPECT_FALSE(json_read::exact_decimal(s).has_value()) << s;
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace momentlab

// The one rule for showing users' and libraries' text (io/printable.hpp), byte by byte: the
// control bytes, DEL, well-formed UTF-8 of each length and the ill-formed sequences of the
// Unicode standard's table 3-7 (overlong, surrogate, above U+10FFFF, cut short), in both forms.
TEST(Printable, OneRuleForMessagesNamesAndPictures) {
    using momentlab::Printable;
    using momentlab::printable;
    const std::string controls("a\nb\tc\rd\x01" "e\x1b[31m\x7f" "f\0g", 18);
    EXPECT_EQ(printable(controls), "a\\nb\\tc\\rd\\x01e\\x1b[31m\\x7ff\\x00g");
    EXPECT_EQ(printable(controls, Printable::Ascii), printable(controls));
    // Well-formed: U+00E9, U+20AC, U+1F600, and the ends of the ranges (U+0080, U+D7FF, U+E000,
    // U+10FFFD, the last that is no noncharacter).
    const std::string good = "\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80 \xC2\x80 \xED\x9F\xBF \xEE\x80\x80 \xF4\x8F\xBF\xBD";
    EXPECT_EQ(printable(good), good);
    EXPECT_EQ(printable("\xC3\xA9", Printable::Ascii), "\\xc3\\xa9");
    // Noncharacters, well-formed but refused by Cairo and XML: U+FDD0, U+FDEF, U+FFFE, U+FFFF,
    // U+1FFFE, U+10FFFF; their neighbours U+FDCF, U+FDF0, U+FFFD, U+1FFFD are kept.
    for (const char* nonchar : {"\xEF\xB7\x90", "\xEF\xB7\xAF", "\xEF\xBF\xBE", "\xEF\xBF\xBF", "\xF0\x9F\xBF\xBE", "\xF4\x8F\xBF\xBF"}) {
        EXPECT_EQ(printable(std::string("<") + nonchar + ">"), "<\xEF\xBF\xBD>") << nonchar;
    }
    for (const char* kept : {"\xEF\xB7\x8F", "\xEF\xB7\xB0", "\xEF\xBF\xBD", "\xF0\x9F\xBF\xBD"}) {
        EXPECT_EQ(printable(kept), kept);
    }
    // Ill-formed: an overlong '/' (C0 AF), a surrogate (ED A0 80), beyond U+10FFFF (F4 90 80 80),
    // E0 80 80 (overlong), a lone continuation byte, a sequence cut by the end, F5 and FF.
    const std::string bad_bytes[] = {"\xC0\xAF", "\xED\xA0\x80", "\xF4\x90\x80\x80", "\xE0\x80\x80", "\x80", "\xE2\x82", "\xF5", "\xFF"};
    for (const std::string& bad : bad_bytes) {
        std::string replaced, escaped;
        for (unsigned char c : bad) {
            replaced += c >= 0x80 ? "\xEF\xBF\xBD" : std::string(1, static_cast<char>(c));
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            escaped += hex;
        }
        EXPECT_EQ(printable("<" + bad + ">"), "<" + replaced + ">") << escaped;
        EXPECT_EQ(printable("<" + bad + ">", Printable::Ascii), "<" + escaped + ">");
    }
    // At most about max_bytes: whole escapes, then "...".
    EXPECT_EQ(printable("abcdef", Printable::Utf8, 4), "abcd...");
    EXPECT_EQ(printable("ab\x01" "cd", Printable::Ascii, 3), "ab\\x01...");
    EXPECT_EQ(printable("abc", Printable::Utf8, 3), "abc");
}
