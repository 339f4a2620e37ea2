// The exact stages of the predicates on stored doubles (core/predicates.hpp), taken when the
// filter cannot decide: the same predicate evaluated in 128-bit integers (all arguments small
// integers), on error-free expansions (arguments in the expansions' range), else on Dyadic
// numbers.
#include "momentlab/core/predicates.hpp"

#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <tuple>

#include "error_free.hpp"
#include "momentlab/core/dyadic.hpp"

namespace momentlab {
namespace {

thread_local PredicateStats g_stats;

__extension__ typedef __int128 Int128;

// Integers up to 2^40 in magnitude: products of three fit in 120 bits, sums of six in 123.
bool small_integer(double x, std::int64_t& out) {
    if (!(std::fabs(x) <= 0x1p40)) return false;
    out = static_cast<std::int64_t>(x);
    return static_cast<double>(out) == x;
}

bool small_integers(const Vec3& v, std::array<Int128, 3>& out) {
    for (int k = 0; k < 3; ++k) {
        std::int64_t i = 0;
        if (!small_integer(v[k], i)) return false;
        out[static_cast<std::size_t>(k)] = i;
    }
    return true;
}

bool in_expansion_range(const Vec3& v) {
    return detail::in_expansion_range(v.x()) && detail::in_expansion_range(v.y()) && detail::in_expansion_range(v.z());
}

std::array<detail::Expansion<1>, 3> expansion(const Vec3& v) {
    return {detail::Expansion<1>(v.x()), detail::Expansion<1>(v.y()), detail::Expansion<1>(v.z())};
}

std::array<Dyadic, 3> dyadic(const Vec3& v) { return {Dyadic(v.x()), Dyadic(v.y()), Dyadic(v.z())}; }

Sign sign_of_integer(Int128 x) { return x > 0 ? Sign::Positive : (x < 0 ? Sign::Negative : Sign::Zero); }

// The stages, for a predicate of degree at most 3 (the ranges above assume it).
template <class Predicate, class... V>
Sign exact_stages(const Predicate& p, const V&... x) {
    assert((x.allFinite() && ...));
    // Exactly degenerate inputs are often small integers: exact in 128-bit arithmetic.
    std::array<std::array<Int128, 3>, sizeof...(V)> integers;
    std::size_t k = 0;
    bool all_small = true;
    ((all_small = all_small && small_integers(x, integers[k++])), ...);
    if (all_small) return std::apply([&](const auto&... v) { return sign_of_integer(p(v...)); }, integers);
    if ((in_expansion_range(x) && ...)) {
        ++g_stats.expansion;
        return p(expansion(x)...).sign();
    }
    ++g_stats.dyadic;
    return p(dyadic(x)...).sign();
}

}  // namespace

PredicateStats& predicate_stats() { return g_stats; }

Sign exact_sign(const Dot& p, const Vec3& a, const Vec3& b) { return exact_stages(p, a, b); }

Sign exact_sign(const Det& p, const Vec3& a, const Vec3& b, const Vec3& c) { return exact_stages(p, a, b, c); }

Sign exact_sign(const Minor& p, const Vec3& a, const Vec3& b) { return exact_stages(p, a, b); }

}  // namespace momentlab
