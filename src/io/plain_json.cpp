// The plain reader: the JSON that programs write, read in one pass (docs/architecture.md,
// "The JSON reader"); anything else goes to the JSON library (json_read.cpp).
#include "json_read.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <vector>

namespace momentlab::json_read {

namespace {

// A reader of the plain JSON that programs write: ASCII strings without escapes and numbers
// that convert to finite doubles. It reads such a text in one pass over its characters with no
// copies (the library reads a character at a time through its input adapter and copies each
// token: bench/bench_io.cpp), and gives up on anything else, which the library then reads.
class PlainReader {
public:
    PlainReader(std::string_view text, Builder& b) : p_(text.data()), end_(text.data() + text.size()), b_(b) {}

    // Reads the text to the builder; false when the text is not plain JSON.
    bool document() {
        std::vector<bool> arrays;  // the open containers, innermost last: true for an array
        for (;;) {
            skip_space();
            if (p_ == end_) return false;
            if (*p_ == '{' || *p_ == '[') {
                const bool array = *p_++ == '[';
                array ? b_.start_array() : b_.start_object();
                if (next_is(array ? ']' : '}')) {
                    array ? b_.end_array() : b_.end_object();
                } else {
                    arrays.push_back(array);
                    if (!array && !member_key()) return false;
                    continue;  // its first value
                }
            } else if (!scalar()) {
                return false;
            }
            // After a value: a comma and the next value, or the ends of containers.
            for (;;) {
                skip_space();
                if (arrays.empty()) return p_ == end_;
                if (p_ == end_) return false;
                const bool array = arrays.back();
                if (*p_ == ',') {
                    ++p_;
                    if (!array && !member_key()) return false;
                    break;
                }
                if (*p_++ != (array ? ']' : '}')) return false;
                arrays.pop_back();
                array ? b_.end_array() : b_.end_object();
            }
        }
    }

private:
    static bool digit(char c) { return c >= '0' && c <= '9'; }

    void skip_space() {
        while (p_ != end_ && (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t')) ++p_;
    }

    // Whether the text continues with c (after white space); consumes it if so.
    bool next_is(char c) {
        skip_space();
        if (p_ == end_ || *p_ != c) return false;
        ++p_;
        return true;
    }

    // A member's key, then its colon (the key is an event before the colon is read, as the
    // library has it, so that both report a repeated key at the same place).
    bool member_key() {
        skip_space();
        std::string_view key;
        if (p_ == end_ || *p_ != '"' || !string(key)) return false;
        b_.key(key, Builder::Text::Lasting);
        return next_is(':');
    }

    bool scalar() {
        switch (*p_) {
            case '"': {
                std::string_view s;
                if (!string(s)) return false;
                b_.string(s, Builder::Text::Lasting);
                return true;
            }
            case 't': return literal("true") && (b_.boolean(true), true);
            case 'f': return literal("false") && (b_.boolean(false), true);
            case 'n': return literal("null") && (b_.null(), true);
            default: return number();
        }
    }

    // ASCII from the space to DEL between quotes, with no escape.
    bool string(std::string_view& out) {
        const char* start = ++p_;
        for (; p_ != end_; ++p_) {
            const auto c = static_cast<unsigned char>(*p_);
            if (c == '"') {
                out = std::string_view(start, static_cast<std::size_t>(p_++ - start));
                return true;
            }
            if (c < 0x20 || c == '\\' || c >= 0x80) return false;
        }
        return false;
    }

    bool literal(std::string_view word) {
        if (static_cast<std::size_t>(end_ - p_) < word.size() || std::string_view(p_, word.size()) != word) return false;
        p_ += word.size();
        return true;
    }

    // JSON's number grammar, and its value as the library gives it: an integer's (+0 for "-0"),
    // or the nearest double.
    bool number() {
        const char* const start = p_;
        const char* q = p_;
        const bool negative = *q == '-';
        if (negative) ++q;
        if (q == end_ || !digit(*q)) return false;
        if (*q == '0') {
            ++q;
        } else {
            while (q != end_ && digit(*q)) ++q;
        }
        const char* const integer_end = q;
        if (q != end_ && *q == '.') {
            const char* const digits = ++q;
            while (q != end_ && digit(*q)) ++q;
            if (q == digits) return false;
        }
        if (q != end_ && (*q == 'e' || *q == 'E')) {
            ++q;
            if (q != end_ && (*q == '+' || *q == '-')) ++q;
            const char* const digits = q;
            while (q != end_ && digit(*q)) ++q;
            if (q == digits) return false;
        }
        p_ = q;
        const std::string_view text(start, static_cast<std::size_t>(q - start));
        double x = 0.0;
        if (q == integer_end && integer_end - start <= 19) {  // up to 18 digits: exact in 64 bits
            std::uint64_t v = 0;
            for (const char* d = start + (negative ? 1 : 0); d != integer_end; ++d) v = v * 10 + static_cast<std::uint64_t>(*d - '0');
            x = negative ? static_cast<double>(-static_cast<std::int64_t>(v)) : static_cast<double>(v);
        } else {
#if defined(__cpp_lib_to_chars)
            const auto [end, error] = std::from_chars(start, q, x);
            if (error != std::errc() || end != q || !std::isfinite(x)) return false;
#else
            return false;  // no exact conversion without a locale: the library reads the text
#endif
        }
        b_.number(x, text, Builder::Text::Lasting);
        return true;
    }

    const char* p_;
    const char* end_;
    Builder& b_;
};

}  // namespace

std::optional<Document> read_plain(std::string_view text, const Schema& schema) {
    Builder b(schema, text);
    if (!PlainReader(text, b).document()) return std::nullopt;
    return b.finish();
}

}  // namespace momentlab::json_read
