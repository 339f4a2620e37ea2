"""The planners (tilt, comply, push; docs/planning.md) against the exact oracle of
tests/python/oracle.py, which shares no code with momentlab: on random scenes with dyadic numbers,
every arc a plan calls unique must give the goal alone at its middle, every shared arc the goal
and another mode, every direction outside the plan not the goal; compliance verdicts must agree
with the centre's label; and the plans of a scene moved by exact transforms (a quarter turn, a
dyadic translation, a mirror that swaps l and r) must be the moved plans."""

import json
import math
import random
from fractions import Fraction

import pytest

import momentlab as ml
import oracle

SEEDS = range(24)
NARROW = 1e-9  # arcs narrower than this are not sampled (the rounded middle may leave them)


def analysis_of(doc):
    return ml.analyze(ml.Scene.from_json(json.dumps(doc)))


class Oracle:
    def __init__(self, doc):
        self.scene = oracle.exact_scene(doc)
        self.modes = sorted(oracle.modes(self.scene))

    def answer(self, point, angle):
        """The modes of the unit force along `angle` (rounded to doubles, read exactly) through point."""
        f = (Fraction(math.cos(angle)), Fraction(math.sin(angle)))
        p = (oracle.exact(point[0]), oracle.exact(point[1]))
        w = oracle.wrench_at(p, f)
        return {m for m in self.modes if oracle.produces(self.scene, m, w)}


def width(arc):
    return arc[1] - arc[0]


def middle(arc):
    return (arc[0] + arc[1]) / 2


def inside_any(angle, arcs, slack):
    return any(a - slack <= angle <= b + slack for a, b in arcs)


def check_directions(plan, goal, point, o, rng):
    """One plan of directions through `point` (a tilt, or a spring through a centre)."""
    unique, shared, union = plan.get("unique", []), plan.get("shared", []), plan["intervals"]
    assert ("unique" in plan) == bool(union)  # told the modes: split whenever feasible
    for arc in unique:
        if width(arc) > NARROW:
            assert o.answer(point, middle(arc)) == {goal}, (plan, arc)
    for arc in shared:
        if width(arc) > NARROW:
            got = o.answer(point, middle(arc))
            assert goal in got and len(got) > 1, (plan, arc, got)
    for arc in union:
        if width(arc) > NARROW:
            assert goal in o.answer(point, middle(arc)), (plan, arc)
    if union and plan.get("best_unique") and plan["margin"] > NARROW:
        assert o.answer(point, plan["best"]) == {goal}, plan
    for _ in range(3):  # directions away from every arc do not give the goal
        angle = rng.uniform(-math.pi, math.pi)
        if not inside_any(angle, union, 1e-6) and not inside_any(angle + 2 * math.pi, union, 1e-6) and not inside_any(
                angle - 2 * math.pi, union, 1e-6):
            assert goal not in o.answer(point, angle), (plan, angle)


@pytest.mark.parametrize("seed", SEEDS)
def test_tilt_and_comply_against_the_oracle(seed):
    rng = random.Random(1000 + seed)
    doc = oracle.random_scene(rng, 1 + seed % 3)
    o = Oracle(doc)
    a = analysis_of(doc)
    assert set(a.modes) == set(o.modes)
    com = doc["body"]["com"]
    for goal in rng.sample(a.modes, min(3, len(a.modes))):
        check_directions(ml.plan_tilt(a, goal), goal, com, o, rng)
        # A random centre, and the corners of E_goal's labelled regions (on their boundaries,
        # where the knife edges are).
        labels = ml.plan_comply(a, goal)["labels"]
        centres = [[float(oracle._grid(rng, -2, 2, 4)), float(oracle._grid(rng, -2, 2, 4))]]
        centres += [list(v) for sign in ("plus", "minus") for v in labels[sign]["vertices"]][:4]
        for centre in centres:
            plan = ml.plan_comply(a, goal, centre)["centre"]
            # The verdict agrees with the exact label (docs/planning.md): inside a labelled region
            # no offset works, on its boundary only knife edges do.
            if plan["verdict"] == "works":
                assert plan["label"] == "none", plan
            if plan["label"] in ("+", "-", "+-") and plan["intervals"]:
                assert plan["verdict"] == "boundary", plan
            if plan["verdict"] == "fails":
                assert plan["intervals"] == []
            check_directions(plan, goal, centre, o, rng)


def with_box(doc, rng):
    """The scene with a body polygon: a dyadic box about the centre of mass."""
    cx, cy = doc["body"]["com"]
    a, b = float(oracle._grid(rng, 1, 2, 4)), float(oracle._grid(rng, 1, 2, 4))
    doc = json.loads(json.dumps(doc))
    doc["body"]["polygon"] = [[cx - a, cy - b], [cx + a, cy - b], [cx + a, cy + b], [cx - a, cy + b]]
    doc["contact_distance"] = 16  # the random contacts need not lie on the box: the pushes are what is checked
    return doc


@pytest.mark.parametrize("seed", range(12))
def test_push_against_the_oracle(seed):
    rng = random.Random(2000 + seed)
    doc = with_box(oracle.random_scene(rng, 1 + seed % 3), rng)
    o = Oracle(doc)
    a = analysis_of(doc)
    for goal in rng.sample(a.modes, min(2, len(a.modes))):
        for c in ml.plan_push(a, goal, mu=0.5, ignore_interference=True):
            if c["verdict"] != "feasible":
                continue
            assert "unique" in c and (c["unique"] or c["shared"]), c
            p, angle = c["best"]["point"], c["best"]["direction"]
            got = o.answer(p, angle)
            assert goal in got, (c, got)
            if c["best_unique"]:
                assert got == {goal}, (c, got)
                assert c["unique"]


# Exact transforms: (x, y) -> (-y, x) keeps every letter and turns every direction by pi/2; a
# dyadic translation changes nothing; the mirror (x, y) -> (-x, y) swaps l and r and sends a
# direction t to pi - t.
def transformed(doc, f):
    doc = json.loads(json.dumps(doc))
    b = doc["body"]
    b["com"] = list(f(b["com"], True))
    for c in doc["contacts"]:
        c["point"] = list(f(c["point"], True))
        c["normal"] = list(f(c["normal"], False))
    return doc


def quarter(v, _):
    return (-v[1], v[0])


def shift(v, is_point):
    return (v[0] + 0.375, v[1] - 1.25) if is_point else tuple(v)


def mirror(v, _):
    return (-v[0], v[1])


def swap_lr(letters):
    return letters.translate(str.maketrans("lr", "rl"))


def canon(arcs, turn=lambda t: t, flip=False):
    """Arcs mapped by t -> turn(t) (reversed when `flip`: a mirror turns the other way round), as
    closed arcs (start in [-pi, pi), end) merged where they meet, pieces through pi joined."""
    items = []
    for a, b in arcs:
        x, y = (turn(b), turn(a)) if flip else (turn(a), turn(b))
        start = math.remainder(x, 2 * math.pi)
        if start >= math.pi - 1e-12:
            start -= 2 * math.pi
        items.append([start, start + (y - x)])
    items.sort()
    out = []
    for arc in items:
        if out and arc[0] <= out[-1][1] + 1e-12:
            out[-1][1] = max(out[-1][1], arc[1])
        else:
            out.append(arc)
    if len(out) > 1 and out[-1][1] >= out[0][0] + 2 * math.pi - 1e-12:
        last = out.pop()
        out[0] = [last[0], max(last[1], out[0][1] + 2 * math.pi)]
        out.sort()
    if any(b - a >= 2 * math.pi - 1e-12 for a, b in out):
        return [(-math.pi, math.pi)]  # the whole turn
    return [tuple(x) for x in out]


def same_arcs(a, b):
    return len(a) == len(b) and all(abs(x[0] - y[0]) < 1e-9 and abs(x[1] - y[1]) < 1e-9 for x, y in zip(a, b))


@pytest.mark.parametrize("seed", range(20))
def test_tilt_plans_move_with_exact_transforms(seed):
    rng = random.Random(3000 + seed)
    doc = oracle.random_scene(rng, 1 + seed % 3)
    a = analysis_of(doc)
    for f, turn, letters in ((quarter, lambda t: t + math.pi / 2, lambda m: m), (shift, lambda t: t, lambda m: m),
                             (mirror, lambda t: math.pi - t, swap_lr)):
        moved = analysis_of(transformed(doc, f))
        assert sorted(moved.modes) == sorted(letters(m) for m in a.modes)
        for goal in a.modes:
            p, q = ml.plan_tilt(a, goal), ml.plan_tilt(moved, letters(goal))
            for key in ("intervals", "unique", "shared"):
                want = canon(p.get(key, []), turn, f is mirror)
                got = canon(q.get(key, []))
                assert same_arcs(got, want), (seed, f.__name__, goal, key, p.get(key), q.get(key))


@pytest.mark.parametrize("seed", range(16))
def test_push_line_bands_against_the_oracle(seed):
    """query --push / push_line: inside each band (its middle, or past its start when unbounded)
    the modes of g + lambda u are exactly the band's, by the oracle; the bands tile [0, inf)."""
    rng = random.Random(4000 + seed)
    doc = oracle.random_scene(rng, 1 + seed % 3)
    o = Oracle(doc)
    a = analysis_of(doc)
    gravity = [float(oracle._grid(rng, -2, 2, 2)), float(oracle._grid(rng, -4, 0, 2))]
    point = [float(oracle._grid(rng, -2, 2, 4)), float(oracle._grid(rng, -2, 2, 4))]
    direction = [float(oracle._grid(rng, -2, 2, 4)), float(oracle._grid(rng, -2, 2, 4))]
    if direction == [0.0, 0.0]:
        direction = [1.0, 0.0]
    bands = ml.push_line(a, point, direction, gravity=gravity)
    assert bands[0]["from"] == 0 and bands[-1]["to"] == math.inf
    for prev, band in zip(bands, bands[1:]):
        assert prev["to"] == band["from"] and prev["to_closed"] != band["from_closed"]
    m, com = oracle.exact(doc["body"]["mass"]), [oracle.exact(x) for x in doc["body"]["com"]]
    g = oracle.wrench_at(com, (m * oracle.exact(gravity[0]), m * oracle.exact(gravity[1])))
    u = oracle.wrench_at([oracle.exact(x) for x in point], [oracle.exact(x) for x in direction])
    for band in bands:
        if band["to"] == math.inf:
            lam = Fraction(band["from"]) * 2 + 1
        elif band["to"] - band["from"] > 1e-9 * max(1.0, band["to"]):
            lam = (Fraction(band["from"]) + Fraction(band["to"])) / 2
        else:
            continue
        w = tuple(gi + lam * ui for gi, ui in zip(g, u))
        assert {x for x in o.modes if oracle.produces(o.scene, x, w)} == set(band["modes"]), (doc, band, bands)
