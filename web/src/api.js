// The JavaScript API of momentlab.mjs (docs/web.md), appended to the module (--post-js): plain
// JS values in and out, a JS Error with the CLI's one-line message for bad input.
//
//   const ml = await (await import('./momentlab.mjs')).default();
//   const a = ml.analyze(sceneJsonText);   // a.modes: ['ff', 'ss', ...]
//   a.query([fx, fy, tau]);                // ['rr']
//   a.delete();                            // frees the WebAssembly memory of the analysis

function momentlabAnswer(text) {
  const value = JSON.parse(text);
  if (value && typeof value === 'object' && !Array.isArray(value) && typeof value.error === 'string') {
    throw new Error(value.error);
  }
  return value;
}

// The CLI's range for numbers: 0, or magnitudes 1e-60 .. 1e60.
function momentlabInRange(x) {
  const m = Math.abs(x);
  return m === 0 || (m >= 1e-60 && m <= 1e60);
}

function momentlabWrench(w, what = 'wrench') {
  if (!w || w.length !== 3) throw new Error(`${what}: expected 3 numbers [fx, fy, tau]`);
  const e = [Number(w[0]), Number(w[1]), Number(w[2])];
  if (!e.every(Number.isFinite)) throw new Error(`${what}: expected finite numbers`);
  if (!e.every(momentlabInRange)) throw new Error(`${what}: out of range: each number must be 0 or of magnitude 1e-60 .. 1e60`);
  return e;
}

function momentlabText(scene, what) {
  if (typeof scene === 'string') return scene;
  if (scene === null || typeof scene !== 'object') throw new Error(`$: expected the JSON text of a ${what} or an object`);
  return JSON.stringify(scene);
}

function momentlabView(view) {
  const v = view || [-2, -2, 2, 2];
  if (v.length !== 4) throw new Error('view: expected [xmin, ymin, xmax, ymax]');
  return v.map(Number);
}

const momentlabVerdicts = ['inconsistent', 'unique', 'ambiguous'];

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
  /** The modes whose closed E_i holds the applied wrench [fx, fy, tau] (tau about the origin). */
  query(w) {
    const e = momentlabWrench(w);
    return Array.from(this._session.query(e[0], e[1], e[2]));
  }
  /** 'unique', 'ambiguous' or 'inconsistent'. */
  verdict(w) {
    return momentlabVerdicts[Math.min(this.query(w).length, 2)];
  }
  /** For N wrenches (an array of [fx, fy, tau] or a flat array of 3 N numbers): a Uint8Array of
   *  N * modes.length, 1 where mode k holds wrench i (index i * modes.length + k). */
  queryBatch(wrenches) {
    let flat;
    if (Array.isArray(wrenches) && wrenches.length && Array.isArray(wrenches[0])) {
      flat = [];
      wrenches.forEach((w, i) => flat.push(...momentlabWrench(w, `wrenches[${i}]`)));
    } else {
      flat = Array.from(wrenches || []);
      if (flat.length % 3 !== 0) throw new Error('wrenches: expected 3 numbers per wrench');
      for (let i = 0; i < flat.length; i += 3) momentlabWrench(flat.slice(i, i + 3), `wrenches[${i / 3}]`);
    }
    return this._session.queryBatch(flat);
  }
  /** One mode's sets: twists, F, T and E (each {cone, plus, minus, both} with the regions cut to
   *  the view [xmin, ymin, xmax, ymax] as "clipped" polygons) and its rotation centres. */
  mode(letters, view) {
    const v = momentlabView(view);
    return momentlabAnswer(this._session.mode(String(letters), v[0], v[1], v[2], v[3]));
  }
  /** The tilts that produce the goal: {goal, intervals: [[from, to], ...], best, margin}. */
  planTilt(goal) {
    return momentlabAnswer(this._session.planTilt(String(goal)));
  }
  /** The pushing table: {goal, mu, cases: [{feature, slip, verdict, feasible, touch, ...}]}. */
  planPush(goal, options) {
    const o = options || {};
    const mu = o.mu === undefined ? 0.5 : Number(o.mu);
    return momentlabAnswer(this._session.planPush(String(goal), mu, Boolean(o.ignoreInterference)));
  }
  /** Compliance: {goal, labels: {plus, minus} of E_goal, centre: {point, label, verdict, intervals}}. */
  planComply(goal, centre, view) {
    const v = momentlabView(view);
    if (!centre || centre.length !== 2) throw new Error('centre: expected [x, y]');
    if (!centre.every((x) => Number.isFinite(Number(x)) && momentlabInRange(Number(x)))) {
      throw new Error('centre: out of range: each number must be 0 or of magnitude 1e-60 .. 1e60');
    }
    return momentlabAnswer(this._session.planComply(String(goal), Number(centre[0]), Number(centre[1]),
                                                    v[0], v[1], v[2], v[3]));
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
  const text = momentlabText(scene, 'scene');
  const session = new Module['Session'](text, Boolean(options && options.quasiStatic));
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
 *  force_closure, form, force, reference, length, metric}. */
Module['graspClosure'] = function (scene) {
  const text = momentlabText(scene, 'scene');
  return momentlabAnswer(Module['closure'](text));
};
