"""docs/problems.md: textbook problems worked by hand, each a bundled example (examples/problem-*.json
and the paper's block along the wall). Every expected value here is the hand derivation of
docs/problems.md, evaluated in exact rationals (fractions.Fraction) from the scene file's raw
numbers; the command line and the library are only asked the question."""

import json
import math
import subprocess
from fractions import Fraction as Q

import pytest

import momentlab as ml
from conftest import CLI, EXAMPLES, cli

G = 9.81  # the gravity of the commands in docs/problems.md


def raw(name):
    return json.loads((EXAMPLES / name).read_text())


def json_of(*args):
    r = subprocess.run([CLI, *map(str, args), "--json"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def close(x, want, tol=1e-12):
    return abs(x - float(want)) <= tol * max(1.0, abs(float(want)))


# ---------------------------------------------------------------------------------------------
# The ladder against a wall: foot (a, 0) on the floor, top (0, h) on the wall, centre of mass
# halfway, mu at both ends. It stands (ff) iff a (1 - mu^2) <= 2 mu h, i.e. tan(theta) >=
# (1 - mu^2) / (2 mu); it slides (rr: foot away from the wall, top down) iff a (1 - mu^2) >= 2 mu h.


def ladder_stands(a, h, mu):
    return a * (1 - mu * mu) <= 2 * mu * h


def ladder_slides(a, h, mu):
    return a * (1 - mu * mu) >= 2 * mu * h


def ladder_scene(a, h, mu):
    return ml.Scene.from_json(json.dumps({
        "body": {"mass": 1.0, "com": [a / 2, h / 2], "inertia": 1 / 3},
        "contacts": [{"point": [a, 0.0], "normal": [0, 1], "mu": mu},
                     {"point": [0.0, h], "normal": [1, 0], "mu": mu}]}))


def ladder_answer(a, h, mu):
    """The modes of the ladder's weight (0, -1) through its centre of mass (a/2, h/2)."""
    return ml.analyze(ladder_scene(a, h, mu)).query([0.0, -1.0, -a / 2])


def test_the_bundled_ladder_stands_at_60_degrees():
    doc = raw("problem-ladder.json")
    foot, top = doc["contacts"][0], doc["contacts"][1]
    a, h, mu = Q(foot["point"][0]), Q(top["point"][1]), Q(foot["mu"])
    assert Q(top["mu"]) == mu and foot["point"][1] == 0 and top["point"][0] == 0
    assert ladder_stands(a, h, mu) and not ladder_slides(a, h, mu)
    m, c = Q(doc["body"]["mass"]), [Q(x) for x in doc["body"]["com"]]
    assert c == [a / 2, h / 2]
    weight = [0, -m * Q(G), -c[0] * m * Q(G)]  # (0, -mg) through c: torque c.x * (-mg)
    got = json_of("query", EXAMPLES / "problem-ladder.json", "--wrench", *map(float, weight))
    assert "ff" in got["modes"] and "rr" not in got["modes"]


def test_a_climber_three_quarters_up_the_bundled_ladder():
    # The ladder stands while (1 + mu^2) N_B <= mu (mg + W), N_B = (mg a/2 + W (a - x)) / (h + mu a).
    doc = raw("problem-ladder.json")
    a, h, mu = Q(doc["contacts"][0]["point"][0]), Q(doc["contacts"][1]["point"][1]), Q(doc["contacts"][0]["mu"])
    mg, x = Q(doc["body"]["mass"]) * Q(G), Q(0.25)
    assert a / h > mu  # the case of the derivation: the wall's friction helps the foot
    k = mu * (h + mu * a)
    w_max = mg * (k - (1 + mu * mu) * a / 2) / ((1 + mu * mu) * (a - x) - k)
    bs = json_of("query", EXAMPLES / "problem-ladder.json", "--gravity", 0, -G, "--push", 0.25, 1.3, 0, -1)["bands"]
    end, _ = at_rest_until(bs)
    assert close(end, w_max) and abs(float(w_max) - 3.049) < 5e-4, (end, float(w_max))


@pytest.mark.parametrize("mu", [0.3, 0.2, 0.5, 0.75])
def test_the_ladder_stands_exactly_above_the_critical_angle(mu):
    theta_c = math.atan((1 - mu * mu) / (2 * mu))
    angles = [k / 32 * math.pi / 2 for k in range(1, 32)]
    angles += [theta_c + d for d in (-1e-3, -1e-9, -1e-12, 1e-12, 1e-9, 1e-3)]
    for theta in angles:
        a, h = 2 * math.cos(theta), 2 * math.sin(theta)
        modes = ladder_answer(a, h, mu)
        assert ("ff" in modes) == ladder_stands(Q(a), Q(h), Q(mu)), (mu, theta, modes)
        assert ("rr" in modes) == ladder_slides(Q(a), Q(h), Q(mu)), (mu, theta, modes)


def test_bisection_with_the_library_finds_the_critical_angle():
    mu = 0.3
    lo, hi = 0.1, 1.5  # slides at lo, stands at hi
    for _ in range(60):
        mid = (lo + hi) / 2
        if "ff" in ladder_answer(2 * math.cos(mid), 2 * math.sin(mid), mu):
            hi = mid
        else:
            lo = mid
    assert abs(hi - math.atan((1 - mu * mu) / (2 * mu))) < 1e-12
    assert abs(math.degrees(hi) - 56.6) < 0.05


# ---------------------------------------------------------------------------------------------
# The block pushed horizontally at height h on its rear face: at rest up to P* = min(mu m g,
# m g w / (2 h)); beyond, it slides (rr) when mu < w / (2 h), tips about its front corner (sf)
# when mu > w / (2 h). While it slides, a corner lifts where the moment about the centre of mass
# sets that corner's normal force to 0.


def block():
    doc = raw("problem-block-push.json")
    (x0, y0), (x1, y1) = doc["contacts"][0]["point"], doc["contacts"][1]["point"]
    assert y0 == y1 == 0 and x0 == 0 and doc["contacts"][0]["mu"] == doc["contacts"][1]["mu"]
    poly = doc["body"]["polygon"]
    b = {"w": Q(x1), "H": Q(max(p[1] for p in poly)), "mu": Q(doc["contacts"][0]["mu"]),
         "mg": Q(doc["body"]["mass"]) * Q(G), "c": [Q(v) for v in doc["body"]["com"]]}
    assert b["c"] == [b["w"] / 2, b["H"] / 2]
    return b


def bands(h, *more):
    return json_of("query", EXAMPLES / "problem-block-push.json", "--gravity", 0, -G, "--push", 0, h, 1, 0, *more)["bands"]


def at_rest_until(bs):
    """The largest push of a band holding ff, and the band after it."""
    last = max(i for i, b in enumerate(bs) if "ff" in b["modes"])
    end = bs[last]["to"]
    after = next(b for b in bs[last + 1:] if b["from"] == end and "ff" not in b["modes"])
    return end, after


def lift_push(b, h):
    """While sliding (rr): moments about the centre of mass, N_rear + N_front = m g:
    -(h - H/2) P - (w + mu H)/2 N_rear + (w - mu H)/2 N_front = 0. The push at which a normal
    force reaches 0, and the mode that starts there (the rear lifts: sr; the front: rs)."""
    w, H, mu, mg = b["w"], b["H"], b["mu"], b["mg"]
    arm = h - H / 2
    if arm > 0 and w - mu * H > 0:
        return mg * (w - mu * H) / (2 * arm), "sr"
    if arm < 0:
        return mg * (w + mu * H) / (2 * -arm), "rs"
    return None, None


@pytest.mark.parametrize("h", [0.25, 0.5, 0.875, 1.25, 1.5])
def test_the_block_slides_or_tips_at_the_hand_thresholds(h):
    b = block()
    w, mu, mg = b["w"], b["mu"], b["mg"]
    slide, tip = mu * mg, mg * w / (2 * Q(h))
    end, after = at_rest_until(bands(h))
    assert close(end, min(slide, tip)), (end, slide, tip)
    if slide < tip:
        assert "rr" in after["modes"] and "sf" not in after["modes"], after
        lift, mode = lift_push(b, Q(h))
        assert lift is not None and lift > slide
        assert close(after["to"], lift), (after, lift)
        following = next(x for x in bands(h) if x["from"] == after["to"] and "rr" not in x["modes"])
        assert mode in following["modes"], following
    else:
        assert "sf" in after["modes"] and "rr" not in after["modes"], after


@pytest.mark.parametrize("h", [0.25, 0.5, 0.875, 1.25, 1.5])
def test_quasi_static_the_same_threshold_then_no_motion_can_be_held(h):
    b = block()
    bs = bands(h, "--quasi-static")
    end, after = at_rest_until(bs)
    assert close(end, min(b["mu"] * b["mg"], b["mg"] * b["w"] / (2 * Q(h))))
    assert after["modes"] == [] and after["verdict"] == "inconsistent" and after["to"] == "unbounded"


# ---------------------------------------------------------------------------------------------
# The peg in the hole: contacts (-1/2, 0) on the left wall, (1/2, 1) on the right wall (normals
# horizontal, into the peg), mu = 1/2, centre of mass (0, 1/2). A force (x, -1) through (0, h)
# inserts (rl) iff x lies between 0 and 1 / (h - 3/4) (h >= 5/4 or h <= 1/4; x = 0 only between);
# for h >= 5/4 it jams (ff) iff its direction is (1, t) with -(h - 3/4) <= t <= h - 1/4.


def peg_ok():
    doc = raw("problem-peg-in-hole.json")
    c = doc["contacts"]
    assert [c[0]["point"], c[0]["normal"], c[1]["point"], c[1]["normal"]] == [[-0.5, 0], [1, 0], [0.5, 1], [-1, 0]]
    assert c[0]["mu"] == c[1]["mu"] == 0.5 and doc["body"]["com"] == [0, 0.5]


def comply(goal, h):
    return json_of("plan", "comply", EXAMPLES / "problem-peg-in-hole.json", "--goal", goal, "--centre", 0, h)["centre"]


def same_arcs(got, want):
    assert len(got) == len(want), (got, want)
    for (a, b), (c, d) in zip(got, want):
        assert close(a, c) and close(b, d), (got, want)


@pytest.mark.parametrize("h", [Q(2), Q(3), Q(5, 4), Q(1), Q(1, 2), Q(1, 4), Q(0), Q(-1)])
def test_the_peg_inserts_for_the_hand_derived_directions(h):
    peg_ok()
    down = -math.pi / 2
    if Q(1, 4) < h < Q(5, 4):
        want = [[down, down]]
    else:
        end = math.atan2(-1, 1 / (h - Q(3, 4)))  # the direction (1 / (h - 3/4), -1)
        want = [[down, end]] if h >= Q(5, 4) else [[end, down]]
    same_arcs(comply("rl", float(h))["intervals"], want)


@pytest.mark.parametrize("h", [Q(2), Q(3), Q(5, 4)])
def test_the_peg_jams_for_the_hand_derived_directions(h):
    peg_ok()
    same_arcs(comply("ff", float(h))["intervals"], [[-math.atan(h - Q(3, 4)), math.atan(h - Q(1, 4))]])


def test_a_centre_at_the_peg_tip_jams_pushes_to_the_left():
    # By hand for h = 0: a force (-1, t) through (0, 0) is held iff -3/4 <= t <= 0.
    peg_ok()
    same_arcs(comply("ff", 0)["intervals"], [[-math.pi, math.atan2(-3, -4)]])


# ---------------------------------------------------------------------------------------------
# Two fingers on the square's sides x = -1 and x = 1 at heights y1, y2, normals inward, mu each:
# the + region of the friction cones' sum is {y1 + mu |1 + x| <= y <= y2 - mu |1 - x|}, the -
# region its mirror; both are empty (force closure) iff |y1 - y2| < 2 mu. Two contacts never give
# form closure.


def grasp(tmp_path, y1, y2, mu):
    doc = raw("problem-two-finger-grasp.json")
    doc["contacts"][0]["point"], doc["contacts"][1]["point"] = [-1, y1], [1, y2]
    doc["contacts"][0]["mu"] = doc["contacts"][1]["mu"] = mu
    del doc["body"]["polygon"]  # fingers on the lines x = -1 and x = 1, beyond the square too
    path = tmp_path / f"grasp-{y1}-{y2}-{mu}.json"
    path.write_text(json.dumps(doc))
    return json_of("closure", path)


def test_the_bundled_grasp_is_force_closure_not_form_closure():
    doc = raw("problem-two-finger-grasp.json")
    (l, r) = doc["contacts"]
    assert l["normal"] == [1, 0] and r["normal"] == [-1, 0] and l["point"][0] == -1 and r["point"][0] == 1
    assert abs(Q(l["point"][1]) - Q(r["point"][1])) < 2 * Q(l["mu"])
    got = json_of("closure", EXAMPLES / "problem-two-finger-grasp.json")
    assert got["force_closure"] is True and got["form_closure"] is False


@pytest.mark.parametrize("mu", [0.125, 0.3, 0.5, 1.0])
def test_two_fingers_hold_iff_the_offset_is_below_twice_mu(tmp_path, mu):
    for offset in (0.0, mu, 2 * mu - 1 / 64, 2 * mu, 2 * mu + 1 / 64, 3 * mu):
        for y1, y2 in ((offset, 0.0), (0.0, -offset), (0.25, 0.25 + offset)):
            got = grasp(tmp_path, y1, y2, mu)
            assert got["form_closure"] is False
            assert got["force_closure"] == (abs(Q(y1) - Q(y2)) < 2 * Q(mu)), (y1, y2, mu)


# ---------------------------------------------------------------------------------------------
# The paper's block along the wall (Mason 1991; docs/planning.md): contacts (0, 0), (1, 0),
# normal +y, mu = 1/2, mass 1, centre of mass (1/2, 1/4). E_rr = cone{(1, 0, -1/4), (1/2, -1, 0),
# (1/2, -1, -1)}: a wrench is in it iff alpha = fx + fy/2 >= 0, beta + gamma = -fy >= 0 and
# gamma = -tau - alpha/4 in [0, -fy].


def in_e_rr(f):
    fx, fy, tau = f
    alpha = fx + fy / 2
    gamma = -tau - alpha / 4
    return alpha >= 0 and -fy >= 0 and 0 <= gamma <= -fy


def test_the_paper_block_figure_3_rr_by_hand():
    doc = raw("figure-3-block-along-wall.json")
    assert [c["point"] for c in doc["contacts"]] == [[0, 0], [1, 0]] and doc["body"]["com"] == [0.5, 0.25]
    inside = ([Q(1), Q(-1), Q(-3, 4)], [Q(1, 2), Q(-1), Q(-1, 2)], [Q(2), Q(-1), Q(-1)])
    outside = ([Q(0), Q(-1), Q(-1, 2)], [Q(1), Q(-1), Q(-2)], [Q(1), Q(-1), Q(1, 2)], [Q(-1), Q(-1), Q(-3, 4)],
               [Q(1), Q(1), Q(-3, 4)])
    assert all(in_e_rr(f) for f in inside) and not any(in_e_rr(f) for f in outside)
    for f in inside + outside:
        got = json_of("query", EXAMPLES / "figure-3-block-along-wall.json", "--wrench", *map(float, f))
        assert ("rr" in got["modes"]) == in_e_rr(f), (f, got)


def test_the_paper_block_figures_5_and_6_by_hand():
    tilt = json_of("plan", "tilt", EXAMPLES / "figure-3-block-along-wall.json", "--goal", "rr")
    same_arcs(tilt["intervals"], [[-math.atan(2), 0.0]])
    push = json_of("plan", "push", EXAMPLES / "figure-3-block-along-wall.json", "--goal", "rr", "--edge", 3, "--slip", "l")
    (case,) = push["cases"]
    assert case["verdict"] == "feasible"
    (p, q), = case["touch"]
    assert sorted([p[1], q[1]]) == [3 / 16, 1 / 2] and p[0] == q[0] == 0
