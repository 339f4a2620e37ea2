#pragma once

/// \file
/// Closed polyhedral convex cones of R^3 (planar wrenches, twists, covectors), kept in both
/// representations at once, each minimal (DESIGN, "The mathematics in one page").

#include <gmpxx.h>

#include <array>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

#include "momentlab/core/predicates.hpp"
#include "momentlab/core/sign.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// An exact rational vector of R^3 (GMP), for predicates of degree above three.
using Rational3 = std::array<mpq_class, 3>;

/// The doubles of v as exact rationals.
[[nodiscard]] Rational3 to_rational(const Vec3& v);

/// A vector known exactly: either stored doubles (an input of some construction), or
/// `sign * (u x v)` for two stored vectors u, v (a construction, such as a facet normal through
/// two extreme rays). `value()` is the rounded value (exact for inputs, and for cross products
/// whose products are representable, e.g. small integers); `dot_sign` is always exact.
class ExactVector {
public:
    /// A stored input vector.
    static ExactVector input(const Vec3& v);
    /// The construction sign * (u x v); `sign` is +1 or -1.
    static ExactVector cross(const Vec3& u, const Vec3& v, int sign);

    /// The rounded value (scaled to a readable magnitude for constructions; see docs/robustness.md).
    [[nodiscard]] const Vec3& value() const { return value_; }
    /// True for constructions, false for inputs.
    [[nodiscard]] bool is_constructed() const { return constructed_; }
    /// The exact sign of (this vector) . w.
    [[nodiscard]] Sign dot_sign(const Vec3& w) const;
    /// The exact sign of (this vector) . other; two constructions use the Binet-Cauchy
    /// identity (u x v) . (a x b) = (u.a)(v.b) - (u.b)(v.a) in rational arithmetic.
    [[nodiscard]] Sign dot_sign(const ExactVector& other) const;
    /// The vector -v, with the same exactness.
    [[nodiscard]] ExactVector negated() const;
    /// The exact value as rationals (the cross product computed exactly for constructions).
    [[nodiscard]] Rational3 rational() const;
    /// The image under a signed permutation matrix P (exact): P v.
    [[nodiscard]] ExactVector signed_permuted(const Mat3& p) const;

    /// A rounded copy of the exact vector for a certified float filter (docs/robustness.md).
    struct Filter {
        Vec3 approx;  ///< the exact vector rounded (unscaled: sign * (u x v) for constructions)
        double bound; ///< beta: |a.w - fl(approx.w)| <= beta * max_k |w_k|, or +inf (see filter())
    };
    /// The filter of this vector. The bound holds for any finite w with max_k |w_k| in
    /// [2^-300, 2^300] and any evaluation order of the three-term dot product; it is +inf
    /// (never certain) when the vector's magnitude is outside [2^-400, 2^400].
    [[nodiscard]] Filter filter() const;

private:
    Vec3 value_ = Vec3::Zero();
    Vec3 u_ = Vec3::Zero();
    Vec3 v_ = Vec3::Zero();
    int sign_ = 1;
    bool constructed_ = false;
};

/// Which extreme rays lie on each facet, stored as compressed rows (one allocation for all).
class Incidence {
public:
    /// Appends the row of the next facet: indices of the rays on it, increasing.
    void add_row(std::initializer_list<int> rays) { add_row(std::span<const int>(rays.begin(), rays.size())); }
    /// Reserves room for `rows` rows of `per_row` rays on average.
    void reserve(std::size_t rows, std::size_t per_row) {
        offsets_.reserve(rows + 1);
        indices_.reserve(rows * per_row);
    }
    void add_row(std::span<const int> rays) {
        indices_.insert(indices_.end(), rays.begin(), rays.end());
        offsets_.push_back(static_cast<int>(indices_.size()));
    }
    /// The rays on facet j.
    [[nodiscard]] std::span<const int> row(std::size_t j) const {
        return {indices_.data() + offsets_[j], static_cast<std::size_t>(offsets_[j + 1] - offsets_[j])};
    }
    /// The number of facets.
    [[nodiscard]] std::size_t size() const { return offsets_.size() - 1; }
    /// The incidence seen from the other side: for each of `columns` rays, the facets through it.
    [[nodiscard]] Incidence transposed(std::size_t columns) const;

private:
    std::vector<int> offsets_{0};
    std::vector<int> indices_;
};

/// Which representation of a cone was given exactly; the other one is computed from it.
enum class Representation { Generators, Halfspaces };

/// A face of a cone: its dimension, the extreme rays it contains and the facets containing it
/// (indices into `Cone::rays()` and `Cone::facets()`). Every face contains the lineality space.
struct Face {
    int dimension = 0;         ///< 0 .. 3
    std::vector<int> rays;     ///< extreme rays of the cone lying in this face
    std::vector<int> facets;   ///< facets of the cone containing this face
};

/// The answer of `Cone::contains`, with a certificate either way.
struct Membership {
    bool member = false;  ///< the exact answer
    /// For members: w = sum of coefficient * generator over these pairs; generators are rays
    /// (coefficient >= 0) and lineality vectors (any sign). Coefficients are rounded.
    std::vector<std::pair<Vec3, double>> combination;
    /// For non-members: a functional h, valid on the cone (a facet normal, or +-an equation),
    /// with exactly h . w < 0.
    ExactVector separator = ExactVector::input(Vec3::Zero());
};

/// A closed polyhedral convex cone C of R^3.
///
/// V-representation: C = cone(rays) + span(lineality); H-representation:
/// C = {x : f . x >= 0 for f in facets, e . x = 0 for e in equations}. Both are minimal.
/// For a full-dimensional pointed cone the rays are in counter-clockwise cyclic order
/// (det(r_i, r_i+1, r_i+2) > 0) and facet i lies between ray i and ray i+1.
/// Every decision (which generator is extreme, membership, equality) is exact for the stored
/// doubles; see docs/robustness.md for what is rounded.
class Cone {
public:
    /// The cone {0}.
    Cone();
    /// The cone generated by `generators` (non-negative combinations; zero vectors ignored).
    /// Throws std::invalid_argument if a coordinate is NaN or infinite.
    /// O(n log n) whenever the angular order around a pivot decides the cone: a pointed cone
    /// whose guessed pivot is an extreme ray, or any cone whose pivot lies on its boundary
    /// (at most three pivots are tried). Otherwise (R^3, or a pivot interior to a half-space
    /// or cone) an exact dual clip in O(n m), m the size of the intermediate duals: small
    /// there, as the dual shrinks to a point or to nothing (docs/architecture.md).
    static Cone from_generators(std::span<const Vec3> generators);
    /// The cone {x : n . x >= 0 for every n in `normals`} (the dual of from_generators).
    static Cone from_halfspaces(std::span<const Vec3> normals);
    /// The cone generated by rays plus the linear span of `lines`.
    static Cone from_generators(std::span<const Vec3> rays, std::span<const Vec3> lines);
    /// R^3.
    static Cone whole_space();
    /// A closed half-space {x : n . x >= 0}; n must be non-zero.
    static Cone half_space(const Vec3& n);

    [[nodiscard]] const std::vector<ExactVector>& rays() const { return rays_; }
    [[nodiscard]] const std::vector<ExactVector>& lineality() const { return lineality_; }
    [[nodiscard]] const std::vector<ExactVector>& facets() const { return facets_; }
    [[nodiscard]] const std::vector<ExactVector>& equations() const { return equations_; }
    /// For each facet, the indices of the extreme rays lying on it.
    [[nodiscard]] const Incidence& facet_rays() const { return facet_rays_; }
    /// Which representation is exact input.
    [[nodiscard]] Representation exact_representation() const { return exact_; }

    /// Dimension of the linear span, 0 .. 3.
    [[nodiscard]] int dimension() const { return 3 - static_cast<int>(equations_.size()); }
    /// Dimension of the largest linear subspace contained in the cone, 0 .. 3.
    [[nodiscard]] int lineality_dimension() const { return static_cast<int>(lineality_.size()); }
    /// True when the cone contains no line.
    [[nodiscard]] bool is_pointed() const { return lineality_.empty(); }
    [[nodiscard]] bool is_zero() const { return dimension() == 0; }
    [[nodiscard]] bool is_whole_space() const { return lineality_dimension() == 3; }
    /// A short name: "{0}", "ray", "line", "wedge", "half-plane", "plane", "pointed cone",
    /// "wedge x line", "half-space", "R^3".
    [[nodiscard]] std::string kind() const;

    /// The dual cone C* = {v : v . w >= 0 for all w in C}. Exact (swaps the representations).
    [[nodiscard]] Cone dual() const;
    /// -C. Exact.
    [[nodiscard]] Cone negated() const;
    /// The image M C under an invertible matrix. Rounds M r unless the products are exact.
    [[nodiscard]] Cone linear_image(const Mat3& m) const;
    /// The image P C under a signed permutation matrix (exact, keeps every representation).
    [[nodiscard]] Cone signed_permuted(const Mat3& p) const;

    /// Exact membership of w, with a certificate.
    [[nodiscard]] Membership contains(const Vec3& w) const;
    /// Exact membership without the certificate.
    [[nodiscard]] bool has(const Vec3& w) const;
    /// Exact membership of an exactly known vector (e.g. a ray of another cone).
    [[nodiscard]] bool has(const ExactVector& w) const;
    /// Exact test that w lies in the relative interior.
    [[nodiscard]] bool in_relative_interior(const Vec3& w) const;

    /// All faces, the cone itself first and the lineality space (minimal face) last.
    [[nodiscard]] std::vector<Face> faces() const;
    /// The face as a cone of its own.
    [[nodiscard]] Cone face_cone(const Face& face) const;

    /// The generators of the V-representation as plain vectors: rays, then +-lineality.
    [[nodiscard]] std::vector<Vec3> generator_values() const;
    /// The normals of the H-representation as plain half-spaces: facets, then +-equations.
    [[nodiscard]] std::vector<Vec3> halfspace_values() const;

private:
    std::vector<ExactVector> rays_;
    std::vector<ExactVector> lineality_;
    std::vector<ExactVector> facets_;
    std::vector<ExactVector> equations_;
    Incidence facet_rays_;
    Representation exact_ = Representation::Generators;

    friend struct ConeBuilder;
};

/// The Minkowski sum F + G: all resultants (the paper's CH(F, G)).
[[nodiscard]] Cone sum(const Cone& f, const Cone& g);
/// The sum of several cones.
[[nodiscard]] Cone sum(std::span<const Cone> cones);
/// The intersection F n G, computed as (F* + G*)*.
[[nodiscard]] Cone intersection(const Cone& f, const Cone& g);
/// True when F is a subset of G. Exact (F's generators against G's half-spaces, both exact).
[[nodiscard]] bool subset(const Cone& f, const Cone& g);
/// Set equality (subset both ways).
[[nodiscard]] bool operator==(const Cone& f, const Cone& g);

}  // namespace momentlab
