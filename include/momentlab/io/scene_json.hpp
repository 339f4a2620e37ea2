#pragma once

/// \file
/// Scene files (docs/formats.md):
/// {"body": {"mass", "com", "inertia" | "radius_of_gyration", "polygon"},
///  "contacts": [{"point", "normal", "mu", "mu_kinetic", "name"}], "obstacles": [{"polygon"}]}.

#include <nlohmann/json.hpp>
#include <string>

#include "momentlab/io/input_error.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// The scene described by `doc`. Throws InputError naming the field on bad input
/// (docs/reliability.md lists the checks): numbers must be finite, 0 or of magnitude 1e-60 ..
/// 1e60; polygons simple (either orientation); given contacts on the body polygon's boundary
/// within "contact_distance" (default 1e-9); at least one contact. Without "contacts", they are
/// found from the body polygon and the obstacles (find_contacts), with the optional top-level
/// "contact_distance" and "mu" (default 0). Unknown fields are ignored with a warning in
/// `warnings`, when given.
[[nodiscard]] Scene read_scene(const nlohmann::json& doc, InputWarnings* warnings = nullptr);

/// The scene as JSON, in the same format (contacts always written out, mu_kinetic included),
/// so that read_scene gives back the same scene: normals as given, and the radius of gyration
/// instead of the inertia when the scene was given one. Numbers are written as doubles: the
/// text they dump to reads back as the same exact values for decimals of up to 15 significant
/// digits (shortest round-trip); a double that is not such a decimal reads back as the decimal
/// nearest it, unless read from the JSON value itself (read_scene, binary values).
[[nodiscard]] nlohmann::json to_json(const Scene& scene);

/// The analysis of a scene a user gave, with the message the CLI, Python and the web module all
/// give when the dynamic model lacks the body: an InputError at "$" naming `command`, what needs
/// the body's mass, com and inertia.
[[nodiscard]] std::vector<ModeForces> analyze_input(const Scene& scene, const std::string& command,
                                                    const AnalysisOptions& options = {});

/// The check analyze_input makes: an InputError at "$" naming `command` when the dynamic model
/// lacks the body.
void require_body(const Scene& scene, const std::string& command, const AnalysisOptions& options = {});

/// The mode a user named by its letters; an unknown mode is an InputError at `where` that lists
/// the scene's modes.
[[nodiscard]] const ModeForces& find_mode(const std::vector<ModeForces>& analysis, const std::string& letters,
                                          const std::string& where);

/// Parses `text` as JSON and reads the scene.
[[nodiscard]] Scene read_scene_text(const std::string& text, InputWarnings* warnings = nullptr);

}  // namespace momentlab
