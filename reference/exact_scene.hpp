#pragma once

// The scene's quantities in exact rationals (GMP), built here from the raw numbers of the
// scene (points, normals as written, mu, mu_kinetic, mass, centre of mass, inertia or radius of
// gyration), never from momentlab's wrenches, matrices or cones: the input of every oracle.
// Also the exact conversion of momentlab's own Dyadic results to rationals, so that its outputs
// can be checked against these.

#include <gmpxx.h>

#include <array>
#include <string>
#include <vector>

#include "momentlab/core/dyadic.hpp"
#include "momentlab/core/exact.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab::reference {

using Q = mpq_class;
using QVec = std::array<Q, 3>;
using QMat = std::array<QVec, 3>;  // by rows

inline Q q(double x) { return Q(x); }
inline QVec q(const Vec3& v) { return {Q(v.x()), Q(v.y()), Q(v.z())}; }

inline Q dot(const QVec& a, const QVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline QVec cross(const QVec& a, const QVec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Q det(const QVec& a, const QVec& b, const QVec& c) { return dot(a, cross(b, c)); }
inline QVec neg(const QVec& a) { return {-a[0], -a[1], -a[2]}; }
inline QVec add(const QVec& a, const QVec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline QVec scale(const Q& s, const QVec& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline QVec mul(const QMat& m, const QVec& v) { return {dot(m[0], v), dot(m[1], v), dot(m[2], v)}; }
inline bool is_zero(const QVec& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }
inline int sign(const Q& x) { return sgn(x); }
inline Vec3 to_vec3(const QVec& v) { return Vec3(v[0].get_d(), v[1].get_d(), v[2].get_d()); }

/// The force (fx, fy) through (px, py): (fx, fy, px fy - py fx).
inline QVec wrench(const Q& px, const Q& py, const Q& fx, const Q& fy) { return {fx, fy, px * fy - py * fx}; }

/// A contact's raw numbers as rationals.
struct QContact {
    Q px, py, nx, ny, mu, mu_kinetic;
    explicit QContact(const Contact& c)
        : px(c.point.x()), py(c.point.y()), nx(c.normal.x()), ny(c.normal.y()), mu(c.mu), mu_kinetic(c.mu_kinetic) {}
    /// N = (n, p x n).
    [[nodiscard]] QVec normal() const { return wrench(px, py, nx, ny); }
    /// T = (t, p x t), t = (n.y, -n.x).
    [[nodiscard]] QVec tangent() const { return wrench(px, py, ny, -nx); }
    /// The force n + s m t through p (s = +1: n + m t, the force opposing sliding along -t).
    [[nodiscard]] QVec edge(const Q& m, int s) const {
        const Q k = s > 0 ? m : Q(-m);
        return wrench(px, py, nx + k * ny, ny - k * nx);
    }
    /// The contact-force generators of a letter: f both static edges, r n - mu_k t, l n + mu_k t.
    [[nodiscard]] std::vector<QVec> generators(char letter) const {
        if (letter == 'f') return {edge(mu, 1), edge(mu, -1)};
        if (letter == 'r') return {edge(mu_kinetic, -1)};
        if (letter == 'l') return {edge(mu_kinetic, 1)};
        return {};
    }
};

/// The inertia at the origin from the body's raw numbers:
/// [[m, 0, -m cy], [0, m, m cx], [-m cy, m cx, I + m (cx^2 + cy^2)]], I = m rho^2 when the
/// radius of gyration rho was given.
inline QMat inertia(const Body& b) {
    const Q m(b.mass), cx(b.com.x()), cy(b.com.y());
    const Q i = b.radius_of_gyration ? Q(m * Q(*b.radius_of_gyration) * Q(*b.radius_of_gyration)) : Q(b.inertia);
    return {QVec{m, 0, -m * cy}, QVec{0, m, m * cx}, QVec{-m * cy, m * cx, i + m * (cx * cx + cy * cy)}};
}

/// A Dyadic of momentlab's, exactly as a rational.
inline Q to_q(const Dyadic& d) {
    mpz_class mag = 0;
    const auto limbs = d.limbs();
    for (std::size_t i = limbs.size(); i-- > 0;) {
        mag <<= 64;
        mag += mpz_class(static_cast<unsigned long>(limbs[i] >> 32)) << 32;
        mag += mpz_class(static_cast<unsigned long>(limbs[i] & 0xffffffffu));
    }
    Q out(mag);
    const long e = static_cast<long>(d.binary_exponent());
    if (e >= 0) {
        mpq_mul_2exp(out.get_mpq_t(), out.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    } else {
        mpq_div_2exp(out.get_mpq_t(), out.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
    }
    return d.sign() == Sign::Negative ? Q(-out) : out;
}

/// An exact vector of momentlab's, exactly as rationals.
inline QVec to_q(const ExactVector& v) {
    const Exact3 e = v.exact();
    return {to_q(e[0]), to_q(e[1]), to_q(e[2])};
}

}  // namespace momentlab::reference
