"""Every public function of the Python module against the command line's answers on the bundled
examples (the CLI is the library's other front door; its own tests check it against oracles),
and the scene's raw numbers where a value can be read off them."""

import dataclasses
import json
import math

import numpy as np
import pytest

import momentlab as ml
from conftest import CLI, EXAMPLES, FORCE_SETS, SCENES, as_json, cli, without_nulls



def cone_matches(cone, doc):
    for key in ("rays", "lineality", "facets", "equations"):
        got = getattr(cone, key)
        want = np.asarray(doc[key], dtype=float).reshape(-1, 3)
        assert got.shape == want.shape, key
        assert np.array_equal(got, want), key  # the same rounding of the same exact vectors
    assert cone.kind == doc["kind"] and cone.dimension == doc["dimension"]


def region_matches(region, doc):
    assert region.kind == doc["kind"]
    for key in ("vertices", "rays", "lines"):
        want = np.asarray(doc[key], dtype=float).reshape(-1, 2)
        assert np.array_equal(getattr(region, key), want), key


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_scene_reads_like_the_cli_and_round_trips(path):
    scene = ml.Scene.from_file(path)
    raw = json.loads(path.read_text())
    if "contacts" in raw:
        assert np.array_equal(scene.points, np.array([c["point"] for c in raw["contacts"]], dtype=float))
        assert np.array_equal(scene.normals, np.array([c["normal"] for c in raw["contacts"]], dtype=float))  # as written
        assert np.array_equal(scene.mu, np.array([c.get("mu", 0) for c in raw["contacts"]], dtype=float))
    again = ml.Scene.from_json(scene.to_json())
    assert again.to_json() == scene.to_json()
    assert ml.analyze(again).modes == ml.analyze(scene).modes


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_modes_and_sets_are_the_clis(path):
    a = ml.analyze(ml.Scene.from_file(path))
    doc = cli("analyze", path, "--json")
    assert a.modes == [m["mode"] for m in doc["modes"]]
    assert a.modes == cli("modes", path, "--json")["modes"]
    assert len(a) == len(a.modes) and [m.letters for m in a] == a.modes
    for k, m in enumerate(doc["modes"]):
        sets = a[k]
        assert sets.letters == m["mode"] and a[m["mode"]].letters == m["mode"]
        cone_matches(sets.twists, m["A"])
        cone_matches(sets.total, m["F"]["cone"])
        cone_matches(sets.contact, m["T"]["cone"])
        cone_matches(sets.applied, m["E"]["cone"])
        for sheet in ("plus", "minus"):
            region_matches(getattr(sets.applied.labels(), sheet), m["E"]["labels"][sheet])
            region_matches(getattr(sets.rotation_centres(), sheet), m["rotation_centres"][sheet])


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_query_single_and_batch_are_the_clis(path, tmp_path):
    a = ml.analyze(ml.Scene.from_file(path))
    rng = np.random.default_rng(17)
    # Random wrenches, and dyadic ones on a coarse grid (many on boundaries between modes).
    W = np.vstack([rng.normal(size=(40, 3)), rng.integers(-4, 5, size=(60, 3)) / 4.0])
    (tmp_path / "w.txt").write_text("\n".join(json.dumps(w.tolist()) for w in W) + "\n")
    lines = cli("query", path, "--wrenches", tmp_path / "w.txt").stdout.splitlines()
    answers = [json.loads(line) for line in lines]
    batch = a.query(W)
    verdicts = a.verdict(W)
    assert batch.shape == (len(W), len(a.modes)) and batch.dtype == bool
    for k, (w, ans) in enumerate(zip(W, answers)):
        assert a.query(w) == ans["modes"]
        assert sorted(m for m, hit in zip(a.modes, batch[k]) if hit) == ans["modes"]
        assert a.verdict(w) == ans["verdict"] == verdicts[k]
    assert a.query(np.zeros((0, 3))).shape == (0, len(a.modes))


def test_query_of_the_block_by_hand():
    # Gravity (0, -1) through the centre of mass (1/2, 1/4): tau = px fy - py fx = -1/2. At rest.
    a = ml.analyze(ml.Scene.from_file(EXAMPLES / "figure-3-block-along-wall.json"))
    assert a.query((0.0, -1.0, -0.5)) == ["ff"] and a.verdict((0.0, -1.0, -0.5)) == "unique"
    # Pulling the block straight up through the centre of mass lifts it off: ss.
    assert a.query((0.0, 1.0, 0.5)) == ["ss"]


@pytest.mark.parametrize("path", FORCE_SETS, ids=lambda p: p.stem)
def test_labels_are_the_clis(path):
    text = path.read_text()
    doc = cli("label", path, "--json")
    cone = ml.force_set_from_json(text)
    cone_matches(cone, doc["cone"])
    lab = ml.labels(text)
    for sheet in ("plus", "minus"):
        region_matches(getattr(lab, sheet), doc["labels"][sheet])
        region_matches(getattr(ml.labels(cone), sheet), doc["labels"][sheet])


def test_force_set_builders_from_raw_numbers():
    # One force (1, 0) through (0, 2): its wrench is (1, 0, p x f) = (1, 0, -2).
    f = ml.force((0, 2), (1, 0))
    assert f.rays.tolist() == [[1.0, 0.0, -2.0]]
    assert f.contains((2.0, 0.0, -4.0)) and not f.contains((1.0, 0.0, -1.0))
    # The moment of f about q is (p - q) x f = -(2 - q.y) * 1 = q.y - 2: + above y = 2 (left of
    # the directed line), - below, +- on it.
    lab = ml.labels(f)
    assert (lab.at((5, 3)), lab.at((-3, 1)), lab.at((7, 2))) == ("+", "-", "+-")
    line = ml.line_of_force((0, 2), (1, 0))
    assert line.lineality_dimension == 1 and line.contains((-3.0, 0.0, 6.0))
    through = ml.forces_through_point((1, 1))
    # forces through (1, 1): tau = fy - fx for every (fx, fy)
    assert through.contains((2.0, 5.0, 3.0)) and not through.contains((2.0, 5.0, 2.0))
    cone = ml.friction_cone((0, 0), (0, 2), 0.5)  # a normal of length 2, used as written
    assert cone.contains((1.0, 2.0, 0.0)) and cone.contains((-1.0, 2.0, 0.0)) and not cone.contains((1.01, 2.0, 0.0))
    moments = ml.pure_moments(1)
    assert moments.contains((0, 0, 3)) and not moments.contains((0, 0, -3))
    both = ml.pure_moments(0)
    assert both.contains((0, 0, -3))
    total = cone + ml.friction_cone((2, 0), (-1, 1), 0.5)
    assert total.contains((1.0, 2.0, 0.0)) and cone.issubset(total) and not total.issubset(cone)
    meet = cone & ml.Cone.from_halfspaces([[1.0, 0.0, 0.0]])
    assert meet.contains((0.5, 2.0, 0.0)) and not meet.contains((-0.5, 2.0, 0.0))
    assert ml.Cone.from_generators([[1, 0, 0], [0, 1, 0]]).dual().contains((1, 1, -5))
    assert (-cone).contains((-1.0, -2.0, 0.0)) and cone.negated() == -cone
    assert ml.Cone.zero().is_zero and ml.Cone.whole_space().dimension == 3


def test_regions_clip_for_drawing():
    # The + region of one force (1, 0) through the origin is the half-plane y >= 0.
    plus = ml.labels(ml.force((0, 0), (1, 0))).plus
    poly = plus.clipped((-1, -1, 1, 1))
    assert poly.shape[1] == 2 and poly[:, 1].min() == 0.0 and poly[:, 1].max() == 1.0
    with pytest.raises(ValueError, match="box"):
        plus.clipped((1, 1, -1, -1))


def test_scene_from_python_values_equals_the_file():
    path = EXAMPLES / "figure-3-block-along-wall.json"
    raw = json.loads(path.read_text())
    body = ml.Body(mass=1.0, com=(0.5, 0.25), inertia=0.104167, polygon=np.array(raw["body"]["polygon"], dtype=float))
    cs = ml.contacts(np.array([[0.0, 0.0], [1.0, 0.0]]), np.array([[0.0, 1.0], [0.0, 1.0]]), 0.5, names=["trailing", "leading"])
    scene = ml.Scene(body=body, contacts=cs, obstacles=[np.array(o["polygon"], dtype=float) for o in raw["obstacles"]])
    assert json.loads(scene.to_json()) == json.loads(ml.Scene.from_file(path).to_json())
    # Dicts in the file format work too, and contacts given as Contact values.
    again = ml.Scene(body=raw["body"], contacts=[ml.Contact((0, 0), (0, 1), 0.5, name="trailing"), raw["contacts"][1]],
                     obstacles=raw["obstacles"])
    assert json.loads(again.to_json()) == json.loads(scene.to_json())
    assert [c.name for c in scene.contacts] == ["trailing", "leading"]
    # A radius of gyration: inertia m rho^2 (1 * 0.5^2).
    peg = ml.Scene(body=ml.Body(2.0, (0, 0), radius_of_gyration=0.5), contacts=[ml.Contact((0, -1), (0, 1))])
    assert peg.body["inertia"] == 0.5


def test_contacts_found_from_polygons_are_the_clis(tmp_path):
    # A square resting on a floor: its two lower corners touch (the same scene as a file
    # without "contacts", read by the CLI).
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    floor = [[-2, -1], [3, -1], [3, 0], [-2, 0]]
    found = ml.find_contacts(square, [floor], mu=0.25)
    assert sorted(tuple(c.point) for c in found) == [(0.0, 0.0), (1.0, 0.0)]
    assert all(c.normal[0] == 0.0 and c.normal[1] > 0 and c.mu == 0.25 for c in found)
    scene = ml.Scene(body=ml.Body(1.0, (0.5, 0.5), 1.0 / 6.0, polygon=square), obstacles=[floor], mu=0.25)
    (tmp_path / "s.json").write_text(json.dumps({"body": {"mass": 1, "com": [0.5, 0.5], "inertia": 1 / 6,
                                                           "polygon": square}, "obstacles": [{"polygon": floor}],
                                                  "mu": 0.25}))
    assert ml.analyze(scene).modes == cli("modes", tmp_path / "s.json", "--json")["modes"]
    assert np.array_equal(scene.points, ml.Scene.from_file(tmp_path / "s.json").points)


def test_plans_are_the_clis():
    path = EXAMPLES / "figure-3-block-along-wall.json"
    a = ml.analyze(ml.Scene.from_file(path))
    for goal in a.modes:
        assert as_json(ml.plan_tilt(a, goal)) == without_nulls(cli("plan", "tilt", path, "--goal", goal, "--json"))
        push = cli("plan", "push", path, "--goal", goal, "--json")
        assert [as_json(c) for c in ml.plan_push(a, goal)] == without_nulls(push["cases"])
        assert [as_json(c) for c in ml.plan_push(ml.Scene.from_file(path), goal, mu=0.25, ignore_interference=True)] == \
            without_nulls(cli("plan", "push", path, "--goal", goal, "--mu", 0.25, "--ignore-interference", "--json")["cases"])
        for centre in [(0.5, 2.0), (-1.0, 0.25), (3.0, -1.0)]:
            want = cli("plan", "comply", path, "--goal", goal, "--centre", *centre, "--json")
            assert as_json(ml.plan_comply(a, goal, centre)) == without_nulls(want)
    # Figure 5 by hand: gravity through the centre of mass slides the block right for
    # directions in [-atan 2, 0] (docs/planning.md).
    (lo, hi), = ml.plan_tilt(a, "rr").intervals
    assert math.isclose(lo, -math.atan(2.0), rel_tol=1e-15) and hi == 0.0


def test_version_and_docstrings():
    assert ml.__version__ == "0.1.0"
    for name in ml.__all__:
        assert getattr(ml, name).__doc__, name


@pytest.mark.parametrize("name", ["closure-four-midpoints", "closure-five-contacts", "closure-antipodal-fingers"])
def test_closure_is_the_clis(name):
    path = EXAMPLES / f"{name}.json"
    got = ml.closure(ml.Scene.from_file(path))
    assert as_json(got) == without_nulls(cli("closure", path, "--json"))
    assert got == ml.closure(ml.Scene.from_file(path), reference=got.reference, length=got.length)
    # By hand (tests/mechanics/test_closure.cpp): midpoints no closure; five contacts form
    # closure; the antipodal frictional fingers force closure only.
    want = {"closure-four-midpoints": (False, False), "closure-five-contacts": (True, True),
            "closure-antipodal-fingers": (False, True)}[name]
    assert (got.form_closure, got.force_closure) == want


def test_quasi_static_is_the_clis(tmp_path):
    path = EXAMPLES / "figure-3-block-along-wall.json"
    a = ml.analyze(ml.Scene.from_file(path), quasi_static=True)
    W = np.array([[0.0, -1.0, -0.5], [1.0, 0.0, -0.25], [0.5, -1.0, -0.625], [1.0, -1.0, -0.75]])
    (tmp_path / "w.txt").write_text("\n".join(json.dumps(w.tolist()) for w in W) + "\n")
    lines = cli("query", path, "--wrenches", tmp_path / "w.txt", "--quasi-static").stdout.splitlines()
    assert [a.query(w) for w in W] == [json.loads(line)["modes"] for line in lines]
    # by hand (tests/mechanics/test_analysis.cpp): gravity at rest; a push with no load held by
    # nothing; pressed and pushed at exactly mu: at rest or sliding right
    assert [a.query(w) for w in W[:3]] == [["ff"], [], ["ff", "rr"]]


def test_margins_are_the_clis():
    path = EXAMPLES / "figure-3-block-along-wall.json"
    a = ml.analyze(ml.Scene.from_file(path))
    for w in ([1.0, -1.0, -0.75], [0.0, -1.0, -0.5], [3.0, -1.0, 0.25]):
        want = cli("query", path, "--wrench", *w, "--margin", "--json")
        got = a.margins(w)
        assert list(got.inside) == want["modes"]
        assert list(got.inside.values()) == [x if x != "unbounded" else math.inf for x in want["margins"]["inside"]]
        to_other = want["margins"]["to_other"]
        assert got.to_other == (math.inf if to_other == "unbounded" else to_other)
        assert list(got.reference) == want["margins"]["metric"]["reference"]
        assert got.length == want["margins"]["metric"]["length"]
    # by hand (tests/mechanics/test_margin.cpp): 1/sqrt(5) from the friction line
    assert math.isclose(a.margins([1.0, -1.0, -0.75]).inside["rr"], 1 / math.sqrt(5), rel_tol=1e-15)


def test_results_are_typed_values_with_inf_for_unbounded_ends():
    """Results are frozen dataclasses with the JSON's fields; a number the JSON writes
    "unbounded" is math.inf; a mapping's missing key is a KeyError."""
    path = EXAMPLES / "block-on-table.json"
    raw = json.loads(path.read_text())
    a = ml.analyze(ml.Scene.from_file(path))
    # Gravity (0, -10) and a push (1, 0) at height 0.5 (docs/planning.md): the last band, tipping
    # (sr), goes on for ever: its end is math.inf, as the CLI's "unbounded".
    bands = ml.push_line(a, (0.0, 0.5), (1.0, 0.0), gravity=(0.0, -10.0))
    assert all(isinstance(b, ml.Band) for b in bands)
    assert bands[-1].to == math.inf and bands[-1].modes == ["sr"] and isinstance(bands[-1].from_, float)
    want = cli("query", path, "--gravity", 0, -10, "--push", 0, 0.5, 1, 0, "--json")["bands"]
    assert [as_json(b) for b in bands] == want and want[-1]["to"] == "unbounded"
    # The first band ends where friction gives: mu m g = 0.5 * 1 * 10 (the file's numbers).
    mu, m = raw["contacts"][0]["mu"], raw["body"]["mass"]
    assert bands[0].modes == ["ff"] and bands[0].to == mu * m * 10
    # A fixed wrench: the magnitudes of the best tilt, with no upper end.
    plan = ml.plan_tilt(a, "rr", wrench=(0.0, 0.0, "0.1"))  # 1/10, as the CLI reads its option
    assert isinstance(plan, ml.DirectionPlan) and isinstance(plan.best_magnitudes, ml.Magnitudes)
    assert plan.best_magnitudes.to == math.inf
    want = cli("plan", "tilt", path, "--goal", "rr", "--wrench", 0, 0, 0.1, "--json")
    assert as_json(plan) == {k: v for k, v in want.items() if k not in ("fixed", "fixed_exact")}
    # A push with gravity: every case a PushCase, best_magnitudes as the CLI's (which reads -9.81
    # as typed: the string here; the float -9.81 is the double's binary value).
    cases = ml.plan_push(a, "sr", gravity=("0", "-9.81"))
    want = cli("plan", "push", path, "--goal", "sr", "--gravity", 0, -9.81, "--json")["cases"]
    assert all(isinstance(c, ml.PushCase) for c in cases) and [as_json(c) for c in cases] == without_nulls(want)
    assert any(c.best_magnitudes is not None and c.best_magnitudes.to == math.inf for c in cases)
    # Frozen values; a field the JSON does not have is refused when reading it.
    with pytest.raises(dataclasses.FrozenInstanceError):
        plan.best = 0.0
    with pytest.raises(ValueError, match="unknown field 'fixed'"):
        ml.DirectionPlan.from_json(cli("plan", "tilt", path, "--goal", "rr", "--wrench", 0, 0, 0.1, "--json"))
    assert isinstance(ml.query(ml.Scene.from_file(path), [0.0, -9.81, -4.905]), ml.QueryAnswer)
    with pytest.raises(KeyError):
        a.margins([0.0, -9.81, -4.905]).inside["rr"]
    with pytest.raises(KeyError, match='no mode "xx"'):
        a["xx"]
