#pragma once

// A JSON document (io/json_read.hpp) written out with everything a reader can see of it, so that
// two documents are the same when their texts are: kinds, whether kept, sizes, keys, strings,
// each number's double (its bits) and the exact value of its text (test_json_read, the fuzz
// target fuzz_scene_reader).

#include <bit>
#include <cstdint>
#include <string>

#include "io/json_read.hpp"

namespace momentlab::testing {

inline void describe(const json_read::Value& v, std::string& out) {
    out += v.type_name();
    if (!v.kept()) out += "(skipped)";
    if (v.is_object() || v.is_array()) out += "#" + std::to_string(v.size());
    if (v.is_number()) {
        const json_read::JsonNumber n = v.number();
        const std::optional<json_read::Decimal> d = json_read::exact_decimal(n.text);
        out += " " + std::to_string(std::bit_cast<std::uint64_t>(n.value)) + " = ";
        out += d ? (d->negative ? "-" : "") + d->digits + "e" + std::to_string(d->exponent) : "(text \"" + std::string(n.text) + "\")";
    }
    if (v.is_string()) out += " \"" + std::string(v.string()) + "\"";
    if (v.is_array()) {
        out += " [";
        v.for_each_element([&](std::size_t, const json_read::Value& e) {
            describe(e, out);
            out += ", ";
        });
        out += "]";
    }
    if (v.is_object()) {
        out += " {";
        v.for_each_member([&](std::string_view key, const json_read::Value& e) {
            out += std::string(key) + ": ";
            describe(e, out);
            out += ", ";
        });
        out += "}";
    }
}

inline std::string describe(const json_read::Document& doc) {
    std::string out;
    describe(doc.root(), out);
    return out;
}

}  // namespace momentlab::testing
