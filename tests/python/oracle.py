"""An independent, exact oracle for momentlab's contact modes and wrench queries.

Pure Python, standard library only (``fractions``).  Everything is derived from the
definitions in docs/design.md (Conventions and "The mathematics"), restated here; no
algorithm of the C++ library is used.  Every decision is an exact linear-programming
feasibility question over ``Fraction`` numbers, and every answer of the LP solver is
checked by a certificate (a feasible point, or a Farkas vector), so a bug in the simplex
code cannot silently give a wrong answer.

Conventions
-----------
* Wrench w = (fx, fy, tau), tau about the world origin; the wrench of force f acting at
  point p is (f, p x f) with p x f = px*fy - py*fx.
* Twist xi = (vx, vy, omega); the body point at p moves with (vx - omega*py, vy + omega*px).
* Contact j: point p, normal n into the body (any positive length, used exactly as
  written, never normalised), tangent t = (n.y, -n.x), static mu, kinetic mu_k.
  N_j = (n, p x n), T_j = (t, p x t): N_j . xi is the normal velocity (times |n|),
  T_j . xi the tangential one.
* Mode letters, one per contact in input order:
    s  separating  N.xi > 0
    f  fixed       N.xi = 0, T.xi = 0
    r  sliding     N.xi = 0, T.xi > 0
    l  sliding     N.xi = 0, T.xi < 0
  A letter string is a mode iff some twist satisfies all its conditions.  The
  conditions are homogeneous, so strict inequalities a.x > 0 can be replaced by
  a.x >= 1 (scale any solution): an LP feasibility question.
* Inertia at the origin, for mass m, centre of mass c and inertia I_c about c:
    M = [[m, 0, -m cy], [0, m, m cx], [-m cy, m cx, I_c + m (cx^2 + cy^2)]];
  the total wrench is M a for the acceleration twist a (body at rest).
* For mode i: A_i = closure of its twist set (> becomes >=, equalities kept; for l,
  T.xi <= 0).  T_i = sum over contacts of {0} (s), the friction cone
  {alpha (n + mu t) + beta (n - mu t) at p : alpha, beta >= 0} (f, static mu), the ray
  lambda (n - mu_k t) at p (r), the ray lambda (n + mu_k t) at p (l).
  E_i = {M a - c : a in A_i, c in T_i}: the applied wrenches that produce mode i.
  query(e) = {feasible modes i : e in E_i}; the sets are closed, so a wrench on a
  boundary belongs to several modes.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Iterable, Optional, Sequence

LETTERS = "sfrl"

# ---------------------------------------------------------------------------------------
# Exact numbers
# ---------------------------------------------------------------------------------------


def exact(x) -> Fraction:
    """The exact value of an int, float (a dyadic rational) or Fraction; never rounds."""
    if isinstance(x, bool):
        raise TypeError("a boolean is not a number")
    if isinstance(x, Fraction):
        return x
    if isinstance(x, int):
        return Fraction(x)
    if isinstance(x, float):
        if not math.isfinite(x):
            raise ValueError(f"not finite: {x!r}")
        return Fraction(x)  # exact: a double is m * 2^k
    raise TypeError(f"not a number: {x!r}")


def cross(p, q) -> Fraction:
    """The planar cross product p x q = px*qy - py*qx."""
    return p[0] * q[1] - p[1] * q[0]


def cross3(u, v) -> tuple:
    """The cross product of two 3-vectors."""
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u, v) -> Fraction:
    return sum((a * b for a, b in zip(u, v)), Fraction(0))


def wrench_at(p, f) -> tuple:
    """The wrench (fx, fy, p x f) of the force f acting at the point p."""
    return (f[0], f[1], cross(p, f))


# ---------------------------------------------------------------------------------------
# Exact LP feasibility: phase-1 simplex with Bland's rule, answers certified
# ---------------------------------------------------------------------------------------


def _eliminate(row: list, factor: Fraction, pivot_row: list, nonzero: list) -> list:
    """row - factor * pivot_row, touching only the pivot row's non-zero entries."""
    row = list(row)
    for k in nonzero:
        row[k] -= factor * pivot_row[k]
    return row


def _nonneg_solution(A: list, b: list) -> Optional[list]:
    """Some x >= 0 with A x = b (A is m x n, entries Fractions), or None if there is none.

    Phase 1 of the simplex method: one artificial variable per row (rows with b_i < 0
    are negated first), minimise their sum, Bland's rule (smallest entering index;
    smallest basic index among tied ratios) so it terminates.  The answer is checked:
    a returned x satisfies A x = b, x >= 0 exactly; for None a Farkas vector y with
    y.A_j <= 0 for every column j and y.b > 0 is checked (then y.(A x) <= 0 < y.b for
    every x >= 0, so no x exists).
    """
    m = len(A)
    n = len(A[0]) if m else 0
    if m == 0:
        return [Fraction(0)] * n
    sign = [(-1 if b[i] < 0 else 1) for i in range(m)]
    # Tableau rows: [A' | I | b'] with A' = sign * A, b' = sign * b >= 0.
    rows = []
    for i in range(m):
        row = [sign[i] * A[i][j] for j in range(n)]
        row += [Fraction(1 if k == i else 0) for k in range(m)]
        row.append(sign[i] * b[i])
        rows.append(row)
    basis = [n + i for i in range(m)]
    width = n + m
    # Reduced costs of "minimise the sum of the artificials"; the last entry is -objective.
    cost = [-sum((rows[i][j] for i in range(m)), Fraction(0)) for j in range(n)]
    cost += [Fraction(0)] * m
    cost.append(-sum((rows[i][-1] for i in range(m)), Fraction(0)))

    while True:
        entering = next((j for j in range(width) if cost[j] < 0), None)
        if entering is None:
            break
        leaving = None
        best = None
        for i in range(m):
            a = rows[i][entering]
            if a > 0:
                ratio = rows[i][-1] / a
                if best is None or ratio < best or (ratio == best and basis[i] < basis[leaving]):
                    best, leaving = ratio, i
        if leaving is None:  # cannot happen: the phase-1 objective is bounded below by 0
            raise AssertionError("phase 1 unbounded")
        pivot_row = rows[leaving]
        piv = pivot_row[entering]
        pivot_row = [v / piv if v else v for v in pivot_row]
        rows[leaving] = pivot_row
        nonzero = [k for k, w in enumerate(pivot_row) if w]
        for i in range(m):
            if i != leaving and rows[i][entering] != 0:
                rows[i] = _eliminate(rows[i], rows[i][entering], pivot_row, nonzero)
        if cost[entering] != 0:
            cost = _eliminate(cost, cost[entering], pivot_row, nonzero)
        basis[leaving] = entering

    objective = -cost[-1]
    if objective == 0:
        x = [Fraction(0)] * n
        for i in range(m):
            if basis[i] < n:
                x[basis[i]] = rows[i][-1]
        # Certificate of feasibility.
        assert all(v >= 0 for v in x)
        assert all(dot(A[i], x) == b[i] for i in range(m)), "simplex: bad solution"
        return x
    # Certificate of infeasibility.  The reduced cost of artificial i is 1 - y'_i, where
    # y' are the simplex multipliers of the sign-flipped rows; y = sign * y'.
    y = [sign[i] * (1 - cost[n + i]) for i in range(m)]
    for j in range(n):
        assert sum((y[i] * A[i][j] for i in range(m)), Fraction(0)) <= 0, "simplex: bad Farkas"
    assert dot(y, b) > 0, "simplex: bad Farkas"
    return None


def lp_feasible(
    n_vars: int,
    equalities: Iterable = (),
    inequalities: Iterable = (),
    nonneg: Iterable[int] = (),
) -> Optional[list]:
    """A point x in Q^n_vars with row.x == rhs for each (row, rhs) of ``equalities``,
    row.x >= rhs for each (row, rhs) of ``inequalities`` and x_j >= 0 for j in ``nonneg``
    (the other variables are free); None if there is none.  Exact.

    Reduced to {z >= 0 : A z = b}: a free x_j is z_j+ - z_j-, each inequality gets a
    surplus variable s >= 0 (row.x - s = rhs).
    """
    equalities = [([exact(v) for v in row], exact(rhs)) for row, rhs in equalities]
    inequalities = [([exact(v) for v in row], exact(rhs)) for row, rhs in inequalities]
    nonneg = set(nonneg)
    # Column layout: one column per variable, a second (negated) one for free variables,
    # then one surplus column per inequality.
    columns = []  # (variable index, sign)
    for j in range(n_vars):
        columns.append((j, 1))
        if j not in nonneg:
            columns.append((j, -1))
    n_struct = len(columns)
    n_cols = n_struct + len(inequalities)
    A, b = [], []
    for row, rhs in equalities:
        assert len(row) == n_vars
        A.append([s * row[j] for j, s in columns] + [Fraction(0)] * len(inequalities))
        b.append(rhs)
    for k, (row, rhs) in enumerate(inequalities):
        assert len(row) == n_vars
        surplus = [Fraction(0)] * len(inequalities)
        surplus[k] = Fraction(-1)
        A.append([s * row[j] for j, s in columns] + surplus)
        b.append(rhs)
    z = _nonneg_solution(A, b) if A else [Fraction(0)] * n_cols
    if z is None:
        return None
    x = [Fraction(0)] * n_vars
    for (j, s), v in zip(columns, z):
        x[j] += s * v
    # Check the answer against the original constraints.
    assert all(dot(row, x) == rhs for row, rhs in equalities)
    assert all(dot(row, x) >= rhs for row, rhs in inequalities)
    assert all(x[j] >= 0 for j in nonneg)
    return x


# ---------------------------------------------------------------------------------------
# Scenes
# ---------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ExactContact:
    """Contact: point p, normal n into the body (as written), static and kinetic mu."""

    point: tuple
    normal: tuple
    mu: Fraction
    mu_kinetic: Fraction
    name: str = ""

    @property
    def tangent(self) -> tuple:
        """t = (n.y, -n.x)."""
        return (self.normal[1], -self.normal[0])

    @property
    def N(self) -> tuple:
        """The normal as a wrench, N = (n, p x n); N . xi is the normal velocity * |n|."""
        return wrench_at(self.point, self.normal)

    @property
    def T(self) -> tuple:
        """The tangent as a wrench, T = (t, p x t); T . xi is the tangential velocity * |n|."""
        return wrench_at(self.point, self.tangent)

    def force_wrench(self, s: Fraction) -> tuple:
        """The wrench of the contact force n + s t at p."""
        n, t = self.normal, self.tangent
        return wrench_at(self.point, (n[0] + s * t[0], n[1] + s * t[1]))

    def cone_edges(self) -> tuple:
        """The friction cone's two edges n + mu t and n - mu t (static mu) as wrenches."""
        return (self.force_wrench(self.mu), self.force_wrench(-self.mu))

    def sliding_ray(self, letter: str) -> tuple:
        """The contact force under sliding: n - mu_k t for 'r', n + mu_k t for 'l'."""
        return self.force_wrench(-self.mu_kinetic if letter == "r" else self.mu_kinetic)


@dataclass
class ExactScene:
    """A scene with every number exact.  ``mass`` is None when the file has no body."""

    contacts: list
    mass: Optional[Fraction] = None
    com: Optional[tuple] = None
    inertia: Optional[Fraction] = None  # about the centre of mass
    _modes: Optional[frozenset] = field(default=None, repr=False, compare=False)

    @property
    def n(self) -> int:
        return len(self.contacts)

    @property
    def M(self) -> list:
        """The inertia matrix at the origin (total wrench = M a)."""
        if self.mass is None:
            raise ValueError("the scene has no body")
        m, (cx, cy), ic = self.mass, self.com, self.inertia
        return [
            [m, Fraction(0), -m * cy],
            [Fraction(0), m, m * cx],
            [-m * cy, m * cx, ic + m * (cx * cx + cy * cy)],
        ]


def _vec2(v, what: str) -> tuple:
    if not isinstance(v, (list, tuple)) or len(v) != 2:
        raise ValueError(f"{what}: expected [x, y]")
    return (exact(v[0]), exact(v[1]))


def exact_scene(doc: dict) -> ExactScene:
    """The scene of a JSON document (docs/formats.md), every number converted exactly.

    body: mass, com [x, y], inertia (about the com) or radius_of_gyration rho
    (I_c = m rho^2, exact); the polygon is ignored.  contacts: point, normal (any
    positive length, used as written), mu (default 0), mu_kinetic (default mu), name.
    Scenes whose contacts are to be found from polygons are not supported.
    """
    if "contacts" not in doc:
        raise NotImplementedError("contacts found from polygons are not supported by the oracle")
    contacts = []
    for k, c in enumerate(doc["contacts"]):
        p = _vec2(c["point"], f"contacts[{k}].point")
        n = _vec2(c["normal"], f"contacts[{k}].normal")
        if n == (0, 0):
            raise ValueError(f"contacts[{k}].normal is zero")
        mu = exact(c.get("mu", 0))
        mu_k = exact(c["mu_kinetic"]) if "mu_kinetic" in c else mu
        if mu < 0 or mu_k < 0:
            raise ValueError(f"contacts[{k}]: negative friction coefficient")
        contacts.append(ExactContact(p, n, mu, mu_k, str(c.get("name", ""))))
    scene = ExactScene(contacts)
    body = doc.get("body")
    if body is not None:
        scene.mass = exact(body["mass"])
        scene.com = _vec2(body.get("com", [0, 0]), "body.com")
        if "inertia" in body and "radius_of_gyration" in body:
            raise ValueError("body: inertia or radius_of_gyration, not both")
        if "inertia" in body:
            scene.inertia = exact(body["inertia"])
        elif "radius_of_gyration" in body:
            rho = exact(body["radius_of_gyration"])
            scene.inertia = scene.mass * rho * rho
        else:
            raise ValueError("body: needs inertia or radius_of_gyration")
    return scene


def _scene(scene) -> ExactScene:
    return scene if isinstance(scene, ExactScene) else exact_scene(scene)


# ---------------------------------------------------------------------------------------
# Modes
# ---------------------------------------------------------------------------------------


def _neg(v) -> list:
    return [-x for x in v]


def twist_constraints(scene: ExactScene, letters: str, strict: bool):
    """The conditions of ``letters`` on a twist xi, as (equalities, inequalities) lists
    of (row, rhs) pairs.  strict=True: the mode itself, each "> 0" written as ">= 1"
    (equivalent, the conditions being homogeneous); strict=False: its closure (">= 0")."""
    one = Fraction(1 if strict else 0)
    eqs, ges = [], []
    for c, letter in zip(scene.contacts, letters):
        N, T = list(c.N), list(c.T)
        if letter == "s":
            ges.append((N, one))
        elif letter == "f":
            eqs += [(N, Fraction(0)), (T, Fraction(0))]
        elif letter == "r":
            eqs.append((N, Fraction(0)))
            ges.append((T, one))
        elif letter == "l":
            eqs.append((N, Fraction(0)))
            ges.append((_neg(T), one))
        else:
            raise ValueError(f"bad mode letter {letter!r}")
    return eqs, ges


def interior_twist(scene, letters: str) -> Optional[list]:
    """A twist with exactly the mode ``letters`` (all its strict conditions hold), or None
    when the mode is infeasible.  ``letters`` may be a prefix (conditions on the first
    contacts only)."""
    scene = _scene(scene)
    eqs, ges = twist_constraints(scene, letters, strict=True)
    return lp_feasible(3, eqs, ges)


def mode_of_twist(scene, xi) -> str:
    """The letters of a twist, straight from the definitions."""
    scene = _scene(scene)
    xi = [exact(v) for v in xi]
    out = []
    for c in scene.contacts:
        vn, vt = dot(c.N, xi), dot(c.T, xi)
        if vn < 0:
            raise ValueError("the twist penetrates a contact")
        if vn > 0:
            out.append("s")
        elif vt == 0:
            out.append("f")
        else:
            out.append("r" if vt > 0 else "l")
    return "".join(out)


def modes(scene) -> set:
    """Every feasible mode (letter string) of the scene.

    All 4^n strings are candidates; a string is feasible iff the LP of its strict
    conditions is.  The conditions of a prefix are a subset of those of its extensions,
    so an infeasible prefix is not extended (depth-first search).
    """
    scene = _scene(scene)
    if scene._modes is not None:
        return set(scene._modes)
    found = set()

    def extend(prefix: str) -> None:
        if interior_twist(scene, prefix) is None:
            return
        if len(prefix) == scene.n:
            found.add(prefix)
            return
        for letter in LETTERS:
            extend(prefix + letter)

    extend("")
    assert "f" * scene.n in found  # xi = 0
    scene._modes = frozenset(found)
    return set(found)


def closure_contains(scene, letters: str, xi) -> bool:
    """Whether the twist xi lies in the closed twist set A_i of the mode ``letters``."""
    scene = _scene(scene)
    xi = [exact(v) for v in xi]
    eqs, ges = twist_constraints(scene, letters, strict=False)
    return all(dot(r, xi) == h for r, h in eqs) and all(dot(r, xi) >= h for r, h in ges)


# ---------------------------------------------------------------------------------------
# Applied wrenches: E_i and queries
# ---------------------------------------------------------------------------------------


def _contact_generators(scene: ExactScene, letters: str) -> list:
    """Generators (wrenches, coefficients >= 0) of T_i."""
    gens = []
    for c, letter in zip(scene.contacts, letters):
        if letter == "f":
            gens += list(c.cone_edges())
        elif letter in "rl":
            gens.append(c.sliding_ray(letter))
    return gens


def produces_certificate(scene, letters: str, e) -> Optional[tuple]:
    """(a, coefficients) with e = M a - sum_k coef_k G_k, a in A_i (closed), coef >= 0, where
    G_k are the generators of T_i (friction-cone edges of 'f' contacts in the order
    n + mu t, n - mu t; sliding rays of 'r'/'l'); None when e is not in E_i.  An
    infeasible mode has E_i empty."""
    scene = _scene(scene)
    if letters not in modes(scene):
        return None
    e = [exact(v) for v in e]
    M = scene.M
    gens = _contact_generators(scene, letters)
    nv = 3 + len(gens)  # a (free), then one coefficient >= 0 per generator
    eqs = []
    for r in range(3):
        eqs.append((list(M[r]) + [-g[r] for g in gens], e[r]))
    t_eqs, t_ges = twist_constraints(scene, letters, strict=False)
    pad = [Fraction(0)] * len(gens)
    eqs += [(row + pad, rhs) for row, rhs in t_eqs]
    ges = [(row + pad, rhs) for row, rhs in t_ges]
    x = lp_feasible(nv, eqs, ges, nonneg=range(3, nv))
    if x is None:
        return None
    return x[:3], x[3:]


def produces(scene, letters: str, e) -> bool:
    """Whether the applied wrench e (3 numbers, converted exactly) lies in E_i of the mode
    ``letters``: e = M a - c for some a in the closed twist set A_i and c in T_i."""
    return produces_certificate(scene, letters, e) is not None


def query(scene, e) -> set:
    """The modes whose E_i holds the applied wrench e (fx, fy, tau about the origin)."""
    scene = _scene(scene)
    return {mode for mode in modes(scene) if produces(scene, mode, e)}


def verdict(k) -> str:
    """'inconsistent' for no mode, 'unique' for one, 'ambiguous' for several (k: a count
    or a collection of modes)."""
    if not isinstance(k, int):
        k = len(k)
    return "inconsistent" if k == 0 else ("unique" if k == 1 else "ambiguous")


# ---------------------------------------------------------------------------------------
# Random scenes and boundary wrenches
# ---------------------------------------------------------------------------------------

_MUS = [Fraction(0), Fraction(1, 4), Fraction(1, 2), Fraction(1), Fraction(3, 2)]


def _grid(rng: random.Random, lo=-2, hi=2, den=8) -> Fraction:
    return Fraction(rng.randint(lo * den, hi * den), den)


def _grid_point(rng: random.Random) -> tuple:
    return (_grid(rng), _grid(rng))


def _random_normal(rng: random.Random) -> tuple:
    """A non-zero normal: integer, or integer times a dyadic length (1/4 .. 2)."""
    while True:
        n = (Fraction(rng.randint(-3, 3)), Fraction(rng.randint(-3, 3)))
        if n != (0, 0):
            break
    scale = rng.choice([Fraction(1), Fraction(1), Fraction(1, 2), Fraction(1, 4), Fraction(2), Fraction(3, 4)])
    return (n[0] * scale, n[1] * scale)


def _num(x: Fraction):
    """A JSON number with exactly the value x (x dyadic of modest size)."""
    if x.denominator == 1:
        return int(x)
    f = float(x)
    if Fraction(f) != x:
        raise ValueError(f"{x} is not a double")
    return f


def random_scene(rng: random.Random, n_contacts: int, kinetic_above_static: bool = False) -> dict:
    """A random JSON-able scene (no polygon) with n_contacts contacts, every number a
    dyadic rational that doubles hold exactly: points on the 1/8 grid of [-2, 2]^2,
    normals of various lengths, mu in {0, 1/4, 1/2, 1, 3/2}, mu_kinetic sometimes smaller.
    About half the scenes are degenerate: normals through one point, parallel normals,
    repeated points, or normals that are opposite on one line.

    kinetic_above_static=True: mu_kinetic is often above mu (up to 3) and the centre of
    mass is often far from the contacts, which makes Painleve-type inconsistent wrenches
    (no mode) common; momentlab accepts such scenes (it only asks mu_kinetic >= 0)."""
    kind = rng.choice(["generic", "generic", "concurrent", "parallel", "repeated", "opposed", "mixed"])
    points, normals = [], []
    if kind == "concurrent":
        q = _grid_point(rng)
        for _ in range(n_contacts):
            while True:
                p = _grid_point(rng)
                if p != q:
                    break
            s = rng.choice([Fraction(1), Fraction(-1), Fraction(1, 2), Fraction(-2)])
            points.append(p)
            normals.append(((q[0] - p[0]) * s, (q[1] - p[1]) * s))
    elif kind == "parallel":
        d = _random_normal(rng)
        for _ in range(n_contacts):
            s = rng.choice([Fraction(1), Fraction(2), Fraction(1, 2), Fraction(-1)])
            points.append(_grid_point(rng))
            normals.append((d[0] * s, d[1] * s))
    elif kind == "repeated":
        pts = [_grid_point(rng) for _ in range(max(1, n_contacts // 2))]
        for _ in range(n_contacts):
            points.append(rng.choice(pts))
            normals.append(_random_normal(rng))
    elif kind == "opposed":
        # Pairs of opposite normals on one line (a slot), the rest generic.
        for k in range(n_contacts):
            if k % 2 == 1:
                p0, n0 = points[-1], normals[-1]
                step = Fraction(rng.choice([0, 1, 2, -1]), 4)
                points.append((p0[0] + step * n0[0], p0[1] + step * n0[1]))
                normals.append((-n0[0], -n0[1]))
            else:
                points.append(_grid_point(rng))
                normals.append(_random_normal(rng))
    else:
        for _ in range(n_contacts):
            points.append(_grid_point(rng))
            normals.append(_random_normal(rng))
        if kind == "mixed" and n_contacts >= 2:
            i, j = rng.sample(range(n_contacts), 2)
            points[j] = points[i]
    contacts = []
    for k, (p, n) in enumerate(zip(points, normals)):
        if n == (0, 0):
            n = (Fraction(0), Fraction(1))
        mu = rng.choice(_MUS)
        c = {"point": [_num(p[0]), _num(p[1])], "normal": [_num(n[0]), _num(n[1])],
             "mu": _num(mu), "name": f"c{k}"}
        if kinetic_above_static and rng.random() < 0.7:
            c["mu_kinetic"] = _num(rng.choice(_MUS + [Fraction(2), Fraction(3)]))
        elif rng.random() < 0.3:
            c["mu_kinetic"] = _num(rng.choice([m for m in _MUS if m <= mu]))
        contacts.append(c)
    mass = rng.choice([Fraction(1, 2), Fraction(1), Fraction(2), Fraction(3)])
    reach = 3 if kinetic_above_static and rng.random() < 0.5 else 1
    body = {"mass": _num(mass), "com": [_num(_grid(rng, -reach, reach, 4)), _num(_grid(rng, -reach, reach, 4))]}
    if rng.random() < 0.3:
        body["radius_of_gyration"] = _num(Fraction(rng.randint(1, 8), 4))
    else:
        body["inertia"] = _num(Fraction(rng.randint(1, 32), 16))
    return {"body": body, "contacts": contacts}


def _integer_direction(v: Sequence[Fraction]) -> list:
    """v scaled by a positive rational to a primitive integer vector (0 stays 0)."""
    den = 1
    for x in v:
        den = den * x.denominator // math.gcd(den, x.denominator)
    ints = [int(x * den) for x in v]
    g = 0
    for x in ints:
        g = math.gcd(g, abs(x))
    return [Fraction(x // g) for x in ints] if g else [Fraction(0)] * len(v)


def _is_double(x: Fraction) -> bool:
    """x is a double exactly, of modest size (|x| <= 1024)."""
    return abs(x) <= 1024 and Fraction(float(x)) == x


def boundary_wrenches(scene, rng: random.Random, k: int) -> list:
    """k applied wrenches (tuples of 3 floats, each exactly the rational computed) built to
    lie on boundaries between the modes' E_i:

    e = M a - c with a = (0 or a small multiple of) a twist in the relative interior of
    some mode j, which lies in the closure A_i of every mode i whose closed conditions
    it meets (so a sits on a lower-dimensional face of those A_i); c in T_i for such a
    mode i, with coefficients that are often 0 (a friction-cone edge, or no force at a
    contact).  So e is in E_i by construction, and typically in a neighbour's E too.
    Also, sometimes, e = 0 (in every E_i).
    """
    ex = _scene(scene)
    all_modes = sorted(modes(ex))
    interiors = {}
    for j in all_modes:
        xi = interior_twist(ex, j)
        # A positive multiple keeps the mode; scale to integers, then by a power of two
        # down to |components| <= 4 (dyadic, so the wrenches below stay doubles).
        d = _integer_direction(xi)
        big = max((abs(v) for v in d), default=Fraction(0))
        shift = 0
        while big > 4 * 2 ** shift:
            shift += 1
        interiors[j] = [v / 2 ** shift for v in d]
    M = ex.M
    coefs = [Fraction(0)] * 3 + [Fraction(1, 2), Fraction(1), Fraction(2), Fraction(3, 4)]
    out = []
    attempts = 0
    while len(out) < k and attempts < 100 * k:
        attempts += 1
        if rng.random() < 0.03:
            out.append((0.0, 0.0, 0.0))
            continue
        j = rng.choice(all_modes)
        scale = rng.choice([Fraction(0), Fraction(0), Fraction(1, 4), Fraction(1, 2), Fraction(1), Fraction(2)])
        a = [scale * v for v in interiors[j]]
        holders = [i for i in all_modes if closure_contains(ex, i, a)]
        i = rng.choice(holders)
        gens = _contact_generators(ex, i)
        c = [Fraction(0)] * 3
        for g in gens:
            w = rng.choice(coefs)
            c = [cv + w * gv for cv, gv in zip(c, g)]
        e = [dot(M[r], a) - c[r] for r in range(3)]
        if not all(_is_double(x) for x in e):
            continue
        assert produces(ex, i, e)
        out.append(tuple(float(x) for x in e))
    return out


def random_wrench(rng: random.Random) -> tuple:
    """A random applied wrench on a dyadic grid (floats, exact)."""
    return tuple(float(Fraction(rng.randint(-32, 32), 8)) for _ in range(3))

