#include "momentlab/geometry/cone.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "cone_build.hpp"

namespace momentlab {
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

Cone Cone::from_generators(std::span<const ExactVector> generators) { return ConeBuilder::build(generators); }

Cone Cone::from_halfspaces(std::span<const ExactVector> normals) { return ConeBuilder::build(normals).dual(); }

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

Cone Cone::dual() const& {
    Cone d;
    d.rays_ = facets_;
    d.lineality_ = equations_;
    d.facets_ = rays_;
    d.equations_ = lineality_;
    d.exact_ = exact_ == Representation::Generators ? Representation::Halfspaces
                                                    : Representation::Generators;
    d.facet_rays_ = facet_rays_.transposed(rays_.size());  // see dual() &&
    return d;
}

Cone Cone::dual() && {
    Cone d;
    // Transpose the incidences: ray j of the dual (facet j of this) lies on facet i of the dual
    // (ray i of this) exactly when ray i lies on facet j here.
    d.facet_rays_ = facet_rays_.transposed(rays_.size());
    d.rays_ = std::move(facets_);
    d.lineality_ = std::move(equations_);
    d.facets_ = std::move(rays_);
    d.equations_ = std::move(lineality_);
    d.exact_ = exact_ == Representation::Generators ? Representation::Halfspaces
                                                    : Representation::Generators;
    return d;
}

Cone Cone::negated() const& { return Cone(*this).negated(); }

Cone Cone::negated() && {
    for (auto* list : {&rays_, &lineality_, &facets_, &equations_}) {
        for (ExactVector& v : *list) v = v.negated();
    }
    return std::move(*this);
}

Cone Cone::signed_permuted(const Mat3& p) const& { return Cone(*this).signed_permuted(p); }

Cone Cone::signed_permuted(const Mat3& p) && {
    for (auto* list : {&rays_, &lineality_, &facets_, &equations_}) {
        for (ExactVector& v : *list) v = v.signed_permuted(p);
    }
    // A reflection (det P = -1) turns a pointed cone's cycle clockwise: ray j becomes ray
    // (k - j) mod k (ray 0 stays first), and each facet moves to where its two rays place it
    // (between rays i and i+1 for a cone built from generators, i-1 and i from half-spaces).
    const std::size_t k = rays_.size();
    if (p.determinant() < 0 && k >= 3 && lineality_.empty() && equations_.empty() && facets_.size() == k) {
        auto mirror = [k](int i) { return static_cast<int>((k - static_cast<std::size_t>(i)) % k); };
        std::vector<ExactVector> rays(k), facets(k);
        for (std::size_t i = 0; i < k; ++i) rays[static_cast<std::size_t>(mirror(static_cast<int>(i)))] = std::move(rays_[i]);
        std::vector<std::array<int, 2>> rows(k);
        for (std::size_t f = 0; f < k; ++f) {
            const auto row = facet_rays_.row(f);
            int x = mirror(row[0]), y = mirror(row[1]);
            if (x > y) std::swap(x, y);
            const bool wraps = !(y == x + 1);  // rays 0 and k - 1
            const std::size_t at = static_cast<std::size_t>(exact_ == Representation::Generators ? (wraps ? static_cast<int>(k) - 1 : x)
                                                                                                 : (wraps ? 0 : y));
            facets[at] = std::move(facets_[f]);
            rows[at] = {x, y};
        }
        Incidence incidence;
        incidence.reserve(k, 2);
        for (const auto& r : rows) incidence.add_row({r[0], r[1]});
        rays_ = std::move(rays);
        facets_ = std::move(facets);
        facet_rays_ = std::move(incidence);
    }
    return std::move(*this);
}

Cone Cone::linear_image(const Mat3& m) const {
    if (!m.allFinite()) throw std::invalid_argument("Cone::linear_image: the matrix must be finite and invertible");
    return linear_image(exact(m));
}

Cone Cone::linear_image(const ExactMatrix& m) const {
    if (det(m[0], m[1], m[2]).is_zero()) throw std::invalid_argument("Cone::linear_image: the matrix must be invertible");
    std::vector<ExactVector> gens;
    gens.reserve(rays_.size() + 2 * lineality_.size());
    for (const ExactVector& r : rays_) gens.push_back(r.transformed(m));
    for (const ExactVector& l : lineality_) {
        gens.push_back(l.transformed(m));
        gens.push_back(gens.back().negated());
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

namespace {

template <class W>
bool strictly_inside(const std::vector<ExactVector>& equations, const std::vector<ExactVector>& facets, const W& w) {
    if (!satisfies(equations, facets, w)) return false;
    for (const ExactVector& f : facets) {
        if (f.dot_sign(w) != Sign::Positive) return false;
    }
    return true;
}

}  // namespace

bool Cone::in_relative_interior(const Vec3& w) const { return strictly_inside(equations_, facets_, w); }

bool Cone::in_relative_interior(const ExactVector& w) const { return strictly_inside(equations_, facets_, w); }

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
        const ExactVector exact_w = ExactVector::input(w);
        const std::size_t k = rays_.size();
        const Vec3& r0 = rays_[0].value();
        for (std::size_t i = 1; i + 1 < k; ++i) {
            const Vec3& a = rays_[i].value();
            const Vec3& b = rays_[i + 1].value();
            if (det_sign(rays_[0], rays_[i], exact_w) != Sign::Negative &&
                det_sign(rays_[0], rays_[i + 1], exact_w) != Sign::Positive) {
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
    if (d - l == 3) {  // the rays of a pointed cone, each with the facets through it (increasing)
        const Incidence through = facet_rays_.transposed(rays_.size());
        for (std::size_t i = 0; i < rays_.size(); ++i) {
            const auto row = through.row(i);
            out.push_back(Face{1, {static_cast<int>(i)}, std::vector<int>(row.begin(), row.end())});
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
    std::vector<ExactVector> gens;
    for (int i : face.rays) gens.push_back(rays_[static_cast<std::size_t>(i)]);
    for (const ExactVector& v : lineality_) {
        gens.push_back(v);
        gens.push_back(v.negated());
    }
    return from_generators(gens);
}

std::vector<ExactVector> Cone::generators() const {
    std::vector<ExactVector> out(rays_.begin(), rays_.end());
    for (const ExactVector& l : lineality_) {
        out.push_back(l);
        out.push_back(l.negated());
    }
    return out;
}

std::vector<ExactVector> Cone::halfspaces() const {
    std::vector<ExactVector> out(facets_.begin(), facets_.end());
    for (const ExactVector& e : equations_) {
        out.push_back(e);
        out.push_back(e.negated());
    }
    return out;
}

std::vector<Vec3> Cone::generator_values() const {
    std::vector<Vec3> out;
    for (const ExactVector& g : generators()) out.push_back(g.value());
    return out;
}

std::vector<Vec3> Cone::halfspace_values() const {
    std::vector<Vec3> out;
    for (const ExactVector& h : halfspaces()) out.push_back(h.value());
    return out;
}

namespace {

// big + small for a pointed 3-dimensional `big` of kBig rays or more and a `small` of at most
// kFew generators, as the dual of big* cut by each generator's half-space (ConeBuilder::cut,
// O(m) each for m facets): a mode's applied wrenches E = F + (-T) add the one or two rays of F
// to a contact cone of up to 2n rays. Nothing when a cut leaves the pointed 3-dimensional cones
// (then the general sum).
std::optional<Cone> sum_by_cuts(const Cone& big, const Cone& small) {
    constexpr std::size_t kFew = 4;
    // Below some 64 rays a new hull (on a stack buffer) is cheaper than the cut's lists.
    constexpr std::size_t kBig = 64;
    if (big.dimension() != 3 || !big.is_pointed() || big.rays().size() < kBig) return std::nullopt;
    const std::vector<ExactVector> gens = small.generators();
    if (gens.size() > kFew) return std::nullopt;
    Cone d = big.dual();
    for (const ExactVector& v : gens) {
        std::optional<Cone> cut = ConeBuilder::cut(d, v);
        if (!cut) return std::nullopt;
        d = std::move(*cut);
    }
    return std::move(d).dual();
}

}  // namespace

Cone sum(const Cone& f, const Cone& g) {
    if (std::optional<Cone> s = sum_by_cuts(f, g)) return std::move(*s);
    if (std::optional<Cone> s = sum_by_cuts(g, f)) return std::move(*s);
    std::vector<ExactVector> gens = f.generators();
    const std::vector<ExactVector> more = g.generators();
    gens.insert(gens.end(), more.begin(), more.end());
    return Cone::from_generators(gens);
}

Cone sum(std::span<const Cone> cones) {
    std::vector<ExactVector> gens;
    for (const Cone& c : cones) {
        const std::vector<ExactVector> more = c.generators();
        gens.insert(gens.end(), more.begin(), more.end());
    }
    return Cone::from_generators(gens);
}

Cone intersection(const Cone& f, const Cone& g) {
    // A pointed cone cut by a half-space (labels' sheets): its facets need no sorting again.
    if (g.dimension() == 3 && g.lineality_dimension() == 2 && g.facets().size() == 1) {
        if (std::optional<Cone> cut = ConeBuilder::cut(f, g.facets()[0])) return std::move(*cut);
    }
    std::vector<ExactVector> normals = f.halfspaces();
    const std::vector<ExactVector> more = g.halfspaces();
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

bool meets_interior(const Cone& c, const Cone& e) {
    if (e.dimension() < 3 || c.is_zero()) return false;
    const auto on = [](const ExactVector& facet, const ExactVector& g) { return facet.dot_sign(g) == Sign::Zero; };
    for (const ExactVector& facet : e.facets()) {
        const bool inside_facet =
            std::all_of(c.rays().begin(), c.rays().end(), [&](const ExactVector& r) { return on(facet, r); }) &&
            std::all_of(c.lineality().begin(), c.lineality().end(), [&](const ExactVector& l) { return on(facet, l); });
        if (inside_facet) return false;
    }
    return true;
}

bool operator==(const Cone& f, const Cone& g) {
    return f.dimension() == g.dimension() &&
           f.lineality_dimension() == g.lineality_dimension() && subset(f, g) && subset(g, f);
}

}  // namespace momentlab
