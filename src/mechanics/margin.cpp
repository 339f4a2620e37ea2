// Margins of a question (mechanics/margin.hpp): distances in the scaled wrench space, measured
// on the cones' generators and facets taken exactly to torques about the reference and rounded
// once there (measures, not decisions).
#include "momentlab/mechanics/margin.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace momentlab {
namespace {

// The direction of an exact vector, rounded coordinate by coordinate after scaling by a power of
// two common to all three (so that nothing overflows or underflows but against the largest).
Vec3 rounded_direction(const Exact3& e) {
    std::int64_t k = std::numeric_limits<std::int64_t>::min();
    for (const Dyadic& x : e) {
        if (!x.is_zero()) k = std::max(k, x.exponent());
    }
    if (k == std::numeric_limits<std::int64_t>::min()) return Vec3::Zero();
    return Vec3(e[0].to_double_scaled(k), e[1].to_double_scaled(k), e[2].to_double_scaled(k));
}

// S w = (fx, fy, tau - r x f): the torque about the reference r instead of the origin, exactly.
// Far from the origin tau and r x f nearly cancel; done in doubles this lost as many digits as
// the scene's distance from the origin has (issue 44: a scene moved by 1e8 kept 8 of 16).
Exact3 about_reference(const Exact3& w, const Exact2& r) { return {w[0], w[1], w[2] - (r[0] * w[1] - r[1] * w[0])}; }

// A facet normal h of a cone of wrenches about the origin, as the normal of its image under S:
// h . w = (S^-T h) . (S w), S^-T h = (h.x - r.y h.z, h.y + r.x h.z, h.z), exactly.
Exact3 normal_about_reference(const Exact3& h, const Exact2& r) { return {h[0] - r[1] * h[2], h[1] + r[0] * h[2], h[2]}; }

// The unit direction of a generator of a cone in the scaled space (fx, fy, tau_r / L).
Vec3 scaled_generator(const ExactVector& g, const Exact2& r, double length) {
    const Vec3 d = rounded_direction(about_reference(g.exact(), r));
    return Vec3(d.x(), d.y(), d.z() / length).normalized();
}

// The unit normal of a facet in the scaled space.
Vec3 scaled_facet(const ExactVector& h, const Exact2& r, double length) {
    const Vec3 n = rounded_direction(normal_about_reference(h.exact(), r));
    return Vec3(n.x(), n.y(), n.z() * length).normalized();
}

Vec3 scaled_wrench(const Exact3& w, const WrenchMetric& m) {
    const Exact3 s = about_reference(w, exact(m.reference));
    return Vec3(s[0].to_double(), s[1].to_double(), s[2].to_double() / m.length);
}

// The distance from p to a closed face of a cone, by the face's own generators (unit vectors in
// the scaled space: `rays` with coefficients >= 0, `lines` with any), when the nearest point of
// the face's span lies in the face; none otherwise (then a smaller face holds the nearest point).
// A sign misjudged by rounding near the face's boundary moves the answer by no more than the
// rounding: there the smaller face's distance is nearly the same, so no tolerance is needed.
std::optional<double> distance_in_face(const Vec3& p, const std::vector<Vec3>& rays, const std::vector<Vec3>& lines) {
    std::vector<Vec3> g = rays;
    g.insert(g.end(), lines.begin(), lines.end());
    if (g.size() == 1) {
        if (!rays.empty() && p.dot(g[0]) < 0.0) return std::nullopt;  // beyond the apex
        return p.cross(g[0]).norm();
    }
    if (g.size() != 2) return std::nullopt;  // not a face of a cone of R^3 (the apex and R^3 are apart)
    // q = a g0 + b g1 is the projection onto the plane with normal nu = g0 x g1; the coefficients'
    // signs are those of det(p, g1, nu) and det(g0, p, nu) (det(g0, g1, nu) = |nu|^2 > 0).
    const Vec3 nu = g[0].cross(g[1]);
    if (!rays.empty() && p.cross(g[1]).dot(nu) < 0.0) return std::nullopt;
    if (rays.size() == 2 && g[0].cross(p).dot(nu) < 0.0) return std::nullopt;
    return std::abs(p.dot(nu)) / nu.norm();
}

// The distance from the scaled wrench p (exactly w) to the closed cone c.
double scaled_distance_to(const Cone& c, const Exact3& w, const Vec3& p, const WrenchMetric& metric) {
    if (c.has(ExactVector::from_exact(w))) return 0.0;
    const Exact2 r = exact(metric.reference);
    std::vector<Vec3> rays, lines;
    for (const ExactVector& g : c.rays()) rays.push_back(scaled_generator(g, r, metric.length));
    for (const ExactVector& l : c.lineality()) lines.push_back(scaled_generator(l, r, metric.length));
    // The nearest point of a closed convex cone not holding p lies on a proper face (on c itself
    // when c is not full-dimensional), in the relative interior of the smallest face holding it;
    // the apex is a candidate always.
    double least = p.norm();
    for (const Face& face : c.faces()) {
        if (face.dimension == 3 || face.dimension == 0) continue;
        std::vector<Vec3> face_rays;
        for (int i : face.rays) face_rays.push_back(rays[static_cast<std::size_t>(i)]);
        if (const auto d = distance_in_face(p, face_rays, lines)) least = std::min(least, *d);
    }
    return least;
}

// The distance from the scaled wrench p, in the closed cone c, to its boundary.
double scaled_distance_to_boundary(const Cone& c, const Vec3& p, const WrenchMetric& metric) {
    if (c.dimension() < 3) return 0.0;
    if (c.is_whole_space()) return std::numeric_limits<double>::infinity();
    const Exact2 r = exact(metric.reference);
    double least = std::numeric_limits<double>::infinity();
    for (const ExactVector& f : c.facets()) least = std::min(least, std::max(0.0, scaled_facet(f, r, metric.length).dot(p)));
    return least;
}

QueryMargins margins_for(std::span<const ModeForces> analysis, const std::vector<std::size_t>& modes, const Exact3& e,
                         const WrenchMetric& metric) {
    QueryMargins out;
    const Vec3 p = scaled_wrench(e, metric);
    for (std::size_t k : modes) out.inside.push_back(scaled_distance_to_boundary(analysis[k].applied, p, metric));
    for (std::size_t j = 0; j < analysis.size(); ++j) {
        if (std::find(modes.begin(), modes.end(), j) != modes.end()) continue;
        const double d = scaled_distance_to(analysis[j].applied, e, p, metric);
        out.to_other = out.to_other ? std::min(*out.to_other, d) : d;
    }
    return out;
}

}  // namespace

Vec3 WrenchMetric::scaled(const Vec3& w) const { return scaled_wrench(exact(w), *this); }

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

double distance_to(const Cone& c, const Vec3& w, const WrenchMetric& metric) {
    return scaled_distance_to(c, exact(w), metric.scaled(w), metric);
}

double distance_to_boundary(const Cone& c, const Vec3& w, const WrenchMetric& metric) {
    return scaled_distance_to_boundary(c, metric.scaled(w), metric);
}

QueryMargins query_margins(std::span<const ModeForces> analysis, const std::vector<std::size_t>& modes,
                           const Vec3& e, const WrenchMetric& metric) {
    return margins_for(analysis, modes, exact(e), metric);
}

QueryMargins margins_of(std::span<const ModeForces> analysis, const Exact3& e, const WrenchMetric& metric) {
    const ExactVector w = ExactVector::from_exact(e);
    std::vector<std::size_t> holding;
    for (std::size_t j = 0; j < analysis.size(); ++j) {
        if (analysis[j].applied.has(w)) holding.push_back(j);
    }
    return margins_for(analysis, holding, e, metric);
}

QueryMargins margins_of(std::span<const ModeForces> analysis, const Vec3& e, const WrenchMetric& metric) {
    return margins_of(analysis, exact(e), metric);
}

}  // namespace momentlab
