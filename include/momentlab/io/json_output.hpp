#pragma once

/// \file
/// JSON views of cones and labels (the machine-readable output of the CLI).

#include <string>

#include <nlohmann/json.hpp>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/geometry/labels.hpp"
#include "momentlab/mechanics/closure.hpp"
#include "momentlab/planning/comply.hpp"
#include "momentlab/planning/push.hpp"

namespace momentlab {

/// [x, y, z] and [x, y]: a vector, rounded (UnrepresentableError beyond the doubles, as below).
[[nodiscard]] nlohmann::json vector_json(const Vec3& v);
[[nodiscard]] nlohmann::json vector_json(const Vec2& v);

/// {"kind", "dimension", "lineality_dimension", "rays", "lineality", "facets", "equations",
///  "facet_rays"}; vectors as [x, y, z] (rounded values). Every function here throws
/// UnrepresentableError for a value beyond the range of a double (never writes null).
[[nodiscard]] nlohmann::json to_json(const Cone& cone);

/// {"kind", "vertices", "rays", "lines"} of one sheet.
[[nodiscard]] nlohmann::json to_json(const Region& region);

/// {"plus": region, "minus": region}.
[[nodiscard]] nlohmann::json to_json(const Labels& labels);

/// {"intervals": [[from, to], ...], "best", "margin"} (best and margin only when feasible):
/// the answer of `plan tilt` and of one compliance centre, radians from +x; told the modes also
/// "unique", "shared" (intervals) and "best_unique"; "best_margins" with a metric (not on a knife edge);
/// "best_magnitudes" (a range or null) with a fixed wrench.
[[nodiscard]] nlohmann::json to_json(const DirectionPlan& plan);
/// {"feature", "from", "to", "slip", "verdict", "feasible", "blocked", "touch", "directions",
///  "best": {"point", "direction"}} of one pushing case (docs/formats.md, Planning); told the
///  modes also "unique", "shared", "best_unique"; "best_margins", "best_magnitudes" as above.
[[nodiscard]] nlohmann::json to_json(const PushCase& push_case);
/// The directions of one compliance centre with its "point", "label" and "verdict".
[[nodiscard]] nlohmann::json to_json(const ComplyPlan& plan);
/// {"form_closure", "force_closure", "form": {"holds", "quality" | "unresisted_wrench"}, "force":
///  {...}, "reference", "length", "metric"} (docs/formats.md, Closure).
[[nodiscard]] nlohmann::json to_json(const Closure& closure);

/// {"from": lo, "to": hi or "unbounded"}: magnitudes of a controlled force; "from_exact" and
/// "to_exact" give an end's exact value as text ("2943/1000") when it is not the double printed.
[[nodiscard]] nlohmann::json to_json(const MagnitudeRange& range);
/// {"inside": [d, ...], "to_other": d}: distances, "unbounded" for infinite ones (or no other set).
[[nodiscard]] nlohmann::json to_json(const QueryMargins& margins);
/// [{"from", "to", "from_closed", "to_closed", "modes": [letters], "verdict"}, ...]: the bands of
/// magnitude_bands, "to" "unbounded" for the last; an end that is not a double also as
/// "from_exact" / "to_exact", its exact value in lowest terms ("2943/1000": docs/formats.md).
[[nodiscard]] nlohmann::json to_json(const std::vector<MagnitudeBand>& bands, std::span<const ModeForces> analysis);
/// The exact quotient num / den in lowest terms: "2943/1000", "-2/3", "5" (den != 0).
[[nodiscard]] std::string exact_text(const Dyadic& num, const Dyadic& den);
/// Beside an input echoed as doubles (`out[key]`, a number or a list), the values it was read
/// as when one is not a double: `out[key + "_exact"]` = its exact_texts ("mu_exact": "1/10",
/// "point_exact": ["31/40", "3/4"]; docs/formats.md). Nothing when every value is a double.
void add_exact(nlohmann::json& out, const std::string& key, std::span<const Rational> values);

}  // namespace momentlab
