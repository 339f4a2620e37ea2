"""The command line's text and JSON say the same things: the contacts found from the polygons
(checked against a hand derivation from the file's numbers) and every region of `analyze`
(read back from the text and compared with --json); typed inputs echoed with their exact values."""

import json
import math
import re
import subprocess
from fractions import Fraction as Q

import pytest

from conftest import CLI, EXAMPLES, cli

STOP = EXAMPLES / "block-against-a-stop.json"


def on_segment(p, a, b):
    """p on the closed segment ab, exactly."""
    p, a, b = ([Q(x) for x in v] for v in (p, a, b))
    cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
    return cross == 0 and min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def incidences(doc):
    """Every vertex of the body on an edge of an obstacle, and every obstacle vertex on an edge of
    the body (not at one of the body's vertices), from the file's numbers: (vertex polygon, vertex,
    edge polygon, edge), polygons named by their path in the file."""
    body = doc["body"]["polygon"]
    out = set()
    for k, o in enumerate(doc["obstacles"]):
        name = f"$.obstacles[{k}].polygon"
        for mine, theirs, mine_name, their_name in ((body, o["polygon"], "$.body.polygon", name),
                                                    (o["polygon"], body, name, "$.body.polygon")):
            for i, v in enumerate(mine):
                if mine is not body and any(Q(v[0]) == Q(u[0]) and Q(v[1]) == Q(u[1]) for u in body):
                    continue
                for j in range(len(theirs)):
                    if on_segment(v, theirs[j], theirs[(j + 1) % len(theirs)]):
                        out.add((mine_name, i, their_name, j))
    return out


def test_contacts_found_from_polygons_are_listed_as_derived_by_hand():
    doc = json.loads(STOP.read_text())
    assert "contacts" not in doc
    body, (floor, stop) = doc["body"]["polygon"], (o["polygon"] for o in doc["obstacles"])
    # By hand: the floor's top edge is its edge 2, from (3, 0) to (-2, 0), at y = 0; the body's
    # vertices 0 (0, 0) and 1 (1, 0) lie on it, its others at y = 1 above it. The stop's tip, its
    # vertex 0 at (1, 1/2), lies on the body's edge 1 from (1, 0) to (1, 1); its other vertices are
    # at x = 2, right of the body. Each touching vertex's neighbours stay on the outer side of the
    # touched edge's line, so each incidence is a contact.
    assert floor[2] == [3, 0] and floor[3] == [-2, 0] and body[0] == [0, 0] and body[1] == [1, 0]
    assert stop[0] == [1, 0.5] and body[1] == [1, 0] and body[2] == [1, 1]
    assert incidences(doc) == {("$.body.polygon", 0, "$.obstacles[0].polygon", 2),
                               ("$.body.polygon", 1, "$.obstacles[0].polygon", 2),
                               ("$.obstacles[1].polygon", 0, "$.body.polygon", 1)}
    # The normals into the body: the floor's outward normal (0, 1) (the counter-clockwise edge
    # (3, 0) -> (-2, 0) turned clockwise); the body's edge 1 turned counter-clockwise, (-1, 0).
    want = [
        {"point": [0.0, 0.0], "normal": [0.0, 1.0], "vertex": {"polygon": "$.body.polygon", "index": 0},
         "edge": {"polygon": "$.obstacles[0].polygon", "index": 2}},
        {"point": [1.0, 0.0], "normal": [0.0, 1.0], "vertex": {"polygon": "$.body.polygon", "index": 1},
         "edge": {"polygon": "$.obstacles[0].polygon", "index": 2}},
        {"point": [1.0, 0.5], "normal": [-1.0, 0.0], "vertex": {"polygon": "$.obstacles[1].polygon", "index": 0},
         "edge": {"polygon": "$.body.polygon", "index": 1}},
    ]
    key = lambda c: (c["point"], c["normal"])  # noqa: E731
    found = cli("modes", STOP, "--json")["found_contacts"]
    assert sorted(found, key=key) == sorted(want, key=key)
    assert cli("analyze", STOP, "--json")["found_contacts"] == found
    # Laid out as the rest of each document: compact for modes; for analyze, two-space indents
    # (nlohmann's dump(2), which json.dumps(indent=2) matches for these keys and numbers).
    for command, layout in (("modes", lambda d: json.dumps(d, separators=(",", ":"))),
                            ("analyze", lambda d: json.dumps(d, indent=2))):
        out = subprocess.run([CLI, command, str(STOP), "--json"], capture_output=True, text=True, check=True).stdout
        assert out == layout(json.loads(out)) + "\n", command
    # In the order of the contacts (the mode letters'): the scene's contacts as the CLI writes them.
    for j, c in enumerate(found):
        assert re.search(rf"contact {j + 1} at \({c['point'][0]:g}, {c['point'][1]:g}\), normal "
                         rf"\({c['normal'][0]:g}, {c['normal'][1]:g}\)", cli("modes", STOP).stdout)
    # The text: one line per contact, the same facts.
    for command in ("modes", "analyze"):
        text = cli(command, STOP).stdout
        lines = re.findall(r"^  contact (\d+) at \(([^,]+), ([^)]+)\), normal \(([^,]+), ([^)]+)\): vertex (\d+) of "
                           r"(the body|obstacle \d+) on edge (\d+) of (the body|obstacle \d+)$", text, re.M)
        assert len(lines) == 3, text
        for (n, x, y, nx, ny, v, vof, e, eof), c in zip(lines, found):
            path = lambda name: "$.body.polygon" if name == "the body" else f"$.obstacles[{name.split()[1]}].polygon"  # noqa: E731
            assert [float(x), float(y)] == c["point"] and [float(nx), float(ny)] == c["normal"]
            assert {"polygon": path(vof), "index": int(v)} == c["vertex"]
            assert {"polygon": path(eof), "index": int(e)} == c["edge"]


@pytest.mark.parametrize("reverse", [("body",), ("floor", "stop"), ("body", "floor", "stop")])
def test_found_contacts_name_the_vertices_and_edges_as_given_clockwise(tmp_path, reverse):
    """Polygons given clockwise: the indices are those of the file's order, as the exact
    incidences of the file's numbers give them."""
    doc = json.loads(STOP.read_text())
    polygons = {"body": doc["body"], "floor": doc["obstacles"][0], "stop": doc["obstacles"][1]}
    for name in reverse:
        polygons[name]["polygon"] = polygons[name]["polygon"][::-1]
    path = tmp_path / "reversed.json"
    path.write_text(json.dumps(doc))
    found = cli("modes", path, "--json")["found_contacts"]
    got = {(c["vertex"]["polygon"], c["vertex"]["index"], c["edge"]["polygon"], c["edge"]["index"]) for c in found}
    assert len(found) == 3 and got == incidences(doc)


def test_given_contacts_are_not_listed_as_found():
    path = EXAMPLES / "block-on-table.json"
    assert "found_contacts" not in cli("modes", path, "--json")
    assert "found_contacts" not in cli("analyze", path, "--json")
    assert "found from the polygons" not in cli("modes", path).stdout


def parse_region(text):
    """'unbounded: vertices (0, 1) (2, 3); rays (1, 0)' -> {'kind', 'vertices', 'rays', 'lines'}."""
    kind, _, rest = text.partition(": ")
    out = {"kind": kind, "vertices": [], "rays": [], "lines": []}
    for part in filter(None, rest.split("; ")):
        name, _, points = part.partition(" ")
        assert name in ("vertices", "rays", "lines") and not out[name], text
        out[name] = [[float(x), float(y)] for x, y in re.findall(r"\(([^,]+), ([^)]+)\)", points)]
    return out


def same_region(got, want):
    assert got["kind"] == want["kind"]
    for key in ("vertices", "rays", "lines"):
        assert len(got[key]) == len(want[key]), (key, got, want)
        for p, q in zip(got[key], want[key]):
            assert all(math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-300) for a, b in zip(p, q)), (key, got, want)


@pytest.mark.parametrize("name", ["figure-3-block-along-wall", "figure-4-peg-in-hole", "rod-in-corner",
                                  "block-against-a-stop"])
def test_analyze_text_gives_every_region_completely(name):
    """Every region of the text, read back, is the --json's (to the 10 digits printed)."""
    path = EXAMPLES / f"{name}.json"
    doc = cli("analyze", path, "--json")
    text = cli("analyze", path).stdout
    modes = re.split(r"^  (?=[a-z]+  )", text, flags=re.M)[1:]
    assert [m.split()[0] for m in modes] == [m["mode"] for m in doc["modes"]]
    rays = 0
    for block, mode in zip(modes, doc["modes"]):
        regions = re.findall(r"^(?: +rotation centres)? +([+-]) (.+)$", block, re.M)
        assert [sign for sign, _ in regions] == ["+", "-", "+", "-"], block
        wants = [mode["rotation_centres"]["plus"], mode["rotation_centres"]["minus"],
                 mode["E"]["labels"]["plus"], mode["E"]["labels"]["minus"]]
        for (_, region), want in zip(regions, wants):
            same_region(parse_region(region), want)
            rays += len(want["rays"])
        assert f"applied wrenches E ({mode['E']['cone']['kind']})" in block
    assert rays > 0  # the unbounded regions' rays were read back


BLOCK = ('{"body":{"mass":1,"com":[0.5,0.25],"inertia":0.1,"polygon":[[0,0],[1,0],[1,0.5],[0,0.5]]},'
         '"contacts":[{"point":[0,0],"normal":[0,1],"mu":0.3},{"point":[1,0],"normal":[0,1],"mu":0.3}]}')


def test_json_echoes_typed_inputs_with_the_values_they_were_read_as(tmp_path):
    """An input echoed in --json that is not a double also comes as "KEY_exact", the exact value
    it was read as in lowest terms (Fraction of the typed text: the oracle); one that is a double
    (0.5, 0.25, -10) has none (docs/formats.md)."""
    path = tmp_path / "block.json"
    path.write_text(BLOCK)

    def exact(texts):
        return [str(Q(t)) for t in texts]

    push = cli("plan", "push", path, "--goal", "ff", "--mu", "0.1", "--gravity", "0", "-9.8", "--json")
    assert push["mu_exact"] == str(Q("0.1")) and push["fixed_exact"] == exact(["0", "-9.8", "-4.9"])
    assert push["fixed"] == [0.0, -9.8, -4.9] and push["mu"] == 0.1
    tilt = cli("plan", "tilt", path, "--goal", "ff", "--wrench", "0.1", "0", "0", "--json")
    assert tilt["fixed_exact"] == exact(["0.1", "0", "0"])
    comply = cli("plan", "comply", path, "--goal", "rr", "--centre", "0.775", "0.5", "--json")["centre"]
    assert comply["point"] == [0.775, 0.5] and comply["point_exact"] == exact(["0.775", "0.5"])
    line = cli("query", path, "--push", "0.3", "0.25", "1", "0", "--gravity", "0", "-9.8", "--json")
    assert line["point_exact"] == exact(["0.3", "0.25"]) and "direction_exact" not in line
    at = cli("label", force_file(tmp_path), "--at", "0.1", "2", "--json")
    assert at["at"][0]["point_exact"] == exact(["0.1", "2"])
    # Doubles have no exact echo.
    dyadic = cli("plan", "push", path, "--goal", "ff", "--mu", "0.5", "--gravity", "0", "-10", "--json")
    assert "mu_exact" not in dyadic and "fixed_exact" not in dyadic


def force_file(tmp_path):
    path = tmp_path / "force.json"
    path.write_text('{"sets": [{"type": "force", "point": [0, 0], "direction": [1, 1]}]}')
    return path
