#!/usr/bin/env bash
# The release build compiled without ccache twice, one file at a time and as a unity build (the
# Makefile's trees), each with Ninja on 2 jobs in a scratch directory; prints, from Ninja's log,
# the compile time summed over tasks per kind of target (library, CLI, tests, other) and the wall
# time. About 12 minutes on 2 cores; run it on a quiet machine.
# Usage: tools/build_times.sh [scratch directory]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-$(mktemp -d)}
lock() { if command -v mlbuild > /dev/null; then mlbuild "$@"; else "$@"; fi; }
for unity in OFF ON; do
    dir=$work/unity-$unity
    rm -rf "$dir"
    cmake -G Ninja -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DMOMENTLAB_PYTHON=ON \
        -DPython_EXECUTABLE=/usr/bin/python3 -DCMAKE_UNITY_BUILD=$unity > /dev/null
    CCACHE_DISABLE=1 lock cmake --build "$dir" -j2 > "$dir/build.log"
    awk -v unity=$unity 'NR > 1 {
        d = ($2 - $1) / 1000; k = $4
        if (k ~ /^CMakeFiles\/momentlab\.dir/) part = "CLI"
        else if (k ~ /^CMakeFiles\/momentlab_/) part = "library"
        else if (k ~ /^tests\//) part = "tests"
        else part = "other (bench, python, reference, validation, links)"
        t[part] += d; total += d; if ($2 > wall) wall = $2
    } END {
        printf "unity %s: task time %.0f s, wall %.0f s\n", unity, total, wall / 1000
        for (p in t) printf "  %-52s %6.0f s\n", p, t[p]
    }' "$dir/.ninja_log"
done
