#pragma once

/// \file
/// The error for bad user input read from JSON.

#include <stdexcept>
#include <string>

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

}  // namespace momentlab
