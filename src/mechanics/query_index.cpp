// QueryIndex (mechanics/query_index.hpp): every distinct plane of the E_i once, a certified
// single-precision filter over them, and the exact path where it cannot decide.
#include "momentlab/mechanics/query_index.hpp"

#include "scene_index.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <unordered_map>

// The 256-bit vectors of QueryIndex::query never cross a call (load is always inlined), so
// the compiler's note that their ABI differs without AVX (-Wpsabi) does not apply here.
#if defined(__GNUC__)  // GCC and Clang
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace momentlab {
namespace {

// The axis of the largest coordinate of a.
int largest_axis(const Vec3& a) {
    int k = 0;
    for (int i = 1; i < 3; ++i) {
        if (std::fabs(a[i]) > std::fabs(a[k])) k = i;
    }
    return k;
}

// A hash of the plane of v up to sign, from its rounded direction: equal planes usually share
// it (a plane whose rounded directions differ is only stored twice, which changes no answer);
// planes are merged only after an exact test. With it, the axis of the largest coordinate of
// v's approximation (part of the hash).
std::pair<std::uint64_t, int> plane_hash(const ExactVector& v) {
    Vec3 a = v.approximation().approx;
    const double m = a.cwiseAbs().maxCoeff();
    if (m == 0.0) return {0, 0};
    const int k = largest_axis(a);
    a /= a[k];
    std::uint64_t h = static_cast<std::uint64_t>(k);
    for (int i = 0; i < 3; ++i) h = h * 1000003u + static_cast<std::uint64_t>(std::llround(a[i] * 0x1p30));
    return {h, k};
}

// The planes of one hash, ordered exactly by their direction up to sign: each is scaled by the
// sign of its coordinate k (the bucket's axis, taken from its first plane) and ordered by its
// other two coordinates over that one (exact 2x2 minors), so a plane is found among k planes
// with O(log k) exact signs. Planes whose coordinate k is exactly 0 are compared one by one.
// Nearly parallel planes share a hash: the E_i of a scene whose friction cones are 1e-17 wide
// have thousands of facets within 2^-30 of each other, and comparing each new one with all of
// them (exact cross products) took seconds at 2,000 contacts.
class PlaneBucket {
public:
    PlaneBucket(const std::vector<ExactVector>& planes, int axis)
        : planes_(planes), axis_(axis), ordered_(Less{this}) {}

    // The index of a stored plane parallel to planes_[candidate] and whether it has the same
    // orientation; or nullopt after storing the candidate itself.
    std::optional<std::pair<std::uint32_t, bool>> find_or_add(std::uint32_t candidate) {
        const Sign s = sign_on_axis(planes_[candidate]);
        if (s == Sign::Zero) {
            for (std::uint32_t j : others_) {
                if (parallel(planes_[j], planes_[candidate])) return std::pair(j, planes_[j].dot_sign(planes_[candidate]) == Sign::Positive);
            }
            others_.push_back(candidate);
            return std::nullopt;
        }
        signs_[candidate] = s;
        const auto [it, added] = ordered_.insert(candidate);
        if (added) return std::nullopt;
        signs_.erase(candidate);  // the caller drops the candidate: its index is reused
        return std::pair(*it, signs_.at(*it) == s);
    }

private:
    Sign sign_on_axis(const ExactVector& v) const {
        const ExactVector::Approximation a = v.approximation();
        const double x = a.approx[axis_];
        if (std::fabs(x) > a.err[axis_]) return x > 0 ? Sign::Positive : Sign::Negative;
        return v.exact()[static_cast<std::size_t>(axis_)].sign();
    }
    struct Less {
        const PlaneBucket* bucket;
        bool operator()(std::uint32_t a, std::uint32_t b) const {
            const PlaneBucket& p = *bucket;
            const int flip = to_int(p.signs_.at(a)) * to_int(p.signs_.at(b));
            for (int i : {(p.axis_ + 1) % 3, (p.axis_ + 2) % 3}) {
                // a_i / a_k against b_i / b_k, both scaled to a positive coordinate k.
                const int c = flip * to_int(minor_sign(p.planes_[a], p.planes_[b], i, p.axis_));
                if (c != 0) return c < 0;
            }
            return false;
        }
    };
    const std::vector<ExactVector>& planes_;
    int axis_;
    std::unordered_map<std::uint32_t, Sign> signs_;
    std::set<std::uint32_t, Less> ordered_;
    std::vector<std::uint32_t> others_;
};

}  // namespace

QueryIndex::~QueryIndex() = default;
QueryIndex::QueryIndex(QueryIndex&&) noexcept = default;
QueryIndex& QueryIndex::operator=(QueryIndex&&) noexcept = default;

QueryIndex::QueryIndex(const std::vector<ModeForces>& analysis) : mode_count_(analysis.size()) {
    letters_.reserve(analysis.size());
    for (const ModeForces& m : analysis) letters_.push_back(m.mode.letters);
    // hash -> the planes stored with it; a plane is merged with a stored one when they are
    // exactly parallel (PlaneBucket says whether it is the same or the opposite normal).
    std::unordered_map<std::uint64_t, PlaneBucket> seen;
    std::vector<std::vector<std::pair<std::uint32_t, int>>> per_mode(analysis.size());
    auto add = [&](std::size_t mode, const ExactVector& normal) {
        if (is_zero(normal)) return;  // 0 . e >= 0 holds everywhere
        const auto candidate = static_cast<std::uint32_t>(exact_.size());
        exact_.push_back(normal);
        const auto [h, axis] = plane_hash(normal);
        auto bucket = seen.find(h);
        if (bucket == seen.end()) bucket = seen.try_emplace(h, exact_, axis).first;
        if (const auto stored = bucket->second.find_or_add(candidate)) {
            exact_.pop_back();
            per_mode[mode].emplace_back(stored->first, stored->second ? 1 : -1);
            return;
        }
        per_mode[mode].emplace_back(candidate, 1);
    };
    for (std::size_t i = 0; i < analysis.size(); ++i) {
        const Cone& e = analysis[i].applied;
        for (const ExactVector& f : e.facets()) add(i, f);
        for (const ExactVector& q : e.equations()) {
            add(i, q);
            add(i, q.negated());
        }
    }
    if (mode_count_ <= 32) build_filter(per_mode);
    row_start_.push_back(0);
    for (const auto& row : per_mode) {
        halfspaces_.insert(halfspaces_.end(), row.begin(), row.end());
        row_start_.push_back(static_cast<std::uint32_t>(halfspaces_.size()));
    }
}

// The filter in single precision. Plane j is the exact vector 2^K (approx + d) (its certified
// approximation, ExactVector::Filter), scaled by a power of two 2^k so that |2^k approx|_1 lies
// in [1, 2). With u = 2^-24 and max|e_k| = m, rounding the plane and e to floats and the dot
// product in floats errs by less than 12 u |a|_1 m < 1.5 2^-20 m; the approximation's own error
// is 2^k bound m. The sum, rounded up, is the plane's bound (docs/robustness.md). m is kept in
// [2^-60, 2^60], so no float overflows, and underflow (below 2^-149 per operation) is far
// inside the slack. Padding planes have a zero normal and a negative bound: always decided.
void QueryIndex::build_filter(const Rows& per_mode) {
    const std::size_t padded = (exact_.size() + kBlock - 1) / kBlock * kBlock;
    ax_.assign(padded, 0.0F);
    ay_.assign(padded, 0.0F);
    az_.assign(padded, 0.0F);
    bound_.assign(padded, -1.0F);
    // Every plane allows at most the existing modes, so the AND over planes needs no final mask
    // (the filter is only used when some plane, perhaps padding, is decided).
    const std::uint32_t existing = mode_count_ == 32 ? ~std::uint32_t{0} : (std::uint32_t{1} << mode_count_) - 1;
    if_positive_.assign(padded, existing);
    if_negative_.assign(padded, existing);
    for (std::size_t j = 0; j < exact_.size(); ++j) {
        const ExactVector::Filter f = exact_[j].filter();
        const double norm = std::fabs(f.approx.x()) + std::fabs(f.approx.y()) + std::fabs(f.approx.z());
        if (!std::isfinite(f.bound) || norm == 0.0) {
            bound_[j] = std::numeric_limits<float>::infinity();  // never certain: always exact
            continue;
        }
        const int k = -std::ilogb(norm);  // |2^k approx|_1 in [1, 2)
        const Vec3 a = f.approx * std::ldexp(1.0, k);
        ax_[j] = static_cast<float>(a.x());
        ay_[j] = static_cast<float>(a.y());
        az_[j] = static_cast<float>(a.z());
        // The double filter's bound on this scale, plus the float evaluation (below 12 u_f |a|_1 <
        // 24 u_f = 1.5 2^-20 per unit of max|e_k|), rounded up.
        const double b = (std::ldexp(f.bound, k) + 0x1p-19) * (1 + 0x1p-20);
        bound_[j] = b < 1e30 ? static_cast<float>(b) * (1 + 0x1p-20F) : std::numeric_limits<float>::infinity();
    }
    for (std::size_t i = 0; i < per_mode.size(); ++i) {
        for (const auto& [plane, orientation] : per_mode[i]) {
            // orientation +1: the mode needs plane . e >= 0, so a negative side excludes it.
            (orientation > 0 ? if_negative_ : if_positive_)[plane] &= ~(std::uint32_t{1} << i);
        }
    }
}

namespace {

constexpr std::size_t kLanes = 8;
using Floats = float __attribute__((vector_size(kLanes * sizeof(float))));
using Words = std::int32_t __attribute__((vector_size(kLanes * sizeof(std::int32_t))));

template <class V>
[[gnu::always_inline]] inline V load(const void* p) {
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

}  // namespace

// The filter runs over eight planes at a time (GCC/Clang vector extensions: AVX2 where the
// machine has it, pairs of SSE2 registers otherwise); a wrench it cannot decide on some plane,
// or one outside its range, takes the exact path.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
Verdict QueryIndex::query(const Vec3& e, std::vector<std::size_t>& modes) const {
    // A NaN or infinite coordinate fails the range test or leaves every plane undecided (NaN
    // compares false), so the exact path, which checks, sees it.
    modes.clear();
    const double m = std::max({std::abs(e.x()), std::abs(e.y()), std::abs(e.z())});
    if (!ax_.empty() && m >= 0x1p-60 && m <= 0x1p60) {
        static_assert(kBlock == kLanes);
        const auto x = static_cast<float>(e.x()), y = static_cast<float>(e.y()), z = static_cast<float>(e.z());
        const auto mf = static_cast<float>(m);
        const Floats ex = {x, x, x, x, x, x, x, x}, ey = {y, y, y, y, y, y, y, y}, ez = {z, z, z, z, z, z, z, z};
        const Floats scale = {mf, mf, mf, mf, mf, mf, mf, mf};
        Words allowed = ~Words{}, undecided = Words{};
        for (std::size_t j = 0; j < ax_.size(); j += kBlock) {
            const Floats d = load<Floats>(&ax_[j]) * ex + load<Floats>(&ay_[j]) * ey + load<Floats>(&az_[j]) * ez;
            const Floats t = load<Floats>(&bound_[j]) * scale;
            const Words positive = d > t, negative = d < -t, neither = ~(positive | negative);
            allowed &= (positive & load<Words>(&if_positive_[j])) | (negative & load<Words>(&if_negative_[j])) | neither;
            undecided |= neither;
        }
        std::int32_t all = ~std::int32_t{0}, any = 0;
        for (std::size_t k = 0; k < kLanes; ++k) {
            all &= allowed[k];
            any |= undecided[k];
        }
        if (any == 0) {
            auto in = static_cast<std::uint32_t>(all);
            for (; in != 0; in &= in - 1) modes.push_back(static_cast<std::size_t>(std::countr_zero(in)));
            return verdict_of(modes.size());
        }
    }
    return exact_query(e, modes);
}

Verdict QueryIndex::exact_query(const Vec3& e, std::vector<std::size_t>& modes) const {
    if (walk_) return walk_->query(e, modes);  // (made from a scene: no planes of its own)
    if (!e.allFinite()) throw std::invalid_argument("query: the wrench must be finite");
    thread_local std::vector<signed char> sides;
    sides.resize(exact_.size());
    for (std::size_t j = 0; j < exact_.size(); ++j) sides[j] = static_cast<signed char>(exact_[j].dot_sign(e));
    for (std::size_t i = 0; i < mode_count_; ++i) {
        bool member = true;
        for (std::uint32_t k = row_start_[i]; k < row_start_[i + 1] && member; ++k) {
            member = sides[halfspaces_[k].first] * halfspaces_[k].second >= 0;
        }
        if (member) modes.push_back(i);
    }
    return verdict_of(modes.size());
}

QueryResult QueryIndex::query(const Vec3& e) const {
    QueryResult r;
    r.verdict = query(e, r.modes);
    return r;
}

}  // namespace momentlab
