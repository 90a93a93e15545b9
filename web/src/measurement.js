// The measured face given to the correction (issue 22): the text in the box, a measurement sent,
// the one in use, and a file refused. All of it is the store's state (store.js: measuredText ...
// measuredMessage), changed here and announced by the store's events ('measured-text',
// 'measurement'); no DOM: views/measured-*.js show it and call these. A grid or points given here
// are measured: the correction assumes the probe's noise (probe-noise.js).
import { checkGridValueCount, checkShape, orient, readMeasured } from '../../wasm/lib/measured-grid.js';
import { looksLikePoints, orientPoints, readPoints } from '../../wasm/lib/points-csv.js';
import { measuredText } from '../../wasm/lib/csv.js';
import { tuningFor } from './probe-noise.js';
import { OPTION_FIELD } from './correction-options.js';

// The grid's and the locks' refusals; the correction's options show theirs at their inputs.
export const isMeasuredField = (field) => /^(measured|correction)/.test(field || '') && !OPTION_FIELD.test(field);

// What is in use, as the note beside the box ends.
export const inUseText = (source) => (source ? `In use: ${source.name} (${source.what}).` : 'In use: no measurement (the face simulated for the axes run).');

// A text as a textarea keeps it (its line ends LF), as the preview reads it.
export const boxText = (text) => String(text).replace(/\r\n?/g, '\n');

// Whether text is the text of the measurement in use, while a refusal is shown: the preview then
// says so ("In use, a.csv: ").
export function isInUseText(state, text) {
  const s = state.measuredSource;
  return Boolean(state.measuredRefusal && s && boxText(s.text) === boxText(text));
}

// Why a grid's text is refused before it goes into the box (too many values: a textarea of a
// million lines takes the browser 20 s to lay out), or '' (a points file has limits of its own).
export function tooManyValues(text) {
  if (looksLikePoints(text)) return '';
  try {
    checkGridValueCount(text);
    return '';
  } catch (e) {
    return e.message;
  }
}

// The grid a text gives with the options ticked, checked against the grid of topography t
// ({r, x}); throws the reader's Error.
export function gridOf(text, t, options) {
  const read = readMeasured(text, t);
  const grid = orient(read.values, options);
  checkShape(grid, t.r.length, t.x.length);
  return { read, grid };
}

// The measurement a text gives, a grid of topography t's shape or the measuring machine's points,
// with the options ticked: {measured} or {measuredPoints}, and its source {name, what, meta, text};
// name: the file's, or undefined for the box's text. Throws the reader's Error.
export function measurementOf(text, t, options, name) {
  if (looksLikePoints(text)) {
    const read = readPoints(text);
    const measuredPoints = orientPoints(read.points, options);
    return { measuredPoints, source: { name: name || 'the points in the box', what: `${measuredPoints.length} points`, meta: read.meta, text } };
  }
  const { read, grid } = gridOf(text, t, options);
  return { measured: grid, source: { name: name || 'the grid in the box', what: `${grid.length} × ${(grid[0] || []).length} values`, meta: read.meta, text } };
}

const withoutPoints = (extra) => {
  const { measuredPoints, ...rest } = extra || {};
  return rest;
};
const refuse = (store, message) => store.refuse({ field: 'measured', message });

// The box's text changed by the user's typing: a file's refusal is no longer what the box shows.
export function typed(store, text) {
  if (store.state.measuredRefusal) store.setMeasurement({ measuredRefusal: null });
  store.setMeasuredText(text, 'box');
}

// The text of a measured grid that came with a loaded case (set aside or used), the machine
// error's, or none (the next run): into the box, and any message beside it goes.
export function giveText(store, text) {
  store.setMeasuredText(text, 'case');
  store.setMeasurement({ measuredMessage: null });
}

// A file the page or the calculator refused: the box gets back what it held before (boxBefore,
// undefined: left as it is), the note beside it and the status (once what is in use is computed
// again) say what was refused, why, and what is in use.
function refusedFile(store, name, reason, boxBefore, error = null, keep = false) {
  const inUse = store.state.measuredSource;
  const lead = name.replace(/^the /, 'The ');  // a file's name as it is; "The grid in the box"
  store.setMeasurement({
    measuredRefusal: {
      note: `${lead} is refused: ${reason} ${inUseText(inUse)}`,
      status: `${lead} is refused (${inUse ? `${inUse.name} stays in use` : 'no measurement in use'}): ${reason}`,
      error, keep,
    },
  });
  if (boxBefore !== undefined && store.state.measuredText !== boxBefore) store.setMeasuredText(boxBefore, 'file');
}

// A file refused before anything is computed: the note and the status say so at once.
export function refuseFile(store, name, reason, boxBefore) {
  refusedFile(store, name, reason, boxBefore);
  const refusal = store.state.measuredRefusal;
  refuse(store, refusal.note);
  store.setStatus(refusal.status, 'error');
  store.setMeasurement({ measuredRefusal: { ...refusal, status: null } });
}

// Sends the measurement a text gives; name: the file's, or undefined for the box's text;
// boxBefore: what the box held before the file, put back if the file is refused.
export function useMeasurement(store, text, { name, boxBefore } = {}) {
  const s = store.state;
  if (!s.result) { refuse(store, 'Compute a setup first, so that the grid is known.'); return; }
  store.setMeasurement({ measuredRefusal: null });
  let m;
  try {
    m = measurementOf(text, s.result.topography, s.measuredOptions, name);
  } catch (e) {
    if (name === undefined) refuse(store, e.message);
    else refuseFile(store, name, e.message, boxBefore);
    return;
  }
  store.setMeasurement({
    measuredMessage: null,
    measuredAttempt: { ...m.source, before: { measured: s.measured, extra: structuredClone(s.extra), tuning: s.tuning }, box: boxBefore },
  });
  const inputs = m.measuredPoints
    ? { measured: null, extra: { ...s.extra, measuredPoints: m.measuredPoints } }
    : { measured: m.measured, extra: withoutPoints(s.extra) };
  store.setInputs({ ...inputs, tuning: tuningFor(s.tuning, false) }, { source: 'measured', force: true });
  store.emit('commit');
}

// A file's text: into the box, then used; the box gets back what it held if the file is refused.
export function useFile(store, text, name) {
  const boxBefore = store.state.measuredText;
  store.setMeasuredText(text, 'file');
  useMeasurement(store, text, { name, boxBefore });
}

// "Clear": no measurement, an empty box.
export function clearMeasurement(store) {
  store.setMeasurement({ measuredRefusal: null, measuredMessage: null });
  store.setMeasuredText('', 'file');
  store.setInputs({ measured: null, extra: withoutPoints(store.state.extra) }, { source: 'measured', force: true });
  store.emit('commit');
}

// What is in use after a result for caseObject: the measurement sent, or, for one that came
// otherwise (a loaded case, the machine error, an undo step), what it is and the box's text.
function inUseAfter(state, caseObject) {
  if (!caseObject.measured && !caseObject.measuredPoints) return null;
  if (state.measuredAttempt) {
    const { before, box, ...source } = state.measuredAttempt;
    return { ...source, meta: source.meta || {} };
  }
  if (state.measuredSource) return state.measuredSource;
  return caseObject.measured
    ? { name: 'the measured grid', what: `${caseObject.measured.length} × ${(caseObject.measured[0] || []).length} values`, meta: {}, text: state.measuredText }
    : { name: 'the measured points', what: `${caseObject.measuredPoints.length} points`, meta: {}, text: state.measuredText };
}

// Keeps the state above from the store's events. Mounted by views/measured.js, among its views: its
// listeners run in the page's order (after the status line's, so that a refused file's status
// stands over "Updated").
export function mountMeasurement(store) {
  // The calculator refused the measurement just sent (its points, or its grid: say, a value
  // beyond 10 mm): the inputs before are computed again (recompute.js then sets no grid aside).
  store.on('refusal', ({ error, caseObject }) => {
    const attempt = store.state.measuredAttempt;
    if (!attempt || !caseObject) return;
    const field = error.field || '';
    const points = Boolean(caseObject.measuredPoints) && /^measuredPoints/.test(field);
    const grid = Boolean(caseObject.measured) && /^measured(\[|$)/.test(field);
    if (!points && !grid) return;
    // The refusal stays in view (keep) while the inputs before are computed again.
    refusedFile(store, attempt.name, error.message, attempt.box, error, true);
    store.setMeasurement({ measuredAttempt: null });
    store.setInputs(attempt.before, { source: 'measured', force: true });
  });
  // A refused file's note where the refusal is that file's (the calculator's, or the note
  // itself); any other refusal as it comes, never an earlier file's note.
  store.on('refusal', ({ error }) => {
    if (!isMeasuredField(error.field)) return;
    const r = store.state.measuredRefusal;
    store.setMeasurement({ measuredMessage: r && (r.error === error || r.note === error.message) ? r.note : error.message });
  });
  // An undo step puts its grid into the box, if it has another grid than the one before.
  store.on('restore', ({ before }, state) => {
    if (JSON.stringify(state.measured) === JSON.stringify(before.measured)) return;
    store.setMeasurement({ measuredSource: null, measuredMessage: null });  // named again by the result
    store.setMeasuredText(state.measured ? measuredText(state.measured) : '', 'restore');
  });
  store.on('result', ({ caseObject }, state) => {
    const measuring = Boolean(caseObject.measured || caseObject.measuredPoints);
    const r = state.measuredRefusal;
    const patch = { measuredSource: inUseAfter(state, caseObject), measuredAttempt: null };
    if (r && r.keep) patch.measuredRefusal = { ...r, keep: false };
    else if (measuring) Object.assign(patch, { measuredRefusal: null, measuredMessage: null });
    store.setMeasurement(patch);
    // A refused file: the status says so over the "Updated" of the measurement in use computed again.
    const after = state.measuredRefusal;
    if (after && after.status) {
      store.setStatus(after.status, 'error');
      store.setMeasurement({ measuredRefusal: { ...after, status: null } });
    }
  });
}
