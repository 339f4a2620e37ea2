#pragma once

/// \file
/// Exact vectors of R^3 and the exact predicates on them: the one home of momentlab's exact
/// arithmetic beyond single doubles (core/predicates.hpp has the predicates on doubles,
/// core/dyadic.hpp the numbers).
///
/// Every vector momentlab decides with is an exact expression of the input doubles: a
/// contact wrench (n, p x n), a friction edge n + mu t acting at p, a facet normal u x v, an
/// image M r under the inertia matrix. An `ExactVector` carries that exact value, a rounded
/// value for printing, and a certified approximation. Its predicates (signs of dot products,
/// 2x2 minors and 3x3 determinants) are those of core/predicates.hpp, decided by the same
/// filter adaptor: on the approximations (core/approx.hpp) when their bound decides, else by
/// exact zeros the constructions show, the wrenches' own stage, and Dyadic arithmetic
/// (docs/robustness.md).

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

#include "momentlab/core/approx.hpp"
#include "momentlab/core/dyadic.hpp"
#include "momentlab/core/predicates.hpp"
#include "momentlab/core/vec.hpp"

namespace momentlab {

/// Exact vectors and matrices of Dyadic numbers.
using Exact2 = std::array<Dyadic, 2>;
using Exact3 = std::array<Dyadic, 3>;
/// A 3x3 matrix by rows.
using ExactMatrix = std::array<Exact3, 3>;

/// The doubles of v, exactly.
[[nodiscard]] Exact2 exact(const Vec2& v);
[[nodiscard]] Exact3 exact(const Vec3& v);
[[nodiscard]] ExactMatrix exact(const Mat3& m);

[[nodiscard]] Dyadic dot(const Exact3& a, const Exact3& b);
[[nodiscard]] Exact3 cross(const Exact3& a, const Exact3& b);
/// det[a b c] = a . (b x c).
[[nodiscard]] Dyadic det(const Exact3& a, const Exact3& b, const Exact3& c);
/// The planar cross product a.x b.y - a.y b.x.
[[nodiscard]] Dyadic cross2(const Exact2& a, const Exact2& b);
[[nodiscard]] Exact3 operator+(const Exact3& a, const Exact3& b);
[[nodiscard]] Exact3 operator-(const Exact3& a, const Exact3& b);
[[nodiscard]] Exact3 operator-(const Exact3& a);
[[nodiscard]] Exact3 operator*(const Dyadic& s, const Exact3& a);
[[nodiscard]] Exact3 operator*(const ExactMatrix& m, const Exact3& a);
[[nodiscard]] Exact2 operator+(const Exact2& a, const Exact2& b);
[[nodiscard]] Exact2 operator-(const Exact2& a, const Exact2& b);
[[nodiscard]] Exact2 operator*(const Dyadic& s, const Exact2& a);
[[nodiscard]] bool is_zero(const Exact3& a);
/// The vector rounded coordinate by coordinate (each with relative error below 2^-52).
[[nodiscard]] Vec3 to_double(const Exact3& a);
[[nodiscard]] Vec2 to_double(const Exact2& a);

/// The wrench of the force d acting through p: (d, p x d), exactly.
[[nodiscard]] Exact3 wrench_through(const Exact2& p, const Exact2& d);

/// A vector of R^3 known exactly: stored doubles (an input), sign * (u x v) for two stored
/// vectors u, v (kept as u and v, the product computed only when needed), or any other exact
/// vector (its Dyadic coordinates, shared between copies). `value()` is a rounded copy for
/// printing; every predicate is exact.
class ExactVector {
public:
    /// Zero.
    ExactVector() = default;
    /// A stored input vector (as input(v); a constructor, so that a list makes it in place).
    explicit ExactVector(const Vec3& v) : value_(v) {}
    /// sign * (u x v) of two stored vectors, as cross(u, v, sign) makes it (in place).
    ExactVector(const Vec3& u, const Vec3& v, int sign);
    /// A stored input vector.
    static ExactVector input(const Vec3& v) { return ExactVector(v); }
    /// The construction sign * (u x v) of two stored vectors; `sign` is +1 or -1.
    static ExactVector cross(const Vec3& u, const Vec3& v, int sign) { return {u, v, sign}; }
    /// sign * (u x v) for any exact u, v.
    static ExactVector cross(const ExactVector& u, const ExactVector& v, int sign = 1);
    /// The exact vector e (an input when every coordinate is a double).
    static ExactVector from_exact(const Exact3& e);
    /// The wrench (d, p x d) of the force d acting through p: the same vector as
    /// from_exact(wrench_through(exact(p), exact(d))), with the same value(), but kept as the
    /// cross product (p.y, -p.x, 1) x (d.y, -d.x, 0) of two stored vectors, so it holds no
    /// Dyadic numbers (a contact's normal and tangent wrenches, 10^5 of each in a big scene).
    static ExactVector wrench(const Vec2& p, const Vec2& d);
    /// For a vector stored as sign (u x v) with u.z = 1 and v.z = 0, which is sign times the
    /// wrench of the force (-v.y, v.x) through (-u.y, u.x) (every wrench() in the readable range):
    /// that point, that direction and the sign. False for any other vector.
    [[nodiscard]] bool force(Vec2& point, Vec2& direction, int& sign) const;

    /// The rounded value, scaled by a power of two (or, for integers, divided by their gcd) to a
    /// readable magnitude: the same direction, always finite. Exact for inputs.
    [[nodiscard]] const Vec3& value() const { return value_; }
    /// True for constructions, false for inputs.
    [[nodiscard]] bool is_constructed() const { return kind_ != Kind::Input; }
    /// The exact sign of (this vector) . w.
    [[nodiscard]] Sign dot_sign(const Vec3& w) const;
    /// The exact sign of (this vector) . other.
    [[nodiscard]] Sign dot_sign(const ExactVector& other) const;
    /// -v, with the same exactness.
    [[nodiscard]] ExactVector negated() const;
    /// The exact coordinates.
    [[nodiscard]] Exact3 exact() const;
    /// The image P v under a signed permutation matrix P (exact).
    [[nodiscard]] ExactVector signed_permuted(const Mat3& p) const;
    /// The image M v under an exact matrix.
    [[nodiscard]] ExactVector transformed(const ExactMatrix& m) const;

    /// A certified approximation: the exact vector is 2^k (approx + d) for some integer k, with
    /// max |approx_i| <= 2 and, coordinate by coordinate, |d_i| <= err_i and |d_i| <= gamma(4)
    /// magnitude_i with magnitude_i >= |approx_i| (the form the filters read: coordinate i is
    /// Approx{approx_i, magnitude_i, 4}, core/approx.hpp). err and magnitude are +inf when there
    /// is none (then every predicate takes the exact path). Bounds per coordinate make the
    /// filters blind to a scaling of one coordinate: a scene 2^40 times larger has torques 2^40
    /// times larger than its forces, and its wrenches keep every bit of their forces.
    struct Approximation {
        Vec3 approx = Vec3::Zero();
        Vec3 err = Vec3::Zero();
        Vec3 magnitude = Vec3::Constant(std::numeric_limits<double>::infinity());  ///< (unset: no bound)
    };
    [[nodiscard]] Approximation approximation() const;

    /// True when both store one construction (the same doubles, the same pair of factors or the
    /// same shared Dyadic coordinates in the same places), so that they are equal or opposite:
    /// the predicates' exact zeros for a vector and its copy (a contact's normal and A's facet
    /// made from it) without Dyadic arithmetic. False says nothing.
    [[nodiscard]] bool same_construction(const ExactVector& other) const;

    /// A rounded copy for a certified float filter of dot products (QueryIndex).
    struct Filter {
        Vec3 approx;   ///< the exact vector divided by a power of two, rounded
        double bound;  ///< |v . w / 2^k - fl(approx . w)| <= bound * max_k |w_k| for finite w
                       ///< with max_k |w_k| in [2^-300, 2^300] (any evaluation order), or +inf
    };
    [[nodiscard]] Filter filter() const;

private:
    enum class Kind : unsigned char { Input, Cross, Computed };
    static ExactVector computed(Exact3 e);

    Vec3 value_ = Vec3::Zero();
    Vec3 u_ = Vec3::Zero();
    Vec3 v_ = Vec3::Zero();
    // Computed: the three exact coordinates packed in one shared block of words (their
    // exponents, signs and sizes, then their limbs: no unused room); the approximation and its
    // magnitudes live in the object (u_, v_).
    std::shared_ptr<const Dyadic::Limb> computed_;
    signed char sign_ = 1;  // Cross and Computed: the vector is sign_ times the construction
    Kind kind_ = Kind::Input;
    // Computed: coordinate i is +-(the stored coordinate |from_[i]| - 1), negated when from_[i]
    // < 0, so a signed permutation (labels' K) shares the stored numbers instead of copying them.
    std::array<signed char, 3> from_{1, 2, 3};
    // Cross made by wrench(): the approximation is value_ 2^approx_shift_ (found when the vector
    // is made, kept by copies, negation and signed permutations), so predicates read it with
    // three multiplications; kNoShift where value_ is not a power of two of it, and for the
    // crosses of cross(), whose facets are tested a few times each (then it is computed from u_
    // and v_).
    static constexpr std::int16_t kNoShift = INT16_MIN;
    std::int16_t approx_shift_ = kNoShift;
    void keep_approximation_shift(const Vec3& base);
};

/// The certified approximations of a vector's coordinates, as the filters read them.
[[nodiscard]] inline Approx3 approximate(const ExactVector::Approximation& p) {
    return {Approx{p.approx.x(), p.magnitude.x(), Approx::kWithinDepth}, Approx{p.approx.y(), p.magnitude.y(), Approx::kWithinDepth},
            Approx{p.approx.z(), p.magnitude.z(), Approx::kWithinDepth}};
}
/// An exact vector's approximation, for the filter adaptor (core/predicates.hpp).
[[nodiscard]] inline Approx3 approximate(const ExactVector& v) { return approximate(v.approximation()); }

/// The sign of a . b from the approximations of a and b alone: true (and the sign in `out`)
/// when their error bounds decide it, false when only exact arithmetic can. It is the filter
/// of every dot_sign below, here inline for a loop that tests one plane against many vectors
/// and calls dot_sign only where this fails (the signs such a loop decides itself are not
/// counted in exact_stats()).
[[nodiscard]] inline bool dot_sign_by_approximations(const ExactVector::Approximation& pa,
                                                     const ExactVector::Approximation& pb, Sign& out) {
    return filter_sign(Dot{}, out, approximate(pa), approximate(pb));
}

/// The exact sign of a . b.
[[nodiscard]] Sign dot_sign(const ExactVector& a, const ExactVector& b);
/// The exact sign of a . b for b given by its Dyadic coordinates (no ExactVector made of b: the
/// filter rounds b on the spot).
[[nodiscard]] Sign dot_sign(const ExactVector& a, const Exact3& b);
/// The certified approximation of exact coordinates, as ExactVector::approximation() gives it
/// for a vector made of them: kept beside b when b is tested many times.
[[nodiscard]] ExactVector::Approximation approximation(const Exact3& b);
/// dot_sign(a, b) with b's approximation(b) given, so that b is not rounded again.
[[nodiscard]] Sign dot_sign(const ExactVector& a, const Exact3& b, const ExactVector::Approximation& b_approximation);
/// dot_sign(a, b) with their approximation()s given, so that neither is rounded again (a plane
/// tested against many vectors).
[[nodiscard]] Sign dot_sign(const ExactVector& a, const ExactVector& b, const ExactVector::Approximation& pa,
                            const ExactVector::Approximation& pb);
/// dot_sign(a, b) for b given by its Dyadic coordinates, with a's approximation() and b's given.
[[nodiscard]] Sign dot_sign(const ExactVector& a, const Exact3& b, const ExactVector::Approximation& pa,
                            const ExactVector::Approximation& pb);
/// The exact sign of det[a b c].
[[nodiscard]] Sign det_sign(const ExactVector& a, const ExactVector& b, const ExactVector& c);
/// det_sign(a, b, c) with their approximation()s given, so that none is rounded again (a scan of
/// many c against fixed a and b).
[[nodiscard]] Sign det_sign(const ExactVector& a, const ExactVector& b, const ExactVector& c,
                            const ExactVector::Approximation& pa, const ExactVector::Approximation& pb,
                            const ExactVector::Approximation& pc);
/// The exact sign of the minor a[i] b[j] - a[j] b[i].
[[nodiscard]] Sign minor_sign(const ExactVector& a, const ExactVector& b, int i, int j);
/// True when a x b = 0 exactly.
[[nodiscard]] bool parallel(const ExactVector& a, const ExactVector& b);
/// True when every coordinate is exactly zero.
[[nodiscard]] bool is_zero(const ExactVector& v);

/// Counters of the exact-vector predicates the approximations could not decide (per thread; the
/// work a thread shares out through for_each_index, core/parallel.hpp, counts as its own).
struct ExactStats {
    long filtered = 0;  ///< decided by the certified approximations
    long exact = 0;     ///< decided in Dyadic arithmetic
};
[[nodiscard]] ExactStats& exact_stats();

}  // namespace momentlab
