// The checks analyze, query_scene, query_once and enumerate_modes make of their input, in one
// place so that every path throws the same errors (internal to the mechanics layer).
#pragma once

#include <optional>
#include <vector>

#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab::detail {

/// Throws std::invalid_argument ("<who>: ...") unless the scene has a body with a finite com,
/// 0 < mass < inf and 0 < inertia < inf (or radius of gyration).
void check_body(const Scene& scene, const char* who);

/// The inertia at the origin, or none when quasi-static (checks the body as check_body does).
[[nodiscard]] std::optional<ExactMatrix> inertia_of(const Scene& scene, const AnalysisOptions& options, const char* who);

/// Throws std::invalid_argument unless every contact has a finite point, a finite non-zero normal
/// and finite mu, mu_kinetic >= 0 (as Contact::make would).
void check_contacts(const std::vector<Contact>& contacts);

}  // namespace momentlab::detail
