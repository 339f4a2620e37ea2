"""The Python module against an exact oracle that shares no code with it (tests/python/oracle.py:
the definitions of docs/design.md as linear programs over Fractions, each answer certified),
on random scenes with dyadic numbers (so the module and the oracle read the same values):
modes, single and batch queries and verdicts, for random wrenches and for wrenches built on
the boundaries between modes (ambiguous by construction)."""

import json
import math
import random
import subprocess
import sys

import numpy as np
import pytest

import momentlab as ml
import oracle
from conftest import CLI, ROOT

SEEDS = range(60)


def scene_of(doc):
    return ml.Scene.from_json(json.dumps(doc))


@pytest.mark.parametrize("seed", SEEDS)
def test_modes_queries_and_verdicts_agree_with_the_oracle(seed):
    rng = random.Random(seed)
    doc = oracle.random_scene(rng, 1 + seed % 4, kinetic_above_static=seed % 5 == 4)
    exact = oracle.exact_scene(doc)
    a = ml.analyze(scene_of(doc))
    assert set(a.modes) == oracle.modes(exact) and len(set(a.modes)) == len(a.modes)
    assert a.modes[0] == "f" * len(doc["contacts"])
    wrenches = [oracle.random_wrench(rng) for _ in range(12)] + oracle.boundary_wrenches(exact, rng, 12)
    W = np.array(wrenches, dtype=np.float64)
    batch, verdicts = a.query(W), a.verdict(W)
    for k, w in enumerate(wrenches):
        want = oracle.query(exact, w)
        got = a.query(w)
        assert set(got) == want, (doc, w)
        assert got == sorted(want)  # sorted, as every answer
        assert sorted(m for m, hit in zip(a.modes, batch[k]) if hit) == got
        assert a.verdict(w) == verdicts[k] == oracle.verdict(len(want))


@pytest.mark.parametrize("seed", range(20))
def test_sets_hold_the_oracles_certificates(seed):
    # For each boundary wrench e and each mode i the oracle certifies (e = M a - c with a in
    # A_i, c in T_i), the module's cones hold a, c and e.
    rng = random.Random(1000 + seed)
    doc = oracle.random_scene(rng, 1 + seed % 3)
    exact = oracle.exact_scene(doc)
    a = ml.analyze(scene_of(doc))
    for e in oracle.boundary_wrenches(exact, rng, 6):
        for letters in a.modes:
            cert = oracle.produces_certificate(exact, letters, e)
            sets = a[letters]
            assert sets.applied.contains(e) == (cert is not None)
            if cert is None:
                continue
            twist = [float(x) for x in cert[0]]
            if all(float(x) == x for x in cert[0]):  # the twist as doubles, exactly
                assert sets.twists.contains(twist)


@pytest.mark.parametrize("seed", range(20))
def test_normals_as_written_and_mirror_images(seed):
    # Scaling a normal changes nothing (every condition is homogeneous in it); a mirror image
    # x -> -x exchanges r and l (t = (n.y, -n.x) turns over) and negates fx... and the torque:
    # the wrench (fx, fy, tau) becomes (-fx, fy, -tau).
    rng = random.Random(2000 + seed)
    doc = oracle.random_scene(rng, 1 + seed % 4)
    a = ml.analyze(scene_of(doc))
    scaled = json.loads(json.dumps(doc))
    for c in scaled["contacts"]:
        c["normal"] = [4.0 * c["normal"][0], 4.0 * c["normal"][1]]
    mirrored = json.loads(json.dumps(doc))
    mirrored["body"]["com"][0] = -mirrored["body"]["com"][0]
    for c in mirrored["contacts"]:
        c["point"][0] = -c["point"][0]
        c["normal"][0] = -c["normal"][0]
    swap = str.maketrans("rl", "lr")
    s, m = ml.analyze(scene_of(scaled)), ml.analyze(scene_of(mirrored))
    assert s.modes == a.modes
    assert sorted(x.translate(swap) for x in m.modes) == sorted(a.modes)
    W = np.array([oracle.random_wrench(rng) for _ in range(64)])
    assert np.array_equal(s.query(W), a.query(W))
    flipped = W * np.array([-1.0, 1.0, -1.0])
    for w, v in zip(W, flipped):
        assert sorted(x.translate(swap) for x in m.query(v)) == sorted(a.query(w))


@pytest.mark.parametrize("seed", range(30))
def test_quasi_static_agrees_with_the_oracle_without_inertia(seed):
    # Quasi-static: inertia neglected, E_i = -T_i. The oracle's LP with a zero inertia matrix
    # (mass, com and inertia all 0) decides the same question; the scene needs no body.
    rng = random.Random(3000 + seed)
    doc = oracle.random_scene(rng, 1 + seed % 3)
    exact = oracle.exact_scene(doc)
    exact.mass, exact.com, exact.inertia = oracle.Fraction(0), (oracle.Fraction(0), oracle.Fraction(0)), oracle.Fraction(0)
    a = ml.analyze(ml.Scene(contacts=doc["contacts"]), quasi_static=True)
    assert a.quasi_static and set(a.modes) == oracle.modes(exact)
    wrenches = [oracle.random_wrench(rng) for _ in range(10)] + oracle.boundary_wrenches(exact, rng, 10)
    batch = a.query(np.array(wrenches))
    for k, w in enumerate(wrenches):
        want = oracle.query(exact, w)
        assert set(a.query(w)) == want, (doc, w)
        assert {m for m, hit in zip(a.modes, batch[k]) if hit} == want
    for sets in a:
        assert sets.total.is_zero and sets.applied == -sets.contact


@pytest.mark.parametrize("seed", range(30))
def test_query_agrees_with_the_oracle(seed):
    # One question about a scene not analysed (2 to 6 contacts: the certified doubles, or the
    # exact path on degenerate scenes and boundary wrenches): the oracle's modes, sorted.
    rng = random.Random(3000 + seed)
    doc = oracle.random_scene(rng, 2 + seed % 5)
    exact, scene = oracle.exact_scene(doc), scene_of(doc)
    wrenches = [oracle.random_wrench(rng) for _ in range(6)] + oracle.boundary_wrenches(exact, rng, 6)
    for w in wrenches:
        want = oracle.query(exact, w)
        got = ml.query(scene, w)
        assert got.modes == sorted(want), (doc, w)
        assert got.verdict == oracle.verdict(len(want))


def test_query_names_what_is_missing():
    doc = oracle.random_scene(random.Random(7), 3)
    del doc["body"]
    with pytest.raises(ValueError, match=r'^\$: missing field "body" \(query needs'):
        ml.query(scene_of(doc), [0.0, -1.0, 0.0])
    with pytest.raises(ValueError, match="^wrench: expected finite numbers"):
        ml.query(scene_of(oracle.random_scene(random.Random(7), 3)), [0.0, float("nan"), 0.0])


def test_the_oracle_checks_itself_and_agrees_with_the_cli():
    # tests/python/check_oracle_against_cli.py at small sizes: the oracle's modes against twists
    # classified straight from the definitions (its self-check), and its modes and answers against
    # the command-line tool on the bundled examples and on random and Painleve scenes.
    script = ROOT / "tests" / "python" / "check_oracle_against_cli.py"
    r = subprocess.run([sys.executable, str(script), "--scenes", "6", "--painleve-scenes", "3", "--wrenches", "2",
                        "--cli", CLI], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "all agree" in r.stdout, r.stdout


def test_the_web_fixtures_are_the_oracles_answers():
    # tests/web/oracle_fixtures.json (the WebAssembly module's oracle, written by
    # tests/web/oracle_fixtures.py) holds the oracle's answers: a seeded sample of them asked again.
    fixtures = json.loads((ROOT / "tests" / "web" / "oracle_fixtures.json").read_text())
    rng = random.Random(5)
    checked = 0
    for f in rng.sample(fixtures["scenes"], 6):
        exact = oracle.exact_scene(f["scene"])
        assert sorted(oracle.modes(exact)) == f["modes"]
        for q in rng.sample(f["queries"], 3):
            assert sorted(oracle.query(exact, q["wrench"])) == q["modes"], (f["scene"], q)
            checked += 1
        for p in f["plans"]:
            k = rng.randrange(len(fixtures["angles"]))
            a = fixtures["angles"][k]
            w = oracle.wrench_at([oracle.exact(x) for x in f["scene"]["body"]["com"]],
                                 (oracle.Fraction(math.cos(a)), oracle.Fraction(math.sin(a))))
            assert sorted(m for m in f["modes"] if oracle.produces(exact, m, w)) == p["tilt"][k]
            case = rng.choice(p["push"])
            i = rng.randrange(len(case["pushes"]))
            px, py, fx, fy = (oracle.exact(x) for x in case["pushes"][i])
            assert oracle.produces(exact, p["goal"], oracle.wrench_at((px, py), (fx, fy))) == case["gives_goal"][i]
            checked += 2
    assert checked >= 20
