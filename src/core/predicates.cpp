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

thread_local PredicateStats g_predicate_stats;

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

// The first stage: all arguments small integers (exactly degenerate inputs often are), in
// 128-bit arithmetic.
template <class Predicate, class... V>
bool integer_stage(const Predicate& p, Sign& out, const V&... x) {
    std::array<std::array<Int128, 3>, sizeof...(V)> integers;
    std::size_t k = 0;
    bool all_small = true;
    ((all_small = all_small && small_integers(x, integers[k++])), ...);
    if (all_small) out = std::apply([&](const auto&... v) { return sign_of_integer(p(v...)); }, integers);
    return all_small;
}

// The last stages: error-free expansions where they are exact, else Dyadic numbers.
template <class Predicate, class... V>
Sign expansion_or_dyadic_stage(const Predicate& p, const V&... x) {
    if ((in_expansion_range(x) && ...)) {
        ++g_predicate_stats.expansion;
        return p(expansion(x)...).sign();
    }
    ++g_predicate_stats.dyadic;
    return p(dyadic(x)...).sign();
}

template <class Predicate, class... V>
Sign exact_stages(const Predicate& p, const V&... x) {
    assert((x.allFinite() && ...));
    Sign s = Sign::Zero;
    if (integer_stage(p, s, x...)) return s;
    return expansion_or_dyadic_stage(p, x...);
}

// b x c with error-free products: coordinate k is the exact sum d + e + pe - qe of four doubles,
// where p + pe and q + qe are its two products exactly (Dekker) and d + e = p - q (Knuth), so
// that its Approx has magnitude |d| + |e| + |pe| + |qe|, near the minor itself when b and c are
// nearly parallel (then p and q nearly cancel). Arguments in the expansions' range.
Approx3 accurate_cross(const Vec3& b, const Vec3& c) {
    Approx3 out;
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        double p, pe, q, qe, d, e;
        detail::two_product(b[i], c[j], p, pe);
        detail::two_product(b[j], c[i], q, qe);
        detail::two_sum(p, -q, d, e);
        out[static_cast<std::size_t>(k)] = Approx::exact(d) + Approx::exact(e) + Approx::exact(pe) - Approx::exact(qe);
    }
    return out;
}

}  // namespace

PredicateStats& predicate_stats() { return g_predicate_stats; }

Sign exact_sign(const Dot& p, const Vec3& a, const Vec3& b) { return exact_stages(p, a, b); }

// Before the expansions, det[a b c] = a . (b x c) through the filter again with b x c computed
// accurately: nearly collinear b and c (10^6 points on a circle, the chart's neighbours) have
// minors far smaller than their products, and their determinants are decided there (on the
// circle of bench_cone at 10^6 generators: 904,784 expansions without this stage, none with it).
Sign exact_sign(const Det& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    assert(a.allFinite() && b.allFinite() && c.allFinite());
    Sign s = Sign::Zero;
    if (integer_stage(p, s, a, b, c)) return s;
    if (in_expansion_range(b) && in_expansion_range(c) && filter_sign(Dot{}, s, approximate(a), accurate_cross(b, c))) return s;
    return expansion_or_dyadic_stage(p, a, b, c);
}

Sign exact_sign(const Minor& p, const Vec3& a, const Vec3& b) { return exact_stages(p, a, b); }

}  // namespace momentlab
