#pragma once

// The bundled scene files (examples/), read as the tests' inputs. Needs MOMENTLAB_EXAMPLES.

#include <fstream>
#include <sstream>
#include <string>

#include "momentlab/io/scene_json.hpp"

namespace momentlab::testing {

/// The scene in examples/<name>.
inline Scene example_scene(const std::string& name) {
    std::ifstream in(std::string(MOMENTLAB_EXAMPLES) + "/" + name);
    std::ostringstream s;
    s << in.rdbuf();
    return read_scene_text(s.str());
}

}  // namespace momentlab::testing
