#!/usr/bin/env bash
# The table of nearly degenerate and big scenes (docs/benchmarks.md, "Nearly degenerate
# scenes"): each row through the real command with /usr/bin/time (wall time, peak memory), the
# modes and letters of the output, and the bound docs/benchmarks.md states for it. Each row is
# run RUNS times (default 3) and shows the median time and the largest peak: on a shared machine
# one run can take 1.5x another of the same command. A run that takes longer than TIMEOUT
# seconds (default 60) is stopped and shown as "> TIMEOUT s" (and the row not run again).
# Usage: [RUNS=n] [TIMEOUT=s] tools/degenerate_table.sh [momentlab binary] [work directory]
set -uo pipefail
bin=${1:-build/release/momentlab}
dir=${2:-build/degenerate}
timeout_s=${TIMEOUT:-60}
runs=${RUNS:-3}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$dir"
need() {  # family size: writes the scene once
    [[ -f "$dir/$1_$2.json" ]] || /usr/bin/python3 "$here/families.py" "$dir" "$1" "$2"
}
# A body outline of n vertices (a wavy circle) on a floor outline of n vertices touching its
# lowest vertex: the simplicity checks and the contact search from the scene file.
polygon_scene() {
    [[ -f "$dir/polygon_$1.json" ]] || /usr/bin/python3 - "$dir" "$1" <<'PY'
import json, math, sys
d, n = sys.argv[1], int(sys.argv[2])
body = [[(1 + 0.1 * math.sin(7 * 2 * math.pi * i / n)) * math.cos(2 * math.pi * i / n),
         (1 + 0.1 * math.sin(7 * 2 * math.pi * i / n)) * math.sin(2 * math.pi * i / n)] for i in range(n)]
low = min(v[1] for v in body)
floor = [[-2 + 4 * i / n, low] for i in range(n)] + [[2, low - 2], [-2, low - 2]]
json.dump({"body": {"mass": 1, "com": [0, 0], "inertia": 0.5, "polygon": body},
           "obstacles": [{"polygon": floor}], "contact_distance": 1e-9}, open(f"{d}/polygon_{n}.json", "w"))
PY
}
printf "%-44s %10s %12s %10s %14s\n" "input" "time (s)" "peak (MB)" "modes" "letters"
row() {  # label, then the command; prints time, peak memory and the size of the output
    local label=$1; shift
    local out="$dir/out.txt" err="$dir/err.txt"
    local times=() kb=0 run
    for (( run = 0; run < runs; ++run )); do
        /usr/bin/time -f "%e %M" -o "$dir/time.txt" timeout "$timeout_s" "$@" > "$out" 2> "$err"
        local rc=$?
        if (( rc == 124 )); then
            printf "%-44s %10s %12s %10s %14s\n" "$label" "> $timeout_s" "-" "-" "-"
            return
        fi
        if (( rc != 0 )); then
            echo "FAIL: $label exited with $rc: $(head -c 300 "$err")"
            exit 1
        fi
        local t k
        read -r t k < <(tail -1 "$dir/time.txt")
        times+=("$t")
        (( k > kb )) && kb=$k
    done
    local secs
    secs=$(printf '%s\n' "${times[@]}" | sort -g | sed -n "$(( (runs + 1) / 2 ))p")  # the median
    local modes letters
    case $count in
        analyze) modes=$(grep -c '"mode":' "$out") ;;
        modes) modes=$(( $(tr -cd ',' < "$out" | wc -c) + 1 )) ;;  # {"modes": ["...", ...]}
        query) modes=$(grep -o '"[srlf]*"' "$out" | wc -l) ;;  # the answer's modes (query --json)
        *) modes=- ;;
    esac
    [[ $modes == - ]] && letters=- || letters=$(( modes * contacts ))
    printf "%-44s %10.2f %12.1f %10s %14s\n" "$label" "$secs" "$(echo "$kb / 1024" | bc -l)" "$modes" "$letters"
}
for f in bowl bowl-exact bowl-near; do
    need $f 100000
    contacts=100000 count=analyze row "$f, 10^5 contacts, analyze --json" "$bin" analyze "$dir/${f}_100000.json" --json
done
for f in collinear cradle tangent; do
    for n in 1000 3000 10000; do
        need $f $n
        contacts=$n count=modes row "$f, $n contacts, modes --json" "$bin" modes "$dir/${f}_$n.json" --json
    done
done
# One query: `modes` and `letters` are the answer's (the modes the wrench gives).
for f in bowl bowl-exact bowl-near; do
    contacts=100000 count=query row "$f, 10^5 contacts, one query" "$bin" query "$dir/${f}_100000.json" --wrench 0.1 1 0.2 --json
done
for f in cradle tangent; do
    for n in 10000 100000; do
        need $f $n
        contacts=$n count=query row "$f, $n contacts, one query" "$bin" query "$dir/${f}_$n.json" --wrench 0.1 1 0.2 --json
    done
done
# The same question on the same scenes with every length times 2^40 and 2^-40: torques 2^40
# times the forces, or 2^-40 (the wrench's torque scaled with them).
for f in cradle tangent; do
    for k in 40 -40; do
        need "$f@$k" 100000
        tau=$(/usr/bin/python3 -c "import math; print(repr(math.ldexp(0.2, $k)))")
        contacts=100000 count=query row "$f x 2^$k, 10^5 contacts, one query" "$bin" query "$dir/$f@${k}_100000.json" --wrench 0.1 1 "$tau" --json
    done
done
# Six questions in one run (query --wrenches: the walk for each, its set-up once; `modes` and
# `letters` summed over the answers).
printf '%s\n' '[0.1, 1, 0.2]' '[0.5, 2, 0.1]' '[1, 1, 0.5]' '[0.2, -1, 0.3]' '[2, 0.5, -0.4]' '[0, 0, 1]' > "$dir/six_wrenches.jsonl"
for f in bowl cradle tangent; do
    contacts=100000 count=query row "$f, 10^5 contacts, six queries (--wrenches)" "$bin" query "$dir/${f}_100000.json" --wrenches "$dir/six_wrenches.jsonl" --json
done
for n in 1000 3000 10000; do
    need collinear $n
    contacts=$n count=query row "collinear, $n contacts, one query" "$bin" query "$dir/collinear_$n.json" --wrench 0.1 1 0.2 --json
done
for n in 10000 30000 1000000; do
    polygon_scene $n
    contacts=0 count=none row "body outline of $n vertices, modes" "$bin" modes "$dir/polygon_$n.json" --json
done
