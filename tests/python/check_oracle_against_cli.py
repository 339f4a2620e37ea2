#!/usr/bin/python3
"""Check the exact oracle (oracle.py) against the momentlab command-line tool.

A script that validates the oracle itself; tests/python/test_oracle.py runs it at small sizes
(`make test`), bigger runs are by hand.  For the bundled example
scenes that list their contacts, for random scenes (1-4 contacts) and for random scenes
with mu_kinetic > mu (where wrenches that produce no mode are common), each written to a
temporary file, it compares

* oracle.modes(scene) with `momentlab modes FILE --json` (as sets), and
* oracle.query(scene, e) with `momentlab query FILE --wrench FX FY TAU --json` (modes as
  sets, and the verdict), for random wrenches and for wrenches built on the boundaries
  between modes (oracle.boundary_wrenches).

It also checks the oracle's modes against twists classified straight from the
definitions (self_check).  Numbers reach the tool as repr(float), which is exact.  Prints counts; exits 1 on any
disagreement (each one printed with its scene and wrench).

Usage: /usr/bin/python3 tests/python/check_oracle_against_cli.py [--scenes N] [--seed S]
       [--painleve-scenes N] [--cli PATH] [--wrenches K]
"""

import argparse
import collections
import itertools
import json
from fractions import Fraction
import os
import random
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)

import oracle  # noqa: E402


def run_cli(cli, args):
    proc = subprocess.run([cli] + args, capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join([cli] + args)} exited {proc.returncode}: {proc.stderr.strip()}")
    return json.loads(proc.stdout)


def self_check(scene, found):
    """Checks of the oracle that need no CLI: every mode found has a twist whose letters,
    computed straight from the definitions (oracle.mode_of_twist), are that mode; and the
    letters of every non-penetrating small integer twist are a mode found."""
    for mode in found:
        assert oracle.mode_of_twist(scene, oracle.interior_twist(scene, mode)) == mode, mode
    grid = range(-2, 3)
    for xi in itertools.product(grid, grid, grid):
        if all(oracle.dot(c.N, xi) >= 0 for c in scene.contacts):
            assert oracle.mode_of_twist(scene, xi) in found, xi


def number_text(x):
    """x's exact decimal when it has one (every double does), else its double's shortest text: the
    wrench as the tool will read it."""
    x = Fraction(x)
    d, k = x.denominator, 0
    while d % 2 == 0 or d % 5 == 0:
        d //= 2 if d % 2 == 0 else 5
        k += 1
    if d != 1 or k > 60:
        return repr(float(x))
    digits = str(abs(x.numerator * 10 ** k // x.denominator)).rjust(k + 1, "0")
    return ("-" if x < 0 else "") + (digits if k == 0 else digits[:-k] + "." + digits[-k:])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", type=int, default=100, help="random scenes (default 100)")
    ap.add_argument("--painleve-scenes", type=int, default=30,
                    help="random scenes with mu_kinetic above mu (default 30)")
    ap.add_argument("--seed", type=int, default=20240601)
    ap.add_argument("--wrenches", type=int, default=6, help="random and boundary wrenches per scene (each)")
    ap.add_argument("--batch", action="store_true",
                    help="one `query FILE --wrenches WFILE --json` call per scene instead of one --wrench call per wrench")
    ap.add_argument("--cli", default=os.path.join(ROOT, "build", "release", "momentlab"))
    args = ap.parse_args()

    start = time.monotonic()
    counts = collections.Counter()
    verdicts = collections.Counter()
    failures = []

    def check(doc, label, rng):
        """Compare modes and queries of one scene; ``label`` names it in messages."""
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            json.dump(doc, f)
            path = f.name
        try:
            # The scene as the tool reads its text: each number the decimal it spells.
            with open(path) as f:
                scene = oracle.exact_scene(json.load(f, parse_float=Fraction))
            mine = oracle.modes(scene)
            self_check(scene, mine)
            theirs = set(run_cli(args.cli, ["modes", path, "--json"])["modes"])
            counts["scenes"] += 1
            if mine == theirs:
                counts["modes agree"] += 1
            else:
                failures.append(f"modes of {label}: oracle {sorted(mine)} cli {sorted(theirs)}\n  {json.dumps(doc)}")
            if "body" not in doc:
                return
            wrenches = [("random", oracle.random_wrench(rng)) for _ in range(args.wrenches)]
            wrenches += [("boundary", w) for w in oracle.boundary_wrenches(scene, rng, args.wrenches)]
            if args.batch:
                wpath = path + ".wrenches"
                with open(wpath, "w") as f:
                    for _, w in wrenches:
                        f.write("[" + ", ".join(number_text(x) for x in w) + "]\n")
                proc = subprocess.run([args.cli, "query", path, "--wrenches", wpath, "--json"],
                                      capture_output=True, text=True)
                os.unlink(wpath)
                if proc.returncode != 0:
                    raise RuntimeError(f"query --wrenches exited {proc.returncode}: {proc.stderr.strip()}")
                outs = [json.loads(line) for line in proc.stdout.splitlines() if line.strip()]
                assert len(outs) == len(wrenches)
            for index, (kind, w) in enumerate(wrenches):
                mine = oracle.query(scene, [Fraction(number_text(x)) for x in w])
                if args.batch:
                    out = outs[index]
                else:
                    out = run_cli(args.cli, ["query", path, "--wrench"] + [number_text(x) for x in w] + ["--json"])
                theirs = set(out["modes"])
                counts[f"{kind} wrenches"] += 1
                verdicts[(kind, oracle.verdict(mine))] += 1
                if mine == theirs and out["verdict"] == oracle.verdict(mine):
                    counts[f"{kind} wrenches agree"] += 1
                else:
                    failures.append(
                        f"query of {label} at {[repr(float(x)) for x in w]}: oracle {sorted(mine)} "
                        f"cli {sorted(theirs)} ({out['verdict']})\n  {json.dumps(doc)}")
        finally:
            os.unlink(path)

    rng = random.Random(args.seed)
    examples = os.path.join(ROOT, "examples")
    for name in sorted(os.listdir(examples)):
        if not name.endswith(".json"):
            continue
        with open(os.path.join(examples, name)) as f:
            doc = json.load(f)
        if isinstance(doc, dict) and "contacts" in doc:
            check(doc, name, rng)
            counts["examples"] += 1
    for k in range(args.scenes):
        doc = oracle.random_scene(rng, rng.randint(1, 4))
        check(doc, f"random scene {k}", rng)
    for k in range(args.painleve_scenes):
        doc = oracle.random_scene(rng, rng.randint(1, 3), kinetic_above_static=True)
        check(doc, f"Painleve scene {k}", rng)

    elapsed = time.monotonic() - start
    for key in sorted(counts):
        print(f"{key:28s} {counts[key]}")
    print("verdicts (oracle):", ", ".join(f"{k}/{v}: {n}" for (k, v), n in sorted(verdicts.items())))
    print(f"time {elapsed:.1f} s")
    for msg in failures:
        print("DISAGREE", msg)
    print("all agree" if not failures else f"{len(failures)} disagreements")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
