#!/usr/bin/env bash
# Mutation checks (docs/validation.md, "Mutations"): each entry below shrinks an error bound or
# plants a plausible bug in a library source, rebuilds the target of the test that must notice in
# build/mutations (the source is restored as soon as it is built, also on error or interrupt),
# runs that test and expects it to FAIL. Prints one line per mutation, "caught" or "NOT caught";
# exits 1 if any was not caught.
# Usage: tools/mutations.sh [name ...]   (all when none is named; the first build compiles the
# library, later ones one file and the test)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=build/mutations
lock=$(command -v mlbuild || true)  # this machine's build lock, when there is one
py="env PYTHONPATH=$root/$build/python MOMENTLAB_CLI=$root/$build/momentlab MPLBACKEND=Agg PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 -m pytest -q -x -p no:cacheprovider"

# name | file | sed expression | target to build | command that must fail
mutations=(
    "one-shot-unit-2^-60|include/momentlab/core/approx.hpp|s/return depth \* kUnitRoundoff \* (1 + 0x1p-40);/return depth * 0x1p-60 * (1 + 0x1p-40);/|test_one_shot|$build/tests/test_one_shot"
    "one-shot-underflow-zero|include/momentlab/core/approx.hpp|s/kUnderflowMagnitude = 0x1p-1020;/kUnderflowMagnitude = 0;/|test_one_shot|$build/tests/test_one_shot"
    "one-shot-no-propagation|include/momentlab/core/approx.hpp|s/std::fabs(v) : a.magnitude \* b.magnitude;/std::fabs(v) : std::fabs(v);/|test_one_shot|$build/tests/test_one_shot"
    "orient2d-unit-2^-60|include/momentlab/core/approx.hpp|s/return depth \* kUnitRoundoff \* (1 + 0x1p-40);/return depth * 0x1p-60 * (1 + 0x1p-40);/|test_polygon|$build/tests/test_polygon"
    "orient2d-difference-magnitude-half|include/momentlab/core/approx.hpp|s/? std::fabs(v) : a.magnitude + b.magnitude/? 0.5 * std::fabs(v) : a.magnitude + b.magnitude/|test_polygon|$build/tests/test_polygon"
    "modes-first-crossing-only|src/mechanics/modes.cpp|s/for (int t : changed) {\$/for (int t : changed.first(1)) {/|test_analysis|$build/tests/test_analysis --gtest_filter=*DirectQuery*:*LongFaces*:*Grouped*:*Large*:*Rings*:*OneShotAgrees*"
    "margin-inside-short|src/mechanics/margin.cpp|s/least = std::min(least, std::max(0.0, scaled_facet(f, r, metric.length).dot(p)));/least = std::min(least, 0.99 * std::max(0.0, scaled_facet(f, r, metric.length).dot(p)));/|test_margin|$build/tests/test_margin"
    "margin-other-no-2d-faces|src/mechanics/margin.cpp|s/if (const auto d = distance_in_face(p, face_rays, lines))/if (const auto d = face.dimension == 1 ? distance_in_face(p, face_rays, lines) : std::nullopt)/|test_margin|$build/tests/test_margin"
    "closure-quality-short|src/mechanics/closure.cpp|s/radius = std::min(radius, d);/radius = std::min(radius, 0.98 * d);/|test_closure|$build/tests/test_closure"
    "reach-plus-g|src/planning/fixed_wrench.cpp|s/ExactVector::from_exact(-fixed)/ExactVector::from_exact(fixed)/|test_fixed_wrench|$build/tests/test_fixed_wrench"
    "push-feasible-as-no|src/planning/push.cpp|s/c.verdict = robust_anywhere                                                    ? PushVerdict::Feasible/c.verdict = robust_anywhere ? PushVerdict::Infeasible/|_momentlab|$py tests/python/test_planners_oracle.py -k push_against"
    "magnitudes-printed-high|src/planning/fixed_wrench.cpp|s/{ return nearest_double(num, den); }/{ return nearest_double(num, den) * (1 + 0x1p-20); }/|_momentlab|$py tests/python/test_planners_oracle.py -k bands"
    "arcs-wider|src/planning/directions.cpp|s/const double to = from + width;/const double to = from + width + 1e-6;/|_momentlab|$py tests/python/test_planners_oracle.py -k tilt_and_comply"
)

selected=("$@")
wanted() {
    [ ${#selected[@]} -eq 0 ] && return 0
    for s in "${selected[@]}"; do [ "$s" = "$1" ] && return 0; done
    return 1
}

[ -f "$build/CMakeCache.txt" ] || cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMOMENTLAB_PYTHON=ON \
    -DPython_EXECUTABLE=/usr/bin/python3 $(command -v ccache >/dev/null && echo -DCMAKE_CXX_COMPILER_LAUNCHER=ccache) >/dev/null

# Mutates, builds and restores, all while holding the build lock (so that no other build of this
# tree sees the mutant).
build_mutant() {
    local file=$1 expr=$2 target=$3 backup
    backup=$(mktemp)
    cp "$file" "$backup"
    trap 'cp "$backup" "$file"' EXIT INT TERM
    sed -i "$expr" "$file"
    if cmp -s "$file" "$backup"; then
        echo "the expression changed nothing in $file (a stale entry)" >&2
        cp "$backup" "$file"
        return 3
    fi
    local status=0
    cmake --build "$build" -j2 --target "$target" >"$build/last-build.log" 2>&1 || status=$?
    cp "$backup" "$file"
    rm -f "$backup"
    trap - EXIT INT TERM
    return $status
}
export -f build_mutant
export build

missed=0
for entry in "${mutations[@]}"; do
    IFS='|' read -r name file expr target command <<<"$entry"
    wanted "$name" || continue
    if ! $lock bash -c 'build_mutant "$@"' _ "$file" "$expr" "$target"; then
        echo "$name: could not build the mutant ($build/last-build.log)"
        missed=1
        continue
    fi
    if $command >"$build/$name.log" 2>&1; then
        echo "$name: NOT caught by $command"
        missed=1
    else
        failed=$(sed -n -e 's/^\[  FAILED  \] \([A-Za-z0-9_.]*\) (.*/\1/p' -e 's/^FAILED \([^ ]*\).*/\1/p' "$build/$name.log" | tr '\n' ' ')
        echo "$name: caught: ${failed:-see $build/$name.log}"
    fi
done
# The last mutant's objects stay in build/mutations; the next build there recompiles the restored sources.
exit $missed
