"""Regressions of issue 44 through the front ends (the command line's text and JSON, the Python
module), each against an oracle written here or in tests/python/oracle.py: exact Fractions read
from the scene's raw numbers, never momentlab's wrenches, cones or mode lists.

1. Unique and shared arcs when the goal holds every direction and one direction is shared.
2. Margins invariant under exact translations (the centre-of-mass frame).
3. Closure quality in (0, 1], against the inner radius of the unit wrenches' hull.
7. A push plan's printed push is the push its magnitudes belong to."""

import itertools
import json
import math
import random
import re
import subprocess
from decimal import Decimal, getcontext
from fractions import Fraction

import pytest

import momentlab as ml
import oracle
from conftest import CLI, EXAMPLES, as_json, cli

# ---------------------------------------------------------------------------------------------
# 1. The goal holds every direction; one other set meets the plane in one direction.

# Two fingers at (0, 0) and (2, 1), antipodal within both friction cones (mu = 1/2): E_ff = R^3
# quasi-statically. Of the other sets only sf's -FC_2 (forces through (2, 1)) meets the forces
# through (0, 1), along y = 1 in the direction (1, 0).
ANTIPODAL = {"body": {"mass": 1, "com": [0, 1], "inertia": 1},
             "contacts": [{"point": [0, 0], "normal": [1, 1], "mu": 0.5, "mu_kinetic": 2},
                          {"point": [2, 1], "normal": [-4, -1], "mu": 0.5, "mu_kinetic": 2}]}


def quasi_static_answer(doc, e):
    """The modes whose quasi-static set E_i = -T_i holds the wrench e (Fractions): -e a
    non-negative combination of T_i's generators, by an exact LP (oracle.lp_feasible)."""
    scene = oracle.exact_scene(doc)
    out = set()
    for letters in oracle.modes(scene):
        gens = oracle._contact_generators(scene, letters)
        if not gens:
            held = all(v == 0 for v in e)
        else:
            eqs = [([g[r] for g in gens], -e[r]) for r in range(3)]
            held = oracle.lp_feasible(len(gens), eqs, [], nonneg=range(len(gens))) is not None
        if held:
            out.add(letters)
    return out


def pythagorean_directions():
    """Exact rational unit vectors all round the circle (from the triples (3, 4, 5), (5, 12, 13),
    (8, 15, 17), (7, 24, 25)), with the four axis directions."""
    out = {(Fraction(1), Fraction(0)), (Fraction(-1), Fraction(0)), (Fraction(0), Fraction(1)), (Fraction(0), Fraction(-1))}
    for a, b, c in [(3, 4, 5), (5, 12, 13), (8, 15, 17), (7, 24, 25)]:
        for x, y in [(a, b), (b, a)]:
            for sx, sy in itertools.product((1, -1), repeat=2):
                out.add((Fraction(sx * x, c), Fraction(sy * y, c)))
    return sorted(out, key=lambda d: math.atan2(d[1], d[0]))


def test_antipodal_grasp_oracle_shares_only_theta_zero():
    """The oracle's own reading of the scene: ff everywhere, sf too only at theta = 0."""
    com = (Fraction(0), Fraction(1))
    for d in pythagorean_directions():
        got = quasi_static_answer(ANTIPODAL, oracle.wrench_at(com, d))
        assert got == ({"ff", "sf"} if d == (1, 0) else {"ff"}), (d, got)


def check_whole_turn_but_zero(plan):
    assert plan["intervals"] == [[-math.pi, math.pi]], plan
    assert plan["unique"] == [[-math.pi, math.pi]], plan  # the closure of the turn less theta = 0
    assert plan["shared"] == [[0.0, 0.0]], plan
    assert plan["best_unique"] is True
    assert abs(plan["best"]) == math.pi and plan["margin"] == math.pi, plan
    # The oracle at the best direction (rounded cos and sin, read exactly): ff alone.
    d = (Fraction(math.cos(plan["best"])), Fraction(math.sin(plan["best"])))
    assert quasi_static_answer(ANTIPODAL, oracle.wrench_at((Fraction(0), Fraction(1)), d)) == {"ff"}


def test_tilt_and_comply_when_the_goal_holds_every_direction(tmp_path):
    scene = tmp_path / "antipodal.json"
    scene.write_text(json.dumps(ANTIPODAL))
    check_whole_turn_but_zero(cli("plan", "tilt", scene, "--goal", "ff", "--quasi-static", "--json"))
    check_whole_turn_but_zero(cli("plan", "comply", scene, "--goal", "ff", "--quasi-static", "--centre", "0", "1", "--json")["centre"])
    a = ml.analyze(ml.Scene.from_json(json.dumps(ANTIPODAL)), quasi_static=True)
    check_whole_turn_but_zero(as_json(ml.plan_tilt(a, "ff")))
    check_whole_turn_but_zero(as_json(ml.plan_comply(a, "ff", [0, 1]).centre))
    text = cli("plan", "tilt", scene, "--goal", "ff", "--quasi-static").stdout
    assert "the goal alone: [-3.14159, 3.14159]\n  shared with another mode: 0 only\n" in text, text
    assert "no arc where the goal is alone" not in text


# ---------------------------------------------------------------------------------------------
# 2. Margins about the centre of mass do not change when the scene moves.

# One frictionless contact at p = (1.5, -1.375), normal n = (1/2, 2); mass m = 3, com c =
# (1/2, -5/8), inertia I = 1. By hand: with torques about c, the contact point's normal
# acceleration under a wrench (f, tau_c) is h . (f, tau_c), h = (n / m, (r x n) / I), r = p - c.
# E_s (contact separating) is the half-space h . e >= 0; every other mode keeps the contact
# (h . e = 0 before its force, which adds -G with h . G = |n|^2 / m + (r x n)^2 / I > 0), so
# those sets lie in h . e <= 0 and together cover the plane h . e = 0 (its twists slide left,
# right or stay). For e with h . e > 0 both margins are the distance to that plane in the
# metric's coordinates q = (fx, fy, tau_c / L), L = |r| (the farthest contact): |h_q . q| / |h_q|,
# h_q = (n / m, (r x n) L / I).
ONE_CONTACT = {"contacts": [{"point": [1.5, -1.375], "normal": [0.5, 2.0], "mu": 0.0}],
               "body": {"mass": 3.0, "com": [0.5, -0.625], "inertia": 1.0}}


def moved(doc, d):
    """The scene moved by d (exactly: every coordinate and offset a dyadic rational that the
    sum keeps within a double, checked)."""
    out = json.loads(json.dumps(doc))
    for pt in [out["body"]["com"]] + out["body"].get("polygon", []) + [c["point"] for c in out["contacts"]]:
        for k in range(2):
            s = pt[k] + d[k]
            assert Fraction(s) == Fraction(pt[k]) + Fraction(d[k])
            pt[k] = s
    return out


def moved_wrench(doc, w, d):
    """The wrench w (about the origin) of the scene moved by d: the same forces, the torque
    tau + d x f, as a double only when exact."""
    tau = Fraction(w[2]) + oracle.cross((Fraction(d[0]), Fraction(d[1])), (Fraction(w[0]), Fraction(w[1])))
    assert Fraction(float(tau)) == tau
    return [w[0], w[1], float(tau)]


def one_contact_plane():
    """h_q and L of the hand derivation, in Fractions, from the raw numbers."""
    c, = ONE_CONTACT["contacts"]
    b = ONE_CONTACT["body"]
    m, inertia = Fraction(b["mass"]), Fraction(b["inertia"])
    r = (Fraction(c["point"][0]) - Fraction(b["com"][0]), Fraction(c["point"][1]) - Fraction(b["com"][1]))
    n = (Fraction(c["normal"][0]), Fraction(c["normal"][1]))
    length_sq = r[0] ** 2 + r[1] ** 2
    length = Fraction(math.isqrt(length_sq.numerator), math.isqrt(length_sq.denominator))
    assert length ** 2 == length_sq  # 5/4 here
    return (n[0] / m, n[1] / m, oracle.cross(r, n) * length / inertia), length


def hand_distance(w_com):
    """The hand derivation's margin of the wrench (fx, fy, tau about the com), Fractions."""
    h, length = one_contact_plane()
    q = (w_com[0], w_com[1], w_com[2] / length)
    dot = sum(a * b for a, b in zip(h, q))
    assert dot > 0  # the wrench separates the contact: the answer is s
    return math.sqrt(dot * dot / sum(a * a for a in h))


OFFSETS = [(0, 0), (1e8, -1e8), (2.0 ** 30, 2.0 ** 29), (-3 * 2.0 ** 26, 5 * 2.0 ** 24), (-123456789, 987654321)]


@pytest.mark.parametrize("d", OFFSETS)
def test_query_margins_do_not_change_when_the_scene_moves(tmp_path, d):
    w = [-0.25, 2.75, 0.5]
    com = [Fraction(x) for x in ONE_CONTACT["body"]["com"]]
    w_com = (Fraction(w[0]), Fraction(w[1]), Fraction(w[2]) - oracle.cross(com, (Fraction(w[0]), Fraction(w[1]))))
    want = hand_distance(w_com)  # 0.0277744...
    doc, wd = moved(ONE_CONTACT, d), moved_wrench(ONE_CONTACT, w, d)
    scene = tmp_path / "moved.json"
    scene.write_text(json.dumps(doc))
    got = cli("query", scene, "--wrench", *map(repr, wd), "--margin", "--json")
    assert got["modes"] == ["s"]
    assert math.isclose(got["margins"]["inside"][0], want, rel_tol=1e-12), (d, got, want)
    assert math.isclose(got["margins"]["to_other"], want, rel_tol=1e-12), (d, got, want)
    py = ml.analyze(ml.Scene.from_json(json.dumps(doc))).margins(wd)
    assert math.isclose(py.inside["s"], want, rel_tol=1e-12) and math.isclose(py.to_other, want, rel_tol=1e-12), (d, py)


@pytest.mark.parametrize("d", OFFSETS)
def test_tilt_margins_do_not_change_when_the_scene_moves(tmp_path, d):
    """The best tilt u = (cos best, sin best), a unit force through the com (no torque about it):
    both margins are the hand's distance of (u, 0)."""
    scene = tmp_path / "moved.json"
    scene.write_text(json.dumps(moved(ONE_CONTACT, d)))
    plan = cli("plan", "tilt", scene, "--goal", "s", "--json")
    u = (Fraction(math.cos(plan["best"])), Fraction(math.sin(plan["best"])))
    want = hand_distance((u[0], u[1], Fraction(0)))  # 0.22551...
    bm = plan["best_margins"]
    assert math.isclose(bm["inside"][0], want, rel_tol=1e-12), (d, bm, want)
    assert math.isclose(bm["to_other"], want, rel_tol=1e-12), (d, bm, want)


# ---------------------------------------------------------------------------------------------
# 3. Closure quality: the radius of the largest ball about 0 in the hull of the unit wrenches.

def _decimal(x):
    return Decimal(x.numerator) / Decimal(x.denominator)


def _sqrt(x):
    """sqrt of a non-negative Fraction to 80 digits, as a Fraction."""
    getcontext().prec = 80
    return Fraction(_decimal(Fraction(x)).sqrt())


def unit_wrenches(doc, force, length=None, reference=None):
    """The contacts' unit wrenches (u, ((p - r) x u) / L) from the raw numbers: u the unit normal
    (form) or the unit friction edges n +- mu t (force), to 80 digits; r the com (else the
    contacts' centroid), L the farthest contact from it (else `length`)."""
    cs = doc["contacts"]
    if reference is None:
        if "body" in doc:
            reference = doc["body"]["com"]
        else:
            reference = [sum(Fraction(c["point"][k]) for c in cs) / len(cs) for k in range(2)]
    r = [Fraction(reference[0]), Fraction(reference[1])]
    if length is None:
        length = max(_sqrt((Fraction(c["point"][0]) - r[0]) ** 2 + (Fraction(c["point"][1]) - r[1]) ** 2) for c in cs)
    length = Fraction(length)
    out = []
    for c in cs:
        n = (Fraction(c["normal"][0]), Fraction(c["normal"][1]))
        mu = Fraction(c.get("mu", 0))
        t = (-n[1], n[0])
        dirs = [n] if not force else [(n[0] + mu * t[0], n[1] + mu * t[1]), (n[0] - mu * t[0], n[1] - mu * t[1])]
        p = (Fraction(c["point"][0]) - r[0], Fraction(c["point"][1]) - r[1])
        for d in dirs:
            norm = _sqrt(d[0] ** 2 + d[1] ** 2)
            u = (d[0] / norm, d[1] / norm)
            out.append((u[0], u[1], oracle.cross(p, u) / length))
    return out


def inner_radius(points):
    """min over the hull's facets (planes through three points with every point on one side) of
    their distance from 0 (which the hull holds: every call here is of a closure that holds)."""
    best = None
    for a, b, c in itertools.combinations(points, 3):
        ab = [b[i] - a[i] for i in range(3)]
        ac = [c[i] - a[i] for i in range(3)]
        n = (ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0])
        if n == (0, 0, 0):
            continue
        d = sum(n[i] * a[i] for i in range(3))
        if d < 0:
            n, d = tuple(-x for x in n), -d
        if all(sum(n[i] * p[i] for i in range(3)) <= d for p in points):
            assert d > 0
            radius = d / _sqrt(sum(x * x for x in n))
            best = radius if best is None or radius < best else best
    return best


# Six axis-aligned contacts, two of them 2^-40 off the axis: form closure by a hull 2^-40 thin.
THIN_GRASP = {"contacts": [{"point": [0, -1], "normal": [0, 1]}, {"point": [0, 1], "normal": [0, -1]},
                           {"point": [-1, 0], "normal": [1, 0]}, {"point": [-1, 2.0 ** -40], "normal": [1, 0]},
                           {"point": [1, 0], "normal": [-1, 0]}, {"point": [1, 2.0 ** -40], "normal": [-1, 0]}]}
FIVE = json.loads((EXAMPLES / "closure-five-contacts.json").read_text())
# Five contacts with oblique normals, whose torques about the origin are not exact far from it.
OBLIQUE = {"body": {"mass": 1, "com": [0, -0.25], "inertia": 1},
           "contacts": [{"point": [0.25, -1], "normal": [0.2, 1], "mu": 0.25}, {"point": [-0.375, -1], "normal": [-0.1, 1], "mu": 0.25},
                        {"point": [0.125, 1], "normal": [-0.3, -1], "mu": 0.25}, {"point": [-1, 0.125], "normal": [1, 0.1], "mu": 0.25},
                        {"point": [1, -0.25], "normal": [-1, 0.3], "mu": 0.25}]}


def check_quality(got, want, absolute=0.0):
    assert got > 0 and abs(Fraction(got) - want) <= Fraction(1, 10 ** 9) * want + Fraction(absolute), (got, float(want))


@pytest.mark.parametrize("length", [None, 1e-15, 1e-10, 1e20, 1e-60, 1e60])
def test_closure_quality_is_the_oracles_at_any_length(tmp_path, length):
    path = tmp_path / "five.json"
    path.write_text(json.dumps(FIVE))
    extra = [] if length is None else ["--length", repr(length)]
    got = cli("closure", path, *extra, "--json")
    want_form = inner_radius(unit_wrenches(FIVE, False, length))
    want_force = inner_radius(unit_wrenches(FIVE, True, length))
    check_quality(got["form"]["quality"], want_form)
    check_quality(got["force"]["quality"], want_force)
    py = ml.closure(ml.Scene.from_json(json.dumps(FIVE)), length=length)
    check_quality(py.form.quality, want_form)
    check_quality(py.force.quality, want_force)


def test_a_thin_closure_has_its_thin_quality(tmp_path):
    """2^-41 by the oracle (the rounding of the unit wrenches moves it by at most 1e-16)."""
    path = tmp_path / "thin.json"
    path.write_text(json.dumps(THIN_GRASP))
    got = cli("closure", path, "--json")
    want = inner_radius(unit_wrenches(THIN_GRASP, False))
    assert 4e-13 < want < 5e-13
    check_quality(got["form"]["quality"], want, absolute=1e-15)
    check_quality(got["force"]["quality"], want, absolute=1e-15)


@pytest.mark.parametrize("d", [(0, 0), (1e8, -1e8), (2.0 ** 30, 3 * 2.0 ** 28), (-123456789, 987654321)])
@pytest.mark.parametrize("grasp", ["five", "oblique"])
def test_closure_quality_does_not_change_when_the_grasp_moves(tmp_path, d, grasp):
    doc = {"five": FIVE, "oblique": OBLIQUE}[grasp]
    path = tmp_path / "moved.json"
    path.write_text(json.dumps(moved(doc, d)))
    got = cli("closure", path, "--json")
    # The oracle in place (the exact move changes no unit wrench).
    check_quality(got["form"]["quality"], inner_radius(unit_wrenches(doc, False)))
    check_quality(got["force"]["quality"], inner_radius(unit_wrenches(doc, True)))


@pytest.mark.parametrize("length", ["1e-300", "5e-324", "1.7e308", "1e61", "0", "-1"])
def test_every_front_end_refuses_the_same_lengths(length):
    r = subprocess.run([CLI, "closure", str(EXAMPLES / "closure-five-contacts.json"), "--length", length],
                       capture_output=True, text=True)
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "--length" in r.stderr, r.stderr
    with pytest.raises(ValueError, match="length"):
        ml.closure(ml.Scene.from_json(json.dumps(FIVE)), length=float(length))


# ---------------------------------------------------------------------------------------------
# 7. The printed push is the push measured.

# The block on two floor contacts of the issue's search, with gravity (-1.375, 0.5): the best push
# on edge 1 is nearly parallel to a facet of E_ss, so its magnitude bound -h.g / h.u moves by
# orders of magnitude with the last bit of the push.
NEAR_FACET = {"body": {"mass": 1, "com": [0.4375, 0.625], "inertia": 0.125,
                       "polygon": [[0, 0], [1.125, 0], [1.125, 1.25], [0, 1.25]]},
              "contacts": [{"point": [0, 0], "normal": [0, 1], "mu": 0.5}, {"point": [1.125, 0], "normal": [0, 1], "mu": 1.0}]}


def gravity_wrench(doc, g):
    m = oracle.exact(doc["body"]["mass"])
    c = (oracle.exact(doc["body"]["com"][0]), oracle.exact(doc["body"]["com"][1]))
    return oracle.wrench_at(c, (m * oracle.exact(g[0]), m * oracle.exact(g[1])))


def check_magnitudes(doc, goal, g, point, direction, lo, hi, rel):
    """The oracle on g + lambda u, u the push (point, direction) read exactly: lo and hi (None:
    unbounded) are the ends of the goal's magnitudes within `rel` (relative)."""
    scene = oracle.exact_scene(doc)
    gw = gravity_wrench(doc, g)
    u = oracle.wrench_at((oracle.exact(point[0]), oracle.exact(point[1])),
                         (oracle.exact(direction[0]), oracle.exact(direction[1])))

    def holds(lam):
        lam = Fraction(lam)
        return oracle.produces(scene, goal, [gw[k] + lam * u[k] for k in range(3)])

    k = Fraction(rel)
    lo, hi = Fraction(lo), None if hi is None else Fraction(hi)
    assert lo == 0 or not holds(lo * (1 - k)), (point, direction, lo)
    if hi is not None and hi <= lo * (1 + 2 * k):  # one magnitude (rounded): only outside it is tested
        assert not holds(hi * (1 + k)), (point, direction, hi)
        return
    assert holds(lo * (1 + k)), (point, direction, lo)
    if hi is None:
        assert holds(Fraction(2) ** 200), (point, direction, "unbounded")
    else:
        assert holds(hi * (1 - k)) and not holds(hi * (1 + k)), (point, direction, hi)


def test_the_printed_best_push_has_the_printed_magnitudes(tmp_path):
    scene = tmp_path / "near_facet.json"
    scene.write_text(json.dumps(NEAR_FACET))
    args = ("plan", "push", scene, "--goal", "ss", "--mu", "0.5", "--ignore-interference", "--gravity", "-1.375", "0.5",
            "--edge", "1", "--slip", "f")
    text = cli(*args).stdout
    m = re.search(r"best push \(([^,]+), ([^)]+)\) at \(([^,]+), ([^)]+)\).*; magnitudes from (\S+) (?:to (\S+)|up)", text)
    assert m, text
    dx, dy, px, py = (float(v) for v in m.group(1, 2, 3, 4))
    lo, hi = float(m.group(5)), None if m.group(6) is None else float(m.group(6))
    check_magnitudes(NEAR_FACET, "ss", (-1.375, 0.5), (px, py), (dx, dy), lo, hi, 1e-5)  # printed with 6 digits
    case = cli(*args, "--json")["cases"][0]
    best, bm = case["best"], case["best_magnitudes"]
    check_magnitudes(NEAR_FACET, "ss", (-1.375, 0.5), best["point"], best["direction_vector"], bm["from"],
                     None if bm["to"] == "unbounded" else bm["to"], 1e-12)


def goal_band(bands, goal):
    """The magnitudes of push_line's bands that hold the goal: (from, to), to None when unbounded."""
    held = [b for b in bands if goal in b.modes]
    if not held:
        return None
    to = held[-1].to
    return held[0].from_, None if to == math.inf else to


@pytest.mark.parametrize("seed", range(6))
def test_best_pushes_with_gravity_are_the_pushes_measured(seed):
    """Random dyadic blocks with gravity: every feasible case's best push, as the JSON gives it,
    has the magnitudes of push_line at that push (bit for bit) and of the oracle."""
    rng = random.Random(4400 + seed)
    checked = 0
    while checked < 4:
        w, h = rng.randint(2, 16) / 8, rng.randint(2, 16) / 8
        doc = {"body": {"mass": rng.choice([0.5, 1, 2]), "com": [w / 2 + rng.randint(-2, 2) / 16, h / 2 + rng.randint(-2, 2) / 16],
                        "inertia": rng.choice([0.125, 0.25, 1]), "polygon": [[0, 0], [w, 0], [w, h], [0, h]]},
               "contacts": [{"point": [0, 0], "normal": [0, 1], "mu": rng.choice([0.25, 0.5, 1.0])},
                            {"point": [w, 0], "normal": [0, 1], "mu": rng.choice([0.25, 0.5, 1.0])}]}
        g = [rng.randint(-16, 16) / 8, rng.randint(-16, 16) / 8]
        if g == [0, 0]:
            continue
        a = ml.analyze(ml.Scene.from_json(json.dumps(doc)))
        goal = rng.choice(a.modes)
        for c in ml.plan_push(a, goal, mu=0.5, ignore_interference=True, gravity=g):
            if not c.feasible or c.best_magnitudes is None:
                continue
            best, bm = c.best, c.best_magnitudes
            hi = None if bm.to == math.inf else bm.to
            band = goal_band(ml.push_line(a, best.point, best.direction_vector, gravity=g), goal)
            assert band == (bm.from_, hi), (doc, goal, g, c, band)
            if checked < 4:
                check_magnitudes(doc, goal, g, best.point, best.direction_vector, bm.from_, hi, 1e-9)
            checked += 1
