// Which contacts are closed on each face of A = {xi : N_j . xi >= 0} (ModeWalk, mode_walk.hpp):
// by locating each N_j among the extreme rays of A* in angular order (a full-dimensional pointed
// A with many faces), or by testing every contact on every face. Exact throughout.
#include <algorithm>
#include <array>
#include <cassert>
#include <cstdint>
#include <unordered_map>

#include "mode_walk.hpp"
#include "momentlab/core/parallel.hpp"
#include "momentlab/geometry/angular_order.hpp"

namespace momentlab::detail {

// Up to this many faces every contact is tested on every face (the bowl of 10^5 contacts has
// 10): below about log2(n) of them the tests cost less than the binary searches.
constexpr std::size_t kFewFaces = 16;
// From this many contacts their searches are shared out to two threads (a thread costs tens of
// microseconds; a search about one).
constexpr std::size_t kTwoThreadLocate = 2000;

std::vector<std::vector<int>> ModeWalk::closed_sets(const std::vector<Face>& faces, Closed how) const {
    std::vector<std::vector<int>> out(faces.size());
    const std::vector<ExactVector>& f = a_.facets();
    const std::size_t k = f.size(), n = normals_.size();
    const bool can_locate = a_.dimension() == 3 && a_.is_pointed() && k >= 3;
    if (!can_locate || how == Closed::Test || (how == Closed::Auto && faces.size() <= kFewFaces)) {
        // Few faces (at most four when A has a line or lies in a plane): N_j . g = 0 for every
        // generator g of the face, a filtered dot product each, is faster than locating N_j.
        for (std::size_t i = 0; i < faces.size(); ++i) {
            if (faces[i].dimension == 0) continue;
            for (std::size_t j = 0; j < n; ++j) {
                bool all = true;
                for (int r : faces[i].rays) all = all && dot_sign(normals_[j], a_.rays()[static_cast<std::size_t>(r)]) == Sign::Zero;
                for (const ExactVector& l : a_.lineality()) all = all && dot_sign(normals_[j], l) == Sign::Zero;
                if (all) out[i].push_back(static_cast<int>(j));
            }
        }
        return out;
    }
    // A* = cone(N_j) is pointed and full-dimensional; its extreme rays are A's facet normals
    // F_i, in cyclic order (order[t]; counter-clockwise about an interior point c). N_j is
    // closed on facet i (and its two rays) when it points along F_i, and on the ray of A
    // between facets i and i' when it lies on A*'s facet between F_i and F_i'; elsewhere it
    // is inside A* and closed on no face but {0}. Each N_j is found by a binary search of its
    // angle about c: O(log k) exact signs.
    const Sign turn = det_sign(f[0], f[1], f[2]);
    std::vector<std::size_t> order(k);
    for (std::size_t t = 0; t < k; ++t) order[t] = turn == Sign::Positive ? t : (k - t) % k;
    const ExactVector& reference = f[order[0]];
    const ExactVector c = ExactVector::from_exact(f[order[0]].exact() + f[order[k / 3]].exact() + f[order[2 * k / 3]].exact());
    const Exact3 c_reference = cross(c.exact(), reference.exact());
    // The approximations of c and of the facets, made once: every search below tests them again.
    const ExactVector::Approximation pc = c.approximation();
    std::vector<ExactVector::Approximation> pf(k);
    for (std::size_t t = 0; t < k; ++t) pf[t] = f[t].approximation();
    // 0: along the reference; 1: counter-clockwise from it by less than pi; 2: opposite; 3: the
    // rest; -1: along c.
    const auto half = [&](const ExactVector& v, const ExactVector::Approximation& pv) {
        int along = 1;
        const int h = angular_half(det_sign(c, reference, v, pc, pf[order[0]], pv), [&] {
            along = to_int(dot(cross(c.exact(), v.exact()), c_reference).sign());
            return along > 0;
        });
        return along == 0 ? -1 : h;
    };
    std::vector<int> ray_half(k);
    for (std::size_t t = 0; t < k; ++t) ray_half[t] = half(f[order[t]], pf[order[t]]);
    // The ray of A on facets i and i' (each ray of A lies on exactly two facets).
    std::unordered_map<std::uint64_t, int> ray_between;
    const Incidence facets_of_ray = a_.facet_rays().transposed(a_.rays().size());
    const auto key = [k](std::size_t i, std::size_t i2) { return static_cast<std::uint64_t>(std::min(i, i2)) * k + std::max(i, i2); };
    for (std::size_t r = 0; r < a_.rays().size(); ++r) {
        const auto row = facets_of_ray.row(r);
        if (row.size() == 2) ray_between[key(static_cast<std::size_t>(row[0]), static_cast<std::size_t>(row[1]))] = static_cast<int>(r);
    }
    // The contacts closed on each facet and on each ray between two facets, found for two halves
    // of the contacts apart (on two threads for large scenes: the searches share nothing they
    // write) and joined in order.
    struct Found {
        std::vector<std::vector<int>> on_facet, on_ray;
    };
    std::array<Found, 2> found;
    detail::for_each_index(2, n >= kTwoThreadLocate, [&](std::size_t part) {
        Found& mine = found[part];
        mine.on_facet.resize(k);
        mine.on_ray.resize(a_.rays().size());
        for (std::size_t j = n * part / 2; j < n * (part + 1) / 2; ++j) {
            const ExactVector& v = normals_[j];
            const ExactVector::Approximation pv = v.approximation();
            const int hv = half(v, pv);
            if (hv < 0) continue;  // along c: inside A*
            const auto not_after = [&](std::size_t t) {  // the angle of ray t is at most v's
                const auto orient_tv = [&] { return det_sign(c, f[order[t]], v, pc, pf[order[t]], pv); };
                return angular_compare(ray_half[t], hv, orient_tv) != Sign::Positive;
            };
            std::size_t lo = 0, hi = k;  // not_after(lo), !not_after(hi) (hi = k: past the end)
            while (hi - lo > 1) {
                const std::size_t mid = lo + (hi - lo) / 2;
                (not_after(mid) ? lo : hi) = mid;
            }
            const std::size_t i = order[lo], i2 = order[(lo + 1) % k];
            if (parallel(v, f[i])) {
                mine.on_facet[i].push_back(static_cast<int>(j));
            } else if (det_sign(f[i], f[i2], v, pf[i], pf[i2], pv) == Sign::Zero) {
                const auto it = ray_between.find(key(i, i2));
                assert(it != ray_between.end());
                mine.on_ray[static_cast<std::size_t>(it->second)].push_back(static_cast<int>(j));
            }
        }
    });
    for (auto list : {&Found::on_facet, &Found::on_ray}) {
        auto& first = found[0].*list;
        const auto& second = found[1].*list;
        for (std::size_t i = 0; i < first.size(); ++i) first[i].insert(first[i].end(), second[i].begin(), second[i].end());
    }
    const std::vector<std::vector<int>>& on_facet = found[0].on_facet;
    const std::vector<std::vector<int>>& on_ray = found[0].on_ray;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const Face& face = faces[i];
        if (face.dimension == 2) {
            out[i] = on_facet[static_cast<std::size_t>(face.facets.front())];
        } else if (face.dimension == 1) {
            for (int fi : face.facets) {
                const auto& more = on_facet[static_cast<std::size_t>(fi)];
                out[i].insert(out[i].end(), more.begin(), more.end());
            }
            const auto& more = on_ray[static_cast<std::size_t>(face.rays.front())];
            out[i].insert(out[i].end(), more.begin(), more.end());
            std::sort(out[i].begin(), out[i].end());
        }
    }
    return out;
}

}  // namespace momentlab::detail
