#pragma once

/// \file
/// Reading force sets from JSON (the input of `momentlab label`).
///
/// A file is either a list of sets, combined by sum, or an object
/// `{"combine": "sum" | "intersection", "sets": [...]}`. Each set is an object with a "type":
///   {"type": "force",         "point": [x, y], "direction": [fx, fy]}   (Figure 1a)
///   {"type": "line",          "point": [x, y], "direction": [dx, dy]}   (both senses)
///   {"type": "point",         "point": [x, y]}                          (Figure 1b)
///   {"type": "friction_cone", "point": [x, y], "normal": [nx, ny], "mu": m}  (Figure 1c)
///   {"type": "moment",        "sign": 1 | -1 | 0}                       (0: both senses)
///   {"type": "wrenches",      "generators": [[fx, fy, tau], ...]}
///   {"type": "halfspaces",    "normals": [[a, b, c], ...]}              ({w : n . w >= 0})
///   {"type": "sum" | "intersection", "sets": [...]}                     (nesting)

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/io/input_error.hpp"

namespace momentlab {

/// The force set described by `doc`. Throws InputError naming the field on bad input (numbers
/// finite, 0 or of magnitude 1e-60 .. 1e60; docs/reliability.md). Unknown fields are ignored
/// with a warning in `warnings`, when given.
[[nodiscard]] Cone read_force_set(const nlohmann::json& doc, InputWarnings* warnings = nullptr);

/// A force-set file with its top-level sets kept apart (for pictures of the combination).
struct ForceSetFile {
    std::vector<Cone> parts;  ///< the top-level sets, in file order
    bool intersect = false;   ///< combined by intersection (else by sum)
    Cone result;              ///< their sum or intersection
};

/// The file `doc` as its parts and their combination; errors as read_force_set.
[[nodiscard]] ForceSetFile read_force_set_parts(const nlohmann::json& doc, InputWarnings* warnings = nullptr);

/// Parses `text` as JSON and reads it as a ForceSetFile.
[[nodiscard]] ForceSetFile read_force_set_parts_text(const std::string& text, InputWarnings* warnings = nullptr);

/// Parses `text` as JSON and reads the force set; malformed JSON is an InputError at "$".
[[nodiscard]] Cone read_force_set_text(const std::string& text, InputWarnings* warnings = nullptr);

}  // namespace momentlab
