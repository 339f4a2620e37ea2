// Grasp closure (mechanics/closure.hpp): form and force closure decided exactly as "the contact
// wrenches' cone is R^3", with a certificate either way.
#include "momentlab/mechanics/closure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

#include "momentlab/geometry/force_sets.hpp"
#include "momentlab/mechanics/margin.hpp"

namespace momentlab {
namespace {

// The radius of the largest ball about 0 inside conv(points), 0 in the interior (the caller
// knows it is for the exact wrenches: their cone is R^3). Each facet of the hull is a plane
// through three points with every point on one side; the radius is the nearest such plane's
// distance. Which triples span a plane and which planes support the hull is decided exactly on
// the (rounded) points, at any scale: a tolerance here took planes 1e-12 beyond a point as
// supporting, and thin triangles as lines, and gave 0 for grasps that hold (issue 44). The
// distance |det(a, b, c)| / |(b - a) x (c - a)| is rounded once from exact values. O(k^4).
double inner_radius(const std::vector<Vec3>& points) {
    const std::size_t k = points.size();
    std::vector<Exact3> exact_points;
    for (const Vec3& p : points) exact_points.push_back(exact(p));
    double radius = std::numeric_limits<double>::infinity();
    std::vector<ExactVector> from_a(k);  // p - a, exactly
    for (std::size_t a = 0; a < k; ++a) {
        for (std::size_t p = 0; p < k; ++p) from_a[p] = ExactVector::from_exact(exact_points[p] - exact_points[a]);
        const ExactVector origin_from_a = ExactVector::from_exact(-exact_points[a]);
        for (std::size_t b = a + 1; b < k; ++b) {
            for (std::size_t c = b + 1; c < k; ++c) {
                const ExactVector n = ExactVector::cross(from_a[b], from_a[c]);
                if (is_zero(n)) continue;  // three points on a line
                Sign side = Sign::Zero;  // of the points off the plane, all on one side
                bool supporting = true;
                for (std::size_t p = 0; p < k && supporting; ++p) {
                    const Sign s = dot_sign(n, from_a[p]);
                    if (s == Sign::Zero) continue;
                    if (side == Sign::Zero) side = s;
                    supporting = s == side;
                }
                if (!supporting) continue;
                // The origin beyond or on a supporting plane: the rounded points' hull lost the
                // ball (thinner than their rounding).
                if (dot_sign(n, origin_from_a) != side) return 0.0;
                const Exact3 normal = n.exact();
                const double d = std::abs(dot(normal, exact_points[a]).to_double()) / to_double(normal).norm();
                radius = std::min(radius, d);
            }
        }
    }
    return std::isfinite(radius) ? radius : 0.0;
}

ClosureTest test(const std::vector<ExactVector>& generators, const std::vector<Vec3>& unit_wrenches) {
    ClosureTest t;
    t.wrenches = Cone::from_generators(std::span<const ExactVector>(generators));
    t.holds = t.wrenches.is_whole_space();
    if (t.holds) {
        t.quality = inner_radius(unit_wrenches);
    } else {
        // C is not R^3, so its dual has a non-zero vector: every contact wrench has w . c >= 0.
        for (const ExactVector& g : t.wrenches.dual().generators()) {
            if (!is_zero(g)) {
                t.unresisted = g;
                break;
            }
        }
    }
    return t;
}

// The wrench of a unit force along `force` at `point`, in the metric's scaled space: the torque
// (point - reference) x u exactly, rounded once (not p x u about the origin less r x u, which
// cancels for a grasp far from the origin), then divided by the length.
Vec3 unit_wrench(const Vec2& point, const Vec2& force, const WrenchMetric& metric) {
    const Vec2 u = force / force.norm();
    const double torque = cross2(exact(point) - exact(metric.reference), exact(u)).to_double();
    return Vec3(u.x(), u.y(), torque / metric.length);
}

}  // namespace

Closure closure(const Scene& scene, const ClosureOptions& options) {
    if (scene.contacts.empty()) throw std::invalid_argument("closure: the scene has no contacts");
    // The quality's metric: the margins' defaults (mechanics/margin.hpp), or the options.
    WrenchMetric metric = default_metric(scene, options.reference);
    if (options.length) {
        if (!(*options.length > 0.0) || !std::isfinite(*options.length)) {
            throw std::invalid_argument("closure: the length must be finite and > 0");
        }
        metric.length = *options.length;
    }
    Closure out;
    out.reference = metric.reference;
    out.length = metric.length;
    std::vector<ExactVector> normals, edges;
    std::vector<Vec3> unit_normals, unit_edges;
    for (const Contact& c : scene.contacts) {
        normals.push_back(c.normal_wrench());
        unit_normals.push_back(unit_wrench(c.point, c.normal, metric));
        for (const ExactVector& w : c.friction_edges()) {  // n + mu t, n - mu t at p
            edges.push_back(w);
            const Vec3 v = w.value();
            unit_edges.push_back(unit_wrench(c.point, Vec2(v.x(), v.y()), metric));
        }
    }
    out.form = test(normals, unit_normals);
    out.force = test(edges, unit_edges);
    return out;
}

}  // namespace momentlab
