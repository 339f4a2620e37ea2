"""Assemblies: several movable bodies under gravity (docs/assemblies.md), and `stand`, the
question `momentlab stand` answers: will it stand, how can it start to move, for which
directions of gravity does it stand.

Bodies are numbered 1..N in the order given and 0 is the fixed world; a contact's "bodies"
[a, b] names its pair, its normal points into body a and body b receives the opposite force.
"""

from __future__ import annotations

import os
import numpy as np

from . import Body, Scene, _exact_json, _flag, _has_exact, _momentlab, _sequence, friction_cone
from ._momentlab import Cone
from .results import StandResult

__all__ = ["Assembly", "stand"]


class Assembly:
    """Bodies, the contacts between them and with the world, and fixed obstacles.

    Assembly(bodies=[Body or dict, ...], contacts=[dict, ...], obstacles=[polygon, ...],
    contact_distance=None, mu=None), in the file format of docs/formats.md ("Assemblies"): a
    body dict has "mass", "com" and optionally "name", "inertia" or "radius_of_gyration" and
    "polygon"; a contact dict has "bodies": [a, b], "point", "normal" and optionally "mu",
    "mu_kinetic", "name". Without contacts they are found from the polygons (within
    `contact_distance`, with friction `mu`), in the order of docs/formats.md.
    Assembly.from_json(text) and Assembly.from_file(path) read a scene file with "bodies" (or
    "body": the assembly of one body). Numbers are read as the command line reads the file.
    """

    def __init__(self, bodies, contacts=None, obstacles=(), contact_distance=None, mu=None, *, _assembly=None):
        if _assembly is not None:
            self._assembly = _assembly
            return
        doc: dict = {"bodies": [b._doc() if isinstance(b, Body) else b for b in _sequence(bodies, "bodies")]}
        if contacts is not None:
            doc["contacts"] = _sequence(contacts, "contacts")
        obstacles = _sequence(obstacles, "obstacles") if obstacles is not None else []
        if len(obstacles):
            doc["obstacles"] = [o if isinstance(o, dict) else {"polygon": o} for o in obstacles]
        if contact_distance is not None:
            doc["contact_distance"] = contact_distance
        if mu is not None:
            doc["mu"] = mu
        if _has_exact(doc):  # Fractions and Decimals: as the text of their decimals, read as a file is
            self._assembly = _momentlab._Assembly.from_json(_exact_json(doc, "$"))
        else:
            self._assembly = _momentlab._Assembly.from_doc(doc)

    @classmethod
    def from_json(cls, text: str) -> "Assembly":
        """The assembly of a JSON text in the file format ("bodies", or "body" for one)."""
        if not isinstance(text, str):
            raise ValueError("$: expected the JSON text of a scene (a str)")
        return cls(None, _assembly=_momentlab._Assembly.from_json(text))

    @classmethod
    def from_file(cls, path) -> "Assembly":
        """The assembly of a JSON file, read as `momentlab stand` reads it (the same checks and
        messages)."""
        return cls(None, _assembly=_momentlab._Assembly.from_file(os.fsdecode(os.fspath(path))))

    @property
    def bodies(self) -> list:
        """Per body (1..N in order) a dict: 'name', 'mass', 'com' (shape (2,)), 'inertia' and
        'radius_of_gyration' (None when not given), 'polygon' (shape (k, 2), k = 0 when none)."""
        return self._assembly.bodies

    @property
    def pairs(self) -> np.ndarray:
        """Each contact's bodies (a, b), shape (n, 2): a in 1..N, b in 0..N (0 the world)."""
        return self._assembly.pairs

    @property
    def points(self) -> np.ndarray:
        """The contact points, shape (n, 2)."""
        return self._assembly.points

    @property
    def normals(self) -> np.ndarray:
        """The contact normals as written (into body a), shape (n, 2)."""
        return self._assembly.normals

    @property
    def mu(self) -> np.ndarray:
        """The static friction coefficients, shape (n,)."""
        return self._assembly.mu

    @property
    def names(self) -> list:
        """The contacts' names ('' when none)."""
        return self._assembly.names

    @property
    def obstacles(self) -> list:
        """The fixed polygons, each of shape (k, 2)."""
        return self._assembly.obstacles

    def contact_wrenches(self, body: int) -> Cone:
        """The wrenches (fx, fy, tau about the origin) that the contacts of body `body` (1..N)
        can apply to it: the sum of its contacts' friction cones, negated where it is body b."""
        n = len(self.bodies)
        if isinstance(body, bool) or not isinstance(body, (int, np.integer)) or not 1 <= body <= n:
            raise ValueError(f"body: expected a body number 1..{n}, got {body!r}")
        total = Cone.zero()
        for (a, b), p, normal, mu in zip(self.pairs, self.points, self.normals, self.mu):
            if body in (a, b):
                cone = friction_cone(p, normal, float(mu))
                total = total + (cone if a == body else -cone)
        return total

    def __repr__(self) -> str:
        return f"<Assembly: {len(self.bodies)} bodies, {len(self.points)} contacts>"


def _assembly_of(scene) -> Assembly:
    if isinstance(scene, Assembly):
        return scene
    if isinstance(scene, Scene):
        return Assembly(None, _assembly=_momentlab._Assembly.from_scene(scene._scene))
    raise ValueError("stand: expected a momentlab.Assembly (or a Scene with a body)")


def stand(scene, gravity=None, tilt: bool = False) -> StandResult:
    """Will the assembly stand under `gravity` (gx, gy, acting on every body at its centre of
    mass; only its direction matters; default (0, -9.81), the decimal, as the command line's),
    how can it start to move, and (tilt=True) for which gravity vectors does it stand: a
    StandResult with the fields of `momentlab stand --json`, every decision exact
    (docs/assemblies.md). Floats are their binary values; Fractions, Decimals and numeric
    strings their exact ones. `scene` is an Assembly, or a Scene with a body (the assembly of
    one body)."""
    a = _assembly_of(scene)
    return StandResult.from_json(_momentlab.stand(a._assembly, gravity, _flag(tilt, "tilt")))
