"""Numbers as typed (issue 46): text is read as the decimal it spells (0.1 is 1/10), numbers that
arrive as binary doubles keep their binary value (docs/design.md, "Numbers as typed").

The oracle reads the scene's raw text with every number a Fraction of its decimal
(json.loads(..., parse_float=Fraction)) or, for the binary reading, of the double Python reads
(Fraction(float)), and answers by exact LPs (tests/python/oracle.py); it never sees momentlab's
wrenches, cones or mode lists. The scenes are degenerate only in decimal: forces through decimal
contact points, thresholds typed as mu m g, normals concurrent at a decimal point, contacts on a
decimal line, a translation by (0.1, 0.3)."""

import json
import random
from decimal import Decimal
from fractions import Fraction

import pytest

import momentlab as ml
import oracle
from conftest import cli
from test_issue44_oracle import quasi_static_answer


def as_decimals(text):
    """The scene's numbers as the decimals they spell."""
    return json.loads(text, parse_float=Fraction, parse_int=Fraction)


def as_doubles(text):
    """The same text as Python reads it: doubles (their exact binary values in the oracle)."""
    return json.loads(text)


def dec(x):
    """The exact decimal text of a Fraction whose denominator divides a power of ten."""
    x = Fraction(x)
    k = 0
    while (x * 10 ** k).denominator != 1:
        k += 1
        assert k < 40, x
    digits = str(abs((x * 10 ** k).numerator)).rjust(k + 1, "0")
    body = digits if k == 0 else digits[:-k] + "." + digits[-k:]
    return ("-" if x < 0 else "") + body


def scene_text(body, contacts):
    """A scene file's text, each number written as its exact decimal."""
    def c(contact):
        p, n, mu = contact
        return f'{{"point":[{dec(p[0])},{dec(p[1])}],"normal":[{dec(n[0])},{dec(n[1])}],"mu":{dec(mu)}}}'
    head = ""
    if body:
        m, com, inertia = body
        head = f'"body":{{"mass":{dec(m)},"com":[{dec(com[0])},{dec(com[1])}],"inertia":{dec(inertia)}}},'
    return "{" + head + '"contacts":[' + ",".join(c(k) for k in contacts) + "]}"


def cli_query(tmp_path, text, wrench, *flags):
    path = tmp_path / "scene.json"
    path.write_text(text)
    out = cli("query", path, "--wrench", *[dec(w) if isinstance(w, Fraction) else w for w in wrench], "--json", *flags)
    return set(out["modes"])


def cli_modes(tmp_path, text):
    path = tmp_path / "scene.json"
    path.write_text(text)
    return set(cli("modes", path, "--json")["modes"])


def python_binary(text, wrench, quasi_static=False):
    """The scene built from Python floats (binary meaning) and a float wrench."""
    doc = as_doubles(text)
    scene = ml.Scene(body=doc.get("body"), contacts=doc["contacts"])
    return set(ml.query(scene, [float(w) for w in wrench], quasi_static=quasi_static).modes)


def binary_oracle(text, wrench, quasi_static=False):
    doc = as_doubles(text)
    e = [Fraction(float(w)) for w in wrench]
    return quasi_static_answer(doc, e) if quasi_static else oracle.query(doc, e)


# ---------------------------------------------------------------------------------------------
# A force through a decimal contact point (quasi-static): tau = 2 0.18699 + 2 0.26866.

THROUGH = '{"contacts":[{"point":[2,-2],"normal":[-1,0],"mu":2}]}'
THROUGH_WRENCH = [Fraction("0.18699"), Fraction("0.26866"), Fraction("0.9113")]


def test_force_through_a_decimal_contact_point_is_held(tmp_path):
    expected = quasi_static_answer(as_decimals(THROUGH), THROUGH_WRENCH)
    assert expected == {"f"}  # the issue's reading: a force through the contact, inside its cone
    assert cli_query(tmp_path, THROUGH, THROUGH_WRENCH, "--quasi-static") == expected
    # Python: Fractions, Decimals and numeric strings have their exact values.
    scene = ml.Scene.from_json(THROUGH)
    for w in (THROUGH_WRENCH, [Decimal("0.18699"), "0.26866", Fraction(9113, 10000)]):
        assert set(ml.query(scene, w, quasi_static=True).modes) == expected
    # The same numbers as doubles: the binary scene, as the binary oracle reads it.
    assert python_binary(THROUGH, THROUGH_WRENCH, True) == binary_oracle(THROUGH, THROUGH_WRENCH, True)


# ---------------------------------------------------------------------------------------------
# Pushes typed at the friction threshold mu m g.

def block(mu, m, h):
    return scene_text((m, (Fraction(1, 2), h), Fraction(1, 10)),
                      [((0, 0), (0, 1), mu), ((1, 0), (0, 1), mu)])


THRESHOLDS = [(Fraction("0.3"), Fraction(1), Fraction("0.25"), Fraction("9.81")),
              (Fraction("0.7"), Fraction("2.3"), Fraction("0.4"), Fraction("9.81")),
              (Fraction("0.15"), Fraction("0.9"), Fraction("1.1"), Fraction("9.8"))]


@pytest.mark.parametrize("mu, m, h, g", THRESHOLDS)
def test_push_typed_at_the_threshold_is_ambiguous(tmp_path, mu, m, h, g):
    text = block(mu, m, h)
    w = [mu * m * g, -m * g, -m * g / 2]  # the push mu m g along the floor, and gravity
    expected = oracle.query(as_decimals(text), w)
    assert {"ff", "rr"} <= expected  # on the boundary between sticking and sliding
    assert cli_query(tmp_path, text, w) == expected
    assert cli_query(tmp_path, text, w, "--quasi-static") == quasi_static_answer(as_decimals(text), w)
    assert python_binary(text, w) == binary_oracle(text, w)


def test_band_end_typed_back_gives_the_bands_modes(tmp_path):
    """The band "2.943 only: ff rr" of the push line, typed back as the wrench it names."""
    mu, m, h, g = THRESHOLDS[0]
    path = tmp_path / "block.json"
    path.write_text(block(mu, m, h))
    bands = cli("query", path, "--gravity", "0", "-9.81", "--push", "0", "0", "1", "0", "--json")["bands"]
    single = [b for b in bands if b["from"] == b["to"]]
    assert single and single[0]["from"] == float(mu * m * g)  # printed 2.943
    w = [Fraction(repr(single[0]["from"])), -m * g, -m * g / 2]
    assert set(single[0]["modes"]) == oracle.query(as_decimals(path.read_text()), w) == cli_query(tmp_path, path.read_text(), w)


# ---------------------------------------------------------------------------------------------
# Normals concurrent at a decimal point (wheels), contacts on a decimal line.

WHEEL = ('{"body":{"mass":1,"com":[0.5,0.7],"inertia":0.1},"contacts":['
         '{"point":[0.4,-0.1],"normal":[0.1,0.8],"mu":0},{"point":[1.3,-0.2],"normal":[-0.8,0.9],"mu":0},'
         '{"point":[-0.2,1],"normal":[0.7,-0.3],"mu":0}]}')


def test_decimal_wheel_spins_about_its_centre(tmp_path):
    expected = oracle.query(as_decimals(WHEEL), [0, 0, 1])
    assert expected == {"rrr", "srs", "ssr", "sss"}  # the issue's reading
    assert cli_query(tmp_path, WHEEL, [Fraction(0), Fraction(0), Fraction(1)]) == expected
    assert cli_modes(tmp_path, WHEEL) == oracle.modes(as_decimals(WHEEL))
    assert python_binary(WHEEL, [0, 0, 1]) == binary_oracle(WHEEL, [0, 0, 1])


def decimal(rng, lo, hi, places=1):
    return Fraction(rng.randint(lo * 10 ** places, hi * 10 ** places), 10 ** places)


def random_wheel(rng):
    """Three contacts whose normals pass through one decimal point (mu = 0)."""
    c = (decimal(rng, -1, 1), decimal(rng, -1, 1))
    contacts = []
    while len(contacts) < 3:
        p = (decimal(rng, -2, 2), decimal(rng, -2, 2))
        if p != c:
            contacts.append((p, (c[0] - p[0], c[1] - p[1]), Fraction(0)))
    return scene_text((Fraction(1), c, Fraction("0.3")), contacts), c


def test_random_decimal_wheels(tmp_path):
    rng = random.Random(46)
    for _ in range(4):
        text, c = random_wheel(rng)
        assert cli_modes(tmp_path, text) == oracle.modes(as_decimals(text)), text
        w = [Fraction(0), Fraction(0), Fraction(1)]
        assert cli_query(tmp_path, text, w) == oracle.query(as_decimals(text), w), text
        assert python_binary(text, w) == binary_oracle(text, w), text


LINE = [(Fraction("0.1"), Fraction("0.3")), (Fraction("0.2"), Fraction("0.5")), (Fraction("0.3"), Fraction("0.7"))]


@pytest.mark.parametrize("normals", [[(1, 2)] * 3, [(1, 2), (-1, -2), (2, -1)],
                                     [(Fraction("0.1"), Fraction("0.2")), (Fraction("0.3"), Fraction("0.6")), (Fraction("-0.2"), Fraction("0.1"))]])
def test_contacts_on_a_decimal_line(tmp_path, normals):
    """Contacts on the line y = 2x + 0.1 (collinear in decimal, not in binary), forces along it."""
    for mu in (Fraction(0), Fraction("0.5")):
        text = scene_text((Fraction(1), (Fraction("0.2"), Fraction("0.5")), Fraction("0.1")),
                          [(p, (Fraction(n[0]), Fraction(n[1])), mu) for p, n in zip(LINE, normals)])
        doc = as_decimals(text)
        assert cli_modes(tmp_path, text) == oracle.modes(doc), text
        for w in ([-1, -2, Fraction("0.1")], [1, 2, Fraction("-0.1")]):  # along the line, through it
            w = [Fraction(x) for x in w]
            assert cli_query(tmp_path, text, w) == oracle.query(doc, w), (text, w)
            assert cli_query(tmp_path, text, w, "--quasi-static") == quasi_static_answer(doc, w), (text, w)


# ---------------------------------------------------------------------------------------------
# Invariance under a decimal translation.

def test_decimal_translation_keeps_the_answers(tmp_path):
    d = (Fraction("0.1"), Fraction("0.3"))
    for text, w in [(WHEEL, [Fraction(0), Fraction(0), Fraction(1)]),
                    (block(*THRESHOLDS[0][:3]), [Fraction("2.943"), Fraction("-9.81"), Fraction("-4.905")])]:
        doc = as_decimals(text)
        moved = scene_text(
            (doc["body"]["mass"], (doc["body"]["com"][0] + d[0], doc["body"]["com"][1] + d[1]), doc["body"]["inertia"]),
            [((c["point"][0] + d[0], c["point"][1] + d[1]), tuple(c["normal"]), c.get("mu", 0)) for c in doc["contacts"]])
        moved_w = [w[0], w[1], w[2] + d[0] * w[1] - d[1] * w[0]]  # the torque about the new origin
        assert cli_query(tmp_path, moved, moved_w) == cli_query(tmp_path, text, w) == oracle.query(doc, w)
        assert cli_modes(tmp_path, moved) == cli_modes(tmp_path, text)


def test_python_scene_of_decimals_and_fractions():
    """A scene built in Python from Decimals and Fractions has their exact values; the same
    numbers as floats have the floats' (binary) values."""
    doc = as_decimals(WHEEL)
    exact_doc = {"body": {"mass": 1, "com": [Decimal("0.5"), Fraction(7, 10)], "inertia": Decimal("0.1")},
                 "contacts": [{"point": [Decimal(dec(c["point"][0])), Decimal(dec(c["point"][1]))],
                               "normal": [Fraction(c["normal"][0]), Fraction(c["normal"][1])], "mu": 0}
                              for c in doc["contacts"]]}
    scene = ml.Scene(body=exact_doc["body"], contacts=exact_doc["contacts"])
    assert set(ml.query(scene, [0, 0, 1]).modes) == oracle.query(doc, [0, 0, 1])
    with pytest.raises(ValueError, match="not a decimal"):
        ml.Scene(body=exact_doc["body"], contacts=[{"point": [Fraction(1, 3), 0], "normal": [0, 1]}])


def odd_part_beyond_doubles(w):
    """True when no positive multiple of the rational vector w is three doubles: w cleared to
    coprime integers has a component whose odd part needs more than 53 bits."""
    from math import gcd, lcm
    den = lcm(*(Fraction(x).denominator for x in w))
    ints = [int(Fraction(x) * den) for x in w]
    g = 0
    for i in ints:
        g = gcd(g, i)
    odd = lambda i: i // (i & -i) if i else 0
    return any(abs(odd(i // g)) >= 2 ** 53 for i in ints)


def test_wrenches_beyond_doubles_are_walked_exactly(tmp_path):
    """query --wrench with decimals whose cleared values no double holds (17 significant digits):
    the answer is the oracle's, on random decimal scenes of 1-3 contacts, many of the wrenches on
    the face two friction edges of two contacts span (lambda e_j + e_k / 10, each edge n +- mu t
    through its contact, by hand from the scene's numbers). Such a wrench is walked (query_scene with the exact wrench),
    not answered from an analysis of the scene (docs/design.md, Numbers as typed)."""
    rng = random.Random(1791)
    lam = Fraction(12345678901234567, 10 ** 17)  # odd, > 2^53: its multiples are no doubles
    one = lambda lo, hi: Fraction(rng.randint(lo * 10, hi * 10), 10)
    edges = beyond = 0
    for case in range(40):
        contacts = []
        for _ in range(rng.randint(1, 3)):
            n = (one(-1, 1), one(-1, 1))
            if n == (0, 0):
                n = (Fraction(0), Fraction(1))
            contacts.append(((one(-1, 1), one(-1, 1)), n, one(0, 1)))
        body = (Fraction(1), (Fraction(3, 10), Fraction(1, 5)), Fraction(1, 10))
        if case % 2 == 0 and len(contacts) >= 2:
            # lam x an edge of one contact's cone plus 1/10 x an edge of another's: on the face
            # the two edges span (n + s mu t, t = (ny, -nx), through the contact)
            def edge(k, s):
                (px, py), (nx, ny), mu = contacts[k]
                fx, fy = nx + s * mu * ny, ny - s * mu * nx
                return [fx, fy, px * fy - py * fx]
            j, k = rng.sample(range(len(contacts)), 2)
            a, b = edge(j, rng.choice((1, -1))), edge(k, rng.choice((1, -1)))
            w = [lam * x + Fraction(1, 10) * y for x, y in zip(a, b)]
        else:
            w = [lam * one(-2, 2), lam * one(-2, 2) + Fraction(1, 10 ** 17), one(-2, 2)]
        if not odd_part_beyond_doubles(w):
            continue
        beyond += 1
        edges += case % 2 == 0 and len(contacts) >= 2
        doc = {"body": {"mass": body[0], "com": list(body[1]), "inertia": body[2]},
               "contacts": [{"point": list(p), "normal": list(n), "mu": mu} for p, n, mu in contacts]}
        text = scene_text(body, contacts)
        assert cli_query(tmp_path, text, w) == oracle.query(doc, w), (text, w)
    print(f"wrenches beyond doubles: {beyond} ({edges} on two friction edges)")
    assert beyond >= 30 and edges >= 8, (beyond, edges)


def test_threshold_wrench_beyond_doubles_is_ambiguous(tmp_path):
    """The block at the sliding threshold, a force (mu m g, -m g) with g = 9.8100000000000001
    whose line meets the floor inside the support (torque -4.90000000000000000000000000000000007,
    sharing no factor with the force): no multiple of the wrench is doubles, and a rounding of
    it moves (fx, fy) off the ratio mu; read and walked exactly it gives ff and rr."""
    mu, m, h, _ = THRESHOLDS[0]
    g = Fraction("9.8100000000000001")
    text = block(mu, m, h)
    w = [mu * m * g, -m * g, Fraction("-4.90000000000000000000000000000000007")]
    assert odd_part_beyond_doubles(w)
    expected = oracle.query(as_decimals(text), w)
    assert {"ff", "rr"} <= expected
    assert cli_query(tmp_path, text, w) == expected
