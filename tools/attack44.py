#!/usr/bin/env python3
"""An attack on momentlab's answers with an exact oracle of its own (issue 44's closing count).

The oracle reads each scene's raw numbers as Fractions and decides everything by exact linear
programs (a Fraction simplex written here, Bland's rule, every answer checked by a certificate);
it uses no momentlab code, not even tests/python/oracle.py. Definitions (docs/design.md):
contact j at p with inward normal n (as written), tangent t = (n.y, -n.x), N = (n, p x n),
T = (t, p x t); twist xi: s N.xi > 0; f N.xi = 0 = T.xi; r N.xi = 0 < T.xi; l N.xi = 0 > T.xi.
Forces of a mode: f the cone of n +- mu t, r the ray n - mu_k t, l the ray n + mu_k t (at p).
E_i = {M a - c : a in closure(A_i), c in T_i}; query(e) = the feasible modes whose E_i holds e.
Closure: force closure when the wrenches of n +- mu t positively span R^3, form closure when the
normals' wrenches do. Tilt (docs/planning.md): gravity of direction theta through the centre of
mass, the wrench (d, c x d); E_i quasi-static is -T_i. The plan's intervals and unique arcs are
checked at their middles, 1e-6 inside and outside each end (the ends are rounded angles), and
at random angles: the goal's set holds the direction exactly where an interval says so, and
alone exactly where a unique arc says so.

Scenes: random dyadic ones (1-3 contacts, coordinates in eighths), degenerate ones (parallel,
concurrent, coincident contacts, mu = 0), each also moved exactly by (1e8, -1e8), turned by 90
degrees, reflected in x = 0, scaled by 2^40 and 2^-40, with huge and tiny mu. Wrenches: random,
and points M a - c of a mode's set built from its own generators (on its boundary). Each scene
is asked of the CLI (modes, query --wrenches --json, closure --json) and of the Python module
(analyze(...).modes, .query, momentlab.query, closure); two goals of each scene as drawn,
moved, turned and reflected are planned by `plan tilt` (dynamic or quasi-static at random).

Usage: /usr/bin/python3 tools/attack44.py [--seed 44] [--scenes 100] [--bin build/release/momentlab]
       [--python build/release/python]
Prints the count of cases per question and every disagreement; exit status 1 if any.
"""

from __future__ import annotations

import argparse
import collections
import itertools
import json
import math
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction as F

# ---------------------------------------------------------------------------------------------
# Exact LP: is there x >= 0 with A x = b? (phase 1, Bland's rule, certified)
# ---------------------------------------------------------------------------------------------


def nonneg_solution(A, b):
    m = len(A)
    n = len(A[0]) if m else 0
    rows = []
    for i in range(m):
        s = -1 if b[i] < 0 else 1
        rows.append([s * a for a in A[i]] + [F(int(k == i)) for k in range(m)] + [s * b[i]])
    basis = [n + i for i in range(m)]
    width = n + m
    # objective: minimise the artificials' sum; reduced costs d_j = c_j - (c_B B^-1 A)_j
    while True:
        cost = [F(int(j >= n)) - sum(r[j] for i, r in enumerate(rows) if basis[i] >= n) for j in range(width)]
        enter = next((j for j in range(width) if cost[j] < 0 and j not in basis), None)
        if enter is None:
            break
        best = None
        for i, r in enumerate(rows):
            if r[enter] > 0:
                ratio = r[-1] / r[enter]
                if best is None or ratio < best[0] or (ratio == best[0] and basis[i] < basis[best[1]]):
                    best = (ratio, i)
        if best is None:
            break  # unbounded direction of phase 1 cannot happen (objective >= 0)
        i = best[1]
        piv = rows[i][enter]
        rows[i] = [v / piv for v in rows[i]]
        for k in range(m):
            if k != i and rows[k][enter] != 0:
                f = rows[k][enter]
                rows[k] = [a - f * c for a, c in zip(rows[k], rows[i])]
        basis[i] = enter
    x = [F(0)] * width
    for i, j in enumerate(basis):
        x[j] = rows[i][-1]
    if any(x[n + i] != 0 for i in range(m)):
        # certificate of infeasibility: y with y.A <= 0, y.b > 0 from the final tableau's duals
        y = farkas(A, b, rows, basis, n, m)
        assert y is not None
        return None
    sol = x[:n]
    assert all(v >= 0 for v in sol)
    assert all(sum(A[i][j] * sol[j] for j in range(n)) == b[i] for i in range(m))
    return sol


def farkas(A, b, rows, basis, n, m):
    # The phase-1 optimum's dual: y_i = (sign-adjusted) coefficients of the artificials' rows.
    # Recover y by solving y^T B = c_B over the artificial columns: the tableau's artificial
    # columns hold B^-1, and the phase-1 costs are 1 on artificials.
    sign = [-1 if b[i] < 0 else 1 for i in range(m)]
    cB = [F(1) if j >= n else F(0) for j in basis]
    # y' = cB^T B^-1, B^-1 = the artificial columns of the final tableau
    yp = [sum(cB[i] * rows[i][n + k] for i in range(m)) for k in range(m)]
    y = [yp[k] * sign[k] for k in range(m)]
    # y.A_j <= 1 - ... : for phase 1 optimality reduced costs >= 0 mean y'.A'_j <= 0 for all j
    ok = all(sum(y[i] * A[i][j] for i in range(m)) <= 0 for j in range(n)) and sum(y[i] * b[i] for i in range(m)) > 0
    return y if ok else None


def feasible(eqs, geqs, nfree, nnonneg):
    """Is there (u free, v >= 0) with every (row, rhs) of eqs equal and of geqs >= ? Rows are
    coefficient lists over u then v."""
    A, b = [], []
    ngeq = len(geqs)
    for row, rhs in eqs:
        A.append(list(row[:nfree]) + [-c for c in row[:nfree]] + list(row[nfree:]) + [F(0)] * ngeq)
        b.append(rhs)
    for k, (row, rhs) in enumerate(geqs):
        A.append(list(row[:nfree]) + [-c for c in row[:nfree]] + list(row[nfree:]) + [F(-int(i == k)) for i in range(ngeq)])
        b.append(rhs)
    if not A:
        return True
    return nonneg_solution(A, b) is not None


# ---------------------------------------------------------------------------------------------
# Mechanics from the raw numbers
# ---------------------------------------------------------------------------------------------


def cr(p, q):
    return p[0] * q[1] - p[1] * q[0]


def wrench(p, f):
    return (f[0], f[1], cr(p, f))


def contacts_of(scene):
    out = []
    for c in scene["contacts"]:
        p = tuple(F(x) for x in c["point"])
        n = tuple(F(x) for x in c["normal"])
        mu = F(c.get("mu", 0))
        mk = F(c.get("mu_kinetic", c.get("mu", 0)))
        t = (n[1], -n[0])
        out.append(dict(p=p, n=n, t=t, mu=mu, mk=mk, N=wrench(p, n), T=wrench(p, t)))
    return out


def inertia(scene):
    b = scene["body"]
    m, I = F(b["mass"]), F(b["inertia"])
    cx, cy = (F(x) for x in b["com"])
    return [[m, 0, -m * cy], [0, m, m * cx], [-m * cy, m * cx, I + m * (cx * cx + cy * cy)]]


def twist_rows(cs, mode, strict):
    """Rows over xi (3 free) for mode's twist set (strict: > as >= 1; closure: >= 0)."""
    one = F(1) if strict else F(0)
    eqs, geqs = [], []
    for c, l in zip(cs, mode):
        N, T = list(c["N"]), list(c["T"])
        if l == "s":
            geqs.append((N, one))
        else:
            eqs.append((N, F(0)))
            if l == "f":
                eqs.append((T, F(0)))
            elif l == "r":
                geqs.append((T, one))
            else:
                geqs.append(([-x for x in T], one))
    return eqs, geqs


def modes_of(cs):
    return sorted("".join(m) for m in itertools.product("sfrl", repeat=len(cs)) if feasible(*twist_rows(cs, m, True), 3, 0))


def generators(cs, mode):
    g = []
    for c, l in zip(cs, mode):
        n, t, p = c["n"], c["t"], c["p"]
        if l == "f":
            g += [wrench(p, (n[0] + c["mu"] * t[0], n[1] + c["mu"] * t[1])), wrench(p, (n[0] - c["mu"] * t[0], n[1] - c["mu"] * t[1]))]
        elif l == "r":
            g.append(wrench(p, (n[0] - c["mk"] * t[0], n[1] - c["mk"] * t[1])))
        elif l == "l":
            g.append(wrench(p, (n[0] + c["mk"] * t[0], n[1] + c["mk"] * t[1])))
    return g


def in_E(cs, M, mode, e):
    """e in E_mode = {M a - sum lambda g : a in closure(A), lambda >= 0}."""
    g = generators(cs, mode)
    eqs, geqs = twist_rows(cs, mode, False)
    k = len(g)
    eqs = [(r + [F(0)] * k, v) for r, v in eqs]
    geqs = [(r + [F(0)] * k, v) for r, v in geqs]
    for i in range(3):
        eqs.append((list(M[i]) + [-gg[i] for gg in g], F(e[i])))
    return feasible(eqs, geqs, 3, k)


def in_E_quasi_static(cs, mode, e):
    """e in -T_mode (no inertia: the contacts alone balance e)."""
    g = generators(cs, mode)
    eqs = [([gg[i] for gg in g], -F(e[i])) for i in range(3)]
    return feasible(eqs, [], 0, len(g))


def holds(cs, M, mode, e, quasi_static):
    return in_E_quasi_static(cs, mode, e) if quasi_static else in_E(cs, M, mode, e)


def tilt_wrench(scene, theta):
    """The wrench of a force of direction theta through the centre of mass (exact values of the
    rounded cosine and sine: every set is a cone, so the magnitude does not matter)."""
    d = (F(math.cos(theta)), F(math.sin(theta)))
    c = tuple(F(x) for x in scene["body"]["com"])
    return wrench(c, d)


def inside(arcs, theta):
    two_pi = 2 * math.pi
    for a, b in arcs:
        t = a + ((theta - a) % two_pi)
        if t <= b:
            return True
    return False


def tilt_checks(rng, cs, M, scene, modes, goal, quasi_static, plan, delta=1e-6):
    """(question, angle, what the plan says, what the oracle says) for angles inside and just
    outside every interval and unique arc, and random ones, away from the plan's ends by 2 delta."""
    intervals, unique = plan["intervals"], plan.get("unique", [])
    ends = [x for a, b in intervals + unique for x in (a, b)]
    angles = []
    for a, b in intervals + unique:
        angles += [a - delta, b + delta]
        if b - a > 4 * delta:
            angles += [a + delta, (a + b) / 2, b - delta]
    angles += [rng.uniform(-math.pi, math.pi) for _ in range(4)]
    out = []
    for theta in angles:
        if any(abs(math.remainder(theta - x, 2 * math.pi)) < delta / 2 for x in ends):
            continue
        e = tilt_wrench(scene, theta)
        others = [m for m in modes if m != goal and holds(cs, M, m, e, quasi_static)]
        in_goal = holds(cs, M, goal, e, quasi_static)
        out.append(("tilt interval", theta, inside(intervals, theta), in_goal))
        if plan.get("unique") is not None:
            out.append(("tilt unique", theta, inside(unique, theta), in_goal and not others))
    return out


def query_of(cs, M, modes, e):
    return sorted(m for m in modes if in_E(cs, M, m, e))


def spans(gens):
    for k in range(3):
        for s in (1, -1):
            target = [F(0)] * 3
            target[k] = F(s)
            eqs = [([g[i] for g in gens], target[i]) for i in range(3)]
            if not feasible(eqs, [], 0, len(gens)):
                return False
    return True


def closure_of(cs):
    force = []
    for c in cs:
        n, t, p, mu = c["n"], c["t"], c["p"], c["mu"]
        force += [wrench(p, (n[0] + mu * t[0], n[1] + mu * t[1])), wrench(p, (n[0] - mu * t[0], n[1] - mu * t[1]))]
    return spans(force), spans([c["N"] for c in cs])


# ---------------------------------------------------------------------------------------------
# Scenes and their exact transforms
# ---------------------------------------------------------------------------------------------


def eighth(rng, r=16):
    return rng.randint(-r, r) / 8


def random_scene(rng, kind):
    k = rng.randint(1, 3)
    mus = [0.0, 0.25, 0.5, 1.0, 0.1, 0.3, 2.0]
    cs = []
    if kind == "random":
        for _ in range(k):
            n = [eighth(rng), eighth(rng)]
            while n == [0, 0]:
                n = [eighth(rng), eighth(rng)]
            c = {"point": [eighth(rng), eighth(rng)], "normal": n, "mu": rng.choice(mus)}
            if rng.random() < 0.3:
                c["mu_kinetic"] = rng.choice(mus)
            cs.append(c)
    elif kind == "parallel":  # one normal, several points (a block on a table, a wall)
        n = [eighth(rng, 8), eighth(rng, 8)] or [0, 1]
        if n == [0, 0]:
            n = [0.0, 1.0]
        for _ in range(k):
            s = eighth(rng)
            cs.append({"point": [s * n[1], -s * n[0]], "normal": n, "mu": rng.choice(mus)})
    elif kind == "concurrent":  # lines of action through one point
        q = [eighth(rng), eighth(rng)]
        for _ in range(k):
            n = [eighth(rng, 8), eighth(rng, 8)]
            if n == [0, 0]:
                n = [1.0, 0.0]
            s = rng.randint(-4, 4) / 4
            cs.append({"point": [q[0] + s * n[0], q[1] + s * n[1]], "normal": n, "mu": rng.choice(mus)})
    else:  # coincident points, opposite normals (an antipodal grasp)
        p = [eighth(rng), eighth(rng)]
        n = [eighth(rng, 8), eighth(rng, 8)]
        if n == [0, 0]:
            n = [0.0, 1.0]
        cs = [{"point": p, "normal": n, "mu": rng.choice(mus)},
              {"point": [p[0] + n[0], p[1] + n[1]], "normal": [-n[0], -n[1]], "mu": rng.choice(mus)}]
    body = {"mass": rng.choice([0.5, 1.0, 2.0, 3.0]), "com": [eighth(rng), eighth(rng)], "inertia": rng.choice([0.25, 0.5, 1.0, 1.5])}
    return {"body": body, "contacts": cs}


def moved(scene, d):
    s = json.loads(json.dumps(scene))
    for c in s["contacts"]:
        c["point"] = [c["point"][0] + d[0], c["point"][1] + d[1]]
    s["body"]["com"] = [s["body"]["com"][0] + d[0], s["body"]["com"][1] + d[1]]
    return s


def mapped(scene, f, lengths=1.0):
    s = json.loads(json.dumps(scene))
    for c in s["contacts"]:
        c["point"] = list(f(c["point"]))
        c["normal"] = list(f(c["normal"]))
    s["body"]["com"] = list(f(s["body"]["com"]))
    s["body"]["inertia"] = s["body"]["inertia"] * lengths * lengths
    return s


def mu_scaled(scene, k):
    s = json.loads(json.dumps(scene))
    for c in s["contacts"]:
        for key in ("mu", "mu_kinetic"):
            if key in c:
                c[key] = c[key] * k
    return s


def variants(scene):
    out = [("as drawn", scene), ("moved 1e8", moved(scene, (1e8, -1e8))),
           ("turned 90", mapped(scene, lambda v: (-v[1], v[0]))),
           ("reflected", mapped(scene, lambda v: (-v[0], v[1]))),
           ("scaled 2^40", mapped(scene, lambda v: (v[0] * 2.0**40, v[1] * 2.0**40), 2.0**40)),
           ("scaled 2^-40", mapped(scene, lambda v: (v[0] * 2.0**-40, v[1] * 2.0**-40), 2.0**-40)),
           ("mu x 2^30", mu_scaled(scene, 2.0**30)), ("mu x 2^-30", mu_scaled(scene, 2.0**-30))]
    return out


def wrenches_for(rng, cs, M, modes, count):
    """Random wrenches and points M a - c of modes' sets from their own generators (exact in
    doubles: small dyadic multipliers; those that do not round exactly are dropped)."""
    out = []
    for _ in range(count):
        out.append([eighth(rng), eighth(rng), eighth(rng)])
    for m in modes[: count]:
        g = generators(cs, m)
        # a in the closure of A_m: a solution of its rows or 0
        a = [F(0)] * 3
        if rng.random() < 0.5:
            eqs, geqs = twist_rows(cs, m, False)
            for _ in range(5):
                cand = [F(rng.randint(-2, 2)) for _ in range(3)]
                if all(sum(r[i] * cand[i] for i in range(3)) == v for r, v in eqs) and all(sum(r[i] * cand[i] for i in range(3)) >= v for r, v in geqs):
                    a = cand
                    break
        lam = [F(rng.choice([0, 0, 1, 2])) for _ in g]
        e = [sum(M[i][j] * a[j] for j in range(3)) - sum(l * gg[i] for l, gg in zip(lam, g)) for i in range(3)]
        if all(F(float(x)) == x for x in e):
            out.append([float(x) for x in e])
    return out


# ---------------------------------------------------------------------------------------------
# Front ends
# ---------------------------------------------------------------------------------------------


def cli(binary, *args):
    r = subprocess.run([binary, *args], capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=44)
    ap.add_argument("--scenes", type=int, default=100)
    ap.add_argument("--bin", default="build/release/momentlab")
    ap.add_argument("--python", default="build/release/python")
    args = ap.parse_args()
    sys.path.insert(0, args.python)
    import momentlab as ml

    rng = random.Random(args.seed)
    count = collections.Counter()
    wrong = []
    tmp = tempfile.mkdtemp(prefix="attack44_")
    kinds = ["random", "parallel", "concurrent", "antipodal"]
    for k in range(args.scenes):
        base = random_scene(rng, kinds[k % 4])
        for name, scene in variants(base):
            path = os.path.join(tmp, "scene.json")
            with open(path, "w") as fh:
                json.dump(scene, fh)
            cs = contacts_of(scene)
            M = inertia(scene)
            tag = f"scene {k} ({kinds[k % 4]}, {name}): {json.dumps(scene)}"
            modes = modes_of(cs)
            status, out, err = cli(args.bin, "modes", path, "--json")
            got = sorted(json.loads(out)["modes"]) if status == 0 else err.strip()
            count["modes (CLI)"] += 1
            if got != modes:
                wrong.append(f"modes: {tag}: CLI {got}, oracle {modes}")
            py = ml.Scene.from_json(json.dumps(scene))
            a = ml.analyze(py)
            count["modes (Python)"] += 1
            if sorted(a.modes) != modes:
                wrong.append(f"modes (Python): {tag}: {sorted(a.modes)}, oracle {modes}")
            force, form = closure_of(cs)
            status, out, err = cli(args.bin, "closure", path, "--json")
            count["closure verdicts (CLI)"] += 2
            if status != 0:
                wrong.append(f"closure: {tag}: exit {status} {err.strip()}")
            else:
                j = json.loads(out)
                if (j["force_closure"], j["form_closure"]) != (force, form):
                    wrong.append(f"closure: {tag}: CLI force {j['force_closure']} form {j['form_closure']}, oracle {force} {form}")
            pc = ml.closure(py)
            count["closure verdicts (Python)"] += 2
            if (pc["force_closure"], pc["form_closure"]) != (force, form):
                wrong.append(f"closure (Python): {tag}: {pc['force_closure']} {pc['form_closure']}, oracle {force} {form}")
            if name in ("as drawn", "moved 1e8", "turned 90", "reflected"):
                for goal in rng.sample(modes, min(2, len(modes))):
                    qs = rng.random() < 0.5
                    status, out, err = cli(args.bin, "plan", "tilt", path, "--goal", goal, "--json", *(["--quasi-static"] if qs else []))
                    if status != 0:
                        wrong.append(f"tilt: {tag} goal {goal}: exit {status} {err.strip()}")
                        continue
                    plan = json.loads(out)
                    for question, theta, said, truth in tilt_checks(rng, cs, M, scene, modes, goal, qs, plan):
                        count[question + (" (quasi-static)" if qs else " (dynamic)")] += 1
                        if said != truth:
                            wrong.append(f"{question}: {tag} goal {goal} quasi-static {qs} theta {theta!r}: CLI {said}, oracle {truth}; plan {out.strip()}")
            ws = wrenches_for(rng, cs, M, modes, 4)
            wpath = os.path.join(tmp, "w.txt")
            with open(wpath, "w") as fh:
                fh.write("\n".join(json.dumps(w) for w in ws) + "\n")
            status, out, err = cli(args.bin, "query", path, "--wrenches", wpath, "--json")
            lines = out.splitlines() if status == 0 else []
            if status != 0 or len(lines) != len(ws):
                wrong.append(f"query: {tag}: exit {status} {err.strip()} ({len(lines)} lines for {len(ws)})")
                continue
            for w, line in zip(ws, lines):
                want = query_of(cs, M, modes, w)
                j = json.loads(line)
                count["query (CLI)"] += 1
                verdict_ok = (j["verdict"] == "ambiguous") == (len(want) > 1)
                if sorted(j["modes"]) != want or not verdict_ok:
                    wrong.append(f"query: {tag} e={w}: CLI {j['modes']} {j['verdict']}, oracle {want}")
                count["query (Python analysis)"] += 1
                pa = sorted(a.query(w))
                if pa != want:
                    wrong.append(f"query (Python analysis): {tag} e={w}: {pa}, oracle {want}")
                count["query (Python one question)"] += 1
                po = sorted(ml.query(py, w)["modes"])
                if po != want:
                    wrong.append(f"query (Python one question): {tag} e={w}: {po}, oracle {want}")
    width = max(len(q) for q in count)
    print(f"attack44: seed {args.seed}, {args.scenes} base scenes x 8 variants")
    for q, n in sorted(count.items()):
        print(f"  {q:<{width}}  {n:6d} cases")
    print(f"  disagreements: {len(wrong)}")
    for w in wrong:
        print("  " + w)
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
