// The page's state and its events. Views subscribe to events; nothing else holds state.
//
// Events (the detail passed to listeners):
//   limits     the module's limits arrived (web/src/limits.js holds them); a case loads after
//   inputs     the case's inputs changed (form, measured grid, locks, run axes): {source, at}
//   commit     the user finished a change of the inputs (an undo step): {}
//   restore    the inputs were set from an undo step: views that show inputs show them again:
//              {before} (the inputs before the step, as they were)
//   computing  a case went to the calculator: {caseObject}
//   result     a result arrived for the newest inputs: {result, caseObject, ms}
//   refusal    an input was refused, by the calculator or by the page: {error, caseObject}
//   aside      a measured grid the calculator refused was set aside: {error, untilFits} (untilFits:
//              it does not fit the grid lines, and is used again when they are back to its shape)
//   cancelled  the user cancelled the calculation of these inputs: {caseObject}
//   status     state.status changed
//   notice     state.notice changed (a message that stays until the user changes something)
//   view       what the views show changed: state.view (normal or circular deviation), or
//              state.pinned (a pinned result, whose difference the views then show)
//   surfaces   state.surfaces changed: the 3D surfaces shown beside the maps, or not
//   plots      every plot shows the newest result: {at}
//   measured-text  state.measuredText changed (the measured data's box): {source}: 'box' (typed),
//              'file' (a file's text, a refused file's put back, or the box cleared), 'case' (a
//              loaded case's grid, the machine error's, the next run's empty box), 'restore' (an
//              undo step's grid; its result follows)
//   measurement    the measured section's state changed (web/src/measurement.js): measuredOptions,
//              measuredSource, measuredAttempt, measuredRefusal, measuredMessage
//   print      print began and opened the parts on demand it prints: their plots are drawn
import { CASE_FORMAT } from './limits.js';
import { ORIENT_OPTIONS } from '../../wasm/lib/measured-grid.js';

export function initialState() {
  return {
    form: { format: CASE_FORMAT },  // the case as the form gives it
    measured: null,          // rows root to tip of values along the gash, µm, or null
    // The measured data (web/src/measurement.js keeps these, views/measured-*.js show them):
    measuredText: '',        // the text in the box: a grid's or points' CSV, as typed, given or put back
    measuredOptions: Object.fromEntries(ORIENT_OPTIONS.map((o) => [o, false])),  // ticked under the preview: transpose ... mm
    measuredSource: null,    // the measurement in use, as its file gave it: {name, what, meta: {date?, part?, operator?}, text}
    measuredAttempt: null,   // a measurement sent, in use once its result comes: {name, what, meta, text,
                             //   before: the inputs to put back if it is refused {measured, extra, tuning},
                             //   box: the box's text to put back then (undefined: leave the box)}
    measuredRefusal: null,   // a file (or the box's text) refused: {note (beside the box), status (the
                             //   status line's once what is in use is computed again, then null),
                             //   error (the calculator's), keep (the note outlives that result)}
    measuredMessage: null,   // the message beside the box (why a measurement was refused), or null
    locked: [],              // coefficients kept out of the correction: 'X a0' ...
    lockedAxes: [],          // axes kept out of the correction: 'X' ...
    tuning: {},              // the correction's thresholds a loaded case gave: truncation, amplification
    axes: null,              // the run axes of the pass under way (a loaded case's "axes"), or null
    passes: [],              // the grinding passes kept: [{axes, measured}], oldest first (pass-history.js)
    extra: {},               // case members the form has no inputs for, kept as loaded (io/case-state.js extraOf)
    offsets: {},             // the what-if machine error: axis -> offset per coefficient
    paper: null,             // the paper's own gamma_m and E_t while its example is loaded as derived
    result: null,            // the last good result
    resultCase: null,        // the case it came from
    status: { text: 'Loading the calculator…', kind: '' },
    notice: null,            // {text, kind}
    view: 'normal',          // the deviation shown: normal or circular
    surfaces: false,         // the 3D surfaces shown beside the maps
    pinned: null,            // a result the views compare with: {result, caseObject}
  };
}

// The case sent to the calculator: the form, the run axes, the measured grid with the locks, and
// the pass history (the correction identifies the machine's error from its faces too,
// docs/method.md §Correction from the pass history).
export function caseOf(state) {
  const c = structuredClone(state.form);
  for (const [k, v] of Object.entries(state.extra || {})) {
    c[k] = v !== null && typeof v === 'object' && !Array.isArray(v) && c[k] ? { ...c[k], ...structuredClone(v) } : structuredClone(v);
  }
  if (state.axes) c.axes = structuredClone(state.axes);
  if (state.measured) c.measured = state.measured;
  if (state.passes?.length) c.passes = structuredClone(state.passes);
  // A measurement as a grid, or as the measuring machine's points (kept in extra), is corrected
  // with the locks and options.
  if (state.measured || c.measuredPoints) {
    c.correction = { ...state.tuning, lockedAxes: [...state.lockedAxes], locked: [...state.locked] };
  }
  return c;
}

// The inputs as one value, for undo and redo: everything the user gave.
const INPUTS = ['form', 'measured', 'locked', 'lockedAxes', 'tuning', 'axes', 'passes', 'offsets', 'paper', 'extra'];
export function inputsOf(state) {
  return structuredClone(Object.fromEntries(INPUTS.map((k) => [k, state[k]])));
}

export function createStore(state = initialState()) {
  const listeners = new Map();
  const store = {
    state,
    on(event, listener) {
      if (!listeners.has(event)) listeners.set(event, new Set());
      listeners.get(event).add(listener);
      return () => listeners.get(event).delete(listener);
    },
    emit(event, detail = {}) {
      for (const listener of [...(listeners.get(event) || [])]) listener(detail, state);
    },
    // Changes the inputs and asks for a recompute; an unchanged case asks for nothing.
    setInputs(patch, detail = {}) {
      const before = JSON.stringify(caseOf(state));
      Object.assign(state, patch);
      if (JSON.stringify(caseOf(state)) !== before || detail.force) store.emit('inputs', detail);
    },
    // Puts back the inputs of an undo step, and recomputes if the case differs.
    restore(inputs) {
      const before = JSON.stringify(caseOf(state));
      const was = Object.fromEntries(INPUTS.map((k) => [k, state[k]]));  // replaced, not changed, below
      Object.assign(state, structuredClone(inputs));
      store.emit('restore', { before: was });
      if (JSON.stringify(caseOf(state)) !== before) store.emit('inputs', { source: 'restore' });
    },
    setStatus(text, kind = '') {
      state.status = { text, kind };
      store.emit('status');
    },
    setNotice(text, kind = 'error') {
      state.notice = text ? { text, kind } : null;
      store.emit('notice');
    },
    setView(view) {
      state.view = view;
      store.emit('view');
    },
    setSurfaces(on) {
      state.surfaces = on;
      store.emit('surfaces');
    },
    // The measured data's box; source as the 'measured-text' event says.
    setMeasuredText(text, source) {
      state.measuredText = text;
      store.emit('measured-text', { source });
    },
    // The measured section's own state (measuredOptions ... measuredMessage).
    setMeasurement(patch) {
      Object.assign(state, patch);
      store.emit('measurement');
    },
    pin(pinned) {
      state.pinned = pinned;
      store.emit('view');
    },
    accept(result, caseObject, ms) {
      Object.assign(state, { result, resultCase: caseObject });
      store.emit('result', { result, caseObject, ms });
    },
    refuse(error, caseObject = null) {
      store.emit('refusal', { error, caseObject });
    },
  };
  return store;
}
