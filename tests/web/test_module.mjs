// out/web/momentlab.mjs in node (docs/web.md): against the answers the exact oracle of
// tests/python/oracle.py wrote to tests/web/oracle_fixtures.json (modes, queries, tilt and spring
// arcs, push cases with no solution), and against the CLI: the same library compiled twice
// (native and WebAssembly, both on momentlab's own exact arithmetic, no GMP) must give the same
// modes and the same answers to every wrench, on the kernel's hard cases (exactly concurrent
// normals, parallel and opposed normals, repeated points, dyadic boundary wrenches) and on random
// scenes; bad input throws a JS Error with the CLI's one-line message.
//   node --no-experimental-fetch --test tests/web/test_module.mjs   (MOMENTLAB_CLI, MOMENTLAB_WEB)
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';

import { assertClose } from './assert_close.mjs';

const ROOT = new URL('../../', import.meta.url).pathname;
const CLI = process.env.MOMENTLAB_CLI || join(ROOT, 'build/release/momentlab');
const WEB = process.env.MOMENTLAB_WEB || join(ROOT, 'out/web');
const ml = await (await import(join(WEB, 'momentlab.mjs'))).default();
const scratch = mkdtempSync(join(tmpdir(), 'momentlab-web-'));

function cliModes(file) {
  return JSON.parse(execFileSync(CLI, ['modes', file, '--json'], { encoding: 'utf8' })).modes;
}

// One CLI run for all the wrenches of a scene: JSON lines {modes, verdict, wrench}.
function cliQueries(file, wrenches) {
  const list = join(scratch, 'wrenches.txt');
  writeFileSync(list, wrenches.map((w) => JSON.stringify(w)).join('\n') + '\n');
  const out = execFileSync(CLI, ['query', file, '--wrenches', list], { encoding: 'utf8' });
  return out.trim().split('\n').map((line) => JSON.parse(line));
}

// A random generator that the test controls (so a failure can be replayed).
function rng(seed) {
  let s = seed >>> 0;
  return () => {
    s = (s * 1664525 + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}
const pick = (r, xs) => xs[Math.floor(r() * xs.length)];
const dyadic = (r, lo, hi, den) => Math.round((lo + (hi - lo) * r()) * den) / den;

// Scenes on the 1/8 grid, half of them degenerate in the ways that decide modes exactly.
function randomScene(r, n) {
  const kind = pick(r, ['generic', 'concurrent', 'parallel', 'opposed', 'repeated']);
  const centre = [dyadic(r, -1, 1, 8), dyadic(r, -1, 1, 8)];
  const contacts = [];
  for (let j = 0; j < n; ++j) {
    let point = [dyadic(r, -2, 2, 8), dyadic(r, -2, 2, 8)];
    let normal = [dyadic(r, -2, 2, 4), dyadic(r, -2, 2, 4)];
    if (kind === 'concurrent') normal = [centre[0] - point[0], centre[1] - point[1]];  // all through one point
    if (kind === 'parallel') normal = [0, pick(r, [1, 2, 0.5])];
    if (kind === 'opposed' && j % 2 === 1) { point = [contacts[j - 1].point[0] + 1, contacts[j - 1].point[1]]; normal = [-contacts[j - 1].normal[0], -contacts[j - 1].normal[1]]; }
    if (kind === 'repeated' && j > 0) point = contacts[0].point.slice();
    if (normal[0] === 0 && normal[1] === 0) normal = [0, 1];
    const mu = pick(r, [0, 0.25, 0.5, 1, 1.5]);
    contacts.push({ point, normal, mu, mu_kinetic: pick(r, [mu, mu / 2]) });
  }
  return { body: { mass: pick(r, [1, 2, 0.5]), com: [dyadic(r, -1, 1, 8), dyadic(r, -1, 1, 8)], inertia: pick(r, [0.125, 0.5, 1]) },
           contacts };
}

function compareScene(doc, wrenches) {
  const file = join(scratch, 'scene.json');
  const text = JSON.stringify(doc);
  writeFileSync(file, text);
  const a = ml.analyze(text);
  try {
    assert.deepEqual(a.modes, cliModes(file), text);
    const answers = cliQueries(file, wrenches);
    const batch = a.queryBatch(wrenches);
    wrenches.forEach((w, i) => {
      assert.deepEqual(a.query(w), answers[i].modes, `${text} ${JSON.stringify(w)}`);
      assert.equal(a.verdict(w), answers[i].verdict);
      assert.deepEqual(a.modes.filter((_, k) => batch[i * a.modes.length + k] === 1).sort(), answers[i].modes);
    });
  } finally {
    a.delete();
  }
}

test('the bundled scenes and the wheel: the CLI modes and answers', () => {
  const files = readdirSync(join(ROOT, 'examples')).filter((f) => f.endsWith('.json')).map((f) => join(ROOT, 'examples', f));
  files.push(join(ROOT, 'examples/downstream/wheel.json'));
  const r = rng(7);
  let scenes = 0;
  for (const file of files) {
    const doc = JSON.parse(readFileSync(file, 'utf8'));
    if (!doc.body) continue;
    const wrenches = Array.from({ length: 40 }, () => [dyadic(r, -2, 2, 4), dyadic(r, -2, 2, 4), dyadic(r, -2, 2, 4)]);
    compareScene(doc, wrenches);
    ++scenes;
  }
  assert.ok(scenes >= 5, `${scenes} scenes`);
  // The wheel of issue 14 (normals meeting in its centre): the torque (0, 0, -1) turns it (lll)
  // or turns it while lifting contact 1 (sll), by hand in tests/mechanics/test_modes.cpp.
  const wheel = ml.analyze(readFileSync(join(ROOT, 'examples/downstream/wheel.json'), 'utf8'));
  assert.deepEqual([...wheel.query([0, 0, -1])].sort(), ['lll', 'sll']);
  wheel.delete();
});

test('random and degenerate scenes: the CLI modes and answers, boundary wrenches included', () => {
  const r = rng(1991);
  for (let k = 0; k < 120; ++k) {
    const doc = randomScene(r, 1 + (k % 4));
    // Wrenches on a coarse dyadic grid land on the boundaries between modes often.
    const wrenches = Array.from({ length: 24 }, () => [dyadic(r, -2, 2, 2), dyadic(r, -2, 2, 2), dyadic(r, -2, 2, 2)]);
    compareScene(doc, wrenches);
  }
});

test('plans and labels equal the CLI', () => {
  const file = join(ROOT, 'examples/figure-3-block-along-wall.json');
  const a = ml.analyze(readFileSync(file, 'utf8'));
  for (const goal of a.modes) {
    const tilt = JSON.parse(execFileSync(CLI, ['plan', 'tilt', file, '--goal', goal, '--json'], { encoding: 'utf8' }));
    assertClose(a.planTilt(goal), tilt);
    const push = JSON.parse(execFileSync(CLI, ['plan', 'push', file, '--goal', goal, '--json'], { encoding: 'utf8' }));
    assertClose(a.planPush(goal).cases, push.cases);
    const comply = JSON.parse(execFileSync(CLI, ['plan', 'comply', file, '--goal', goal, '--centre', '0.875', '0.25', '--json'], { encoding: 'utf8' }));
    const mine = a.planComply(goal, [0.875, 0.25]);
    assertClose(mine.centre, comply.centre);
    for (const sheet of ['plus', 'minus']) {
      for (const key of ['kind', 'vertices', 'rays', 'lines']) assert.deepEqual(mine.labels[sheet][key], comply.labels[sheet][key]);
    }
  }
  a.delete();
  const label = JSON.parse(execFileSync(CLI, ['label', join(ROOT, 'examples/figure-2-two-friction-cones.json'), '--json'], { encoding: 'utf8' }));
  const mine = ml.forceSetLabels(readFileSync(join(ROOT, 'examples/figure-2-two-friction-cones.json'), 'utf8'), [-2, -2, 4, 4]);
  assert.deepEqual(mine.cone, label.cone);
  for (const sheet of ['plus', 'minus']) {
    for (const key of ['kind', 'vertices', 'rays', 'lines']) assert.deepEqual(mine[sheet][key], label.labels[sheet][key]);
    assert.ok(mine[sheet].clipped.length >= 3);
  }
});

test('closure and the quasi-static model equal the CLI', () => {
  for (const name of ['closure-four-midpoints', 'closure-five-contacts', 'closure-antipodal-fingers']) {
    const file = join(ROOT, 'examples', `${name}.json`);
    const cli = JSON.parse(execFileSync(CLI, ['closure', file, '--json'], { encoding: 'utf8' }));
    assertClose(ml.graspClosure(readFileSync(file, 'utf8')), cli);  // the quality is rounded arithmetic
  }
  const r = rng(77);
  for (let k = 0; k < 30; ++k) {
    const doc = randomScene(r, 1 + (k % 3));
    delete doc.body;  // quasi-static needs no body
    const file = join(scratch, 'qs.json');
    writeFileSync(file, JSON.stringify(doc));
    const wrenches = Array.from({ length: 16 }, () => [dyadic(r, -2, 2, 2), dyadic(r, -2, 2, 2), dyadic(r, -2, 2, 2)]);
    const list = join(scratch, 'qs.txt');
    writeFileSync(list, wrenches.map((w) => JSON.stringify(w)).join('\n') + '\n');
    const answers = execFileSync(CLI, ['query', file, '--wrenches', list, '--quasi-static'], { encoding: 'utf8' })
      .trim().split('\n').map((l) => JSON.parse(l).modes);
    const a = ml.analyze(JSON.stringify(doc), { quasiStatic: true });
    wrenches.forEach((w, i) => assert.deepEqual(a.query(w), answers[i]));
    a.delete();
  }
});

// Against the exact oracle of tests/python/oracle.py (Fractions, no momentlab code), through the
// answers it wrote to tests/web/oracle_fixtures.json (tests/web/oracle_fixtures.py): modes,
// answers and verdicts of every wrench; tilt and compliance arcs probed at 48 angles (the goal
// alone inside a unique arc, the goal and another inside a shared one, the goal inside the union,
// no goal outside it; angles within 1e-9 of an end left out); push cases with no solution ("no")
// given no sampled push of their W that produces the goal. (The module has no query margins and
// no push bands along a line: those are checked in the CLI and Python tests only.)
const fixtures = JSON.parse(readFileSync(join(ROOT, 'tests/web/oracle_fixtures.json'), 'utf8'));
const SLACK = 1e-9;

function within(angle, arcs, slack) {
  return arcs.some(([a, b]) => [angle, angle + 2 * Math.PI, angle - 2 * Math.PI].some((t) => a - slack <= t && t <= b + slack));
}

// One plan of directions (a tilt, or a spring through a centre) against the oracle's modes at each angle.
function checkArcs(plan, goal, answers, counts, what) {
  const unique = plan.unique || [], shared = plan.shared || [], union = plan.intervals;
  fixtures.angles.forEach((angle, k) => {
    const got = answers[k], where = `${what}, angle ${angle}: oracle ${got}; plan ${JSON.stringify(plan)}`;
    const near = [...unique, ...shared, ...union].some(([a, b]) => [a, b].some((end) =>
      [angle, angle + 2 * Math.PI, angle - 2 * Math.PI].some((t) => Math.abs(t - end) <= SLACK)));
    if (near) {
      counts.near += 1;
    } else if (within(angle, unique, -SLACK)) {
      assert.deepEqual(got, [goal], where);
      counts.unique += 1;
    } else if (within(angle, shared, -SLACK)) {
      assert.ok(got.includes(goal) && got.length > 1, where);
      counts.shared += 1;
    } else if (within(angle, union, -SLACK)) {
      assert.ok(got.includes(goal), where);
      counts.union += 1;
    } else {
      assert.ok(!got.includes(goal), where);
      counts.outside += 1;
    }
  });
}

test('modes, answers and verdicts: the exact oracle\'s', () => {
  let queries = 0, several = 0;
  for (const f of fixtures.scenes) {
    const text = JSON.stringify(f.scene);
    const a = ml.analyze(text);
    try {
      assert.deepEqual([...a.modes].sort(), f.modes, text);
      const wrenches = f.queries.map((q) => q.wrench);
      const batch = a.queryBatch(wrenches);
      f.queries.forEach((q, i) => {
        assert.deepEqual([...a.query(q.wrench)].sort(), q.modes, `${text} ${JSON.stringify(q.wrench)}`);
        assert.equal(a.verdict(q.wrench), ['inconsistent', 'unique', 'ambiguous'][Math.min(q.modes.length, 2)]);
        assert.deepEqual(a.modes.filter((_, k) => batch[i * a.modes.length + k] === 1).sort(), q.modes);
        queries += 1;
        several += q.modes.length > 1;
      });
    } finally {
      a.delete();
    }
  }
  assert.ok(queries >= 300 && several >= 50, `${queries} queries, ${several} in several modes`);
});

test('tilts, springs and pushes: the exact oracle\'s', () => {
  const counts = { unique: 0, shared: 0, union: 0, outside: 0, near: 0, no: 0, noPushes: 0 };
  for (const f of fixtures.scenes) {
    const a = ml.analyze(JSON.stringify(f.scene));
    try {
      for (const p of f.plans) {
        checkArcs(a.planTilt(p.goal), p.goal, p.tilt, counts, `tilt ${p.goal}`);
        checkArcs(a.planComply(p.goal, p.centre).centre, p.goal, p.comply, counts, `spring through ${p.centre}, ${p.goal}`);
        const cases = a.planPush(p.goal, { mu: fixtures.finger_mu, ignoreInterference: true }).cases;
        for (const sampled of p.push) {
          const c = cases.find((x) => x.feature === sampled.feature && x.slip === sampled.slip);
          assert.ok(c, `${sampled.feature} ${sampled.slip}`);
          if (c.verdict !== 'no') continue;
          counts.no += 1;
          sampled.gives_goal.forEach((gives, i) => {
            assert.equal(gives, false, `${p.goal}: ${c.feature} ${c.slip} is "no" but the push ${sampled.pushes[i]} gives the goal`);
            counts.noPushes += 1;
          });
        }
      }
    } finally {
      a.delete();
    }
  }
  assert.ok(counts.unique >= 200 && counts.shared >= 20 && counts.outside >= 200 && counts.noPushes >= 200, JSON.stringify(counts));
  assert.ok(counts.near * 50 < counts.unique + counts.shared + counts.union + counts.outside, JSON.stringify(counts));
});

test('bad input throws an Error with the CLI message', () => {
  // The ladder, drawn 0.1 into its wall (contacts found from the polygons): refused.
  const ladder = '{"body": {"mass": 1, "com": [1.05, 2], "inertia": 1, "polygon": [[0, 0], [0.1, 0], [2.1, 4], [2, 4]]}, "mu": 0.3, ' +
    '"obstacles": [{"polygon": [[-1, -1], [3, -1], [3, 0], [-1, 0]]}, {"polygon": [[2, 0], [3, 0], [3, 5], [2, 5]]}]}';
  assert.throws(() => ml.analyze(ladder), /^Error: \$\.obstacles\[1\]\.polygon: overlaps the body polygon \(\$\.body\.polygon\), for instance at \(/);
  const bad = [
    ladder,
    '{"body": {"mass": 1, "com": [0, 0], "inertia": 1}, "contacts": [{"point": [0, 0], "normal": [0, 1], "mu": -1}]}',
    '{"body": {"mass": 1, "com": [0, 0], "inertia": 1}, "contacts": [{"point": [0, 0], "normal": [0, 0]}]}',
    '{"body": {"mass": 0, "com": [0, 0], "inertia": 1}, "contacts": [{"point": [0, 0], "normal": [0, 1]}]}',
    '{"body": {"mass": 1, "com": [0, 0], "inertia": 1}, "contacts": [{"point": [0, 1e-400], "normal": [0, 1]}]}',
    '{"body": {"mass": 1, "mass": 2}}',
    '{not json',
  ];
  for (const text of bad) {
    const file = join(scratch, 'bad.json');
    writeFileSync(file, text);
    const cli = spawnSync(CLI, ['modes', file], { encoding: 'utf8' });
    assert.equal(cli.status, 2);
    assert.throws(() => ml.analyze(text), (e) => e instanceof Error && `momentlab: ${e.message}` === cli.stderr.trim());
  }
  const a = ml.analyze(readFileSync(join(ROOT, 'examples/figure-3-block-along-wall.json'), 'utf8'));
  assert.throws(() => a.query([1, NaN, 0]), /^Error: wrench\[1\]: expected a finite number, got NaN$/);
  assert.throws(() => a.query([1, 2]), /wrench: expected 3 numbers/);
  assert.throws(() => a.queryBatch([[1, 2, 3], [4, Infinity, 6]]), /wrenches\[1\]\[1\]: expected a finite number, got Infinity/);
  assert.throws(() => a.mode('xx'), /no mode "xx" in this scene/);
  assert.throws(() => a.query([1e300, 0, 0]), /^Error: wrench: out of range/);
  assert.throws(() => a.queryBatch([[1, 2, 3, 4], [5, 6]]), /^Error: wrenches\[0\]: expected 3 numbers/);
  assert.throws(() => a.planComply('rr', [1e300, 0]), /^Error: centre: out of range/);
  assert.throws(() => ml.analyze(undefined), /^Error: \$: expected the JSON text of a scene/);
  assert.throws(() => a.planPush('rr', { mu: -1 }), /^Error: mu:/);
  assert.throws(() => a.mode('rr', [1, 1, 0, 0]), /^Error: view:/);
  a.delete();
  assert.throws(() => a.query([0, 0, 1]), /^Error: analysis: already deleted/);
});

// Issue 44 item 6: what a function does not take is an error naming it; what JSON cannot hold is an
// error in one line naming its path; and the module asks the same questions as the CLI with the
// same load (gravity, a wrench, forces at points) and the same input rule (the largest coordinate's).
test('options, NaN, cycles and lone surrogates are refused in one line naming them', () => {
  const file = join(ROOT, 'examples/figure-3-block-along-wall.json');
  const text = readFileSync(file, 'utf8');
  const a = ml.analyze(text);
  const oneLine = (pattern) => (e) => e instanceof Error && !e.message.includes('\n') && pattern.test(e.message);
  assert.throws(() => a.planPush('sr', { gravty: [0, -10] }), oneLine(/^gravty: not an option of planPush/));
  assert.throws(() => a.planTilt('rr', { mu: 1 }), oneLine(/^mu: not an option of planTilt/));
  assert.throws(() => a.planComply('rr', [0, 0], null, { ignoreInterference: true }), oneLine(/^ignoreInterference: not an option of planComply/));
  assert.throws(() => ml.analyze(text, { quasistatic: true }), oneLine(/^quasistatic: not an option of analyze/));
  assert.throws(() => ml.graspClosure(text, { centre: [0, 0] }), oneLine(/^centre: not an option of graspClosure/));
  assert.throws(() => a.query([1, 0, 0], { wrench: [0, 1, 0] }), oneLine(/^wrench: not an option of query/));
  assert.throws(() => a.planTilt('rr', { gravity: [0, -10] }), oneLine(/^gravity: a tilt turns gravity itself/));
  assert.throws(() => a.planTilt('rr', { wrench: [NaN, 0, 0] }), oneLine(/^wrench\[0\]: expected a finite number, got NaN$/));
  assert.throws(() => a.planPush('rr', { mu: NaN }), oneLine(/^mu: expected a finite number, got NaN$/));
  assert.throws(() => a.pushLine([0, NaN], [0, -1]), oneLine(/^point\[1\]: expected a finite number, got NaN$/));
  const nan = JSON.parse(text);
  nan.contacts[0].mu = NaN;
  assert.throws(() => ml.analyze(nan), oneLine(/^\$\.contacts\[0\]\.mu: expected a finite number, got NaN$/));
  assert.throws(() => a.queryBatch(undefined), oneLine(/^wrenches: expected an array/));
  assert.throws(() => a.queryBatch(5), oneLine(/^wrenches: expected an array/));
  const cyclic = JSON.parse(text);
  cyclic.body.self = cyclic;
  assert.throws(() => ml.analyze(cyclic), oneLine(/^\$\.body\.self: a cyclic object/));
  const surrogate = JSON.parse(text);
  surrogate.contacts[0].name = 'a\uD800b';
  assert.throws(() => ml.analyze(surrogate), oneLine(/^\$\.contacts\[0\]\.name: a string with a lone surrogate/));
  assert.throws(() => ml.analyze(text.replace('"contacts"', '"contacts\uDC00"')), oneLine(/^\$: the scene's text holds a lone surrogate/));
  a.delete();
});

test('loads and the input rule: the CLI answers with --gravity, --wrench, --force, --push, closure options', () => {
  const file = join(ROOT, 'examples/figure-3-block-along-wall.json');
  const cli = (...args) => JSON.parse(execFileSync(CLI, args, { encoding: 'utf8' }));
  const a = ml.analyze(readFileSync(file, 'utf8'));
  // The wrench (1, -2, 5e-324) and (1, 0, 1e-61): their largest coordinate is in range (issue 44 item 4).
  for (const w of [[1, -2, 5e-324], [1, 0, 1e-61]]) {
    assert.deepEqual(a.query(w), cli('query', file, '--wrench', ...w.map(String), '--json').modes, JSON.stringify(w));
  }
  // planPush('sr', {gravity}) pushes against gravity (the touch segment reaches (0, 0); without
  // gravity it stops at (0, 0.104)).
  const push = a.planPush('sr', { gravity: [0, -10] });
  assertClose(push, cli('plan', 'push', file, '--goal', 'sr', '--gravity', '0', '-10', '--json'));
  assert.ok(push.cases.some((c) => c.feasible && c.touch.some(([p, q]) => q[1] === 0)));
  assertClose(a.planTilt('rr', { wrench: [0.5, 0, 0.25] }), cli('plan', 'tilt', file, '--goal', 'rr', '--wrench', '0.5', '0', '0.25', '--json'));
  const comply = a.planComply('rr', [0.875, 0.25], null, { forces: [[[0.5, 0.5], [0, -1]]] });
  const cliComply = cli('plan', 'comply', file, '--goal', 'rr', '--centre', '0.875', '0.25', '--force', '0.5', '0.5', '0', '-1', '--json');
  assertClose(comply.centre, cliComply.centre);
  assert.deepEqual(a.query(null, { gravity: [0, -10] }), cli('query', file, '--gravity', '0', '-10', '--json').modes);
  assert.deepEqual(a.query([0.25, 0, 0], { gravity: [0, -10], forces: [[[1, 1], [-1, 0]]] }),
                   cli('query', file, '--wrench', '0.25', '0', '0', '--gravity', '0', '-10', '--force', '1', '1', '-1', '0', '--json').modes);
  const line = cli('query', file, '--push', '0.5', '0.25', '-1', '0', '--gravity', '0', '-10', '--json');
  assertClose(a.pushLine([0.5, 0.25], [-1, 0], { gravity: [0, -10] }), line);
  assert.ok(line.bands.length >= 2, JSON.stringify(line));
  const closureFile = join(ROOT, 'examples/closure-five-contacts.json');
  const mine = ml.graspClosure(readFileSync(closureFile, 'utf8'), { reference: [0.25, 0], length: 2, view: [-2, -2, 2, 2] });
  assert.ok(mine.labels.form.plus && mine.labels.force.minus);
  delete mine.labels;
  assertClose(mine, cli('closure', closureFile, '--reference', '0.25', '0', '--length', '2', '--json'));
  a.delete();
});

test('assemblies: stand answers as `momentlab stand --json`, and bad assemblies as the CLI refuses them', () => {
  const names = readdirSync(join(ROOT, 'examples')).filter((f) => f.startsWith('assembly-'));
  assert.ok(names.length >= 4);
  const outcomes = new Set();
  for (const name of names) {
    const file = join(ROOT, 'examples', name);
    for (const [gravity, args] of [[undefined, []], [[1, -3], ['--gravity', '1', '-3']], [[-0.25, -1], ['--gravity', '-0.25', '-1']]]) {
      const r = ml.stand(readFileSync(file, 'utf8'), gravity === undefined ? { tilt: true } : { gravity, tilt: true });
      const cli = JSON.parse(execFileSync(CLI, ['stand', file, ...args, '--tilt', '--json'], { encoding: 'utf8' }));
      // the scene as read, for drawing: every contact written out with its pair
      assert.equal(r.assembly.bodies.length, JSON.parse(readFileSync(file, 'utf8')).bodies.length, name);
      assert.ok(r.assembly.contacts.every((c) => c.bodies[0] >= 1 && c.bodies[1] >= 0), name);
      delete r.assembly;
      delete r.warnings;
      assert.deepEqual(r, cli, `${name} ${args.join(' ')}`);
      outcomes.add(r.outcome);
    }
  }
  assert.ok(outcomes.has('stands') && outcomes.has('falls'), [...outcomes].join(', '));
  const doc = JSON.parse(readFileSync(join(ROOT, 'examples/assembly-modern-robotics.json'), 'utf8'));
  doc.contacts[1].bodies = [2, 2];
  const bad = join(scratch, 'bad-assembly.json');
  writeFileSync(bad, JSON.stringify(doc));
  const cli = spawnSync(CLI, ['stand', bad], { encoding: 'utf8' });
  assert.equal(cli.status, 2);
  assert.throws(() => ml.stand(doc), { message: cli.stderr.trim().replace(/^momentlab: /, '') });
  assert.throws(() => ml.stand(JSON.stringify(doc), { gravity: [0, NaN] }), /gravity\[1\]: expected a finite number, got NaN/);
  assert.throws(() => ml.stand(JSON.stringify(doc), { mu: 1 }), /mu: not an option of stand/);
});

test('numbers as typed: decimal strings in loads and stand\'s gravity are the decimals, as the CLI reads its options', () => {
  // A block of mass 1 on two floor contacts at mu = 0.3 (docs/design.md): the push 2.943 = 0.3 x 9.81
  // is the threshold, ff and rr both; typed as decimals the module answers as the CLI.
  const block = '{"body":{"mass":1,"com":[0.5,0.25],"inertia":0.1},"contacts":[{"point":[0,0],"normal":[0,1],"mu":0.3},{"point":[1,0],"normal":[0,1],"mu":0.3}]}';
  const file = join(scratch, 'typed-block.json');
  writeFileSync(file, block);
  const a = ml.analyze(block);
  const typed = ['2.943', '-9.81', '-4.905'];
  const cli = JSON.parse(execFileSync(CLI, ['query', file, '--wrench', ...typed, '--json'], { encoding: 'utf8' }));
  assert.deepEqual(cli.modes, ['ff', 'rr']);
  assert.deepEqual(a.query(typed), cli.modes);
  assert.equal(a.verdict(typed), 'ambiguous');
  assert.deepEqual(a.query(null, { gravity: ['0', '-9.81'], forces: [[['0.5', '0.25'], ['2.943', '0']]] }), ['ff', 'rr']);
  assert.throws(() => a.query(['0x1p3', 0, 0]), /wrench\[0\]: expected a finite number \(or a decimal string such as "0\.1"\), got "0x1p3"/);
  // the CLI's decimals (.3, 3., +3, 3e+0) are the module's too
  assert.deepEqual(a.query(['.3e1', '-10.', '-5']), ['ff', 'rr']);
  assert.deepEqual(a.query(['+3', '-1e+1', ' -5 ']), ['ff', 'rr']);
  assert.throws(() => a.query(['3e', '-10', '-5']), /wrench\[0\]: expected a finite number/);
  // blanks as the CLI strips them (space, tab, CR, LF), not Unicode's no-break space
  assert.throws(() => a.query(['3', '-10', '-5\u00a0']), /wrench\[2\]: expected a finite number/);
  assert.throws(() => a.query(['1e-400', 0, 0]), /wrench\[0\]: a number is too small for a double: it would be taken as 0/);
  assert.throws(() => a.query(['1e-999999999', 0, 0]), /wrench\[0\]: a number is too small for a double: it would be taken as 0/);
  assert.deepEqual(a.query(['0e-999999999', '-9.81', '-4.905']), a.query([0, -9.81, -4.905]));  // zero with any exponent
  assert.throws(() => ml.analyze(block + '\u0000x'), /^Error: \$: not a JSON document: a control byte, byte 0x00 at offset/);
  assert.throws(() => a.query(['1e999999999', 0, 0]), /wrench\[0\]: expected a finite number/);
  // A compliance centre on the line of force (-0.3, 1) through (0.925, 0.25) in decimal: a knife
  // edge as the CLI reads --centre; as numbers the centre is off that line and fails.
  const comply = JSON.parse(execFileSync(CLI, ['plan', 'comply', file, '--goal', 'rr', '--centre', '0.775', '0.75', '--json'], { encoding: 'utf8' }));
  assert.equal(comply.centre.verdict, 'boundary');
  // (a knife edge has no best_margins: its margin is 0, and its rounded direction may miss E_rr)
  assert.deepEqual(a.planComply('rr', ['0.775', '0.75'], [-2, -2, 2, 2]).centre, comply.centre);
  assert.equal(comply.centre.best_margins, undefined);
  assert.equal(a.planComply('rr', [0.775, 0.75], [-2, -2, 2, 2]).centre.verdict, 'fails');
  // The push through the centre of mass under typed gravity 9.8: ff up to 0.3 x 9.8 = 2.94 exactly.
  const line = JSON.parse(execFileSync(CLI, ['query', file, '--push', '0.5', '0.25', '1', '0', '--gravity', '0', '-9.8', '--json'], { encoding: 'utf8' }));
  const bands = a.pushLine(['0.5', '0.25'], ['1', '0'], { gravity: ['0', '-9.8'] });
  assert.deepEqual(bands, line);  // fixed_exact ['0', '-49/5', '-49/10'] too
  assert.equal(bands.bands[0].to, 2.94);
  a.delete();
  // stand: a block on the floor at mu = 0.3 stands exactly when |gx| <= 0.3 |gy|; the float 0.9 is
  // a little above 9/10, so under (0.9, -3) as numbers it slides.
  const floor = JSON.stringify({ bodies: [{ mass: 2, com: [1, 0.5], inertia: 1, polygon: [[0, 0], [2, 0], [2, 1], [0, 1]] }],
                                 obstacles: [{ polygon: [[-5, -1], [5, -1], [5, 0], [-5, 0]] }], mu: 0.3 });
  const floorFile = join(scratch, 'typed-floor.json');
  writeFileSync(floorFile, floor);
  const standCli = JSON.parse(execFileSync(CLI, ['stand', floorFile, '--gravity', '0.9', '-3', '--json'], { encoding: 'utf8' }));
  assert.equal(standCli.can_stand, true);
  assert.equal(ml.stand(floor, { gravity: ['0.9', '-3'] }).can_stand, true);
  assert.equal(ml.stand(floor, { gravity: [0.9, -3] }).can_stand, false);
  // planPush's mu as typed: a finger sliding on the top of a block whose floor has mu = 0.1 is held
  // exactly when the finger's mu is at most 1/10 (test_decimals_inputs.py derives it by hand):
  // typed '0.1' it is on the boundary of the floor's cones, "boundary"; the number 0.1 is the double,
  // a hair above 1/10, "no". The CLI's --mu 0.1 gives the same cases and mu_exact.
  const finger = '{"body":{"mass":1,"com":[1,0.5],"inertia":0.5,"polygon":[[0,0],[2,0],[2,1],[0,1]]},' +
                 '"contacts":[{"point":[0,0],"normal":[0,1],"mu":0.1},{"point":[2,0],"normal":[0,1],"mu":0.1}]}';
  const fingerFile = join(scratch, 'typed-finger.json');
  writeFileSync(fingerFile, finger);
  const onTop = (plan) => plan.cases.filter((c) => c.feature === 'edge 2' && 'lr'.includes(c.slip)).map((c) => c.verdict);
  const b = ml.analyze(finger);
  const pushCli = JSON.parse(execFileSync(CLI, ['plan', 'push', fingerFile, '--goal', 'ff', '--mu', '0.1', '--json'], { encoding: 'utf8' }));
  const pushTyped = b.planPush('ff', { mu: '0.1' });
  assert.deepEqual(onTop(pushTyped), ['boundary', 'boundary']);
  assertClose(pushTyped, pushCli);  // (angles from this libm's atan2: within its last bits)
  assert.equal(pushTyped.mu_exact, '1/10');
  assert.deepEqual(onTop(b.planPush('ff', { mu: 0.1 })), ['no', 'no']);
  assert.throws(() => b.planPush('ff', { mu: '0x1p-3' }), /^Error: mu: expected a finite number \(or a decimal string/);
  b.delete();
});
