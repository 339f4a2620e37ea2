#include "momentlab/mechanics/find_contacts.hpp"

#include "momentlab/core/approx.hpp"
#include "momentlab/core/predicates.hpp"
#include "momentlab/geometry/polygon.hpp"
#include "../core/error_free.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <unordered_map>
#include <span>
#include <utility>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace momentlab {
namespace {

// The polygon (simple, checked by the caller) counter-clockwise.
template <class P>
std::vector<P> counter_clockwise(std::span<const P> p) {
    std::vector<P> q(p.begin(), p.end());
    if (!is_counter_clockwise(p)) std::reverse(q.begin(), q.end());
    return q;
}

// Outward unit normal of the counter-clockwise edge a -> b (an edge whose squared length would
// underflow or overflow first brought near 1 by a power of two, exactly: an edge 2^-1000 long).
Vec2 outward(const Vec2& a, const Vec2& b) {
    Vec2 d = b - a;
    const double m = d.cwiseAbs().maxCoeff();
    if (m < 0x1p-500 || m > 0x1p500) d = Vec2(std::ldexp(d.x(), -std::ilogb(m)), std::ldexp(d.y(), -std::ilogb(m)));
    return Vec2(d.y(), -d.x()) / d.norm();
}

struct CellHash {
    std::size_t operator()(const std::pair<std::int64_t, std::int64_t>& c) const {
        return std::hash<std::int64_t>()(c.first) * 0x9E3779B97F4A7C15ull ^ std::hash<std::int64_t>()(c.second);
    }
};

// Index i of a polygon of n vertices made counter-clockwise, as given: a vertex, or the edge from
// vertex i to i + 1 (reversed: the edge from given vertex n - 1 - i to n - 2 - i).
std::size_t given_vertex(std::size_t i, std::size_t n, bool reversed) { return reversed ? n - 1 - i : i; }
std::size_t given_edge(std::size_t i, std::size_t n, bool reversed) { return reversed ? (2 * n - 2 - i) % n : i; }

// Vertices of `touching` lying on edges of `touched` (both counter-clockwise; `*_reversed` says
// whether they were given clockwise); `body_is_touching` gives the normal's sense. Each contact's
// origin goes to `origins`, against obstacle `obstacle`.
// Whether x lies beyond the line of the counter-clockwise edge ab, on its inner side, by more
// than `distance`: (b - a) x (x - a) > distance |b - a|, exactly.
template <class P>
bool inside_line_beyond(const P& x, const P& a, const P& b, const Dyadic& distance) {
    using D = Dyadic;
    const D dx = D(b.x()) - D(a.x()), dy = D(b.y()) - D(a.y());
    const D cross = dx * (D(x.y()) - D(a.y())) - dy * (D(x.x()) - D(a.x()));
    if (cross.sign() != Sign::Positive) return false;
    return compare(cross * cross, distance * distance * (dx * dx + dy * dy)) > 0;
}

// The edge a -> b (counter-clockwise) whose perpendicular is a contact's normal: outward when
// `outward`, else inward.
template <class P>
struct TouchedEdge {
    P a, b;
    bool outward;
};

// A coordinate as the filter reads it (core/approx.hpp): a double itself, an exact number its
// rounding.
Approx approx_of(double x) { return Approx::exact(x); }
Approx approx_of(const Dyadic& x) { return approximate(x); }

// The sign of f on the perpendiculars' coordinates: on their approximations where the bound
// decides it, else in Dyadic arithmetic.
template <class F, class P>
Sign normals_sign(const F& f, const TouchedEdge<P>& e1, const TouchedEdge<P>& e2) {
    const auto perpendicular = [](const TouchedEdge<P>& e, auto number) {  // (d.y, -d.x), d = b - a, outward
        using T = decltype(number(e.a.x()));
        const T dx = number(e.b.x()) - number(e.a.x()), dy = number(e.b.y()) - number(e.a.y());
        return e.outward ? std::array<T, 2>{dy, T(-dx)} : std::array<T, 2>{T(-dy), dx};
    };
    Sign s = Sign::Zero;
    const auto approx = [](const auto& x) { return approx_of(x); };
    if (certified_sign(f(perpendicular(e1, approx), perpendicular(e2, approx), approx), s)) return s;
    const auto exact = [](const auto& x) { return Dyadic(x); };
    return f(perpendicular(e1, exact), perpendicular(e2, exact), exact).sign();
}

// The sign of c = 1 - d^2 / 2 in normals_within.
Sign normals_threshold(double d) { return (Dyadic(1.0) - Dyadic(d) * Dyadic(d) * Dyadic(0.5)).sign(); }

// The perpendicular of a touched edge in doubles, when its coordinates' differences are exact
// (Knuth's two-sum leaves no error): then parallel normals are told by the exact predicates on
// doubles (the edges of a floor drawn with many collinear vertices, whose contacts at shared
// vertices have equal normals; the filter below cannot certify a zero).
std::optional<Vec2> exact_perpendicular(const TouchedEdge<Vec2>& e) {
    const std::optional<double> dx = detail::exact_difference(e.b.x(), e.a.x()), dy = detail::exact_difference(e.b.y(), e.a.y());
    if (!dx || !dy) return std::nullopt;
    return e.outward ? Vec2(*dy, -*dx) : Vec2(-*dy, *dx);
}
std::optional<Vec2> exact_perpendicular(const TouchedEdge<ExactPoint>&) { return std::nullopt; }

// Whether the unit normals n_i = e_i / |e_i| of two touched edges' perpendiculars e_i lie within
// d of each other, exactly: |n_1 - n_2|^2 = 2 - 2 n_1 . n_2 <= d^2, that is
// s = e_1 . e_2 >= c |e_1| |e_2| with c = 1 - d^2 / 2: for c <= 0, s >= 0 or s^2 <= c^2 m, and
// for c > 0, s > 0 and s^2 >= c^2 m, with m = |e_1|^2 |e_2|^2. `c` is the sign of c
// (normals_threshold).
template <class P>
bool normals_within(const TouchedEdge<P>& e1, const TouchedEdge<P>& e2, double d, Sign c) {
    if (const std::optional<Vec2> u = exact_perpendicular(e1), v = exact_perpendicular(e2); u && v && cross2_sign(*u, *v) == Sign::Zero) {
        return dot_sign(Vec3(u->x(), u->y(), 0.0), Vec3(v->x(), v->y(), 0.0)) == Sign::Positive || d >= 2.0;  // (|n_1 - n_2| 0 or 2)
    }
    const auto dot = [](const auto& u, const auto& v, const auto&) { return u[0] * v[0] + u[1] * v[1]; };
    const Sign s = normals_sign(dot, e1, e2);
    if (c != Sign::Positive && s != Sign::Negative) return true;
    if (c == Sign::Positive && s != Sign::Positive) return false;
    const auto gap = [&](const auto& u, const auto& v, const auto& number) {  // s^2 - c^2 m
        const auto cc = number(1.0) - number(d) * number(d) * number(0.5);
        return dot(u, v, number) * dot(u, v, number) - cc * cc * (dot(u, u, number) * dot(v, v, number));
    };
    const Sign g = normals_sign(gap, e1, e2);
    return c == Sign::Positive ? g != Sign::Negative : g != Sign::Positive;
}

template <class P>
void vertex_on_edge(const std::vector<P>& touching, const std::vector<P>& touched, bool body_is_touching, bool touching_reversed,
                    bool touched_reversed, std::size_t obstacle, const ContactFinding& o, double point_distance,
                    const Dyadic& distance, std::vector<Contact>& out, std::vector<ContactOrigin>& origins,
                    std::vector<P>& points, std::vector<TouchedEdge<P>>& edges) {
    const std::size_t n = touching.size(), m = touched.size();
    const EdgeGrid grid(std::span<const P>(touched), point_distance);
    for (std::size_t i = 0; i < n; ++i) {
        const P& v = touching[i];
        for (std::size_t k : grid.near(rounded(v))) {
            const P& a = touched[k];
            const P& b = touched[(k + 1) % m];
            if (!within_distance_of_segment(v, a, b, distance, point_distance)) continue;
            // Vertex on vertex: an obstacle vertex at a body vertex is left to that body
            // vertex, whose contact takes the supporting obstacle edge's normal.
            if (!body_is_touching && (within_distance_of_segment(v, a, a, distance, point_distance) ||
                                      within_distance_of_segment(v, b, b, distance, point_distance))) {
                continue;
            }
            // The neighbours of v must stay outside the touched edge's line (within the distance).
            if (inside_line_beyond(touching[(i + n - 1) % n], a, b, distance) ||
                inside_line_beyond(touching[(i + 1) % n], a, b, distance)) {
                continue;
            }
            // Into the moving body: the obstacle's outward normal, or the body edge's inward one
            // (in doubles: contact_as_typed makes it exact for decimals).
            const Vec2 out_n = outward(rounded(a), rounded(b));
            const Vec2 normal = body_is_touching ? out_n : Vec2(-out_n);
            out.push_back(Contact::make(rounded(v), normal, o.mu, o.mu_kinetic));
            points.push_back(v);
            edges.push_back({a, b, body_is_touching});
            origins.push_back({body_is_touching, obstacle, given_vertex(i, n, touching_reversed), given_edge(k, m, touched_reversed)});
        }
    }
}

// The shortest "%g" text that reads back as x.
std::string shortest(double x) {
    char text[32];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, x);
        if (std::strtod(text, nullptr) == x) break;
    }
    return text;
}

void check_distance(const ContactFinding& options) {
    if (!(options.distance >= 0.0)) throw std::invalid_argument("find_contacts: distance must be >= 0");
}

}  // namespace

Contact contact_as_typed(const Contact& found, const Rational2& v, const Rational2& a, const Rational2& b, const Rational& mu,
                         bool scaled) {
    if (!scaled && is_double(v) && is_double(a) && is_double(b)) {
        if (mu.is_double()) return found;
        return Contact::make(rational(found.point), rational(found.normal), mu, std::nullopt, found.name);
    }
    Rational2 n{b[1] - a[1], a[0] - b[0]};  // (d.y, -d.x) for the edge d = b - a
    const Rational along = n[0] * Rational(found.normal.x()) + n[1] * Rational(found.normal.y());
    if (along.sign() == Sign::Negative) n = {-n[0], -n[1]};
    const Rational largest = compare(n[0] * n[0], n[1] * n[1]) >= 0 ? n[0] : n[1];
    const Rational size = largest.sign() == Sign::Negative ? -largest : largest;
    return Contact::make(v, Rational2{n[0] / size, n[1] / size}, mu, std::nullopt, found.name);
}

std::optional<ScaledPolygons> scaled_polygons(const std::vector<std::vector<Rational2>>& exact) {
    const bool doubles = std::all_of(exact.begin(), exact.end(), [](const std::vector<Rational2>& p) {
        return std::all_of(p.begin(), p.end(), [](const Rational2& v) { return is_double(v); });
    });
    if (doubles) return std::nullopt;
    std::vector<Rational> all;
    for (const auto& p : exact) {
        for (const Rational2& v : p) all.insert(all.end(), v.begin(), v.end());
    }
    ScaledPolygons out;
    std::vector<Dyadic> cleared = clear_denominators(all, &out.scale);
    const bool fit = out.scale.fits_double() && std::all_of(cleared.begin(), cleared.end(), [](const Dyadic& x) { return x.fits_double(); });
    // Exact points: brought near 1 by a power of two (exact), so that their doubles, which the
    // grids and filters read, are finite however many digits the decimals have.
    if (!fit) {
        std::int64_t largest = std::numeric_limits<std::int64_t>::min();
        for (const Dyadic& x : cleared) {
            if (!x.is_zero()) largest = std::max(largest, x.exponent());
        }
        if (largest != std::numeric_limits<std::int64_t>::min()) {
            for (Dyadic& x : cleared) x = x.scaled(-largest);
            out.scale = out.scale.scaled(-largest);
        }
    }
    std::size_t at = 0;
    for (const auto& p : exact) {
        if (fit) {
            Polygon& q = out.doubles.emplace_back();
            for (std::size_t i = 0; i < p.size(); ++i, at += 2) q.emplace_back(cleared[at].to_double(), cleared[at + 1].to_double());
        } else {
            ExactPolygon& q = out.exact.emplace_back();
            for (std::size_t i = 0; i < p.size(); ++i, at += 2) q.push_back({cleared[at], cleared[at + 1]});
        }
    }
    return out;
}

std::vector<Contact> find_contacts(const Polygon& body, const std::vector<Polygon>& obstacles,
                                   const ContactFinding& options, std::vector<ContactOrigin>* origins) {
    check_distance(options);
    for (std::size_t i = 0; i <= obstacles.size(); ++i) {
        const Polygon& p = i == 0 ? body : obstacles[i - 1];
        const std::string problem = polygon_problem(p);
        if (!problem.empty()) {
            throw std::invalid_argument("find_contacts: " + (i == 0 ? std::string("the body polygon: ") : "obstacle " + std::to_string(i - 1) + ": ") + problem);
        }
    }
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
        if (const std::optional<Vec2> x = polygons_overlap(body, obstacles[i])) {
            throw std::invalid_argument("find_contacts: the body polygon overlaps obstacle " + std::to_string(i) +
                                        ", for instance at (" + shortest(x->x()) + ", " + shortest(x->y()) + ")");
        }
    }
    return detail::find_contacts_of_simple(body, obstacles, options, origins);
}

namespace {

template <class P>
std::vector<Contact> merged(const std::vector<Contact>& found, const std::vector<ContactOrigin>& found_origins,
                            const std::vector<P>& points, const std::vector<TouchedEdge<P>>& edges,
                            const ContactFinding& options, double point_distance,
                            const Dyadic& distance, std::vector<ContactOrigin>* origins);

// The contacts of polygons whose coordinates may be the given ones scaled (scaled_polygons):
// `point_distance` the distance between points there (the double of `distance`, exact), while
// the unit normals compare with options.distance itself.
template <class P>
std::vector<Contact> contacts_of(std::span<const P> body, const std::vector<std::vector<P>>& obstacles, const ContactFinding& options,
                                 double point_distance, const Dyadic& distance, std::vector<ContactOrigin>* origins) {
    check_distance(options);
    const std::vector<P> b = counter_clockwise(body);
    const bool body_reversed = !is_counter_clockwise(body);
    std::vector<Contact> found;
    std::vector<ContactOrigin> found_origins;
    std::vector<P> points;  // each contact's point, exactly
    std::vector<TouchedEdge<P>> edges;  // and the edge that gives its normal
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
        const std::span<const P> given(obstacles[k]);
        const std::vector<P> o = counter_clockwise(given);
        const bool reversed = !is_counter_clockwise(given);
        vertex_on_edge(b, o, true, body_reversed, reversed, k, options, point_distance, distance, found, found_origins, points, edges);
        vertex_on_edge(o, b, false, reversed, body_reversed, k, options, point_distance, distance, found, found_origins, points, edges);
    }
    return merged(found, found_origins, points, edges, options, point_distance, distance, origins);
}

template <class P>
std::vector<Contact> merged(const std::vector<Contact>& found, const std::vector<ContactOrigin>& found_origins,
                            const std::vector<P>& points, const std::vector<TouchedEdge<P>>& edges,
                            const ContactFinding& options, double point_distance,
                            const Dyadic& distance, std::vector<ContactOrigin>* origins) {
    // One contact for points and normals both within the distance (the first kept), as the plain
    // comparison of every pair would merge them: the kept ones hashed by cells of side 2 d (or
    // of the coordinates' resolution where that is larger), so a contact is compared only with
    // those in the 3 x 3 cells around it (points within d are in neighbouring cells even after
    // rounding); the points themselves are compared exactly. O(k) expected for k contacts found.
    std::vector<Contact> out;
    std::vector<std::size_t> kept;  // the contact found that each one kept is
    std::unordered_map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>, CellHash> cells;
    // Cells of side at least 2^-52 of the largest coordinate too, so that every point's cell is an
    // integer below 2^53 (far from the origin, points within d of each other were once compared
    // only when their doubles were equal: review-33); any side when every point is at the origin.
    double largest = 0.0;
    for (const Contact& c : found) largest = std::max({largest, std::fabs(c.point.x()), std::fabs(c.point.y())});
    double side = std::max(2.0 * point_distance, largest * 0x1p-52);
    if (side == 0.0) side = 1.0;
    const auto cell_of = [&](const Vec2& p) {
        return std::pair(static_cast<std::int64_t>(std::floor(p.x() / side)), static_cast<std::int64_t>(std::floor(p.y() / side)));
    };
    const Sign threshold = normals_threshold(options.distance);
    const auto same = [&](std::size_t f, std::size_t k) {
        const P& q = points[kept[k]];
        return within_distance_of_segment(points[f], q, q, distance, point_distance) &&
               normals_within(edges[f], edges[kept[k]], options.distance, threshold);
    };
    if (origins != nullptr) origins->clear();
    for (std::size_t f = 0; f < found.size(); ++f) {
        const Contact& c = found[f];
        const auto cell = cell_of(c.point);
        bool repeated = false;
        for (std::int64_t dx = -1; dx <= 1 && !repeated; ++dx) {
            for (std::int64_t dy = -1; dy <= 1 && !repeated; ++dy) {
                const auto it = cells.find({cell.first + dx, cell.second + dy});
                if (it == cells.end()) continue;
                repeated = std::any_of(it->second.begin(), it->second.end(), [&](std::size_t k) { return same(f, k); });
            }
        }
        if (repeated) continue;
        cells[cell].push_back(out.size());
        out.push_back(c);
        kept.push_back(f);
        if (origins != nullptr) origins->push_back(found_origins[f]);
    }
    return out;
}

}  // namespace

std::vector<Contact> detail::find_contacts_of_simple(const Polygon& body, const std::vector<Polygon>& obstacles,
                                                     const ContactFinding& options, std::vector<ContactOrigin>* origins) {
    return contacts_of(std::span<const Vec2>(body), obstacles, options, options.distance, Dyadic(options.distance), origins);
}

std::vector<Contact> detail::find_contacts_of_simple(const Polygon& body, const std::vector<Polygon>& obstacles,
                                                     const ContactFinding& options, const ScaledPolygons& scaled,
                                                     std::vector<ContactOrigin>* origins) {
    return contacts_of(std::span<const Vec2>(body), obstacles, options, scaled.rounded_distance(options.distance),
                       scaled.distance(options.distance), origins);
}

std::vector<Contact> detail::find_contacts_of_simple(const ExactPolygon& body, const std::vector<ExactPolygon>& obstacles,
                                                     const ContactFinding& options, const ScaledPolygons& scaled,
                                                     std::vector<ContactOrigin>* origins) {
    return contacts_of(std::span<const ExactPoint>(body), obstacles, options, scaled.rounded_distance(options.distance),
                       scaled.distance(options.distance), origins);
}

}  // namespace momentlab
