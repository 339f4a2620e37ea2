#!/usr/bin/env bash
# The mutation table of docs/robustness.md: each bound of the core's filter mechanism shrunk in
# turn (a copy of the sources, one replacement each), the core and its two tests built beside it
# (g++, ccache) and run; prints the tests each mutation makes fail ("none" for the unchanged
# sources must print none). A few minutes per mutation.
# Usage: tools/core_mutations.sh [work directory [name ...]]   (all when no name is given)
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-$root/build/mutations}
only=" ${*:2} "
lock() { if command -v mlbuild > /dev/null; then mlbuild "$@"; else "$@"; fi; }

mutate() {  # name, file, text, replacement
    local name=$1 file=$2 old=$3 new=$4 dir=$work/$1
    [[ $only == "  " || $only == *" $name "* ]] || return 0
    rm -rf "$dir" && mkdir -p "$dir"
    cp -r "$root/include" "$root/src" "$root/tests" "$root/reference" "$dir"/
    if ! python3 - "$dir/$file" "$old" "$new" <<'PY'
import sys
path, old, new = sys.argv[1:4]
text = open(path).read()
if text.count(old) != 1:
    sys.exit(1)
open(path, 'w').write(text.replace(old, new))
PY
    then
        echo "$name: the text to replace is not in $file (once)"
        return
    fi
    (
        cd "$dir" || exit 1
        export flags="-O2 -std=c++20 -ffp-contract=off -Iinclude -Isrc -Ireference -Itests/common -I/usr/include/eigen3"
        lock bash -c 'printf "%s\n" src/core/dyadic.cpp src/core/exact.cpp src/core/exact_predicates.cpp src/core/predicates.cpp src/core/rounding.cpp \
                          tests/core/test_predicates.cpp tests/core/test_exact.cpp |
                      xargs -P2 -I{} sh -c "ccache g++ \$flags -c {} -o \$(basename {} .cpp).o" &&
                      for t in test_predicates test_exact; do
                          g++ $t.o dyadic.o exact.o exact_predicates.o predicates.o rounding.o -lgtest -lgtest_main -lgmpxx -lgmp -pthread -o $t || exit 1
                      done' > build.log 2>&1 || { echo "$name: build failed (see $dir/build.log)"; exit 0; }
        failed=$( (./test_predicates; ./test_exact) 2>&1 | sed -n 's/^\[  FAILED  \] \([A-Za-z]*\.[A-Za-z]*\) (.*/\1/p')
        echo "$name: ${failed:-none}" | tr '\n' ' '
        echo
    )
}

A=include/momentlab/core/approx.hpp
X=src/core/exact.cpp
mutate none $A "kUnitRoundoff = 0x1p-53;" "kUnitRoundoff = 0x1p-53;"
mutate unit_2^-60 $A "return depth * kUnitRoundoff * (1 + 0x1p-40);" "return depth * 0x1p-60 * (1 + 0x1p-40);"
mutate slack_0 $A "return depth * kUnitRoundoff * (1 + 0x1p-40);" "return depth * kUnitRoundoff;"
mutate underflow_0 $A "kUnderflowMagnitude = 0x1p-1020;" "kUnderflowMagnitude = 0;"
mutate product_depth_max $A "a.depth + b.depth + 1};" "(a.depth > b.depth ? a.depth : b.depth) + 1};"
mutate sum_depth_no_rounding $A \
    "a.magnitude + b.magnitude, (a.depth > b.depth ? a.depth : b.depth) + 1};" \
    "a.magnitude + b.magnitude, (a.depth > b.depth ? a.depth : b.depth)};"
mutate exact_sum_magnitude_half $A "? std::fabs(v) : a.magnitude + b.magnitude" "? 0.5 * std::fabs(v) : a.magnitude + b.magnitude"
mutate within_2^45 $A "m = error * 0x1p51;" "m = error * 0x1p45;"
mutate within_depth_1 $A "kWithinDepth = 4;" "kWithinDepth = 1;"
mutate cross_error_2^-60 $X "times_power_of_two(s->sums, s->scale - 51)" "times_power_of_two(s->sums, s->scale - 60)"
mutate rounding_error_2^-60 $X "return Vec3(0x1p-51 * std::fabs(a.x()) + floor, 0x1p-51 * std::fabs(a.y()) + floor, 0x1p-51 * std::fabs(a.z()) + floor);" \
    "return Vec3(0x1p-60 * std::fabs(a.x()) + floor, 0x1p-60 * std::fabs(a.y()) + floor, 0x1p-60 * std::fabs(a.z()) + floor);"
mutate expansion_range_2^-400 src/core/error_free.hpp "(a >= 0x1p-250 && a <= 0x1p250)" "(a >= 0x1p-400 && a <= 0x1p250)"
mutate integer_range_2^52 src/core/predicates.cpp "if (!(std::fabs(x) <= 0x1p40)) return false;" "if (!(std::fabs(x) <= 0x1p52)) return false;"
mutate no_accurate_cross src/core/predicates.cpp \
    "if (in_expansion_range(b) && in_expansion_range(c) && filter_sign(" "if (false && filter_sign("
