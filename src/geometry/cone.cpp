#include "momentlab/geometry/cone.hpp"

#include <gmpxx.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "cone_build.hpp"

namespace momentlab {
namespace {

// Scales v by a power of two (exact) so that its largest coordinate lies in [1, 2).
Vec3 scaled_by_power_of_two(const Vec3& v) {
    const double m = v.cwiseAbs().maxCoeff();
    if (m == 0.0 || !std::isfinite(m)) return v;
    int e = 0;
    std::frexp(m, &e);
    return Vec3(std::ldexp(v.x(), 1 - e), std::ldexp(v.y(), 1 - e), std::ldexp(v.z(), 1 - e));
}

// For display: integer vectors are divided by the gcd of their coordinates (exact), others are
// left as they are unless far from 1, then scaled by a power of two. Neither changes the
// direction.
Vec3 readable(const Vec3& v) {
    const double limit = 0x1p53;
    bool integral = true;
    for (int i = 0; i < 3; ++i) {
        if (v[i] != std::floor(v[i]) || std::fabs(v[i]) >= limit) integral = false;
    }
    if (integral) {
        long long g = 0;
        for (int i = 0; i < 3; ++i) g = std::gcd(g, std::llabs(static_cast<long long>(v[i])));
        if (g > 1) return v / static_cast<double>(g);
        return v;
    }
    const double m = v.cwiseAbs().maxCoeff();
    return m > 0x1p-64 && m < 0x1p64 ? v : scaled_by_power_of_two(v);
}

}  // namespace

Rational3 to_rational(const Vec3& v) { return {mpq_class(v.x()), mpq_class(v.y()), mpq_class(v.z())}; }

Rational3 ExactVector::rational() const {
    if (!constructed_) return to_rational(value_);
    const Rational3 a = to_rational(u_), b = to_rational(v_);
    const mpq_class s(sign_);
    return {s * (a[1] * b[2] - a[2] * b[1]), s * (a[2] * b[0] - a[0] * b[2]), s * (a[0] * b[1] - a[1] * b[0])};
}

ExactVector ExactVector::input(const Vec3& v) {
    ExactVector e;
    e.value_ = v;
    return e;
}

ExactVector ExactVector::cross(const Vec3& u, const Vec3& v, int sign) {
    ExactVector e;
    e.constructed_ = true;
    e.u_ = u;
    e.v_ = v;
    e.sign_ = sign >= 0 ? 1 : -1;
    // The plain product is exact for small integers; if it overflows (or underflows to zero),
    // scaling the factors first by powers of two keeps it finite for any finite input.
    Vec3 raw = u.cross(v);
    const double m = raw.cwiseAbs().maxCoeff();
    if (!(m > 0x1p-900 && m < 0x1p900)) {
        raw = scaled_by_power_of_two(u).cross(scaled_by_power_of_two(v));
    }
    e.value_ = readable(raw) * static_cast<double>(e.sign_);
    return e;
}

Sign ExactVector::dot_sign(const Vec3& w) const {
    if (!constructed_) return momentlab::dot_sign(value_, w);
    return sign_of_int(sign_) * det_sign(u_, v_, w);
}

Sign ExactVector::dot_sign(const ExactVector& other) const {
    if (!other.constructed_) return dot_sign(other.value_);
    if (!constructed_) return other.dot_sign(value_);
    auto q = [](const Vec3& a, const Vec3& b) -> mpq_class {
        return mpq_class(a.x()) * mpq_class(b.x()) + mpq_class(a.y()) * mpq_class(b.y()) +
               mpq_class(a.z()) * mpq_class(b.z());
    };
    const mpq_class value = q(u_, other.u_) * q(v_, other.v_) - q(u_, other.v_) * q(v_, other.u_);
    return sign_of_int(sgn(value) * sign_ * other.sign_);
}

ExactVector::Filter ExactVector::filter() const {
    // With u = 2^-53: a cross-product coordinate c~ = fl(fl(p) - fl(q)) is within (2u + u^2)
    // (|p| + |q|) of c = p - q, and a three-term dot product adds gamma_3 sum |c~_k| |w_k|, so
    // the error is below 6u sum_k B_k |w_k| with B_k = |p_k| + |q_k| (B_k = |a_k| for inputs).
    // 8u leaves room for the rounding of beta and of beta * max|w|; the range limits keep every
    // product far from overflow and underflow (docs/robustness.md).
    Filter f{Vec3::Zero(), std::numeric_limits<double>::infinity()};
    double b = 0;
    if (!constructed_) {
        f.approx = value_;
        b = value_.cwiseAbs().sum();
    } else {
        const Vec3& p = u_;
        const Vec3& q = v_;
        f.approx = p.cross(q) * static_cast<double>(sign_);
        b = std::abs(p.y() * q.z()) + std::abs(p.z() * q.y()) + std::abs(p.z() * q.x()) + std::abs(p.x() * q.z()) +
            std::abs(p.x() * q.y()) + std::abs(p.y() * q.x());
    }
    if (b >= 0x1p-400 && b <= 0x1p400 && f.approx.allFinite()) f.bound = 0x1p-50 * b;
    return f;
}

ExactVector ExactVector::negated() const {
    ExactVector e = *this;
    e.value_ = -value_;
    e.sign_ = -sign_;
    return e;
}

ExactVector ExactVector::signed_permuted(const Mat3& p) const {
    ExactVector e = *this;
    e.value_ = p * value_;
    if (constructed_) {
        // P (u x v) = det(P) (P u x P v) for orthogonal P.
        e.u_ = p * u_;
        e.v_ = p * v_;
        e.sign_ = sign_ * (p.determinant() > 0 ? 1 : -1);
    }
    return e;
}

Incidence Incidence::transposed(std::size_t columns) const {
    std::vector<int> count(columns + 1, 0);
    for (int i : indices_) ++count[static_cast<std::size_t>(i) + 1];
    Incidence t;
    t.offsets_.assign(columns + 1, 0);
    for (std::size_t c = 0; c < columns; ++c) t.offsets_[c + 1] = t.offsets_[c] + count[c + 1];
    t.indices_.resize(indices_.size());
    std::vector<int> fill(t.offsets_.begin(), t.offsets_.end() - 1);
    for (std::size_t j = 0; j < size(); ++j) {
        for (int i : row(j)) t.indices_[static_cast<std::size_t>(fill[static_cast<std::size_t>(i)]++)] = static_cast<int>(j);
    }
    return t;
}

Cone::Cone() {
    for (int i = 0; i < 3; ++i) equations_.push_back(ExactVector::input(Vec3::Unit(i)));
}

Cone Cone::from_generators(std::span<const Vec3> generators) {
    for (const Vec3& g : generators) {
        if (!g.allFinite()) {
            throw std::invalid_argument("Cone::from_generators: a generator has a NaN or infinite coordinate");
        }
    }
    return ConeBuilder::build(generators);
}

Cone Cone::from_generators(std::span<const Vec3> rays, std::span<const Vec3> lines) {
    std::vector<Vec3> all(rays.begin(), rays.end());
    for (const Vec3& l : lines) {
        all.push_back(l);
        all.push_back(-l);
    }
    return from_generators(all);
}

Cone Cone::from_halfspaces(std::span<const Vec3> normals) {
    for (const Vec3& n : normals) {
        if (!n.allFinite()) {
            throw std::invalid_argument("Cone::from_halfspaces: a normal has a NaN or infinite coordinate");
        }
    }
    return ConeBuilder::build(normals).dual();
}

Cone Cone::whole_space() { return Cone().dual(); }

Cone Cone::half_space(const Vec3& n) {
    if (momentlab::is_zero(n) || !n.allFinite()) {
        throw std::invalid_argument("Cone::half_space: the normal must be finite and non-zero");
    }
    const Vec3 one[] = {n};
    return from_halfspaces(one);
}

std::string Cone::kind() const {
    const int d = dimension(), l = lineality_dimension();
    switch (d) {
        case 0: return "{0}";
        case 1: return l == 1 ? "line" : "ray";
        case 2: return l == 2 ? "plane" : (l == 1 ? "half-plane" : "wedge");
        default: break;
    }
    switch (l) {
        case 3: return "R^3";
        case 2: return "half-space";
        case 1: return "wedge x line";
        default: return "pointed cone";
    }
}

Cone Cone::dual() const {
    Cone d;
    d.rays_ = facets_;
    d.lineality_ = equations_;
    d.facets_ = rays_;
    d.equations_ = lineality_;
    d.exact_ = exact_ == Representation::Generators ? Representation::Halfspaces
                                                    : Representation::Generators;
    // Transpose the incidences: ray j of the dual (facet j of this) lies on facet i of the dual
    // (ray i of this) exactly when ray i lies on facet j here.
    d.facet_rays_ = facet_rays_.transposed(rays_.size());
    return d;
}

Cone Cone::negated() const {
    Cone c = *this;
    for (auto* list : {&c.rays_, &c.lineality_, &c.facets_, &c.equations_}) {
        for (ExactVector& v : *list) v = v.negated();
    }
    return c;
}

Cone Cone::signed_permuted(const Mat3& p) const {
    Cone c = *this;
    for (auto* list : {&c.rays_, &c.lineality_, &c.facets_, &c.equations_}) {
        for (ExactVector& v : *list) v = v.signed_permuted(p);
    }
    return c;
}

Cone Cone::linear_image(const Mat3& m) const {
    if (!m.allFinite() || det_sign(m.col(0), m.col(1), m.col(2)) == Sign::Zero) {
        throw std::invalid_argument("Cone::linear_image: the matrix must be finite and invertible");
    }
    std::vector<Vec3> gens;
    for (const ExactVector& r : rays_) gens.push_back(m * r.value());
    for (const ExactVector& l : lineality_) {
        gens.push_back(m * l.value());
        gens.push_back(-(m * l.value()));
    }
    return from_generators(gens);
}

namespace {

// w satisfies every equation and facet inequality (w a Vec3 or an ExactVector).
template <class W>
bool satisfies(const std::vector<ExactVector>& equations, const std::vector<ExactVector>& facets, const W& w) {
    for (const ExactVector& e : equations) {
        if (e.dot_sign(w) != Sign::Zero) return false;
    }
    for (const ExactVector& f : facets) {
        if (f.dot_sign(w) == Sign::Negative) return false;
    }
    return true;
}

}  // namespace

bool Cone::has(const Vec3& w) const { return satisfies(equations_, facets_, w); }

bool Cone::has(const ExactVector& w) const { return satisfies(equations_, facets_, w); }

bool Cone::in_relative_interior(const Vec3& w) const {
    if (!has(w)) return false;
    for (const ExactVector& f : facets_) {
        if (f.dot_sign(w) != Sign::Positive) return false;
    }
    return true;
}

Membership Cone::contains(const Vec3& w) const {
    if (!w.allFinite()) throw std::invalid_argument("Cone::contains: w has a NaN or infinite coordinate");
    Membership result;
    for (const ExactVector& e : equations_) {
        const Sign s = e.dot_sign(w);
        if (s != Sign::Zero) {
            result.separator = s == Sign::Positive ? e.negated() : e;
            return result;
        }
    }
    for (const ExactVector& f : facets_) {
        if (f.dot_sign(w) == Sign::Negative) {
            result.separator = f;
            return result;
        }
    }
    result.member = true;
    if (momentlab::is_zero(w)) return result;
    // Pick at most three generators whose cone holds w, then solve for the coefficients.
    std::vector<Vec3> columns;
    if (dimension() == 3 && is_pointed()) {
        const std::size_t k = rays_.size();
        const Vec3& r0 = rays_[0].value();
        for (std::size_t i = 1; i + 1 < k; ++i) {
            const Vec3& a = rays_[i].value();
            const Vec3& b = rays_[i + 1].value();
            if (det_sign(r0, a, w) != Sign::Negative && det_sign(r0, b, w) != Sign::Positive) {
                columns = {r0, a, b};
                break;
            }
        }
        if (columns.empty()) columns = {r0, rays_[1].value(), rays_[k - 1].value()};
    } else {
        for (const ExactVector& r : rays_) columns.push_back(r.value());
        for (const ExactVector& l : lineality_) columns.push_back(l.value());
    }
    Eigen::MatrixXd a(3, static_cast<Eigen::Index>(columns.size()));
    for (std::size_t i = 0; i < columns.size(); ++i) a.col(static_cast<Eigen::Index>(i)) = columns[i];
    const Eigen::VectorXd c = a.colPivHouseholderQr().solve(w);
    for (std::size_t i = 0; i < columns.size(); ++i) {
        result.combination.emplace_back(columns[i], c(static_cast<Eigen::Index>(i)));
    }
    return result;
}

std::vector<Face> Cone::faces() const {
    std::vector<Face> out;
    const int d = dimension(), l = lineality_dimension();
    std::vector<int> all_rays(rays_.size());
    std::iota(all_rays.begin(), all_rays.end(), 0);
    out.push_back(Face{d, all_rays, {}});
    if (d == l) return out;  // a linear subspace has no other face
    for (std::size_t j = 0; j < facets_.size(); ++j) {
        const auto row = facet_rays_.row(j);
        out.push_back(Face{d - 1, std::vector<int>(row.begin(), row.end()), {static_cast<int>(j)}});
    }
    if (d - l == 3) {
        for (std::size_t i = 0; i < rays_.size(); ++i) {
            Face f{1, {static_cast<int>(i)}, {}};
            for (std::size_t j = 0; j < facets_.size(); ++j) {
                const auto fr = facet_rays_.row(j);
                if (std::find(fr.begin(), fr.end(), static_cast<int>(i)) != fr.end()) {
                    f.facets.push_back(static_cast<int>(j));
                }
            }
            out.push_back(f);
        }
    }
    if (d - l >= 2) {
        std::vector<int> all_facets(facets_.size());
        std::iota(all_facets.begin(), all_facets.end(), 0);
        out.push_back(Face{l, {}, all_facets});
    }
    return out;
}

Cone Cone::face_cone(const Face& face) const {
    std::vector<Vec3> gens;
    for (int i : face.rays) gens.push_back(rays_[static_cast<std::size_t>(i)].value());
    for (const ExactVector& v : lineality_) {
        gens.push_back(v.value());
        gens.push_back(-v.value());
    }
    return from_generators(gens);
}

std::vector<Vec3> Cone::generator_values() const {
    std::vector<Vec3> out;
    for (const ExactVector& r : rays_) out.push_back(r.value());
    for (const ExactVector& l : lineality_) {
        out.push_back(l.value());
        out.push_back(-l.value());
    }
    return out;
}

std::vector<Vec3> Cone::halfspace_values() const {
    std::vector<Vec3> out;
    for (const ExactVector& f : facets_) out.push_back(f.value());
    for (const ExactVector& e : equations_) {
        out.push_back(e.value());
        out.push_back(-e.value());
    }
    return out;
}

Cone sum(const Cone& f, const Cone& g) {
    std::vector<Vec3> gens = f.generator_values();
    const std::vector<Vec3> more = g.generator_values();
    gens.insert(gens.end(), more.begin(), more.end());
    return Cone::from_generators(gens);
}

Cone sum(std::span<const Cone> cones) {
    std::vector<Vec3> gens;
    for (const Cone& c : cones) {
        const std::vector<Vec3> more = c.generator_values();
        gens.insert(gens.end(), more.begin(), more.end());
    }
    return Cone::from_generators(gens);
}

Cone intersection(const Cone& f, const Cone& g) {
    std::vector<Vec3> normals = f.halfspace_values();
    const std::vector<Vec3> more = g.halfspace_values();
    normals.insert(normals.end(), more.begin(), more.end());
    return Cone::from_halfspaces(normals);
}

bool subset(const Cone& f, const Cone& g) {
    if (f.dimension() > g.dimension() || f.lineality_dimension() > g.lineality_dimension()) {
        return false;
    }
    for (const ExactVector& r : f.rays()) {
        if (!g.has(r)) return false;
    }
    for (const ExactVector& l : f.lineality()) {
        if (!g.has(l) || !g.has(l.negated())) return false;
    }
    return true;
}

bool operator==(const Cone& f, const Cone& g) {
    return f.dimension() == g.dimension() &&
           f.lineality_dimension() == g.lineality_dimension() && subset(f, g) && subset(g, f);
}

}  // namespace momentlab
