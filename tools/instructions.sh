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
