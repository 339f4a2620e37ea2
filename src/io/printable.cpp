// Text as it can be shown (io/printable.hpp).
#include "momentlab/io/printable.hpp"

#include <cstdint>
#include <cstdio>

namespace momentlab {
namespace {

// The length of the well-formed UTF-8 sequence that starts at p[i] (0 when there is none): no
// overlong forms, no surrogates, nothing above U+10FFFF (the Unicode standard, table 3-7).
std::size_t utf8_length(const unsigned char* p, std::size_t i, std::size_t n) {
    const unsigned char c = p[i];
    std::size_t len = 0;
    unsigned char lo = 0x80, hi = 0xBF;  // the range of the second byte
    if (c >= 0xC2 && c <= 0xDF) len = 2;
    else if (c == 0xE0) len = 3, lo = 0xA0;
    else if (c >= 0xE1 && c <= 0xEC) len = 3;
    else if (c == 0xED) len = 3, hi = 0x9F;
    else if (c >= 0xEE && c <= 0xEF) len = 3;
    else if (c == 0xF0) len = 4, lo = 0x90;
    else if (c >= 0xF1 && c <= 0xF3) len = 4;
    else if (c == 0xF4) len = 4, hi = 0x8F;
    if (len == 0 || i + len > n || p[i + 1] < lo || p[i + 1] > hi) return 0;
    for (std::size_t k = 2; k < len; ++k) {
        if (p[i + k] < 0x80 || p[i + k] > 0xBF) return 0;
    }
    return len;
}

// U+FDD0..U+FDEF and the last two code points of every plane (U+FFFE, U+FFFF, U+1FFFE, ...):
// well-formed, but neither XML 1.0 nor Cairo takes U+FFFE and U+FFFF, and no text means them.
bool noncharacter(const unsigned char* s, std::size_t len) {
    std::uint32_t cp = len == 2 ? s[0] & 0x1Fu : len == 3 ? s[0] & 0x0Fu : s[0] & 0x07u;
    for (std::size_t k = 1; k < len; ++k) cp = (cp << 6) | (s[k] & 0x3Fu);
    return (cp >= 0xFDD0 && cp <= 0xFDEF) || (cp & 0xFFFEu) == 0xFFFEu;
}

void append_escape(std::string& out, unsigned char c) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02x", c);
    out += hex;
}

}  // namespace

std::string printable(std::string_view text, Printable how, std::size_t max_bytes) {
    std::string out;
    const auto* p = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t n = text.size();
    for (std::size_t i = 0; i < n;) {
        if (out.size() >= max_bytes) {
            out += "...";
            break;
        }
        const unsigned char c = p[i];
        if (c >= 0x20 && c < 0x7F) {
            out += static_cast<char>(c);
            ++i;
        } else if (c == '\n' || c == '\t' || c == '\r') {
            out += c == '\n' ? "\\n" : (c == '\t' ? "\\t" : "\\r");
            ++i;
        } else if (c < 0x80 || how == Printable::Ascii) {
            append_escape(out, c);
            ++i;
        } else if (const std::size_t len = utf8_length(p, i, n); len > 0) {
            if (noncharacter(p + i, len)) {
                out += "\xEF\xBF\xBD";  // (one for the character)
            } else {
                out.append(text.substr(i, len));
            }
            i += len;
        } else {
            out += "\xEF\xBF\xBD";
            ++i;
        }
    }
    return out;
}

}  // namespace momentlab
