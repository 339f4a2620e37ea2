// The viewer's answers (docs/web.md): the plans of the picked mode (tilt, push, compliance), grasp
// closure, and the bands of the applied force's magnitude, each as text in the side panel and
// marked on the picture; and the panel's friction sliders. Each panel keeps the module's answer
// (the CLI's --json view) in its element's data-answer, so that what is shown can be checked
// against the CLI. Needs draw.js.
'use strict';

// Each changes the page only when the value changed (a drag redraws often; unchanged text costs no layout).
function setAnswer(id, answer) {
  const text = JSON.stringify(answer);
  if ($(id).dataset.answer !== text) $(id).dataset.answer = text;
}

function say(id, words) {
  if ($(id).textContent !== words) $(id).textContent = words;
}

function unit(v) {
  const l = Math.hypot(v[0], v[1]);
  return [v[0] / l, v[1] / l];
}

// The load acting besides the applied force: gravity through the centre of mass when it is on.
function load() {
  if (!$('gravity-on').checked) return {};
  return { gravity: [$('gravity-x').value, $('gravity-y').value] };  // as typed: 0.1 is 1/10
}

function directionsText(plan) {
  if (!plan.intervals || !plan.intervals.length) return 'none';
  let out = arcsText(plan.intervals);
  if (plan.unique) out += `; the goal alone: ${arcsText(plan.unique)}; shared: ${arcsText(plan.shared)}`;
  if (typeof plan.best === 'number') out += plan.knife_edge ? '; a knife edge' : `; best ${degrees(plan.best)}`;
  return out;
}

function drawPlans(a) {
  const goal = app.selected, l = load(), key = JSON.stringify(l);
  const tilt = cached(`tilt ${goal}`, () => a.planTilt(goal));
  setAnswer('tilt', tilt);
  say('tilt', directionsText(tilt));
  const centre = app.centre || app.doc.body.com;
  const comply = cached(`comply centre ${goal} ${centre} ${key}`, () => a.planComply(goal, centre, app.view, l));
  setAnswer('comply', comply.centre);
  say('comply', `centre (${centre.map((x) => Number(x.toPrecision(4))).join(', ')}): ${comply.centre.verdict}, ` +
    `label ${comply.centre.label}; spring directions ${directionsText(comply.centre)}`);
  drawClosureText();
  drawBandsText(a);
  const pushKey = `push ${goal} ${$('finger-mu').value} ${key}`;
  const push = app.cache[pushKey];
  app.plans = { tilt, push: push || { cases: [] }, comply };
  if (push) {
    if (app.shownPush !== push) drawPushTable(push);
    app.shownPush = push;
  } else if (!app.dragging && !app.sliding) {
    schedulePush(pushKey, goal, l);  // during a drag it waits for the drag's end
  }
}

// The push table after the frame, unless the scene or goal changes again first.
function schedulePush(key, goal, l) {
  clearTimeout(app.pushTimer);
  app.pushTimer = setTimeout(() => {
    const a = app.analysis;
    if (!a || !app.cache || app.cache[key]) return;
    const body = app.doc.body;
    app.cache[key] = body.polygon && body.polygon.length >= 3
      ? a.planPush(goal, Object.assign({ mu: Number($('finger-mu').value) }, l)) : { cases: [] };
    recompute();
  }, 0);
}

function drawPushTable(push) {
  const body = $('push').querySelector('tbody');
  body.textContent = '';
  for (const c of push.cases) {
    const tr = document.createElement('tr');
    if (c.verdict === 'feasible' || c.verdict === 'boundary') tr.className = c.verdict;
    const goal = c.unique && c.shared ? 'both' : c.unique ? 'alone' : c.shared ? 'shared' : '';
    for (const t of [c.feature, c.slip, c.verdict, goal, c.directions ? `${degrees(c.directions[0])} .. ${degrees(c.directions[1])}` : '']) {
      const td = document.createElement('td');
      td.textContent = t;
      tr.appendChild(td);
    }
    body.appendChild(tr);
  }
  $('push').dataset.goal = push.goal || '';
  setAnswer('push', push);
}

// Grasp closure of the scene's contacts: each test's verdict, and its quality (it holds) or the
// wrench no contact can resist (it fails; for form closure also a twist that frees the body).
function closureAnswer() {
  return cached(`closure ${app.screenBox}`, () => app.ml.graspClosure(app.sceneKey, { view: app.screenBox }));
}

function drawClosureText() {
  const c = closureAnswer();
  const said = (t) => (t.holds ? `holds, quality ${Number(t.quality.toPrecision(4))}`
    : `fails: no contact resists the wrench (${t.unresisted_wrench.map((x) => Number(x.toPrecision(4))).join(', ')})`);
  say('closure-form', said(c.form));
  say('closure-force', said(c.force));
  say('closure-metric', `quality about (${c.reference.map((x) => Number(x.toPrecision(4))).join(', ')}), length ${Number(c.length.toPrecision(4))}`);
  const shown = Object.assign({}, c);
  delete shown.labels;
  setAnswer('closure', shown);
}

// The bands of the applied force's magnitude along its line, with gravity when it is on.
function bandsAnswer(a) {
  const f = app.force, l = load();
  if (f.moment) l.wrench = [0, 0, f.moment];
  if (f.vector[0] === 0 && f.vector[1] === 0) return null;
  return a.pushLine(f.point, unit(f.vector), l);
}

function drawBandsText(a) {
  const bands = bandsAnswer(a);
  app.bands = bands;
  const box = $('bands');
  if (box.dataset.answer === JSON.stringify(bands)) return;
  setAnswer('bands', bands);
  box.textContent = '';
  if (!bands) return;
  const mag = Math.hypot(app.force.vector[0], app.force.vector[1]);
  say('bands-head', `the force through (${app.force.point.map((x) => Number(x.toPrecision(4))).join(', ')}) along ` +
    `${degrees(Math.atan2(app.force.vector[1], app.force.vector[0]))}, magnitude \u03bb from 0 up (now ${Number(mag.toPrecision(4))})` +
    (bands.fixed.some((x) => x !== 0) ? `, with the fixed wrench (${bands.fixed.map((x) => Number(x.toPrecision(4))).join(', ')})` : ''));
  for (const b of bands.bands) {
    const li = document.createElement('li');
    const to = b.to === 'unbounded' ? '\u221e' : Number(b.to.toPrecision(6));
    li.textContent = `\u03bb ${b.from_closed ? '[' : '('}${Number(b.from.toPrecision(6))}, ${to}${b.to_closed ? ']' : ')'}: ` +
      `${b.modes.length ? b.modes.join(', ') : 'no mode'} (${b.verdict})`;
    box.appendChild(li);
  }
}

// The push table's marks: touch segments (dark where the goal is alone) and best pushes. Many on
// a body of many vertices, and the same while the applied force is dragged: built once per table
// and frame of view, then copied.
function pushMarks(push, s, size) {
  const frame = JSON.stringify([app.view, s.w, s.h]);
  if (app.pushMarks && app.pushMarks.push === push && app.pushMarks.frame === frame) return app.pushMarks.node.cloneNode(true);
  const g = el('g', { class: 'push-marks' });
  for (const c of push.cases) {
    if (c.verdict !== 'feasible' && c.verdict !== 'boundary') continue;
    for (const [p, q] of c.touch) {
      el('path', { d: pathOf([p, q], s), stroke: COLOURS.push, 'stroke-width': c.feasible ? 6 : 3,
                   'stroke-dasharray': c.feasible ? '' : '3 3', opacity: 0.5, fill: 'none', 'stroke-linecap': 'round',
                   class: 'push-touch' }, g);
    }
    for (const [p, q] of c.unique_touch || []) {
      el('path', { d: pathOf([p, q], s), stroke: '#145a2a', 'stroke-width': 3, fill: 'none', 'stroke-linecap': 'round',
                   class: 'push-unique-touch' }, g);
    }
    if (c.feasible && c.best) {
      const d = [Math.cos(c.best.direction), Math.sin(c.best.direction)], p = c.best.point;
      arrow(g, [p[0] - 0.15 * size * d[0], p[1] - 0.15 * size * d[1]], p, COLOURS.push, s, 1.5, 'push-best');
    }
  }
  app.pushMarks = { push, frame, node: g.cloneNode(true) };
  return g;
}

// The marks of the answers on the picture.
function drawPlanMarks(g, a, s, len) {
  if (!app.plans) return;
  const { push, tilt, comply } = app.plans;
  const size = app.view[2] - app.view[0];
  g.appendChild(pushMarks(push, s, size));
  drawDirections(g, tilt, app.doc.body.com, 0.2 * size, COLOURS.tilt, s, 'tilt-arc');
  if (comply.centre.intervals.length) drawDirections(g, comply.centre, comply.centre.point, 0.12 * size, COLOURS.spring, s, 'spring-arc');
  const c = comply.centre.point;
  el('path', { d: `M${s.x(c[0]) - 6},${s.y(c[1]) - 6} l12,12 m-12,0 l12,-12`, stroke: COLOURS.spring, 'stroke-width': 2.5,
               class: 'compliance-centre' }, g);
  drawBandMarks(g, s, len);
}

// The bands along the applied force's line: lambda at the arrow's scale (its tip is the force's
// magnitude), each band in its first mode's colour, named.
function drawBandMarks(g, s, len) {
  if (!app.bands) return;
  const f = app.force, d = unit(f.vector), k = 2 * len, far = 2 * (app.view[2] - app.view[0]) / k;
  const modes = app.analysis.modes;
  for (const b of app.bands.bands) {
    const to = b.to === 'unbounded' ? far : Math.min(b.to, far);
    if (b.from > far) continue;
    const p = [f.point[0] + d[0] * b.from * k, f.point[1] + d[1] * b.from * k];
    const q = [f.point[0] + d[0] * to * k, f.point[1] + d[1] * to * k];
    const colour = b.modes.length ? MODE_COLOURS[modes.indexOf(b.modes[0]) % MODE_COLOURS.length] : '#eee';
    const band = el('path', { d: pathOf([p, q], s), stroke: colour, 'stroke-width': 9, opacity: 0.8, fill: 'none', class: 'band' }, g);
    band.dataset.band = JSON.stringify(b);
    const m = [(p[0] + q[0]) / 2, (p[1] + q[1]) / 2];
    if (Math.hypot(s.x(q[0]) - s.x(p[0]), s.y(q[1]) - s.y(p[1])) > 30) {
      text(g, s.x(m[0]) + 8, s.y(m[1]), b.modes.join(' ') || 'none', { 'font-size': 10, stroke: '#fff', 'stroke-width': 3,
        'paint-order': 'stroke', class: 'band-label' });
    }
  }
}

// What the closure tests show on the picture: a failing test's unresisted wrench on its line of
// action (red, dashed) and, for form closure, the rotation centre of the twist that frees it.
function drawClosureMarks(g, which, s) {
  const t = closureAnswer()[which];
  if (t.holds) return;
  const w = t.unresisted_wrench, line = lineOfAction(w);
  if (line) {
    drawLine(g, line, s, { stroke: COLOURS.certificate, 'stroke-dasharray': '8 4', 'stroke-width': 1.5, class: 'certificate' }, app.view);
    const size = 0.15 * (app.view[2] - app.view[0]), p = line.point, d = line.direction;
    arrow(g, p, [p[0] + size * d[0], p[1] + size * d[1]], COLOURS.certificate, s, 2.5, 'certificate');
  } else {  // a pure moment
    text(g, s.w - 12, s.h - 26, `no contact resists the pure moment ${w[2] > 0 ? '\u21ba' : '\u21bb'} ${Number(w[2].toPrecision(4))}`,
         { 'text-anchor': 'end', fill: COLOURS.certificate, 'font-size': 13, class: 'certificate' });
  }
  if (which === 'form' && w[2] !== 0) {  // the twist (vx, vy, omega) turns about (-vy, vx) / omega
    const c = [-w[1] / w[2], w[0] / w[2]];
    el('circle', { cx: s.x(c[0]), cy: s.y(c[1]), r: 6, fill: 'none', stroke: COLOURS.certificate, 'stroke-width': 2, class: 'certificate-centre' }, g);
    text(g, s.x(c[0]) + 9, s.y(c[1]) - 8, w[2] > 0 ? '\u21ba frees it' : '\u21bb frees it', { fill: COLOURS.certificate, 'font-size': 11 });
  }
}

// The legend's entries for what is shown.
function legendEntries(show) {
  const regions = show === 'centres' || show === 'all'
    ? [[swatch.fill(COLOURS.plus, COLOURS.plusEdge), 'turns + (counter-clockwise) about'],
       [swatch.fill(COLOURS.minus, COLOURS.minusEdge), 'turns \u2212 (clockwise) about']]
    : [[swatch.fill(COLOURS.plus, COLOURS.plusEdge), '+: every force turns ccw about'],
       [swatch.fill(COLOURS.minus, COLOURS.minusEdge), '\u2212: every force turns cw about'],
       [swatch.fill(COLOURS.both, COLOURS.both), '\u00b1: moment zero about'],
       [swatch.line(COLOURS.ink, 1, '5 4'), 'line of action of an extreme force']];
  if (show === 'closure-form' || show === 'closure-force') regions.push([swatch.line(COLOURS.certificate, 2, '8 4'), 'wrench no contact resists']);
  return regions.concat([
    [swatch.line(COLOURS.tilt, 5), 'tilt: goal alone (dashed: shared)'],
    [swatch.line(COLOURS.spring, 5), 'spring: goal alone (dashed: shared)'],
    [swatch.line(COLOURS.push, 5), 'push: touch (dark: goal alone)'],
    [swatch.line(MODE_COLOURS[0], 8), 'force magnitude band (mode)'],
    [swatch.square(COLOURS.body), 'handle: body vertex'],
    [swatch.dot(COLOURS.body, 5), 'handle: centre of mass'],
    [swatch.dot(COLOURS.friction, 5), 'handle: contact (square: normal)'],
    [swatch.ring(COLOURS.ink), 'handle: force point (dot: tip)'],
  ]);
}

// The friction sliders, one a contact (static and kinetic mu together), in the side panel.
function buildMuSliders() {
  const box = $('mus');
  box.textContent = '';
  (app.doc.contacts || []).forEach((c, j) => {
    const row = document.createElement('div');
    row.className = 'row';
    const label = document.createElement('label');
    label.textContent = `contact ${j}${c.name ? ` (${c.name})` : ''} \u03bc (static = kinetic)`;
    const input = document.createElement('input');
    Object.assign(input, { type: 'range', min: 0, max: Math.max(1.5, c.mu || 0), step: 0.05, value: c.mu || 0 });
    input.id = `mu-${j}`;
    label.htmlFor = input.id;
    const value = document.createElement('span');
    value.textContent = String(c.mu || 0);
    input.title = 'static and kinetic friction (the slider sets both)';
    input.addEventListener('input', () => {
      c.mu = Number(input.value);
      c.mu_kinetic = c.mu;
      value.textContent = input.value;
      app.sliding = true;  // the push table waits for the release
      recompute();
    });
    input.addEventListener('change', () => { app.sliding = false; recompute(); });
    row.append(label, input, value);
    box.appendChild(row);
  });
}
