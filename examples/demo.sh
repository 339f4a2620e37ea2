#!/usr/bin/env bash
# The main job on the bundled examples: textbook problems first (docs/problems.md), then the
# paper (Mason 1991): moment labels of its Figure 1 and 2 force sets, the contact problem (every
# mode of the bundled scenes with its sets, and which mode an applied wrench produces), grasp
# closure, assemblies of several bodies (`stand`), planning by tilting, pushing and compliance;
# last, the figures drawn from these files into OUT (default: out/).
set -euo pipefail
bin=${1:?usage: demo.sh path/to/momentlab [OUT]}
out=${2:-out}
here=$(cd "$(dirname "$0")" && pwd)
show() {
    echo
    echo "== $1"
    echo "   momentlab ${*:2}" | sed "s#$here/#examples/#g"
    "$bin" "${@:2}"
}
# Textbook problems, each worked by hand in docs/problems.md and asserted by tests/python/test_problems.py.
echo "#### Textbook problems (docs/problems.md works each one by hand)"
show "A ladder at 60 degrees to the floor, mu = 0.3 at both ends, under its weight (0, -9.81) through (0.5, 0.866): it stands (ff), since tan 60 > (1 - 0.3^2) / (2 x 0.3)" \
    query "$here/problem-ladder.json" --wrench 0 -9.81 -4.905
show "A block 1 wide, pushed at height 0.5: at rest up to mu m g = 4.905, then it slides (rr) until its front lifts (rs)" \
    query "$here/problem-block-push.json" --gravity 0 -9.81 --push 0 0.5 1 0
show "... pushed at height 1.25: at rest up to m g w / 2h = 3.924, then it tips about its front corner (sf)" \
    query "$here/problem-block-push.json" --gravity 0 -9.81 --push 0 1.25 1 0
show "A peg tilted in a hole, pushed through (0, 2): the directions that insert it (rl)" \
    plan comply "$here/problem-peg-in-hole.json" --goal rl --centre 0 2
show "... and the directions that jam it (ff)" plan comply "$here/problem-peg-in-hole.json" --goal ff --centre 0 2
show "Two fingers on a square, offset 0.5 < 2 mu = 0.6: force closure" closure "$here/problem-two-finger-grasp.json"

echo
echo "#### The paper: Mason, \"Two Graphical Methods for Planar Contact Problems\" (IROS 1991)"
show "Figure 1a: a force along +x through the origin" label "$here/figure-1a-force.json" --at 0 1 --at 0 -1 --at 3 0
show "Figure 1b: all forces through the point (1, 2)" label "$here/figure-1b-point.json" --at 1 2 --at 0 0
show "Figure 1c: friction cone at the origin, normal +y, mu = 0.5" label "$here/figure-1c-friction-cone.json" --at -1 0 --at 1 0 --at 0 0
show "Figure 2: two friction cones combined (labels intersected)" label "$here/figure-2-two-friction-cones.json" --at -1 0 --at 3 1
show "Intersection of two parallel forces on different lines: only the zero wrench (the paper's hull shorthand would give y >= 0)" label "$here/parallel-rays-intersection.json" --at 0 -1
show "Figure 3: the block along the wall, every mode (goal: rr)" analyze "$here/figure-3-block-along-wall.json"
show "Figure 4: two-point peg insertion, every mode (goal: rl, down in two-point contact)" analyze "$here/figure-4-peg-in-hole.json"
show "A peg on the hole's lip (normals meet at (4, -1.5)): every mode" modes "$here/figure-4b-peg-on-the-lip.json"
show "A block on a table: every mode" modes "$here/block-on-table.json"
show "... under its weight alone" query "$here/block-on-table.json" --wrench 0 -9.81 -4.905
show "... pushed with 20 N along its base" query "$here/block-on-table.json" --wrench 20 -9.81 -5.105
show "... pushed with 20 N near its top" query "$here/block-on-table.json" --wrench 20 -9.81 -14.705
show "A rod wedged in a corner (mu = 2): every mode" modes "$here/rod-in-corner.json"
show "... a wrench that can both jam it (ff) and throw it off (ss): Painleve-style ambiguity" query "$here/rod-in-corner.json" --wrench 19 16 -2
show "A wheel held at (5, 0), (3, 4), (-3, -4) by normals through its centre, written with length 5: exact, so no sss (contacts 2 and 3 face each other)" modes "$here/downstream/wheel.json"
show "... turned by a clockwise torque: it rolls (lll) or lifts off contact 1 (sll)" query "$here/downstream/wheel.json" --wrench 0 0 -1
show "Quasi-static (inertia neglected, E = -T): a push along the floor with no load is held by nothing (inconsistent); dynamically it slides" query "$here/figure-3-block-along-wall.json" --wrench 1 0 -0.25 --quasi-static
show "... pressed down and pushed at exactly mu: held at rest or sliding right" query "$here/figure-3-block-along-wall.json" --wrench 0.5 -1 -0.625 --quasi-static

# Grasp closure (Modern Robotics, ch. 12): do the contacts resist every wrench?
show "Four frictionless contacts at a square's side midpoints: a torque about the centre is unresisted" closure "$here/closure-four-midpoints.json"
show "Five contacts: form closure" closure "$here/closure-five-contacts.json"
show "Two frictional fingers nearly opposite: force closure, not form closure" closure "$here/closure-antipodal-fingers.json"

# Assemblies (docs/assemblies.md works each by hand): several bodies under gravity; bodies 1..N, 0 the world.
show "Two blocks of Modern Robotics (ch. 12): body 1 leans on body 2; with mu = 0.1 at its foot it needs 10/31, so it falls (its mechanism drawn below: out/assembly-falls)" \
    stand "$here/assembly-modern-robotics.json"
show "A ladder on a frictionless wall, mu = 3/8 = 1 / (2 tan a) at the floor: it stands, on the boundary; gravity (gamma, -1) keeps it up for gamma in [0, 3/2]" \
    stand "$here/assembly-ladder.json" --tilt
show "A three-block arch at mu = 0.3 (it needs (sqrt 29 - 3)/10 = 0.2385): it stands; drawn below with its forces (out/assembly-arch)" \
    stand "$here/assembly-arch.json"

# Planning (the paper's section 3): reaching the goal rr (slide along the wall, no turning).
show "Tilting the block along the wall: which gravity directions slide it right (rr)" plan tilt "$here/figure-3-block-along-wall.json" --goal rr
show "Pushing it: 4 edges + 4 vertices x 3 finger slips = 24 cases (the paper finds 4)" plan push "$here/figure-3-block-along-wall.json" --goal rr
show "A spring through a compliance centre at its outboard trailing corner" plan comply "$here/figure-3-block-along-wall.json" --goal rr --centre 0 0.5

# Gravity plus a push: the magnitude matters (docs/planning.md, "A fixed wrench plus a push").
show "The block on the table under gravity (0, -9.81), pushed horizontally at the top of its rear face: at rest, sliding (rr), then tipping (sr)" query "$here/block-on-table.json" --gravity 0 -9.81 --push 0 0.5 1 0
show "... pushed low, at height 0.1: it slides, then its front lifts (rs)" query "$here/block-on-table.json" --gravity 0 -9.81 --push 0 0.1 1 0
show "... which pushes of a sticking finger on the rear face tip it (sr), and how hard" plan push "$here/block-on-table.json" --goal sr --gravity 0 -9.81 --edge 3 --slip f

# Many questions at once (a planner's use): one wrench per line in, one JSON answer per line out.
wrenches=$(mktemp)
printf '%s\n' '[0, -9.81, -4.905]' '[20, -9.81, -5.105]' '[20, -9.81, -14.705]' '[0, 9.81, 4.905]' > "$wrenches"
echo
echo "== The block on the table, four wrenches at once (weight; pushed at the base; near the top; lifted)"
echo "   momentlab query examples/block-on-table.json --wrenches wrenches.txt"
"$bin" query "$here/block-on-table.json" --wrenches "$wrenches"
rm -f "$wrenches"

# Bad input: exit status 2 and one line naming the field (docs/reliability.md has the table).
bad=$(mktemp)
printf '%s' '{"contacts": [{"point": [0, 0], "normal": [0, 1], "mu": -0.3}]}' > "$bad"
echo
echo "== Bad input gets one line naming the field, exit status 2"
echo "   momentlab modes bad.json   (mu = -0.3)"
"$bin" modes "$bad" || echo "   (exit status $?)"
rm -f "$bad"

# The paper's figures, drawn from the bundled files (SVG for reading, PNG for showing).
mkdir -p "$out"
echo
echo "== The paper's Figures 1-6, drawn"
figure() {  # figure NAME TITLE ARGS...
    local name=$1 title=$2
    shift 2
    echo "   momentlab $* --title \"$title\" -o $out/$name.svg -o $out/$name.png" | sed "s#$here/#examples/#g"
    "$bin" "$@" --title "$title" -o "$out/$name.svg" -o "$out/$name.png" >/dev/null
}
figure figure-1a "Figure 1a: a line of force" label "$here/figure-1a-force.json"
figure figure-1b "Figure 1b: all forces through a point" label "$here/figure-1b-point.json"
figure figure-1c "Figure 1c: a friction cone" label "$here/figure-1c-friction-cone.json"
figure figure-2 "Figure 2: two friction cones and their resultants" label "$here/figure-2-two-friction-cones.json"
figure figure-3 "Figure 3: sliding the block along the wall (mode rr)" \
    draw "$here/figure-3-block-along-wall.json" --mode rr
figure figure-3-modes "The block along the wall: every contact mode" \
    draw "$here/figure-3-block-along-wall.json" --what modes
figure figure-4 "Figure 4: two-point peg insertion (mode rl)" draw "$here/figure-4-peg-in-hole.json" --mode rl
figure figure-4b "A peg on the hole's lip: sliding in turns it about (4, -1.5), so its inertia matters (mode rl)" \
    draw "$here/figure-4b-peg-on-the-lip.json" --mode rl
figure figure-5 "Figure 5: tilting the block along the wall (goal rr)" \
    plan tilt "$here/figure-3-block-along-wall.json" --goal rr
figure figure-6 "Figure 6: pushing the trailing edge, finger slip l (goal rr)" \
    plan push "$here/figure-3-block-along-wall.json" --goal rr --edge 3 --slip l
figure push-vertex "Pushing the outboard trailing vertex, finger stuck (goal rr)" \
    plan push "$here/figure-3-block-along-wall.json" --goal rr --vertex 3 --slip f
figure comply "A compliance centre at (0, 0.5) (goal rr)" \
    plan comply "$here/figure-3-block-along-wall.json" --goal rr --centre 0 0.5
figure rod-in-corner-modes "A rod in a corner: every contact mode" draw "$here/rod-in-corner.json" --what modes
figure assembly-falls "Two blocks of Modern Robotics fall (mu = 0.1 at the foot < 10/31): a collapse mechanism" \
    draw "$here/assembly-modern-robotics.json" --what stand
figure assembly-arch "A three-block arch at mu = 0.3 stands: the forces of one equilibrium, each block's labels" \
    draw "$here/assembly-arch.json" --what stand
figure problem-ladder-slip "How the ladder slips, when it does (rr): it turns about (1, 1.73)" \
    draw "$here/problem-ladder.json" --mode rr
figure problem-peg "A peg in a hole pushed through (0, 2): the directions that slide it in (rl)" \
    plan comply "$here/problem-peg-in-hole.json" --goal rl --centre 0 2
figure problem-grasp "Two fingers on a square, offset 0.5 < 2 mu = 0.6: no labels, force closure" \
    draw "$here/problem-two-finger-grasp.json" --what closure
figure closure-four-midpoints "Four midpoints: the + and - regions say which turns nothing resists" \
    draw "$here/closure-four-midpoints.json" --what closure
figure closure-antipodal-fingers "Two fingers: no labels for the friction cones, force closure" \
    draw "$here/closure-antipodal-fingers.json" --what closure
echo "   pictures written to $out/:"
ls "$out" | sed 's/^/     /'
