#!/usr/bin/env bash
# The usual way into a user's own environment (docs/python.md): a virtual environment made
# with --system-site-packages (numpy, matplotlib from Debian), then `pip install
# --no-build-isolation .` from the checkout, offline. The installed module must answer from
# another directory, with the checkout's build trees out of its path.
#   pip_install.sh SOURCE_DIR PYTHON
set -euo pipefail
src=$1
python=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$python" -m venv --system-site-packages "$tmp/venv"
PIP_NO_INDEX=1 "$tmp/venv/bin/pip" install --no-build-isolation --no-index --quiet --disable-pip-version-check "$src"

cd "$tmp"
env -u PYTHONPATH "$tmp/venv/bin/python" - "$src" <<'PY'
import sys
from pathlib import Path
import numpy as np
import momentlab as ml

src = Path(sys.argv[1])
where = Path(ml.__file__).resolve()
assert str(where).startswith(sys.prefix), f"momentlab imported from {where}, not the environment {sys.prefix}"
a = ml.analyze(ml.Scene.from_file(src / "examples" / "figure-3-block-along-wall.json"))
assert a.modes == ["ff", "ss", "fs", "rs", "ls", "sf", "sr", "sl", "rr", "ll"], a.modes
# By hand: gravity (0, -1) through the centre of mass (1/2, 1/4) leaves the block at rest; the
# force (1, -1) there (torque -3/4) beats friction (1 > 1/2 * 1) and slides it right.
assert a.query([0.0, -1.0, -0.5]) == ["ff"]
hits = a.query(np.array([[0.0, -1.0, -0.5], [1.0, -1.0, -0.75]]))
assert hits.shape == (2, 10) and hits[0].tolist() == [m == "ff" for m in a.modes]
assert hits[1].tolist() == [m == "rr" for m in a.modes]
print(f"pip install into a virtual environment: momentlab {ml.__version__} from {where.parent}")
PY
