// Where a plan's solutions give the goal and nothing else (planning/unique.hpp).
#include "momentlab/planning/unique.hpp"

#include <algorithm>
#include <cstddef>

#include "momentlab/geometry/angular_order.hpp"

namespace momentlab {
namespace {

bool is_goal(const ModeForces& m, const ModeForces& goal) { return &m == &goal || m.mode.letters == goal.mode.letters; }

ExactVector sum_of(const ExactVector& a, const ExactVector& b) { return ExactVector::from_exact(a.exact() + b.exact()); }

// The arcs of a cone c lying in the plane with normal nu: none, one point, two opposite points,
// a half-plane, a wedge or the whole plane (Cone's own shapes, oriented about nu).
std::vector<WrenchArc> arcs_of(const ExactVector& nu, const Cone& c) {
    if (c.is_zero()) return {};
    if (c.lineality_dimension() >= 2) return {WrenchArc{c.lineality()[0], c.lineality()[0], true}};
    if (c.lineality_dimension() == 1) {
        const ExactVector& d = c.lineality()[0];
        if (c.rays().empty()) return {WrenchArc{d, d}, WrenchArc{d.negated(), d.negated()}};
        const bool left = det_sign(nu, d, c.rays()[0]) == Sign::Positive;
        return {left ? WrenchArc{d, d.negated()} : WrenchArc{d.negated(), d}};
    }
    if (c.rays().size() == 1) return {WrenchArc{c.rays()[0], c.rays()[0]}};
    const ExactVector &a = c.rays()[0], &b = c.rays()[1];
    return {det_sign(nu, a, b) == Sign::Positive ? WrenchArc{a, b} : WrenchArc{b, a}};
}

// The exact angular order about nu (geometry/angular_order.hpp), starting at the reference
// direction r.
struct ArcOrder {
    ExactVector nu, r;
    [[nodiscard]] int half(const ExactVector& v) const {
        return angular_half(det_sign(nu, r, v), [&] { return dot_sign(r, v) == Sign::Positive; });
    }
    [[nodiscard]] bool less(const ExactVector& a, const ExactVector& b) const {
        return angular_compare(half(a), half(b), [&] { return det_sign(nu, a, b); }) == Sign::Negative;
    }
    // a and b are one direction: b is in a's half 0.
    [[nodiscard]] bool same(const ExactVector& a, const ExactVector& b) const {
        return angular_half(det_sign(nu, a, b), [&] { return dot_sign(a, b) == Sign::Positive; }) == 0;
    }
};

enum class Cover : unsigned char { None, Unique, Shared };

}  // namespace

ExactVector arc_middle(const ExactVector& nu, const WrenchArc& arc) {
    if (arc.whole) return arc.from.negated();  // the half-turn from where the turn starts
    const Sign turn = det_sign(nu, arc.from, arc.to);
    if (turn == Sign::Positive) return sum_of(arc.from, arc.to);
    if (turn == Sign::Zero) {
        if (dot_sign(arc.from, arc.to) == Sign::Positive) return arc.from;  // one direction
        return ExactVector::cross(nu, arc.from);                            // a half-turn: its quarter
    }
    return sum_of(arc.from, arc.to).negated();  // wider than a half-turn
}

PlaneSplit split_plane(const ExactVector& nu, const Cone& s, std::span<const ModeForces> modes, const ModeForces& goal) {
    PlaneSplit out;
    const std::vector<WrenchArc> goal_arcs = arcs_of(nu, s);
    if (goal_arcs.empty()) return out;
    std::vector<std::vector<WrenchArc>> others;
    for (const ModeForces& m : modes) {
        if (is_goal(m, goal)) continue;
        std::vector<WrenchArc> a = arcs_of(nu, intersection(s, m.applied));
        if (!a.empty()) others.push_back(std::move(a));
    }
    // Every arc end, in angular order, without repeats.
    std::vector<ExactVector> cuts;
    const auto collect = [&](const std::vector<WrenchArc>& arcs) {
        for (const WrenchArc& a : arcs) {
            if (a.whole) continue;
            cuts.push_back(a.from);
            cuts.push_back(a.to);
        }
    };
    collect(goal_arcs);
    for (const auto& a : others) collect(a);
    const std::size_t pieces_wanted = cuts.empty() ? 1 : 0;
    std::vector<Cover> cover;
    std::size_t k_count = 0;
    std::vector<ExactVector> order;
    if (!cuts.empty()) {
        const ArcOrder ord{nu, cuts.front()};
        std::sort(cuts.begin(), cuts.end(), [&](const ExactVector& a, const ExactVector& b) { return ord.less(a, b); });
        for (const ExactVector& c : cuts) {
            if (order.empty() || !ord.same(order.back(), c)) order.push_back(c);
        }
        if (order.size() > 1 && ord.same(order.back(), order.front())) order.pop_back();
        k_count = order.size();
    }
    const std::size_t n_pieces = pieces_wanted ? 1 : 2 * k_count;  // point k is piece 2k, the open arc after it 2k + 1
    const auto index_of = [&](const ExactVector& v) {
        const ArcOrder ord{nu, order.front()};
        for (std::size_t k = 0; k < order.size(); ++k) {
            if (ord.same(order[k], v)) return k;
        }
        return std::size_t{0};  // unreachable: every end is a cut
    };
    const auto covers = [&](const std::vector<WrenchArc>& arcs, std::size_t piece) {
        for (const WrenchArc& a : arcs) {
            if (a.whole) return true;
            const std::size_t i = index_of(a.from), j = index_of(a.to), k = piece / 2;
            const bool point = piece % 2 == 0;
            if (i == j) {
                if (point && k == i) return true;
                continue;
            }
            const bool in = i < j ? (k >= i && (point ? k <= j : k < j)) : (k >= i || (point ? k <= j : k < j));
            if (in) return true;
        }
        return false;
    };
    cover.resize(n_pieces, Cover::None);
    for (std::size_t p = 0; p < n_pieces; ++p) {
        if (!covers(goal_arcs, p)) continue;
        const bool shared = std::any_of(others.begin(), others.end(), [&](const auto& a) { return covers(a, p); });
        cover[p] = shared ? Cover::Shared : Cover::Unique;
    }
    // Runs of equal cover, walked cyclically from a change (the whole turn when there is none).
    const auto emit = [&](Cover c, WrenchArc arc) {
        if (c == Cover::Unique) out.unique.push_back(std::move(arc));
        if (c == Cover::Shared) out.shared.push_back(std::move(arc));
    };
    std::size_t start = n_pieces;
    for (std::size_t p = 0; p < n_pieces; ++p) {
        if (cover[p] != cover[(p + n_pieces - 1) % n_pieces]) {
            start = p;
            break;
        }
    }
    if (start == n_pieces) {  // one cover all the way round
        const ExactVector any = order.empty() ? goal_arcs.front().from : order.front();
        emit(cover.front(), WrenchArc{any, any, true});
        return out;
    }
    const auto begin_of = [&](std::size_t p) { return p / 2; };
    const auto end_of = [&](std::size_t p) { return p % 2 == 0 ? p / 2 : (p / 2 + 1) % k_count; };
    std::size_t p = start;
    do {
        std::size_t q = p;
        while (cover[(q + 1) % n_pieces] == cover[p] && (q + 1) % n_pieces != start) q = (q + 1) % n_pieces;
        // A run that is more than one point and ends where it begins goes all the way round but
        // for that point (the goal holds every direction and one other set meets it in one): the
        // whole turn from there, as a closure, not the single direction {d, d}.
        const bool around = !(p % 2 == 0 && q == p) && begin_of(p) == end_of(q);
        emit(cover[p], WrenchArc{order[begin_of(p)], order[end_of(q)], around});
        p = (q + 1) % n_pieces;
    } while (p != start);
    return out;
}

namespace {

// The unique part of a full-dimensional s: s minus every full-dimensional E_j, as convex cones
// (a cone minus E_j with facets f_1..f_k is the union of the cones f_1 <= 0, f_1 >= 0 and
// f_2 <= 0, ...; only full-dimensional pieces are kept, as a lower-dimensional E_j or piece
// cannot cover or make an open set).
Uniqueness uniqueness_3d(const Cone& s, std::span<const ModeForces> modes, const ModeForces& goal) {
    Uniqueness u;
    std::vector<Cone> pieces = {s};
    for (const ModeForces& m : modes) {
        if (!is_goal(m, goal) && !intersection(s, m.applied).is_zero()) u.shared = true;
    }
    for (const ModeForces& m : modes) {
        if (is_goal(m, goal) || m.applied.dimension() < 3) continue;
        std::vector<Cone> next;
        for (const Cone& piece : pieces) {
            std::vector<ExactVector> kept;  // the facets already passed on the outside: f >= 0
            for (const ExactVector& f : m.applied.facets()) {
                std::vector<ExactVector> h = kept;
                h.push_back(f.negated());
                Cone cut = intersection(piece, Cone::from_halfspaces(h));
                if (cut.dimension() == 3) next.push_back(std::move(cut));
                kept.push_back(f);
            }
        }
        pieces = std::move(next);
        if (pieces.empty()) break;
    }
    if (!pieces.empty()) {
        u.unique = true;
        Exact3 total{};
        for (const ExactVector& g : pieces.front().generators()) total = total + g.exact();
        u.representative = ExactVector::from_exact(total);
        u.parts = std::move(pieces);
    }
    return u;
}

}  // namespace

Uniqueness uniqueness(const Cone& s, std::span<const ModeForces> modes, const ModeForces& goal) {
    Uniqueness u;
    if (s.is_zero()) return u;
    if (s.dimension() == 3) return uniqueness_3d(s, modes, goal);
    if (s.dimension() == 1) {  // a ray, or a line: its directions
        for (const ExactVector& g : s.generators()) {
            bool alone = true;
            for (const ModeForces& m : modes) {
                if (!is_goal(m, goal) && m.applied.has(g)) alone = false;
            }
            u.shared = u.shared || !alone;
            if (alone) {
                if (!u.unique) u.representative = g;
                u.unique = true;
                u.parts.push_back(Cone::from_generators(std::span<const ExactVector>(&g, 1)));
            }
        }
        return u;
    }
    const ExactVector& nu = s.equations()[0];
    const PlaneSplit split = split_plane(nu, s, modes, goal);
    u.shared = !split.shared.empty();
    for (const WrenchArc& a : split.unique) {
        // A part of the plane's own dimension: more than one direction.
        if (!a.whole && det_sign(nu, a.from, a.to) == Sign::Zero && dot_sign(a.from, a.to) == Sign::Positive) continue;
        const ExactVector middle = arc_middle(nu, a);
        if (!u.unique) u.representative = middle;
        u.unique = true;
        // As convex cones: the arc itself when narrower than a half-turn, else its two halves
        // (the whole plane: the plane).
        if (a.whole) {
            u.parts.push_back(s);
        } else if (det_sign(nu, a.from, a.to) == Sign::Positive) {
            u.parts.push_back(Cone::from_generators(std::vector<ExactVector>{a.from, a.to}));
        } else {
            u.parts.push_back(Cone::from_generators(std::vector<ExactVector>{a.from, middle}));
            u.parts.push_back(Cone::from_generators(std::vector<ExactVector>{middle, a.to}));
        }
    }
    return u;
}

}  // namespace momentlab
