#include "held_cone.hpp"

#include <algorithm>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "cone_build.hpp"
#include "cone_parts.hpp"

namespace momentlab {
namespace {

// w against the pointed full-dimensional cone of g whose extreme rays are c (counter-clockwise):
// facet i is r_i x r_{i+1} (pointed_from_cycle), so w is in the cone when no det(r_i, r_{i+1}, w)
// is negative. from[i] is g[i]'s index among the caller's generators (empty: the same).
Held held_by_cycle(std::span<const ExactVector> g, std::span<const std::size_t> from, std::span<const int> c,
                   const ExactVector& w) {
    const auto origin = [&](int i) { return from.empty() ? static_cast<std::size_t>(i) : from[static_cast<std::size_t>(i)]; };
    Held out;
    const std::size_t k = c.size();
    const auto ray = [&](std::size_t i) -> const ExactVector& { return g[static_cast<std::size_t>(c[i % k])]; };
    for (std::size_t i = 0; i < k; ++i) {
        if (det_sign(ray(i), ray(i + 1), w) == Sign::Negative) {
            out.separator = ExactVector::cross(ray(i), ray(i + 1), 1);
            return out;
        }
    }
    out.member = true;
    // The fan from ray 0: the triangle (r_0, r_i, r_{i+1}) that holds w.
    for (std::size_t i = 1; i + 1 < k; ++i) {
        if (det_sign(ray(0), ray(i), w) != Sign::Negative && det_sign(ray(0), ray(i + 1), w) != Sign::Positive) {
            out.triangle = {origin(c[0]), origin(c[i]), origin(c[i + 1])};
            break;
        }
    }
    return out;
}

// Removes the zero vectors of g; the index in g of each vector kept, or nothing when none was
// zero.
std::vector<std::size_t> drop_zeros(std::vector<ExactVector>& g) {
    std::vector<std::size_t> from;
    if (std::none_of(g.begin(), g.end(), [](const ExactVector& v) { return is_zero(v); })) return from;
    std::vector<ExactVector> nonzero;
    for (std::size_t i = 0; i < g.size(); ++i) {
        if (is_zero(g[i])) continue;
        nonzero.push_back(std::move(g[i]));
        from.push_back(i);
    }
    g = std::move(nonzero);
    return from;
}

// cone(g) of non-zero generators as cone_holds tests against it: a pointed full-dimensional
// cone as its extreme rays in cyclic order (indices into g, no facets built), any other as the
// Cone itself. Nothing for no generators ({0}).
void held_form(std::span<const ExactVector> g, std::vector<int>& cycle, std::optional<Cone>& cone) {
    if (g.empty()) return;
    geometry_detail::Parts parts;
    geometry_detail::parts_of(g, false, parts);
    if (parts.cycle.empty()) {
        cone = ConeBuilder::assemble(std::move(parts.rays), std::move(parts.lineality), std::move(parts.facets),
                                     std::move(parts.equations), std::move(parts.facet_rays));
    } else {
        cycle = std::move(parts.cycle);
    }
}

// w against that form of cone(g), with a certificate.
Held held_by(std::span<const ExactVector> g, std::span<const std::size_t> from, std::span<const int> cycle,
             const std::optional<Cone>& cone, const ExactVector& wrench) {
    Held out;
    if (g.empty()) {  // {0}
        out.member = is_zero(wrench);
        if (!out.member) out.separator = wrench.negated();
        return out;
    }
    if (cone) {  // as Cone::contains decides, for an exact w: an equation or facet that separates
        for (const ExactVector& e : cone->equations()) {
            const Sign s = dot_sign(e, wrench);
            if (s != Sign::Zero) {
                out.separator = s == Sign::Positive ? e.negated() : e;
                return out;
            }
        }
        for (const ExactVector& f : cone->facets()) {
            if (dot_sign(f, wrench) == Sign::Negative) {
                out.separator = f;
                return out;
            }
        }
        out.member = true;
        return out;
    }
    return held_by_cycle(g, from, cycle, wrench);
}

}  // namespace

Held cone_holds(std::span<const ExactVector> generators, const Vec3& wrench) {
    return cone_holds(generators, ExactVector::input(wrench));
}

Held cone_holds(std::span<const ExactVector> generators, const ExactVector& wrench) {
    // The nonzero generators, and where each came from; copied only when some are zero.
    std::span<const ExactVector> g = generators;
    std::vector<ExactVector> nonzero;
    std::vector<std::size_t> from;
    if (std::any_of(generators.begin(), generators.end(), [](const ExactVector& v) { return is_zero(v); })) {
        nonzero.assign(generators.begin(), generators.end());
        from = drop_zeros(nonzero);
        g = nonzero;
    }
    std::vector<int> cycle;
    std::optional<Cone> cone;
    held_form(g, cycle, cone);
    return held_by(g, from, cycle, cone, wrench);
}

HeldCone::HeldCone(std::vector<ExactVector> generators) : generators_(std::move(generators)) {
    from_ = drop_zeros(generators_);
    held_form(generators_, cycle_, cone_);
}

Held HeldCone::holds(const ExactVector& wrench) const { return held_by(generators_, from_, cycle_, cone_, wrench); }

}  // namespace momentlab
