#pragma once

// The linear programs of an assembly, written once for both number types: Interval (the
// enclosures, built from the scene's numbers in interval arithmetic) and Rational (exact). Each
// quantity is a polynomial in the numbers as read: a contact's normal wrench N = (n, p x n) and
// tangent wrench T = (t, p x t) with t = (n.y, -n.x), its friction edges n +- mu t and kinetic
// edges n -+ mu_k t as wrenches through p, a body's gravity wrench (m g, c x m g) and its inertia
// at the origin M = [[m, 0, -m c.y], [0, m, m c.x], [-m c.y, m c.x, I + m |c|^2]]
// (docs/design.md, docs/assemblies.md).
//
// Twists: x = (x_1, ..., x_N), x_k = (vx, vy, omega) of body k, columns 3(k-1) .. 3(k-1)+2; the
// relative twist at contact j is d_j = x_a - x_b (x_0 = 0), its normal velocity N_j . d_j and
// tangential velocity T_j . d_j. Forces: a column per edge, +w on body a's rows, -w on b's.

#include <algorithm>
#include <array>
#include <optional>
#include <cstdint>
#include <string>
#include <vector>

#include "exact_number.hpp"
#include "interval.hpp"
#include "linear_program.hpp"
#include "momentlab/geometry/force_sets.hpp"
#include "momentlab/mechanics/modes.hpp"
#include "momentlab/mechanics/scene.hpp"
#include "momentlab/assembly/assembly.hpp"

namespace momentlab::assembly_detail {

using Index = std::uint32_t;

template <class T>
using Wrench = std::array<T, 3>;

/// A number of the scene: a double is exact in both types; a decimal as typed (0.1 is 1/10) is
/// enclosed in the Interval one and exact in the Rational one.
template <class T>
T number(double x) {
    if constexpr (std::is_same_v<T, Interval>) {
        return Interval(x);
    } else {
        return exact_value(x);
    }
}

template <class T>
T number(const momentlab::Rational& x) {
    if constexpr (std::is_same_v<T, Interval>) {
        return enclose(x);
    } else {
        return exact_value(x);
    }
}

template <class T>
bool is_zero_number(const T& v) {
    if constexpr (std::is_same_v<T, Interval>) {
        return is_exact_zero(v);
    } else {
        return v == 0;
    }
}

/// Entries of one column in one row added into one (a force can reach a row through both of
/// its contact's bodies); exact zeros dropped.
template <class T>
void merge_repeated_entries(Program<T>& p) {
    for (SparseColumn<T>& column : p.columns) {
        SparseColumn<T> merged;
        for (SparseEntry<T>& e : column) {
            if (!merged.empty() && merged.back().index == e.index) {
                merged.back().value = merged.back().value + e.value;
            } else {
                merged.push_back(std::move(e));
            }
        }
        std::erase_if(merged, [](const SparseEntry<T>& e) { return is_zero_number(e.value); });
        column = std::move(merged);
    }
}

/// The force (fx, fy) through (px, py) as a wrench.
template <class T>
Wrench<T> force_wrench(const T& px, const T& py, const T& fx, const T& fy) {
    return {fx, fy, px * fy - py * fx};
}

template <class T>
struct ContactData {
    Index a = 1, b = 0;
    Wrench<T> normal, tangent;
    /// The friction cone's edges n + mu t and n - mu t (one edge, n, when mu = 0).
    std::vector<Wrench<T>> cone;
    /// The kinetic forces: n - mu_k t opposes sliding along +t (letter r), n + mu_k t along -t (l).
    Wrench<T> slide_r, slide_l;
    /// mu_k > mu: the kinetic forces lie outside the static cone.
    bool kinetic_outside = false;
    /// Earlier contacts of the same pair whose normal (tangent) wrench is exactly this one's: the
    /// same equation when both are closed (fixed), decided from the numbers as read.
    std::vector<Index> same_normal, same_tangent;
};

template <class T>
struct BodyData {
    /// The gravity wrenches of gravity (1, 0) and (0, 1): (m, 0, -m c.y) and (0, m, m c.x).
    Wrench<T> gravity_x, gravity_y;
    /// M at the origin and its inverse, (1/m + c.y^2/I, -c.x c.y/I, c.y/I; -c.x c.y/I,
    /// 1/m + c.x^2/I, -c.x/I; c.y/I, -c.x/I, 1/I) with I the inertia about the centre of mass
    /// (when the body has one).
    std::array<Wrench<T>, 3> inertia, inverse_inertia;
    bool has_inertia = false;
};

template <class T>
struct AssemblyData {
    Index bodies = 0;
    std::vector<BodyData<T>> body;
    std::vector<ContactData<T>> contacts;
};

template <class T>
AssemblyData<T> assembly_data(const Assembly& assembly) {
    AssemblyData<T> d;
    d.bodies = static_cast<Index>(assembly.bodies.size());
    for (const AssemblyBody& b : assembly.bodies) {
        BodyData<T> out;
        // The numbers as read: the exact values of decimals, else the doubles.
        const BodyValues* v = b.exact_values();
        const T m = v ? number<T>(v->mass) : number<T>(b.mass);
        const T cx = v ? number<T>(v->com[0]) : number<T>(b.com.x()), cy = v ? number<T>(v->com[1]) : number<T>(b.com.y());
        const T zero(number<T>(0.0));
        out.gravity_x = {m, zero, zero - m * cy};
        out.gravity_y = {zero, m, m * cx};
        if (b.inertia || b.radius_of_gyration) {
            T ic = zero;
            if (b.radius_of_gyration) {
                const T rho = v ? number<T>(*v->radius_of_gyration) : number<T>(*b.radius_of_gyration);
                ic = m * rho * rho;
            } else {
                ic = v ? number<T>(v->inertia) : number<T>(*b.inertia);
            }
            out.inertia = inertia_matrix(m, cx, cy, ic);
            const T one = number<T>(1.0);
            const T im = one / m, ii = one / ic;
            out.inverse_inertia = {Wrench<T>{im + cy * cy * ii, zero - cx * cy * ii, cy * ii},
                                   Wrench<T>{zero - cx * cy * ii, im + cx * cx * ii, zero - cx * ii},
                                   Wrench<T>{cy * ii, zero - cx * ii, ii}};
            out.has_inertia = true;
        }
        d.body.push_back(std::move(out));
    }
    for (const AssemblyContact& ac : assembly.contacts) {
        const Contact& c = ac.contact;
        const ContactValues* v = c.exact_values();  // the decimals as read, when some are not doubles
        ContactData<T> out;
        out.a = static_cast<Index>(ac.a);
        out.b = static_cast<Index>(ac.b);
        const T px = v ? number<T>(v->point[0]) : number<T>(c.point.x()), py = v ? number<T>(v->point[1]) : number<T>(c.point.y());
        const T nx = v ? number<T>(v->normal[0]) : number<T>(c.normal.x()), ny = v ? number<T>(v->normal[1]) : number<T>(c.normal.y());
        const T tx = ny, ty = number<T>(0.0) - nx;
        out.normal = force_wrench(px, py, nx, ny);
        out.tangent = force_wrench(px, py, tx, ty);
        const auto edge = [&](const T& k) { const auto dir = friction_direction(nx, ny, k); return force_wrench(px, py, dir[0], dir[1]); };
        const T mu = v ? number<T>(v->mu) : number<T>(c.mu), muk = v ? number<T>(v->mu_kinetic) : number<T>(c.mu_kinetic);
        if (c.mu == 0.0) {  // (a decimal is 0 exactly when its double is: the readers refuse the tiny)
            out.cone = {out.normal};
        } else {
            out.cone = {edge(mu), edge(number<T>(0.0) - mu)};
        }
        out.slide_r = edge(number<T>(opposing_friction(ContactMode::SlidingRight)) * muk);
        out.slide_l = edge(number<T>(opposing_friction(ContactMode::SlidingLeft)) * muk);
        out.kinetic_outside = v ? compare(v->mu_kinetic, v->mu) > 0 : c.mu_kinetic > c.mu;
        // Same pair and same normal as an earlier contact: the wrenches are equal exactly when
        // p x n (for N) or p . n (for T = (t, -p . n)) are, decided on the numbers as read
        // (doubles: an interval that is a point decides; decimals: exactly).
        for (Index k = 0; k < d.contacts.size(); ++k) {
            const AssemblyContact& o = assembly.contacts[k];
            if (o.a != ac.a || o.b != ac.b || o.contact.normal != c.normal) continue;
            const ContactValues* w = o.contact.exact_values();
            if (v || w) {
                const Rational2 n = v ? v->normal : rational(c.normal), m = w ? w->normal : rational(o.contact.normal);
                if (!(n == m)) continue;
                const Rational2 p = v ? v->point : rational(c.point), q = w ? w->point : rational(o.contact.point);
                const momentlab::Rational dx = p[0] - q[0], dy = p[1] - q[1];
                if ((dx * n[1] - dy * n[0]).is_zero()) out.same_normal.push_back(k);
                if ((dx * n[0] + dy * n[1]).is_zero()) out.same_tangent.push_back(k);
                continue;
            }
            const Interval n0(c.normal.x()), n1(c.normal.y());
            const Interval dx = Interval(c.point.x()) - Interval(o.contact.point.x());
            const Interval dy = Interval(c.point.y()) - Interval(o.contact.point.y());
            if (is_exact_zero(dx * n1 - dy * n0)) out.same_normal.push_back(k);
            if (is_exact_zero(dx * n0 + dy * n1)) out.same_tangent.push_back(k);
        }
        d.contacts.push_back(std::move(out));
    }
    return d;
}

/// A program assembled row by row into columns.
template <class T>
class ProgramAssembler {
public:
    explicit ProgramAssembler(Index twist_columns = 0) {
        for (Index j = 0; j < twist_columns; ++j) p_.add({}, true, false);
    }
    Index row(const T& rhs) {
        p_.rhs.push_back(rhs);
        return p_.rows++;
    }
    Index column(bool strict = false) { return p_.add({}, false, strict); }
    void put(Index row, Index column, const T& value) {
        if (!is_zero_number(value)) p_.columns[column].push_back({row, value});
    }
    /// value . d_j into `row`: +value on body a's twist, -value on body b's.
    void put_relative(Index row, const ContactData<T>& c, const Wrench<T>& w) {
        for (Index k = 0; k < 3; ++k) {
            put(row, 3 * (c.a - 1) + k, w[k]);
            if (c.b != 0) put(row, 3 * (c.b - 1) + k, number<T>(0.0) - w[k]);
        }
    }
    /// A force column along w on contact c: sign * w on a's rows from `first` (rows first + 3(k-1)).
    void put_force(Index first, Index column, const ContactData<T>& c, const Wrench<T>& w, int sign) {
        for (Index k = 0; k < 3; ++k) {
            const T v = sign > 0 ? w[k] : number<T>(0.0) - w[k];
            put(first + 3 * (c.a - 1) + k, column, v);
            if (c.b != 0) put(first + 3 * (c.b - 1) + k, column, number<T>(0.0) - v);
        }
    }
    Program<T> take() { return std::move(p_); }
    [[nodiscard]] Index columns() const { return static_cast<Index>(p_.columns.size()); }

private:
    Program<T> p_;
};

/// Which edge a force column of the equilibrium program is: contact and edge.
struct ForceColumn {
    Index contact, edge;
};

/// Equilibrium: sum over edges lambda_e (+w_e on a, -w_e on b) = -G, lambda >= 0 (all strict:
/// the margin helps the certificate; feasibility is the question). Rows 3(k-1).. of body k.
/// `frictionless`: the normal forces alone.
template <class T>
Program<T> equilibrium_program(const AssemblyData<T>& d, const T& gx, const T& gy,
                               std::vector<ForceColumn>* columns = nullptr, bool frictionless = false) {
    ProgramAssembler<T> pa;
    for (Index k = 0; k < d.bodies; ++k) {
        for (Index r = 0; r < 3; ++r) {
            pa.row(number<T>(0.0) - (gx * d.body[k].gravity_x[r] + gy * d.body[k].gravity_y[r]));
        }
    }
    for (Index j = 0; j < d.contacts.size(); ++j) {
        const ContactData<T>& c = d.contacts[j];
        if (frictionless) {
            pa.put_force(0, pa.column(true), c, c.normal, 1);
            continue;
        }
        for (Index e = 0; e < c.cone.size(); ++e) {
            const Index col = pa.column(true);
            pa.put_force(0, col, c, c.cone[e], 1);
            if (columns) columns->push_back({j, e});
        }
    }
    return pa.take();
}

/// The tilt chart u: A lambda + (Gamma u_perp) s = -Gamma u, lambda >= 0, s free: the gravity
/// vectors u + s u_perp (u_perp = (-u.y, u.x)) for which an equilibrium exists. s is the last
/// column.
template <class T>
Program<T> tilt_program(const AssemblyData<T>& d, int ux, int uy) {
    ProgramAssembler<T> pa;
    const T zero = number<T>(0.0);
    const auto g = [&](Index k, Index r, int gx, int gy) {
        T v = zero;
        if (gx != 0) v = v + number<T>(gx) * d.body[k].gravity_x[r];
        if (gy != 0) v = v + number<T>(gy) * d.body[k].gravity_y[r];
        return v;
    };
    for (Index k = 0; k < d.bodies; ++k) {
        for (Index r = 0; r < 3; ++r) pa.row(zero - g(k, r, ux, uy));
    }
    for (const ContactData<T>& c : d.contacts) {
        for (const Wrench<T>& w : c.cone) pa.put_force(0, pa.column(false), c, w, 1);
    }
    Program<T> p = pa.take();
    SparseColumn<T> s;
    for (Index k = 0; k < d.bodies; ++k) {
        for (Index r = 0; r < 3; ++r) {
            const T v = g(k, r, -uy, ux);
            if (!is_zero_number(v)) s.push_back({3 * k + r, v});
        }
    }
    p.add(std::move(s), true, false);
    return p;
}

/// The letters of a mode's prefix: the first letters.size() contacts have them, the rest are
/// unassigned (each of s, f, r, l).
///
/// Kinematics (strict): s: N . d > 0; f: N . d = 0 = T . d; r: N . d = 0 < T . d; l: N . d = 0
/// > T . d; unassigned: N . d >= 0. Homogeneous: x = 0 is a point; strictly feasible exactly when
/// the cell of the letters is non-empty.
template <class T>
Program<T> kinematic_program(const AssemblyData<T>& d, const std::string& letters) {
    ProgramAssembler<T> pa(3 * d.bodies);
    const T zero = number<T>(0.0), minus_one = number<T>(-1.0);
    const auto closed = [&](Index k) { return k < letters.size() && letters[k] != 's'; };
    const auto fixed = [&](Index k) { return k < letters.size() && letters[k] == 'f'; };
    for (Index j = 0; j < d.contacts.size(); ++j) {
        const ContactData<T>& c = d.contacts[j];
        const char letter = j < letters.size() ? letters[j] : '?';
        // An equation that an earlier row already states is left out (a dependent row would keep
        // an artificial in the basis and send the decision to the exact path).
        const bool normal_stated = closed(j) && std::any_of(c.same_normal.begin(), c.same_normal.end(), closed);
        if (!normal_stated) {
            const Index n = pa.row(zero);
            pa.put_relative(n, c, c.normal);
            if (letter == 's' || letter == '?') pa.put(n, pa.column(letter == 's'), minus_one);
        }
        if (letter == 'f' || letter == 'r' || letter == 'l') {
            if (letter == 'f' && std::any_of(c.same_tangent.begin(), c.same_tangent.end(), fixed)) continue;
            const Index t = pa.row(zero);
            pa.put_relative(t, c, c.tangent);
            if (letter != 'f') pa.put(t, pa.column(true), number<T>(letter == 'r' ? -1.0 : 1.0));
        }
    }
    return pa.take();
}

/// The accelerations eliminated: x_k = M_k^-1 (G_k + F_k), F_k the contact wrenches on body k
/// (each force column +w on its contact's body a, -w on b). An affine function of the forces:
/// a row of coefficients per force column and a constant, for a functional v on relative twists.
template <class T>
struct AffineRow {
    std::vector<std::pair<Index, T>> coefficients;  // (force column, value)
    T constant;
};

/// The loads: M_k x_k = G_k + (the contact wrenches on body k) for every body, the accelerations
/// eliminated (M_k is invertible), with x in the closure of the letters' cell (the kinematic rows
/// in the forces) and each contact's force in its letter's set: s none, f the friction cone, r
/// the ray n - mu_k t, l the ray n + mu_k t; an unassigned contact any of them (the cone of all
/// four edges): a relaxation for the prefixes. With `open_cell` the kinematic slacks of s, r, l
/// are strict (a motion from rest) and nothing else; otherwise every column is marked strict,
/// only so that a certificate has a margin when there is one (feasible either way is the answer).
/// With `moving` = (i, sign), one more row: sign * x_i minus a strict slack (and then only that
/// slack is strict): a motion with sign * x_i > 0.
template <class T>
Program<T> loads_program(const AssemblyData<T>& d, const T& gx, const T& gy, const std::string& letters, bool open_cell,
                         std::optional<std::pair<Index, int>> moving = std::nullopt) {
    const T zero = number<T>(0.0);
    const bool margin = !open_cell && !moving;
    // The force columns: contact, wrench.
    struct Force {
        Index contact;
        const Wrench<T>* w;
    };
    std::vector<Force> forces;
    for (Index j = 0; j < d.contacts.size(); ++j) {
        const ContactData<T>& c = d.contacts[j];
        const char letter = j < letters.size() ? letters[j] : '?';
        if (letter == 'f' || letter == '?') {
            for (const Wrench<T>& w : c.cone) forces.push_back({j, &w});
        }
        if (letter == 'r' || (letter == '?' && c.kinetic_outside)) forces.push_back({j, &c.slide_r});
        if (letter == 'l' || (letter == '?' && c.kinetic_outside)) forces.push_back({j, &c.slide_l});
    }
    // The force columns touching each body, with their signs.
    std::vector<std::vector<std::pair<Index, int>>> on_body(d.bodies + 1);
    for (Index f = 0; f < forces.size(); ++f) {
        const ContactData<T>& c = d.contacts[forces[f].contact];
        on_body[c.a].push_back({f, 1});
        if (c.b != 0) on_body[c.b].push_back({f, -1});
    }
    const auto dot3 = [&](const Wrench<T>& a, const Wrench<T>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    const auto times_inverse = [&](Index body, const Wrench<T>& v) {  // M^-1 v (symmetric)
        const auto& mi = d.body[body - 1].inverse_inertia;
        return Wrench<T>{dot3(mi[0], v), dot3(mi[1], v), dot3(mi[2], v)};
    };
    const auto gravity = [&](Index body) {
        const BodyData<T>& b = d.body[body - 1];
        return Wrench<T>{gx * b.gravity_x[0] + gy * b.gravity_y[0], gx * b.gravity_x[1] + gy * b.gravity_y[1],
                         gx * b.gravity_x[2] + gy * b.gravity_y[2]};
    };
    // v . x_body as an affine function of the forces, added with `sign` into `row`.
    const auto add_functional = [&](AffineRow<T>& row, Index body, const Wrench<T>& v, int sign) {
        if (body == 0) return;
        const Wrench<T> u = times_inverse(body, v);
        const T g = dot3(u, gravity(body));
        row.constant = sign > 0 ? row.constant + g : row.constant - g;
        for (const auto& [f, s] : on_body[body]) {
            const T value = dot3(u, *forces[f].w);
            row.coefficients.push_back({f, s * sign > 0 ? value : zero - value});
        }
    };
    ProgramAssembler<T> pa;
    // Force columns first, in the order above.
    for (Index f = 0; f < forces.size(); ++f) (void)pa.column(margin);
    // A row: coefficients . lambda + slack_sign * slack = -constant.
    const auto put_row = [&](const AffineRow<T>& r, int slack_sign, bool strict_slack) {
        const Index row = pa.row(zero - r.constant);
        for (const auto& [f, v] : r.coefficients) pa.put(row, f, v);  // a column twice in a row: merged below
        if (slack_sign != 0) pa.put(row, pa.column(strict_slack || margin), number<T>(static_cast<double>(slack_sign)));
    };
    const auto closed = [&](Index k) { return k < letters.size() && letters[k] != 's'; };
    const auto fixed = [&](Index k) { return k < letters.size() && letters[k] == 'f'; };
    for (Index j = 0; j < d.contacts.size(); ++j) {
        const ContactData<T>& c = d.contacts[j];
        const char letter = j < letters.size() ? letters[j] : '?';
        // Equations an earlier row states are left out, as in kinematic_program.
        if (!(closed(j) && std::any_of(c.same_normal.begin(), c.same_normal.end(), closed))) {
            AffineRow<T> n{{}, zero};
            add_functional(n, c.a, c.normal, 1);
            add_functional(n, c.b, c.normal, -1);
            // s and unassigned: N . d - s = 0 (s >= 0); f, r, l: N . d = 0.
            put_row(n, (letter == 's' || letter == '?') ? -1 : 0, letter == 's');
        }
        if (letter == 'f' && std::any_of(c.same_tangent.begin(), c.same_tangent.end(), fixed)) continue;
        if (letter == 'f' || letter == 'r' || letter == 'l') {
            AffineRow<T> t{{}, zero};
            add_functional(t, c.a, c.tangent, 1);
            add_functional(t, c.b, c.tangent, -1);
            put_row(t, letter == 'f' ? 0 : (letter == 'r' ? -1 : 1), true);
        }
    }
    if (moving) {
        const Index body = moving->first / 3 + 1;
        Wrench<T> unit{zero, zero, zero};
        unit[moving->first % 3] = number<T>(1.0);
        AffineRow<T> x{{}, zero};
        add_functional(x, body, unit, moving->second);
        put_row(x, -1, true);
    }
    Program<T> p = pa.take();
    merge_repeated_entries(p);
    if (moving) {
        for (std::size_t j = 0; j + 1 < p.strict.size(); ++j) p.strict[j] = false;
    }
    return p;
}

}  // namespace momentlab::assembly_detail
