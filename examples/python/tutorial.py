"""The paper's Figures 1-6 in Python (Mason 1991, "Two graphical methods for planar contact
problems"), with momentlab and matplotlib. Run it from anywhere:

    /usr/bin/python3 examples/python/tutorial.py [OUTPUT_DIRECTORY]     (default: out/python)

Each step prints what the figure shows and checks it against what the paper derives by hand
(the assertions are the paper's, not this program's output), then saves the picture.
"""

import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import momentlab as ml  # noqa: E402
import momentlab.plot as mp  # noqa: E402

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parent
OUT = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("out/python")
OUT.mkdir(parents=True, exist_ok=True)


def save(fig, name):
    path = OUT / f"{name}.png"
    fig.savefig(path, dpi=90, bbox_inches="tight")
    plt.close(fig)
    print(f"   -> {path}")


# --- Figure 1: three force sets and their moment labels -------------------------------------
# A point is labelled + when every force of the set turns counter-clockwise about it (moment
# >= 0), - when every force turns clockwise.
print("Figure 1a: one force along +x through the origin")
f1a = ml.force((0, 0), (1, 0))
lab = ml.labels(f1a)
assert lab.at((0, 1)) == "+" and lab.at((0, -1)) == "-"  # left of a directed line is +
assert lab.at((5, 0)) == "+-"  # on the line: moment 0
print("   left of the force:", lab.at((0, 1)), " right:", lab.at((0, -1)), " on it:", lab.at((5, 0)))

print("Figure 1b: every force through the point (1, 1)")
f1b = ml.forces_through_point((1, 1))
assert ml.labels(f1b).at((1, 1)) == "+-" and ml.labels(f1b).at((0, 0)) == "none"

print("Figure 1c: a friction cone at the origin, normal +y, mu 1/2")
f1c = ml.friction_cone((0, 0), (0, 1), 0.5)
assert f1c.kind == "wedge" and len(f1c.rays) == 2

fig, axes = plt.subplots(1, 3, figsize=(12, 4))
for ax, cone, title in zip(axes, (f1a, f1b, f1c), ("1a: a force", "1b: forces through a point", "1c: friction cone")):
    mp.labels(ax, cone, view=(-2, -2, 2, 2), title=title)
save(fig, "figure-1")

# --- Figure 2: two friction cones combined ---------------------------------------------------
print("Figure 2: the sum of two friction cones; + of the sum is + of one and + of the other")
g = ml.friction_cone((2, 0), (-1, 1), 0.5)
total = f1c + g
# (F + G)+ = F+ n G+ and (F + G)- = F- n G- (the paper's rule), on a grid of points.
for x in np.arange(-2.0, 4.01, 0.25):
    for y in np.arange(-2.0, 4.01, 0.25):
        for sign in "+-":
            has = lambda label: label in (sign, "+-")  # noqa: E731
            assert has(ml.labels(total).at((x, y))) == (has(ml.labels(f1c).at((x, y))) and has(ml.labels(g).at((x, y))))
fig, axes = plt.subplots(1, 3, figsize=(12, 4))
for ax, cone, title in zip(axes, (f1c, g, total), ("cone at (0, 0)", "cone at (2, 0)", "their sum")):
    mp.labels(ax, cone, view=(-2, -2, 4, 4), title=title)
save(fig, "figure-2")

# --- Figure 3: the block along the wall ------------------------------------------------------
print("Figure 3: a block on a floor, two contacts with mu 1/2")
block = ml.Scene.from_file(EXAMPLES / "figure-3-block-along-wall.json")
a = ml.analyze(block)
print("   modes:", " ".join(a.modes))
assert len(a.modes) == 10  # two contacts on one line: 10 modes (Mason 1991, section 2.1)
# A force (1, -1) through the centre of mass (1/2, 1/4), torque px fy - py fx = -3/4: it presses
# the block down with 1 and pushes it right with 1 > mu * 1, so it slides right (rr).
print("   push (1, -1) through the centre of mass:", a.query([1.0, -1.0, -0.75]))
assert a.query([1.0, -1.0, -0.75]) == ["rr"]
print("   gravity alone (0, -1, -1/2):", a.query([0.0, -1.0, -0.5]))
assert a.query([0.0, -1.0, -0.5]) == ["ff"]  # at rest on the floor
# One question about a scene not analysed, as a simulator asks at each step: ml.query answers
# it exactly without building every mode's sets (docs/robustness.md).
once = ml.query(block, [1.0, -1.0, -0.75])
print("   the same push asked once, without the analysis:", once.modes, once.verdict)
assert once.modes == ["rr"] and once.verdict == "unique"
fig, axes = plt.subplots(1, 3, figsize=(13, 4.5))
mp.mode_sets(axes, a, "rr")
save(fig, "figure-3")
fig, ax = plt.subplots(figsize=(8, 5))
mp.modes(ax, a)
save(fig, "figure-3-modes")

# --- Figure 4: two-point peg insertion -------------------------------------------------------
print("Figure 4: a peg touching both sides of a hole")
peg = ml.analyze(ml.Scene.from_file(EXAMPLES / "figure-4-peg-in-hole.json"))
print("   modes:", " ".join(peg.modes))
assert "rl" in peg.modes
fig, axes = plt.subplots(1, 3, figsize=(13, 4.5))
mp.mode_sets(axes, peg, "rl")
save(fig, "figure-4")

# --- Figure 5: tilting -----------------------------------------------------------------------
print("Figure 5: which tilts (gravity directions) slide the block right (rr)")
tilt = ml.plan_tilt(a, "rr")
print("   intervals (radians):", tilt.intervals)
# By hand (docs/planning.md): gravity g = (cos a, sin a) through the centre of mass slides the
# block right when it points into the floor and beats friction: a in [-atan 2, 0].
(lo, hi), = tilt.intervals
assert math.isclose(lo, -math.atan(2), abs_tol=1e-12) and math.isclose(hi, 0.0, abs_tol=1e-12)
fig, ax = plt.subplots(figsize=(6, 5))
mp.tilt(ax, a, "rr")
save(fig, "figure-5")

# --- Figure 6: pushing -----------------------------------------------------------------------
print("Figure 6: a finger pushing the trailing edge (edge 3), slipping l, to slide the block right")
cases = ml.plan_push(a, "rr")
case = next(c for c in cases if c.feature == "edge 3" and c.slip == "l")
print("   verdict:", case.verdict, " touch:", case.touch)
# By hand (docs/planning.md): force (1, -1/2) at (0, y) with y in [3/16, 1/2].
assert case.verdict == "feasible"
(p, q), = case.touch
assert sorted([p[1], q[1]]) == [3 / 16, 1 / 2]
fig, ax = plt.subplots(figsize=(6, 5))
mp.push(ax, a, "rr")
save(fig, "figure-6")

# --- Many questions at once ------------------------------------------------------------------
rng = np.random.default_rng(1991)
W = rng.normal(size=(100_000, 3))
hits = a.query(W)
counts = dict(zip(a.modes, hits.sum(axis=0).tolist()))
print("Batch: 100,000 random wrenches, how often each mode:", counts)
assert hits.shape == (100_000, 10)
print("done: pictures in", OUT)
