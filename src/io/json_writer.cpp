#include "momentlab/io/json_writer.hpp"

#include <array>
#include <charconv>
#include <exception>
#include <stdexcept>
#include <nlohmann/json.hpp>

#include "momentlab/io/input_error.hpp"

namespace momentlab {
namespace {

constexpr std::size_t kFlushAt = std::size_t{1} << 20;

}  // namespace

JsonWriter::JsonWriter(std::ostream& out, int indent)
    : out_(out), indent_(indent), exceptions_(std::uncaught_exceptions()) {
    buffer_.reserve(kFlushAt + 4096);
}

JsonWriter::~JsonWriter() {
    // Left by an exception (a value that cannot be written): the part written is not passed on.
    if (std::uncaught_exceptions() > exceptions_) return;
    try {
        flush();
    } catch (...) {  // a destructor does not throw; the stream's state tells
    }
}

void JsonWriter::flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
}

void JsonWriter::newline(std::size_t depth) {
    buffer_.push_back('\n');
    buffer_.append(static_cast<std::size_t>(indent_) + 2 * depth, ' ');
}

void JsonWriter::separate() {
    if (after_key_) {
        after_key_ = false;
        return;
    }
    if (open_.empty()) {  // the top-level value: one only
        if (top_written_) throw std::logic_error("JsonWriter: a second top-level value");
        top_written_ = true;
        return;
    }
    if (open_.back().is_object) throw std::logic_error("JsonWriter: a value in an object needs its key first");
    if (!open_.back().empty) buffer_.push_back(',');
    open_.back().empty = false;
    newline(open_.size());
    if (buffer_.size() >= kFlushAt) flush();
}

void JsonWriter::open(bool is_object) {
    separate();
    buffer_.push_back(is_object ? '{' : '[');
    open_.push_back({is_object, true});
}

void JsonWriter::close(bool is_object) {
    if (open_.empty() || open_.back().is_object != is_object || after_key_) {
        throw std::logic_error(is_object ? "JsonWriter: end_object without its object" : "JsonWriter: end_array without its array");
    }
    const bool was_empty = open_.back().empty;
    open_.pop_back();
    if (!was_empty) newline(open_.size());
    buffer_.push_back(is_object ? '}' : ']');
}

void JsonWriter::begin_object() { open(true); }
void JsonWriter::end_object() { close(true); }
void JsonWriter::begin_array() { open(false); }
void JsonWriter::end_array() { close(false); }

void JsonWriter::key(std::string_view name) {
    if (open_.empty() || !open_.back().is_object || after_key_) throw std::logic_error("JsonWriter: a key outside an object");
    if (!open_.back().empty) buffer_.push_back(',');
    open_.back().empty = false;
    newline(open_.size());
    write_string(name);
    buffer_.append(": ");
    after_key_ = true;
}

void JsonWriter::value(double x) {
    separate();
    std::array<char, 64> digits{};  // as nlohmann's serializer: its Grisu2 to_chars
    char* end = nlohmann::detail::to_chars(digits.data(), digits.data() + digits.size(), output_value(x));
    buffer_.append(digits.data(), static_cast<std::size_t>(end - digits.data()));
}

void JsonWriter::value(long long n) {
    separate();
    std::array<char, 24> digits{};
    const auto [end, ec] = std::to_chars(digits.data(), digits.data() + digits.size(), n);
    buffer_.append(digits.data(), static_cast<std::size_t>(end - digits.data()));
}

void JsonWriter::value(std::string_view s) {
    separate();
    write_string(s);
}

void JsonWriter::write_string(std::string_view s) {
    buffer_.push_back('"');
    for (const char c : s) {
        switch (c) {
            case '"': buffer_.append("\\\""); break;
            case '\\': buffer_.append("\\\\"); break;
            case '\b': buffer_.append("\\b"); break;
            case '\f': buffer_.append("\\f"); break;
            case '\n': buffer_.append("\\n"); break;
            case '\r': buffer_.append("\\r"); break;
            case '\t': buffer_.append("\\t"); break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    constexpr std::string_view kHex = "0123456789abcdef";
                    buffer_.append("\\u00");
                    buffer_.push_back(kHex[static_cast<unsigned char>(c) >> 4]);
                    buffer_.push_back(kHex[static_cast<unsigned char>(c) & 15]);
                } else {
                    buffer_.push_back(c);
                }
        }
    }
    buffer_.push_back('"');
}

void JsonWriter::value(bool b) {
    separate();
    buffer_.append(b ? "true" : "false");
}

void JsonWriter::value(const Vec2& v) {
    begin_array();
    value(v.x());
    value(v.y());
    end_array();
}

void JsonWriter::value(const Vec3& v) {
    begin_array();
    value(v.x());
    value(v.y());
    value(v.z());
    end_array();
}

namespace {

template <class T>
void write_list(JsonWriter& w, const std::vector<T>& vs) {
    w.begin_array();
    for (const T& v : vs) {
        if constexpr (std::is_same_v<T, ExactVector>) {
            w.value(v.value());
        } else {
            w.value(v);
        }
    }
    w.end_array();
}

}  // namespace

// Keys in the order of nlohmann::json's std::map, as to_json (json_output.cpp) makes them.
void write_json(JsonWriter& w, const Cone& cone) {
    w.begin_object();
    w.key("dimension");
    w.value(cone.dimension());
    w.key("equations");
    write_list(w, cone.equations());
    w.key("facet_rays");
    w.begin_array();
    for (std::size_t j = 0; j < cone.facet_rays().size(); ++j) {
        w.begin_array();
        for (const int r : cone.facet_rays().row(j)) w.value(r);
        w.end_array();
    }
    w.end_array();
    w.key("facets");
    write_list(w, cone.facets());
    w.key("kind");
    w.value(cone.kind());
    w.key("lineality");
    write_list(w, cone.lineality());
    w.key("lineality_dimension");
    w.value(cone.lineality_dimension());
    w.key("rays");
    write_list(w, cone.rays());
    w.end_object();
}

void write_json(JsonWriter& w, const Region& region) {
    w.begin_object();
    w.key("kind");
    w.value(region.kind());
    w.key("lines");
    write_list(w, region.lines);
    w.key("rays");
    write_list(w, region.rays);
    w.key("vertices");
    write_list(w, region.vertices);
    w.end_object();
}

void write_json(JsonWriter& w, const Labels& labels) {
    w.begin_object();
    w.key("minus");
    write_json(w, labels.minus());
    w.key("plus");
    write_json(w, labels.plus());
    w.end_object();
}

}  // namespace momentlab
