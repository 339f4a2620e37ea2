// A fixed wrench plus a controlled one (planning/fixed_wrench.hpp).
#include "momentlab/planning/fixed_wrench.hpp"

#include "momentlab/core/rounding.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace momentlab {

Exact3 gravity_wrench(const Body& body, const Vec2& acceleration) {
    if (!acceleration.allFinite()) throw std::invalid_argument("gravity_wrench: the acceleration must be finite");
    const Dyadic m(body.mass);
    const Exact2 a = exact(acceleration);
    return wrench_through(exact(body.com), Exact2{m * a[0], m * a[1]});
}

double Magnitude::value() const { return nearest_double(num, den); }

int compare(const Magnitude& a, const Magnitude& b) { return compare(a.num * b.den, b.num * a.den); }

std::optional<MagnitudeRange> magnitudes(const Cone& c, const Exact3& fixed, const Exact3& u) {
    MagnitudeRange r{Magnitude{Dyadic(0.0), Dyadic(1.0)}, std::nullopt};
    const auto at_least = [&](Magnitude m) {
        if (compare(m, r.lo) > 0) r.lo = std::move(m);
    };
    const auto at_most = [&](Magnitude m) {
        if (!r.hi || compare(m, *r.hi) < 0) r.hi = std::move(m);
    };
    // h . (fixed + lambda u) >= 0 for every facet h, = 0 for every equation.
    for (const ExactVector& f : c.facets()) {
        const Exact3 h = f.exact();
        Dyadic hg = dot(h, fixed), hu = dot(h, u);
        switch (hu.sign()) {
            case Sign::Positive: at_least({-hg, std::move(hu)}); break;
            case Sign::Negative: at_most({std::move(hg), -hu}); break;
            case Sign::Zero:
                if (hg.sign() == Sign::Negative) return std::nullopt;
                break;
        }
    }
    for (const ExactVector& e : c.equations()) {
        const Exact3 h = e.exact();
        const Dyadic hg = dot(h, fixed), hu = dot(h, u);
        if (hu.is_zero()) {
            if (!hg.is_zero()) return std::nullopt;
            continue;
        }
        const Magnitude m = hu.sign() == Sign::Positive ? Magnitude{-hg, hu} : Magnitude{hg, -hu};
        at_least(m);
        at_most(m);
    }
    if (r.hi && compare(*r.hi, r.lo) < 0) return std::nullopt;
    return r;
}

Cone reachable_directions(const Cone& c, const Exact3& fixed) {
    const ExactVector minus_fixed = ExactVector::from_exact(-fixed);
    return sum(c, Cone::from_generators(std::span<const ExactVector>(&minus_fixed, 1)));
}

std::vector<MagnitudeBand> magnitude_bands(const std::vector<ModeForces>& analysis, const Exact3& fixed, const Exact3& u) {
    std::vector<std::optional<MagnitudeRange>> ranges;
    ranges.reserve(analysis.size());
    std::vector<Magnitude> cuts = {Magnitude{Dyadic(0.0), Dyadic(1.0)}};
    for (const ModeForces& m : analysis) {
        ranges.push_back(magnitudes(m.applied, fixed, u));
        if (!ranges.back()) continue;
        cuts.push_back(ranges.back()->lo);
        if (ranges.back()->hi) cuts.push_back(*ranges.back()->hi);
    }
    const auto less = [](const Magnitude& a, const Magnitude& b) { return compare(a, b) < 0; };
    std::sort(cuts.begin(), cuts.end(), less);
    cuts.erase(std::unique(cuts.begin(), cuts.end(), [](const Magnitude& a, const Magnitude& b) { return compare(a, b) == 0; }),
               cuts.end());
    // The pieces in order: each cut, then the open stretch after it (to the next cut, or unbounded).
    // A range holds a cut when lo <= cut <= hi, and the stretch (a, b) when lo <= a and b <= hi:
    // every end of every range is a cut, so no range ends inside a stretch.
    std::vector<MagnitudeBand> bands;
    const auto add = [&](MagnitudeBand piece) {
        if (!bands.empty() && bands.back().modes == piece.modes) {
            bands.back().to = std::move(piece.to);
            bands.back().to_closed = piece.to_closed;
        } else {
            bands.push_back(std::move(piece));
        }
    };
    for (std::size_t k = 0; k < cuts.size(); ++k) {
        const Magnitude& a = cuts[k];
        const Magnitude* b = k + 1 < cuts.size() ? &cuts[k + 1] : nullptr;
        MagnitudeBand point{a, a, true, true, {}}, stretch{a, std::nullopt, false, false, {}};
        if (b) stretch.to = *b;
        for (std::size_t j = 0; j < ranges.size(); ++j) {
            if (!ranges[j] || compare(ranges[j]->lo, a) > 0) continue;
            const std::optional<Magnitude>& hi = ranges[j]->hi;
            if (!hi || compare(a, *hi) <= 0) point.modes.push_back(j);
            if (!hi || (b && compare(*b, *hi) <= 0)) stretch.modes.push_back(j);
        }
        add(std::move(point));
        add(std::move(stretch));
    }
    return bands;
}

}  // namespace momentlab
