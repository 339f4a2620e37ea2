// The viewer's drawing (docs/web.md): SVG helpers, labelled regions, arrows and arcs, the axes
// with coordinates, the legend, and handles that never hide one another. Loaded before panels.js
// and app.js (web/build_page.py inlines the three in that order).
'use strict';

const COLOURS = {
  plus: '#fdc585', plusEdge: '#d9720b', minus: '#99c8f2', minusEdge: '#216ab5', both: '#7a1c96',
  body: '#59595f', obstacle: '#8c8c8c', friction: '#2e994f', guide: '#9e9ea8', ink: '#1f1f24',
  tilt: '#6a3d9a', spring: '#b15928', push: '#2e994f', certificate: '#c0162b',
};
const MODE_COLOURS = ['#a6cee3', '#b2df8a', '#fb9a99', '#fdbf6f', '#cab2d6', '#ffff99', '#8dd3c7', '#fccde5',
                      '#d9d9d9', '#ccebc5', '#bc80bd', '#ffed6f'];
const SVG = 'http://www.w3.org/2000/svg';

function el(name, attrs, parent) {
  const e = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

function text(g, x, y, content, attrs) {
  const t = el('text', Object.assign({ x, y, 'font-size': 11, fill: COLOURS.ink }, attrs || {}), g);
  t.textContent = content;
  return t;
}

function pathOf(points, s, closed) {
  if (!points.length) return '';
  return points.map((p, i) => `${i ? 'L' : 'M'}${s.x(p[0]).toFixed(2)},${s.y(p[1]).toFixed(2)}`).join(' ') + (closed ? ' Z' : '');
}

function centroid(points) {
  const n = points.length;
  return [points.reduce((a, p) => a + p[0], 0) / n, points.reduce((a, p) => a + p[1], 0) / n];
}

function degrees(r) { return `${(r * 180 / Math.PI).toFixed(2)}\u00b0`; }

// Arcs as text: "[-120.96°, -25.11°], 0.00° only" ("none" for no arc).
function arcsText(arcs) {
  if (!arcs || !arcs.length) return 'none';
  return arcs.map(([lo, hi]) => (lo === hi ? `${degrees(lo)} only` : `[${degrees(lo)}, ${degrees(hi)}]`)).join(', ');
}

function drawRegion(g, region, fill, edge, s, cls, mark) {
  const poly = region.clipped || [];
  let shape = null;
  if (poly.length >= 3) {
    shape = el('path', { d: pathOf(poly, s, true), fill, 'fill-opacity': 0.85, stroke: edge, 'stroke-width': 1.2, class: cls }, g);
  } else if (poly.length === 2) {
    shape = el('path', { d: pathOf(poly, s, false), stroke: edge, 'stroke-width': 3, fill: 'none', class: cls }, g);
  } else if (poly.length === 1) {
    shape = el('circle', { cx: s.x(poly[0][0]), cy: s.y(poly[0][1]), r: 5, fill: edge, class: cls }, g);
  }
  if (shape) shape.dataset.world = JSON.stringify(poly);
  if (mark && poly.length) {
    const c = centroid(poly);
    // A white halo keeps a label readable over other regions (every mode's rotation centres).
    text(g, s.x(c[0]), s.y(c[1]), mark, { fill: edge, 'font-size': 20, 'font-weight': 700, 'text-anchor': 'middle',
      'dominant-baseline': 'middle', stroke: '#fff', 'stroke-width': 3, 'paint-order': 'stroke', class: `${cls}-mark` });
  }
}

// The line of action of a wrench (fx, fy, tau about the origin): a point on it and its unit direction.
function lineOfAction(w) {
  const [fx, fy, tau] = w, n2 = fx * fx + fy * fy;
  if (n2 === 0) return null;
  return { point: [tau / n2 * fy, -tau / n2 * fx], direction: [fx / Math.sqrt(n2), fy / Math.sqrt(n2)] };
}

function drawLine(g, line, s, attrs, view) {
  const far = 4 * (view[2] - view[0]), { point: p, direction: d } = line;
  return el('path', Object.assign({ d: pathOf([[p[0] - far * d[0], p[1] - far * d[1]], [p[0] + far * d[0], p[1] + far * d[1]]], s) }, attrs), g);
}

function drawSet(g, set, s, view) {
  drawRegion(g, set.plus, COLOURS.plus, COLOURS.plusEdge, s, 'plus', '+');
  drawRegion(g, set.minus, COLOURS.minus, COLOURS.minusEdge, s, 'minus', '\u2212');
  if (set.both) drawRegion(g, set.both, COLOURS.both, COLOURS.both, s, 'both', '');
  // the forces: the cone's extreme rays on their (dashed) lines of action
  for (const r of (set.cone && set.cone.rays) || []) {
    const line = lineOfAction(r);
    if (line) drawLine(g, line, s, { stroke: COLOURS.ink, 'stroke-dasharray': '5 4', 'stroke-width': 0.8, opacity: 0.6, class: 'line-of-action' }, view);
  }
}

function arrow(g, from, to, colour, s, width, cls) {
  const [x0, y0, x1, y1] = [s.x(from[0]), s.y(from[1]), s.x(to[0]), s.y(to[1])];
  const line = el('line', { x1: x0, y1: y0, x2: x1, y2: y1, stroke: colour, 'stroke-width': width, class: cls || '' }, g);
  const a = Math.atan2(y1 - y0, x1 - x0), h = 9;
  el('path', { d: `M${x1},${y1} L${x1 - h * Math.cos(a - 0.4)},${y1 - h * Math.sin(a - 0.4)} L${x1 - h * Math.cos(a + 0.4)},${y1 - h * Math.sin(a + 0.4)} Z`,
               fill: colour, class: cls || '' }, g);
  return line;
}

// Directions as arcs about a point (radius r, in the scene's units): the plan's union thin, the
// arcs where the goal is alone thick and solid, those shared with another mode thick and dashed;
// the best direction an arrow. Each arc's element carries its [from, to] (data-arc).
function drawDirections(g, plan, at, r, colour, s, cls) {
  const arc = (lo, hi, attrs, kind) => {
    const steps = Math.max(2, Math.ceil(48 * (hi - lo) / Math.PI)), pts = [];
    for (let i = 0; i <= steps; ++i) {
      const t = lo + (hi - lo) * i / steps;
      pts.push([at[0] + r * Math.cos(t), at[1] + r * Math.sin(t)]);
    }
    const p = el('path', Object.assign({ d: pathOf(pts, s), fill: 'none', stroke: colour, 'stroke-linecap': 'round', class: `${cls} ${kind}` }, attrs), g);
    p.dataset.arc = JSON.stringify([lo, hi]);
  };
  for (const [lo, hi] of plan.intervals || []) arc(lo, hi, { 'stroke-width': 2, opacity: 0.5 }, 'union');
  for (const [lo, hi] of plan.unique || []) arc(lo, hi, { 'stroke-width': hi > lo ? 6 : 3, opacity: 0.85 }, 'unique');
  for (const [lo, hi] of plan.shared || []) arc(lo, hi, { 'stroke-width': hi > lo ? 6 : 3, 'stroke-dasharray': '4 5', opacity: 0.85 }, 'shared');
  if (plan.intervals && plan.intervals.length && typeof plan.best === 'number') {
    arrow(g, at, [at[0] + 1.3 * r * Math.cos(plan.best), at[1] + 1.3 * r * Math.sin(plan.best)], colour, s, 2, `${cls} best`);
  }
}

// A tick step of 1, 2 or 5 times a power of ten, about `ticks` steps over `span`.
function tickStep(span, ticks) {
  const raw = span / ticks, p = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((m) => m * p).find((x) => x >= raw);
}

// Axes along the bottom and left edges with the scene's coordinates, and the origin's cross.
function drawAxes(svg, s) {
  const g = el('g', { id: 'axes' }, svg);
  const [x0, y0, x1, y1] = s.box();
  const step = tickStep(Math.max(x1 - x0, y1 - y0), 8);
  const label = (v) => String(Number(v.toPrecision(6)));
  el('line', { x1: 0, y1: s.h - 1, x2: s.w, y2: s.h - 1, stroke: COLOURS.guide }, g);
  el('line', { x1: 1, y1: 0, x2: 1, y2: s.h, stroke: COLOURS.guide }, g);
  for (let x = Math.ceil(x0 / step) * step; x <= x1; x += step) {
    el('line', { x1: s.x(x), y1: s.h, x2: s.x(x), y2: s.h - 6, stroke: COLOURS.guide, class: 'tick-x' }, g);
    text(g, s.x(x), s.h - 9, label(x), { 'text-anchor': 'middle', fill: '#666', 'font-size': 10, class: 'tick-x-label' });
  }
  for (let y = Math.ceil(y0 / step) * step; y <= y1; y += step) {
    el('line', { x1: 0, y1: s.y(y), x2: 6, y2: s.y(y), stroke: COLOURS.guide, class: 'tick-y' }, g);
    text(g, 9, s.y(y), label(y), { 'dominant-baseline': 'middle', fill: '#666', 'font-size': 10, class: 'tick-y-label' });
  }
  if (x0 < 0 && x1 > 0 && y0 < 0 && y1 > 0) {
    el('path', { d: `M${s.x(0) - 6},${s.y(0)} h12 M${s.x(0)},${s.y(0) - 6} v12`, stroke: COLOURS.guide, class: 'origin' }, g);
  }
  g.dataset.step = step;
  return g;
}

// The legend: what each colour, line and handle means, compact in the top left corner.
function drawLegend(svg, entries) {
  const g = el('g', { id: 'legend' }, svg);
  const columns = 2, width = 222, row = 15, rows = Math.ceil(entries.length / columns);
  el('rect', { x: 24, y: 6, width: columns * width + 8, height: rows * row + 8, fill: '#fff', 'fill-opacity': 0.88,
               stroke: '#ccc', rx: 3 }, g);
  entries.forEach(([swatch, words], i) => {
    const x = 30 + Math.floor(i / rows) * width, y = 14 + (i % rows) * row;
    swatch(g, x, y);
    text(g, x + 22, y + 4, words, { 'font-size': 10.5, class: 'legend-entry' });
  });
  return g;
}

const swatch = {
  fill: (colour, edge) => (g, x, y) => el('rect', { x, y: y - 4, width: 16, height: 9, fill: colour, stroke: edge }, g),
  line: (colour, width, dash) => (g, x, y) => el('line', { x1: x, y1: y, x2: x + 16, y2: y, stroke: colour, 'stroke-width': width, 'stroke-dasharray': dash || '' }, g),
  dot: (colour, r) => (g, x, y) => el('circle', { cx: x + 8, cy: y, r, fill: colour }, g),
  square: (colour) => (g, x, y) => el('rect', { x: x + 3, y: y - 5, width: 10, height: 10, fill: colour, 'fill-opacity': 0.8 }, g),
  ring: (colour) => (g, x, y) => el('circle', { cx: x + 8, cy: y, r: 5, fill: 'none', stroke: colour, 'stroke-width': 2.5 }, g),
};

// Handles are placed in the order drawn; one that would cover an earlier one (its centre within
// SPACING pixels) is drawn beside it, joined to its point by a thin leader, and drags keep that
// offset: every handle stays reachable (the force's point never sits on the centre of mass).
const SPACING = 28;

function placeHandle(placed, sx, sy) {
  let dx = 0, dy = 0;
  for (let k = 0; k < 16 && placed.some(([x, y]) => Math.hypot(x - sx - dx, y - sy - dy) < SPACING); ++k) {
    const a = -Math.PI / 4 + k * Math.PI / 4, r = SPACING * (1 + Math.floor(k / 8));
    dx = r * Math.cos(a);
    dy = r * Math.sin(a);
  }
  placed.push([sx + dx, sy + dy]);
  return [dx, dy];
}

// --- exports: the picture as SVG (without the handles) or PNG ---------------------------------

function download(name, type, data) {
  const url = URL.createObjectURL(new Blob([data], { type }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

function svgText() {
  const svg = $('view').cloneNode(true);
  svg.querySelectorAll('#handles').forEach((h) => h.remove());
  svg.setAttribute('width', $('view').clientWidth);
  svg.setAttribute('height', $('view').clientHeight);
  return new XMLSerializer().serializeToString(svg);
}

function exportPng() {
  const img = new Image();
  const w = $('view').clientWidth, h = $('view').clientHeight;
  img.onload = () => {
    const canvas = document.createElement('canvas');
    canvas.width = w * 2;
    canvas.height = h * 2;
    const ctx = canvas.getContext('2d');
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    ctx.drawImage(img, 0, 0, canvas.width, canvas.height);
    canvas.toBlob((blob) => download('momentlab.png', 'image/png', blob));
  };
  img.src = `data:image/svg+xml;charset=utf-8,${encodeURIComponent(svgText())}`;
}
