// The viewer (docs/web.md): a scene drawn to scale with draggable body vertices, contacts, normals
// and an applied force; after every change the scene is analysed again by the library compiled
// to WebAssembly, and the modes, the selected mode's labelled regions, the verdict and the answers
// (panels.js) are redrawn. Everything shown is computed by the library; this file edits, and with
// draw.js draws.
'use strict';

const app = {
  ml: null,
  doc: null,          // the scene as a JSON object (the CLI's format)
  analysis: null,
  selected: null,     // the selected mode's letters
  force: { point: [0.5, 0.25], vector: [0, -1], moment: 0 },
  centre: null,       // the compliance centre
  view: [-1, -1, 2, 2],
  frameTimes: [],     // milliseconds per recompute + redraw
  errors: [],
};
window.momentlabApp = app;

const $ = (id) => document.getElementById(id);

function showError(message) {
  const box = $('error');
  if (message) {
    box.textContent = message;
    box.classList.add('shown');
    app.errors.push(message);
  } else {
    box.textContent = '';
    box.classList.remove('shown');
  }
}

// --- geometry of the view ------------------------------------------------------------------

function fitView(doc) {
  const pts = [];
  if (doc.body) {
    if (doc.body.com) pts.push(doc.body.com);
    for (const p of doc.body.polygon || []) pts.push(p);
  }
  for (const c of doc.contacts || []) pts.push(c.point);
  if (!pts.length) pts.push([0, 0]);
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (const [x, y] of pts) { x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y); }
  const size = Math.max(x1 - x0, y1 - y0, 1e-3);
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, half = size * 0.95;
  return [cx - half, cy - half, cx + half, cy + half];
}

function screen() {
  const svg = $('view');
  const w = svg.clientWidth || 800, h = svg.clientHeight || 600;
  const [x0, y0, x1, y1] = app.view;
  const k = Math.min(w / (x1 - x0), h / (y1 - y0));
  const ox = (w - k * (x1 - x0)) / 2, oy = (h - k * (y1 - y0)) / 2;
  return {
    w, h, k,
    x: (x) => ox + k * (x - x0),
    y: (y) => oy + k * (y1 - y),
    world: (sx, sy) => [x0 + (sx - ox) / k, y1 - (sy - oy) / k],
    box: () => [x0 - ox / k, y0 - (h - oy - k * (y1 - y0)) / k, x1 + (w - ox - k * (x1 - x0)) / k, y1 + oy / k],
  };
}

// --- the scene -----------------------------------------------------------------------------

function unitNormal(n) {
  const l = Math.hypot(n[0], n[1]);
  return [n[0] / l, n[1] / l];
}

// The nearest point of the body polygon's boundary (contacts stay on it when the body moves).
function onBoundary(p, polygon) {
  let best = p, dist = Infinity;
  for (let i = 0; i < polygon.length; ++i) {
    const a = polygon[i], b = polygon[(i + 1) % polygon.length];
    const d = [b[0] - a[0], b[1] - a[1]];
    const len2 = d[0] * d[0] + d[1] * d[1];
    let t = len2 ? ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2 : 0;
    t = Math.max(0, Math.min(1, t));
    const q = t === 0 ? a.slice() : t === 1 ? b.slice() : [a[0] + t * d[0], a[1] + t * d[1]];
    const e = Math.hypot(q[0] - p[0], q[1] - p[1]);
    if (e < dist) { dist = e; best = q; }
  }
  return best;
}

// Contacts put on the outline by the page are rounded there: the file's contact_distance (default
// 1e-9) is raised to the rounding of coordinates of this size, so large scenes stay editable.
function projectedTolerance() {
  let size = 1;
  for (const p of app.doc.body.polygon || []) size = Math.max(size, Math.abs(p[0]), Math.abs(p[1]));
  app.doc.contact_distance = Math.max(app.doc.contact_distance || 1e-9, 1e-12 * size);
}

function wrench() {
  const [px, py] = app.force.point, [fx, fy] = app.force.vector;
  return [fx, fy, px * fy - py * fx + app.force.moment];
}

// --- recompute and redraw ------------------------------------------------------------------

// After every change: the scene is analysed again only when it changed (dragging the applied
// force asks the same analysis a new question); the shown sets and the plans are cached by what
// they depend on. The push table, the costliest plan (about 15 ms for a 16-gon), is computed
// after the frame when the scene or the goal changed, and during a drag only when it ends, so
// that every drag event stays within one frame.
function recompute() {
  if (document.body.classList.contains('assembly')) return recomputeAssembly();
  const t0 = performance.now();
  const key = JSON.stringify(app.doc);
  if (key !== app.sceneKey || !app.analysis) {
    let analysis;
    try {
      analysis = app.ml.analyze(key);
    } catch (e) {
      // An impossible edit (crossing edges, a contact off the outline): said, and undone, so
      // that the picture, the answers and a saved file stay those of the last good scene.
      showError(e.message);
      if (app.goodDoc) app.doc = JSON.parse(JSON.stringify(app.goodDoc));
      if (app.analysis) redraw();
      return false;
    }
    if (app.analysis) app.analysis.delete();
    app.analysis = analysis;
    app.sceneKey = key;
    app.goodDoc = JSON.parse(key);
    app.cache = {};
    if (!analysis.modes.includes(app.selected)) app.selected = null;
  }
  showError('');
  $('warnings').textContent = (app.warnings || []).length ? `warnings: ${app.warnings.join('; ')}` : '';
  try {
    redraw();
  } catch (e) {
    showError(e.message);
  }
  const ms = performance.now() - t0;
  app.frameTimes.push(ms);
  $('timing').textContent = `last update: ${ms.toFixed(2)} ms (analysis when the scene changed, query, sets, drawing)`;
  return true;
}

// A value computed once per scene and key.
function cached(name, compute) {
  if (!(name in app.cache)) app.cache[name] = compute();
  return app.cache[name];
}

function redraw() {
  const a = app.analysis;
  const s = screen();  // measured before the panel's text changes, so that no layout is forced mid-frame
  app.screenBox = s.box();
  const produced = a.query(wrench(), load());  // with gravity when it is on
  if (!app.selected) app.selected = produced.length ? produced[0] : a.modes[0];
  drawModes(a, produced);
  drawForceText(produced, a.verdict(wrench(), load()));
  drawPlans(a);
  drawPicture(a, produced, s);
}

// The mode buttons: built when the modes change, otherwise only their marks are updated.
function drawModes(a, produced) {
  const box = $('modes');
  const key = a.modes.join(' ');
  if (box.dataset.modes !== key) {
    box.textContent = '';
    box.dataset.modes = key;
    $('mode-count').textContent = `(${a.modes.length})`;
    a.modes.forEach((m, k) => {
      const b = document.createElement('button');
      b.textContent = m;
      b.dataset.mode = m;
      b.style.borderLeft = `6px solid ${MODE_COLOURS[k % MODE_COLOURS.length]}`;
      b.addEventListener('click', () => { app.selected = m; recompute(); });
      box.appendChild(b);
    });
  }
  for (const b of box.children) {
    const m = b.dataset.mode;
    b.classList.toggle('selected', m === app.selected);
    b.classList.toggle('produced', produced.includes(m));
    b.title = produced.includes(m) ? 'the applied force produces this mode' : 'pick to see its sets';
  }
}

function drawForceText(produced, verdict) {
  const w = wrench();
  $('wrench').textContent = `(${w.map((x) => (x === 0 ? '0' : Number(x.toPrecision(4)).toString())).join(', ')})`;
  $('produced').textContent = produced.length ? produced.join(', ') : 'no mode';
  $('produced').dataset.modes = produced.join(' ');
  $('verdict').textContent = verdict;
}

// A draggable point p drawn at its place, or beside it (joined by a leader) when an earlier handle
// is there (draw.js, placeHandle); a drag keeps that offset.
function handle(g, p, s, colour, name, onMove, shape) {
  const [ox, oy] = placeHandle(app.placed, s.x(p[0]), s.y(p[1]));
  const [hx, hy] = [s.x(p[0]) + ox, s.y(p[1]) + oy];
  if (ox || oy) el('line', { x1: s.x(p[0]), y1: s.y(p[1]), x2: hx, y2: hy, stroke: colour, 'stroke-width': 1, 'pointer-events': 'none', class: 'leader' }, g);
  const h = el(shape === 'square' ? 'rect' : 'circle', shape === 'square'
    ? { x: hx - 9, y: hy - 9, width: 18, height: 18 }
    : { cx: hx, cy: hy, r: shape === 'ring' ? 9 : 6 }, g);
  if (shape === 'ring') {
    h.setAttribute('fill', 'none');
    h.setAttribute('stroke', colour);
    h.setAttribute('stroke-width', 5);
    h.setAttribute('pointer-events', 'stroke');
  } else {
    h.setAttribute('fill', colour);
    h.setAttribute('fill-opacity', 0.8);
    h.setAttribute('stroke', '#fff');
  }
  h.setAttribute('class', 'handle');
  h.setAttribute('tabindex', '0');
  h.dataset.handle = name;
  h.dataset.offset = JSON.stringify([ox, oy]);
  h.setAttribute('aria-label', name);
  h.addEventListener('pointerdown', (ev) => {
    ev.preventDefault();
    h.setPointerCapture(ev.pointerId);
    app.dragging = { name, onMove, offset: [ox, oy] };
  });
  h.addEventListener('keydown', (ev) => {
    const step = (app.view[2] - app.view[0]) * (ev.shiftKey ? 0.002 : 0.02);  // in the scene's scale
    const d = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, step], ArrowDown: [0, -step] }[ev.key];
    if (!d) return;
    ev.preventDefault();
    onMove([p[0] + d[0], p[1] + d[1]]);
    recompute();
  });
  return h;
}

// The regions the "show" menu asks for: a mode's E, F or T, rotation centres, E's compliance
// labels, or the labels of grasp closure's contact wrenches.
function drawRegions(regions, a, s, show, box) {
  if (show === 'all') {
    a.modes.forEach((m, k) => {
      const sets = cached(`mode ${m} ${box}`, () => a.mode(m, box));
      const colour = MODE_COLOURS[k % MODE_COLOURS.length];
      drawRegion(regions, sets.centres.plus, colour, COLOURS.ink, s, `centres mode-${m}`, `${m} \u21ba`);
      drawRegion(regions, sets.centres.minus, colour, COLOURS.ink, s, `centres mode-${m}`, `${m} \u21bb`);
    });
  } else if (show === 'comply') {
    const centre = app.centre || app.doc.body.com;
    const plan = cached(`comply ${app.selected} ${centre} ${box} ${JSON.stringify(load())}`,
                        () => a.planComply(app.selected, centre, box, load()));
    drawSet(regions, plan.labels, s, app.view);
  } else if (show === 'closure-form' || show === 'closure-force') {
    const which = show === 'closure-form' ? 'form' : 'force';
    drawSet(regions, closureAnswer().labels[which], s, app.view);
    drawClosureMarks(regions, which, s);
  } else if (app.selected) {
    const sets = cached(`mode ${app.selected} ${box}`, () => a.mode(app.selected, box));
    if (show === 'centres') {
      drawRegion(regions, sets.centres.plus, COLOURS.plus, COLOURS.plusEdge, s, 'plus', '\u21ba');
      drawRegion(regions, sets.centres.minus, COLOURS.minus, COLOURS.minusEdge, s, 'minus', '\u21bb');
    } else {
      drawSet(regions, sets[show], s, app.view);
    }
  }
}

function drawPicture(a, produced, s) {
  const svg = $('view');
  const focused = document.activeElement && document.activeElement.dataset ? document.activeElement.dataset.handle : null;
  svg.textContent = '';
  svg.setAttribute('viewBox', `0 0 ${s.w} ${s.h}`);
  const show = $('show').value;
  drawRegions(el('g', { id: 'regions' }, svg), a, s, show, s.box());
  drawAxes(svg, s);
  const scene = el('g', { id: 'scene' }, svg);
  for (const o of app.doc.obstacles || []) {
    el('path', { d: pathOf(o.polygon, s, true), fill: COLOURS.obstacle, 'fill-opacity': 0.45, class: 'obstacle' }, scene);
  }
  const body = app.doc.body;
  if (body.polygon) {
    el('path', { d: pathOf(body.polygon, s, true), fill: COLOURS.body, 'fill-opacity': 0.15, stroke: COLOURS.body,
                 'stroke-width': 1.5, class: 'body' }, scene);
  }
  el('circle', { cx: s.x(body.com[0]), cy: s.y(body.com[1]), r: 4, fill: COLOURS.body, class: 'com' }, scene);
  const len = 0.12 * (app.view[2] - app.view[0]);
  (app.doc.contacts || []).forEach((c) => {
    const u = unitNormal(c.normal), t = [u[1], -u[0]], mu = c.mu || 0;
    el('path', { d: pathOf([c.point, [c.point[0] + len * (u[0] + mu * t[0]), c.point[1] + len * (u[1] + mu * t[1])],
                            [c.point[0] + len * (u[0] - mu * t[0]), c.point[1] + len * (u[1] - mu * t[1])]], s, true),
                 fill: COLOURS.friction, 'fill-opacity': 0.25, class: 'friction-cone' }, scene);
    arrow(scene, c.point, [c.point[0] + len * u[0], c.point[1] + len * u[1]], COLOURS.friction, s, 1.5, 'normal');
  });
  drawPlanMarks(scene, a, s, len);
  // the applied force, and gravity (when on) at the centre of mass
  const f = app.force, tip = [f.point[0] + f.vector[0] * len * 2, f.point[1] + f.vector[1] * len * 2];
  arrow(scene, f.point, tip, produced.length === 1 ? COLOURS.ink : '#b00', s, 2.5, 'applied-force');
  const g = load().gravity ? load().gravity.map(Number) : null;  // (typed text, drawn as numbers)
  if (g && (g[0] || g[1])) {
    const u = unit(g);
    arrow(scene, body.com, [body.com[0] + len * u[0], body.com[1] + len * u[1]], COLOURS.guide, s, 2, 'gravity');
  }
  drawLegend(svg, legendEntries(show));
  // handles, the centre of mass first: it stays on its dot, and a later handle there moves aside
  const handles = el('g', { id: 'handles' }, svg);
  app.placed = [];
  // Every move edits the scene as it is now (by index), not the objects of this drawing: an edit
  // that was undone replaced them.
  const now = () => app.doc;
  handle(handles, body.com, s, COLOURS.body, 'centre of mass', (q) => { now().body.com = q; });
  handle(handles, f.point, s, COLOURS.ink, 'force point', (q) => { f.point = q; }, 'ring');
  handle(handles, tip, s, COLOURS.ink, 'force tip', (q) => {
    f.vector = [(q[0] - f.point[0]) / (len * 2), (q[1] - f.point[1]) / (len * 2)];
  });
  (body.polygon || []).forEach((p, i) => handle(handles, p, s, COLOURS.body, `vertex ${i}`, (q) => {
    const b = now().body;
    b.polygon[i] = q;
    for (const c of now().contacts || []) c.point = onBoundary(c.point, b.polygon);
    projectedTolerance();
  }, 'square'));
  (app.doc.contacts || []).forEach((c, j) => {
    handle(handles, c.point, s, COLOURS.friction, `contact ${j}`, (q) => {
      const poly = now().body.polygon;
      now().contacts[j].point = poly && poly.length >= 3 ? onBoundary(q, poly) : q;
      projectedTolerance();
    });
    const u = unitNormal(c.normal);
    handle(handles, [c.point[0] + len * u[0], c.point[1] + len * u[1]], s, COLOURS.friction, `normal ${j}`, (q) => {
      const contact = now().contacts[j];
      const d = [q[0] - contact.point[0], q[1] - contact.point[1]];
      if (Math.hypot(d[0], d[1]) > 1e-9 * (app.view[2] - app.view[0])) contact.normal = d;
    }, 'square');
  });
  (app.doc.obstacles || []).forEach((o, k) => o.polygon.forEach((p, i) =>
    handle(handles, p, s, COLOURS.obstacle, `obstacle ${k} vertex ${i}`, (q) => { now().obstacles[k].polygon[i] = q; },
           'square')));
  if (focused) {  // a keyboard user keeps the handle they were on across redraws
    const again = handles.querySelector(`[data-handle="${CSS.escape(focused)}"]`);
    if (again) again.focus();
  }
}

// --- files (the friction sliders: panels.js) -----------------------------------------------

function loadScene(text, name) {
  let parsed = null;
  try {
    parsed = JSON.parse(text);
  } catch (e) {
    // the library words the error (below)
  }
  if (isAssembly(parsed)) {
    app.dragging = null;
    if (!loadAssembly(parsed, text)) {
      showError(`${name || 'scene'}: ${app.errors[app.errors.length - 1]}`);
      return false;
    }
    return true;
  }
  let analysis;
  try {
    analysis = app.ml.analyze(text);  // the library's own checks, with the CLI's messages
  } catch (e) {
    showError(`${name || 'scene'}: ${e.message}`);
    return false;
  }
  document.body.classList.remove('assembly');
  // Keep the scene as the library read it (contacts written out, found ones included).
  app.doc = JSON.parse(analysis.sceneJson());
  app.goodDoc = JSON.parse(JSON.stringify(app.doc));
  app.warnings = analysis.warnings;
  analysis.delete();
  app.dragging = null;  // a drag of the previous scene ends here
  app.selected = null;
  app.centre = null;
  app.view = fitView(app.doc);
  const com = app.doc.body.com;
  app.force = { point: com.slice(), vector: [0, -1], moment: 0 };
  const size = app.view[2] - app.view[0];
  Object.assign($('moment'), { min: -size, max: size, step: size / 200 });  // torques of the scene's size
  $('moment').value = 0;
  $('moment-value').textContent = '0';
  buildMuSliders();
  return recompute();
}

// --- start -----------------------------------------------------------------------------------

function start(ml) {
  app.ml = ml;
  const select = $('examples');
  const fromFile = document.createElement('option');
  fromFile.value = '';
  fromFile.textContent = '(an opened file)';
  fromFile.disabled = true;
  select.appendChild(fromFile);
  for (const name of Object.keys(MOMENTLAB_EXAMPLES)) {
    const o = document.createElement('option');
    o.value = o.textContent = name;
    select.appendChild(o);
  }
  select.value = 'figure-3-block-along-wall';
  select.addEventListener('change', () => {
    if (select.value) loadScene(JSON.stringify(MOMENTLAB_EXAMPLES[select.value]), select.value);
  });
  $('open').addEventListener('change', async (ev) => {
    const file = ev.target.files[0];
    if (file && loadScene(await file.text(), file.name)) $('examples').value = '';
  });
  $('save').addEventListener('click', () => download('scene.json', 'application/json',
    document.body.classList.contains('assembly') ? assemblyText() : JSON.stringify(app.doc, null, 1)));
  $('export-svg').addEventListener('click', () => download('momentlab.svg', 'image/svg+xml', svgText()));
  $('export-png').addEventListener('click', exportPng);
  $('show').addEventListener('change', recompute);
  for (const id of ['gravity-on', 'gravity-x', 'gravity-y', 'stand-gx', 'stand-gy']) $(id).addEventListener('input', recompute);
  $('moment').addEventListener('input', () => {
    app.force.moment = Number($('moment').value);
    $('moment-value').textContent = $('moment').value;
    recompute();
  });
  $('finger-mu').addEventListener('input', () => { $('finger-mu-value').textContent = $('finger-mu').value; recompute(); });
  const svg = $('view');
  window.addEventListener('pointermove', (ev) => {
    if (!app.dragging) return;
    const r = svg.getBoundingClientRect();
    const [ox, oy] = app.dragging.offset || [0, 0];  // a handle drawn beside its point
    app.dragging.onMove(screen().world(ev.clientX - r.left - ox, ev.clientY - r.top - oy));
    recompute();
  });
  const stop = () => {
    if (!app.dragging) return;
    app.dragging = null;
    recompute();  // the push table of the scene where the drag ended
  };
  window.addEventListener('pointerup', stop);  // a release anywhere ends the drag
  window.addEventListener('pointercancel', stop);
  $('place-centre').addEventListener('click', () => { app.placing = true; $('place-centre').textContent = 'tap the picture'; });
  svg.addEventListener('click', (ev) => {
    if (!ev.shiftKey && !app.placing) return;
    app.placing = false;
    $('place-centre').textContent = 'place it';
    const r = svg.getBoundingClientRect();
    app.centre = screen().world(ev.clientX - r.left, ev.clientY - r.top);
    recompute();
  });
  window.addEventListener('resize', () => app.doc && recompute());
  // Zoom (wheel, or + and - keys) about the pointer or the centre: obstacles beyond the first
  // view come into reach.
  const zoom = (factor, at) => {
    const [x0, y0, x1, y1] = app.view;
    const [cx, cy] = at || [(x0 + x1) / 2, (y0 + y1) / 2];
    app.view = [cx + (x0 - cx) * factor, cy + (y0 - cy) * factor, cx + (x1 - cx) * factor, cy + (y1 - cy) * factor];
    app.cache = {};
    recompute();
  };
  svg.addEventListener('wheel', (ev) => {
    ev.preventDefault();
    const r = svg.getBoundingClientRect();
    zoom(ev.deltaY > 0 ? 1.25 : 0.8, screen().world(ev.clientX - r.left, ev.clientY - r.top));
  }, { passive: false });
  window.addEventListener('keydown', (ev) => {
    if (ev.target && ev.target.tagName === 'INPUT') return;
    if (ev.key === '+' || ev.key === '=') zoom(0.8);
    if (ev.key === '-' || ev.key === '_') zoom(1.25);
  });
  app.wrench = wrench;
  app.screen = screen;
  app.loadScene = loadScene;
  app.recompute = recompute;
  loadScene(JSON.stringify(MOMENTLAB_EXAMPLES['figure-3-block-along-wall']), 'figure-3-block-along-wall');
  app.ready = true;
}

window.addEventListener('error', (ev) => showError(ev.message));
momentlabModule().then(start, (e) => showError(`momentlab could not start: ${e.message || e}`));
