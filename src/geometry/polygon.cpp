#include "momentlab/geometry/polygon.hpp"
#include "../core/error_free.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "momentlab/core/dyadic.hpp"
#include "momentlab/core/predicates.hpp"

namespace momentlab {
namespace {

Vec3 lift(const Vec2& p) { return Vec3(p.x(), p.y(), 1.0); }

// c lies on the closed segment ab, given that a, b, c are collinear (exact comparisons).
template <class P>
bool within(const P& a, const P& b, const P& c) {
    return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= c.y() &&
           c.y() <= std::max(a.y(), b.y());
}

// The closed segments pq and rs share a point.
template <class P>
bool segments_meet(const P& p, const P& q, const P& r, const P& s) {
    const Sign o1 = orient2d(p, q, r), o2 = orient2d(p, q, s), o3 = orient2d(r, s, p), o4 = orient2d(r, s, q);
    if (o1 != Sign::Zero && o2 != Sign::Zero && o3 != Sign::Zero && o4 != Sign::Zero) return o1 != o2 && o3 != o4;
    return (o1 == Sign::Zero && within(p, q, r)) || (o2 == Sign::Zero && within(p, q, s)) ||
           (o3 == Sign::Zero && within(r, s, p)) || (o4 == Sign::Zero && within(r, s, q));
}

double distance_to_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
    const Vec2 d = b - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (a + t * d - p).norm();
}

// The orientation of three points, (b - a) x (c - a), over any number type.
struct Orientation {
    template <class T>
    T operator()(const std::array<T, 2>& a, const std::array<T, 2>& b, const std::array<T, 2>& c) const {
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }
};

std::array<Approx, 2> exactly(const Vec2& p) { return {Approx::exact(p.x()), Approx::exact(p.y())}; }

}  // namespace

Sign orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
    // The sign of (b - a) x (c - a): the filter adaptor's certified approximation first (its
    // bound, from the operations, is Shewchuk's: "Adaptive precision floating-point arithmetic
    // and fast robust geometric predicates", 1997). Where it cannot decide: a 2x2 minor when the
    // four differences are exact doubles (points on a grid, or along an axis-parallel edge, where
    // the orientation is often exactly zero), the lifted 3x3 determinant otherwise. Exact for
    // every finite input.
    Sign s = Sign::Zero;
    if (filter_sign(Orientation{}, s, exactly(a), exactly(b), exactly(c))) return s;
    using detail::exact_difference;
    const std::optional<double> ux = exact_difference(b.x(), a.x()), uy = exact_difference(b.y(), a.y());
    const std::optional<double> vx = exact_difference(c.x(), a.x()), vy = exact_difference(c.y(), a.y());
    if (ux && uy && vx && vy) return minor_sign(Vec3(*ux, *uy, 0.0), Vec3(*vx, *vy, 0.0), 0, 1);
    return det_sign(lift(a), lift(b), lift(c));
}

Sign orient2d(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
    return ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x())).sign();
}

namespace {

template <class P>
bool turns_counter_clockwise(std::span<const P> p) {
    const std::size_t n = p.size();
    const auto leftmost = static_cast<std::size_t>(std::min_element(p.begin(), p.end(), [](const P& a, const P& b) {
                                                     return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
                                                 }) - p.begin());
    return orient2d(p[(leftmost + n - 1) % n], p[leftmost], p[(leftmost + 1) % n]) == Sign::Positive;
}

template <class P>
bool in_closed(std::span<const P> polygon, const P& p) {
    // Winding number with exact orientations (Sunday's crossing rule); the boundary first.
    int winding = 0;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const P& a = polygon[i];
        const P& b = polygon[(i + 1) % n];
        const Sign side = orient2d(a, b, p);
        if (side == Sign::Zero && within(a, b, p)) return true;
        if (a.y() <= p.y()) {
            if (b.y() > p.y() && side == Sign::Positive) ++winding;
        } else if (b.y() <= p.y() && side == Sign::Negative) {
            --winding;
        }
    }
    return winding != 0;
}

template <class P>
bool lex_less(const P& a, const P& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); }

// An edge of the sweep: its lexicographically smaller end `l`, larger end `r`, and its number.
template <class P>
struct SweepEdge {
    P l, r;
    std::size_t index = 0;
};

// Where q lies from the edge e: +1 above its line (a vertical edge: above its top), -1 below, 0 on.
template <class P>
int side(const SweepEdge<P>& e, const P& q) {
    if (e.l.x() == e.r.x()) return q.y() > e.r.y() ? 1 : (q.y() < e.l.y() ? -1 : 0);
    const Sign s = orient2d(e.l, e.r, q);
    return s == Sign::Positive ? 1 : (s == Sign::Negative ? -1 : 0);
}

// +1 when b rises more steeply than a (directions l -> r, all in x >= 0), -1 less, 0 parallel. Exact.
template <class P>
int steeper(const SweepEdge<P>& a, const SweepEdge<P>& b) {
    using D = Dyadic;
    const D c = (D(a.r.x()) - D(a.l.x())) * (D(b.r.y()) - D(b.l.y())) - (D(a.r.y()) - D(a.l.y())) * (D(b.r.x()) - D(b.l.x()));
    return c.sign() == Sign::Positive ? 1 : (c.sign() == Sign::Negative ? -1 : 0);
}

// a below b at the sweep line, judged where the later of them starts: while no two edges have
// met, the order of the edges crossing the sweep line does not change between events.
template <class P>
bool below(const SweepEdge<P>& a, const SweepEdge<P>& b) {
    if (a.index == b.index) return false;
    const bool b_later = !lex_less(b.l, a.l);
    const SweepEdge<P>& first = b_later ? a : b;
    const SweepEdge<P>& later = b_later ? b : a;
    int up = side(first, later.l);  // +1: the later edge lies above the first
    if (up == 0) up = steeper(first, later);
    if (up == 0) up = later.index > first.index ? 1 : -1;  // collinear: they overlap (and meet)
    return b_later ? up > 0 : up < 0;
}

// Two edges that meet other than at the vertex they share, found by a sweep from left to right
// (Shamos and Hoey, "Geometric intersection problems", FOCS 1976): an edge is compared with its
// neighbours along the sweep line when it enters and when it leaves, so the first meeting is
// seen before the order could go wrong. Needs distinct vertices, and their numbers in sweep order
// (lex_less). O(n log n), exact.
template <class P>
std::optional<std::pair<std::size_t, std::size_t>> meeting_edges(std::span<const P> p, const std::vector<std::size_t>& order) {
    const std::size_t n = p.size();
    std::vector<SweepEdge<P>> edges(n);
    for (std::size_t i = 0; i < n; ++i) {
        const P &a = p[i], &b = p[(i + 1) % n];
        edges[i] = lex_less(a, b) ? SweepEdge<P>{a, b, i} : SweepEdge<P>{b, a, i};
    }
    const auto adjacent = [n](std::size_t i, std::size_t j) { return (i + 1) % n == j || (j + 1) % n == i; };
    const auto cmp = [&](std::size_t i, std::size_t j) { return below(edges[i], edges[j]); };
    std::set<std::size_t, decltype(cmp)> status(cmp);
    std::vector<typename std::set<std::size_t, decltype(cmp)>::iterator> where(n, status.end());
    std::optional<std::pair<std::size_t, std::size_t>> found;
    const auto check = [&](std::size_t i, std::size_t j) {
        if (found || adjacent(i, j)) return;
        const SweepEdge<P> &a = edges[i], &b = edges[j];
        if (segments_meet(a.l, a.r, b.l, b.r)) found = std::pair(std::min(i, j), std::max(i, j));
    };
    for (std::size_t v : order) {
        const std::size_t in = (v + n - 1) % n, out = v;  // the edges ending and starting at vertex v
        for (std::size_t e : {in, out}) {  // first the edges that end here (v is their right end)
            if (edges[e].r != p[v]) continue;
            auto it = where[e];
            if (it != status.begin() && std::next(it) != status.end()) check(*std::prev(it), *std::next(it));
            status.erase(it);
            where[e] = status.end();
        }
        for (std::size_t e : {in, out}) {
            if (edges[e].l != p[v]) continue;
            const auto it = status.insert(e).first;
            where[e] = it;
            if (it != status.begin()) check(*std::prev(it), e);
            if (std::next(it) != status.end()) check(e, *std::next(it));
        }
        if (found) return found;
    }
    return found;
}

bool finite(const Vec2& p) { return p.allFinite(); }
bool finite(const ExactPoint&) { return true; }

template <class P>
std::string problem_of(std::span<const P> polygon) {
    const std::size_t n = polygon.size();
    if (n < 3) return "expected a polygon of at least 3 vertices, got " + std::to_string(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (!finite(polygon[i])) return "vertex " + std::to_string(i) + " is not finite";
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (polygon[i] == polygon[(i + 1) % n]) {
            return "vertices " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                   " coincide (expected a simple polygon)";
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        // The next edge b c may only touch this one at b: not fold back along it.
        const P &a = polygon[i], &b = polygon[(i + 1) % n], &c = polygon[(i + 2) % n];
        if (orient2d(a, b, c) == Sign::Zero && (within(a, b, c) || within(b, c, a))) {
            return "edges " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                   " fold back along each other (expected a simple polygon of non-zero area)";
        }
    }
    const auto cross_or_touch = [](std::size_t i, std::size_t j) {
        return "edges " + std::to_string(i) + " and " + std::to_string(j) +
               " cross or touch (expected a simple polygon, either orientation)";
    };
    // Two vertices at one point (not consecutive: checked above): the edges leaving them touch.
    // Sorted as (point, number) records rather than numbers looked up in the polygon: the
    // comparisons read neighbouring memory.
    struct Key {
        P p;
        std::size_t i;
    };
    std::vector<Key> keys(n);
    for (std::size_t i = 0; i < n; ++i) keys[i] = {polygon[i], i};
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
        return a.p.x() < b.p.x() || (a.p.x() == b.p.x() && (a.p.y() < b.p.y() || (a.p.y() == b.p.y() && a.i < b.i)));
    });
    std::vector<std::size_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = keys[k].i;
    keys = {};
    for (std::size_t k = 0; k + 1 < n; ++k) {
        if (polygon[order[k]] == polygon[order[k + 1]]) return cross_or_touch(order[k], order[k + 1]);
    }
    if (const auto pair = meeting_edges(polygon, order)) return cross_or_touch(pair->first, pair->second);
    return {};
}

// p within `distance` (exact; its double `rounded_distance`) of the closed segment ab.
template <class P, class Distance>
bool within_distance(const P& p, const P& a, const P& b, const Distance& distance, double rounded_distance) {
    // The float distance errs by a few units in the last place of the coordinates involved (and
    // of their rounding, for exact points); far beyond that margin the answer is certain.
    const Vec2 rp = rounded(p), ra = rounded(a), rb = rounded(b);
    const double scale = rp.cwiseAbs().maxCoeff() + ra.cwiseAbs().maxCoeff() + rb.cwiseAbs().maxCoeff();
    if (distance_to_segment(ra, rb, rp) > 2.0 * rounded_distance + 1e-6 * scale) return false;
    using D = Dyadic;
    const D ux = D(p.x()) - D(a.x()), uy = D(p.y()) - D(a.y());
    const D vx = D(b.x()) - D(a.x()), vy = D(b.y()) - D(a.y());
    const D exact_distance(distance);
    const D d2 = exact_distance * exact_distance;
    const D uu = ux * ux + uy * uy, uv = ux * vx + uy * vy, vv = vx * vx + vy * vy;
    if (uv.sign() != Sign::Positive || vv.is_zero()) return compare(uu, d2) <= 0;  // closest to a
    if (compare(uv, vv) >= 0) {                                                      // closest to b
        const D wx = D(p.x()) - D(b.x()), wy = D(p.y()) - D(b.y());
        return compare(wx * wx + wy * wy, d2) <= 0;
    }
    const D cross = ux * vy - uy * vx;  // distance to the line: |cross| / |v|
    return compare(cross * cross, d2 * vv) <= 0;
}

template <class P, class Distance>
bool within_distance_of_outline(std::span<const P> polygon, const P& p, const Distance& distance, double rounded_distance) {
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        if (within_distance(p, polygon[i], polygon[(i + 1) % polygon.size()], distance, rounded_distance)) return true;
    }
    return false;
}

}  // namespace

std::vector<Vec2> rounded(std::span<const ExactPoint> polygon) {
    std::vector<Vec2> out;
    out.reserve(polygon.size());
    for (const ExactPoint& x : polygon) out.push_back(rounded(x));
    return out;
}

std::string polygon_problem(std::span<const Vec2> polygon) { return problem_of(polygon); }
std::string polygon_problem(std::span<const ExactPoint> polygon) { return problem_of(polygon); }
bool is_counter_clockwise(std::span<const Vec2> p) { return turns_counter_clockwise(p); }
bool is_counter_clockwise(std::span<const ExactPoint> p) { return turns_counter_clockwise(p); }
bool in_closed_polygon(std::span<const Vec2> polygon, const Vec2& p) { return in_closed(polygon, p); }
bool in_closed_polygon(std::span<const ExactPoint> polygon, const ExactPoint& p) { return in_closed(polygon, p); }

bool within_distance_of_segment(const Vec2& p, const Vec2& a, const Vec2& b, double distance) {
    return within_distance(p, a, b, distance, distance);
}
bool within_distance_of_segment(const Vec2& p, const Vec2& a, const Vec2& b, const Dyadic& distance, double rounded_distance) {
    return within_distance(p, a, b, distance, rounded_distance);
}
bool within_distance_of_segment(const ExactPoint& p, const ExactPoint& a, const ExactPoint& b, const Dyadic& distance,
                                double rounded_distance) {
    return within_distance(p, a, b, distance, rounded_distance);
}
bool within_distance_of_boundary(std::span<const Vec2> polygon, const Vec2& p, double distance) {
    return within_distance_of_outline(polygon, p, distance, distance);
}
bool within_distance_of_boundary(std::span<const ExactPoint> polygon, const ExactPoint& p, const Dyadic& distance,
                                 double rounded_distance) {
    return within_distance_of_outline(polygon, p, distance, rounded_distance);
}

double distance_to_boundary(std::span<const Vec2> polygon, const Vec2& p) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        best = std::min(best, distance_to_segment(polygon[i], polygon[(i + 1) % polygon.size()], p));
    }
    return best;
}

EdgeGrid::EdgeGrid(std::span<const Vec2> p, double distance) {
    const std::size_t m = p.size();
    edge_count_ = m;
    if (m == 0 || !(distance >= 0.0) || !std::isfinite(distance) ||
        std::any_of(p.begin(), p.end(), [](const Vec2& v) { return !v.allFinite(); })) {
        throw std::invalid_argument("EdgeGrid: expected finite vertices and a finite distance >= 0");
    }
    lo_ = hi_ = p[0];
    double length = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
        lo_ = lo_.cwiseMin(p[k]);
        hi_ = hi_.cwiseMax(p[k]);
        length += (p[(k + 1) % m] - p[k]).norm();
    }
    const Vec2 extent = hi_ - lo_;
    margin_ = distance + 1e-9 * (lo_.cwiseAbs().maxCoeff() + hi_.cwiseAbs().maxCoeff() + extent.maxCoeff());
    cell_ = std::max({length / static_cast<double>(m), 2.0 * margin_, extent.maxCoeff() / static_cast<double>(4 * m)});
    if (!(cell_ > 0.0) || !std::isfinite(cell_)) cell_ = 1.0;  // a point, or lengths beyond the doubles
    // At most about 4 m cells: coarser for outlines whose edges are short beside their box.
    while ((extent.x() / cell_ + 1.0) * (extent.y() / cell_ + 1.0) > 4.0 * static_cast<double>(m) + 16.0) cell_ *= 1.5;
    nx_ = static_cast<std::size_t>(extent.x() / cell_) + 1;
    ny_ = static_cast<std::size_t>(extent.y() / cell_) + 1;
    std::vector<std::pair<std::size_t, std::size_t>> entries;  // (cell, edge)
    for (std::size_t k = 0; k < m; ++k) {
        const Vec2 &a = p[k], &b = p[(k + 1) % m];
        const std::size_t pieces = static_cast<std::size_t>((b - a).norm() / cell_) + 1;
        const std::size_t first = entries.size();
        for (std::size_t i = 0; i < pieces; ++i) {
            const double parts = static_cast<double>(pieces);
            const Vec2 u = a + (b - a) * (static_cast<double>(i) / parts);
            const Vec2 v = i + 1 == pieces ? b : Vec2(a + (b - a) * (static_cast<double>(i + 1) / parts));
            const Vec2 box_lo = u.cwiseMin(v).array() - margin_, box_hi = u.cwiseMax(v).array() + margin_;
            const auto [x0, y0] = index(box_lo);
            const auto [x1, y1] = index(box_hi);
            for (std::size_t x = x0; x <= x1; ++x) {
                for (std::size_t y = y0; y <= y1; ++y) entries.emplace_back(x * ny_ + y, k);
            }
        }
        std::sort(entries.begin() + static_cast<std::ptrdiff_t>(first), entries.end());
        entries.erase(std::unique(entries.begin() + static_cast<std::ptrdiff_t>(first), entries.end()), entries.end());
    }
    std::stable_sort(entries.begin(), entries.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    start_.assign(nx_ * ny_ + 1, 0);
    for (const auto& e : entries) ++start_[e.first + 1];
    for (std::size_t c = 0; c < nx_ * ny_; ++c) start_[c + 1] += start_[c];
    edges_.reserve(entries.size());
    for (const auto& e : entries) edges_.push_back(e.second);  // per cell, increasing edge number
}

std::span<const std::size_t> EdgeGrid::near(const Vec2& q) const {
    if ((q.array() < lo_.array() - margin_).any() || (q.array() > hi_.array() + margin_).any()) return {};
    const auto [x, y] = index(q);
    const std::size_t c = x * ny_ + y;
    return {edges_.data() + start_[c], start_[c + 1] - start_[c]};
}

void EdgeGrid::near_segment(const Vec2& a, const Vec2& b, std::vector<std::size_t>& out) const {
    out.clear();
    // The part of ab within the polygon's box grown by the margin, and by an allowance for the
    // rounding of the segment's own points (parameters found in floating point).
    const double slack = margin_ + 1e-9 * (a.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff());
    const Vec2 d = b - a;
    double t0 = 0.0, t1 = 1.0;
    for (int k = 0; k < 2; ++k) {
        const double lo = lo_[k] - slack, hi = hi_[k] + slack;
        if (d[k] == 0.0) {
            if (a[k] < lo || a[k] > hi) return;
            continue;
        }
        const double u = (lo - a[k]) / d[k], v = (hi - a[k]) / d[k];
        t0 = std::max(t0, std::min(u, v));
        t1 = std::min(t1, std::max(u, v));
    }
    if (!(t0 <= t1)) return;
    const Vec2 from = a + t0 * d, to = a + t1 * d;
    // Pieces about a cell long, but no more than a line crosses cells (nx + ny): where the slack
    // dwarfs the cells (a polygon of edges 1e-16 touched by one of length 1) longer pieces whose
    // boxes cover more cells, not 10^16 of them.
    const double cells_along = (to - from).norm() / cell_;
    const std::size_t most = nx_ + ny_ + 1;
    const std::size_t pieces = cells_along < static_cast<double>(most) ? static_cast<std::size_t>(cells_along) + 1 : most;
    for (std::size_t i = 0; i < pieces; ++i) {
        const double parts = static_cast<double>(pieces);
        const Vec2 u = from + (to - from) * (static_cast<double>(i) / parts);
        const Vec2 v = i + 1 == pieces ? to : Vec2(from + (to - from) * (static_cast<double>(i + 1) / parts));
        const auto [x0, y0] = index(u.cwiseMin(v).array() - slack);
        const auto [x1, y1] = index(u.cwiseMax(v).array() + slack);
        if (x0 == 0 && y0 == 0 && x1 + 1 == nx_ && y1 + 1 == ny_) {  // every cell: every edge, once
            out.resize(edge_count_);
            std::iota(out.begin(), out.end(), std::size_t{0});
            return;
        }
        for (std::size_t x = x0; x <= x1; ++x) {
            for (std::size_t y = y0; y <= y1; ++y) {
                const std::size_t c = x * ny_ + y;
                out.insert(out.end(), edges_.begin() + static_cast<std::ptrdiff_t>(start_[c]),
                           edges_.begin() + static_cast<std::ptrdiff_t>(start_[c + 1]));
            }
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

std::pair<std::size_t, std::size_t> EdgeGrid::index(const Vec2& q) const {
    const auto clamp = [](double t, std::size_t n) {  // (in doubles first: t may be far beyond the cells)
        return !(t > 0.0) ? std::size_t{0} : (t >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::size_t>(t));
    };
    return {clamp((q.x() - lo_.x()) / cell_, nx_), clamp((q.y() - lo_.y()) / cell_, ny_)};
}

}  // namespace momentlab
