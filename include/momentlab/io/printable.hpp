#pragma once

/// \file
/// Text from users' files and options, and from libraries' messages, as it can be shown: one
/// rule for the CLI's messages, the JSON reader's errors and the pictures' titles and labels.

#include <cstddef>
#include <string>
#include <string_view>

namespace momentlab {

/// What `printable` keeps of the bytes beyond ASCII.
enum class Printable {
    Utf8,   ///< well-formed UTF-8 kept but noncharacters (U+FFFE ...); any other byte, and those, as U+FFFD (Cairo and XML take the result)
    Ascii,  ///< every byte beyond ASCII as \xNN (a message that must be one line of ASCII)
};

/// `text` as one line that a terminal, Python, an SVG file or a font can show: a newline, tab and
/// carriage return as \n, \t and \r, every other control byte and DEL as \xNN (XML 1.0 cannot hold
/// them, a font has no glyph for them), the bytes beyond ASCII as `how` says; at most about
/// `max_bytes` of the result (whole escapes), then "...".
[[nodiscard]] std::string printable(std::string_view text, Printable how = Printable::Utf8,
                                    std::size_t max_bytes = std::string::npos);

}  // namespace momentlab
