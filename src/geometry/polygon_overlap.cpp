// Whether the interiors of two simple polygons meet, decided exactly (geometry/polygon.hpp).
//
// If the interiors of A and B meet, their intersection I is open, bounded and not empty, so its
// boundary has infinitely many points, all on the boundary of A or of B; take one, x, that is no
// vertex and no point where the two boundaries meet. Say x is on an edge e of A. Cut e at every
// point where B's boundary meets it: x is inside a piece, and along that piece B's boundary is
// either absent (the piece lies inside B, or outside) or runs along it. Since x is on the
// boundary of I, the side of e towards A's interior lies in B's interior near x, and so all along
// the piece. Conversely such a piece gives points of I beside it. So the interiors meet exactly
// when some piece of an edge of one polygon, cut by the other's boundary, is inside the other or
// runs along an edge of the other that has its interior on the same side. A piece's status is
// read at an end where the other boundary meets the edge (every piece of a cut edge has one),
// from how that boundary passes there: through an edge (the piece's direction against it) or a
// vertex (the direction against the vertex's interior angle). Edges that the other boundary does
// not meet lie wholly inside or outside it: when no edge is met at all, one vertex of each
// decides; otherwise every chain of unmet edges ends at a met edge, whose piece at that end has
// the chain's status.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "momentlab/core/dyadic.hpp"
#include "momentlab/geometry/polygon.hpp"

namespace momentlab {
namespace {

using D = Dyadic;

// The polygons' points: doubles (Vec2) or exact (ExactPoint), each check below written once.
template <class P>
D cross(const P& a, const P& b, const P& c, const P& d) {  // (b - a) x (d - c), exactly
    return (D(b.x()) - D(a.x())) * (D(d.y()) - D(c.y())) - (D(b.y()) - D(a.y())) * (D(d.x()) - D(c.x()));
}
template <class P>
D dot(const P& a, const P& b, const P& c, const P& d) {  // (b - a) . (d - c), exactly
    return (D(b.x()) - D(a.x())) * (D(d.x()) - D(c.x())) + (D(b.y()) - D(a.y())) * (D(d.y()) - D(c.y()));
}

bool on_segment(const Vec2& x, const Vec2& a, const Vec2& b) { return within_distance_of_segment(x, a, b, 0.0); }
bool on_segment(const ExactPoint& x, const ExactPoint& a, const ExactPoint& b) {
    return within_distance_of_segment(x, a, b, Dyadic(), 0.0);
}
bool on_boundary(std::span<const Vec2> polygon, const Vec2& x) { return within_distance_of_boundary(polygon, x, 0.0); }
bool on_boundary(std::span<const ExactPoint> polygon, const ExactPoint& x) {
    return within_distance_of_boundary(polygon, x, Dyadic(), 0.0);
}
// A double point as a point of the polygons' kind.
void as_point(const Vec2& x, Vec2& out) { out = x; }
void as_point(const Vec2& x, ExactPoint& out) { out = {Dyadic(x.x()), Dyadic(x.y())}; }

// Where the other polygon's boundary meets an edge pq: at p + (num / den)(q - p), den > 0,
// through the other's vertex `index` or through the inside of its edge `index` (from that
// vertex to the next).
struct Meeting {
    D num, den;
    bool at_vertex = false;
    std::size_t index = 0;
};

bool before(const Meeting& a, const Meeting& b) { return compare(a.num * b.den, b.num * a.den) < 0; }
bool same_place(const Meeting& a, const Meeting& b) { return compare(a.num * b.den, b.num * a.den) == 0; }

// The counter-clockwise copy of a simple polygon.
template <class P>
std::vector<P> counter_clockwise_copy(std::span<const P> p) {
    std::vector<P> q(p.begin(), p.end());
    if (!is_counter_clockwise(p)) std::reverse(q.begin(), q.end());
    return q;
}

// The places where the boundary of b meets the edge pq (b counter-clockwise).
template <class P>
std::vector<Meeting> meetings(const P& p, const P& q, const std::vector<P>& b, const std::vector<std::size_t>& candidates) {
    std::vector<Meeting> out;
    const std::size_t m = b.size();
    const D length2 = dot(p, q, p, q);
    const auto vertex_on = [&](std::size_t k) { out.push_back({dot(p, b[k], p, q), length2, true, k}); };
    for (std::size_t f : candidates) {
        const P &r = b[f], &s = b[(f + 1) % m];
        const Sign o_r = orient2d(p, q, r), o_s = orient2d(p, q, s);
        if (o_r != Sign::Zero && o_r == o_s) continue;
        const Sign o_p = orient2d(r, s, p), o_q = orient2d(r, s, q);
        if (o_p != Sign::Zero && o_p == o_q) continue;
        if (o_r != Sign::Zero && o_s != Sign::Zero && o_p != Sign::Zero && o_q != Sign::Zero) {  // a crossing
            D num = cross(p, r, r, s), den = cross(p, q, r, s);
            if (den.sign() == Sign::Negative) {
                num = -num;
                den = -den;
            }
            out.push_back({std::move(num), std::move(den), false, f});
            continue;
        }
        if (o_r == Sign::Zero && on_segment(r, p, q)) vertex_on(f);
        if (o_s == Sign::Zero && on_segment(s, p, q)) vertex_on((f + 1) % m);
        if (o_p == Sign::Zero && p != r && p != s && on_segment(p, r, s)) {
            out.push_back({D(), D(1.0), false, f});
        }
        if (o_q == Sign::Zero && q != r && q != s && on_segment(q, r, s)) {
            out.push_back({D(1.0), D(1.0), false, f});
        }
    }
    std::sort(out.begin(), out.end(), before);
    out.erase(std::unique(out.begin(), out.end(), same_place), out.end());
    return out;
}

// Whether the piece of the edge pq (of a counter-clockwise polygon) that leaves the meeting
// `at` in the direction `sense` (+1 towards q, -1 towards p) has that polygon's interior beside
// it inside the interior of b: the piece is inside b, or runs along an edge of b with b's
// interior on the same side.
template <class P>
bool piece_inside(const P& p, const P& q, int sense, const Meeting& at, const std::vector<P>& b) {
    const std::size_t m = b.size();
    // Signs of (v - u) x d and (v - u) . d for the piece's direction d = sense (q - p).
    const auto turn = [&](const P& u, const P& v) { return sense * to_int(cross(u, v, p, q).sign()); };
    const auto ahead = [&](const P& u, const P& v) { return sense * to_int(dot(u, v, p, q).sign()) > 0; };
    const auto same_way = [&](const P& u, const P& v) { return dot(u, v, p, q).sign() == Sign::Positive; };
    if (!at.at_vertex) {  // through the inside of b's edge rs: b's interior is on its left
        const P &r = b[at.index], &s = b[(at.index + 1) % m];
        const int t = turn(r, s);
        return t > 0 || (t == 0 && same_way(r, s));
    }
    const P &u = b[(at.index + m - 1) % m], &v = b[at.index], &w = b[(at.index + 1) % m];
    // Along the edge v w or u v: interiors on one side when the edges point the same way.
    if (turn(v, w) == 0 && ahead(v, w)) return same_way(v, w);
    if (turn(v, u) == 0 && ahead(v, u)) return same_way(u, v);
    // Strictly inside the interior angle at v, from w - v counter-clockwise to u - v.
    const int after_w = turn(v, w), before_u = -turn(v, u);  // d left of w - v; d right of u - v
    switch (orient2d(u, v, w)) {
        case Sign::Positive: return after_w > 0 && before_u > 0;     // convex
        case Sign::Zero: return after_w > 0;                         // straight
        case Sign::Negative: return !(after_w <= 0 && before_u <= 0);  // reflex: not in the rest
    }
    return false;
}

template <class P>
bool strictly_inside(std::span<const P> polygon, const Vec2& x) {
    P point;
    as_point(x, point);
    return in_closed_polygon(polygon, point) && !on_boundary(polygon, point);
}

// A point strictly inside both polygons beside the piece [t0, t1] of a's edge pq (whose side
// towards a's interior lies in b's interior): its middle moved into a by half the piece's length,
// a quarter, ..., as long as the doubles hold such a point; else the middle itself, rounded.
template <class P>
Vec2 witness(const P& exact_p, const P& exact_q, double t0, double t1, std::span<const P> a, std::span<const P> b) {
    const Vec2 p = rounded(exact_p), q = rounded(exact_q);
    const Vec2 d = q - p, inward(-d.y(), d.x());
    const Vec2 middle = p + 0.5 * (t0 + t1) * d;
    double step = 0.5 * (t1 - t0);
    for (int k = 0; k < 80 && step > 0.0; ++k, step *= 0.5) {
        const Vec2 x = middle + step * inward;
        if (x.allFinite() && strictly_inside(a, x) && strictly_inside(b, x)) return x;
    }
    return middle;
}

double parameter(const Meeting& m) {
    const std::int64_t k = m.den.exponent();
    return m.num.to_double_scaled(k) / m.den.to_double_scaled(k);
}

// A point of the overlap found from a's edges cut by b's boundary (both counter-clockwise), and
// whether b's boundary meets a's at all.
template <class P>
std::optional<Vec2> overlap_along(const std::vector<P>& a, const std::vector<P>& b, bool& met) {
    const EdgeGrid grid(std::span<const P>(b), 0.0);
    std::vector<std::size_t> candidates;
    const std::size_t n = a.size();
    for (std::size_t i = 0; i < n; ++i) {
        const P &p = a[i], &q = a[(i + 1) % n];
        grid.near_segment(rounded(p), rounded(q), candidates);
        const std::vector<Meeting> cuts = meetings(p, q, b, candidates);
        if (cuts.empty()) continue;
        met = true;
        // The pieces between 0, the cuts and 1, each read at an end that is a cut.
        for (std::size_t k = 0; k <= cuts.size(); ++k) {
            const Meeting* left = k > 0 ? &cuts[k - 1] : nullptr;
            const Meeting* right = k < cuts.size() ? &cuts[k] : nullptr;
            const bool at_start = left == nullptr && right->num.is_zero();
            const bool at_end = right == nullptr && compare(left->num, left->den) == 0;
            if (at_start || at_end) continue;  // an empty piece: the cut is the edge's end
            const bool inside = left != nullptr ? piece_inside(p, q, +1, *left, b) : piece_inside(p, q, -1, *right, b);
            if (inside) {
                return witness(p, q, left ? parameter(*left) : 0.0, right ? parameter(*right) : 1.0, std::span<const P>(a),
                               std::span<const P>(b));
            }
        }
    }
    return std::nullopt;
}

template <class P>
std::optional<Vec2> overlap(std::span<const P> a_given, std::span<const P> b_given) {
    const std::vector<P> a = counter_clockwise_copy(a_given), b = counter_clockwise_copy(b_given);
    bool met = false;
    if (auto x = overlap_along(a, b, met)) return x;
    if (auto x = overlap_along(b, a, met)) return x;
    if (met) return std::nullopt;
    // The boundaries do not meet: one lies inside the other, or they are apart.
    const std::span<const P> sa(a), sb(b);
    if (in_closed_polygon(sb, a[0]) && !on_boundary(sb, a[0])) return witness(a[0], a[1], 0.0, 1.0, sa, sb);
    if (in_closed_polygon(sa, b[0]) && !on_boundary(sa, b[0])) return witness(b[0], b[1], 0.0, 1.0, sb, sa);
    return std::nullopt;
}

}  // namespace

std::optional<Vec2> polygons_overlap(std::span<const Vec2> a, std::span<const Vec2> b) { return overlap(a, b); }
std::optional<Vec2> polygons_overlap(std::span<const ExactPoint> a, std::span<const ExactPoint> b) { return overlap(a, b); }

}  // namespace momentlab
