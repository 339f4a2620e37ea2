// The JavaScript API of momentlab.mjs (docs/web.md), appended to the module (--post-js): plain
// JS values in and out, a JS Error with the CLI's one-line message for bad input.
//
//   const ml = await (await import('./momentlab.mjs')).default();
//   const a = ml.analyze(sceneJsonText);   // a.modes: ['ff', 'ss', ...]
//   a.query([fx, fy, tau]);                // ['rr']
//   a.delete();                            // frees the WebAssembly memory of the analysis
//
// Here only the shapes of JS values are checked (an array of so many numbers, NaN and infinities
// said as such, options by name: one a function does not take is an error naming it); every
// number's range is checked by the library's application layer (app/checks.hpp), as the CLI and
// Python check it.

function momentlabAnswer(text) {
  const value = JSON.parse(text);
  if (value && typeof value === 'object' && !Array.isArray(value) && typeof value.error === 'string') {
    throw new Error(value.error);
  }
  return value;
}

// "got NaN", "got Infinity", "got a string", ...: what a value is, in a message.
function momentlabGot(x) {
  if (typeof x === 'number') return `got ${x}`;
  if (x === null || x === undefined) return `got ${x}`;
  if (Array.isArray(x)) return 'got an array';
  return `got ${typeof x === 'object' ? 'an object' : `a ${typeof x}`}`;
}

// Decimal text as the CLI reads its options (Rational::parse): a sign, digits with at most one
// point (.3 and 3. too), an exponent.
const momentlabDecimal = /^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$/;
// Blanks around a number as the CLI and Python strip them (space, tab, CR, LF; not Unicode's).
const momentlabStrip = (text) => text.replace(/^[ \t\r\n]+|[ \t\r\n]+$/g, '');

// n finite numbers (an array or a typed array) at `where`, as a plain array; with `typed`, a
// decimal string may stand for a number ('0.1' is exactly 1/10, as the CLI reads its options;
// docs/design.md, "Numbers as typed") and is kept as given for bindings.cpp (loads).
function momentlabNumbers(value, n, where, shape, typed = false) {
  const isList = Array.isArray(value) || ArrayBuffer.isView(value);
  if (!isList || value.length !== n) {
    throw new Error(`${where}: expected ${n} numbers ${shape}, ${isList ? `got ${value.length}` : momentlabGot(value)}`);
  }
  return Array.from(value, (x, i) => (typed ? momentlabTypedNumber(x, `${where}[${i}]`) : momentlabNumber(x, `${where}[${i}]`)));
}

// A finite number, or a decimal string standing for one (kept as given for bindings.cpp).
function momentlabTypedNumber(x, where) {
  if (typeof x === 'string' && momentlabDecimal.test(momentlabStrip(x))) return momentlabStrip(x);
  if (typeof x === 'string') throw new Error(`${where}: expected a finite number (or a decimal string such as "0.1"), got "${x}"`);
  return momentlabNumber(x, where);
}

const momentlabTyped = (value, n, where, shape) => momentlabNumbers(value, n, where, shape, true);

function momentlabNumber(x, where) {
  if (typeof x !== 'number' || !Number.isFinite(x)) throw new Error(`${where}: expected a finite number, ${momentlabGot(x)}`);
  return x;
}

const momentlabWrench = (w, where = 'wrench') => momentlabNumbers(w, 3, where, '[fx, fy, tau]');
const momentlabPoint = (p, where) => momentlabNumbers(p, 2, where, '[x, y]');

// The options object of `what`: absent, or an object whose keys are all in `known`.
function momentlabOptions(options, what, known) {
  if (options === undefined || options === null) return {};
  if (typeof options !== 'object' || Array.isArray(options)) throw new Error(`options: expected an object of ${what}'s options, ${momentlabGot(options)}`);
  for (const key of Object.keys(options)) {
    if (!known.includes(key)) {
      throw new Error(`${key}: not an option of ${what} (${known.length ? `its options: ${known.join(', ')}` : 'it takes none'})`);
    }
  }
  return options;
}

const momentlabLoadKeys = ['gravity', 'wrench', 'forces'];

// The load of a question or plan (docs/web.md): gravity [gx, gy] through the centre of mass, a
// wrench [fx, fy, tau] and forces [[[x, y], [fx, fy]], ...], as JSON text for bindings.cpp.
function momentlabLoad(o) {
  const load = {};
  if (o.gravity !== undefined) load.gravity = momentlabTyped(o.gravity, 2, 'gravity', '[gx, gy]');
  if (o.wrench !== undefined) load.wrench = momentlabTyped(o.wrench, 3, 'wrench', '[fx, fy, tau]');
  if (o.forces !== undefined) {
    if (!Array.isArray(o.forces)) throw new Error(`forces: expected an array of [point, force], ${momentlabGot(o.forces)}`);
    load.forces = o.forces.map((f, i) => {
      if (!Array.isArray(f) || f.length !== 2) throw new Error(`forces[${i}]: expected [point, force]`);
      return [momentlabTyped(f[0], 2, `forces[${i}][0]`, '[x, y]'), momentlabTyped(f[1], 2, `forces[${i}][1]`, '[fx, fy]')];
    });
  }
  return JSON.stringify(load);
}

// A scene or force set as JSON text: a string as it is (Unicode), an object as JSON data. A value
// JSON cannot hold (NaN, an infinity, undefined, a function, a cycle, a lone surrogate) is an
// error naming its path, in one line.
function momentlabHasLoneSurrogate(text) {
  for (let i = 0; i < text.length; ++i) {
    const c = text.charCodeAt(i);
    if (c >= 0xd800 && c <= 0xdbff) {
      const next = i + 1 < text.length ? text.charCodeAt(i + 1) : 0;
      if (next < 0xdc00 || next > 0xdfff) return true;
      ++i;
    } else if (c >= 0xdc00 && c <= 0xdfff) {
      return true;
    }
  }
  return false;
}

function momentlabJsonData(value, path, open) {
  if (typeof value === 'string') {
    if (momentlabHasLoneSurrogate(value)) throw new Error(`${path}: a string with a lone surrogate (not Unicode text)`);
    return;
  }
  if (typeof value === 'number') {
    if (!Number.isFinite(value)) throw new Error(`${path}: expected a finite number, got ${value}`);
    return;
  }
  if (value === null || typeof value === 'boolean') return;
  if (typeof value !== 'object') throw new Error(`${path}: expected JSON data, ${momentlabGot(value)}`);
  if (open.has(value)) throw new Error(`${path}: a cyclic object (JSON data has no cycles)`);
  open.add(value);
  if (Array.isArray(value)) {
    value.forEach((x, i) => momentlabJsonData(x, `${path}[${i}]`, open));
  } else {
    for (const k of Object.keys(value)) {
      const x = value[k];
      if (momentlabHasLoneSurrogate(k)) throw new Error(`${path}: a key with a lone surrogate (not Unicode text)`);
      momentlabJsonData(x, /^[A-Za-z_][A-Za-z0-9_]*$/.test(k) ? `${path}.${k}` : `${path}[${JSON.stringify(k)}]`, open);
    }
  }
  open.delete(value);
}

function momentlabText(scene, what) {
  if (typeof scene === 'string') {
    if (momentlabHasLoneSurrogate(scene)) throw new Error(`$: the ${what}'s text holds a lone surrogate (not Unicode text)`);
    return scene;
  }
  if (scene === null || typeof scene !== 'object') throw new Error(`$: expected the JSON text of a ${what} or an object`);
  momentlabJsonData(scene, '$', new Set());
  return JSON.stringify(scene);
}

function momentlabView(view) {
  return view === undefined || view === null ? [-2, -2, 2, 2] : momentlabNumbers(view, 4, 'view', '[xmin, ymin, xmax, ymax]');
}

class MomentlabAnalysis {
  constructor(session) {
    this._live = session;
    /** The mode strings, the all-f mode first. */
    this.modes = Array.from(session.modes());
    /** Warnings about the scene (unknown fields), each "path: message". */
    this.warnings = Array.from(session.warnings());
  }
  get _session() {
    if (!this._live) throw new Error('analysis: already deleted');
    return this._live;
  }
  _ask(w, options) {
    const o = momentlabOptions(options, 'query', ['gravity', 'forces']);
    const load = Object.assign({}, o);
    if (w !== undefined && w !== null) load.wrench = w;
    return momentlabAnswer(this._session.query(momentlabLoad(load)));
  }
  /** The modes whose closed E_i hold the applied wrench [fx, fy, tau] (tau about the origin),
   *  sorted; options {gravity: [gx, gy], forces: [[point, force], ...]} add to it (the wrench
   *  may then be null). */
  query(w, options) {
    return this._ask(w, options).modes;
  }
  /** 'unique', 'ambiguous' or 'inconsistent'. */
  verdict(w, options) {
    return this._ask(w, options).verdict;
  }
  /** For N wrenches (an array of [fx, fy, tau] or a flat array of 3 N numbers): a Uint8Array of
   *  N * modes.length, 1 where mode k holds wrench i (index i * modes.length + k). */
  queryBatch(wrenches) {
    if (!Array.isArray(wrenches) && !ArrayBuffer.isView(wrenches)) {
      throw new Error(`wrenches: expected an array of [fx, fy, tau] or a flat array of 3 N numbers, ${momentlabGot(wrenches)}`);
    }
    let flat;
    if (wrenches.length && Array.isArray(wrenches[0])) {
      flat = [];
      wrenches.forEach((w, i) => flat.push(...momentlabWrench(w, `wrenches[${i}]`)));
    } else {
      if (wrenches.length % 3 !== 0) throw new Error('wrenches: expected 3 numbers per wrench');
      flat = [];
      for (let i = 0; i < wrenches.length; i += 3) flat.push(...momentlabWrench(Array.from(wrenches).slice(i, i + 3), `wrenches[${i / 3}]`));
    }
    const out = this._session.queryBatch(flat);
    if (typeof out === 'string') momentlabAnswer(out);
    return out;
  }
  /** One mode's sets: twists, F, T and E (each {cone, plus, minus, both} with the regions cut to
   *  the view [xmin, ymin, xmax, ymax] as "clipped" polygons) and its rotation centres. */
  mode(letters, view) {
    const v = momentlabView(view);
    return momentlabAnswer(this._session.mode(String(letters), v[0], v[1], v[2], v[3]));
  }
  /** The tilts that produce the goal, as `plan tilt --json`: {goal, intervals, best, margin,
   *  unique, shared, ...}; options {wrench, forces} act besides gravity (gravity itself is refused:
   *  a tilt turns it). */
  planTilt(goal, options) {
    const o = momentlabOptions(options, 'planTilt', momentlabLoadKeys);
    return momentlabAnswer(this._session.planTilt(String(goal), momentlabLoad(o)));
  }
  /** The pushing table, as `plan push --json`: {goal, mu, interference, cases: [...]}; options
   *  {mu (0.5), ignoreInterference, edge, vertex, slip ('l', 'f' or 'r'), gravity, wrench, forces}. */
  planPush(goal, options) {
    const o = momentlabOptions(options, 'planPush', ['mu', 'ignoreInterference', 'edge', 'vertex', 'slip', ...momentlabLoadKeys]);
    const mu = o.mu === undefined ? 0.5 : momentlabTypedNumber(o.mu, 'mu');
    const index = (key) => {
      if (o[key] === undefined) return -1;
      if (!Number.isInteger(o[key]) || o[key] < 0 || o[key] > 2 ** 31 - 1) throw new Error(`${key}: expected an index 0, 1, ..., ${momentlabGot(o[key])}`);
      return o[key];
    };
    if (o.slip !== undefined && !['l', 'f', 'r'].includes(o.slip)) throw new Error(`slip: expected 'l', 'f' or 'r'`);
    if (o.ignoreInterference !== undefined && typeof o.ignoreInterference !== 'boolean') throw new Error(`ignoreInterference: expected true or false, ${momentlabGot(o.ignoreInterference)}`);
    return momentlabAnswer(this._session.planPush(String(goal), JSON.stringify(mu), Boolean(o.ignoreInterference), index('edge'), index('vertex'),
                                                  o.slip || '', momentlabLoad(o)));
  }
  /** Compliance, as `plan comply --json`: {goal, labels: {plus, minus} of E_goal (+ cone(-g) with
   *  a load), centre: {point, label, verdict, intervals, unique, shared, ...} when a centre [x, y]
   *  is given (null: the labels only); options {gravity, wrench, forces}. */
  planComply(goal, centre, view, options) {
    const v = momentlabView(view);
    const o = momentlabOptions(options, 'planComply', momentlabLoadKeys);
    const c = centre === null ? '' : JSON.stringify(momentlabTyped(centre, 2, 'centre', '[x, y]'));
    return momentlabAnswer(this._session.planComply(String(goal), c, v[0], v[1], v[2], v[3], momentlabLoad(o)));
  }
  /** The force lambda * direction through point, lambda from 0 up, added to the load of options
   *  {gravity, wrench, forces}: as `query --push X Y DX DY --json`, {point, direction, fixed,
   *  bands: [{from, to, from_closed, to_closed, modes, verdict}]}. */
  pushLine(point, direction, options) {
    const p = momentlabTyped(point, 2, 'point', '[x, y]'), d = momentlabTyped(direction, 2, 'direction', '[dx, dy]');
    const o = momentlabOptions(options, 'pushLine', momentlabLoadKeys);
    return momentlabAnswer(this._session.pushLine(JSON.stringify([p, d]), momentlabLoad(o)));
  }
  /** The scene in the file format (contacts written out). */
  sceneJson() {
    return this._session.sceneJson();
  }
  /** Frees the analysis (WebAssembly memory is not garbage collected). */
  delete() {
    if (this._live) this._live.delete();
    this._live = null;
  }
}

/** Every mode of a scene (JSON text in the CLI's format, or an object) with its sets;
 *  options.quasiStatic neglects inertia (E = -T, no body needed). */
Module['analyze'] = function (scene, options) {
  const o = momentlabOptions(options, 'analyze', ['quasiStatic']);
  const text = momentlabText(scene, 'scene');
  const session = new Module['Session'](text, Boolean(o.quasiStatic));
  const error = session.error();
  if (error) {
    session.delete();
    throw new Error(error);
  }
  return new MomentlabAnalysis(session);
};

/** The moment labels of a force set (the format of `momentlab label`, text or object), cut to
 *  the view: {cone, plus, minus, both}. */
Module['forceSetLabels'] = function (forceSet, view) {
  const v = momentlabView(view);
  const text = momentlabText(forceSet, 'force set');
  return momentlabAnswer(Module['labels'](text, v[0], v[1], v[2], v[3]));
};

/** Grasp closure of a scene's contacts, as `momentlab closure --json`: {form_closure,
 *  force_closure, form, force, reference, length, metric}; options {reference: [x, y], length,
 *  view: [xmin, ymin, xmax, ymax]} (with a view, also labels: {form, force}, the moment labels
 *  of each test's contact wrenches cut to it). */
Module['graspClosure'] = function (scene, options) {
  const o = momentlabOptions(options, 'graspClosure', ['reference', 'length', 'view']);
  const text = momentlabText(scene, 'scene');
  const r = o.reference === undefined ? null : momentlabPoint(o.reference, 'reference');
  const length = o.length === undefined ? null : momentlabNumber(o.length, 'length');
  const v = o.view === undefined ? null : momentlabView(o.view);
  return momentlabAnswer(Module['closure'](text, r !== null, r ? r[0] : 0, r ? r[1] : 0, length !== null, length || 0,
                                           v !== null, ...(v || [0, 0, 1, 1])));
};

/** Will an assembly stand (docs/assemblies.md), as `momentlab stand --json`: {can_stand, forces |
 *  mechanism, modes, verdict, motions, outcome, tilt?} and assembly: the scene as read, contacts
 *  written out (found ones included); options {gravity: [gx, gy] (default (0, -9.81); numbers
 *  or decimal strings, as loads), tilt}. */
Module['stand'] = function (scene, options) {
  const o = momentlabOptions(options, 'stand', ['gravity', 'tilt']);
  const text = momentlabText(scene, 'scene');
  if (o.tilt !== undefined && typeof o.tilt !== 'boolean') throw new Error(`tilt: expected true or false, ${momentlabGot(o.tilt)}`);
  return momentlabAnswer(Module['standJson'](text, momentlabLoad({ gravity: o.gravity }), o.tilt === true));
};
