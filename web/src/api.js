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

function momentlabWrench(w) {
  if (!w || w.length !== 3) throw new Error('wrench: expected 3 numbers [fx, fy, tau]');
  const e = [Number(w[0]), Number(w[1]), Number(w[2])];
  if (!e.every(Number.isFinite)) throw new Error('wrench: expected finite numbers');
  return e;
}

function momentlabView(view) {
  const v = view || [-2, -2, 2, 2];
  if (v.length !== 4) throw new Error('view: expected [xmin, ymin, xmax, ymax]');
  return v.map(Number);
}

const momentlabVerdicts = ['inconsistent', 'unique', 'ambiguous'];

class MomentlabAnalysis {
  constructor(session) {
    this._session = session;
    /** The mode strings, the all-f mode first. */
    this.modes = Array.from(session.modes());
    /** Warnings about the scene (unknown fields), each "path: message". */
    this.warnings = Array.from(session.warnings());
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
    const flat = Array.isArray(wrenches) && Array.isArray(wrenches[0]) ? wrenches.flat() : Array.from(wrenches);
    if (flat.length % 3 !== 0) throw new Error('wrenches: expected 3 numbers per wrench');
    for (let i = 0; i < flat.length; ++i) {
      if (!Number.isFinite(flat[i])) throw new Error(`wrenches[${Math.floor(i / 3)}]: expected finite numbers`);
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
    return momentlabAnswer(this._session.planComply(String(goal), Number(centre[0]), Number(centre[1]),
                                                    v[0], v[1], v[2], v[3]));
  }
  /** The scene in the file format (contacts written out). */
  sceneJson() {
    return this._session.sceneJson();
  }
  /** Frees the analysis (WebAssembly memory is not garbage collected). */
  delete() {
    if (this._session) this._session.delete();
    this._session = null;
  }
}

/** Every mode of a scene (JSON text in the CLI's format, or an object) with its sets;
 *  options.quasiStatic neglects inertia (E = -T, no body needed). */
Module['analyze'] = function (scene, options) {
  const text = typeof scene === 'string' ? scene : JSON.stringify(scene);
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
  const text = typeof forceSet === 'string' ? forceSet : JSON.stringify(forceSet);
  return momentlabAnswer(Module['labels'](text, v[0], v[1], v[2], v[3]));
};

/** Grasp closure of a scene's contacts, as `momentlab closure --json`: {form_closure,
 *  force_closure, form, force, reference, length, metric}. */
Module['graspClosure'] = function (scene) {
  const text = typeof scene === 'string' ? scene : JSON.stringify(scene);
  return momentlabAnswer(Module['closure'](text));
};
