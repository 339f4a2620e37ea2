#!/usr/bin/python3
"""Writes the (nearly) degenerate scene families of docs/benchmarks.md ("Nearly degenerate scenes")
as scene files: python3 tools/families.py DIR FAMILY N [FAMILY N ...].

Families (a unit body at the origin, mu = 0.3):
  bowl        contacts on the lower half of the unit circle, every coordinate rounded to 9
              digits, normals exactly -p (round(-c, 9) is -round(c, 9)): the normal lines all
              meet in the centre, the origin
  bowl-exact  the same scene as bowl, written as -p (the same file)
  bowl-near   contacts on the arc from 1.1 pi to 1.9 pi of the unit circle centred at (0, 1),
              normals towards that centre, points and normals rounded to 9 digits, centre of
              mass (0, 0.8): the normal lines nearly meet in the centre, each missing it by
              about 10^-9
  collinear   contacts on the x axis with normals +x and -x in turn: every normal on one line
  cradle      contacts on a half ring, normals tilted by 0.2 rad from the radius
  tangent     normal lines tangent to the lower half of the unit circle (contacts at the
              tangent points)

FAMILY@K is the same scene with every length times 2^K (points and centre of mass; inertia
times 2^2K), written to FAMILY@K_N.json: the same question, with torques 2^K times as large
against the forces (a wrench (fx, fy, tau) of the scene is (fx, fy, 2^K tau) there).
"""
import json
import math
import sys


def contact(p, n):
    return {"point": [p[0], p[1]], "normal": [n[0], n[1]], "mu": 0.3}


def family(name, n):
    if name == "bowl-near":
        return bowl_near(n)
    cs = []
    for k in range(n):
        a = math.pi * (1.0 + (k + 0.5) / n)
        c, s = math.cos(a), math.sin(a)
        if name == "bowl":
            cs.append(contact((round(c, 9), round(s, 9)), (round(-c, 9), round(-s, 9))))
        elif name == "bowl-exact":
            p = (round(c, 9), round(s, 9))
            cs.append(contact(p, (-p[0], -p[1])))
        elif name == "collinear":
            x = (k + 0.5) / n * 4.0 - 2.0
            cs.append(contact((x, 0.0), (1.0 if k % 2 == 0 else -1.0, 0.0)))
        elif name == "cradle":
            t = 0.2
            cs.append(contact((c, s), (-(c * math.cos(t) - s * math.sin(t)), -(c * math.sin(t) + s * math.cos(t)))))
        elif name == "tangent":
            cs.append(contact((c, s), (-s, c)))
        else:
            raise SystemExit(f"families.py: unknown family {name}")
    return {"body": {"mass": 1.0, "com": [0.0, 0.0], "inertia": 0.5}, "contacts": cs}


def bowl_near(n):
    cs = []
    for k in range(n):
        a = math.pi * (1.1 + 0.8 * (k + 0.5) / n)
        c, s = math.cos(a), math.sin(a)
        cs.append(contact((round(c, 9), round(1.0 + s, 9)), (round(-c, 9), round(-s, 9))))
    return {"body": {"mass": 1.0, "com": [0.0, 0.8], "inertia": 0.5}, "contacts": cs}


def scaled(scene, k):
    s = math.ldexp(1.0, k)
    body = scene["body"]
    body["com"] = [x * s for x in body["com"]]
    body["inertia"] = body["inertia"] * s * s
    for c in scene["contacts"]:
        c["point"] = [x * s for x in c["point"]]
    return scene


def main():
    args = sys.argv[1:]
    if len(args) < 3 or len(args) % 2 == 0:
        raise SystemExit(__doc__)
    out = args[0]
    for name, size in zip(args[1::2], args[2::2]):
        base, _, k = name.partition("@")
        scene = family(base, int(size))
        if k:
            scene = scaled(scene, int(k))
        with open(f"{out}/{name}_{size}.json", "w") as f:
            json.dump(scene, f)


if __name__ == "__main__":
    main()
