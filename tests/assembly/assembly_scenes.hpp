#pragma once

// Scenes of many bodies for the assembly tests and benchmarks (bench/bench_stand.cpp,
// tests/assembly/test_stand.cpp): masonry arches of voussoirs between fixed abutments, walls of
// bricks in running bond on a floor, and towers of bricks. Every contact is written out (no
// polygons are searched); each body's polygon is kept for pictures and for checking the contacts
// against find_assembly_contacts.

#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "momentlab/assembly/assembly.hpp"

namespace momentlab::assembly_scenes {

/// The polygon's area and the mean of its vertices (a point inside a convex polygon; exact for
/// small dyadic vertices, which the oracle tests want) or its centroid (rounded).
inline std::pair<double, Vec2> area_and_centre(const Polygon& p, bool centroid) {
    double area = 0.0;
    Vec2 c = Vec2::Zero();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec2& u = p[i];
        const Vec2& v = p[(i + 1) % p.size()];
        const double cross = u.x() * v.y() - v.x() * u.y();
        area += cross / 2;
        c += centroid ? Vec2((u + v) * cross / 6) : Vec2(u / static_cast<double>(p.size()));
    }
    return {area, centroid ? Vec2(c / area) : c};
}

inline AssemblyBody body_of(Polygon polygon, bool centroid) {
    AssemblyBody b;
    const auto [area, centre] = area_and_centre(polygon, centroid);
    b.mass = area;
    b.com = centre;
    b.inertia = area;  // any positive inertia (the modes need one; statics do not)
    b.polygon = std::move(polygon);
    return b;
}

/// An arch of voussoirs between two fixed abutments given by its joints: joint i runs from the
/// intrados point inner[i] to the extrados point outer[i], from the left springing (i = 0) to
/// the right one (i = n); voussoir k (body k + 1) lies between joints k and k + 1. Each joint
/// has a contact at both of its ends (and at its midpoint with `points` = 3), normal perpendicular to the joint into the voussoir on its
/// right (body a), the one on its left (or the abutment) being body b; at the right springing
/// body a is the last voussoir and b the abutment. The mass is the area and the centre the
/// centroid (or the mean of the corners). The springings lie on y = 0, on abutments of height 1
/// (obstacles) that reach from the intrados outwards.
inline Assembly arch_of(const std::vector<Vec2>& inner, const std::vector<Vec2>& outer, double mu, bool centroid,
                        int points = 2) {
    Assembly a;
    const std::size_t n = inner.size() - 1;
    a.obstacles = {{{outer[0].x() - 1, -1}, {inner[0].x(), -1}, {inner[0].x(), 0}, {outer[0].x() - 1, 0}},
                   {{inner[n].x(), -1}, {outer[n].x() + 1, -1}, {outer[n].x() + 1, 0}, {inner[n].x(), 0}}};
    for (std::size_t k = 0; k < n; ++k) {
        a.bodies.push_back(body_of({inner[k], inner[k + 1], outer[k + 1], outer[k]}, centroid));  // counter-clockwise
    }
    for (std::size_t i = 0; i <= n; ++i) {
        const Vec2 d = outer[i] - inner[i];
        // Clockwise of the joint's direction (intrados to extrados, around the arch from left to
        // right) points into the voussoir on its right.
        const Vec2 right(d.y(), -d.x());
        const bool last = i == n;
        const std::size_t body_a = last ? n : i + 1, body_b = last ? 0 : i;
        const Vec2 normal = last ? Vec2(-right) : right;
        std::vector<Vec2> at{inner[i], outer[i]};
        if (points == 3) at.insert(at.begin() + 1, (inner[i] + outer[i]) / 2);
        for (const Vec2& p : at) a.contacts.push_back({body_a, body_b, Contact::make(p, normal, mu)});
    }
    return a;
}

/// A semicircular arch of n voussoirs of equal angle, intrados radius 1 and extrados 1 +
/// thickness, centred at the origin (Heyman, "The Stone Skeleton", 1995: a semicircular arch
/// stands under its own weight when its thickness is more than about 0.11 of its mean radius).
inline Assembly semicircular_arch(int voussoirs, double thickness, double mu) {
    std::vector<Vec2> inner, outer;
    for (int i = 0; i <= voussoirs; ++i) {
        const double t = M_PI * (1.0 - static_cast<double>(i) / voussoirs);
        const Vec2 d(std::cos(t), i == 0 || i == voussoirs ? 0.0 : std::sin(t));  // the springings on y = 0
        inner.push_back(d);
        outer.push_back((1.0 + thickness) * d);
    }
    return arch_of(inner, outer, mu, true);
}

/// An arch of `voussoirs` voussoirs of equal angle with its corners rounded to multiples of 1/8
/// (exact dyadic numbers, few bits: for the exact oracles): intrados radius 2, extrados 2 +
/// thickness, the centre of each voussoir the mean of its corners.
inline Assembly dyadic_arch(int voussoirs, double thickness, double mu, int points = 2) {
    std::vector<Vec2> inner, outer;
    const auto eighths = [](double x) { return std::round(8 * x) / 8; };
    for (int i = 0; i <= voussoirs; ++i) {
        const double t = M_PI * (1.0 - static_cast<double>(i) / voussoirs);
        inner.emplace_back(eighths(2 * std::cos(t)), eighths(2 * std::sin(t)));
        outer.emplace_back(eighths((2 + thickness) * std::cos(t)), eighths((2 + thickness) * std::sin(t)));
    }
    return arch_of(inner, outer, mu, false, points);
}

/// A tower of bricks of length 2 and height 1 on a floor, brick k (from the bottom) shifted
/// right by k * shift, with `points` (2 or 3) contacts on each interface: its ends (and its
/// midpoint), normal (0, 1) into the upper brick.
inline Assembly tower(int bricks, int points, double shift, double mu) {
    Assembly a;
    for (int k = 0; k < bricks; ++k) {
        const double x0 = k * shift, y0 = k;
        a.bodies.push_back(body_of({{x0, y0}, {x0 + 2, y0}, {x0 + 2, y0 + 1}, {x0, y0 + 1}}, false));
        const double lo = k == 0 ? 0.0 : x0, hi = k == 0 ? 2.0 : (k - 1) * shift + 2;
        std::vector<double> at{lo, hi};
        if (points == 3) at.insert(at.begin() + 1, (lo + hi) / 2);
        for (const double x : at) {
            a.contacts.push_back({static_cast<std::size_t>(k + 1), static_cast<std::size_t>(k),
                                  Contact::make(Vec2(x, y0), Vec2(0, 1), mu)});
        }
    }
    return a;
}

/// A wall of `bricks` bricks of length 2 and height 1 in running bond on a floor (y = 0), laid
/// row by row from the bottom and from the left: even rows `per_row` whole bricks from x = 0,
/// odd rows a half brick, per_row - 1 whole ones and a half brick, flush with the ends (the
/// last row may be partial). With `overhang`, odd rows are per_row whole bricks shifted by a
/// half, so that the last one's centre lies exactly above the end of the brick below it (on
/// the boundary of tipping). Contacts at both ends of every interval where a brick rests on the
/// floor or on a brick, normal (0, 1) into the upper brick (body a), and at both ends of the
/// joint between neighbours in a row, normal (1, 0) into the right one (body a), with friction
/// `head_mu` (default mu; friction there can clamp a brick, so the overhang is on the boundary
/// only with head_mu = 0). Masses are the areas.
inline Assembly running_bond_wall(int bricks, int per_row, double mu, bool overhang = false,
                                  std::optional<double> head_mu = std::nullopt) {
    struct Brick {
        double x0, x1;
        int row;
    };
    std::vector<Brick> laid;
    for (int row = 0; static_cast<int>(laid.size()) < bricks; ++row) {
        std::vector<std::pair<double, double>> spans;
        if (row % 2 == 0) {
            for (int k = 0; k < per_row; ++k) spans.push_back({2.0 * k, 2.0 * k + 2});
        } else if (overhang) {
            for (int k = 0; k < per_row; ++k) spans.push_back({2.0 * k + 1, 2.0 * k + 3});
        } else {
            spans.push_back({0, 1});
            for (int k = 0; k + 1 < per_row; ++k) spans.push_back({2.0 * k + 1, 2.0 * k + 3});
            spans.push_back({2.0 * per_row - 1, 2.0 * per_row});
        }
        for (const auto& [x0, x1] : spans) {
            if (static_cast<int>(laid.size()) == bricks) break;
            laid.push_back({x0, x1, row});
        }
    }
    Assembly a;
    for (const Brick& b : laid) {
        const double y0 = b.row, y1 = b.row + 1;
        a.bodies.push_back(body_of({{b.x0, y0}, {b.x1, y0}, {b.x1, y1}, {b.x0, y1}}, false));
    }
    const double width = 2.0 * per_row + (overhang ? 1 : 0);
    a.obstacles = {{{-1, -1}, {width + 1, -1}, {width + 1, 0}, {-1, 0}}};
    for (std::size_t i = 0; i < laid.size(); ++i) {
        const auto rest = [&](std::size_t below, double lo, double hi) {
            for (const double x : {lo, hi}) {
                a.contacts.push_back({i + 1, below, Contact::make(Vec2(x, laid[i].row), Vec2(0, 1), mu)});
            }
        };
        if (laid[i].row == 0) {
            rest(0, laid[i].x0, laid[i].x1);
            continue;
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (laid[j].row + 1 != laid[i].row) continue;
            const double lo = std::max(laid[i].x0, laid[j].x0), hi = std::min(laid[i].x1, laid[j].x1);
            if (lo < hi) rest(j + 1, lo, hi);
        }
    }
    for (std::size_t i = 1; i < laid.size(); ++i) {  // the head joints
        if (laid[i].row != laid[i - 1].row || laid[i].x0 != laid[i - 1].x1) continue;
        for (const double y : {laid[i].row, laid[i].row + 1}) {
            a.contacts.push_back({i + 1, i, Contact::make(Vec2(laid[i].x0, y), Vec2(1, 0), head_mu.value_or(mu))});
        }
    }
    return a;
}

/// The assembly without its polygons (and obstacles): the same contacts, nothing to search or
/// check for overlaps.
inline Assembly without_polygons(Assembly a) {
    for (AssemblyBody& b : a.bodies) b.polygon.clear();
    a.obstacles.clear();
    return a;
}

}  // namespace momentlab::assembly_scenes
