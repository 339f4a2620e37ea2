"""Bad input raises ValueError with the command line's one-line message (its JSON path); nothing
crashes or aborts the interpreter: NaN, wrong shapes, wrong dtypes, empty and non-contiguous
arrays, bad files."""

import json
import math

import numpy as np
import pytest

import momentlab as ml
from conftest import EXAMPLES, cli
import oracle

BLOCK = EXAMPLES / "figure-3-block-along-wall.json"
GOOD = {"body": {"mass": 1, "com": [0.5, 0.25], "inertia": 0.1},
        "contacts": [{"point": [0, 0], "normal": [0, 1], "mu": 0.5}, {"point": [1, 0], "normal": [0, 1], "mu": 0.5}]}

# (what to change in GOOD, the JSON path the message must start with)
BAD_SCENES = [
    (lambda d: d["contacts"][0].update(mu=-1), "$.contacts[0].mu"),
    (lambda d: d["contacts"][1].update(normal=[0, 0]), "$.contacts[1].normal"),
    (lambda d: d["contacts"][0].update(point=[0, "x"]), "$.contacts[0].point[1]"),
    (lambda d: d["contacts"][0].update(point=[0, 1, 2]), "$.contacts[0].point"),
    (lambda d: d["body"].update(mass=0), "$.body.mass"),
    (lambda d: d["body"].update(com=[1e-400 * 0 + 1e300 * 1e300, 0]), "$.body.com[0]"),  # inf
    (lambda d: d["body"].update(inertia=1e-70), "$.body.inertia"),
    (lambda d: d.update(contacts=[]), "$.contacts"),
]


@pytest.mark.parametrize("change,path", BAD_SCENES)
def test_bad_scene_values_name_the_path_as_the_cli_does(change, path, tmp_path):
    doc = json.loads(json.dumps(GOOD))
    change(doc)
    with pytest.raises(ValueError) as python_error:
        ml.Scene(body=doc["body"], contacts=doc["contacts"])
    message = str(python_error.value)
    assert message.startswith(path + ":"), message
    if all(math.isfinite(x) for x in doc["body"]["com"]):  # JSON files cannot hold inf
        (tmp_path / "bad.json").write_text(json.dumps(doc))
        r = cli("modes", tmp_path / "bad.json", check=False)
        assert r.returncode == 2 and r.stderr.strip() == "momentlab: " + message
        with pytest.raises(ValueError) as from_text:
            ml.Scene.from_json(json.dumps(doc))
        assert str(from_text.value) == message


def test_nan_and_infinity_from_numpy():
    for bad in (np.nan, np.inf, -np.inf):
        with pytest.raises(ValueError, match=r"^\$\.contacts\[0\]\.point\[0\]:"):
            ml.Scene(body=GOOD["body"], contacts=ml.contacts(np.array([[bad, 0.0]]), np.array([[0.0, 1.0]]), 0.5))
        with pytest.raises(ValueError, match=r"^\$\.contacts\[0\]\.mu:"):
            ml.Scene(body=GOOD["body"], contacts=ml.contacts([[0.0, 0.0]], [[0.0, 1.0]], np.array([bad])))


def test_contacts_from_arrays_check_shapes():
    with pytest.raises(ValueError, match="points"):
        ml.contacts(np.zeros((3, 3)), np.zeros((3, 3)))
    with pytest.raises(ValueError, match="normals"):
        ml.contacts(np.zeros((3, 2)), np.zeros((2, 2)))
    with pytest.raises(ValueError, match="mu"):
        ml.contacts(np.zeros((3, 2)), np.ones((3, 2)), mu=[0.1, 0.2])
    with pytest.raises(ValueError):
        ml.contacts([["a", "b"]], [[0, 1]])
    # No contacts at all: the reader's message.
    with pytest.raises(ValueError, match=r"^\$\.contacts:"):
        ml.Scene(body=GOOD["body"], contacts=ml.contacts(np.zeros((0, 2)), np.zeros((0, 2))))


def test_bad_json_and_files():
    with pytest.raises(ValueError, match=r"^\$"):
        ml.Scene.from_json("{not json")
    with pytest.raises(ValueError, match="duplicate"):
        ml.Scene.from_json('{"body": {"mass": 1, "mass": 2}, "contacts": []}')
    with pytest.raises(ValueError):
        ml.Scene.from_json(b"{}")
    with pytest.raises(ValueError, match=r'^\$: cannot read file ".*no-such-scene.json" \(No such file or directory\)'):
        ml.Scene.from_file(EXAMPLES / "no-such-scene.json")
    with pytest.raises(ValueError, match=r"^\$: missing field \"body\""):
        ml.analyze(ml.Scene(contacts=GOOD["contacts"]))
    with pytest.raises(ValueError):
        ml.analyze("examples/figure-3-block-along-wall.json")  # a path is not a scene
    with pytest.raises(ValueError, match=r"^\$\.contacts\[0\]\.point:"):
        ml.Scene(contacts=[{"point": {"x": 0}, "normal": [0, 1]}])
    with pytest.raises(ValueError, match="expected a number, list or object"):
        ml.Scene(contacts=[{"point": [0, object()], "normal": [0, 1]}])
    with pytest.raises(ValueError, match=r'^\$\[0\]: missing field "direction"'):
        ml.force_set_from_json('[{"type": "force", "point": [0, 0]}]')


@pytest.fixture(scope="module")
def block():
    return ml.analyze(ml.Scene.from_file(BLOCK))


@pytest.mark.parametrize("w", [
    [1.0, 2.0], [[1.0, 2.0]], np.zeros((2, 4)), np.zeros((2, 3, 1)), [], "1 2 3", ["a", "b", "c"],
    [1 + 1j, 0, 0], [[1, 2, 3], [4, 5]], None, {"fx": 1}, np.array([1, 2, 3], dtype=object),
])
def test_wrenches_of_the_wrong_shape_or_type(block, w):
    with pytest.raises(ValueError, match="wrench"):
        block.query(w)
    with pytest.raises(ValueError, match="wrench"):
        block.verdict(w)


def test_non_finite_wrenches_name_the_row(block):
    W = np.zeros((5, 3))
    W[3, 1] = np.nan
    with pytest.raises(ValueError, match=r"^wrenches\[3\]: expected finite numbers"):
        block.query(W)
    with pytest.raises(ValueError, match="finite"):
        block.query([0.0, np.inf, 0.0])


def test_dtypes_and_layouts_give_the_same_answers(block):
    rng = np.random.default_rng(3)
    W = rng.integers(-3, 4, size=(200, 3))
    want = block.query(W.astype(np.float64))
    assert np.array_equal(block.query(W), want)  # integers
    assert np.array_equal(block.query(W.astype(np.float32)), want)  # small integers are exact in float32
    assert np.array_equal(block.query(W.tolist()), want)  # lists
    assert np.array_equal(block.query(np.asfortranarray(W.astype(np.float64))), want)
    wide = np.zeros((200, 6))
    wide[:, ::2] = W
    assert not wide[:, ::2].flags.c_contiguous
    assert np.array_equal(block.query(wide[:, ::2]), want)  # a strided view
    assert np.array_equal(block.query(W[::-1])[::-1], want)  # a reversed view
    assert block.query(np.zeros((0, 3))).shape == (0, len(block.modes))
    assert block.verdict(np.zeros((0, 3))).shape == (0,)


def test_bad_plans_and_modes(block):
    with pytest.raises(ValueError, match=r'^goal: no mode "xx" in this scene \(its modes: ff, ss'):
        ml.plan_tilt(block, "xx")
    with pytest.raises(ValueError, match="^mu:"):
        ml.plan_push(block, "rr", mu=-1)
    with pytest.raises(ValueError, match="^mu:"):
        ml.plan_push(block, "rr", mu=float("nan"))
    with pytest.raises(ValueError, match="^centre:"):
        ml.plan_comply(block, "rr", (0.0, float("nan")))
    with pytest.raises(ValueError, match="^centre:"):
        ml.plan_comply(block, "rr", (0.0, 1.0, 2.0))
    with pytest.raises(IndexError):
        block[len(block.modes)]
    with pytest.raises(KeyError, match="no mode"):
        block["zz"]
    no_polygon = ml.analyze(ml.Scene(body=GOOD["body"], contacts=GOOD["contacts"]))
    with pytest.raises(ValueError, match=r"^\$\.body\.polygon:"):
        ml.plan_push(no_polygon, "ff")


def test_bad_force_set_arguments():
    with pytest.raises(ValueError, match="direction"):
        ml.force((0, 0), (0, 0))
    with pytest.raises(ValueError, match="point"):
        ml.force((0, np.nan), (1, 0))
    with pytest.raises(ValueError, match="mu"):
        ml.friction_cone((0, 0), (0, 1), -0.5)
    with pytest.raises(ValueError, match="generators"):
        ml.Cone.from_generators(np.zeros((3, 2)))
    with pytest.raises(ValueError, match=r"generators\[1\]"):
        ml.Cone.from_generators([[1, 0, 0], [np.nan, 0, 0]])
    with pytest.raises(ValueError, match="point"):
        ml.labels(ml.force((0, 0), (1, 0))).at((1, 2, 3))
    with pytest.raises(ValueError):
        ml.labels(42)
    with pytest.raises(ValueError, match="body"):
        ml.find_contacts([[0, 0], [1, 0]], [])  # two vertices: not a polygon
    with pytest.raises(ValueError, match=r"obstacles\[0\]"):
        ml.find_contacts([[0, 0], [1, 0], [0, 1]], [[[0, 0], [np.nan, 0], [0, 1]]])


LADDER = [[0, 0], [0.1, 0], [2.1, 4], [2, 4]]  # drawn 0.1 into its wall
FLOOR, WALL = [[-1, -1], [3, -1], [3, 0], [-1, 0]], [[2, 0], [3, 0], [3, 5], [2, 5]]


def test_polygons_drawn_overlapping_are_refused(tmp_path):
    doc = {"body": {"mass": 1, "com": [1.05, 2], "inertia": 1, "polygon": LADDER}, "mu": 0.3,
           "obstacles": [{"polygon": FLOOR}, {"polygon": WALL}]}
    with pytest.raises(ValueError) as python_error:
        ml.Scene(body=doc["body"], obstacles=[FLOOR, WALL], mu=0.3)
    message = str(python_error.value)
    assert message.startswith("$.obstacles[1].polygon: overlaps the body polygon ($.body.polygon), for instance at ("), message
    (tmp_path / "ladder.json").write_text(json.dumps(doc))
    r = cli("modes", tmp_path / "ladder.json", check=False)
    assert r.returncode == 2 and r.stderr.strip() == "momentlab: " + message
    with pytest.raises(ValueError, match=r"^find_contacts: the body polygon overlaps obstacle 1, for instance at \("):
        ml.find_contacts(LADDER, [FLOOR, WALL])
    touching = [[0, 0], [0.125, 0], [2, 4], [1.875, 4]]  # against the wall: found, not refused
    assert len(ml.find_contacts(touching, [FLOOR, WALL])) == 3


def test_files_are_read_as_the_cli_reads_them(tmp_path):
    (tmp_path / "nul.json").write_bytes(b'{"contacts": [{"point": [0, 0], "normal": [0, 1]}]}\0')
    (tmp_path / "latin1.json").write_bytes(b"\xff")
    (tmp_path / "null.json").write_text("null")
    for path in [tmp_path / "nul.json", tmp_path / "latin1.json", tmp_path / "null.json", tmp_path, "/dev/zero"]:
        r = cli("modes", path, check=False)
        assert r.returncode == 2
        with pytest.raises(ValueError) as e:
            ml.Scene.from_file(path)
        assert "momentlab: " + str(e.value) == r.stderr.strip(), path


def test_python_values_that_once_crashed_or_slipped_through():
    # numpy long doubles (their tolist() is themselves), values that contain themselves, and
    # nesting deeper than any scene needs: ValueError, never a crash.
    body = {"mass": 1, "com": [0, 0], "inertia": 1}
    s = ml.Scene(body=body, contacts=[{"point": [np.longdouble(0.5), 0], "normal": [0, 1]}])
    assert s.points.tolist() == [[0.5, 0.0]]
    with pytest.raises(ValueError, match=r"^\$\.contacts\[0\]\.point\[0\]: too small"):
        ml.Scene(body=body, contacts=[{"point": [np.longdouble("1e-4000"), 0], "normal": [0, 1]}])
    with pytest.raises(ValueError, match=r"^\$\.contacts\[0\]\.point\[1\]: expected a real number"):
        ml.Scene(body=body, contacts=[{"point": [0, np.clongdouble(1j)], "normal": [0, 1]}])
    p = [0, 0]
    p.append(p)
    with pytest.raises(ValueError, match="nested more than 100 levels"):
        ml.Scene(body=body, contacts=[{"point": p, "normal": [0, 1]}])
    deep = 0
    for _ in range(30000):
        deep = [deep]
    with pytest.raises(ValueError, match="nested more than 100 levels"):
        ml.Scene(body=body, contacts=[{"point": deep, "normal": [0, 1]}])
    with pytest.raises(ValueError, match="^contacts: expected a list"):
        ml.Scene(body=body, contacts=5)
    assert len(ml.Scene(body=body, contacts=(c for c in [{"point": [0, 0], "normal": [0, 1]}])).points) == 1


def test_unknown_fields_warn_and_raise_under_error_filters():
    text = '{"contacts": [{"point": [0, 0], "normal": [0, 1]}], "foo": 1}'
    with pytest.warns(UserWarning, match=r"^\$\.foo: "):
        ml.Scene.from_json(text)
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(UserWarning, match=r"^\$\.foo: "):
            ml.Scene.from_json(text)


def test_numbers_outside_the_clis_range_and_unrepresentable_answers(block):
    for w in ([1e300, -1e300, 0.0], [5e-324, 0.0, 0.0]):
        with pytest.raises(ValueError, match="^wrench: out of range"):
            block.query(w)
        with pytest.raises(ValueError, match=r"^wrenches\[1\]: out of range"):
            block.query(np.array([[0.0, -1.0, -0.5], w]))
    with pytest.raises(ValueError, match="^centre: out of range"):
        ml.plan_comply(block, "rr", (5e-324, 0.0))
    with pytest.raises(ValueError, match="^mu:"):
        ml.friction_cone((0, 0), (0, 1), 1e300)
    with pytest.raises(ValueError, match="^mu:"):
        ml.friction_cone((0, 0), (0, 1), "0.5 N")  # a numeric string is its decimal; this is not one
    # A vector is in range by its largest coordinate (docs/formats.md, as the CLI and scene files
    # read vectors): (1, 1e-300) is accepted, (1e-300, 1e-300) refused.
    ml.force((0, 1e60), (1, 1e-300))
    with pytest.raises(ValueError, match=r"^direction: out of range"):
        ml.force((0, 1e60), (1e-300, 1e-300))


def test_one_rule_for_vectors_in_every_front_end(block):
    # Issue 44, item 4: the CLI answers [1, -2, 5e-324] and [1, 0, 1e-61] on block-on-table.json;
    # Python refused both (a per-coordinate rule). The answers against the independent oracle.
    doc = json.loads((EXAMPLES / "block-on-table.json").read_text())
    scene = ml.Scene.from_json(json.dumps(doc))
    exact = oracle.exact_scene(doc)
    for w in ([1.0, -2.0, 5e-324], [1.0, 0.0, 1e-61]):
        want = sorted(oracle.query(exact, w))
        assert ml.analyze(scene).query(w) == want
        assert ml.query(scene, w).modes == want
        assert ml.analyze(scene).query(np.array([w, w])).sum() == 2 * len(want)
    assert sorted(oracle.query(exact, [1.0, -2.0, 5e-324])) == ["fs", "rs"]
    with pytest.raises(ValueError, match=r"^wrench: out of range \(expected the largest coordinate"):
        ml.query(scene, [1e-61, 0.0, 0.0])


def test_an_unknown_mode_of_the_mapping_is_a_key_error(block):
    with pytest.raises(KeyError, match='no mode "xx"'):
        block["xx"]
    assert "xx" not in block


def test_complex_strings_and_masked_arrays_are_refused(block):
    with pytest.raises(ValueError, match="^points: expected real numbers"):
        ml.contacts([[0, 1j]], [[0, 1]])
    with pytest.raises(ValueError, match="^points: expected real numbers"):
        ml.contacts(np.array([["0", "1"]]), [[0, 1]])
    with pytest.raises(ValueError, match="^point: expected numbers"):
        ml.force(("0", "zero"), ("1", "0"))  # numeric strings are decimals (test_decimals_inputs.py)
    with pytest.raises(ValueError, match="^wrench: expected real numbers"):
        ml.force((0, 0), (1, 0)).contains([1, -1, -0.75 + 1j])
    with pytest.raises(ValueError, match="^wrench: a masked array"):
        block.query(np.ma.masked_array([1.0, -1.0, -0.75], mask=[0, 1, 0]))
    with pytest.raises(ValueError, match="^goal: expected a mode string"):
        ml.plan_tilt(block, 5)
    with pytest.raises(ValueError, match="^sign:"):
        ml.pure_moments(1.5)
    assert "rr" in block and "zz" not in block
    modes = block.modes
    modes.append("zz")
    assert "zz" not in block.modes and len(block) == 10


def test_found_contacts_round_trip_with_their_distance():
    s = ml.Scene(body=dict(mass=1, com=[0, 1], inertia=0.2, polygon=[[-1, 0.05], [1, 0.05], [1, 2], [-1, 2]]),
                 obstacles=[[[-0.5, -1], [0.5, -1], [0, 0]]], contact_distance=0.1)
    again = ml.Scene.from_json(s.to_json())
    assert json.loads(again.to_json()) == json.loads(s.to_json())
    assert json.loads(s.to_json())["contact_distance"] == 0.1


@pytest.mark.parametrize("flag", ["yes", "false", [1], 2.5, 2, None])
def test_quasi_static_is_true_or_false(flag):
    # A string such as "false" is refused, not read as true (found by the review of query_once, now query).
    scene = ml.Scene.from_file(str(BLOCK))
    with pytest.raises(ValueError, match="quasi_static: expected True or False"):
        ml.analyze(scene, quasi_static=flag)
    with pytest.raises(ValueError, match="quasi_static: expected True or False"):
        ml.query(scene, [0.0, -1.0, 0.0], quasi_static=flag)
    for ok in (True, False, np.bool_(True), 0, 1):
        assert ml.analyze(scene, quasi_static=ok).quasi_static == bool(ok)
