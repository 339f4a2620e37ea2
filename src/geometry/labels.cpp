#include "momentlab/geometry/labels.hpp"

#include "momentlab/core/rounding.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace momentlab {
namespace {

// X = (x, y, s) -> functional (y, -x, s), and back.
Mat3 points_to_functionals() {
    Mat3 m;
    m << 0, 1, 0, -1, 0, 0, 0, 0, 1;
    return m;
}

Mat3 functionals_to_points() { return points_to_functionals().transpose(); }

// The sheet s >= 0 of a cone of homogeneous points.
Region sheet(const Cone& k_sheet) {
    Region r;
    for (const ExactVector& ray : k_sheet.rays()) {
        if (ray.dot_sign(Vec3::UnitZ()) == Sign::Positive) {
            const Exact3 v = ray.exact();
            r.vertices_h.push_back(ray);
            r.vertices.emplace_back(nearest_double(v[0], v[2]), nearest_double(v[1], v[2]));
        } else {
            r.rays_h.push_back(ray);
            r.rays.emplace_back(ray.value().x(), ray.value().y());
        }
    }
    for (const ExactVector& l : k_sheet.lineality()) {
        r.lines_dir_h.push_back(l);
        r.lines.emplace_back(l.value().x(), l.value().y());
    }
    r.is_empty = r.vertices_h.empty();
    if (r.is_empty) {
        r.rays.clear();
        r.lines.clear();
        r.rays_h.clear();
        r.lines_dir_h.clear();
        return r;
    }
    if (k_sheet.is_pointed() && k_sheet.dimension() == 3) {
        for (const ExactVector& ray : k_sheet.rays()) r.boundary.push_back(ray.value());
    }
    for (const ExactVector& f : k_sheet.facets()) {
        const Vec3& v = f.value();
        if (v.x() != 0.0 || v.y() != 0.0) r.halfplanes.push_back(v);
    }
    for (const ExactVector& e : k_sheet.equations()) r.lines_h.push_back(e.value());
    return r;
}

// Sutherland-Hodgman clip of a convex polygon by a x + b y + c >= 0 (for drawing).
std::vector<Vec2> clip(const std::vector<Vec2>& poly, const Vec3& h) {
    std::vector<Vec2> out;
    const std::size_t n = poly.size();
    auto value = [&](const Vec2& p) { return h.x() * p.x() + h.y() * p.y() + h.z(); };
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2& a = poly[i];
        const Vec2& b = poly[(i + 1) % n];
        const double va = value(a), vb = value(b);
        if (va >= 0) out.push_back(a);
        if ((va >= 0) != (vb >= 0)) out.push_back(a + (b - a) * (va / (va - vb)));
    }
    return out;
}

}  // namespace

const char* to_string(Label label) {
    switch (label) {
        case Label::Plus: return "+";
        case Label::Minus: return "-";
        case Label::Both: return "+-";
        default: return "none";
    }
}

std::string Region::kind() const {
    if (is_empty) return "empty";
    const std::size_t v = vertices.size(), r = rays.size(), l = lines.size();
    if (l == 2) return "plane";
    if (l == 1) {
        if (r > 0) return "half-plane";
        return v >= 2 ? "strip" : "line";
    }
    if (r == 0) return v == 1 ? "point" : (v == 2 ? "segment" : "polygon");
    if (v == 1 && r == 1) return "ray";
    return "unbounded";
}

std::vector<Vec2> Region::clipped(const Box& box) const {
    if (is_empty) return {};
    const auto inside = [&](const Vec2& p) {
        return p.x() >= box.min.x() && p.x() <= box.max.x() && p.y() >= box.min.y() && p.y() <= box.max.y();
    };
    // Points and 1-dimensional regions directly: cutting a polygon down to them by pairs of
    // opposite half-planes loses them to rounding.
    if (lines.size() + rays.size() == 0 && vertices.size() == 1) {
        return inside(vertices[0]) ? std::vector<Vec2>{vertices[0]} : std::vector<Vec2>{};
    }
    const bool one_dimensional = lines.size() + rays.size() + vertices.size() == 2 ||
                                 (lines.size() == 1 && rays.empty() && vertices.size() == 1);
    if (one_dimensional) {
        // q + t d with t in [lo, hi]: a segment (t in [0, 1]), a ray (t >= 0) or a line.
        const Vec2 q = vertices[0];
        const Vec2 d = vertices.size() == 2 ? Vec2(vertices[1] - q) : (rays.empty() ? lines[0] : rays[0]);
        double lo = lines.empty() ? 0.0 : -INFINITY, hi = vertices.size() == 2 ? 1.0 : INFINITY;
        for (int k = 0; k < 2; ++k) {
            if (d[k] == 0.0) {
                if (q[k] < box.min[k] || q[k] > box.max[k]) return {};
                continue;
            }
            double a = (box.min[k] - q[k]) / d[k], b = (box.max[k] - q[k]) / d[k];
            if (a > b) std::swap(a, b);
            lo = std::max(lo, a);
            hi = std::min(hi, b);
        }
        if (lo > hi) return {};
        if (lo == hi) return {q + lo * d};
        return {q + lo * d, q + hi * d};
    }
    std::vector<Vec2> poly = {box.min, Vec2(box.max.x(), box.min.y()), box.max,
                              Vec2(box.min.x(), box.max.y())};
    for (const Vec3& h : halfplanes) poly = clip(poly, h);
    for (const Vec3& e : lines_h) {
        if (e.x() == 0.0 && e.y() == 0.0) continue;
        poly = clip(clip(poly, e), -e);
    }
    // Drop the repeated points that cuts through a vertex leave behind.
    std::vector<Vec2> out;
    for (const Vec2& p : poly) {
        if (out.empty() || p != out.back()) out.push_back(p);
    }
    while (out.size() > 1 && out.front() == out.back()) out.pop_back();
    return out;
}

Labels::Labels(Cone forces)
    : forces_(std::move(forces)),
      dual_(forces_.dual()),
      points_(dual_.signed_permuted(functionals_to_points())) {
    plus_ = sheet(intersection(points_, Cone::half_space(Vec3::UnitZ())));
    // -K n {s >= 0} = -(K n {s <= 0}): a pointed K is cut first, so that only the cut is
    // negated (the same lists; with lines, a line's direction would come out negated).
    minus_ = sheet(points_.is_pointed() ? intersection(points_, Cone::half_space(-Vec3::UnitZ())).negated()
                                        : intersection(points_.negated(), Cone::half_space(Vec3::UnitZ())));
}

namespace {

// The label of a point from the dual cone F*: its moment functional (or its negative) in F*.
// `lambda` is the functional (y, -x, 1) of the point, or a positive multiple of it.
template <class Functional>
Label label_from_dual(const Cone& dual, const Functional& lambda, const Functional& negated) {
    const bool plus = dual.has(lambda);
    const bool minus = dual.has(negated);
    if (plus && minus) return Label::Both;
    if (plus) return Label::Plus;
    if (minus) return Label::Minus;
    return Label::None;
}

Label label_from_dual(const Cone& dual, const Vec2& point) {
    if (!point.allFinite()) throw std::invalid_argument("the label's point must be finite");
    const Vec3 lambda = moment_functional(point);
    return label_from_dual(dual, lambda, Vec3(-lambda));
}

Label label_from_dual(const Cone& dual, const Rational2& point) {
    const ExactVector lambda = moment_functional(point);
    return label_from_dual(dual, lambda, lambda.negated());
}

}  // namespace

ExactVector moment_functional(const Rational2& point) {
    Dyadic d;
    const std::vector<Dyadic> p = clear_denominators(point, &d);
    return ExactVector::from_exact({p[1], -p[0], d});
}

Label Labels::at(const Vec2& point) const { return label_from_dual(dual_, point); }

Label Labels::at(const Rational2& point) const { return label_from_dual(dual_, point); }

Label moment_label(const Cone& forces, const Vec2& point) { return label_from_dual(forces.dual(), point); }

Label moment_label(const Cone& forces, const Rational2& point) { return label_from_dual(forces.dual(), point); }

Cone Labels::forces_from_regions(const Region& plus, const Region& minus) {
    std::vector<ExactVector> gens;
    for (const Region* r : {&plus, &minus}) {
        if (r->is_empty) continue;
        const bool negate = r == &minus;
        for (const auto* list : {&r->vertices_h, &r->rays_h}) {
            for (const ExactVector& v : *list) gens.push_back(negate ? v.negated() : v);
        }
        for (const ExactVector& d : r->lines_dir_h) {
            gens.push_back(d);
            gens.push_back(d.negated());
        }
    }
    const Cone k = Cone::from_generators(gens);
    return k.signed_permuted(points_to_functionals()).dual();
}

Region both_region(const Cone& forces) {
    std::vector<ExactVector> span;
    for (const ExactVector& r : forces.rays()) {
        span.push_back(r);
        span.push_back(r.negated());
    }
    for (const ExactVector& l : forces.lineality()) {
        span.push_back(l);
        span.push_back(l.negated());
    }
    return Labels(Cone::from_generators(std::span<const ExactVector>(span))).plus();
}

}  // namespace momentlab
