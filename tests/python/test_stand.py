"""momentlab.stand on assemblies (docs/assemblies.md): the bundled examples' hand answers, derived
again here from the scenes' raw numbers in exact rationals (fractions.Fraction), not read from
the library; Python equal to `momentlab stand --json` on the examples and random assemblies;
bad input as ValueError naming the JSON path, as the CLI does."""

import json
import random
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import momentlab as ml
import oracle
from conftest import EXAMPLES, cli

MR = EXAMPLES / "assembly-modern-robotics.json"
LADDER = EXAMPLES / "assembly-ladder.json"
STACK = EXAMPLES / "assembly-harmonic-stack.json"
ARCH = EXAMPLES / "assembly-arch.json"
ASSEMBLIES = [MR, LADDER, STACK, ARCH]
G = 9.81


def doc_of(path):
    return json.loads(path.read_text())


def as_typed(text):
    """A scene's text as Python values with the meaning the file has: decimals as Decimals."""
    return json.loads(text, parse_float=Decimal)


def assembly(doc):
    """The assembly of a scene document, from Python values (not from its text)."""
    return ml.Assembly(doc["bodies"], doc.get("contacts"), doc.get("obstacles", ()), doc.get("contact_distance"),
                       doc.get("mu"))


def wedge(lo, hi):
    """The tilt wedge of gravity (gamma, -1) for gamma in [lo, hi], each edge scaled so that its
    larger coordinate is +-1 (docs/formats.md)."""
    def edge(gamma):
        return (Fraction(1), Fraction(-1) / gamma) if gamma > 1 else (gamma, Fraction(-1))
    return [edge(lo), edge(hi)]


# -- the two blocks of Modern Robotics ------------------------------------------------------------

def modern_robotics(mu_a, m):
    doc = doc_of(MR)
    doc["contacts"][0]["mu"] = mu_a
    doc["bodies"][1]["mass"] = m
    return doc


def mr_threshold_mu_a():
    # Upright, body 1: f + n = K = 5/6, N_A = 2 - f, the floor's friction n; B's cone needs
    # n >= 2K/3 = 5/9; the ratio n / N_A = n / (7/6 + n) grows with n, so its least value is at 5/9.
    n = Fraction(5, 9)
    return n / (2 - (Fraction(5, 6) - n))


def mr_tilt(m):
    # Gravity (gamma, -1): the upper end from N_C >= 0 with n >= 2K/3, K = (5 + 7 gamma)/6:
    # (5 + 7 gamma)/2 <= m (1 - 7 gamma)/2; the lower from A's friction n <= (7 + 17 gamma)/6 with
    # N_D >= 0 (n >= -m (1 + 7 gamma)/10) and with B's cone (n >= (5 + 7 gamma)/9).
    hi = Fraction(m - 5) / (7 * (m + 1))
    lo = max(-Fraction(6 * m + 70) / (170 + 42 * m), Fraction(-33, 111))
    return lo, hi


def test_modern_robotics_as_given_falls():
    assert mr_threshold_mu_a() == Fraction(10, 31)
    assert Fraction(doc_of(MR)["contacts"][0]["mu"]) < mr_threshold_mu_a()
    r = ml.stand(ml.Assembly.from_file(MR), tilt=True)
    assert not r.can_stand and r.forces is None and r.outcome == "falls"
    assert r.tilt.kind == "empty" and r.tilt.directions == []
    check_mechanism(doc_of(MR), r, (0.0, -G))


def test_modern_robotics_thresholds():
    assert ml.stand(assembly(modern_robotics(0.5, 10))).can_stand
    # m >= 12 n - 5/3 with n >= 5/9: the least mass is 5, where it stands on the boundary.
    least = 12 * Fraction(5, 9) - Fraction(5, 3)
    assert least == 5
    assert ml.stand(assembly(modern_robotics(0.5, float(least)))).can_stand
    assert not ml.stand(assembly(modern_robotics(0.5, float(least) - 2.0 ** -40))).can_stand
    # mu_A just above and below 10/31 (m = 10)
    mu = mr_threshold_mu_a()
    above, below = float(mu), float(mu)
    above = above if Fraction(above) >= mu else np.nextafter(above, 1.0)
    below = below if Fraction(below) < mu else np.nextafter(below, 0.0)
    assert ml.stand(assembly(modern_robotics(float(above), 10))).can_stand
    assert not ml.stand(assembly(modern_robotics(float(below), 10))).can_stand


@pytest.mark.parametrize("m", [10, 5])
def test_modern_robotics_stands_and_tilts(m):
    r = ml.stand(assembly(modern_robotics(0.5, m)), tilt=True)
    assert r.can_stand and r.outcome == "stands" and r.motions == []
    assert "ffff" in r.modes
    assert r.tilt.kind == "wedge" and r.tilt.directions == wedge(*mr_tilt(m))
    check_equilibrium(modern_robotics(0.5, m), r, (0.0, -G))
    if m == 5:
        # The equilibrium is unique: n = 5/9, f = 5/18 (body 1 gets (-n, f) at B, body 2 the
        # opposite), nothing at C, N_A = 2 - f, N_D = m + f; the floor's friction n at A, -n at D.
        n, f = Fraction(5, 9), Fraction(5, 18)
        expected = [(n, 2 - f), (-n, f), (0, 0), (-n, m + f)]
        assert r.forces[2].tolist() == [0.0, 0.0]
        np.testing.assert_allclose(r.forces, G * np.array(expected, dtype=float), rtol=1e-12, atol=1e-12)


# -- the ladder -----------------------------------------------------------------------------------

def ladder_tilt(mu):
    # Vertically N_A = 1, about A: 4 N_B = 3/2 + 2 gamma, the floor's friction (3 - 4 gamma)/8:
    # |3 - 4 gamma| <= 8 mu and N_B >= 0 (gamma >= -3/4).
    return max((3 - 8 * mu) / 4, Fraction(-3, 4)), (3 + 8 * mu) / 4


def test_ladder_on_the_boundary():
    doc = doc_of(LADDER)
    mu = Fraction(doc["contacts"][0]["mu"])
    assert mu == Fraction(1, 2) / Fraction(4, 3)  # 1 / (2 tan a), tan a = 4/3
    r = ml.stand(ml.Assembly.from_file(LADDER), tilt=True)
    assert r.can_stand and r.outcome == "stands" and r.motions == []
    assert sorted(r.modes) == ["ff", "ll"]
    assert r.tilt.kind == "wedge" and r.tilt.directions == wedge(*ladder_tilt(mu))
    assert r.tilt.directions[1] == (1, Fraction(-2, 3))
    check_equilibrium(doc, r, (0.0, -G))
    doc["contacts"][0]["mu"] = 0.375 - 2.0 ** -40
    falls = ml.stand(assembly(doc))
    assert not falls.can_stand and falls.outcome == "falls"
    check_mechanism(doc, falls, (0.0, -G))
    doc["contacts"][0]["mu"] = 0.5
    assert ml.stand(assembly(doc), tilt=True).tilt.directions == wedge(*ladder_tilt(Fraction(1, 2)))


# -- the harmonic stack ---------------------------------------------------------------------------

def test_harmonic_stack_stands_with_the_load_at_the_outer_ends():
    doc = doc_of(STACK)
    a = ml.Assembly.from_file(STACK)
    r = ml.stand(a, tilt=True)
    assert r.can_stand and r.outcome == "stands" and r.motions == []
    # Friction |gamma| <= mu = 1/2 bounds the left tilt; any right tilt moves a line beyond its end.
    assert r.tilt.kind == "wedge" and r.tilt.directions == wedge(-Fraction(doc["mu"]), Fraction(0))
    # The top k bricks' weight (0, -k) is carried at the outer end of their lowest interface
    # (x = 0, 3, 7, 13 from the floor up), whose line it passes: nothing at the inner ends.
    outer = {0.0: 4, 3.0: 3, 7.0: 2, 13.0: 1}
    for p, f in zip(a.points, r.forces):
        assert f.tolist() == pytest.approx([0.0, G * outer[p[0]]] if p[0] in outer else [0.0, 0.0], abs=1e-12)
    check_equilibrium(doc, r, (0.0, -G))
    top = doc["bodies"][3]
    top["com"][0] += 2.0 ** -20
    top["polygon"] = [[x + 2.0 ** -20, y] for x, y in top["polygon"]]
    assert not ml.stand(assembly(doc)).can_stand


# -- the arch -------------------------------------------------------------------------------------

def arch_stands(mu):
    # Upright, by symmetry b = d = 1; the faces' friction needs k <= 5 mu, k = (2 - mu)/(1 + 2 mu),
    # i.e. 10 mu^2 + 6 mu - 2 >= 0.
    return 10 * mu * mu + 6 * mu - 2 >= 0


def test_arch():
    doc = doc_of(ARCH)
    mu = json.loads(ARCH.read_text(), parse_float=Fraction)["contacts"][0]["mu"]  # 3/10, as typed
    k = (2 - mu) / (1 + 2 * mu)
    gamma = k * (5 * mu - k) / (5 * k - mu)
    assert gamma == Fraction(595, 6416)
    r = ml.stand(ml.Assembly.from_file(ARCH), tilt=True)
    assert r.can_stand and r.outcome == "stands" and "ffffffff" in r.modes and r.motions == []
    assert r.tilt.kind == "wedge" and r.tilt.directions == wedge(-gamma, gamma)
    # the same numbers as Python floats: mu the double nearest 0.3, a little below 3/10
    binary = Fraction(0.3)
    k = (2 - binary) / (1 + 2 * binary)
    binary_gamma = k * (5 * binary - k) / (5 * k - binary)
    assert binary_gamma < gamma and ml.stand(assembly(doc), tilt=True).tilt.directions == wedge(-binary_gamma, binary_gamma)
    check_equilibrium(doc, r, (0.0, -G))
    for m in (0.2385, 0.2386, 0.25, 0.2):
        for c in doc["contacts"]:
            c["mu"] = m
        assert ml.stand(assembly(doc)).can_stand == arch_stands(Fraction(m)), m


# -- certificates, checked from the raw numbers ---------------------------------------------------

def wrench(p, f):
    return np.array([f[0], f[1], p[0] * f[1] - p[1] * f[0]])


def check_equilibrium(doc, r, g):
    """Every contact force in its friction cone, and every body's gravity wrench plus its contact
    wrenches zero (the forces are rounded: to a relative 1e-9)."""
    bodies = doc["bodies"]
    contacts = ml.Assembly.from_json(json.dumps(doc))
    total = [wrench(b["com"], (b["mass"] * g[0], b["mass"] * g[1])) for b in bodies]
    scale = max(abs(b["mass"]) for b in bodies) * G * max(1.0, np.abs(contacts.points).max())
    for (a, b), p, n, mu, f in zip(contacts.pairs, contacts.points, contacts.normals, contacts.mu, r.forces):
        t = np.array([n[1], -n[0]])
        normal, tangent = f @ n, f @ t
        assert normal >= -1e-9 * scale and abs(tangent) <= mu * normal + 1e-9 * scale
        total[a - 1] = total[a - 1] + wrench(p, f)
        if b:
            total[b - 1] = total[b - 1] - wrench(p, f)
    for w in total:
        assert np.abs(w).max() <= 1e-9 * scale


def check_mechanism(doc, r, g):
    """Every contact allows the relative twist (N.v >= mu |T.v|) and gravity does positive work."""
    contacts = ml.Assembly.from_json(json.dumps(doc))
    twists = {m.body: m.twist for m in r.mechanism}
    assert sorted(twists) == list(range(1, len(doc["bodies"]) + 1))
    size = max(np.abs(m.twist).max() for m in r.mechanism) * max(1.0, np.abs(contacts.points).max())
    for (a, b), p, n, mu in zip(contacts.pairs, contacts.points, contacts.normals, contacts.mu):
        v = twists[a] - (twists[b] if b else 0)
        t = np.array([n[1], -n[0]])
        normal, tangent = wrench(p, n) @ v, wrench(p, t) @ v
        assert normal >= mu * abs(tangent) - 1e-9 * size * np.abs(n).max()
    work = sum(wrench(b["com"], (b["mass"] * g[0], b["mass"] * g[1])) @ twists[k + 1] for k, b in enumerate(doc["bodies"]))
    # (Work of the order of the distance to the boundary: 2^-40 for the ladder just below it.)
    assert work > 1e-14 * size * max(b["mass"] for b in doc["bodies"]) * G
    for m in r.mechanism:
        vx, vy, w = m.twist
        if w != 0:
            assert m.rotation_centre == pytest.approx((-vy / w, vx / w))
        else:
            assert m.rotation_centre is None


# -- Python equals the CLI ------------------------------------------------------------------------

def normal_form(doc):
    """A `stand --json` document with exact tilt edges (Fractions) and plain lists."""
    out = dict(doc)
    if out.get("tilt") is not None:
        out["tilt"] = {"kind": doc["tilt"]["kind"],
                       "directions": [tuple(Fraction(x) for x in d) for d in doc["tilt"]["directions"]]}
    return out


def python_form(r):
    """A StandResult in the form of normal_form, written from the JSON's field names."""
    out = {"can_stand": r.can_stand, "modes": r.modes, "verdict": r.verdict, "motions": r.motions, "outcome": r.outcome}
    if r.forces is not None:
        out["forces"] = r.forces.tolist()
    if r.mechanism is not None:
        out["mechanism"] = [{"body": m.body, "twist": m.twist.tolist(),
                             "rotation_centre": None if m.rotation_centre is None else list(m.rotation_centre)}
                            for m in r.mechanism]
    if r.modes_reason is not None:
        out["modes_reason"] = r.modes_reason
    if r.tilt is not None:
        out["tilt"] = {"kind": r.tilt.kind, "directions": r.tilt.directions}
    return out


def same_as_cli(path, python_result, *options):
    assert python_form(python_result) == normal_form(cli("stand", path, *options, "--json"))


@pytest.mark.parametrize("path", ASSEMBLIES, ids=lambda p: p.stem)
def test_examples_equal_the_cli(path):
    same_as_cli(path, ml.stand(ml.Assembly.from_file(path), tilt=True), "--tilt")
    same_as_cli(path, ml.stand(assembly(as_typed(path.read_text())), gravity=(1, -3)), "--gravity", "1", "-3")


def test_one_body_scene_equals_the_cli():
    path = EXAMPLES / "problem-ladder.json"
    same_as_cli(path, ml.stand(ml.Scene.from_file(path), tilt=True), "--tilt")


def random_assembly(rng):
    """A stack of 2-3 blocks of integer sizes and offsets on the floor, the contacts found from
    the polygons (some stand, some fall, some sit exactly on an edge), or a rod leaning on a block."""
    bodies, x, y = [], 0, 0
    for _ in range(rng.randint(2, 3)):
        w, h = rng.randint(2, 6), rng.randint(1, 3)
        x0 = x + rng.randint(-w, w)
        poly = [[x0, y], [x0 + w, y], [x0 + w, y + h], [x0, y + h]]
        bodies.append({"mass": rng.choice([1, 2, 3]), "com": [x0 + w / 2, y + h / 2], "inertia": 1, "polygon": poly})
        x, y = x0, y + h
    return {"bodies": bodies, "obstacles": [{"polygon": [[-20, -1], [20, -1], [20, 0], [-20, 0]]}],
            "mu": rng.choice([0, 0.1, 0.25, 0.5, 1])}


def test_random_assemblies_equal_the_cli(tmp_path):
    rng = random.Random(47)
    outcomes = set()
    for i in range(16):
        doc = random_assembly(rng)
        path = tmp_path / f"random-{i}.json"
        path.write_text(json.dumps(doc))
        g = (rng.choice([-1, 0, 0.5, 1]), -rng.randint(1, 4))
        r = ml.stand(assembly(as_typed(path.read_text())), gravity=g, tilt=True)
        same_as_cli(path, r, "--gravity", *map(str, g), "--tilt")
        outcomes.add(r.can_stand)
    assert outcomes == {True, False}


def test_decimals_read_as_the_cli_reads_their_text(tmp_path):
    doc = doc_of(LADDER)
    text = LADDER.read_text()
    with_decimals = json.loads(text, parse_float=Decimal)
    r = ml.stand(assembly(with_decimals), tilt=True)
    same_as_cli(LADDER, r, "--tilt")
    assert python_form(r) == python_form(ml.stand(assembly(doc), tilt=True))


# -- bad input ------------------------------------------------------------------------------------

BAD = [
    (lambda d: d["contacts"][1].update(bodies=[2, 2]), "$.contacts[1].bodies"),
    (lambda d: d["contacts"][0].update(bodies=[3, 0]), "$.contacts[0].bodies"),
    (lambda d: d["bodies"][0].pop("mass"), "$.bodies[0]"),
    (lambda d: d["bodies"][1].update(mass=-5), "$.bodies[1].mass"),
    (lambda d: d["contacts"][2].update(mu=-1), "$.contacts[2].mu"),
    (lambda d: d["bodies"][0].update(polygon=[[0, 0], [60, 60], [65, 45]]), "$.bodies[1].polygon"),  # into the block
]


@pytest.mark.parametrize("change,path", BAD)
def test_bad_assemblies_name_the_path_as_the_cli_does(change, path, tmp_path):
    doc = doc_of(MR)
    change(doc)
    with pytest.raises(ValueError) as error:
        assembly(doc)
    message = str(error.value)
    assert message.startswith(path + ":"), message
    (tmp_path / "bad.json").write_text(json.dumps(doc))
    r = cli("stand", tmp_path / "bad.json", check=False)
    assert r.returncode == 2 and r.stderr.strip() == "momentlab: " + message
    with pytest.raises(ValueError) as from_file:
        ml.Assembly.from_file(tmp_path / "bad.json")
    assert str(from_file.value) == message


def test_bad_arguments():
    a = ml.Assembly.from_file(MR)
    with pytest.raises(ValueError, match="^gravity"):
        ml.stand(a, gravity=(0, "x"))
    with pytest.raises(ValueError, match="^gravity"):
        ml.stand(a, gravity=(0, np.nan))
    with pytest.raises(ValueError, match="^tilt"):
        ml.stand(a, tilt="yes")
    with pytest.raises(ValueError, match="Assembly"):
        ml.stand(str(MR))
    with pytest.raises(ValueError, match=r'^\$: missing field "body"'):
        ml.stand(ml.Scene(contacts=[ml.Contact((0, 0), (0, 1))]))
    with pytest.raises(ValueError, match=r"^\$\.bodies"):
        ml.Assembly([])
    with pytest.raises(ValueError, match=r"^\$: cannot read file"):
        ml.Assembly.from_file(EXAMPLES / "no-such-assembly.json")
    with pytest.raises(ValueError, match="^body"):
        a.contact_wrenches(3)


def test_assembly_values_and_result_types():
    a = ml.Assembly.from_file(MR)
    assert [b["name"] for b in a.bodies] == ["leaning", "block"] and a.bodies[1]["mass"] == 5
    assert a.pairs.tolist() == [[1, 0], [1, 2], [2, 0], [2, 0]]
    r = ml.stand(assembly(modern_robotics(0.5, 10)))
    assert isinstance(r, ml.StandResult) and r.forces.shape == (4, 2) and not r.forces.flags.writeable
    with pytest.raises(Exception):
        r.can_stand = False  # frozen
    # Body 2's contacts can apply: the floor's cones at C and D and the opposite of B's cone.
    cone = a.contact_wrenches(2)
    assert cone.contains([0, 1, 66]) and not cone.contains([0, -1, -66])
    assert cone.contains(wrench((60, 60), (1, 0))) and not cone.contains(wrench((60, 60), (-1, 0)))


# -- pictures -------------------------------------------------------------------------------------

def answer_arrows(ax):
    import matplotlib.text
    from matplotlib.colors import to_rgb
    import momentlab.plot as mp
    return [t for t in ax.texts if isinstance(t, matplotlib.text.Annotation) and t.arrowprops
            and np.allclose(to_rgb(t.arrowprops["color"]), mp.ANSWER)]


def test_plot_stand_draws_the_loaded_ends_of_the_harmonic_stack():
    import matplotlib.pyplot as plt
    import momentlab.plot as mp
    fig, axes = plt.subplots(1, 5)
    r = mp.stand(axes, ml.Assembly.from_file(STACK))
    assert r.can_stand
    # By hand (docs/assemblies.md): the load k at the outer ends (0, 0), (3, 1), (7, 2), (13, 3), up.
    arrows = {tuple(a.xyann): np.subtract(a.xy, a.xyann) for a in answer_arrows(axes[0])}
    assert sorted(arrows) == [(0, 0), (3, 1), (7, 2), (13, 3)]
    unit = arrows[(0, 0)][1] / 4
    for start, load in ((3, 1), 3), ((7, 2), 2), ((13, 3), 1):
        assert arrows[start] == pytest.approx((0.0, load * unit))
    assert [ax.get_title() for ax in axes[1:]] == [f"body {k}: wrenches its contacts can apply" for k in range(1, 5)]
    plt.close(fig)


def test_plot_stand_draws_a_mechanism_along_which_gravity_works():
    import matplotlib.pyplot as plt
    import momentlab.plot as mp
    fig, ax = plt.subplots()
    doc = doc_of(MR)
    r = mp.stand(ax, ml.Assembly.from_file(MR))
    assert not r.can_stand
    coms = {tuple(b["com"]): b["mass"] for b in doc["bodies"]}
    arrows = answer_arrows(ax)
    assert arrows and all(tuple(a.xyann) in coms for a in arrows)
    assert sum(coms[tuple(a.xyann)] * (a.xy[1] - a.xyann[1]) for a in arrows) < 0  # gravity (0, -1) works
    plt.close(fig)


def test_cli_draws_the_stand_picture(tmp_path):
    svg, png = tmp_path / "stack.svg", tmp_path / "stack.png"
    r = cli("draw", STACK, "--what", "stand", "-o", svg, "-o", png)
    assert r.returncode == 0 and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    text = svg.read_text()
    assert "4 of 8 contacts carry force" in text  # the four outer ends, by hand
    assert all(f"body {k} " in text for k in range(1, 5))
    falls = cli("draw", MR, "--what", "stand", "-o", tmp_path / "mr.svg")
    assert falls.returncode == 0 and "falls: a collapse mechanism" in (tmp_path / "mr.svg").read_text()
    bad = cli("draw", EXAMPLES / "figure-1a-force.json", "--what", "stand", "-o", tmp_path / "bad.svg", check=False)
    assert bad.returncode == 2 and bad.stderr.startswith("momentlab: $") and not (tmp_path / "bad.svg").exists()


# -- numbers as typed (docs/design.md): decimals in files and --gravity are the decimals they spell --

# A unit-ish block on the ramp y = 0.3 x (integer corners (0, 0), (10, 3)), its bottom corners
# (2, 0.6) and (4, 1.2) on the ramp exactly in decimals; in doubles 0.6 is below the line.
RAMP = {"bodies": [{"mass": 1, "com": [2.85, 1.4], "inertia": 1,
                    "polygon": [[2, 0.6], [4, 1.2], [3.7, 2.2], [1.7, 1.6]]}],
        "obstacles": [{"polygon": [[0, 0], [10, 0], [10, 3]]}]}


def ramp_text(mu):
    return json.dumps(RAMP)[:-1] + f', "mu": {mu}}}'


def test_block_on_a_decimal_ramp_at_its_friction_limit(tmp_path):
    # The ramp's normal n = (-0.3, 1), t = (1, 0.3): the cone edge n + mu t = (0, 1 + 0.09) at
    # mu = 0.3 is vertical, so the weight lies on the cone's edge: it stands, on the boundary;
    # any less friction and it slides. Its com (2.85) is over the base [2, 4].
    for mu, stands in (("0.3", True), ("0.29", False), ("0.31", True)):
        path = tmp_path / f"ramp-{mu}.json"
        path.write_text(ramp_text(mu))
        r = cli("stand", path, "--json")
        assert r["can_stand"] is stands, mu
        assert r["outcome"] == ("stands" if stands else "falls"), mu
        # the contacts as found: the two bottom corners, the ramp's normal exactly
        a = ml.Assembly.from_file(path)
        assert a.points.tolist() == [[2.0, 0.6], [4.0, 1.2]] and a.normals.tolist() == [[-0.3, 1.0], [-0.3, 1.0]]
        assert ml.stand(a).can_stand is stands
        # Python's exact values read the same: Decimals and Fractions as typed
        exact = json.loads(ramp_text(mu), parse_float=Decimal)
        assert ml.stand(assembly(exact)).can_stand is stands


def test_typed_gravity_exactly_at_the_friction_limit(tmp_path):
    # A block on the floor (two corners, mu = 0.3 typed): it stands exactly when |gx| <= 0.3 |gy|.
    doc = {"bodies": [{"mass": 2, "com": [1, 0.5], "inertia": 1, "polygon": [[0, 0], [2, 0], [2, 1], [0, 1]]}],
           "obstacles": [{"polygon": [[-5, -1], [5, -1], [5, 0], [-5, 0]]}], "mu": 0.3}
    path = tmp_path / "block.json"
    path.write_text(json.dumps(doc))
    # (19 digits: within an ulp of 0.9, on either side; their doubles are 0.9's, and the
    # enclosures of the decimals must leave the decision to the exact path)
    for gx in ("0.9", "0.91", "-0.9", "0.89", "0.8999999999999999999", "0.9000000000000000001"):
        stands = abs(Fraction(gx)) <= Fraction(3, 10) * 3
        assert cli("stand", path, "--gravity", gx, "-3", "--json")["can_stand"] is stands, gx
        a = ml.Assembly.from_file(path)
        assert ml.stand(a, gravity=(Decimal(gx), -3)).can_stand is stands, gx
        assert ml.stand(a, gravity=(gx, "-3")).can_stand is stands, gx
        # a float is its binary value: 0.9 is a little above 9/10
        binary = abs(Fraction(float(gx))) <= Fraction(3, 10) * 3
        assert ml.stand(a, gravity=(float(gx), -3)).can_stand is binary, gx
    assert Fraction(0.9) > Fraction(9, 10)  # so the float 0.9 slides where the decimal stands
    picture = tmp_path / "block.svg"
    falls = cli("draw", path, "--what", "stand", "--gravity", "0.91", "-3", "-o", picture)
    assert falls.returncode == 0 and "falls: a collapse mechanism" in picture.read_text()
    cli("draw", path, "--what", "stand", "--gravity", "0.9", "-3", "-o", picture)
    assert "falls" not in picture.read_text()
    bad = cli("draw", path, "--what", "modes", "--gravity", "0", "-1", "-o", picture, check=False)
    assert bad.returncode == 2 and bad.stderr.startswith("momentlab: --gravity")


def equilibrium_exists(doc, gravity):
    """The oracle: some contact forces in their cones balance every body's weight, decided by an
    exact phase-1 simplex (tests/python/oracle.py) on the scene's numbers read as Fractions from
    their text. Columns: each contact's cone edges n +- mu t (n alone at mu = 0) as wrenches
    through its point, on body a's rows and negated on body b's."""
    bodies, rows = doc["bodies"], 3 * len(doc["bodies"])
    gx, gy = gravity
    b = [Fraction(0)] * rows
    for k, body in enumerate(bodies):
        m, (cx, cy) = body["mass"], body["com"]
        b[3 * k:3 * k + 3] = [-m * gx, -m * gy, -(cx * m * gy - cy * m * gx)]
    columns = []
    for c in doc["contacts"]:
        (px, py), (nx, ny), mu = c["point"], c["normal"], c.get("mu", Fraction(0))
        tx, ty = ny, -nx
        for s in ((mu, -mu) if mu else (0,)):
            fx, fy = nx + s * tx, ny + s * ty
            col = [Fraction(0)] * rows
            a, bb = c["bodies"]
            for body, sign in ((a, 1), (bb, -1)):
                if body:
                    col[3 * (body - 1):3 * body] = [sign * fx, sign * fy, sign * (px * fy - py * fx)]
            columns.append(col)
    A = [[Fraction(col[i]) for col in columns] for i in range(rows)]  # Fractions: no int division
    return oracle._nonneg_solution(A, [Fraction(v) for v in b]) is not None


def decimal_stack(rng, gravity):
    """1-3 blocks stacked on a ramp of decimal slope s, with listed contacts: each block's bottom
    corners on the block below (or the ramp) at decimal points a d + h n (d = (1, s), n = (-s, 1));
    mu per interface a decimal, often s itself (the weight of a block alone then lies on its
    cone's edge); its com often on the line along gravity through a corner, corner + 0.5 (-gx, 1)
    for gravity (gx, -1) (on that block's tipping boundary: a relation among decimals that their
    doubles miss), else in the middle of its base or anywhere above it."""
    s = Fraction(rng.choice(range(-5, 6)), 10)
    d, n = (1, s), (-s, 1)
    at = lambda a, h: [a * d[0] + h * n[0], a * d[1] + h * n[1]]
    bodies, contacts, lo, hi, h = [], [], Fraction(0), Fraction(4), Fraction(0)
    for k in range(rng.randint(1, 3)):
        lo2 = lo + Fraction(rng.randint(-10, 10), 10)
        hi2 = lo2 + Fraction(rng.randint(5, 30), 10)
        a1, a2 = max(lo, lo2), min(hi, hi2)  # the overlap with the block below
        if a1 >= a2:
            break
        mu = rng.choice([abs(s), abs(s), Fraction(rng.randint(0, 8), 10)])
        for a in (a1, a2):
            contacts.append({"bodies": [k + 1, k], "point": at(a, h), "normal": list(n), "mu": mu})
        corner = at(rng.choice([a1, a2]), h)
        tipping = [corner[0] - gravity[0] / 2, corner[1] + Fraction(1, 2)]
        com = rng.choice([tipping, tipping,
                          at((lo2 + hi2) / 2, h + Fraction(1, 2)),
                          at(Fraction(rng.randint(int(10 * lo2), int(10 * hi2)), 10), h + Fraction(1, 2))])
        bodies.append({"mass": Fraction(rng.randint(1, 30), 10), "com": com, "inertia": 1})
        on_tipping_line = [com[0] - corner[0], com[1] - corner[1]] == [-gravity[0] / 2, Fraction(1, 2)]
        lo, hi, h = lo2, hi2, h + 1
    return {"bodies": bodies, "contacts": contacts}, bool(bodies) and on_tipping_line


def decimal_text(x):
    """A Fraction whose denominator divides a power of ten, as its decimal text."""
    k = 0
    while (x * 10 ** k).denominator != 1:
        k += 1
    v = x * 10 ** k
    return f"{v.numerator}e-{k}" if k else str(v.numerator)


def test_random_decimal_stacks_agree_with_an_exact_oracle(tmp_path):
    rng = random.Random(4647)
    counts = {"scenes": 0, "stands": 0, "top block on its tipping line": 0, "binary differs": 0}
    for i in range(60):
        gravity = (Fraction(rng.choice([0, 0, 1, -1, 3]), 10), Fraction(-1))
        doc, boundary = decimal_stack(rng, gravity)
        while not doc["bodies"]:
            doc, boundary = decimal_stack(rng, gravity)
        expected = equilibrium_exists(doc, gravity)
        text = json.dumps(doc, default=lambda x: "@" + decimal_text(x) + "@").replace('"@', "").replace('@"', "")
        path = tmp_path / f"stack-{i}.json"
        path.write_text(text)
        g = [decimal_text(x) for x in gravity]
        assert cli("stand", path, "--gravity", *g, "--json")["can_stand"] is expected, text
        assert ml.stand(ml.Assembly.from_json(text), gravity=tuple(g)).can_stand is expected, text
        # The same numbers as binary doubles are another scene: the oracle on their exact values.
        binary = json.loads(text)
        as_doubles = json.loads(text, parse_float=lambda t: Fraction(float(t)))
        float_gravity = tuple(float(x) for x in gravity)
        binary_expected = equilibrium_exists(as_doubles, tuple(Fraction(x) for x in float_gravity))
        assert ml.stand(assembly(binary), gravity=float_gravity).can_stand is binary_expected, text
        counts["scenes"] += 1
        counts["stands"] += expected
        counts["top block on its tipping line"] += boundary
        counts["binary differs"] += expected != binary_expected
    print(counts)
    assert counts["stands"] not in (0, counts["scenes"]) and counts["binary differs"] > 0
    assert 3 * counts["top block on its tipping line"] >= counts["scenes"]


def test_a_body_index_is_an_integer_as_typed(tmp_path):
    text = MR.read_text().replace('"bodies": [1, 2]', '"bodies": [1, 2.0000000000000000001]')
    assert "2.0000000000000000001" in text
    path = tmp_path / "index.json"
    path.write_text(text)
    r = cli("stand", path, check=False)
    assert r.returncode == 2 and r.stderr.startswith("momentlab: $.contacts[1].bodies[1]: expected a body index")
    with pytest.raises(ValueError, match=r"\$\.contacts\[1\]\.bodies\[1\]"):
        ml.Assembly.from_json(text)
    path.write_text(MR.read_text().replace('"bodies": [1, 2]', '"bodies": [1, 2.0]'))
    assert cli("stand", path, "--json")["can_stand"] is False  # 2.0 is the integer 2
