"""momentlab.plot draws onto a matplotlib Axes with the colours of docs/pictures.md, and what it
fills is where the labels are (checked from the raw numbers of the force, not by the labels
code); the tutorial of the paper's Figures 1-6 runs and writes its pictures."""

import os
import subprocess
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.colors import to_rgb  # noqa: E402

import momentlab as ml  # noqa: E402
import momentlab.plot as mp  # noqa: E402
from conftest import EXAMPLES, ROOT  # noqa: E402


def filled(ax, colour):
    """The vertices of the filled polygons of that colour."""
    out = []
    for patch in ax.patches:
        if np.allclose(to_rgb(patch.get_facecolor()), colour):
            out.append(patch.get_xy())
    return out


def test_labels_of_one_force_fill_the_right_sides():
    # The force (1, 0) through (0, 1/2): its moment about q is (p - q) x f = q.y - 1/2, so the +
    # region is y >= 1/2 and the - region y <= 1/2.
    fig, ax = plt.subplots()
    mp.labels(ax, ml.force((0, 0.5), (1, 0)), view=(-2, -2, 2, 2))
    plus, minus = filled(ax, mp.PLUS), filled(ax, mp.MINUS)
    assert len(plus) == 1 and len(minus) == 1
    assert plus[0][:, 1].min() == pytest.approx(0.5) and plus[0][:, 1].max() == pytest.approx(2.0)
    assert minus[0][:, 1].max() == pytest.approx(0.5) and minus[0][:, 1].min() == pytest.approx(-2.0)
    # the +- set is the line itself, drawn in purple
    purple = [l for l in ax.lines if np.allclose(to_rgb(l.get_color()), mp.BOTH)]
    assert purple and all(np.allclose(l.get_ydata(), 0.5) for l in purple)
    texts = {t.get_text() for t in ax.texts}
    assert {"+", "\u2212"} <= texts
    plt.close(fig)


def test_friction_cone_labels_and_scene_pictures():
    fig, axes = plt.subplots(1, 3)
    # A friction cone at the origin, normal +y, mu 1/2: no point is unlabelled on the normal's
    # line below... the apex is the +- point.
    mp.labels(axes[0], ml.friction_cone((0, 0), (0, 1), 0.5), view=(-2, -2, 2, 2))
    dots = [l for l in axes[0].lines if np.allclose(to_rgb(l.get_color()), mp.BOTH)]
    assert any(np.allclose(np.c_[l.get_xdata(), l.get_ydata()], [[0.0, 0.0]]) for l in dots)
    a = ml.analyze(ml.Scene.from_file(EXAMPLES / "figure-3-block-along-wall.json"))
    mp.scene(axes[1], a.scene)
    assert filled(axes[1], mp.OBSTACLE) and filled(axes[1], mp.BODY) and len(filled(axes[1], mp.FRICTION)) == 2
    mp.modes(axes[2], a)
    legend = [t.get_text() for t in axes[2].get_legend().get_texts()]
    assert [entry.split(":")[0] for entry in legend] == a.modes
    plt.close(fig)


def test_mode_sets_plans_draw():
    a = ml.analyze(ml.Scene.from_file(EXAMPLES / "figure-3-block-along-wall.json"))
    fig, axes = plt.subplots(2, 3)
    mp.mode_sets(axes[0], a, "rr")
    assert [ax.get_title() for ax in axes[0]] == ["F: mode rr", "T: mode rr", "E: mode rr"]
    mp.tilt(axes[1][0], a, "rr")
    cases = mp.push(axes[1][1], a, "rr")
    assert any(c.feasible for c in cases)
    # E_rr of the block along the wall is cone{(1, 0, -1/4), (1/2, -1, 0), (1/2, -1, -1)}; their
    # moments about (x, y) are y - 1/4, x + y/2 and x + y/2 - 1 (tests/planning/test_comply.cpp).
    # At (-1, 1/4) they are 0, -7/8 and -15/8: on the edge of the - region, a boundary centre.
    plan = mp.comply(axes[1][2], a, "rr", centre=(-1.0, 0.25))
    assert plan.centre.verdict == "boundary"
    assert plan.centre.label == "-"
    plt.close(fig)


def test_tutorial_runs(tmp_path):
    env = dict(os.environ, MPLBACKEND="Agg")
    r = subprocess.run([sys.executable, str(ROOT / "examples" / "python" / "tutorial.py"), str(tmp_path)],
                       capture_output=True, text=True, env=env, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    for name in ("figure-1", "figure-2", "figure-3", "figure-3-modes", "figure-4", "figure-5", "figure-6"):
        data = (tmp_path / f"{name}.png").read_bytes()
        assert data.startswith(b"\x89PNG\r\n\x1a\n") and len(data) > 5000, name
