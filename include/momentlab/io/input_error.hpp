#pragma once

/// \file
/// The error for bad user input read from JSON.

#include <stdexcept>
#include <string>
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

/// Warnings about input that is accepted but probably not meant (e.g. an unknown field, which
/// is ignored), each "path: message".
using InputWarnings = std::vector<std::string>;

/// The accepted magnitudes of numbers in input files: 0, or between these.
inline constexpr double kSmallestMagnitude = 1e-60;
inline constexpr double kLargestMagnitude = 1e60;

/// True for an accepted magnitude (of a number, or of a vector's largest coordinate): 0, or
/// between kSmallestMagnitude and kLargestMagnitude. False for NaN and infinity.
inline bool magnitude_in_range(double m) {
    return m == 0.0 || (m >= kSmallestMagnitude && m <= kLargestMagnitude);
}

}  // namespace momentlab
