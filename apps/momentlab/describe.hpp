#pragma once

// Contact modes and labelled regions in words, shared by the commands that print them.

#include <iomanip>
#include <sstream>
#include <string>

#include "momentlab/geometry/labels.hpp"
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

/// "polygon (0, 1) (2, 3) ...": a labelled region's kind and vertices, 6 digits.
inline std::string region_text(const Region& r) {
    std::ostringstream s;
    s << std::setprecision(6) << r.kind();
    for (const Vec2& v : r.vertices) s << " (" << v.x() + 0.0 << ", " << v.y() + 0.0 << ")";  // no -0
    return s.str();
}

}  // namespace momentlab::cli
