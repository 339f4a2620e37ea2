"""Pictures on matplotlib Axes, with the colours and marks of the command line's pictures
(docs/pictures.md): + regions orange, - regions blue, the +- set purple, forces as dark
arrows with their dashed lines of action, friction cones green, obstacles grey.

`stand` draws an assembly with the answer of momentlab.stand in magenta (ANSWER): the contact
forces of its equilibrium, or its collapse mechanism, and each body's moment labels.

Every function draws onto the `ax` it is given, so a notebook composes the pictures with its
own plots; it returns the Axes (`push` and `comply` the plan they drew, `region` the polygon).
Functions that take an analysis also take a Scene. Regions are cut to the view for drawing
only; every label a program decides is exact (Labels.at). Unlike the CLI's pictures, regions
that go on beyond the view get no arrow.

    import matplotlib.pyplot as plt
    import momentlab as ml, momentlab.plot as mp
    a = ml.analyze(ml.Scene.from_file("examples/figure-3-block-along-wall.json"))
    fig, axes = plt.subplots(1, 3, figsize=(12, 4))
    mp.mode_sets(axes, a, "rr")
"""

from __future__ import annotations

import math

import numpy as np

from . import Analysis, Assembly, Cone, Labels, Scene, analyze, plan_comply, plan_push, plan_tilt
from . import stand as _stand

# docs/pictures.md; the same values as include/momentlab/render/figure.hpp.
PAPER = (1.0, 1.0, 1.0)
INK = (0.12, 0.12, 0.14)
PLUS = (0.992, 0.773, 0.522)
PLUS_EDGE = (0.851, 0.447, 0.043)
MINUS = (0.600, 0.784, 0.949)
MINUS_EDGE = (0.129, 0.416, 0.710)
BOTH = (0.478, 0.110, 0.588)
BODY = (0.35, 0.35, 0.38)
OBSTACLE = (0.55, 0.55, 0.55)
FRICTION = (0.180, 0.600, 0.310)
GUIDE = (0.62, 0.62, 0.66)
ANSWER = (0.827, 0.106, 0.447)
MODE_COLOURS = [(0.651, 0.808, 0.890), (0.698, 0.875, 0.541), (0.984, 0.604, 0.600), (0.992, 0.749, 0.435),
                (0.792, 0.698, 0.839), (1.000, 1.000, 0.600), (0.553, 0.827, 0.780), (0.988, 0.804, 0.898),
                (0.851, 0.851, 0.851), (0.800, 0.922, 0.773), (0.737, 0.502, 0.741), (1.000, 0.929, 0.435)]


def _view(ax, view):
    """The box (xmin, ymin, xmax, ymax) to draw in: the given one, or the Axes' limits."""
    if view is None:
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        return (x0, y0, x1, y1)
    return tuple(float(v) for v in view)


def scene_view(scene: Scene, pad: float = 0.35):
    """A square box around the body, its contacts and centre of mass, padded by `pad` of its size."""
    pts = [np.asarray(scene.points)]
    body = scene.body
    if body is not None:
        pts.append(np.asarray(body["com"]).reshape(1, 2))
        if len(body["polygon"]):
            pts.append(body["polygon"])
    p = np.vstack([q for q in pts if len(q)])
    lo, hi = p.min(axis=0), p.max(axis=0)
    size = max(float((hi - lo).max()), 1.0 if not np.any(hi - lo) else 0.0)
    c = (lo + hi) / 2
    half = size * (0.5 + pad)
    return (c[0] - half, c[1] - half, c[0] + half, c[1] + half)


def _setup(ax, view):
    ax.set_xlim(view[0], view[2])
    ax.set_ylim(view[1], view[3])
    ax.set_aspect("equal", adjustable="box")


def region(ax, reg, fill, edge, view=None, alpha=1.0, mark=None, **kw):
    """One sheet of labels (a Region), cut to the view: filled polygon, segment or point."""
    box = _view(ax, view)
    poly = reg.clipped(box) if not reg.is_empty else np.zeros((0, 2))
    if len(poly) >= 3:
        ax.fill(poly[:, 0], poly[:, 1], color=fill, alpha=alpha, zorder=1, **kw)
        closed = np.vstack([poly, poly[:1]])
        ax.plot(closed[:, 0], closed[:, 1], color=edge, lw=1.2, zorder=2)
    elif len(poly) == 2:
        ax.plot(poly[:, 0], poly[:, 1], color=edge, lw=2.5, zorder=3, **kw)
    elif len(poly) == 1:
        ax.plot(poly[:, 0], poly[:, 1], "o", color=edge, ms=6, zorder=3, **kw)
    if mark and len(poly):
        c = poly.mean(axis=0)
        ax.text(c[0], c[1], mark, color=edge, fontsize=16, fontweight="bold", ha="center", va="center", zorder=5)
    return poly


def forces(ax, cone: Cone, view=None, colour=INK, at=None):
    """The extreme rays of a force set as arrows on their (dashed) lines of action; a ray
    through `at` (a point, e.g. the centre of mass) starts there. Pure moments are listed in
    the corner (counter-clockwise / clockwise)."""
    box = _view(ax, view)
    size = max(box[2] - box[0], box[3] - box[1])
    moments = []
    generators = [(r, False) for r in cone.rays] + [(l, True) for l in cone.lineality]
    for w, both_ways in generators:
        f = np.array(w[:2])
        norm2 = float(f @ f)
        if norm2 == 0.0:
            moments.append("\u21ba" if w[2] > 0 or both_ways else "\u21bb")
            if both_ways:
                moments.append("\u21bb")
            continue
        p = w[2] / norm2 * np.array([f[1], -f[0]])  # the point of the line nearest the origin
        if at is not None:
            a = np.asarray(at, dtype=float)
            if abs((a[0] * f[1] - a[1] * f[0]) - w[2]) <= 1e-12 * max(1.0, abs(w[2])):
                p = a
        d = f / math.sqrt(norm2)
        ax.plot([p[0] - 2 * size * d[0], p[0] + 2 * size * d[0]], [p[1] - 2 * size * d[1], p[1] + 2 * size * d[1]],
                ls="--", lw=0.8, color=colour, alpha=0.6, zorder=4)
        tip = p + 0.2 * size * d
        ax.annotate("", xy=tip, xytext=p, arrowprops=dict(arrowstyle="<|-|>" if both_ways else "-|>", color=colour,
                                                         lw=1.5), zorder=6)
    if moments:
        ax.text(0.02, 0.98, "moments " + " ".join(sorted(set(moments))), transform=ax.transAxes, va="top",
                color=colour, fontsize=10)
    _setup(ax, box)
    return ax


def labels(ax, what, view=None, show_forces=True, title=None, at=None):
    """The moment labels of a force set (a Cone or Labels): + orange, - blue, the +- set purple."""
    lab = what if isinstance(what, Labels) else Labels(what)
    box = _view(ax, view)
    region(ax, lab.plus, PLUS, PLUS_EDGE, box, mark="+")
    region(ax, lab.minus, MINUS, MINUS_EDGE, box, mark="\u2212")
    both = lab.both
    if not both.is_empty:
        poly = region(ax, both, BOTH, BOTH, box)
        if len(poly) and len(poly) <= 2:
            c = poly.mean(axis=0)
            ax.text(c[0], c[1], " \u00b1", color=BOTH, fontsize=14, fontweight="bold", va="bottom", zorder=5)
    if show_forces:
        forces(ax, lab.forces, box, at=at)
    if title:
        ax.set_title(title)
    _setup(ax, box)
    return ax


def scene(ax, sc: Scene, view=None, faint=False):
    """Obstacles grey, the body outlined with its centre of mass as a dot, each contact with its
    friction cone (green) and its normal pointing into the body."""
    box = scene_view(sc) if view is None else tuple(view)
    k = 0.5 if faint else 1.0
    for o in sc.obstacles:
        ax.fill(o[:, 0], o[:, 1], color=OBSTACLE, alpha=0.45 * k, zorder=0.5)
    body = sc.body
    if body is not None:
        poly = body["polygon"]
        if len(poly):
            ax.fill(poly[:, 0], poly[:, 1], color=BODY, alpha=0.15 * k, zorder=0.6)
            closed = np.vstack([poly, poly[:1]])
            ax.plot(closed[:, 0], closed[:, 1], color=BODY, lw=1.5, alpha=k, zorder=0.7)
        ax.plot([body["com"][0]], [body["com"][1]], "o", color=BODY, ms=5, alpha=k, zorder=7)
    length = 0.12 * max(box[2] - box[0], box[3] - box[1])
    for p, n, mu in zip(sc.points, sc.normals, sc.mu):
        u = n / np.linalg.norm(n)
        t = np.array([u[1], -u[0]])
        cone = np.array([p, p + length * (u + mu * t), p + length * (u - mu * t)])
        ax.fill(cone[:, 0], cone[:, 1], color=FRICTION, alpha=0.25 * k, zorder=0.8)
        ax.annotate("", xy=p + length * u, xytext=p, arrowprops=dict(arrowstyle="-|>", color=FRICTION, lw=1.2,
                                                                     alpha=k), zorder=8)
    _setup(ax, box)
    return ax


def mode_sets(axes, analysis: Analysis, mode: str, view=None):
    """Three panels: F (total), T (contact) and E (applied) wrenches of one mode, over the scene
    (the paper's Figures 3 and 4)."""
    analysis = figure_for(analysis)
    sets = analysis[mode]
    box = scene_view(analysis.scene) if view is None else tuple(view)
    com = analysis.scene.body["com"]
    for ax, cone, name in zip(axes, (sets.total, sets.contact, sets.applied), ("F", "T", "E")):
        scene(ax, analysis.scene, box, faint=True)
        labels(ax, cone, box, at=com if name == "F" else None, title=f"{name}: mode {mode}")
    return axes


def modes(ax, analysis: Analysis, view=None):
    """Every mode's rotation centres (Reuleaux): counter-clockwise centres (the + region) and
    clockwise ones (the - region) in the mode's colour; the contact normals and tangents as
    dashed guides; modes without a finite centre (translations, or at rest) in the legend."""
    analysis = figure_for(analysis)
    sc = analysis.scene
    box = scene_view(sc) if view is None else tuple(view)
    size = max(box[2] - box[0], box[3] - box[1])
    scene(ax, sc, box, faint=True)
    for p, n in zip(sc.points, sc.normals):
        u = n / np.linalg.norm(n)
        for d in (u, np.array([u[1], -u[0]])):
            ax.plot([p[0] - 2 * size * d[0], p[0] + 2 * size * d[0]], [p[1] - 2 * size * d[1], p[1] + 2 * size * d[1]],
                    ls="--", lw=0.7, color=GUIDE, zorder=0.9)
    handles = []
    import matplotlib.patches as patches
    for k, sets in enumerate(analysis):
        colour = MODE_COLOURS[k % len(MODE_COLOURS)]
        centres = sets.rotation_centres()
        shown = []
        for reg, sense in ((centres.plus, "\u21ba"), (centres.minus, "\u21bb")):
            poly = region(ax, reg, colour, tuple(0.6 * c for c in colour), box, alpha=0.75)
            if len(poly):
                c = poly.mean(axis=0)
                ax.text(c[0], c[1], f"{sets.letters} {sense}", fontsize=8, ha="center", va="center", zorder=6)
                shown.append(sense)
        what = "centres " + " ".join(shown) if shown else "no finite centre"
        handles.append(patches.Patch(color=colour, label=f"{sets.letters}: {what}"))
    ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    _setup(ax, box)
    return ax


def _arc(ax, centre, start, end, radius, colour, lw=6, alpha=0.6):
    t = np.linspace(start, end, 64)
    ax.plot(centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t), color=colour, lw=lw, alpha=alpha,
            solid_capstyle="butt", zorder=6)


def tilt(ax, analysis: Analysis, goal: str, view=None):
    """The paper's Figure 5: E_goal's labels over the scene and, at the centre of mass, the arcs
    of gravity directions that produce the goal (with the best one as an arrow)."""
    analysis = figure_for(analysis)
    plan = plan_tilt(analysis, goal)
    box = scene_view(analysis.scene) if view is None else tuple(view)
    size = max(box[2] - box[0], box[3] - box[1])
    com = np.asarray(analysis.scene.body["com"])
    scene(ax, analysis.scene, box, faint=True)
    labels(ax, analysis[goal].applied, box, title=f"tilts that produce {goal}")
    for lo, hi in plan.intervals:
        _arc(ax, com, lo, hi, 0.15 * size, FRICTION)
    if plan.best is not None:
        d = np.array([math.cos(plan.best), math.sin(plan.best)])
        ax.annotate("", xy=com + 0.25 * size * d, xytext=com,
                    arrowprops=dict(arrowstyle="-|>", color=FRICTION, lw=2), zorder=8)
    return ax


def push(ax, analysis: Analysis, goal: str, mu: float = 0.5, ignore_interference: bool = False, view=None):
    """The pushing table on the body: where a feasible push may touch (green), with its best
    push as an arrow; boundary cases dotted."""
    analysis = figure_for(analysis)
    cases = plan_push(analysis, goal, mu, ignore_interference)
    box = scene_view(analysis.scene) if view is None else tuple(view)
    size = max(box[2] - box[0], box[3] - box[1])
    scene(ax, analysis.scene, box)
    for c in cases:
        if c.verdict not in ("feasible", "boundary"):
            continue
        style = "-" if c.feasible else ":"
        for a, b in c.touch:
            ax.plot([a[0], b[0]], [a[1], b[1]], style, color=FRICTION, lw=5, alpha=0.6, zorder=7)
        if c.best is not None:
            p = np.asarray(c.best.point)
            d = np.array([math.cos(c.best.direction), math.sin(c.best.direction)])
            ax.annotate("", xy=p, xytext=p - 0.2 * size * d,
                        arrowprops=dict(arrowstyle="-|>", color=INK, lw=1.5), zorder=8)
    ax.set_title(f"pushes that produce {goal} (finger mu {mu:g})")
    _setup(ax, box)
    return cases


def comply(ax, analysis: Analysis, goal: str, centre=None, view=None):
    """Compliance centres: E_goal's labels (centres outside both regions work) and, for a given
    centre, the arcs of spring directions through it."""
    analysis = figure_for(analysis)
    plan = plan_comply(analysis, goal, centre)
    box = scene_view(analysis.scene) if view is None else tuple(view)
    size = max(box[2] - box[0], box[3] - box[1])
    scene(ax, analysis.scene, box, faint=True)
    labels(ax, analysis[goal].applied, box, show_forces=False, title=f"compliance centres for {goal}")
    if centre is not None:
        c = np.asarray(centre, dtype=float)
        ax.plot([c[0]], [c[1]], "x", color=INK, ms=8, mew=2, zorder=9)
        for lo, hi in plan.centre.intervals:
            _arc(ax, c, lo, hi, 0.1 * size, FRICTION)
    return plan


def figure_for(analysis_or_scene):
    """An Analysis from a Scene or Analysis (for the functions above)."""
    return analysis_or_scene if isinstance(analysis_or_scene, Analysis) else analyze(analysis_or_scene)


def assembly_view(assembly: Assembly, pad: float = 0.25):
    """A square box around the bodies (polygons and centres of mass) and the contacts."""
    pts = [np.asarray(assembly.points).reshape(-1, 2)]
    for b in assembly.bodies:
        pts += [np.asarray(b["com"]).reshape(1, 2), np.asarray(b["polygon"]).reshape(-1, 2)]
    p = np.vstack(pts)
    lo, hi = p.min(axis=0), p.max(axis=0)
    size = max(float((hi - lo).max()), 1.0 if not np.any(hi - lo) else 0.0)
    c = (lo + hi) / 2
    half = size * (0.5 + pad)
    return (c[0] - half, c[1] - half, c[0] + half, c[1] + half)


def assembly(ax, asm: Assembly, view=None, faint=False, outlined=None):
    """Obstacles grey; each body's polygon (body `outlined`, 1..N, in ink) with its centre of mass
    as a dot and its number; each contact with its friction cone and its normal into body a
    (contact points only when faint)."""
    box = assembly_view(asm) if view is None else tuple(view)
    size = max(box[2] - box[0], box[3] - box[1])
    for o in asm.obstacles:
        ax.fill(o[:, 0], o[:, 1], color=OBSTACLE, alpha=0.2 if faint else 0.45, zorder=0.5)
    for k, b in enumerate(asm.bodies, start=1):
        poly, own = b["polygon"], outlined == k
        if len(poly):
            ax.fill(poly[:, 0], poly[:, 1], color=BODY, alpha=0.25 if own else (0.05 if faint else 0.15), zorder=0.6)
            closed = np.vstack([poly, poly[:1]])
            ax.plot(closed[:, 0], closed[:, 1], color=INK if own else BODY, lw=2.2 if own else 1.5, zorder=0.7)
        ax.plot([b["com"][0]], [b["com"][1]], "o", color=INK, ms=4 if len(poly) else 7, zorder=7)
        ax.annotate(f"{k} {b['name']}".strip(), b["com"], xytext=(0, 8), textcoords="offset points", ha="center",
                    fontsize=8, fontweight="bold" if own else "normal", zorder=9)
    for p, n, mu in zip(asm.points, asm.normals, asm.mu):
        if faint:
            ax.plot([p[0]], [p[1]], "o", color=FRICTION, ms=3, zorder=8)
            continue
        u = n / np.linalg.norm(n)
        t = np.array([u[1], -u[0]])
        length = 0.1 * size
        cone = np.array([p, p + length * (u + mu * t) / np.linalg.norm(u + mu * t),
                         p + length * (u - mu * t) / np.linalg.norm(u - mu * t)])
        ax.fill(cone[:, 0], cone[:, 1], color=FRICTION, alpha=0.2, zorder=0.8)
        ax.annotate("", xy=p + length * u, xytext=p, arrowprops=dict(arrowstyle="-|>", color=FRICTION, lw=1.0), zorder=8)
    _setup(ax, box)
    return ax


def stand(axes, asm: Assembly, gravity=None, view=None):
    """The picture of `momentlab draw SCENE --what stand`; returns momentlab.stand(asm, gravity)
    (gravity as momentlab.stand takes it: by default (0, -9.81), the decimal).

    On the first Axes (or the only one given): the assembly and, in magenta, the force on body a
    at each contact of the equilibrium as an arrow from the contact (lengths in proportion; none
    where the force is zero) when it can stand, else the collapse mechanism: each turning body's
    rotation centre as a cross with its number and sense, and each moving body's velocity at its
    centre of mass as an arrow. On each further Axes k (k = 1, 2, ...): the moment labels of the
    wrenches body k's contacts can apply (Assembly.contact_wrenches) over the faint assembly."""
    all_axes = list(np.ravel(axes)) if isinstance(axes, (list, tuple, np.ndarray)) else [axes]
    result = _stand(asm, gravity)
    box = assembly_view(asm) if view is None else tuple(view)
    size = max(box[2] - box[0], box[3] - box[1])
    ax = all_axes[0]
    assembly(ax, asm, box)
    if result.can_stand:
        largest = max(float(np.linalg.norm(f)) for f in result.forces) if len(result.forces) else 0.0
        carrying = 0
        for p, f in zip(asm.points, result.forces):
            if not np.any(f):
                continue
            carrying += 1
            ax.annotate("", xy=p + 0.2 * size * f / largest, xytext=p,
                        arrowprops=dict(arrowstyle="-|>", color=ANSWER, lw=2), zorder=10)
        ax.set_title(f"stands: forces of one equilibrium ({carrying} of {len(result.forces)} contacts carry force)",
                     fontsize=9)
    else:
        coms = [np.asarray(b["com"]) for b in asm.bodies]
        velocity = [np.array([m.twist[0] - m.twist[2] * c[1], m.twist[1] + m.twist[2] * c[0]])
                    for m, c in zip(result.mechanism, coms)]
        fastest = max(float(np.linalg.norm(v)) for v in velocity)
        for m, c, v in zip(result.mechanism, coms, velocity):
            if np.any(v) and fastest > 0:
                ax.annotate("", xy=c + 0.18 * size * v / fastest, xytext=c,
                            arrowprops=dict(arrowstyle="-|>", color=ANSWER, lw=2), zorder=10)
            if m.rotation_centre is not None:
                r = m.rotation_centre
                ax.plot([r[0]], [r[1]], "x", color=ANSWER, ms=9, mew=2, zorder=10)
                sense = "\u21ba" if m.twist[2] > 0 else "\u21bb"
                ax.annotate(f"{m.body} {sense}", r, xytext=(0, -12), textcoords="offset points", ha="center",
                            color=ANSWER, fontsize=8, zorder=10)
        ax.set_title("falls: a collapse mechanism", fontsize=9)
    _setup(ax, box)
    for k, lax in enumerate(all_axes[1:len(asm.bodies) + 1], start=1):
        points = [p for (a, b), p in zip(asm.pairs, asm.points) if k in (a, b)]
        labels(lax, asm.contact_wrenches(k), box, show_forces=False, title=f"body {k}: wrenches its contacts can apply")
        assembly(lax, asm, box, faint=True, outlined=k)
        for p in points:
            lax.plot([p[0]], [p[1]], "o", color=INK, ms=3, zorder=8)
    return result
