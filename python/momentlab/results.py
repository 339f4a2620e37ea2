"""The answers of query, margins, closure and the planners as small typed values (frozen
dataclasses), with the fields of the command line's `--json` output (docs/formats.md).

Units: lengths and points in the scene's length unit (m), forces and magnitudes in its force
unit (N), torques in N m about the world origin, angles in radians from +x in (-pi, pi].
Where the JSON writes "unbounded" for a number (the end of a range of magnitudes, a distance
to a set that does not exist), the field holds math.inf. The JSON key "from" is the field
`from_` (a Python keyword). A field the JSON leaves out or writes as null is None.
`X.from_json(doc)` reads the JSON form (a dict, as json.loads gives it); a key the class does
not know is a ValueError, so that no field of the JSON is dropped unseen.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from fractions import Fraction
from typing import Optional

import numpy as np

__all__ = [
    "Band", "BestMargins", "CentrePlan", "Closure", "ClosureTest", "Compliance", "DirectionPlan", "Labelling",
    "Magnitudes", "Margins", "Push", "PushCase", "QueryAnswer", "RegionData", "BodyMotion", "StandResult",
    "TiltCone",
]


def _distance(x) -> float:
    """A number of the JSON that may be the word "unbounded" (math.inf)."""
    return math.inf if x == "unbounded" else float(x)


def _point(p) -> Optional[tuple]:
    return None if p is None else tuple(float(x) for x in p)


def _arcs(intervals) -> Optional[list]:
    return None if intervals is None else [(float(a), float(b)) for a, b in intervals]


def _read(cls, doc: dict, convert: dict):
    """cls from the JSON object `doc`: each key through convert[key] (identity when absent),
    "from" into from_; unknown keys refused."""
    if not isinstance(doc, dict):
        raise ValueError(f"{cls.__name__}: expected a JSON object, got {type(doc).__name__}")
    names = {f.name for f in fields(cls)}
    values = {}
    for key, value in doc.items():
        name = "from_" if key == "from" else key
        if name not in names:
            raise ValueError(f"{cls.__name__}: unknown field {key!r}")
        values[name] = None if value is None else convert.get(name, lambda v: v)(value)
    return cls(**values)


@dataclass(frozen=True)
class QueryAnswer:
    """Which modes an applied wrench produces (`momentlab query --json`).

    modes: the mode strings whose closed E_i holds the wrench, sorted.
    verdict: 'unique' (one mode), 'ambiguous' (several) or 'inconsistent' (none).
    """

    modes: list
    verdict: str

    @classmethod
    def from_json(cls, doc: dict) -> "QueryAnswer":
        return _read(cls, doc, {"modes": list})


@dataclass(frozen=True)
class Margins:
    """How far an applied wrench may move before the answer changes (docs/design.md, Margins),
    distances of (fx, fy, tau / length) with tau about `reference` (N):

    inside: {mode: distance from the wrench to the boundary of that mode's E}, for the modes
        of the answer (math.inf when E is the whole space).
    to_other: distance to the nearest E of a mode not in the answer (math.inf when none).
    reference: the point (m) the torques are taken about; length: the length (m) dividing them.
    """

    inside: dict
    to_other: float
    reference: tuple
    length: float


@dataclass(frozen=True)
class BestMargins:
    """The margins of a plan's best action (docs/design.md, Margins; N): `inside`, one distance
    per goal mode to the boundary of its E (math.inf for the whole space), and `to_other`, to
    the nearest other mode's E (math.inf when none)."""

    inside: list
    to_other: float

    @classmethod
    def from_json(cls, doc: dict) -> "BestMargins":
        return _read(cls, doc, {"inside": lambda v: [_distance(x) for x in v], "to_other": _distance})


@dataclass(frozen=True)
class Magnitudes:
    """The magnitudes (N) of a controlled force that produce the goal: from `from_` to `to`
    (math.inf when it has no upper end). An end that is not exactly a double also has its exact
    value, from_exact / to_exact (a Fraction; None otherwise)."""

    from_: float
    to: float
    from_exact: Optional[Fraction] = None
    to_exact: Optional[Fraction] = None

    @classmethod
    def from_json(cls, doc: dict) -> "Magnitudes":
        return _read(cls, doc, {"from_": float, "to": _distance, "from_exact": Fraction, "to_exact": Fraction})


_PLAN = {
    "intervals": _arcs, "unique": _arcs, "shared": _arcs, "best": float, "margin": float,
    "best_margins": BestMargins.from_json, "best_magnitudes": Magnitudes.from_json,
}


@dataclass(frozen=True)
class DirectionPlan:
    """The directions (radians from +x) of a force through the centre of mass that produce the
    goal mode (`momentlab plan tilt --json`; docs/planning.md):

    goal: the mode's letters. intervals: closed arcs [(from, to), ...], counter-clockwise.
    best: the direction deepest inside them; margin: its angle (radians) to their nearest end.
    knife_edge: the arcs are single directions. unique / shared: the arcs where the goal is the
    only mode / one of several. best_unique: best lies where the goal is unique.
    best_margins: BestMargins of the best direction. best_magnitudes: with a fixed wrench, the
    Magnitudes (N) of the force along best that produce the goal.
    Fields the plan does not have (no best when infeasible) are None.
    """

    goal: str
    intervals: list
    best: Optional[float] = None
    margin: Optional[float] = None
    knife_edge: Optional[bool] = None
    unique: Optional[list] = None
    shared: Optional[list] = None
    best_unique: Optional[bool] = None
    best_margins: Optional[BestMargins] = None
    best_magnitudes: Optional[Magnitudes] = None

    @classmethod
    def from_json(cls, doc: dict) -> "DirectionPlan":
        return _read(cls, doc, _PLAN)


@dataclass(frozen=True)
class CentrePlan:
    """A compliance centre (m) and the directions (radians) of the force through it that produce
    the goal (`momentlab plan comply --centre X Y --json`, its "centre"): point, its moment label
    ('+', '-', '+-', 'none') for E_goal, verdict ('works', 'boundary', 'fails'), and the fields
    of DirectionPlan (without goal). A centre given as Fractions, Decimals or strings that are not
    doubles also has point_exact, its exact coordinates (Fractions)."""

    point: tuple
    label: str
    verdict: str
    intervals: list
    best: Optional[float] = None
    margin: Optional[float] = None
    knife_edge: Optional[bool] = None
    unique: Optional[list] = None
    shared: Optional[list] = None
    best_unique: Optional[bool] = None
    best_margins: Optional[BestMargins] = None
    best_magnitudes: Optional[Magnitudes] = None
    point_exact: Optional[tuple] = None

    @classmethod
    def from_json(cls, doc: dict) -> "CentrePlan":
        return _read(cls, doc, {**_PLAN, "point": _point, "point_exact": lambda p: tuple(Fraction(x) for x in p)})


@dataclass(frozen=True)
class RegionData:
    """One sheet of moment labels as plain data (m): conv(vertices) + cone(rays) + span(lines);
    kind is 'empty', 'point', 'segment', 'polygon', 'unbounded', ... (the JSON's words)."""

    kind: str
    vertices: list
    rays: list
    lines: list

    @classmethod
    def from_json(cls, doc: dict) -> "RegionData":
        points = lambda v: [_point(p) for p in v]  # noqa: E731
        return _read(cls, doc, {"vertices": points, "rays": points, "lines": points})


@dataclass(frozen=True)
class Labelling:
    """The + and - regions (RegionData) of a set's moment labels."""

    plus: RegionData
    minus: RegionData

    @classmethod
    def from_json(cls, doc: dict) -> "Labelling":
        return _read(cls, doc, {"plus": RegionData.from_json, "minus": RegionData.from_json})


@dataclass(frozen=True)
class Compliance:
    """Compliance for a goal (`momentlab plan comply --json`): labels, the moment labels of
    E_goal (the centres labelled neither + nor - work for some direction), and centre, the
    CentrePlan of a given centre (None when none was given)."""

    goal: str
    labels: Labelling
    centre: Optional[CentrePlan] = None

    @classmethod
    def from_json(cls, doc: dict) -> "Compliance":
        return _read(cls, doc, {"labels": Labelling.from_json, "centre": CentrePlan.from_json})


@dataclass(frozen=True)
class Push:
    """A push: the force through `point` (m) along `direction` (radians from +x), whose unit
    vector is `direction_vector`."""

    point: tuple
    direction: float
    direction_vector: tuple

    @classmethod
    def from_json(cls, doc: dict) -> "Push":
        return _read(cls, doc, {"point": _point, "direction_vector": _point, "direction": float})


@dataclass(frozen=True)
class PushCase:
    """One case of the pushing table (`momentlab plan push --json`, its "cases"; docs/planning.md):
    a finger on `feature` ('edge i' or 'vertex i', from from_ to to, m) slipping `slip` ('l',
    'f', 'r'). verdict: 'feasible', 'boundary' or 'no'; feasible: some push produces the goal
    with room to spare; blocked: how much of the feature other contacts block ('none', 'part',
    'all'). touch: the segments [(p, q), ...] where the finger may push; directions: the arc
    (from, to) of push directions (radians), or None; best: the Push deepest inside. unique /
    shared: the goal is the only mode / one of several for some push; best_unique: at best.
    unique_touch, unique_directions: where and how the goal is the only mode. best_margins,
    best_magnitudes: as in DirectionPlan (N). Fields a case does not have are None.
    """

    feature: str
    from_: tuple
    to: tuple
    slip: str
    verdict: str
    feasible: bool
    blocked: str
    touch: list
    directions: Optional[tuple] = None
    best: Optional[Push] = None
    unique: Optional[bool] = None
    shared: Optional[bool] = None
    best_unique: Optional[bool] = None
    unique_touch: Optional[list] = None
    unique_directions: Optional[tuple] = None
    best_margins: Optional[BestMargins] = None
    best_magnitudes: Optional[Magnitudes] = None

    @classmethod
    def from_json(cls, doc: dict) -> "PushCase":
        segments = lambda v: [(_point(p), _point(q)) for p, q in v]  # noqa: E731
        return _read(cls, doc, {
            "from_": _point, "to": _point, "touch": segments, "unique_touch": segments,
            "directions": _point, "unique_directions": _point, "best": Push.from_json,
            "best_margins": BestMargins.from_json, "best_magnitudes": Magnitudes.from_json,
        })


@dataclass(frozen=True)
class Band:
    """A band of magnitudes (N) of a push added to a fixed wrench (`momentlab query --push
    --json`, its "bands"): from from_ to to (math.inf for the last band), each end closed or
    open, and the modes (sorted) and verdict all along it. An end that is not exactly a double
    also has its exact value, from_exact / to_exact (a Fraction; None otherwise)."""

    from_: float
    to: float
    from_closed: bool
    to_closed: bool
    modes: list
    verdict: str
    from_exact: Optional[Fraction] = None
    to_exact: Optional[Fraction] = None

    @classmethod
    def from_json(cls, doc: dict) -> "Band":
        return _read(cls, doc, {"from_": float, "to": _distance, "modes": list,
                                "from_exact": Fraction, "to_exact": Fraction})


@dataclass(frozen=True)
class ClosureTest:
    """One closure test: holds; quality when it holds (the radius, in N, of the largest ball
    about 0 inside the hull of the contacts' unit wrenches (fx, fy, tau / length)); otherwise
    unresisted_wrench, a wrench (fx, fy, tau) no contact force resists."""

    holds: bool
    quality: Optional[float] = None
    unresisted_wrench: Optional[tuple] = None

    @classmethod
    def from_json(cls, doc: dict) -> "ClosureTest":
        return _read(cls, doc, {"quality": float, "unresisted_wrench": _point})


@dataclass(frozen=True)
class Closure:
    """Grasp closure (`momentlab closure --json`; docs/design.md, Closure): form_closure and
    force_closure, their ClosureTests form and force, the reference point (m) and length (m) of
    the quality's metric, and the metric in words."""

    form_closure: bool
    force_closure: bool
    form: ClosureTest
    force: ClosureTest
    reference: tuple
    length: float
    metric: str

    @classmethod
    def from_json(cls, doc: dict) -> "Closure":
        return _read(cls, doc, {"form": ClosureTest.from_json, "force": ClosureTest.from_json,
                                "reference": _point, "length": float})


def _frozen_array(v, shape) -> np.ndarray:
    """A read-only float64 array of the given shape ((n, 2) or (3,)) from JSON numbers."""
    a = np.array(v, dtype=np.float64).reshape(shape)
    a.flags.writeable = False
    return a


def _exact(x) -> Fraction:
    """A coordinate of a tilt edge: a JSON number (a double, exactly) or exact text "p/q"."""
    if isinstance(x, bool) or not isinstance(x, (int, float, str)):
        raise ValueError(f"TiltCone: expected a number or \"p/q\", got {x!r}")
    return Fraction(x)


@dataclass(frozen=True)
class BodyMotion:
    """One body's motion in a collapse mechanism (`stand --json`, its "mechanism"): body (1..N),
    twist (vx, vy, omega) as an array of shape (3,) (lengths in the scene's unit per unit time,
    omega in radians per unit time; only its direction matters, rounded), and rotation_centre
    (x, y) = (-vy, vx) / omega when it turns, else None (it translates, or stays: twist 0)."""

    body: int
    twist: np.ndarray
    rotation_centre: Optional[tuple] = None

    @classmethod
    def from_json(cls, doc: dict) -> "BodyMotion":
        return _read(cls, doc, {"body": int, "twist": lambda v: _frozen_array(v, (3,)), "rotation_centre": _point})


@dataclass(frozen=True)
class TiltCone:
    """The gravity vectors for which an assembly can stand, a closed convex cone of the plane
    (`stand --tilt --json`, its "tilt"): kind 'empty', 'ray', 'wedge', 'halfplane', 'line' or
    'plane', and directions, exact (x, y) pairs of Fractions scaled so that the larger coordinate
    is +-1: ray [d]; wedge [d1, d2] counter-clockwise; halfplane [d, -d], swept
    counter-clockwise from d; line [d, -d]; empty and plane []."""

    kind: str
    directions: list

    @classmethod
    def from_json(cls, doc: dict) -> "TiltCone":
        return _read(cls, doc, {"directions": lambda v: [(_exact(x), _exact(y)) for x, y in v]})


@dataclass(frozen=True)
class StandResult:
    """Will an assembly stand, how can it start to move, how far can it be tilted
    (`momentlab stand --json`; docs/assemblies.md):

    can_stand: an equilibrium exists (every body's gravity wrench plus its contact wrenches sum
        to zero, every contact force in its friction cone), decided exactly.
    forces: when it can, the force on body a at each contact of one equilibrium, an array of
        shape (n, 2) in the units of mass times gravity (N for kg and m/s^2); else None.
    mechanism: when it cannot, a BodyMotion per body: twists that every contact allows and
        along which gravity does positive work; else None.
    modes, verdict, motions, outcome: the contact modes (one letter per contact: s, f, r, l),
        'unique' / 'ambiguous' / 'inconsistent', the modes with a motion from rest, and 'stands'
        / 'may fall' / 'falls' / 'inconsistent'; all None when the modes were not enumerated,
        with modes_reason saying why.
    tilt: the TiltCone when asked for (tilt=True), else None.
    """

    can_stand: bool
    forces: Optional[np.ndarray] = None
    mechanism: Optional[list] = None
    modes: Optional[list] = None
    modes_reason: Optional[str] = None
    verdict: Optional[str] = None
    motions: Optional[list] = None
    outcome: Optional[str] = None
    tilt: Optional[TiltCone] = None

    @classmethod
    def from_json(cls, doc: dict) -> "StandResult":
        return _read(cls, doc, {
            "forces": lambda v: _frozen_array(v, (len(v), 2)), "mechanism": lambda v: [BodyMotion.from_json(m) for m in v],
            "modes": list, "motions": list, "tilt": TiltCone.from_json,
        })
