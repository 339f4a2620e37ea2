// Margins of a question (mechanics/margin.hpp): distances in the scaled wrench space, from the
// cones' rounded generators and facets (measures, not decisions).
#include "momentlab/mechanics/margin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace momentlab {
namespace {

// A facet normal h of the cone in the original space, as the normal of its image in the scaled
// one: h . w = (S^-T h) . (S w) with S^-1 = [[1, 0, 0], [0, 1, 0], [-r.y, r.x, L]].
Vec3 scaled_normal(const Vec3& h, const WrenchMetric& m) {
    return Vec3(h.x() - m.reference.y() * h.z(), h.y() + m.reference.x() * h.z(), m.length * h.z());
}

// Whether the scaled point p lies in the scaled cone, within a relative rounding slack.
bool inside(const std::vector<Vec3>& normals, const Vec3& p) {
    const double size = p.norm();
    return std::all_of(normals.begin(), normals.end(),
                       [&](const Vec3& n) { return n.dot(p) >= -1e-9 * n.norm() * size; });
}

}  // namespace

Vec3 WrenchMetric::scaled(const Vec3& w) const {
    const double torque_here = w.z() - (reference.x() * w.y() - reference.y() * w.x());
    return Vec3(w.x(), w.y(), torque_here / length);
}

WrenchMetric default_metric(const Scene& scene, std::optional<Vec2> reference) {
    WrenchMetric m;
    if (reference) {
        m.reference = *reference;
    } else if (scene.body) {
        m.reference = scene.body->com;
    } else if (!scene.contacts.empty()) {
        Vec2 sum = Vec2::Zero();
        for (const Contact& c : scene.contacts) sum += c.point;
        m.reference = sum / static_cast<double>(scene.contacts.size());
    }
    double far = 0.0;
    for (const Contact& c : scene.contacts) far = std::max(far, (c.point - m.reference).norm());
    m.length = far > 0.0 && std::isfinite(far) ? far : 1.0;
    return m;
}

double distance_to_boundary(const Cone& c, const Vec3& w, const WrenchMetric& metric) {
    if (c.dimension() < 3) return 0.0;
    if (c.is_whole_space()) return std::numeric_limits<double>::infinity();
    const Vec3 p = metric.scaled(w);
    double least = std::numeric_limits<double>::infinity();
    for (const ExactVector& f : c.facets()) {
        const Vec3 n = scaled_normal(f.value(), metric);
        least = std::min(least, std::max(0.0, n.dot(p)) / n.norm());
    }
    return least;
}

double distance_to(const Cone& c, const Vec3& w, const WrenchMetric& metric) {
    if (c.has(w)) return 0.0;
    const Vec3 p = metric.scaled(w);
    std::vector<Vec3> normals;
    for (const Vec3& h : c.halfspace_values()) normals.push_back(scaled_normal(h, metric));
    // The nearest point of a polyhedral cone lies in the relative interior of one of its faces:
    // the projection onto the span of the face, when that lands in the cone. The apex always does.
    double least = p.norm();
    for (const Face& face : c.faces()) {
        std::vector<Vec3> basis;  // orthonormal, by Gram-Schmidt on the face's scaled generators
        auto add = [&](const Vec3& v) {
            Vec3 u = v;
            for (const Vec3& b : basis) u -= u.dot(b) * b;
            if (u.norm() > 1e-12 * v.norm()) basis.push_back(u.normalized());
        };
        for (int r : face.rays) add(metric.scaled(c.rays()[static_cast<std::size_t>(r)].value()));
        for (const ExactVector& l : c.lineality()) add(metric.scaled(l.value()));
        if (basis.empty()) continue;
        Vec3 q = Vec3::Zero();
        for (const Vec3& b : basis) q += p.dot(b) * b;
        if (inside(normals, q)) least = std::min(least, (p - q).norm());
    }
    return least;
}

QueryMargins query_margins(std::span<const ModeForces> analysis, const std::vector<std::size_t>& modes,
                           const Vec3& e, const WrenchMetric& metric) {
    QueryMargins out;
    for (std::size_t k : modes) out.inside.push_back(distance_to_boundary(analysis[k].applied, e, metric));
    for (std::size_t j = 0; j < analysis.size(); ++j) {
        if (std::find(modes.begin(), modes.end(), j) != modes.end()) continue;
        const double d = distance_to(analysis[j].applied, e, metric);
        out.to_other = out.to_other ? std::min(*out.to_other, d) : d;
    }
    return out;
}

QueryMargins margins_of(std::span<const ModeForces> analysis, const Vec3& e, const WrenchMetric& metric) {
    std::vector<std::size_t> holding;
    for (std::size_t j = 0; j < analysis.size(); ++j) {
        if (analysis[j].applied.has(e)) holding.push_back(j);
    }
    return query_margins(analysis, holding, e, metric);
}

}  // namespace momentlab
