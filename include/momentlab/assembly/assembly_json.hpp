#pragma once

/// \file
/// Assemblies in scene files and the answers of `momentlab stand` as JSON (docs/formats.md,
/// docs/assemblies.md). The multi-body format:
/// {"bodies": [{"name"?, "mass", "com", "inertia"? | "radius_of_gyration"?, "polygon"?}, ...],
///  "contacts"?: [{"bodies": [a, b], "point", "normal", "mu"?, "mu_kinetic"?, "name"?}, ...],
///  "obstacles"?: [{"polygon"}], "contact_distance"?, "mu"?}
/// (bodies 1..N in order, 0 the world; the normal into a). Without "contacts" they are found
/// from the polygons (find_assembly_contacts), with the top-level "mu". A document with "body"
/// is the single-body format (read_scene): the assembly with N = 1.

#include <nlohmann/json.hpp>
#include <string>

#include "momentlab/assembly/stand.hpp"
#include "momentlab/io/input_error.hpp"

namespace momentlab {

/// The assembly of a scene document, checked (check_assembly). Throws InputError naming the
/// field by its JSON path; unknown fields are ignored with a warning in `warnings`.
[[nodiscard]] Assembly read_assembly(const nlohmann::json& doc, InputWarnings* warnings = nullptr);

/// Parses `text` (malformed JSON and numbers that underflow are InputErrors at "$") and reads it.
[[nodiscard]] Assembly read_assembly_text(const std::string& text, InputWarnings* warnings = nullptr);

/// The answer of `momentlab stand --json`: {"can_stand", "forces" | "mechanism", "modes",
/// "modes_reason"?, "verdict", "motions", "outcome", "tilt"?} (docs/formats.md).
[[nodiscard]] nlohmann::json to_json(const StandResult& result);

/// The tilt cone as {"kind", "directions": [[x, y], ...]}, each coordinate a number when the
/// rounded value is exact, else its exact text "p/q".
[[nodiscard]] nlohmann::json to_json(const TiltCone& tilt);

}  // namespace momentlab
