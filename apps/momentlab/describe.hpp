#pragma once

// Contact modes in words, shared by the commands that print them.

#include <string>

#include "momentlab/mechanics/scene.hpp"

namespace momentlab::cli {

/// "contact 2 slides along +t, floor separates, ..." for the letters of a mode.
inline std::string describe_mode(const Scene& scene, const std::string& letters) {
    std::string out;
    for (std::size_t j = 0; j < letters.size(); ++j) {
        const std::string& name = scene.contacts[j].name;
        const char* what = letters[j] == 's'   ? "separates"
                           : letters[j] == 'f' ? "fixed"
                           : letters[j] == 'r' ? "slides along +t"
                                               : "slides along -t";
        out += (j ? ", " : "") + (name.empty() ? "contact " + std::to_string(j + 1) : name) + " " + what;
    }
    return out;
}

}  // namespace momentlab::cli
