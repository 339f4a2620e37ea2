"""The planners (tilt, comply, push; docs/planning.md) against the exact oracle of
tests/python/oracle.py, which shares no code with momentlab: on random scenes with dyadic numbers,
every arc a plan calls unique must give the goal alone at its middle, every shared arc the goal
and another mode, every direction outside the plan not the goal; compliance verdicts must agree
with the centre's label; and the plans of a scene moved by exact transforms (a quarter turn, a
dyadic translation, a mirror that swaps l and r) must be the moved plans."""

import collections
import json
import math
import random
from fractions import Fraction

import pytest

import momentlab as ml
import oracle

SEEDS = range(24)
DELTA = 1e-7  # how far past an arc's end a probe goes (the printed ends are rounded by ~1e-16)


def analysis_of(doc):
    return ml.analyze(ml.Scene.from_json(json.dumps(doc)))


class Oracle:
    def __init__(self, doc):
        self.scene = oracle.exact_scene(doc)
        self.modes = sorted(oracle.modes(self.scene))

    def answer(self, point, angle):
        """The modes of the unit force along `angle` (rounded to doubles, read exactly) through point."""
        return {m for m in self.modes if oracle.produces(self.scene, m, self.wrench(point, angle))}

    def gives(self, goal, point, angle):
        """Whether the goal's E holds that force (one LP)."""
        return oracle.produces(self.scene, goal, self.wrench(point, angle))

    @staticmethod
    def wrench(point, angle):
        f = (Fraction(math.cos(angle)), Fraction(math.sin(angle)))
        return oracle.wrench_at((oracle.exact(point[0]), oracle.exact(point[1])), f)


def width(arc):
    return arc[1] - arc[0]


def middle(arc):
    return (arc[0] + arc[1]) / 2


def turns(angle):
    return (angle, angle + 2 * math.pi, angle - 2 * math.pi)


def inside_any(angle, arcs, slack):
    """Within `slack` of an arc (slack < 0: at least -slack inside one), the angle taken mod 2 pi."""
    return any(a - slack <= t <= b + slack for t in turns(angle) for a, b in arcs)


def near_an_end(angle, arcs, slack):
    return any(abs(t - end) < slack for t in turns(angle) for arc in arcs for end in arc)


def check_directions(plan, goal, point, o, rng, counts):
    """One plan of directions through `point` (a tilt, or a spring through a centre): the oracle
    at the middle of every arc and DELTA on either side of each of its ends, where the plan says
    what must hold: inside a unique arc the goal alone, inside a shared arc the goal and another,
    inside the union the goal, outside it no goal; and at three random angles away from every
    end. A probe within DELTA / 2 of any end of the plan (arcs narrower than 2 DELTA) is left out
    and counted."""
    unique, shared, union = plan.unique or [], plan.shared or [], plan.intervals
    assert (plan.unique is not None) == bool(union)  # told the modes: split whenever feasible
    ends = unique + shared + union
    probes = {middle(arc) for arc in ends if width(arc) > 2 * DELTA}
    counts["arcs narrower than 2 DELTA"] += sum(width(arc) <= 2 * DELTA for arc in ends)
    probes |= {end + side * DELTA for arc in ends for end in arc for side in (-1, 1)}
    probes |= {rng.uniform(-math.pi, math.pi) for _ in range(3)}
    for angle in sorted(probes):
        if near_an_end(angle, ends, DELTA / 2):
            counts["left out (near an end)"] += 1
            continue
        if inside_any(angle, unique, 0):
            assert o.answer(point, angle) == {goal}, (plan, angle)
            counts["unique"] += 1
        elif inside_any(angle, shared, 0):
            got = o.answer(point, angle)
            assert goal in got and len(got) > 1, (plan, angle, got)
            counts["shared"] += 1
        elif inside_any(angle, union, 0):
            assert o.gives(goal, point, angle), (plan, angle)
            counts["in the union"] += 1
        else:
            assert not o.gives(goal, point, angle), (plan, angle)
            counts["outside"] += 1
    if union and plan.best_unique and plan.margin > DELTA:
        assert o.answer(point, plan.best) == {goal}, plan


def test_tilt_and_comply_against_the_oracle():
    counts = collections.Counter()
    for seed in SEEDS:
        rng = random.Random(1000 + seed)
        doc = oracle.random_scene(rng, 1 + seed % 3)
        o = Oracle(doc)
        a = analysis_of(doc)
        assert set(a.modes) == set(o.modes)
        com = doc["body"]["com"]
        for goal in rng.sample(a.modes, min(2, len(a.modes))):
            check_directions(ml.plan_tilt(a, goal), goal, com, o, rng, counts)
            # A random centre, and the corners of E_goal's labelled regions (on their boundaries,
            # where the knife edges are).
            labels = ml.plan_comply(a, goal).labels
            centres = [[float(oracle._grid(rng, -2, 2, 4)), float(oracle._grid(rng, -2, 2, 4))]]
            centres += [list(v) for sign in ("plus", "minus") for v in getattr(labels, sign).vertices][:2]
            for centre in centres:
                plan = ml.plan_comply(a, goal, centre).centre
                # The verdict agrees with the exact label (docs/planning.md): inside a labelled region
                # no offset works, on its boundary only knife edges do.
                if plan.verdict == "works":
                    assert plan.label == "none", plan
                if plan.label in ("+", "-", "+-") and plan.intervals:
                    assert plan.verdict == "boundary", plan
                if plan.verdict == "fails":
                    assert plan.intervals == []
                check_directions(plan, goal, centre, o, rng, counts)
    print("[planners] directions probed:", dict(counts))
    # Ends probed on both sides, in every kind of arc, and outside.
    assert counts["unique"] >= 200 and counts["shared"] >= 100 and counts["outside"] >= 200, counts
    assert counts["left out (near an end)"] * 20 < sum(counts.values()), counts


def with_box(doc, rng):
    """The scene with a body polygon: a dyadic box about the centre of mass (counter-clockwise)."""
    cx, cy = doc["body"]["com"]
    a, b = float(oracle._grid(rng, 1, 2, 4)), float(oracle._grid(rng, 1, 2, 4))
    doc = json.loads(json.dumps(doc))
    doc["body"]["polygon"] = [[cx - a, cy - b], [cx + a, cy - b], [cx + a, cy + b], [cx - a, cy + b]]
    doc["contact_distance"] = 16  # the random contacts need not lie on the box: the pushes are what is checked
    return doc


def finger_forces(polygon, case, mu):
    """Pushes of the case's W, from the definitions (docs/planning.md): on edge i (inward normal n,
    the edge turned by 90 degrees; t = (n.y, -n.x)) the finger's force is n - mu t (slip r),
    n + mu t (l) or anything between (f); on a convex vertex the normal is any direction between
    its two edges' normals. As (point, force) pairs in exact rationals."""
    kind, index = case.feature.split()
    index = int(index)
    q = [[oracle.exact(x) for x in v] for v in polygon]
    k = len(q)

    def normal(i):
        d = (q[(i + 1) % k][0] - q[i][0], q[(i + 1) % k][1] - q[i][1])
        return (-d[1], d[0])

    slips = {"r": [-1], "l": [1], "f": [-1, 0, 1]}[case.slip]
    m = oracle.exact(mu)

    def forces(n):
        t = (n[1], -n[0])
        return [(n[0] + s * m * t[0], n[1] + s * m * t[1]) for s in slips]

    out = []
    if kind == "edge":
        a, b = q[index], q[(index + 1) % k]
        for w in (Fraction(0), Fraction(1, 4), Fraction(1, 2), Fraction(1)):
            p = (a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]))
            out += [(p, f) for f in forces(normal(index))]
    else:
        n_in, n_out = normal((index - 1) % k), normal(index)
        for w in (Fraction(0), Fraction(1, 2), Fraction(1)):
            n = (n_in[0] + w * (n_out[0] - n_in[0]), n_in[1] + w * (n_out[1] - n_in[1]))
            out += [(q[index], f) for f in forces(n)]
    return out


def test_push_against_the_oracle():
    """Feasible cases: the best push gives the goal (alone when the plan says so). Cases with no
    solution ("no": W meets E_goal only at 0): no push of W gives the goal, for pushes sampled on
    the feature from the definitions. Both kinds counted."""
    counts = collections.Counter()
    for seed in range(12):
        rng = random.Random(2000 + seed)
        doc = with_box(oracle.random_scene(rng, 1 + seed % 3), rng)
        o = Oracle(doc)
        a = analysis_of(doc)
        for goal in rng.sample(a.modes, min(2, len(a.modes))):
            for c in ml.plan_push(a, goal, mu=0.5, ignore_interference=True):
                counts[c.verdict] += 1
                if c.verdict == "no":
                    for p, f in finger_forces(doc["body"]["polygon"], c, 0.5):
                        assert not oracle.produces(o.scene, goal, oracle.wrench_at(p, f)), (c, p, f)
                        counts["pushes of 'no' cases"] += 1
                if c.verdict != "feasible":
                    continue
                assert c.unique is not None and (c.unique or c.shared), c
                p, angle = c.best.point, c.best.direction
                got = o.answer(p, angle)
                assert goal in got, (c, got)
                if c.best_unique:
                    assert got == {goal}, (c, got)
                    assert c.unique
                counts["best pushes"] += 1
    print("[planners] push cases:", dict(counts))
    assert counts["best pushes"] >= 20 and counts["pushes of 'no' cases"] >= 200, counts


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
                want = canon(getattr(p, key) or [], turn, f is mirror)
                got = canon(getattr(q, key) or [])
                assert same_arcs(got, want), (seed, f.__name__, goal, key, getattr(p, key), getattr(q, key))


def test_push_line_bands_against_the_oracle():
    """query --push / push_line: the modes of g + lambda u are exactly the band's, by the oracle,
    at each band's middle (or past its start when unbounded) and at (1 -+ DELTA) times each end
    between bands, on both sides; at the printed end itself they are one of the two bands'
    (the printed end is the exact ratio rounded); the bands tile [0, inf)."""
    counts = collections.Counter()
    for seed in range(32):
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
        assert bands[0].from_ == 0 and bands[-1].to == math.inf
        for prev, band in zip(bands, bands[1:]):
            assert prev.to == band.from_ and prev.to_closed != band.from_closed
        m, com = oracle.exact(doc["body"]["mass"]), [oracle.exact(x) for x in doc["body"]["com"]]
        g = oracle.wrench_at(com, (m * oracle.exact(gravity[0]), m * oracle.exact(gravity[1])))
        u = oracle.wrench_at([oracle.exact(x) for x in point], [oracle.exact(x) for x in direction])

        def modes_at(lam):
            w = tuple(gi + lam * ui for gi, ui in zip(g, u))
            return {x for x in o.modes if oracle.produces(o.scene, x, w)}

        def band_of(lam):
            """The band holding lam at least DELTA / 2 (relative) from its ends, or None."""
            for band in bands:
                lo, hi = Fraction(band.from_), None if band.to == math.inf else Fraction(band.to)
                slack = Fraction(DELTA / 2) * max(lo, 1 if hi is None else hi)
                if lo + slack < lam and (hi is None or lam < hi - slack):
                    return band
            return None

        probes = []
        for band in bands:
            if band.to == math.inf:
                probes.append(Fraction(band.from_) * 2 + 1)
            else:
                probes.append((Fraction(band.from_) + Fraction(band.to)) / 2)
                end = Fraction(band.to)
                probes += [end * (1 - Fraction(DELTA)), end * (1 + Fraction(DELTA))]
                # At the printed end: the modes of a band that starts or ends there (the closed one
                # if the end is exact, else the one on the side it was rounded to).
                touching = [set(b.modes) for b in bands if b.from_ == band.to or b.to == band.to]
                assert modes_at(end) in touching, (doc, band, bands)
                counts["printed ends"] += 1
        for lam in probes:
            band = band_of(lam)
            if band is None:
                counts["left out (band narrower than DELTA)"] += 1
                continue
            assert modes_at(lam) == set(band.modes), (doc, float(lam), band, bands)
            counts["probes"] += 1
    print("[planners] bands:", dict(counts))
    assert counts["probes"] >= 100 and counts["printed ends"] >= 30, counts
