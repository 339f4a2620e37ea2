#pragma once

/// \file
/// Writing JSON as a stream, for answers too big to hold as a document (`analyze --json` on
/// 10^5 contacts writes hundreds of megabytes). The text is the one nlohmann::json's dump(2)
/// writes for the same document (tests/io/test_json_writer.cpp compares them).

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/geometry/labels.hpp"

namespace momentlab {

/// Writes one JSON value to `out`, indented by two spaces per level as dump(2) indents it.
/// Objects' keys are written in the order given: give them sorted, as a document would hold
/// them. Buffered: the text reaches `out` in pieces of about a megabyte and at flush() and
/// destruction (not when an exception is leaving: a value that cannot be written stops the text
/// where it is, and less than a megabyte of it is not passed on). Misuse (a key outside an
/// object, a value without its key, an end without its begin, two top-level values) throws
/// std::logic_error.
class JsonWriter {
public:
    /// Every line after the first starts with `indent` spaces (for a value inside a document
    /// written around it).
    explicit JsonWriter(std::ostream& out, int indent = 0);
    ~JsonWriter();
    JsonWriter(const JsonWriter&) = delete;
    JsonWriter& operator=(const JsonWriter&) = delete;

    void begin_object();
    void end_object();
    void begin_array();
    void end_array();
    /// The key of the next value, in an object.
    void key(std::string_view name);
    /// A number as dump() writes it (shortest round-trip form, "1.0" for one); -0 as 0 and
    /// UnrepresentableError where it is not finite (input_error.hpp, output_value).
    void value(double x);
    void value(long long n);
    void value(int n) { value(static_cast<long long>(n)); }
    void value(std::string_view s);
    void value(const char* s) { value(std::string_view(s)); }
    void value(bool b);
    /// [x, y] and [x, y, z] (rounded values).
    void value(const Vec2& v);
    void value(const Vec3& v);
    /// Passes the text written so far on to the stream.
    void flush();

private:
    struct Level {
        bool is_object;
        bool empty;  // nothing written in it yet
    };
    void separate();  // before a value: the comma and new line of its container
    void newline(std::size_t depth);
    void open(bool is_object);
    void close(bool is_object);  // the end of the innermost container
    void write_string(std::string_view s);

    std::ostream& out_;
    std::string buffer_;
    int indent_;
    int exceptions_;  // std::uncaught_exceptions() when made: the destructor flushes only when no new one is in flight
    std::vector<Level> open_;
    bool after_key_ = false;
    bool top_written_ = false;
};

/// The documents of json_output.hpp (to_json of a Cone, Region or Labels), written to `w`.
void write_json(JsonWriter& w, const Cone& cone);
void write_json(JsonWriter& w, const Region& region);
void write_json(JsonWriter& w, const Labels& labels);

}  // namespace momentlab
