#!/usr/bin/env bash
# The main job on the bundled examples: the moment labels of the paper's Figure 1 and 2
# force sets (Mason 1991), and the intersection that the paper's hull shorthand gets wrong.
set -euo pipefail
bin=${1:?usage: demo.sh path/to/momentlab}
here=$(cd "$(dirname "$0")" && pwd)
show() {
    echo
    echo "== $1"
    echo "   momentlab label examples/$2 ${3:-}"
    "$bin" label "$here/$2" ${3:-}
}
show "Figure 1a: a force along +x through the origin" figure-1a-force.json "--at 0 1 --at 0 -1 --at 3 0"
show "Figure 1b: all forces through the point (1, 2)" figure-1b-point.json "--at 1 2 --at 0 0"
show "Figure 1c: friction cone at the origin, normal +y, mu = 0.5" figure-1c-friction-cone.json "--at -1 0 --at 1 0 --at 0 0"
show "Figure 2: two friction cones combined (labels intersected)" figure-2-two-friction-cones.json "--at -1 0 --at 3 1"
show "Intersection of two parallel forces on different lines: only the zero wrench (labels: the whole plane, twice; the paper's hull shorthand would give y >= 0)" parallel-rays-intersection.json "--at 0 -1"
