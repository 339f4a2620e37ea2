#!/usr/bin/env bash
# The instruction counts of docs/benchmarks.md: valgrind's callgrind (counts this machine's noise
# does not move) of bench_instructions, a SceneQuestions set-up and six wrenches on the cradle
# and the tangent of 10^4 contacts, asked one by one (one walk each), the first alone and the
# other five in one batch, and all six in one batch; each file read as typed (its decimals
# exactly) and read as the doubles nearest its numbers (bench_instructions ... doubles). Prints G
# instructions per row.
# Usage: tools/instructions.sh [build directory] [work directory]
set -euo pipefail
build=${1:-build/release}
dir=${2:-build/degenerate}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$dir"
printf "%-44s %10s %10s %16s %16s\n" "six wrenches, set-up included (G)" "cradle" "tangent" "cradle, doubles" "tangent, doubles"
for f in cradle tangent; do
    [[ -f "$dir/${f}_10000.json" ]] || /usr/bin/python3 "$here/families.py" "$dir" "$f" 10000
done
for mode in one split all; do
    case $mode in
        one) label="one by one (one walk each)" ;;
        split) label="first alone, then five in one batch" ;;
        all) label="all six in one batch" ;;
    esac
    row=()
    for reading in typed doubles; do
        for f in cradle tangent; do
            refs=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$build/bench/bench_instructions" \
                       "$dir/${f}_10000.json" "$mode" $([[ $reading == doubles ]] && echo doubles) 2>&1 >/dev/null |
                   sed -n 's/.*refs: *//p' | tr -d ',')
            row+=("$(echo "scale=3; $refs / 1000000000" | bc -l)")
        done
    done
    printf "%-44s %10.3f %10.3f %16.3f %16.3f\n" "$label" "${row[0]}" "${row[1]}" "${row[2]}" "${row[3]}"
done
# How many signs of exact vectors the certified approximations decided, all six in one batch
# (bench_instructions' counters, a native run).
for reading in typed doubles; do
    for f in cradle tangent; do
        line=$("$build/bench/bench_instructions" "$dir/${f}_10000.json" all $([[ $reading == doubles ]] && echo doubles))
        printf "signs, %-8s %-8s %s\n" "$f" "$reading" "${line##*signs: }"
    done
done
# The cost of reading as typed when the text is exactly doubles: the same scenes with every number
# written as the exact decimal expansion of its double (dyadic text, up to 60 digits) and as
# the shortest text of the double nearest it on a grid of 2^-16 (short dyadic text), all six in
# one batch, read as typed and as doubles (the same values either way).
for f in cradle tangent; do
    for kind in exact short; do
        [[ -f "$dir/${f}-${kind}_10000.json" ]] || /usr/bin/python3 - "$dir/${f}_10000.json" "$dir/${f}-${kind}_10000.json" "$kind" <<'PY'
import json, sys
from decimal import Decimal
from fractions import Fraction
def text(x, kind):
    if kind == "short":
        x = round(x * 2**16) / 2**16
        assert Fraction(repr(x)) == Fraction(x)
        return repr(x)
    return format(Decimal(x), "f")
def dump(o, kind):
    if isinstance(o, float): return text(o, kind)
    if isinstance(o, list): return "[" + ",".join(dump(v, kind) for v in o) + "]"
    if isinstance(o, dict): return "{" + ",".join(json.dumps(k) + ":" + dump(v, kind) for k, v in o.items()) + "}"
    return json.dumps(o)
doc = json.load(open(sys.argv[1]))
open(sys.argv[2], "w").write(dump(doc, sys.argv[3]) + "\n")
PY
    done
done
printf "%-44s %10s %10s %16s %16s\n" "all six in one batch, doubles as text (G)" "cradle" "tangent" "cradle, doubles" "tangent, doubles"
for kind in exact short; do
    row=()
    for reading in typed doubles; do
        for f in cradle tangent; do
            refs=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$build/bench/bench_instructions" \
                       "$dir/${f}-${kind}_10000.json" all $([[ $reading == doubles ]] && echo doubles) 2>&1 >/dev/null |
                   sed -n 's/.*refs: *//p' | tr -d ',')
            row+=("$(echo "scale=3; $refs / 1000000000" | bc -l)")
        done
    done
    label=$([[ $kind == exact ]] && echo "exact expansions (dyadic, up to 60 digits)" || echo "short dyadic text (a 2^-16 grid)")
    printf "%-44s %10.3f %10.3f %16.3f %16.3f\n" "$label" "${row[0]}" "${row[1]}" "${row[2]}" "${row[3]}"
done
