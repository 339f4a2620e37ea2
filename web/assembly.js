// The viewer's assemblies (docs/web.md, docs/assemblies.md): a scene with "bodies" is drawn with
// its bodies, contacts and obstacles; after every change `stand` runs again in the library
// compiled to WebAssembly, and the picture shows its answer (the equilibrium's contact forces, or
// the collapse mechanism: each turning body's rotation centre and each moving body's velocity at
// its centre of mass), the panel can stand, the outcome, the modes and the tilt range. Handles:
// each centre of mass (anywhere), each body with a polygon (sideways: a stack stays stacked; its
// com and listed contacts go with it, and the bodies joined to it by listed contacts) and each
// listed contact point. Loaded after draw.js and
// before app.js (web/build_page.py); app.js hands a scene with "bodies" to these functions.
'use strict';

function isAssembly(doc) {
  return doc && typeof doc === 'object' && Array.isArray(doc.bodies);
}

// Gravity as typed in the panel (decimal strings: 0.1 is 1/10, as the CLI reads --gravity).
function assemblyGravity() {
  return [$('stand-gx').value, $('stand-gy').value];
}

// stand on the current document: the answer, or an error shown and the last good scene restored.
// The scene's text: the file as opened while no edit has changed it (its decimals as typed; a
// JS number would round them), else the edited document.
function assemblyText() {
  const edited = JSON.stringify(app.doc);
  return edited === app.openedKey ? app.openedText : edited;
}

function assemblyAnswer() {
  const key = JSON.stringify(app.doc) + JSON.stringify(assemblyGravity());
  if (key === app.standKey && app.stand) return app.stand;
  let r;
  try {
    r = app.ml.stand(assemblyText(), { gravity: assemblyGravity(), tilt: true });
  } catch (e) {
    showError(e.message);
    if (app.goodDoc) app.doc = JSON.parse(JSON.stringify(app.goodDoc));
    return app.stand;
  }
  showError('');
  app.stand = r;
  app.standKey = key;
  app.goodDoc = JSON.parse(JSON.stringify(app.doc));
  return r;
}

function loadAssembly(doc, text) {
  // A file the library refuses leaves the last good scene (shown and saved) as it was.
  try {
    app.ml.stand(text, { gravity: assemblyGravity() });
  } catch (e) {
    showError(e.message);
    return false;
  }
  app.doc = doc;
  app.openedText = text;
  app.openedKey = JSON.stringify(doc);
  app.goodDoc = null;
  app.stand = null;
  app.standKey = null;
  const r = assemblyAnswer();
  if (!r) return false;
  document.body.classList.add('assembly');
  const pts = [];
  for (const b of r.assembly.bodies) pts.push(b.com, ...b.polygon);
  for (const c of r.assembly.contacts) pts.push(c.point);
  app.view = fitView({ contacts: pts.map((p) => ({ point: p })) });
  return recomputeAssembly();
}

function recomputeAssembly() {
  const t0 = performance.now();
  const r = assemblyAnswer();
  if (!r) return false;
  const s = screen();
  drawAssemblyPanel(r);
  drawAssemblyPicture(r, s);
  const ms = performance.now() - t0;
  app.frameTimes.push(ms);
  $('timing').textContent = `last update: ${ms.toFixed(2)} ms (stand and drawing)`;
  $('warnings').textContent = r.warnings.length ? `warnings: ${r.warnings.join('; ')}` : '';
  return true;
}

function tiltText(tilt) {
  const xy = (d) => `(${d.map((x) => (typeof x === 'number' ? Number(x.toPrecision(6)) : x)).join(', ')})`;
  if (!tilt.directions.length) return tilt.kind;
  return `${tilt.kind} ${tilt.directions.map(xy).join(' to ')}`;
}

function drawAssemblyPanel(r) {
  $('stand-can').textContent = r.can_stand ? 'yes' : 'no';
  $('stand-outcome').textContent = r.outcome === null ? `— (${r.modes_reason})` : r.outcome;
  $('stand-verdict').textContent = r.verdict === null ? '—' : r.verdict;
  $('stand-modes').textContent = r.modes === null ? '—' : r.modes.join(' ');
  $('stand-motions').textContent = r.motions === null ? '—' : (r.motions.length ? r.motions.join(' ') : 'none');
  $('stand-tilt').textContent = tiltText(r.tilt);
}

// Moves body k (0-based) by d, with every body joined to it by listed contacts between bodies
// (a stack, an arch: those contacts stay where both their bodies are): their polygons, centres of
// mass and every listed contact of theirs, those with the world included. The library then judges
// the scene as drawn (a contact moved off the world's outline is refused).
function moveBody(k, d) {
  const shift = (p) => [p[0] + d[0], p[1] + d[1]];
  const contacts = app.doc.contacts || [];
  const moving = new Set([k + 1]);
  for (let grown = true; grown;) {
    grown = false;
    for (const c of contacts) {
      const [a, b] = c.bodies;
      if (a !== 0 && b !== 0 && moving.has(a) !== moving.has(b)) {
        moving.add(moving.has(a) ? b : a);
        grown = true;
      }
    }
  }
  for (const i of moving) {
    const body = app.doc.bodies[i - 1];
    body.com = shift(body.com);
    if (body.polygon) body.polygon = body.polygon.map(shift);
  }
  for (const c of contacts) {
    if (moving.has(c.bodies[0]) || moving.has(c.bodies[1])) c.point = shift(c.point);
  }
}

function drawAssemblyPicture(r, s) {
  const focused = document.activeElement && document.activeElement.dataset ? document.activeElement.dataset.handle : null;
  const svg = $('view');
  svg.textContent = '';
  svg.setAttribute('viewBox', `0 0 ${s.w} ${s.h}`);
  drawAxes(svg, s);
  const g = el('g', { id: 'scene' }, svg);
  const asm = r.assembly;
  for (const o of asm.obstacles) el('path', { d: pathOf(o, s, true), fill: COLOURS.obstacle, 'fill-opacity': 0.45, class: 'obstacle' }, g);
  const len = 0.08 * (app.view[2] - app.view[0]);
  asm.bodies.forEach((b, k) => {
    if (b.polygon.length) {
      el('path', { d: pathOf(b.polygon, s, true), fill: COLOURS.body, 'fill-opacity': 0.15, stroke: COLOURS.body,
                   'stroke-width': 1.5, class: 'body' }, g);
    }
    el('circle', { cx: s.x(b.com[0]), cy: s.y(b.com[1]), r: 4, fill: COLOURS.body, class: 'com' }, g);
    text(g, s.x(b.com[0]) + 6, s.y(b.com[1]) - 6, `${k + 1}${b.name ? ` ${b.name}` : ''}`, { class: 'body-number' });
  });
  asm.contacts.forEach((c) => {
    const u = unitNormal(c.normal), t = [u[1], -u[0]], mu = c.mu;
    el('path', { d: pathOf([c.point, [c.point[0] + len * (u[0] + mu * t[0]), c.point[1] + len * (u[1] + mu * t[1])],
                            [c.point[0] + len * (u[0] - mu * t[0]), c.point[1] + len * (u[1] - mu * t[1])]], s, true),
                 fill: COLOURS.friction, 'fill-opacity': 0.25, class: 'friction-cone' }, g);
    arrow(g, c.point, [c.point[0] + len * u[0], c.point[1] + len * u[1]], COLOURS.friction, s, 1.5, 'normal');
  });
  // The answer: the equilibrium's forces on body a (lengths in proportion), or the mechanism.
  const answer = el('g', { id: 'answer' }, g);
  if (r.can_stand) {
    const largest = Math.max(...r.forces.map((f) => Math.hypot(f[0], f[1])), 0);
    r.forces.forEach((f, j) => {
      const size = Math.hypot(f[0], f[1]);
      if (!size) return;
      const p = asm.contacts[j].point, k = 2.5 * len / largest;
      arrow(answer, p, [p[0] + k * f[0], p[1] + k * f[1]], COLOURS.certificate, s, 2.5, 'stand-force');
    });
  } else {
    const speeds = r.mechanism.map((m) => {
      const b = asm.bodies[m.body - 1], [vx, vy, w] = m.twist;
      return [vx - w * b.com[1], vy + w * b.com[0]];
    });
    const largest = Math.max(...speeds.map((v) => Math.hypot(v[0], v[1])), 0);
    r.mechanism.forEach((m, i) => {
      const com = asm.bodies[m.body - 1].com, v = speeds[i];
      if (largest > 0 && Math.hypot(v[0], v[1]) > 0) {
        const k = 2.5 * len / largest;
        arrow(answer, com, [com[0] + k * v[0], com[1] + k * v[1]], COLOURS.certificate, s, 2.5, 'mechanism-velocity');
      }
      if (m.rotation_centre) {
        const [x, y] = [s.x(m.rotation_centre[0]), s.y(m.rotation_centre[1])];
        el('path', { d: `M${x - 6},${y - 6} L${x + 6},${y + 6} M${x - 6},${y + 6} L${x + 6},${y - 6}`, stroke: COLOURS.certificate,
                     'stroke-width': 2.5, class: 'rotation-centre' }, answer);
        text(answer, x + 8, y + 4, `${m.body} ${m.twist[2] > 0 ? '\u21ba' : '\u21bb'}`, { fill: COLOURS.certificate });
      }
    });
  }
  // gravity at the left of the picture
  const gn = assemblyGravity().map(Number);
  if (gn[0] || gn[1]) {
    const gv = unit(gn);
    const box = s.box(), at = [box[0] + 0.08 * (box[2] - box[0]), box[3] - 0.12 * (box[3] - box[1])];
    arrow(g, at, [at[0] + len * gv[0], at[1] + len * gv[1]], COLOURS.guide, s, 2, 'gravity');
  }
  // handles: centres of mass, bodies (sideways), listed contacts
  app.placed = [];
  const handles = el('g', { id: 'handles' }, svg);
  // (each move reads the document as it is then: a refused edit restores the last good one)
  app.doc.bodies.forEach((b, k) => {
    handle(handles, b.com, s, COLOURS.body, `com ${k + 1}`, (p) => { app.doc.bodies[k].com = p; });
    if (b.polygon && b.polygon.length) {
      handle(handles, centroid(b.polygon), s, COLOURS.body, `body ${k + 1}`,
             (p) => moveBody(k, [p[0] - centroid(app.doc.bodies[k].polygon)[0], 0]), 'square');
    }
  });
  (app.doc.contacts || []).forEach((c, j) => {
    handle(handles, c.point, s, COLOURS.friction, `contact ${j + 1}`, (p) => { app.doc.contacts[j].point = p; }, 'ring');
  });
  if (focused) {  // a keyboard user keeps the handle they were on across redraws
    const again = handles.querySelector(`[data-handle="${CSS.escape(focused)}"]`);
    if (again) again.focus();
  }
}
