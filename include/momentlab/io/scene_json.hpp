#pragma once

/// \file
/// Scene files (DESIGN, "Interfaces"):
/// {"body": {"mass", "com", "inertia" | "radius_of_gyration", "polygon"},
///  "contacts": [{"point", "normal", "mu", "mu_kinetic", "name"}], "obstacles": [{"polygon"}]}.

#include <nlohmann/json.hpp>
#include <string>

#include "momentlab/io/input_error.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// The scene described by `doc`. Throws InputError naming the field on bad input. Without
/// "contacts", they are found from the body polygon and the obstacles (find_contacts), with
/// the optional top-level "contact_distance" (default 1e-9) and "mu" (default 0).
[[nodiscard]] Scene read_scene(const nlohmann::json& doc);

/// The scene as JSON, in the same format (contacts always written out, mu_kinetic included).
[[nodiscard]] nlohmann::json to_json(const Scene& scene);

/// Parses `text` as JSON and reads the scene.
[[nodiscard]] Scene read_scene_text(const std::string& text);

}  // namespace momentlab
