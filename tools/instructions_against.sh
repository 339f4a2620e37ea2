#!/usr/bin/env bash
# The cost of reading text that is exactly doubles as typed, against a build of another commit
# (docs/benchmarks.md, "Instructions of the query path"): callgrind of bench_instructions on the
# cradle and tangent of 10^4 contacts written as short dyadic text and as 60-digit exact
# expansions (the files `make instructions` writes in build/degenerate), asked one by one, first
# then five, all six; prints each count and the ratio (this build / the other).
# Usage: tools/instructions_against.sh OTHER_BUILD [BUILD [WORK DIRECTORY]]
#   e.g. git worktree add /tmp/old 6919988 && cmake -S /tmp/old -B /tmp/old/build -G Ninja \
#        -DCMAKE_BUILD_TYPE=Release && cmake --build /tmp/old/build --target bench_instructions
set -euo pipefail
other=${1:?usage: tools/instructions_against.sh OTHER_BUILD [BUILD [WORK DIRECTORY]]}
build=${2:-build/release}
dir=${3:-build/degenerate}
for f in cradle tangent; do
    for kind in short exact; do
        [[ -f "$dir/${f}-${kind}_10000.json" ]] || { echo "no $dir/${f}-${kind}_10000.json: run make instructions first" >&2; exit 1; }
    done
done
count() {  # build, file, mode: the instructions (the libraries of that build, not the RUNPATH's)
    local b=$1
    LD_LIBRARY_PATH=$b valgrind --tool=callgrind --callgrind-out-file=/dev/null "$b/bench/bench_instructions" "$2" "$3" 2>&1 >/dev/null |
        sed -n 's/.*refs: *//p' | tr -d ','
}
printf "%-34s %-6s %14s %14s %7s\n" "file" "mode" "other" "this" "ratio"
for kind in short exact; do
    for f in cradle tangent; do
        for mode in one split all; do
            a=$(count "$other" "$dir/${f}-${kind}_10000.json" $mode)
            b=$(count "$build" "$dir/${f}-${kind}_10000.json" $mode)
            printf "%-34s %-6s %14d %14d %7.3f\n" "${f}-${kind}_10000.json" "$mode" "$a" "$b" "$(echo "$b / $a" | bc -l)"
        done
    done
done
