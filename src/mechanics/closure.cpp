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
// knows it is: the points' cone is R^3). Each facet of the hull is a plane through three points
// with every point on one side; the radius is the nearest such plane's distance. O(k^4).
double inner_radius(const std::vector<Vec3>& points) {
    const std::size_t k = points.size();
    double scale = 0.0;
    for (const Vec3& p : points) scale = std::max(scale, p.norm());
    const double slack = 1e-12 * scale;
    double radius = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < k; ++a) {
        for (std::size_t b = a + 1; b < k; ++b) {
            for (std::size_t c = b + 1; c < k; ++c) {
                Vec3 n = (points[b] - points[a]).cross(points[c] - points[a]);
                const double length = n.norm();
                if (!(length > 1e-12 * scale * scale)) continue;  // three points on a line
                n /= length;
                double d = n.dot(points[a]);
                if (d < 0.0) {
                    n = -n;
                    d = -d;
                }
                const bool supporting =
                    std::all_of(points.begin(), points.end(), [&](const Vec3& p) { return n.dot(p) <= d + slack; });
                if (supporting) radius = std::min(radius, d);
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

// The wrench of a unit force along `force` at `point`, in the metric's scaled space.
Vec3 unit_wrench(const Vec2& point, const Vec2& force, const WrenchMetric& metric) {
    const Vec2 u = force / force.norm();
    return metric.scaled(Vec3(u.x(), u.y(), point.x() * u.y() - point.y() * u.x()));
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
        for (const ExactVector& w : friction_cone_edges(c.point, c.normal, c.mu)) {  // n + mu t, n - mu t at p
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
