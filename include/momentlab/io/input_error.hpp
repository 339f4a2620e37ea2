#pragma once

/// \file
/// The error for bad user input read from JSON.

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace momentlab {

/// Bad user input, with the JSON path of the offending field (e.g. "$.contacts[2].mu").
class InputError : public std::invalid_argument {
public:
    InputError(const std::string& path, const std::string& message)
        : std::invalid_argument(path + ": " + message), path_(path) {}
    [[nodiscard]] const std::string& path() const { return path_; }

private:
    std::string path_;
};

/// A value of an answer that cannot be written as a double (a coordinate beyond 1e308, such as
/// the vertex of a labelled region where two nearly parallel lines meet far away): the input is
/// accepted, the answer exists exactly, but it cannot be printed.
class UnrepresentableError : public std::range_error {
public:
    explicit UnrepresentableError(const std::string& what) : std::range_error(what) {}
};

/// A coordinate of an answer as it is written out (JSON or text): -0 as 0; a value beyond the
/// range of a double is an UnrepresentableError, never "inf", "nan" or null.
[[nodiscard]] inline double output_value(double x) {
    if (!std::isfinite(x)) {
        throw UnrepresentableError("a coordinate of the answer is beyond the range of a double (the scene's numbers are "
                                   "too far apart to write it; the answer itself is exact)");
    }
    return x == 0.0 ? 0.0 : x;
}

/// Warnings about input that is accepted but probably not meant (e.g. an unknown field, which
/// is ignored), each "path: message".
using InputWarnings = std::vector<std::string>;

/// What a number that is not 0 but reads as 0.0 (1e-400) is told, in every front end. No range
/// of magnitudes: a vector's coordinate may be tiny where its largest is in range, and each field
/// checks its own.
inline constexpr std::string_view kTooSmallForADouble = "too small for a double: it would be taken as 0";

/// The accepted magnitudes of numbers in input files: 0, or between these.
inline constexpr double kSmallestMagnitude = 1e-60;
inline constexpr double kLargestMagnitude = 1e60;
/// The accepted magnitudes as every message about them says them (written only here).
inline constexpr std::string_view kMagnitudeRange = "0 or of magnitude 1e-60 .. 1e60";
/// The non-zero magnitudes alone (kMagnitudeRange without its "0 or of magnitude "), for a
/// quantity that must not be 0.
inline constexpr std::string_view kMagnitudeBounds = kMagnitudeRange.substr(kMagnitudeRange.find("1e"));

/// True for an accepted magnitude (of a number, or of a vector's largest coordinate): 0, or
/// between kSmallestMagnitude and kLargestMagnitude. False for NaN and infinity.
inline bool magnitude_in_range(double m) {
    return m == 0.0 || (m >= kSmallestMagnitude && m <= kLargestMagnitude);
}

/// True when the text of a number (decimal, or hexadecimal 0x..p..) has a non-zero digit
/// before its exponent: a number that reads as 0.0 although it is not zero (1e-400, 0x1p-2000)
/// has underflowed, and is refused rather than taken as 0.
[[nodiscard]] bool nonzero_digits(std::string_view number);

/// The first number of a JSON text that underflows (reads as 0.0 though it is not zero), if
/// any. read_scene_text and the force-set readers refuse such numbers with their JSON path.
[[nodiscard]] std::optional<std::string> underflowing_number(std::string_view json_text);

}  // namespace momentlab
