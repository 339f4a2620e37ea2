#pragma once

/// \file
/// Closed polyhedral convex cones of R^3 (planar wrenches, twists, covectors), kept in both
/// representations at once, each minimal (docs/design.md, "The mathematics").

#include <initializer_list>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "momentlab/core/exact.hpp"
#include "momentlab/core/sign.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// Which extreme rays lie on each facet, stored as compressed rows: while every row has the
/// same length (the two rays of each facet of a pointed cone) only the indices are stored, one
/// allocation; rows of different lengths add their offsets. The cyclic incidence of a pointed
/// cone of up to 1024 facets is read from tables shared by all cones: no allocation.
class Incidence {
public:
    /// Appends the row of the next facet: indices of the rays on it, increasing.
    void add_row(std::initializer_list<int> rays) { add_row(std::span<const int>(rays.begin(), rays.size())); }
    /// Reserves room for `rows` rows of `per_row` rays on average.
    void reserve(std::size_t rows, std::size_t per_row) { indices_.reserve(rows * per_row); }
    void add_row(std::span<const int> rays) {
        if (shared_ != nullptr) own();
        const int length = static_cast<int>(rays.size());
        if (offsets_.empty() && rows_ > 0 && length != stride_) {  // lengths differ from now on
            offsets_.reserve(static_cast<std::size_t>(rows_) + 2);
            for (int j = 0; j <= rows_; ++j) offsets_.push_back(j * stride_);
        }
        if (rows_ == 0) stride_ = length;
        indices_.insert(indices_.end(), rays.begin(), rays.end());
        if (!offsets_.empty()) offsets_.push_back(static_cast<int>(indices_.size()));
        ++rows_;
    }
    /// The rays on facet j.
    [[nodiscard]] std::span<const int> row(std::size_t j) const {
        if (shared_ != nullptr) return {j + 1 < static_cast<std::size_t>(rows_) ? shared_ + 2 * j : last_, 2};
        if (offsets_.empty()) return {indices_.data() + j * static_cast<std::size_t>(stride_), static_cast<std::size_t>(stride_)};
        return {indices_.data() + offsets_[j], static_cast<std::size_t>(offsets_[j + 1] - offsets_[j])};
    }
    /// The number of facets.
    [[nodiscard]] std::size_t size() const { return static_cast<std::size_t>(rows_); }
    /// The incidence of a pointed cone's k >= 3 facets in cyclic order: facet i holds rays i
    /// and i + 1 (mod k).
    [[nodiscard]] static Incidence cyclic(std::size_t k);
    /// The incidence seen from the other side: for each of `columns` rays, the facets through it.
    [[nodiscard]] Incidence transposed(std::size_t columns) const;

private:
    // Row j is indices_[offsets_[j], offsets_[j + 1]), or indices_[j * stride_, (j + 1) *
    // stride_) while offsets_ is empty (every row so far has stride_ indices). A cyclic
    // incidence from the shared tables has no indices_: row j is shared_[2j, 2j + 2) = {j, j + 1},
    // and the last row last_[0, 2) = {0, rows_ - 1}.
    void own();  // the shared rows copied into indices_
    const int* shared_ = nullptr;
    const int* last_ = nullptr;
    std::vector<int> offsets_;
    std::vector<int> indices_;
    int rows_ = 0;
    int stride_ = 0;
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
/// (det(r_i, r_i+1, r_i+2) > 0) and each facet holds two consecutive rays (`facet_rays()`):
/// facet i lies between ray i and ray i+1 for a cone built from generators, between ray i-1 and
/// ray i for one built from half-spaces (the dual of a cone built from generators).
/// Every decision (which generator is extreme, membership, equality) is exact for the exact
/// generators or half-spaces given (stored doubles or exact constructions, core/exact.hpp);
/// only the printed values are rounded (docs/robustness.md).
class Cone {
public:
    /// The cone {0}.
    Cone();
    /// The cone generated by `generators` (non-negative combinations; zero vectors ignored).
    /// Throws std::invalid_argument if a coordinate is NaN or infinite.
    /// A pointed cone of up to 128 generators whose mean direction (nearly) has every generator
    /// in front of it is found as a convex hull in a plane across it (Andrew's monotone chain
    /// on exact determinants, O(n log n)). Otherwise: O(n log n) whenever the angular order around a pivot decides the cone: a pointed cone
    /// whose guessed pivot is an extreme ray, or any cone whose pivot lies on its boundary
    /// (at most three pivots are tried). Otherwise (R^3, or a pivot interior to a half-space
    /// or cone) an exact dual clip in O(n m), m the size of the intermediate duals: small
    /// there, as the dual shrinks to a point or to nothing (docs/architecture.md).
    static Cone from_generators(std::span<const Vec3> generators);
    /// The cone generated by exact vectors (the same algorithm on exact predicates).
    static Cone from_generators(std::span<const ExactVector> generators);
    /// The cone {x : n . x >= 0 for every n in `normals`} (the dual of from_generators).
    static Cone from_halfspaces(std::span<const Vec3> normals);
    static Cone from_halfspaces(std::span<const ExactVector> normals);
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
    [[nodiscard]] Cone dual() const&;
    [[nodiscard]] Cone dual() &&;  ///< the same, made from this cone's own lists (no copy)
    /// -C. Exact.
    [[nodiscard]] Cone negated() const&;
    [[nodiscard]] Cone negated() &&;  ///< the same, in place (no copy)
    /// The image M C under an invertible matrix, exact (the images of the generators are exact
    /// vectors). Throws std::invalid_argument for a singular (or non-finite) matrix.
    [[nodiscard]] Cone linear_image(const Mat3& m) const;
    [[nodiscard]] Cone linear_image(const ExactMatrix& m) const;
    /// The image P C under a signed permutation matrix (exact, keeps every representation; a
    /// reflection, det P = -1, reverses a pointed cone's cycle after ray 0, so that it stays
    /// counter-clockwise, and moves each facet to the place its two rays give it).
    [[nodiscard]] Cone signed_permuted(const Mat3& p) const&;
    [[nodiscard]] Cone signed_permuted(const Mat3& p) &&;  ///< the same, in place (no copy)

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

    /// The generators of the V-representation, exact: rays, then +-lineality.
    [[nodiscard]] std::vector<ExactVector> generators() const;
    /// The normals of the H-representation, exact: facets, then +-equations.
    [[nodiscard]] std::vector<ExactVector> halfspaces() const;
    /// The generators rounded (for drawing and printing): rays, then +-lineality.
    [[nodiscard]] std::vector<Vec3> generator_values() const;
    /// The half-space normals rounded: facets, then +-equations.
    [[nodiscard]] std::vector<Vec3> halfspace_values() const;

private:
    // Every member moved in, for ConeBuilder (which has made each list minimal).
    Cone(std::vector<ExactVector>&& rays, std::vector<ExactVector>&& lineality, std::vector<ExactVector>&& facets,
         std::vector<ExactVector>&& equations, Incidence&& facet_rays, Representation exact)
        : rays_(std::move(rays)), lineality_(std::move(lineality)), facets_(std::move(facets)),
          equations_(std::move(equations)), facet_rays_(std::move(facet_rays)), exact_(exact) {}

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

/// True when the cone c (a subset of e) contains a point of the interior of e: c lies in no
/// facet of e. False whenever e is not full-dimensional. Exact.
[[nodiscard]] bool meets_interior(const Cone& c, const Cone& e);
/// Set equality (subset both ways).
[[nodiscard]] bool operator==(const Cone& f, const Cone& g);

}  // namespace momentlab
