"""momentlab: exact planar contact mechanics with Coulomb friction by Mason's graphical methods.

Moment labels for sets of forces, rotation centres for motions, every contact mode of a body
at rest with its sets of total (F), contact (T) and applied (E) wrenches, the mode(s) an
applied wrench produces, and plans (tilt, push, comply) that reach a goal mode (Mason 1991).
Every decision is exact for the numbers given; only printed values are rounded.

    >>> import momentlab as ml
    >>> a = ml.analyze(ml.Scene.from_file("examples/figure-3-block-along-wall.json"))
    >>> a.modes
    ['ff', 'ss', 'fs', 'rs', 'ls', 'sf', 'sr', 'sl', 'rr', 'll']
    >>> a.query([1.0, -1.0, -0.75])
    ['rr']

Wrenches are (fx, fy, tau) with tau about the world origin; contact normals point into the
body; mode letters per contact: s separating, f fixed, r / l sliding along +t / -t,
t = (n.y, -n.x) (docs/design.md). Bad input raises ValueError with the one-line message the
command line prints ("$.contacts[0].mu: ..."). The reference is docs/python.md.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, replace as _replace
from typing import Any, Optional, Sequence

import numpy as np

from ._momentlab import (
    Cone,
    Labels,
    ModeSets,
    Region,
    force,
    force_set_from_json,
    forces_through_point,
    line_of_force,
)
from . import _momentlab
from .values import (
    _exact_json, _exact_number, _exact_wrench, _exact_wrenches, _flag, _forces, _goal, _has_exact, _number,
    _sequence, _table, _wrenches,
)
from .results import (
    Band, BestMargins, CentrePlan, Closure, ClosureTest, Compliance, DirectionPlan, Labelling, Magnitudes,
    Margins, Push, PushCase, QueryAnswer, RegionData, BodyMotion, StandResult, TiltCone,
)

__all__ = [
    "Assembly", "BodyMotion", "StandResult", "TiltCone", "stand",
    "Analysis", "Body", "Cone", "Contact", "Labels", "ModeSets", "Region", "Scene",
    "Band", "BestMargins", "CentrePlan", "Closure", "ClosureTest", "Compliance", "DirectionPlan", "Labelling",
    "Magnitudes", "Margins", "Push", "PushCase", "QueryAnswer", "RegionData",
    "analyze", "closure", "contacts", "find_contacts", "force", "force_set_from_json", "forces_through_point",
    "friction_cone", "labels", "line_of_force", "plan_comply", "plan_push", "plan_tilt", "push_line",
    "pure_moments", "query", "wrench",
]

__version__ = "0.1.0"

VERDICTS = ("inconsistent", "unique", "ambiguous")


@dataclass
class Body:
    """The moving body: mass, centre of mass, inertia about it (or a radius of gyration, for
    which the inertia is exactly mass * radius_of_gyration**2) and an optional outline."""

    mass: float = 1.0
    com: Sequence[float] = (0.0, 0.0)
    inertia: Optional[float] = None
    radius_of_gyration: Optional[float] = None
    polygon: Optional[Any] = None

    def _doc(self) -> dict:
        doc = {"mass": self.mass, "com": self.com}
        if self.inertia is not None:
            doc["inertia"] = self.inertia
        if self.radius_of_gyration is not None:
            doc["radius_of_gyration"] = self.radius_of_gyration
        if self.polygon is not None:
            doc["polygon"] = self.polygon
        return doc


@dataclass
class Contact:
    """A point contact: `normal` points into the body and is used as written (any positive
    length); `mu` static and `mu_kinetic` (default: mu) kinetic friction."""

    point: Sequence[float]
    normal: Sequence[float]
    mu: float = 0.0
    mu_kinetic: Optional[float] = None
    name: str = ""

    def _doc(self) -> dict:
        doc = {"point": self.point, "normal": self.normal, "mu": self.mu}
        if self.mu_kinetic is not None:
            doc["mu_kinetic"] = self.mu_kinetic
        if self.name:
            doc["name"] = self.name
        return doc


def contacts(points, normals, mu=0.0, mu_kinetic=None, names=None) -> list:
    """Contacts from arrays: points and normals of shape (n, 2), mu and mu_kinetic scalars or
    of shape (n,). Fractions and Decimals are kept as given (a scene reads them exactly)."""
    p = _table(points, "points")
    n = _table(normals, "normals")
    if len(p.shape) != 2 or p.shape[1] != 2:
        raise ValueError(f"points: expected an array of shape (n, 2), got shape {p.shape}")
    if n.shape != p.shape:
        raise ValueError(f"normals: expected shape {p.shape} like the points, got shape {n.shape}")
    count = p.shape[0]

    def per_contact(value, what):
        if value is None:
            return [None] * count
        v = _table(value, what)
        if not v.shape:
            return [v.values] * count
        if v.shape != (count,):
            raise ValueError(f"{what}: expected a number or an array of shape ({count},), got shape {v.shape}")
        return v.values

    mus = per_contact(mu, "mu")
    kinetic = per_contact(mu_kinetic, "mu_kinetic")
    labels_ = list(names) if names is not None else [""] * count
    if len(labels_) != count:
        raise ValueError(f"names: expected {count} names, got {len(labels_)}")
    return [Contact(p.values[i], n.values[i], mus[i], kinetic[i], str(labels_[i])) for i in range(count)]


def _contact_doc(c) -> dict:
    if isinstance(c, Contact):
        return c._doc()
    return c  # a dict in the file format; the reader checks it


class Scene:
    """A body (optional for purely kinematic questions), its contacts and fixed obstacles.

    Scene(body=Body(...) or dict, contacts=[Contact or dict, ...], obstacles=[polygon, ...]).
    Without contacts, they are found where the body's polygon touches the obstacles (within
    `contact_distance`, default 1e-9, with friction `mu`), as for a scene file.
    Scene.from_json(text) and Scene.from_file(path) read the file format (docs/formats.md).
    """

    def __init__(self, body=None, contacts=None, obstacles=(), contact_distance=None, mu=None, *, _scene=None):
        if _scene is not None:
            self._scene = _scene
            return
        doc: dict = {}
        if body is not None:
            doc["body"] = body._doc() if isinstance(body, Body) else body
        if contacts is not None:
            doc["contacts"] = [_contact_doc(c) for c in _sequence(contacts, "contacts")]
        obstacles = _sequence(obstacles, "obstacles") if obstacles is not None else []
        if len(obstacles):
            doc["obstacles"] = [o if isinstance(o, dict) else {"polygon": o} for o in obstacles]
        if contact_distance is not None:
            doc["contact_distance"] = contact_distance
        if mu is not None:
            doc["mu"] = mu
        if _has_exact(doc):  # Fractions and Decimals: read exactly, as the text of their decimals
            self._scene = _momentlab._Scene.from_json(_exact_json(doc, "$"))
        else:
            self._scene = _momentlab._Scene.from_doc(doc)

    @classmethod
    def from_json(cls, text: str) -> "Scene":
        """The scene of a JSON text in the file format."""
        if not isinstance(text, str):
            raise ValueError("$: expected the JSON text of a scene (a str)")
        return cls(_scene=_momentlab._Scene.from_json(text))

    @classmethod
    def from_file(cls, path) -> "Scene":
        """The scene of a JSON file, read as the CLI reads it (the same checks and messages:
        a missing file, a directory, a device or a binary file is a ValueError at "$")."""
        return cls(_scene=_momentlab._Scene.from_file(os.fsdecode(os.fspath(path))))

    def to_json(self) -> str:
        """The scene in the file format (contacts written out); from_json gives it back."""
        return self._scene.to_json()

    @property
    def body(self) -> Optional[dict]:
        """{'mass', 'com', 'inertia', 'polygon'} or None."""
        s = self._scene
        if not s.has_body:
            return None
        return {"mass": s.mass, "com": np.array(s.com), "inertia": s.inertia, "polygon": s.polygon}

    @property
    def points(self) -> np.ndarray:
        """The contact points, shape (n, 2)."""
        return self._scene.points

    @property
    def normals(self) -> np.ndarray:
        """The contact normals as written (into the body), shape (n, 2)."""
        return self._scene.normals

    @property
    def mu(self) -> np.ndarray:
        return self._scene.mu

    @property
    def mu_kinetic(self) -> np.ndarray:
        return self._scene.mu_kinetic

    @property
    def obstacles(self) -> list:
        """The fixed polygons, each of shape (k, 2)."""
        return self._scene.obstacles

    @property
    def contacts(self) -> list:
        """The contacts as Contact values."""
        s = self._scene
        return [Contact(p.tolist(), n.tolist(), float(m), float(k), name)
                for p, n, m, k, name in zip(s.points, s.normals, s.mu, s.mu_kinetic, s.names)]

    def __repr__(self) -> str:
        return f"<Scene: {len(self.points)} contacts, {'a body' if self._scene.has_body else 'no body'}>"


def find_contacts(body, obstacles, distance=1e-9, mu=0.0, mu_kinetic=None) -> list:
    """The contacts where the body polygon (shape (n, 2)) touches the obstacles (a list of
    polygons), within `distance`; decided exactly. Floats are their binary values; polygons,
    distance or mu holding Fractions or Decimals are read as typed, as a scene's polygons are
    (Scene(body=..., obstacles=...), which keeps the contacts exact; the Contact values returned
    show their doubles)."""
    obstacles = list(obstacles)
    if not _has_exact([body, obstacles, distance, mu]):
        return Scene(_scene=_momentlab.find_contacts(body, obstacles, distance, mu, mu_kinetic)).contacts
    doc = {"body": {"mass": 1, "com": [0, 0], "inertia": 1, "polygon": body},
           "obstacles": [{"polygon": o} for o in obstacles], "contact_distance": distance, "mu": mu}
    try:
        found = Scene(_scene=_momentlab._Scene.from_json(_exact_json(doc, "$"))).contacts
    except ValueError as e:  # named as the arguments are
        names = (("$.body.polygon", "body"), ("$.contact_distance", "distance"), ("$.mu", "mu"), ("$.obstacles", "obstacles"))
        text = re.sub(r"(obstacles\[\d+\])\.polygon", r"\1", str(e))
        for path, name in names:
            text = text.replace(path, name)
        raise ValueError(text) from None
    if mu_kinetic is not None:
        found = [_replace(c, mu_kinetic=_number(mu_kinetic, "mu_kinetic")) for c in found]
    return found


class Analysis:
    """Every contact mode of a scene with its sets (F, T, E), and the questions asked of them.

    `modes` lists the mode strings (the all-f mode first); `analysis[i]` or `analysis["rs"]`
    gives one mode's sets (ModeSets: .twists, .total, .contact, .applied as Cones, and
    .rotation_centres()).
    """

    def __init__(self, scene: Scene, quasi_static: bool = False):
        if not isinstance(scene, Scene):
            raise ValueError("analyze: expected a momentlab.Scene")
        self.quasi_static = _flag(quasi_static, "quasi_static")
        self._analysis = _momentlab._Analysis(scene._scene, self.quasi_static)
        self.scene = scene
        self._modes = tuple(self._analysis.modes)

    @property
    def modes(self) -> list:
        """The mode strings, the all-f mode first (a new list each time)."""
        return list(self._modes)

    def __contains__(self, letters) -> bool:
        return letters in self._modes

    def __len__(self) -> int:
        return len(self._modes)

    def __getitem__(self, key) -> ModeSets:
        if isinstance(key, str):
            if key not in self._modes:
                raise KeyError(f'mode: no mode "{key}" in this scene (its modes: {", ".join(self._modes)})')
            return self._analysis.mode(key)
        if isinstance(key, (int, np.integer)):
            i = int(key)
            if i < 0:
                i += len(self.modes)
            if not 0 <= i < len(self.modes):
                raise IndexError(f"mode index {key} out of range (0 .. {len(self.modes) - 1})")
            return self._analysis.mode_at(i)
        raise TypeError("modes are indexed by position or by their letters")

    def __iter__(self):
        return (self._analysis.mode_at(i) for i in range(len(self.modes)))

    def query(self, w):
        """The modes whose closed E_i holds the applied wrench, exactly.

        One wrench (shape (3,)): the list of mode strings, sorted (the order of every answer).
        A batch (shape (N, 3)): a bool array of shape (N, len(modes)); row k says which modes
        wrench k produces. Runs in the compiled index without the interpreter's lock. Fractions,
        Decimals and numeric strings are read exactly (docs/design.md, "Numbers as typed").
        """
        if _exact_wrench(w):
            return self._analysis.query_one(w)
        if _exact_wrenches(w):
            return self._query_rows(w)
        a = _wrenches(w)
        if a.ndim == 1:
            return self._analysis.query_one(a)
        return self._analysis.query_batch(a)

    def margins(self, w) -> Margins:
        """How far the wrench (shape (3,)) may move before the answer changes (docs/design.md,
        Margins): Margins(.inside: {mode: distance to the boundary of its E}, .to_other: distance
        to the nearest other mode's E (math.inf when none), .reference, .length): distances (N)
        of (fx, fy, tau / length), tau about the reference (m)."""
        if _exact_wrench(w):
            m = self._analysis.margins(w)
        else:
            a = _wrenches(w)
            if a.ndim != 1:
                raise ValueError("wrench: margins take one wrench of shape (3,)")
            m = self._analysis.margins(a)
        return Margins(dict(m["inside"]), float(m["to_other"]), tuple(m["reference"]), float(m["length"]))

    def verdict(self, w):
        """'unique', 'ambiguous' or 'inconsistent' for one wrench; for a batch, an array of them."""
        a = self.query(w)
        if isinstance(a, list):
            return VERDICTS[min(len(a), 2)]
        counts = np.minimum(np.asarray(a).sum(axis=1), 2)
        return np.asarray(VERDICTS)[counts]

    def _query_rows(self, rows) -> np.ndarray:
        # A batch holding exact numbers, one wrench at a time (each row checked as one wrench).
        out = np.zeros((len(rows), len(self.modes)), dtype=bool)
        index = {m: k for k, m in enumerate(self.modes)}
        for i, row in enumerate(rows):
            for m in self._analysis.query_one(row):
                out[i, index[m]] = True
        return out

    def __repr__(self) -> str:
        return f"<Analysis: {len(self.modes)} modes>"


def analyze(scene: Scene, quasi_static: bool = False) -> Analysis:
    """Every mode of the scene with its sets; the scene needs a body (mass, com, inertia).
    quasi_static=True neglects inertia: E_i = -T_i (the applied wrench balances the contact
    wrench), and no body is needed."""
    return Analysis(scene, quasi_static)


def query(scene: Scene, w=None, quasi_static: bool = False, gravity=None, forces=None) -> QueryAnswer:
    """Which modes the applied wrench produces on a scene not analysed, exactly: w (fx, fy, tau
    about the origin, N and N m), plus gravity (gx, gy, m/s^2, through the centre of mass) and
    forces [(point, force), ...] (m, N) when given. A QueryAnswer (.modes: the mode strings,
    sorted; .verdict: 'unique' | 'ambiguous' | 'inconsistent'), as `query --json`: the same modes as analyze(scene,
    quasi_static).query(w), found the fast way (certified doubles for 2 to 12 contacts, the exact
    walk otherwise; docs/robustness.md, "One question about a new scene")."""
    if not isinstance(scene, Scene):
        raise ValueError("query: expected a momentlab.Scene")
    return QueryAnswer.from_json(_momentlab.query(scene._scene, w, _flag(quasi_static, "quasi_static"), gravity, _forces(forces)))


def wrench(point, force) -> list:
    """The wrench [fx, fy, tau] of the force (fx, fy) acting through the point (x, y): tau =
    x fy - y fx about the origin (rounded to a double)."""
    return _momentlab.wrench(point, force)


def closure(scene: Scene, reference=None, length=None) -> Closure:
    """Grasp closure of the scene's contacts, decided exactly (the body is optional): a Closure
    (.form_closure, .force_closure, .form and .force as ClosureTest(holds, quality |
    unresisted_wrench), .reference, .length, .metric), as `momentlab closure --json`
    (docs/design.md, Closure). reference (m) and length (m) set the quality's metric."""
    if not isinstance(scene, Scene):
        raise ValueError("closure: expected a momentlab.Scene")
    return Closure.from_json(_momentlab.closure(scene._scene, reference, None if length is None else _number(length, "length")))


def friction_cone(point, normal, mu) -> Cone:
    """The Coulomb cone of a contact (Figure 1c): forces n + s t, |s| <= mu, at the point.
    Fractions, Decimals and numeric strings are read as typed (mu = Decimal("0.3") is 3/10)."""
    return _momentlab.friction_cone(point, normal, _exact_number(mu, "mu"))


def pure_moments(sign: int) -> Cone:
    """Pure moments: positive (sign 1), negative (-1) or both (0)."""
    if sign not in (-1, 0, 1) or isinstance(sign, bool):
        raise ValueError(f"sign: expected -1, 0 or 1, got {sign!r}")
    return _momentlab.pure_moments(int(sign))


def labels(forces) -> Labels:
    """The moment labels of a force set: a Cone, or the JSON text of a force-set file."""
    if isinstance(forces, str):
        forces = force_set_from_json(forces)
    if not isinstance(forces, Cone):
        raise ValueError("labels: expected a momentlab.Cone or the JSON text of a force set")
    return Labels(forces)


def _analysis_of(what) -> Analysis:
    if isinstance(what, Analysis):
        return what
    if isinstance(what, Scene):
        return Analysis(what)
    raise ValueError("expected a momentlab.Scene or Analysis")


def plan_tilt(scene, goal: str, wrench=None, forces=None) -> DirectionPlan:
    """The tilts (gravity directions, radians from +x) that produce mode `goal`: a DirectionPlan
    (.goal, .intervals [(from, to), ...], .best, .margin, .unique, .shared, .best_unique,
    .best_margins; best and the rest None when infeasible), as `plan tilt --json`. With `wrench`
    (FX, FY, TAU; N, N m) or `forces` acting besides the tilted force, the directions for which
    some magnitude works and .best_magnitudes (N)."""
    return DirectionPlan.from_json(_analysis_of(scene)._analysis.plan_tilt(_goal(goal), wrench, _forces(forces)))


def plan_push(scene, goal: str, mu: float = 0.5, ignore_interference: bool = False, gravity=None, wrench=None,
              forces=None) -> list:
    """The pushing table for mode `goal`: one PushCase per feature (edge, vertex) and finger slip
    (l, f, r) with .verdict, .feasible, .touch, .directions (radians), .best, and whether the goal
    is .unique or .shared there, as the "cases" of `plan push --json` (docs/planning.md); mu is
    the finger's friction (a float its binary value; a Fraction, Decimal or string exactly). With `gravity` (GX, GY; m/s^2) and/or a fixed `wrench` acting besides
    the push: the pushes for which some magnitude works, with .best_magnitudes (N)."""
    cases = _analysis_of(scene)._analysis.plan_push(_goal(goal), _exact_number(mu, "mu"), bool(ignore_interference),
                                                    gravity, wrench, _forces(forces))
    return [PushCase.from_json(c) for c in cases]


def plan_comply(scene, goal: str, centre=None, gravity=None, wrench=None, forces=None) -> Compliance:
    """Compliance, as `plan comply --json`: a Compliance (.goal, .labels: the .plus and .minus
    RegionData of E_goal's moment labels (the centres outside both work), .centre: a CentrePlan
    (.point, .label, .verdict, .intervals, .best, .margin, .unique, .shared, ...) for a given
    centre (m; floats their binary value, a Fraction, Decimal or string exactly), else None)."""
    return Compliance.from_json(_analysis_of(scene)._analysis.plan_comply(_goal(goal), centre, gravity, wrench, _forces(forces)))


def push_line(scene, point, direction, gravity=None, wrench=None, forces=None) -> list:
    """The force lambda * direction through `point` (m), lambda (N) from 0 up, added to the fixed
    wrench (`gravity` (m/s^2) through the centre of mass, plus `wrench`): a list of Bands
    (.from_, .to, .from_closed, .to_closed, .modes, .verdict; .to is math.inf for the last), as
    the "bands" of `momentlab query --push X Y DX DY --json`."""
    bands = _analysis_of(scene)._analysis.push_line(point, direction, gravity, wrench, _forces(forces))
    return [Band.from_json(b) for b in bands]


# Assemblies of several bodies (docs/assemblies.md); last, as assembly.py reads the names above.
from .assembly import Assembly, stand  # noqa: E402
