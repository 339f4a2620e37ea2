// The exact predicates on exact vectors (core/exact.hpp): the filter adaptor of
// core/predicates.hpp on each kind of operand, and the exact stages it falls back to where the
// certified approximations (exact.cpp) cannot decide: exact zeros the constructions show, the
// wrenches of three forces taken about one of their points, and Dyadic arithmetic. Each is
// counted in exact_stats().
#include "momentlab/core/exact.hpp"

#include "error_free.hpp"

#include <array>
#include <cmath>
#include <optional>

namespace momentlab {
namespace {

// Every filtered predicate counts itself here: in the initial-exec model on ELF systems, where
// the count is one instruction rather than a call to __tls_get_addr per predicate (the library
// is loaded with the program or, as the Python module loads it, by dlopen into the static TLS
// block's spare room: 16 bytes).
#if defined(__ELF__) && !defined(__EMSCRIPTEN__)
__attribute__((tls_model("initial-exec")))
#endif
thread_local ExactStats g_exact_stats;

// The sign of an exact value computed in Dyadic arithmetic: the last stage, counted.
Sign dyadic_sign(const Dyadic& x) {
    ++g_exact_stats.exact;
    return x.sign();
}

}  // namespace

ExactStats& exact_stats() { return g_exact_stats; }

// ---------------------------------------------------------------------------------------------
// Predicates: the filter adaptor of core/predicates.hpp on three kinds of operand, an
// ExactVector, a vector given by its Dyadic coordinates (Exact3), and either with the
// approximation its caller keeps (Kept); their exact stages below. (In namespace momentlab,
// where the adaptor's argument-dependent lookup finds them; internal linkage.)

namespace {

// An operand with the approximation its caller made once (a plane tested against many vectors).
template <class V>
struct Kept {
    const V& vector;
    const ExactVector::Approximation& approximation;
};

}  // namespace

template <class V>
static Approx3 approximate(const Kept<V>& x) {
    return approximate(x.approximation);
}
static Approx3 approximate(const Exact3& v) { return approximate(approximation(v)); }

static const ExactVector* vector_of(const ExactVector& v) { return &v; }
template <class V>
static const ExactVector* vector_of(const Kept<V>& x) {
    return vector_of(x.vector);
}
static Exact3 exact_of(const ExactVector& v) { return v.exact(); }
static const Exact3& exact_of(const Exact3& v) { return v; }
template <class V>
static decltype(auto) exact_of(const Kept<V>& x) {
    return exact_of(x.vector);
}

// Two operands that store one construction are parallel: a zero of every predicate that is
// linear in both (a contact's normal against A's facet copied from it), without arithmetic.
template <class A, class B>
static bool same_construction(const A& a, const B& b) {
    const ExactVector *x = vector_of(a), *y = vector_of(b);
    return x && y && x->same_construction(*y);
}

namespace {

// det(w_1, w_2, w_3) / (s_1 s_2 s_3) for the wrenches w_i = s_i (d_i, p_i x d_i) of three forces,
// taken about the first force's point, over any number type: subtracting q x d_i from every
// torque (adding multiples of the first two rows) leaves the determinant as it is, and for
// q = p_1 it is t_3 (d_1 x d_2) - t_2 (d_1 x d_3) with t_i = (p_i - p_1) x d_i. A scene far from
// the origin has torques near o x f, whose rounding hides what tells nearly dependent wrenches
// apart (the normals of a body in a bowl 1000 away from the origin); about p_1 nothing is hidden.
struct ForcesAboutTheFirstPoint {
    template <class T>
    T operator()(const std::array<T, 2>& q2, const std::array<T, 2>& q3, const std::array<T, 2>& d1,
                 const std::array<T, 2>& d2, const std::array<T, 2>& d3) const {
        const T t2 = q2[0] * d2[1] - q2[1] * d2[0], t3 = q3[0] * d3[1] - q3[1] * d3[0];
        return t3 * (d1[0] * d2[1] - d1[1] * d2[0]) - t2 * (d1[0] * d3[1] - d1[1] * d3[0]);
    }
};

std::array<Approx, 2> approximate(double x, double y) { return {Approx::exact(x), Approx::exact(y)}; }
std::array<Approx, 2> approximate(const Vec2& v) { return approximate(v.x(), v.y()); }

// ForcesAboutTheFirstPoint's filter, when the differences p_i - p_1 are doubles.
bool forces_filter(const Vec2& p1, const Vec2& p2, const Vec2& p3, const Vec2& d1, const Vec2& d2, const Vec2& d3,
                   Sign& out) {
    const std::optional<double> x2 = detail::exact_difference(p2.x(), p1.x()), y2 = detail::exact_difference(p2.y(), p1.y());
    const std::optional<double> x3 = detail::exact_difference(p3.x(), p1.x()), y3 = detail::exact_difference(p3.y(), p1.y());
    if (!x2 || !y2 || !x3 || !y3) return false;
    return filter_sign(ForcesAboutTheFirstPoint{}, out, approximate(*x2, *y2), approximate(*x3, *y3), approximate(d1),
                       approximate(d2), approximate(d3));
}

// The sign of t_3 (d_1 x d_2) - t_2 (d_1 x d_3), t_i = (p_i - p_1) x d_i = det(P_1, P_i, D_i)
// (P = (p, 1), D = (d, 0)), when d_1 x d_2 or d_1 x d_3 is exactly 0: a product of exact 2 x 2
// and 3 x 3 determinants of doubles.
bool parallel_forces_det(const Vec2& p1, const Vec2& p2, const Vec2& p3, const Vec2& d1, const Vec2& d2, const Vec2& d3,
                         Sign& out) {
    // (equal or opposite directions, as a friction edge and its copies on other contacts are,
    // without the exact minor)
    const auto cross = [](const Vec2& u, const Vec2& w) { return u == w || u == -w ? Sign::Zero : cross2_sign(u, w); };
    const Sign c12 = cross(d1, d2), c13 = cross(d1, d3);
    if (c12 != Sign::Zero && c13 != Sign::Zero) return false;
    const auto t = [&](const Vec2& p, const Vec2& d) {
        return det_sign(Vec3(p1.x(), p1.y(), 1.0), Vec3(p.x(), p.y(), 1.0), Vec3(d.x(), d.y(), 0.0));
    };
    out = c12 != Sign::Zero ? t(p3, d3) * c12 : c13 != Sign::Zero ? -(t(p2, d2) * c13) : Sign::Zero;
    return true;
}

// The wrenches' stage: for three forces, their determinant about the first point (filtered), or
// where that does not decide, the exact zeros of parallel forces: two of the three directions
// parallel (the determinant is invariant under a cyclic permutation, so the parallel pair is
// taken about the third force's point). Three wrenches of parallel forces are dependent; the
// friction edges of contacts along a line have two directions.
bool forces_det(const ExactVector& a, const ExactVector& b, const ExactVector& c, Sign& out) {
    Vec2 p1, p2, p3, d1, d2, d3;
    int s1 = 1, s2 = 1, s3 = 1;
    if (!a.force(p1, d1, s1) || !b.force(p2, d2, s2) || !c.force(p3, d3, s3)) return false;
    Sign v = Sign::Zero;
    if (!forces_filter(p1, p2, p3, d1, d2, d3, v) && !parallel_forces_det(p1, p2, p3, d1, d2, d3, v) &&
        !parallel_forces_det(p2, p3, p1, d2, d3, d1, v)) {
        return false;
    }
    out = s1 * s2 * s3 > 0 ? v : -v;
    return true;
}

}  // namespace

template <class A, class B>
static Sign exact_sign(const Dot& p, const A& a, const B& b) {
    return dyadic_sign(p(exact_of(a), exact_of(b)));
}

template <class A, class B>
static Sign exact_sign(const Minor& p, const A& a, const B& b) {
    if (same_construction(a, b)) return Sign::Zero;
    return dyadic_sign(p(exact_of(a), exact_of(b)));
}

template <class A, class B, class C>
static Sign exact_sign(const Det& p, const A& a, const B& b, const C& c) {
    if (same_construction(a, b) || same_construction(b, c) || same_construction(a, c)) return Sign::Zero;  // two parallel columns
    Sign s = Sign::Zero;
    const ExactVector *x = vector_of(a), *y = vector_of(b), *z = vector_of(c);
    if (x && y && z && forces_det(*x, *y, *z, s)) return s;
    return dyadic_sign(p(exact_of(a), exact_of(b), exact_of(c)));
}

// The adaptor, counting what it decided without Dyadic arithmetic.
template <class Predicate, class... Operands>
static Sign counted_sign(const Predicate& p, const Operands&... x) {
    const long exact_before = g_exact_stats.exact;
    const Sign s = filtered_sign(p, x...);
    if (g_exact_stats.exact == exact_before) ++g_exact_stats.filtered;
    return s;
}

Sign dot_sign(const ExactVector& a, const ExactVector& b) {
    if (!a.is_constructed() && !b.is_constructed()) return dot_sign(a.value(), b.value());
    return counted_sign(Dot{}, a, b);
}

Sign dot_sign(const ExactVector& a, const ExactVector& b, const ExactVector::Approximation& pa,
              const ExactVector::Approximation& pb) {
    if (!a.is_constructed() && !b.is_constructed()) return dot_sign(a.value(), b.value());
    return counted_sign(Dot{}, Kept<ExactVector>{a, pa}, Kept<ExactVector>{b, pb});
}

Sign dot_sign(const ExactVector& a, const Exact3& b) { return counted_sign(Dot{}, a, b); }

Sign dot_sign(const ExactVector& a, const Exact3& b, const ExactVector::Approximation& b_approximation) {
    return counted_sign(Dot{}, a, Kept<Exact3>{b, b_approximation});
}

Sign dot_sign(const ExactVector& a, const Exact3& b, const ExactVector::Approximation& pa, const ExactVector::Approximation& pb) {
    return counted_sign(Dot{}, Kept<ExactVector>{a, pa}, Kept<Exact3>{b, pb});
}

Sign det_sign(const ExactVector& a, const ExactVector& b, const ExactVector& c) {
    if (!a.is_constructed() && !b.is_constructed() && !c.is_constructed()) return det_sign(a.value(), b.value(), c.value());
    return counted_sign(Det{}, a, b, c);
}

Sign det_sign(const ExactVector& a, const ExactVector& b, const ExactVector& c, const ExactVector::Approximation& pa,
              const ExactVector::Approximation& pb, const ExactVector::Approximation& pc) {
    if (!a.is_constructed() && !b.is_constructed() && !c.is_constructed()) return det_sign(a.value(), b.value(), c.value());
    return counted_sign(Det{}, Kept<ExactVector>{a, pa}, Kept<ExactVector>{b, pb}, Kept<ExactVector>{c, pc});
}

Sign minor_sign(const ExactVector& a, const ExactVector& b, int i, int j) {
    if (!a.is_constructed() && !b.is_constructed()) return minor_sign(a.value(), b.value(), i, j);
    return counted_sign(Minor{i, j}, a, b);
}

bool parallel(const ExactVector& a, const ExactVector& b) {
    if (!a.is_constructed() && !b.is_constructed()) return parallel(a.value(), b.value());
    // Parallel unless a minor is certainly not zero: the filter on each (a cross product is
    // linear in both); then exactly.
    const Approx3 pa = approximate(a), pb = approximate(b);
    Sign s = Sign::Zero;
    for (int k = 0; k < 3; ++k) {
        if (filter_sign(Minor{(k + 1) % 3, (k + 2) % 3}, s, pa, pb)) {
            ++g_exact_stats.filtered;
            return false;
        }
    }
    if (a.same_construction(b)) return true;
    ++g_exact_stats.exact;
    return is_zero(cross(a.exact(), b.exact()));
}

bool is_zero(const ExactVector& v) {
    // Constructions that are exactly doubles are stored as inputs, so a computed vector is
    // never zero; a lazy cross product is zero when its factors are parallel.
    if (!v.is_constructed()) return is_zero(v.value());
    // A coordinate whose approximation certainly is not 0 is not 0 (no Dyadic coordinates made
    // for the many that are not: the cones' generators are tested).
    Sign s = Sign::Zero;
    for (const Approx& x : approximate(v)) {
        if (certified_sign(x, s)) return false;
    }
    return is_zero(v.exact());
}

}  // namespace momentlab
