"""Shared fixtures of the Python tests (docs/python.md): the command line to compare with and the
bundled examples. MOMENTLAB_CLI names the momentlab executable (ctest sets it)."""

import json
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
