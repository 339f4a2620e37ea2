#include "momentlab/geometry/force_sets.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "momentlab/geometry/labels.hpp"

namespace momentlab {
namespace {

void require_finite(const Vec2& v, const char* what) {
    if (!v.allFinite()) throw std::invalid_argument(std::string(what) + " must be finite");
}

void require_nonzero(const Vec2& v, const char* what) {
    require_finite(v, what);
    if (v.x() == 0.0 && v.y() == 0.0) throw std::invalid_argument(std::string(what) + " must be non-zero");
}

// Exact sets (decimals as typed): each generator times a positive number, its denominators
// cleared, so the same cone with Dyadic coordinates. A point P / d (P integer, d > 0 their
// common denominator) and a direction cleared to integers N give the force's wrench
// (N, (P / d) x N) times d: (d N, P x N).
struct ClearedPoint {
    std::vector<Dyadic> p;
    Dyadic d;
};

ClearedPoint cleared_point(const Rational2& point) {
    ClearedPoint out;
    out.p = clear_denominators(point, &out.d);
    return out;
}

Exact2 cleared_direction(const Rational2& direction) {
    const std::vector<Dyadic> n = clear_denominators(direction);
    return {n[0], n[1]};
}

ExactVector cleared_force(const ClearedPoint& at, const Exact2& n) {
    return ExactVector::from_exact({at.d * n[0], at.d * n[1], at.p[0] * n[1] - at.p[1] * n[0]});
}

}  // namespace

ExactVector force_wrench(const Vec2& point, const Vec2& direction) {
    return ExactVector::wrench(point, direction);
}

Exact2 friction_edge(const Exact2& n, double mu, bool left) {
    return friction_direction(n[0], n[1], Dyadic(left ? mu : -mu));
}

Exact2 friction_edge(const Vec2& normal, double mu, bool left) { return friction_edge(exact(normal), mu, left); }

Exact2 friction_edge(const Exact2& n, const Rational& mu, bool left) {
    return friction_direction(n[0], n[1], left ? mu.num() : -mu.num(), &mu.den());
}

std::array<ExactVector, 2> friction_cone_edges(const Vec2& point, const Vec2& normal, double mu) {
    // An edge whose direction is exactly doubles (axis-parallel normals, mu = 0) is kept as
    // ExactVector::wrench keeps it: no Dyadic numbers, and the predicates' filters for forces.
    const Exact2 p = exact(point);
    const auto edge = [&](bool plus) {
        const Exact2 d = friction_edge(normal, mu, plus);
        if (d[0].fits_double() && d[1].fits_double()) return ExactVector::wrench(point, to_double(d));
        return ExactVector::from_exact(wrench_through(p, d));
    };
    return {edge(true), edge(false)};
}

Cone forces_across(const Rational2& a, const Rational2& b, const std::vector<Exact2>& directions) {
    std::vector<ExactVector> gens;
    Exact2 sum{};
    for (const Exact2& d : directions) {
        gens.push_back(ExactVector::from_exact({d[0], d[1], Dyadic()}));
        sum = sum + d;
    }
    gens.push_back(ExactVector::input(Vec3::UnitZ()));  // every pure moment
    gens.push_back(ExactVector::input(-Vec3::UnitZ()));
    const Cone turning = Cone::from_generators(gens);
    const ExactVector about_a = moment_functional(a);  // moments about a point
    std::vector<ExactVector> halfspaces;
    if (a == b) {
        halfspaces = {about_a, about_a.negated()};
    } else {
        const Exact2 ab = cleared_direction({b[0] - a[0], b[1] - a[1]});  // (a positive multiple)
        const bool positive = cross2(ab, sum).sign() == Sign::Positive;
        const ExactVector about_b = moment_functional(b);
        halfspaces = {positive ? about_a : about_a.negated(), positive ? about_b.negated() : about_b};
    }
    return intersection(turning, Cone::from_halfspaces(halfspaces));
}

Cone force_ray(const Vec2& point, const Vec2& direction) {
    require_finite(point, "point");
    require_nonzero(direction, "direction");
    const ExactVector g[] = {force_wrench(point, direction)};
    return Cone::from_generators(g);
}

Cone line_of_force(const Vec2& point, const Vec2& direction) {
    require_finite(point, "point");
    require_nonzero(direction, "direction");
    const ExactVector w = force_wrench(point, direction);
    const ExactVector g[] = {w, w.negated()};
    return Cone::from_generators(g);
}

Cone forces_through_point(const Vec2& point) {
    require_finite(point, "point");
    // Unit forces along x and y through the point; the torque p x f is exact here.
    const Vec3 ex(1.0, 0.0, -point.y()), ey(0.0, 1.0, point.x());
    const Vec3 g[] = {ex, -ex, ey, -ey};
    return Cone::from_generators(g);
}

Cone friction_cone(const Vec2& point, const Vec2& normal, double mu) {
    require_finite(point, "point");
    require_nonzero(normal, "normal");
    if (!(mu >= 0.0) || !std::isfinite(mu)) throw std::invalid_argument("mu must be finite and >= 0");
    const auto edges = friction_cone_edges(point, normal, mu);
    return Cone::from_generators(std::span<const ExactVector>(edges));
}

Cone pure_moments(int sign) {
    const Vec3 up(0.0, 0.0, 1.0);
    if (sign > 0) {
        const Vec3 g[] = {up};
        return Cone::from_generators(g);
    }
    if (sign < 0) {
        const Vec3 g[] = {-up};
        return Cone::from_generators(g);
    }
    const Vec3 g[] = {up, -up};
    return Cone::from_generators(g);
}

Cone force_ray(const Rational2& point, const Rational2& direction) {
    if (is_double(point) && is_double(direction)) return force_ray(to_double(point), to_double(direction));
    const ExactVector g[] = {cleared_force(cleared_point(point), cleared_direction(direction))};
    return Cone::from_generators(g);
}

Cone line_of_force(const Rational2& point, const Rational2& direction) {
    if (is_double(point) && is_double(direction)) return line_of_force(to_double(point), to_double(direction));
    const ExactVector w = cleared_force(cleared_point(point), cleared_direction(direction));
    const ExactVector g[] = {w, w.negated()};
    return Cone::from_generators(g);
}

// All forces through the point P / d: (d, 0, -P.y), (0, d, P.x) and their negatives.
Cone forces_through_point(const Rational2& point) {
    if (is_double(point)) return forces_through_point(to_double(point));
    const ClearedPoint at = cleared_point(point);
    const Dyadic zero;
    const ExactVector ex = ExactVector::from_exact({at.d, zero, -at.p[1]});
    const ExactVector ey = ExactVector::from_exact({zero, at.d, at.p[0]});
    const ExactVector g[] = {ex, ex.negated(), ey, ey.negated()};
    return Cone::from_generators(g);
}

// The edges b N +- a t at P / d, each times d (friction_direction with a denominator).
Cone friction_cone(const Rational2& point, const Rational2& normal, const Rational& mu) {
    if (is_double(point) && is_double(normal) && mu.is_double()) return friction_cone(to_double(point), to_double(normal), mu.to_double());
    const ClearedPoint at = cleared_point(point);
    const Exact2 n = cleared_direction(normal);
    Dyadic b;
    const Dyadic a = clear_denominators(std::span<const Rational>(&mu, 1), &b).front();
    const auto edge = [&](const Dyadic& c) {
        const auto d = friction_direction(n[0], n[1], c, &b);
        return cleared_force(at, Exact2{d[0], d[1]});
    };
    const ExactVector g[] = {edge(a), edge(-a)};
    return Cone::from_generators(g);
}

}  // namespace momentlab
