#pragma once

// The exact angular order of vectors about an axis (a coordinate axis across a plane, or a
// pivot vector: the order in the quotient R^3 / p; the order itself is geometry/angular_order.hpp),
// and the sort that puts many vectors in that order from floating-point keys repaired by exact
// comparisons. Used by the planar case
// (cone_planar.cpp) and the pivot analysis (cone_pivot.cpp) of cone(generators); written for
// any generator type with the predicates of generators.hpp (Vec3, ExactVector). Private to the
// geometry layer.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>

#include "generators.hpp"
#include "momentlab/geometry/angular_order.hpp"
#include "scratch.hpp"

// Private to the geometry layer: hidden from the shared library's interface.
namespace momentlab {
namespace [[gnu::visibility("hidden")]] geometry_detail {

// Angular order around an axis. For the plane case the axis is a coordinate direction e_k
// transversal to the plane (orientation = sign of (u x v)[k]); for the quotient by a pivot p it
// is p itself (orientation = det(p, u, v)). `half` places a vector in one of four classes
// relative to a reference direction r: 0 along r, 1 strictly left, 2 along -r, 3 strictly right.
template <class G>
struct AngularOrder {
    enum class Mode { PlaneAxis, Pivot } mode;
    int axis = 2;
    G pivot{};
    G reference{};
    G witness{};  // pivot mode: a vector with det(p, r, witness) != 0
    RoundingOf<G> pivot_rounding = unrounded<G>();  // pivot mode: the pivot's approximation

    Sign orient(const G& u, const G& v) const {
        return mode == Mode::PlaneAxis ? cross_component_sign(u, v, axis) : det_sign(pivot, u, v);
    }
    int half(const G& u) const {
        return angular_half(orient(reference, u), [&] {
            if (mode == Mode::PlaneAxis) return dot_sign(reference, u) == Sign::Positive;
            return det_sign(pivot, u, witness) == det_sign(pivot, reference, witness);
        });
    }
};

// The vector travels with the item so that the exact passes after sorting read memory in
// order (indexing back into the input was cache-bound: ~60 ns a predicate at 10^6 items).
template <class G>
struct Item {
    G v;
    std::uint64_t key;  // angle_key: the half, then the angle inside it; only a hint for the sort
    int index;
    int half;
    // Pivot mode: v's approximation, made once for the determinants of the sort and the scan.
    [[no_unique_address]] RoundingOf<G> rounding = unrounded<G>();
};

// ord.orient(a.v, b.v), with the items' approximations in pivot mode.
template <class G>
Sign orient(const AngularOrder<G>& ord, const Item<G>& a, const Item<G>& b) {
    if (ord.mode == AngularOrder<G>::Mode::Pivot) {
        return det_rounded(ord.pivot, a.v, b.v, ord.pivot_rounding, a.rounding, b.rounding);
    }
    return ord.orient(a.v, b.v);
}

// A key increasing with the angle: the half in the top two bits, then, inside the open halves
// 1 and 3, -a / b from coordinates (a, b) along and across the reference direction (b > 0 in
// half 1, b < 0 in half 3): minus the cotangent, which keeps the relative precision of a and b
// at every angle. (A pseudo-angle on a fixed interval, such as 1 - a / (|a| + |b|), rounds
// every angle within 2^-53 of an end of the half to that end: the angles of generators nearly
// in one plane through the pivot.) The double's bits are mapped to an unsigned integer of the
// same order, less its two lowest bits, so that one integer orders the halves and the angles
// within each. Only a hint for the sort; halves 0 and 2 need none.
inline std::uint64_t angle_key(double a, double b, int half) {
    double key = 0.0;
    if (half == 1 || half == 3) {
        if (!(half == 1 ? b > 0.0 : b < 0.0)) b = half == 1 ? 0.0 : -0.0;  // rounded to 0 or past it
        key = -a / b;                                                       // +-inf for b = 0
        if (std::isnan(key)) key = 0.0;
    }
    std::uint64_t bits = 0;
    std::memcpy(&bits, &key, sizeof bits);  // (std::bit_cast: not in the WebAssembly build's library)
    bits = bits >> 63 ? ~bits : bits | (std::uint64_t{1} << 63);  // negative keys in reverse
    return static_cast<std::uint64_t>(half) << 62 | bits >> 2;
}

// Groups of items of exactly equal angle: [begin, end) ranges, stored as 32-bit starts.
class Groups {
public:
    explicit Groups(Scratch* memory) : starts_(memory) {}
    void add(std::size_t begin) { starts_.push_back(static_cast<std::uint32_t>(begin)); }
    void close(std::size_t end) { end_ = end; }
    [[nodiscard]] std::size_t size() const { return starts_.size(); }
    [[nodiscard]] std::pair<std::size_t, std::size_t> operator[](std::size_t i) const {
        return {starts_[i], i + 1 < starts_.size() ? starts_[i + 1] : end_};
    }

private:
    ScratchVector<std::uint32_t> starts_;
    std::size_t end_ = 0;
};

// Sorts items by key (equal keys in their present order): the keys and positions are sorted,
// 16 bytes each, and then each item is moved once to its place, following the cycles of the
// permutation (an item is about 200 bytes with its approximation, and std::sort moves each
// about log n times: on the cradle of 10^4 contacts, 14 M of the 45 M instructions of a
// SceneQuestions set-up, `make instructions`).
template <class G>
void sort_by_key(ScratchVector<Item<G>>& items) {
    struct Keyed {
        std::uint64_t key;
        std::uint32_t at;
    };
    ScratchVector<Keyed> order(items.get_allocator());
    order.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) order.push_back({items[i].key, static_cast<std::uint32_t>(i)});
    std::sort(order.begin(), order.end(), [](const Keyed& a, const Keyed& b) { return a.key < b.key || (a.key == b.key && a.at < b.at); });
    // items[i] is to become the item now at order[i].at; a place filled is marked at = i.
    for (std::size_t start = 0; start < items.size(); ++start) {
        if (order[start].at == start) continue;
        Item<G> first = std::move(items[start]);
        std::size_t i = start;
        while (order[i].at != start) {
            const std::size_t from = order[i].at;
            items[i] = std::move(items[from]);
            order[i].at = static_cast<std::uint32_t>(i);
            i = from;
        }
        items[i] = std::move(first);
        order[i].at = static_cast<std::uint32_t>(i);
    }
}

// Sorts items by angle, ties (the same direction around the axis) by the order
// `tie_order(first)` gives for the group of `first`, and returns the groups of exactly equal
// angle as [begin, end) ranges.
// The floating-point keys put the items almost in order; an exact insertion pass then makes
// the order exact in O(n + inversions), and runs of exactly equal angle are sorted by the
// exact tie-break. Correct for any keys; fast when they are close to the truth.
template <class G, class TieOrder>
Groups angular_sort(ScratchVector<Item<G>>& items, const AngularOrder<G>& ord, TieOrder tie_order) {
    using Item = geometry_detail::Item<G>;
    sort_by_key(items);
    // compare(a, b): Negative if a comes first, Zero for the same angle, Positive after.
    auto compare = [&](const Item& a, const Item& b) { return angular_compare(a.half, b.half, [&] { return orient(ord, a, b); }); };
    // One exact comparison per neighbouring pair; an item found out of order is moved back
    // (insertion), which is rare when the keys are good. When they are not (generators almost
    // in one plane through the pivot, where the floating-point angles are noise), the moves
    // are bounded and a plain exact sort takes over, so the whole stays O(n log n).
    // `same[i]`: items i-1 and i share an angle.
    // While nothing has moved, the comparison that stopped item i is its final relation to item
    // i-1, so `same` is filled on the way; after a move it is filled again.
    ScratchVector<char> same(items.size(), 0, items.get_allocator());
    std::size_t moves = 0;
    const std::size_t budget = 8 * items.size() + 1024;
    bool sorted = true;
    for (std::size_t i = 1; i < items.size() && sorted; ++i) {
        std::size_t j = i;
        Sign c = Sign::Negative;
        while (j > 0 && (c = compare(items[j - 1], items[j])) == Sign::Positive) {
            std::swap(items[j], items[j - 1]);
            --j;
            if (++moves > budget) {
                sorted = false;
                break;
            }
        }
        if (moves == 0) same[i] = c == Sign::Zero;
    }
    if (!sorted) {
        std::sort(items.begin(), items.end(),
                  [&](const Item& a, const Item& b) { return compare(a, b) == Sign::Negative; });
    }
    if (moves > 0) {
        for (std::size_t i = 1; i < items.size(); ++i) same[i] = compare(items[i - 1], items[i]) == Sign::Zero;
    }
    Groups groups(items.get_allocator().scratch);
    std::size_t start = 0;
    for (std::size_t i = 1; i <= items.size(); ++i) {
        if (i < items.size() && same[i]) continue;
        groups.add(start);
        if (i - start > 1) {
            const auto closer_first = tie_order(items[start].v);
            std::sort(items.begin() + static_cast<std::ptrdiff_t>(start),
                      items.begin() + static_cast<std::ptrdiff_t>(i),
                      [&](const Item& a, const Item& b) { return closer_first(a.v, b.v); });
        }
        start = i;
    }
    groups.close(items.size());
    return groups;
}

// The angular gap from direction u to the next direction v (counter-clockwise), compared with
// pi: -1 smaller, 0 equal, +1 larger. u and v are distinct directions.
template <class G>
int gap_vs_pi(const Item<G>& u, const Item<G>& v, const AngularOrder<G>& ord) {
    const Sign s = orient(ord, u, v);
    if (s == Sign::Positive) return -1;
    if (s == Sign::Negative) return 1;
    return 0;
}

}  // namespace geometry_detail
}  // namespace momentlab
