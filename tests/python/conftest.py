"""Shared fixtures of the Python tests (docs/python.md): the command line to compare with and the
bundled examples. MOMENTLAB_CLI names the momentlab executable (ctest sets it)."""

import dataclasses
import json
import math
from fractions import Fraction
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
CLI = os.environ.get("MOMENTLAB_CLI", str(ROOT / "build" / "release" / "momentlab"))

# The bundled scenes with a body (modes, query and plans need one).
SCENES = sorted(p for p in EXAMPLES.glob("*.json") if "body" in json.loads(p.read_text()))
FORCE_SETS = sorted(p for p in EXAMPLES.glob("figure-[12]*.json"))


def cli(*args, check=True):
    """Runs the command line; returns its stdout parsed as JSON when it ran with --json."""
    r = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    if check and r.returncode != 0:
        raise AssertionError(f"momentlab {' '.join(map(str, args))}: exit {r.returncode}: {r.stderr}")
    if "--json" in args and r.returncode == 0:
        return json.loads(r.stdout)
    return r


@pytest.fixture(scope="session")
def examples():
    return EXAMPLES


def as_json(value):
    """A result of the Python module (momentlab.results) in the form of the CLI's --json output,
    written here from the JSON's rules (not the module's reader): each dataclass field a key,
    from_ as "from", math.inf as "unbounded", tuples as lists, a Fraction as "p/q" (docs/formats.md:
    an exact value in lowest terms), a field that is None left out."""
    if dataclasses.is_dataclass(value):
        return {("from" if f.name == "from_" else f.name): as_json(getattr(value, f.name))
                for f in dataclasses.fields(value) if getattr(value, f.name) is not None}
    if isinstance(value, dict):
        return {k: as_json(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [as_json(v) for v in value]
    if isinstance(value, float) and math.isinf(value) and value > 0:
        return "unbounded"
    if isinstance(value, Fraction):
        return f"{value.numerator}/{value.denominator}"
    return value


def without_nulls(doc):
    """The CLI's JSON with its null fields left out (None in Python, as in as_json)."""
    if isinstance(doc, dict):
        return {k: without_nulls(v) for k, v in doc.items() if v is not None}
    if isinstance(doc, list):
        return [without_nulls(v) for v in doc]
    return doc
