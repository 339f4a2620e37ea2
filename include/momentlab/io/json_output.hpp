#pragma once

/// \file
/// JSON views of cones and labels (the machine-readable output of the CLI).

#include <nlohmann/json.hpp>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/geometry/labels.hpp"

namespace momentlab {

/// {"kind", "dimension", "lineality_dimension", "rays", "lineality", "facets", "equations",
///  "facet_rays"}; vectors as [x, y, z] (rounded values). Every function here throws
/// UnrepresentableError for a value beyond the range of a double (never writes null).
[[nodiscard]] nlohmann::json to_json(const Cone& cone);

/// {"kind", "vertices", "rays", "lines"} of one sheet.
[[nodiscard]] nlohmann::json to_json(const Region& region);

/// {"plus": region, "minus": region}.
[[nodiscard]] nlohmann::json to_json(const Labels& labels);

}  // namespace momentlab
