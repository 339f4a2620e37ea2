"""Numbers as typed (issue 46) in the inputs beyond scenes and loads: force-set files, `label
--at`, the planners' points and loads (docs/design.md, "Numbers as typed"; docs/formats.md).

The oracle reads the force-set file's raw text with every number a Fraction of its decimal
(json.loads(..., parse_float=Fraction)) and decides each label from its definition (docs/design.md,
"Moment labels"): + when every force of the set has moment >= 0 about the point, - when every one
has moment <= 0. A set given by generators has those moments on its generators; a set of
half-spaces {w : n . w >= 0} has F* = cone(normals), so + is "the point's moment functional is in
cone(normals)", an exact LP (tests/python/oracle.py). It never sees momentlab's cones. The scenes
are degenerate only in decimal: forces whose lines meet at a decimal point, points on a decimal
line of force."""

import json
import random
from fractions import Fraction

import pytest

import oracle
from conftest import cli
from test_decimals_oracle import dec
from test_issue44_oracle import quasi_static_answer


def generators(s):
    """The generators of a force set of the file (Fractions), or None for half-spaces."""
    t = s["type"]
    if t in ("force", "line"):
        w = oracle.wrench_at(s["point"], s["direction"])
        return [w] if t == "force" else [w, tuple(-x for x in w)]
    if t == "point":
        x, y = s["point"]
        return [(1, 0, -y), (-1, 0, y), (0, 1, x), (0, -1, -x)]
    if t == "friction_cone":
        (nx, ny), mu = s["normal"], s["mu"]
        return [oracle.wrench_at(s["point"], (nx + c * ny, ny - c * nx)) for c in (mu, -mu)]
    if t == "moment":
        return {1: [(0, 0, 1)], -1: [(0, 0, -1)], 0: [(0, 0, 1), (0, 0, -1)]}[s["sign"]]
    if t == "wrenches":
        return [tuple(g) for g in s["generators"]]
    return None


def in_dual(s, functional):
    """The functional (y, -x, 1) of a point (or its negative) is in the set's dual cone F*."""
    gens = generators(s)
    if gens is not None:
        return all(oracle.dot(functional, g) >= 0 for g in gens)
    normals = s["normals"]  # F* = cone(normals)
    rows = [([n[k] for n in normals], functional[k]) for k in range(3)]
    return oracle.lp_feasible(len(normals), equalities=rows, nonneg=range(len(normals))) is not None


def label(sets, point):
    """The label of `point` for the sum of `sets` (F* is the intersection of their duals)."""
    f = (Fraction(point[1]), -Fraction(point[0]), Fraction(1))
    plus = all(in_dual(s, f) for s in sets)
    minus = all(in_dual(s, tuple(-x for x in f)) for s in sets)
    return {(True, True): "+-", (True, False): "+", (False, True): "-", (False, False): "none"}[(plus, minus)]


def decimals(text):
    return json.loads(text, parse_float=Fraction, parse_int=Fraction)


def doubles(text):
    """The same numbers as the doubles nearest them (the reading before issue 46), exactly."""
    return json.loads(text, parse_float=lambda s: Fraction(float(s)), parse_int=Fraction)


def cli_labels(tmp_path, text, points):
    path = tmp_path / "forces.json"
    path.write_text(text)
    args = [a for p in points for a in ("--at", dec(p[0]), dec(p[1]))]
    return cli("label", path, *args, "--json")


def sets_text(sets):
    """A force-set file's text, each number written as its exact decimal."""
    def value(v):
        if isinstance(v, (list, tuple)):
            return "[" + ",".join(value(x) for x in v) + "]"
        return json.dumps(v) if isinstance(v, str) else dec(v)
    return "[" + ",".join("{" + ",".join(f'"{k}":{value(v)}' for k, v in s.items()) + "}" for s in sets) + "]"


D = Fraction
X = (D("0.1"), D("0.7"))  # where the forces below meet, in decimal


def through_x(kind, p, **more):
    """A set of `kind` at p whose force (a friction cone: its edge n + mu t) points along the line
    from p to X."""
    d = (X[0] - p[0], X[1] - p[1])
    if kind == "friction_cone":  # n + mu t = (1 + mu^2) d for n = (d.x - mu d.y, d.y + mu d.x)
        mu = more["mu"]
        return {"type": kind, "point": p, "normal": (d[0] - mu * d[1], d[1] + mu * d[0]), **more}
    return {"type": kind, "point": p, "direction": d}


MEETING = [through_x("force", (D("0.4"), D("0.3"))), through_x("force", (D("0.6"), D("0.9")))]


def test_forces_meeting_at_a_decimal_point(tmp_path):
    """Two forces whose lines meet at (0.1, 0.7): the point has both labels, and the labelled
    regions are wedges with that apex, correctly rounded."""
    text = sets_text(MEETING)
    assert label(decimals(text), X) == "+-"
    assert label(doubles(text), X) != "+-"  # the degeneracy holds in decimal only
    out = cli_labels(tmp_path, text, [X])
    assert out["at"] == [{"point": [0.1, 0.7], "point_exact": ["1/10", "7/10"], "label": "+-"}]
    for region in out["labels"].values():
        assert region["vertices"] == [[0.1, 0.7]], region


@pytest.mark.parametrize("kind", ["force", "line", "friction_cone", "wrenches", "halfspaces"])
def test_each_kind_of_set_reads_decimals(tmp_path, kind):
    """Each type of set, with its numbers decimal, labels points on decimal lines as the oracle."""
    p, q = (D("0.3"), D("-0.2")), (D("-0.4"), D("0.5"))
    if kind == "friction_cone":
        s = through_x(kind, p, mu=D("0.3"))
    elif kind == "wrenches":
        s = {"type": kind, "generators": [oracle.wrench_at(p, (X[0] - p[0], X[1] - p[1])), (D("0.2"), D("0.1"), D("-0.3"))]}
    elif kind == "halfspaces":  # the functionals of X and of q (times 3 and 0.7) span F*
        s = {"type": kind, "normals": [(3 * X[1], -3 * X[0], D(3)), (D("0.7") * q[1], D("-0.7") * q[0], D("0.7"))]}
    else:
        s = through_x(kind, p)
    sets = [s, through_x("force", (D("0.6"), D("0.9")))]
    text = sets_text(sets)
    # X, q, a point on the segment X-p (decimal), one beyond p on its line, and one off the line.
    points = [X, q, ((X[0] + p[0]) / 2, (X[1] + p[1]) / 2), (2 * p[0] - X[0], 2 * p[1] - X[1]), (D("0.2"), D("0.1"))]
    expected = [label(decimals(text), x) for x in points]
    got = [a["label"] for a in cli_labels(tmp_path, text, points)["at"]]
    assert got == expected, (text, points)
    assert expected != [label(doubles(text), x) for x in points]  # decimal only


def random_decimal(rng, lo=-2, hi=2, places=1):
    return Fraction(rng.randint(lo * 10 ** places, hi * 10 ** places), 10 ** places)


def test_random_sets_meeting_at_a_decimal_point(tmp_path):
    """Random sums of sets whose lines of force pass through one decimal point, labelled there and
    at decimal points on those lines, against the oracle; count where the doubles differ."""
    rng = random.Random(4646)
    differ = 0
    for _ in range(8):
        x = (random_decimal(rng), random_decimal(rng))
        sets, points = [], [x]
        for _ in range(rng.randint(1, 3)):
            p = (random_decimal(rng), random_decimal(rng))
            if p == x:
                continue
            kind = rng.choice(["force", "line", "friction_cone", "point"])
            d = (x[0] - p[0], x[1] - p[1])
            if kind == "point":
                sets.append({"type": "point", "point": x})
            elif kind == "friction_cone":
                sets.append({"type": kind, "point": p, "normal": d, "mu": random_decimal(rng, 0, 1)})
            else:
                sets.append({"type": kind, "point": p, "direction": d})
            k = Fraction(rng.randint(-9, 19), 10)
            points.append((p[0] + k * d[0], p[1] + k * d[1]))  # on the line through p and x
        if not sets:
            continue
        text = sets_text(sets)
        expected = [label(decimals(text), y) for y in points]
        assert [a["label"] for a in cli_labels(tmp_path, text, points)["at"]] == expected, (text, points)
        differ += expected != [label(doubles(text), y) for y in points]
    assert differ >= 3  # 3 of these 8 cases are decided differently for the doubles


# ---------------------------------------------------------------------------------------------
# The one-shot path of query (src/mechanics/one_shot.cpp) on cleared values beyond the doubles.

def test_wheels_of_cleared_values_beyond_the_doubles(tmp_path):
    """Wheels whose normals meet at the centre of mass, every coordinate a decimal of 18 places:
    cleared of their denominators the generators are integers beyond 2^53, which the one-shot path
    of query takes as their roundings with an error bound (approx_of). query and modes agree with
    the oracle on every wheel. (Not a test of that bound: with the bound set to 0 these wheels, and
    80 more, still agree; the operations' own bounds cover the inputs' rounding here.)"""
    from test_decimals_oracle import cli_modes, cli_query, scene_text

    rng = random.Random(18)
    for _ in range(6):
        c = (random_decimal(rng, -1, 1, 18), random_decimal(rng, -1, 1, 18))
        contacts = []
        while len(contacts) < 3:
            p = (random_decimal(rng, -2, 2, 18), random_decimal(rng, -2, 2, 18))
            contacts.append((p, (c[0] - p[0], c[1] - p[1]), Fraction(0)))
        text = scene_text((Fraction(1), c, Fraction("0.3")), contacts)
        doc = json.loads(text, parse_float=Fraction, parse_int=Fraction)
        assert any(abs(x * 10 ** 18) > 2 ** 53 for k in doc["contacts"] for x in k["point"])
        w = [Fraction(0), Fraction(0), Fraction(1)]
        assert cli_query(tmp_path, text, w) == oracle.query(doc, w), text
        assert cli_modes(tmp_path, text) == oracle.modes(doc), text


# ---------------------------------------------------------------------------------------------
# Contacts found from polygons with decimal vertices.

RAMP = [(D(0), D("0.1")), (D(3), D("1.3")), (D(3), D(0)), (D(0), D(0))]  # its top edge: y = 0.1 + 0.4 x
BLOCK = [(D("0.5"), D("0.3")), (D("1.5"), D("0.7")), (D("1.3"), D("1.2")), (D("0.3"), D("0.8"))]  # on it


def polygon_scene(mu, com):
    def pts(p):
        return "[" + ",".join(f"[{dec(x)},{dec(y)}]" for x, y in p) + "]"
    return (f'{{"body":{{"mass":1,"com":[{dec(com[0])},{dec(com[1])}],"inertia":0.1,"polygon":{pts(BLOCK)}}},'
            f'"obstacles":[{{"polygon":{pts(RAMP)}}}],"mu":{dec(mu)}}}')


def test_block_on_a_decimal_ramp_at_the_friction_threshold(tmp_path):
    """A block drawn on the ramp y = 0.1 + 0.4 x with mu = 0.4 = the slope: gravity lies on the
    edge of each friction cone (n + 0.4 t is vertical for n = (-0.4, 1)), so the block is exactly at
    the threshold of sliding. The contacts found are the block's bottom vertices as typed, with the
    ramp's normal (-0.4, 1) exactly; the oracle answers for those contacts, written by hand."""
    com = (D("0.8"), D("0.75"))
    mu = D("0.4")
    path = tmp_path / "ramp.json"
    path.write_text(polygon_scene(mu, com))
    found = cli("modes", path, "--json")["found_contacts"]
    assert [(c["point"], c["normal"]) for c in found] == [([0.5, 0.3], [-0.4, 1]), ([1.5, 0.7], [-0.4, 1])]
    contacts = [{"point": [x, y], "normal": [D("-0.4"), D(1)], "mu": mu} for x, y in BLOCK[:2]]
    doc = {"body": {"mass": D(1), "com": list(com), "inertia": D("0.1")}, "contacts": contacts}
    g = D("9.81")
    w = [D(0), -g, -com[0] * g]  # gravity through the centre of mass
    expected = oracle.query(doc, w)
    assert {"ff"} < expected  # on the threshold: sticking and sliding down both hold it
    got = cli("query", path, "--gravity", "0", "-9.81", "--json")["modes"]
    assert set(got) == expected
    assert set(cli("modes", path, "--json")["modes"]) == oracle.modes(doc)


def test_push_band_ends_give_their_exact_value(tmp_path):
    """query --push --json: an end that is not a double also comes as "p/q" in lowest terms (the
    threshold mu m g = 0.3 x 1 x 9.81 of the block, by hand); ends that are doubles do not."""
    from test_decimals_oracle import THRESHOLDS, block

    mu, m, h, g = THRESHOLDS[0]
    path = tmp_path / "block.json"
    path.write_text(block(mu, m, h))
    bands = cli("query", path, "--gravity", "0", "-9.81", "--push", "0", "0", "1", "0", "--json")["bands"]
    ends = [(b["from"], b.get("from_exact")) for b in bands] + [(b["to"], b.get("to_exact")) for b in bands]
    assert (float(mu * m * g), "2943/1000") in ends
    for value, text in ends:
        if text is not None:  # the exact value, of which the number is the rounding
            assert Fraction(text) != Fraction(value) and float(Fraction(text)) == value
    integer = cli("query", path, "--gravity", "0", "-10", "--push", "0", "0", "1", "0", "--json")["bands"]
    assert all("from_exact" not in b and "to_exact" not in b for b in integer if b["from"] in (0, 3))


def test_python_push_line_bands_carry_the_exact_end(tmp_path):
    """momentlab.push_line: mu = 0.3 read as typed, gravity the double nearest 9.81; the sliding
    threshold is mu m g = (3/10) x 1 x double(9.81) exactly, which is not a double: the Band has it
    as to_exact (a Fraction, computed here from the typed numbers), and .to is its rounding."""
    import momentlab as ml
    from test_decimals_oracle import THRESHOLDS, block

    mu, m, h, _ = THRESHOLDS[0]
    path = tmp_path / "block.json"
    path.write_text(block(mu, m, h))
    bands = ml.push_line(ml.Scene.from_file(path), (0, 0), (1, 0), gravity=(0, -9.81))
    threshold = mu * m * Fraction(9.81)
    assert float(threshold) != threshold
    ends = [(b.to, b.to_exact) for b in bands] + [(b.from_, b.from_exact) for b in bands]
    assert (float(threshold), threshold) in ends
    for value, exact in ends:
        assert exact is None or (exact != Fraction(value) and float(exact) == value)


FLOOR_BLOCK = """{"body": {"mass": 1, "com": [1, 0.5], "inertia": 0.5, "polygon": [[0, 0], [2, 0], [2, 1], [0, 1]]},
 "contacts": [{"point": [0, 0], "normal": [0, 1], "mu": 0.1}, {"point": [2, 0], "normal": [0, 1], "mu": 0.1}]}"""
# The exact decimal of the double nearest 0.1: a finger mu a hair above the floor's 1/10.
DOUBLE_OF_TENTH = format(Fraction(0.1).numerator / Fraction(0.1).denominator, ".60f").rstrip("0")


def sliding_finger_on_top(cases):
    """The cases of the top edge (edge 2, from (2, 1) to (0, 1)) with a sliding finger (l, r)."""
    return {c["slip"]: c for c in cases if c["feature"] == "edge 2" and c["slip"] in ("l", "r")}


def test_plan_push_reads_the_finger_mu_as_typed(tmp_path):
    """plan push --mu: a finger sliding on the top of a block whose floor has mu = 0.1 pushes along
    n -+ mu_p t, (-+mu_p, -1). The floor holds it (goal ff: zero acceleration, contact forces in
    their cones) exactly when mu_p <= 1/10 and its line meets the floor in [0, 2] (by hand). Typed
    0.1, mu_p is 1/10: the push is on the edge of the floor's cones, verdict "boundary", from every
    touch point x with x -+ 1/10 in [0, 2] (slip l: (2, 1) to (0.1, 1)). The double nearest 0.1 is
    1/10 + 5.55e-18: verdict "no"."""
    path = tmp_path / "block.json"
    path.write_text(FLOOR_BLOCK)
    assert Fraction(DOUBLE_OF_TENTH) == Fraction(0.1) and Fraction(0.1) > Fraction(1, 10)
    typed = sliding_finger_on_top(cli("plan", "push", path, "--goal", "ff", "--mu", "0.1", "--json")["cases"])
    assert {k: c["verdict"] for k, c in typed.items()} == {"l": "boundary", "r": "boundary"}, typed
    assert typed["l"]["touch"] == [[[2, 1], [pytest.approx(0.1, abs=1e-15), 1]]]
    assert typed["r"]["touch"] == [[[pytest.approx(1.9, abs=1e-15), 1], [0, 1]]]
    double = sliding_finger_on_top(cli("plan", "push", path, "--goal", "ff", "--mu", DOUBLE_OF_TENTH, "--json")["cases"])
    assert {k: c["verdict"] for k, c in double.items()} == {"l": "no", "r": "no"}, double


def test_python_plan_push_mu_exact_or_binary(tmp_path):
    """momentlab.plan_push: mu as a string, Fraction or Decimal is read exactly (1/10: "boundary"
    for a sliding finger on the top, as above); mu as the float 0.1 is the double ("no")."""
    import decimal
    import momentlab as ml

    path = tmp_path / "block.json"
    path.write_text(FLOOR_BLOCK)
    scene = ml.Scene.from_file(path)
    top = lambda cases: sorted(c.verdict for c in cases if c.feature == "edge 2" and c.slip in "lr")
    for mu in ("0.1", Fraction(1, 10), decimal.Decimal("0.1")):
        assert top(ml.plan_push(scene, "ff", mu=mu)) == ["boundary", "boundary"], mu
    assert top(ml.plan_push(scene, "ff", mu=0.1)) == ["no", "no"]


def test_python_never_reads_a_tiny_exact_number_as_zero():
    """A Decimal below exact reading's exponent range, or a long double below the doubles', in
    a list read exactly (beside a Fraction), is refused, never taken as 0 (the torque 1e-200000
    would otherwise give the zero wrench's modes); Decimal('sNaN') is refused naming the field."""
    import decimal
    import numpy as np
    import momentlab as ml

    scene = ml.Scene(body={"mass": 1, "com": [0, 1], "inertia": 1},
                     contacts=[{"point": [-1, 0], "normal": [0, 1], "mu": 0.5},
                               {"point": [1, 0], "normal": [0, 1], "mu": 0.5}])
    for w in ([0, -1, decimal.Decimal("1e-200000")], [np.longdouble("1e-4000"), Fraction(0), 0]):
        with pytest.raises(ValueError, match="too small for a double"):
            ml.query(scene, w)
    with pytest.raises(ValueError, match="wrench"):
        ml.query(scene, [decimal.Decimal("sNaN"), Fraction(0), 0])


# ---------------------------------------------------------------------------------------------
# Planners: a compliance centre, a centre of mass and a load typed with decimals. The block on
# the floor (mass 1, contacts (0, 0) and (1, 0), normals up, mu 0.3); the oracle reads its text
# as Fractions and decides by exact LPs whether a mode's set holds a wrench.

PLAN_BLOCK = ('{"body":{"mass":1,"com":[%s,%s],"inertia":0.1,"polygon":[[0,0],[1,0],[1,0.5],[0,0.5]]},'
              '"contacts":[{"point":[0,0],"normal":[0,1],"mu":0.3},{"point":[1,0],"normal":[0,1],"mu":0.3}]}')


def rotated(d, angle):
    """The exact direction d turned by the double `angle` (its cosine and sine read exactly)."""
    import math
    c, s = Fraction(math.cos(angle)), Fraction(math.sin(angle))
    return (c * d[0] - s * d[1], s * d[0] + c * d[1])


def test_comply_centre_is_read_as_typed(tmp_path):
    """The centre (0.775, 0.75) lies on the line of force (-0.3, 1) through (0.925, 0.25) in
    decimal: the oracle finds that force of E_rr through it and no force 1e-7 rad to either side
    (a knife edge), so the verdict is "boundary" with that one direction: from the CLI's --centre
    and from Python's strings, Fractions and Decimals. As floats the centre is another point:
    Python answers for it, and the oracle agrees that the force is not in E_rr there."""
    import decimal
    import math
    import momentlab as ml

    text = PLAN_BLOCK % ("0.5", "0.25")
    path = tmp_path / "block.json"
    path.write_text(text)
    scene = oracle.exact_scene(json.loads(text, parse_float=Fraction, parse_int=Fraction))
    centre = (Fraction("0.775"), Fraction("0.75"))
    d = (Fraction(3, 10), Fraction(-1))  # the sense E_rr holds (the body pushed down and left)
    assert oracle.produces(scene, "rr", oracle.wrench_at(centre, d))
    assert not oracle.produces(scene, "rr", oracle.wrench_at(centre, (-d[0], -d[1])))
    for side in (-1e-7, 1e-7):
        assert not oracle.produces(scene, "rr", oracle.wrench_at(centre, rotated(d, side)))
    angle = math.atan2(-1, 0.3)
    plan = cli("plan", "comply", path, "--goal", "rr", "--centre", "0.775", "0.75", "--json")["centre"]
    assert (plan["verdict"], plan["intervals"]) == ("boundary", [[angle, angle]])
    analysis = ml.analyze(ml.Scene.from_file(path))
    for typed in (["0.775", "0.75"], [Fraction("0.775"), Fraction("0.75")], [decimal.Decimal("0.775"), "0.75"]):
        got = ml.plan_comply(analysis, "rr", typed).centre
        assert (got.verdict, got.intervals) == ("boundary", [(angle, angle)]), typed
        assert got.point_exact == centre and plan["point_exact"] == ["31/40", "3/4"]  # echoed as read
    binary = ml.plan_comply(analysis, "rr", [0.775, 0.75]).centre
    assert binary.verdict == "fails" and binary.intervals == [] and binary.point_exact is None
    centre_binary = (Fraction(0.775), Fraction(0.75))
    assert not any(oracle.produces(scene, "rr", oracle.wrench_at(centre_binary, v)) for v in (d, (-d[0], -d[1])))


def test_tilt_uses_the_centre_of_mass_as_typed(tmp_path):
    """Quasi-statically E_rr is the forces (0.3, -1) between the lines through the contacts; the
    centre of mass (0.79, 0.7) is on the one through (1, 0) in decimal (0.79 + 0.3 0.7 = 1), so
    gravity along (0.3, -1) gives rr, as the oracle's LP finds; the same numbers as doubles put
    the centre of mass outside the strip: no tilt, and the oracle agrees."""
    import math
    import momentlab as ml

    text = PLAN_BLOCK % ("0.79", "0.7")
    path = tmp_path / "block.json"
    path.write_text(text)
    g = (Fraction(3, 10), Fraction(-1))
    for doc, holds in ((json.loads(text, parse_float=Fraction, parse_int=Fraction), True), (json.loads(text), False)):
        com = tuple(oracle.exact(c) for c in doc["body"]["com"])
        assert ("rr" in quasi_static_answer(doc, oracle.wrench_at(com, g))) == holds
    angle = math.atan2(-1, 0.3)
    assert cli("plan", "tilt", path, "--goal", "rr", "--quasi-static", "--json")["intervals"] == [[angle, angle]]
    doc = json.loads(text)
    binary = ml.Scene(body=doc["body"], contacts=doc["contacts"])
    assert ml.plan_tilt(ml.analyze(binary, quasi_static=True), "rr").intervals == []


@pytest.mark.parametrize("gravity", ["9.8", "9.806", "9.78"])
def test_planner_loads_are_exact(tmp_path, gravity):
    """A horizontal force through the centre of mass keeps ff up to mu m g (both contacts press,
    the friction limit is mu times their sum; tipping needs 0.5 m g / 0.25 = 2 m g): for g = 9.8
    that is 2.94 exactly. The plans' magnitudes with --gravity typed are mu m g correctly rounded
    (2.94), not the value of the rounded load (2.9400000000000004): comply through the centre of
    mass, from the CLI and from Python's strings."""
    import momentlab as ml

    path = tmp_path / "block.json"
    path.write_text(PLAN_BLOCK % ("0.5", "0.25"))
    end = float(Fraction(3, 10) * Fraction(gravity))
    assert end != float(Fraction(3, 10) * Fraction(float(Fraction(gravity))))  # the rounded load's end differs
    plan = cli("plan", "comply", path, "--goal", "ff", "--centre", "0.5", "0.25", "--gravity", "0", f"-{gravity}", "--json")
    exact = Fraction(3, 10) * Fraction(gravity)  # not a double: also given exactly, "p/q"
    assert plan["centre"]["best"] == 0.0 and plan["centre"]["best_magnitudes"] == {"from": 0.0, "to": end, "to_exact": str(exact)}
    got = ml.plan_comply(ml.analyze(ml.Scene.from_file(path)), "ff", ["0.5", "0.25"], gravity=["0", f"-{gravity}"]).centre
    assert (got.best_magnitudes.from_, got.best_magnitudes.to, got.best_magnitudes.to_exact) == (0.0, end, exact)
    assert got.best_magnitudes.from_exact is None  # 0 is a double


def test_python_labels_at_a_typed_point():
    """Labels.at: the force (-0.3, 1) through (1, 0) has moment 0 about (0.79, 0.7) in decimal
    (the oracle's cross product is 0: "+-", both labels); as floats the point is off its line, on
    the side the oracle's exact moment gives."""
    from decimal import Decimal
    import momentlab as ml

    labels = ml.labels('{"sets": [{"type": "force", "point": [1, 0], "direction": [-0.3, 1]}]}')
    force = (Fraction("-0.3"), Fraction(1))

    def oracle_label(point):
        m = oracle.cross((1 - point[0], -point[1]), force)  # (q - p) x f, q = (1, 0) on the force's line
        return "+-" if m == 0 else "+" if m > 0 else "-"

    assert oracle_label((Fraction("0.79"), Fraction("0.7"))) == "+-"
    for typed in (["0.79", "0.7"], [Fraction("0.79"), Fraction("0.7")], [Decimal("0.79"), "0.7"]):
        assert labels.at(typed) == "+-", typed
    # The set of the file is the decimal force; the floats' point is the double nearest each.
    binary = oracle_label((Fraction(0.79), Fraction(0.7)))
    assert binary != "+-" and labels.at([0.79, 0.7]) == binary


def test_python_find_contacts_reads_polygons_as_typed():
    """A vertex at (0.1, 0.7) lies on the obstacle's edge from (0, 0) to (1, 7) in decimal (the
    oracle's cross product is 0), so it touches at distance 0; as floats it is 3/2^55 off the
    edge's line, outside the obstacle: no contact. A decimal polygon 0.1 into the obstacle is
    refused, as a scene's is, naming the arguments."""
    from decimal import Decimal
    import momentlab as ml

    obstacle = [[0, 0], [1, 7], [-1, 7]]
    typed = [["0.1", "0.7"], ["1.1", "0.7"], ["1.1", "1.7"]]
    assert oracle.cross((Fraction(1), Fraction(7)), (Fraction("0.1"), Fraction("0.7"))) == 0
    assert oracle.cross((Fraction(1), Fraction(7)), (Fraction(0.1), Fraction(0.7))) < 0  # right of the edge: outside
    for number in (Decimal, Fraction):
        found = ml.find_contacts([[number(x) for x in v] for v in typed], [obstacle], distance=0, mu=number("0.3"))
        assert [(c.point, c.mu) for c in found] == [([0.1, 0.7], 0.3)]
        assert found[0].normal[0] / found[0].normal[1] == -7.0  # the edge's inward normal (7, -1)
    assert ml.find_contacts([[float(x) for x in v] for v in typed], [obstacle], distance=0) == []
    into = [[Decimal(x) - Decimal("0.1") if i == 0 else Decimal(x) for i, x in enumerate(v)] for v in typed]
    with pytest.raises(ValueError, match=r"^obstacles\[0\]: overlaps the body polygon \(body\)"):
        ml.find_contacts(into, [obstacle], distance=0)


def test_python_refuses_bools_and_numbers_too_small_for_a_double():
    """A bool is not a number (numpy would read True as 1), and a typed number that rounds to 0
    is refused as in files and options (docs/reliability.md): never taken as 0."""
    import numpy as np
    import momentlab as ml

    analysis = ml.analyze(ml.Scene.from_json(PLAN_BLOCK % ("0.5", "0.25")))
    for gravity in ([True, -1], [0, np.bool_(True)], np.array([True, False]), ["0", False]):
        with pytest.raises(ValueError, match="^gravity: expected (numbers, got a bool|real numbers, not an array of dtype bool)"):
            ml.plan_comply(analysis, "ff", gravity=gravity)
    with pytest.raises(ValueError, match="^centre: expected numbers, got a bool"):
        ml.plan_comply(analysis, "ff", ["0.5", False])
    for tiny in (["1e-400", -1], [Fraction(1, 10 ** 400), -1], ["1e-999999999", -1]):  # (the last: beyond parse's exponents)
        with pytest.raises(ValueError, match="^gravity: a number is too small for a double"):
            ml.plan_comply(analysis, "ff", gravity=tiny)
    with pytest.raises(ValueError, match="^gravity: expected finite numbers"):
        ml.plan_comply(analysis, "ff", gravity=["1e999999999", -1])
    with pytest.raises(ValueError, match="^gravity: expected numbers$"):
        ml.plan_comply(analysis, "ff", gravity=["0x1p3", -1])


def test_python_scene_with_decimals_takes_numpy_scalars_and_names_bad_values():
    """A scene holding a Decimal is read exactly; numpy scalars beside it are their values, and
    a NaN or an infinity is refused naming its field, as in a scene of floats."""
    from decimal import Decimal
    import numpy as np
    import momentlab as ml

    body = {"mass": np.int64(1), "com": [np.float32(0.5), 0.25], "inertia": Decimal("0.1")}
    scene = ml.Scene(body=body, contacts=[{"point": [0, 0], "normal": [0, 1], "mu": np.float64(0.5)}])
    assert scene.contacts[0].mu == 0.5 and scene.body["mass"] == 1.0
    for bad in (float("nan"), np.float64("inf")):
        with pytest.raises(ValueError, match=r"^\$\.contacts\[0\]\.mu: expected a finite number"):
            ml.Scene(body=body, contacts=[{"point": [0, 0], "normal": [0, 1], "mu": bad}])


def test_push_reads_the_outline_as_typed(tmp_path):
    """The frictionless block spanning x 0.1 .. 1.1 (found by review): pushing its vertex 2 at
    (1.1, 0.5) straight down is in E_rr in decimal (the oracle's LP), a knife edge: "boundary",
    as for the same block at x 0 .. 1. Read as doubles the vertex is elsewhere and the case
    fails ("no"), as it did before the outline was read as typed."""
    text = ('{"body":{"mass":1,"com":[0.6,0.25],"inertia":0.1,"polygon":[[0.1,0],[1.1,0],[1.1,0.5],[0.1,0.5]]},'
            '"contacts":[{"point":[0.1,0],"normal":[0,1],"mu":0},{"point":[1.1,0],"normal":[0,1],"mu":0}]}')
    path = tmp_path / "b1.json"
    path.write_text(text)
    scene = oracle.exact_scene(json.loads(text, parse_float=Fraction, parse_int=Fraction))
    assert oracle.produces(scene, "rr", oracle.wrench_at((Fraction("1.1"), Fraction("0.5")), (Fraction(0), Fraction(-1))))
    out = cli("plan", "push", path, "--goal", "rr", "--vertex", "2", "--slip", "f", "--json")
    assert [c["verdict"] for c in out["cases"]] == ["boundary"]


def test_python_analysis_takes_wrenches_as_typed():
    """Analysis.query, .verdict and .margins read a wrench of Fractions, Decimals or strings as
    typed: the threshold push mu m g (0.3 · 1 · 9.81 = 2.943) is ambiguous between ff and rr in
    decimal (the oracle's LP on the decimal scene); a batch holding one typed row answers that row
    as one wrench. Bools are refused (numpy would read True as 1)."""
    from decimal import Decimal
    import numpy as np
    import momentlab as ml
    from test_decimals_oracle import THRESHOLDS, as_decimals, block

    mu, m, h, g = THRESHOLDS[0]
    text = block(mu, m, h)
    w = [mu * m * g, -m * g, -m * g / 2]
    expected = oracle.query(as_decimals(text), w)
    assert {"ff", "rr"} <= expected
    analysis = ml.analyze(ml.Scene.from_json(text))
    for typed in (w, [Decimal("2.943"), Decimal("-9.81"), Decimal("-4.905")], ["2.943", "-9.81", "-4.905"]):
        assert set(analysis.query(typed)) == expected, typed
        assert analysis.verdict(typed) == oracle.verdict(len(expected))
        assert set(analysis.margins(typed).inside) == expected
    floats = [float(x) for x in w]
    batch = analysis.query([floats, ["2.943", "-9.81", "-4.905"]])
    assert batch.shape == (2, len(analysis.modes))
    assert {analysis.modes[k] for k in np.flatnonzero(batch[1])} == expected
    assert {analysis.modes[k] for k in np.flatnonzero(batch[0])} == set(analysis.query(floats))
    assert list(analysis.verdict([floats, w])) == [analysis.verdict(floats), analysis.verdict(w)]
    for bad in ([True, -9.81, -4.905], np.array([1.0, 2.0, 3.0]) > 0, [np.bool_(False), 1, 2], [[1, 2, 3], [1, True, 3]]):
        with pytest.raises(ValueError, match="^wrench: expected numbers, got a bool"):
            analysis.query(bad)
        with pytest.raises(ValueError, match="^wrench: expected numbers, got a bool"):
            analysis.verdict(bad)
    with pytest.raises(ValueError, match="^wrench: expected numbers, got a bool"):
        analysis.margins([1, True, 3])


def test_python_contacts_keep_typed_values_and_refuse_bools():
    """ml.contacts keeps Fractions and Decimals as given, so a scene of them is decimal: the
    threshold push is ambiguous as in the oracle's decimal scene (floats give one side); a bool mu
    or point is refused."""
    from decimal import Decimal
    import momentlab as ml
    from test_decimals_oracle import THRESHOLDS, as_decimals, block

    mu, m, h, g = THRESHOLDS[0]
    w = [mu * m * g, -m * g, -m * g / 2]
    expected = oracle.query(as_decimals(block(mu, m, h)), w)
    body = ml.Body(mass=1, com=[Fraction(1, 2), Decimal("0.25")], inertia=Decimal("0.1"))
    for mus in (Decimal("0.3"), [Fraction(3, 10), Decimal("0.3")]):
        cs = ml.contacts([[0, 0], [1, 0]], [[0, 1], [Fraction(0), Decimal(1)]], mu=mus)
        assert set(ml.analyze(ml.Scene(body=body, contacts=cs)).query(w)) == expected
    floats = ml.contacts([[0, 0], [1, 0]], [[0, 1], [0, 1]], mu=0.3)
    assert len(ml.analyze(ml.Scene(body=body, contacts=floats)).query([float(x) for x in w])) == 1
    for kwargs in ({"mu": True}, {"mu": [0.3, False]}, {"mu_kinetic": True}):
        with pytest.raises(ValueError, match="expected numbers, got a bool"):
            ml.contacts([[0, 0], [1, 0]], [[0, 1], [0, 1]], **kwargs)
    with pytest.raises(ValueError, match="^points: expected numbers, got a bool"):
        ml.contacts([[0, True], [1, 0]], [[0, 1], [0, 1]])
    with pytest.raises(ValueError, match=r"^normals: expected shape \(2, 2\)"):
        ml.contacts([[0, 0], [1, 0]], [[0, Decimal(1)]])
    for bad in (Decimal("NaN"), Decimal("sNaN"), Decimal("-Infinity")):
        with pytest.raises(ValueError, match="^mu: expected finite numbers"):
            ml.contacts([[0, 0], [1, 0]], [[0, 1], [0, 1]], mu=bad)


def test_python_force_sets_and_cones_take_typed_numbers():
    """The friction cone at (0.1, 0) with normal (0, 1) and mu 0.3 has the edge force (0.3, 1),
    whose wrench is (0.3, 1, 0.1 · 1 - 0 · 0.3) = (0.3, 1, 0.1) in decimal (the oracle's
    wrench_at): on the cone's boundary, not inside; a tangential force a hair above mu is outside.
    The same for a force ray through a decimal point."""
    from decimal import Decimal
    import momentlab as ml

    p, f = (Fraction("0.1"), Fraction(0)), (Fraction("0.3"), Fraction(1))
    w = list(oracle.wrench_at(p, f))
    assert w == [Fraction("0.3"), 1, Fraction("0.1")]
    hair = [w[0] + Fraction(1, 10 ** 30), w[1], w[2]]
    for mu in (Fraction(3, 10), Decimal("0.3"), "0.3"):
        cone = ml.friction_cone([Decimal("0.1"), 0], [0, 1], mu)
        assert cone.contains(w) and not cone.in_relative_interior(w)
        assert cone.contains(["0", "1", "0.1"])  # the normal force
        assert cone.in_relative_interior([0, 1, Fraction("0.1")])
        assert not cone.contains(hair)
    ray = ml.force(["0.1", "0"], ["0.3", "1"])
    assert ray.contains(w) and not ray.contains(hair) and not ray.contains([Fraction("0.3"), 1, 0.1])
    assert ml.line_of_force([Fraction(1, 10), 0], ["0.3", 1]).contains([-x for x in w])
    assert ml.forces_through_point(["0.1", 0]).contains([5, 7, Fraction("0.7")])  # 0.1 · 7
    assert not ml.forces_through_point([0.1, 0]).contains([5, 7, Fraction("0.7")])  # the double 0.1 is not 1/10
    with pytest.raises(ValueError, match="^mu: expected a number, got bool"):
        ml.friction_cone([0, 0], [0, 1], True)
    with pytest.raises(ValueError, match="direction must be non-zero"):
        ml.force(["0.1", 0], [Fraction(0), "0"])
    with pytest.raises(ValueError, match="^mu: expected a finite mu >= 0"):
        ml.friction_cone([0, 0], [0, 1], "-0.1")


@pytest.mark.parametrize("com_y", ["1.2", "1.23", "1.37"])
def test_push_touch_ends_are_the_exact_end_correctly_rounded(tmp_path, com_y):
    """Review of issue 46: a finger sliding (r) on the top of a unit block on a frictionless floor,
    com (0.5, y): the force (1, -2) of the finger's friction edge at (x, 1) gives rr from x =
    (y - 1) / 2 on (the oracle's LP: rr and rs at that point, rs alone just before it, rr just
    after). The touch segment printed ends at that point's nearest double (0.1, 0.115, 0.185), not
    at a rounded intersection a few ulps off (0.09999999999999998 lay outside E_rr)."""
    import momentlab as ml

    text = ('{"body":{"mass":1,"com":[0.5,%s],"inertia":0.1,"polygon":[[0,0],[1,0],[1,1],[0,1]]},'
            '"obstacles":[{"polygon":[[-2,-1],[3,-1],[3,0],[-2,0]]}]}' % com_y)
    doc = {"body": {"mass": 1, "com": [Fraction("0.5"), Fraction(com_y)], "inertia": Fraction("0.1")},
           "contacts": [{"point": [0, 0], "normal": [0, 1], "mu": 0}, {"point": [1, 0], "normal": [0, 1], "mu": 0}]}
    scene = oracle.exact_scene(doc)
    end = (Fraction(com_y) - 1) / 2
    at = lambda x: oracle.query(scene, oracle.wrench_at((x, Fraction(1)), (Fraction(1), Fraction(-2))))
    assert at(end) == {"rr", "rs"} and at(end - Fraction(1, 10 ** 12)) == {"rs"} and at(end + Fraction(1, 10 ** 12)) == {"rr"}
    path = tmp_path / "block.json"
    path.write_text(text)
    cases = cli("plan", "push", path, "--goal", "rr", "--edge", "2", "--slip", "r", "--json")["cases"]
    assert [c["touch"] for c in cases] == [[[[1.0, 1.0], [float(end), 1.0]]]]
    assert cases[0]["unique_touch"] == cases[0]["touch"]
    python = [c for c in ml.plan_push(ml.Scene.from_json(text), "rr") if c.feature == "edge 2" and c.slip == "r"]
    assert [[list(p) for p in seg] for seg in python[0].touch] == [[[1.0, 1.0], [float(end), 1.0]]]


def test_malformed_json_messages_are_one_short_ascii_line(tmp_path):
    """Review of issue 46: the JSON library's "last read" text cut a non-ASCII character in two
    (Python raised a ValueError with no message; the CLI wrote bytes that are not UTF-8), and a
    number of 10^5 digits was echoed whole, at "$". Now one ASCII line of at most a few hundred
    bytes, the number named by its path."""
    import subprocess
    import momentlab as ml
    from conftest import CLI

    for bad, at in (('{"contacts":[{"point":[0,0],"normal":[0,1],"mu":\u00e9}]}', "$: malformed JSON"),
                    ('{"contacts":[{"point":[0,0],"normal":[0,1],"mu":\u00a01}]}', "$: malformed JSON"),
                    ('{"contacts":[{"point":[0,0],"normal":[0,1],"mu":1' + "0" * 100000 + '}]}', "$.contacts[0].mu: a number beyond")):
        with pytest.raises(ValueError) as e:
            ml.Scene.from_json(bad)
        message = str(e.value)
        assert message.startswith(at) and message.isascii() and len(message) < 400, message[:500]
        path = tmp_path / "bad.json"
        path.write_text(bad, encoding="utf-8")
        r = subprocess.run([CLI, "modes", str(path)], capture_output=True)
        assert r.returncode == 2 and r.stderr.decode("ascii").strip() == "momentlab: " + message


def test_zero_with_any_exponent_and_control_bytes_in_json_text():
    """Re-check of issue 46's review: "0e-999999999" is 0 in every front end (Python refused it as
    too small while the CLI and files read 0), and a NUL in JSON text given as a string is refused
    as the CLI refuses it in a file (the JSON library took it as the text's end)."""
    import momentlab as ml

    analysis = ml.analyze(ml.Scene.from_json(PLAN_BLOCK % ("0.5", "0.25")))
    assert analysis.query(["0e-999999999", -1, "-0.5"]) == analysis.query([0, -1, -0.5])
    valid = PLAN_BLOCK % ("0.5", "0.25")
    for text, offset in ((valid + "\x00garbage", len(valid)), (valid[:10] + "\x00" + valid[10:], 10)):
        with pytest.raises(ValueError, match=rf"^\$: not a JSON document: a control byte, byte 0x00 at offset {offset}$"):
            ml.Scene.from_json(text)
    with pytest.raises(ValueError, match=r"^\$\.body\.mass: duplicate key"):  # an error before the NUL comes first
        ml.Scene.from_json('{"body": {"mass": 1, "mass": 2}}\x00')

