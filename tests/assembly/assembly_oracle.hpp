#pragma once

// An exact oracle for assemblies that shares nothing with the library: it reads the assembly's
// raw numbers (points, normals as written, mu, mu_kinetic, masses, centres of mass, inertias) as
// GMP rationals and asks cddlib's exact rational LP (dual simplex) the questions of docs/
// assemblies.md in their textbook form: equilibrium (friction-cone edges), the modes by
// realisability of every letter string (a depth-first search that drops a prefix no twist
// realises) and the loads with the accelerations as unknowns (M x = G + contact wrenches, x in
// the closure of the mode's twists), the tilt cone from the four charts.

#include <gmpxx.h>
#include <setoper.h>
#include <cdd.h>

#include <array>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "momentlab/assembly/assembly.hpp"

namespace momentlab::assembly_oracle {

using Q = mpq_class;
using W = std::array<Q, 3>;

struct QContact {
    int a, b;
    Q px, py, nx, ny, mu, muk;
    W normal() const { return {nx, ny, px * ny - py * nx}; }
    W tangent() const { return {ny, -nx, px * (-nx) - py * ny}; }
    W edge(const Q& k) const {  // n + k t through p
        const Q fx = nx + k * ny, fy = ny - k * nx;
        return {fx, fy, px * fy - py * fx};
    }
};

struct QBody {
    Q m, cx, cy, ic;
};

struct QAssembly {
    std::vector<QBody> bodies;
    std::vector<QContact> contacts;
};

inline QAssembly exact(const Assembly& a) {
    QAssembly q;
    for (const AssemblyBody& b : a.bodies) {
        Q ic = 0;
        if (b.inertia) ic = Q(*b.inertia);
        if (b.radius_of_gyration) ic = Q(b.mass) * Q(*b.radius_of_gyration) * Q(*b.radius_of_gyration);
        q.bodies.push_back({Q(b.mass), Q(b.com.x()), Q(b.com.y()), ic});
    }
    for (const AssemblyContact& c : a.contacts) {
        q.contacts.push_back({static_cast<int>(c.a), static_cast<int>(c.b), Q(c.contact.point.x()), Q(c.contact.point.y()),
                              Q(c.contact.normal.x()), Q(c.contact.normal.y()), Q(c.contact.mu), Q(c.contact.mu_kinetic)});
    }
    return q;
}

/// A linear program for cddlib: rows b + a . x >= 0 or = 0 over `vars` variables.
class Lp {
public:
    explicit Lp(int vars) : vars_(vars) {}
    void row(const std::vector<Q>& a, const Q& b, bool equal) {
        rows_.push_back({a, b, equal});
    }
    std::vector<Q> zeros() const { return std::vector<Q>(static_cast<std::size_t>(vars_), Q(0)); }
    /// max objective . x; the status and value.
    std::pair<dd_LPStatusType, Q> maximize(const std::vector<Q>& objective) const {
        static std::once_flag once;
        std::call_once(once, [] { dd_set_global_constants(); });
        dd_MatrixPtr m = dd_CreateMatrix(static_cast<long>(rows_.size()), vars_ + 1);
        m->representation = dd_Inequality;
        m->numbtype = dd_Rational;
        for (std::size_t r = 0; r < rows_.size(); ++r) {
            mpq_set(m->matrix[r][0], rows_[r].b.get_mpq_t());
            for (int k = 0; k < vars_; ++k) mpq_set(m->matrix[r][k + 1], rows_[r].a[static_cast<std::size_t>(k)].get_mpq_t());
            if (rows_[r].equal) set_addelem(m->linset, static_cast<long>(r) + 1);
        }
        m->objective = dd_LPmax;
        dd_set_si(m->rowvec[0], 0);
        for (int k = 0; k < vars_; ++k) mpq_set(m->rowvec[k + 1], objective[static_cast<std::size_t>(k)].get_mpq_t());
        dd_ErrorType err = dd_NoError;
        dd_LPPtr lp = dd_Matrix2LP(m, &err);
        dd_LPSolve(lp, dd_DualSimplex, &err);
        std::pair<dd_LPStatusType, Q> out{lp->LPS, Q(lp->optvalue)};
        dd_FreeLPData(lp);
        dd_FreeMatrix(m);
        return out;
    }
    bool feasible() const {
        const auto r = maximize(zeros());
        return r.first == dd_Optimal;
    }

private:
    struct Row {
        std::vector<Q> a;
        Q b;
        bool equal;
    };
    int vars_;
    std::vector<Row> rows_;
};

inline std::vector<W> cone_edges(const QContact& c) {
    if (c.mu == 0) return {c.normal()};
    return {c.edge(c.mu), c.edge(-c.mu)};
}

/// Gravity wrench of body k for gravity (gx, gy).
inline W gravity(const QBody& b, const Q& gx, const Q& gy) { return {b.m * gx, b.m * gy, b.cx * b.m * gy - b.cy * b.m * gx}; }

/// Equilibrium: lambda >= 0 on every cone edge with sum (+w on a, -w on b) = -G.
inline bool can_stand(const QAssembly& q, const Q& gx, const Q& gy) {
    std::vector<std::pair<int, W>> columns;  // (contact, edge)
    for (std::size_t j = 0; j < q.contacts.size(); ++j) {
        for (const W& w : cone_edges(q.contacts[j])) columns.push_back({static_cast<int>(j), w});
    }
    const int n = static_cast<int>(columns.size());
    Lp lp(n);
    for (std::size_t k = 0; k < q.bodies.size(); ++k) {
        const W g = gravity(q.bodies[k], gx, gy);
        for (int r = 0; r < 3; ++r) {
            std::vector<Q> a = lp.zeros();
            for (int c = 0; c < n; ++c) {
                const QContact& ct = q.contacts[static_cast<std::size_t>(columns[static_cast<std::size_t>(c)].first)];
                const Q& v = columns[static_cast<std::size_t>(c)].second[static_cast<std::size_t>(r)];
                if (ct.a == static_cast<int>(k) + 1) a[static_cast<std::size_t>(c)] += v;
                if (ct.b == static_cast<int>(k) + 1) a[static_cast<std::size_t>(c)] -= v;
            }
            lp.row(a, g[static_cast<std::size_t>(r)], true);  // G + A lambda = 0
        }
    }
    for (int c = 0; c < n; ++c) {
        std::vector<Q> a = lp.zeros();
        a[static_cast<std::size_t>(c)] = 1;
        lp.row(a, 0, false);
    }
    return lp.feasible();
}

/// A row's coefficients of w . (x_a - x_b) over the twist variables (3 per body) placed from 0.
inline void relative(std::vector<Q>& a, const QContact& c, const W& w, const Q& sign) {
    for (int k = 0; k < 3; ++k) {
        a[static_cast<std::size_t>(3 * (c.a - 1) + k)] += sign * w[static_cast<std::size_t>(k)];
        if (c.b != 0) a[static_cast<std::size_t>(3 * (c.b - 1) + k)] -= sign * w[static_cast<std::size_t>(k)];
    }
}

/// Some twist realises the letters of the first letters.size() contacts (a slack t <= 1 on the
/// strict inequalities, maximised; realisable when t > 0 or when nothing is strict).
inline bool realisable(const QAssembly& q, const std::string& letters) {
    const int n = 3 * static_cast<int>(q.bodies.size()) + 1;
    const std::size_t t = static_cast<std::size_t>(n - 1);
    Lp lp(n);
    bool strict = false;
    for (std::size_t j = 0; j < letters.size(); ++j) {
        const QContact& c = q.contacts[j];
        std::vector<Q> nrow = lp.zeros(), trow = lp.zeros();
        relative(nrow, c, c.normal(), 1);
        relative(trow, c, c.tangent(), letters[j] == 'l' ? -1 : 1);
        if (letters[j] == 's') {
            nrow[t] = -1;
            lp.row(nrow, 0, false);
            strict = true;
            continue;
        }
        lp.row(nrow, 0, true);
        if (letters[j] == 'f') {
            lp.row(trow, 0, true);
        } else {
            trow[t] = -1;
            lp.row(trow, 0, false);
            strict = true;
        }
    }
    if (!strict) return true;
    std::vector<Q> cap = lp.zeros();
    cap[t] = -1;
    lp.row(cap, 1, false);
    std::vector<Q> objective = lp.zeros();
    objective[t] = 1;
    const auto r = lp.maximize(objective);
    return r.first == dd_Optimal && sgn(r.second) > 0;
}

/// The loads: x (3 per body) and the forces of the letters (f: the cone's edges, r: n - mu_k t,
/// l: n + mu_k t) with M_k x_k = G_k + contact wrenches on k, x in the closure of the letters'
/// twists (s: N . d >= 0; f: N . d = 0 = T . d; r: N . d = 0 <= T . d; l: N . d = 0 >= T . d).
/// A contact past the letters ('?') is relaxed to the union of its four letters: N . d >= 0 and
/// a force in the cone of every letter's forces (feasible for every completion that is).
/// The last variable is a margin m: with `open`, the inequalities of s, r and l are asked with
/// the margin (N . d >= m, +-T . d >= m) and m <= 1; otherwise m appears nowhere.
struct LoadsLp {
    Lp lp;
    int twist;  // the twist variables are 0 .. twist - 1
    std::size_t margin;
};

inline LoadsLp loads_lp(const QAssembly& q, std::string letters, const Q& gx, const Q& gy, bool open) {
    letters.resize(q.contacts.size(), '?');
    const int twist = 3 * static_cast<int>(q.bodies.size());
    std::vector<std::pair<int, W>> forces;
    for (std::size_t j = 0; j < letters.size(); ++j) {
        const QContact& c = q.contacts[j];
        const char l = letters[j];
        if (l == 'f' || l == '?') {
            for (const W& w : cone_edges(c)) forces.push_back({static_cast<int>(j), w});
        }
        if (l == 'r' || (l == '?' && c.muk > c.mu)) forces.push_back({static_cast<int>(j), c.edge(-c.muk)});
        if (l == 'l' || (l == '?' && c.muk > c.mu)) forces.push_back({static_cast<int>(j), c.edge(c.muk)});
    }
    const int n = twist + static_cast<int>(forces.size()) + 1;
    const auto margin = static_cast<std::size_t>(n - 1);
    Lp lp(n);
    for (std::size_t k = 0; k < q.bodies.size(); ++k) {
        const QBody& b = q.bodies[k];
        const Q io = b.ic + b.m * (b.cx * b.cx + b.cy * b.cy);
        const std::array<W, 3> m{W{b.m, 0, -b.m * b.cy}, W{0, b.m, b.m * b.cx}, W{-b.m * b.cy, b.m * b.cx, io}};
        const W g = gravity(b, gx, gy);
        for (int r = 0; r < 3; ++r) {  // M x - sum(forces on k) - G = 0
            std::vector<Q> a = lp.zeros();
            for (int c = 0; c < 3; ++c) a[3 * k + static_cast<std::size_t>(c)] = m[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
            for (std::size_t f = 0; f < forces.size(); ++f) {
                const QContact& ct = q.contacts[static_cast<std::size_t>(forces[f].first)];
                const Q& v = forces[f].second[static_cast<std::size_t>(r)];
                if (ct.a == static_cast<int>(k) + 1) a[static_cast<std::size_t>(twist) + f] -= v;
                if (ct.b == static_cast<int>(k) + 1) a[static_cast<std::size_t>(twist) + f] += v;
            }
            lp.row(a, -g[static_cast<std::size_t>(r)], true);
        }
    }
    for (std::size_t j = 0; j < letters.size(); ++j) {
        const QContact& c = q.contacts[j];
        const char l = letters[j];
        std::vector<Q> nrow = lp.zeros(), trow = lp.zeros();
        relative(nrow, c, c.normal(), 1);
        relative(trow, c, c.tangent(), l == 'l' ? -1 : 1);
        if (open && l == 's') nrow[margin] = -1;
        if (open && (l == 'r' || l == 'l')) trow[margin] = -1;
        lp.row(nrow, 0, l != 's' && l != '?');
        if (l == 'f') lp.row(trow, 0, true);
        if (l == 'r' || l == 'l') lp.row(trow, 0, false);
    }
    for (std::size_t f = 0; f < forces.size(); ++f) {
        std::vector<Q> a = lp.zeros();
        a[static_cast<std::size_t>(twist) + f] = 1;
        lp.row(a, 0, false);
    }
    if (open) {
        std::vector<Q> cap = lp.zeros();
        cap[margin] = -1;
        lp.row(cap, 1, false);
    }
    return {std::move(lp), twist, margin};
}

inline bool loads_hold(const QAssembly& q, const std::string& letters, const Q& gx, const Q& gy) {
    return loads_lp(q, letters, gx, gy, false).lp.feasible();
}

/// A motion from rest in the mode: accelerations in its open cell (every s strictly separating,
/// every r / l strictly sliding) with the loads balanced and some body moving. With a letter
/// s, r or l: the largest margin is positive. All f: some coordinate of x can be made positive
/// or negative (each asked in turn, capped at 1).
inline bool has_motion(const QAssembly& q, const std::string& mode, const Q& gx, const Q& gy) {
    LoadsLp l = loads_lp(q, mode, gx, gy, true);
    if (mode.find_first_not_of('f') != std::string::npos) {
        std::vector<Q> objective = l.lp.zeros();
        objective[l.margin] = 1;
        const auto r = l.lp.maximize(objective);
        return r.first == dd_Optimal && sgn(r.second) > 0;
    }
    for (int i = 0; i < l.twist; ++i) {
        for (int sign : {1, -1}) {
            Lp lp = l.lp;
            std::vector<Q> cap = lp.zeros();
            cap[static_cast<std::size_t>(i)] = -sign;
            lp.row(cap, 1, false);
            std::vector<Q> objective = lp.zeros();
            objective[static_cast<std::size_t>(i)] = sign;
            const auto r = lp.maximize(objective);
            if (r.first == dd_Optimal && sgn(r.second) > 0) return true;
        }
    }
    return false;
}

/// Every mode: realisable strings whose loads hold (a prefix dropped when no twist realises it
/// or its relaxed loads fail).
inline std::set<std::string> modes(const QAssembly& q, const Q& gx, const Q& gy) {
    std::set<std::string> out;
    std::vector<std::string> stack{""};
    while (!stack.empty()) {
        const std::string p = stack.back();
        stack.pop_back();
        if (!realisable(q, p) || !loads_hold(q, p, gx, gy)) continue;
        if (p.size() == q.contacts.size()) {
            out.insert(p);
            continue;
        }
        for (char c : {'s', 'f', 'r', 'l'}) stack.push_back(p + c);
    }
    return out;
}

/// The tilt cone's boundary rays from the charts u . g = 1: in each, max and min of s over
/// A lambda + Gamma (u + s u_perp) = 0. Returns the finite ends as directions u + s u_perp,
/// and whether any chart was feasible.
struct Chart {
    bool feasible = false;
    std::vector<std::array<Q, 2>> ends;
};

inline Chart tilt_chart(const QAssembly& q, int ux, int uy) {
    std::vector<std::pair<int, W>> columns;
    for (std::size_t j = 0; j < q.contacts.size(); ++j) {
        for (const W& w : cone_edges(q.contacts[j])) columns.push_back({static_cast<int>(j), w});
    }
    const int n = static_cast<int>(columns.size()) + 1;  // lambda..., s
    const std::size_t s = static_cast<std::size_t>(n - 1);
    Lp lp(n);
    for (std::size_t k = 0; k < q.bodies.size(); ++k) {
        const W g0 = gravity(q.bodies[k], Q(ux), Q(uy));
        const W g1 = gravity(q.bodies[k], Q(-uy), Q(ux));
        for (int r = 0; r < 3; ++r) {
            std::vector<Q> a = lp.zeros();
            for (std::size_t c = 0; c < columns.size(); ++c) {
                const QContact& ct = q.contacts[static_cast<std::size_t>(columns[c].first)];
                if (ct.a == static_cast<int>(k) + 1) a[c] += columns[c].second[static_cast<std::size_t>(r)];
                if (ct.b == static_cast<int>(k) + 1) a[c] -= columns[c].second[static_cast<std::size_t>(r)];
            }
            a[s] = g1[static_cast<std::size_t>(r)];
            lp.row(a, g0[static_cast<std::size_t>(r)], true);
        }
    }
    for (std::size_t c = 0; c < columns.size(); ++c) {
        std::vector<Q> a = lp.zeros();
        a[c] = 1;
        lp.row(a, 0, false);
    }
    Chart out;
    out.feasible = lp.feasible();
    if (!out.feasible) return out;
    for (int sign : {1, -1}) {
        std::vector<Q> objective = lp.zeros();
        objective[s] = sign;
        const auto r = lp.maximize(objective);
        if (r.first != dd_Optimal) continue;
        const Q end = sign > 0 ? r.second : Q(-r.second);
        out.ends.push_back({Q(ux) - end * uy, Q(uy) + end * ux});
    }
    return out;
}

}  // namespace momentlab::assembly_oracle
