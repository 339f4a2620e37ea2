#pragma once

/// \file
/// A fixed wrench plus a controlled one (docs/planning.md, "A fixed wrench plus a push"): gravity
/// through the centre of mass (or any known wrench) g acts whatever the controller does, and the
/// controller adds a wrench lambda u of its own choosing (a push, a spring, a tilt). The applied
/// wrenches g + lambda u form an affine set, not a cone, so the magnitude matters: the goal's mode
/// appears for the magnitudes lambda >= 0 with g + lambda u in E_goal, a closed interval because
/// E_goal is convex. The directions u for which some positive magnitude works form the closed cone
/// E_goal + cone(-g), so the cone planners (tilt, push, comply) answer the direction question on
/// it unchanged. Every decision is exact: g is the exact product of the input doubles, and a
/// magnitude is an exact ratio of two Dyadic numbers (-h.g / h.u for a facet h of E_goal).

#include <cstddef>
#include <optional>
#include <vector>

#include "momentlab/core/exact.hpp"
#include "momentlab/geometry/cone.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// The wrench of gravity (an acceleration) on the body: m (a, com x a), exactly. Throws
/// std::invalid_argument for a non-finite acceleration.
[[nodiscard]] Exact3 gravity_wrench(const Body& body, const Vec2& acceleration);

/// A magnitude lambda >= 0, exactly num / den with den > 0.
struct Magnitude {
    Dyadic num;
    Dyadic den = Dyadic(1.0);
    /// The ratio correctly rounded to a double (nearest_double, core/rounding.hpp).
    [[nodiscard]] double value() const;
    /// A magnitude found for cleared wrenches, scaled back: with the push's wrench times
    /// push_scale and the fixed wrench times fixed_scale (both > 0), fixed_scale g + l push_scale u
    /// is fixed_scale (g + lambda u) for lambda = l push_scale / fixed_scale. Exact.
    [[nodiscard]] Magnitude scaled_back(const Dyadic& push_scale, const Dyadic& fixed_scale) const {
        return {num * push_scale, den * fixed_scale};
    }
};

/// -1, 0 or +1 as a < b, a == b, a > b (exact).
[[nodiscard]] int compare(const Magnitude& a, const Magnitude& b);

/// The magnitudes lambda >= 0 for which fixed + lambda u lies in a closed cone: from `lo` to `hi`
/// (no `hi`: unbounded), both ends included; lo == hi is one magnitude.
struct MagnitudeRange {
    Magnitude lo;
    std::optional<Magnitude> hi;
};

/// The magnitudes lambda >= 0 with fixed + lambda u in c, or none. Exact.
[[nodiscard]] std::optional<MagnitudeRange> magnitudes(const Cone& c, const Exact3& fixed, const Exact3& u);

/// The directions u for which some lambda > 0 puts fixed + lambda u in c, with their limits: the
/// closed cone c + cone(-fixed) (every direction when fixed is inside c). Its interior (for a full-dimensional c) holds exactly the u for
/// which some lambda > 0 puts fixed + lambda u in the interior of c. Exact.
[[nodiscard]] Cone reachable_directions(const Cone& c, const Exact3& fixed);

/// A stretch of magnitudes and the modes whose E holds fixed + lambda u for every lambda in it.
struct MagnitudeBand {
    Magnitude from;
    std::optional<Magnitude> to;  ///< none: unbounded
    bool from_closed = true;      ///< the end magnitude itself belongs to the band
    bool to_closed = true;
    std::vector<std::size_t> modes;  ///< indices into the analysis, increasing
};

/// The line of pushes fixed + lambda u, lambda from 0 upwards, cut where the set of modes that
/// hold it changes: every magnitude lies in exactly one band, and the modes of a band are exactly
/// query's answer at each of its magnitudes. O(m f log(m f)) for m modes of at most f facets each.
[[nodiscard]] std::vector<MagnitudeBand> magnitude_bands(const std::vector<ModeForces>& analysis, const Exact3& fixed,
                                                         const Exact3& u);

}  // namespace momentlab
