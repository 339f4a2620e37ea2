#!/usr/bin/python3
"""Writes tests/web/oracle_fixtures.json: the answers of the exact oracle of tests/python/oracle.py
(Fractions, no momentlab code) that tests/web/test_module.mjs checks the WebAssembly module against.

For seeded random scenes with dyadic numbers (half of them degenerate: concurrent, parallel,
repeated or opposed normals), each with a box about its centre of mass as the body's polygon:
  * the modes (brute force over {s, f, r, l}^n, an exact LP per prefix);
  * wrenches (random, and built on the boundaries between modes) with the modes whose E holds
    each one, one exact LP per mode;
  * for a few goals, the modes of the unit force along each of 48 angles through the centre of
    mass (the tilt's plane) and through a compliance centre (the spring's);
  * for the goals' pushes with a finger of mu 1/2, pushes of each feature's W sampled from the
    definitions (docs/planning.md), with whether the goal's E holds each one.
Regenerate with `/usr/bin/python3 tests/web/oracle_fixtures.py` (about a minute); never edit
the JSON by hand. tests/python/test_oracle.py checks a sample of it against the oracle again.
"""

import json
import math
import random
import sys
from fractions import Fraction
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "python"))

import oracle  # noqa: E402

SEED = 20261201
SCENES = 24
ANGLES = [k * math.pi / 24 - math.pi + math.pi / 96 for k in range(48)]  # none on an axis
FINGER_MU = 0.5


def with_box(doc, rng):
    """A dyadic box about the centre of mass as the body's polygon (counter-clockwise)."""
    cx, cy = doc["body"]["com"]
    a, b = float(oracle._grid(rng, 1, 2, 4)), float(oracle._grid(rng, 1, 2, 4))
    doc["body"]["polygon"] = [[cx - a, cy - b], [cx + a, cy - b], [cx + a, cy + b], [cx - a, cy + b]]
    doc["contact_distance"] = 16  # the contacts need not lie on the box: the pushes are what is checked
    return doc


def modes_of_force(scene, modes, point, angle):
    """The modes whose E holds the unit force along `angle` (cos and sin as doubles) through point."""
    w = oracle.wrench_at((oracle.exact(point[0]), oracle.exact(point[1])),
                         (Fraction(math.cos(angle)), Fraction(math.sin(angle))))
    return sorted(m for m in modes if oracle.produces(scene, m, w))


def finger_pushes(polygon, mu):
    """For every feature of the convex polygon and every slip, pushes of its W from the
    definitions: on edge i (inward normal n: the edge turned by 90 degrees; t = (n.y, -n.x)) the
    force n - mu t (slip r), n + mu t (l) or between (f) at points of the edge; on vertex i the
    same with any normal between its two edges'. As {feature, slip, pushes: [[px, py, fx, fy]]}
    with exact dyadic numbers."""
    q = [[Fraction(x) for x in v] for v in polygon]
    k = len(q)
    m = Fraction(mu)

    def normal(i):
        d = (q[(i + 1) % k][0] - q[i][0], q[(i + 1) % k][1] - q[i][1])
        return (-d[1], d[0])

    out = []
    for kind in ("edge", "vertex"):
        for i in range(k):
            for slip, sides in (("l", [1]), ("f", [-1, 0, 1]), ("r", [-1])):
                pushes = []
                if kind == "edge":
                    n = normal(i)
                    normals = [n]
                    a, b = q[i], q[(i + 1) % k]
                    points = [(a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]))
                              for w in (Fraction(0), Fraction(1, 4), Fraction(1, 2), Fraction(1))]
                else:
                    n_in, n_out = normal((i - 1) % k), normal(i)
                    normals = [(n_in[0] + w * (n_out[0] - n_in[0]), n_in[1] + w * (n_out[1] - n_in[1]))
                               for w in (Fraction(0), Fraction(1, 2), Fraction(1))]
                    points = [tuple(q[i])]
                for p in points:
                    for n in normals:
                        t = (n[1], -n[0])
                        for s in sides:
                            pushes.append((p, (n[0] + s * m * t[0], n[1] + s * m * t[1])))
                out.append({"feature": f"{kind} {i}", "slip": slip, "pushes": pushes})
    return out


def number(x):
    f = float(x)
    assert Fraction(f) == x, x
    return f


def main():
    rng = random.Random(SEED)
    out = {"generator": "tests/web/oracle_fixtures.py", "seed": SEED, "finger_mu": FINGER_MU, "angles": ANGLES,
           "scenes": []}
    for k in range(SCENES):
        doc = with_box(oracle.random_scene(rng, 1 + k % 4), rng)
        scene = oracle.exact_scene(doc)
        modes = sorted(oracle.modes(scene))
        wrenches = [oracle.random_wrench(rng) for _ in range(8)] + oracle.boundary_wrenches(scene, rng, 8)
        entry = {"scene": doc, "modes": modes,
                 "queries": [{"wrench": list(w), "modes": sorted(oracle.query(scene, w))} for w in wrenches],
                 "plans": []}
        if k % 2 == 0:  # plans on half the scenes
            com = doc["body"]["com"]
            centre = [float(oracle._grid(rng, -2, 2, 4)), float(oracle._grid(rng, -2, 2, 4))]
            pushes = finger_pushes(doc["body"]["polygon"], FINGER_MU)
            for goal in rng.sample(modes, min(2, len(modes))):
                plan = {"goal": goal, "centre": centre,
                        "tilt": [modes_of_force(scene, modes, com, a) for a in ANGLES],
                        "comply": [modes_of_force(scene, modes, centre, a) for a in ANGLES],
                        "push": []}
                for case in pushes:
                    gives = [oracle.produces(scene, goal, oracle.wrench_at(p, f)) for p, f in case["pushes"]]
                    plan["push"].append({"feature": case["feature"], "slip": case["slip"],
                                         "pushes": [[number(x) for x in (*p, *f)] for p, f in case["pushes"]],
                                         "gives_goal": gives})
                entry["plans"].append(plan)
        out["scenes"].append(entry)
        print(f"scene {k}: {len(modes)} modes, {len(entry['plans'])} goals planned", file=sys.stderr)
    path = HERE / "oracle_fixtures.json"
    path.write_text(json.dumps(out, separators=(",", ":")) + "\n")
    print(f"wrote {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
