// What the engineer reads of a correction's identification of the machine error (pure, with Node
// tests): per axis what the face tells of its error (read on its own with its standard
// uncertainty, or together with other axes, or not shown at all) and the change proposed; the
// combinations in words; the precision demand; the solver's status and iterations; and the axes as
// the NC program carries them. Units and labels come from the result's field list (resultFields(),
// passed in as unitOf(path) and labelOf(path)); each part is there only when the result has its
// fields; a number that is not finite is null (a dash).
import { fieldLabel } from './result-fields.js';

const num = (v) => (typeof v === 'number' && Number.isFinite(v) ? v : null);
const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const pick = (o, a) => (isObject(o) ? num(o[a]) : null);

// What correction.identifiedAxes.<axis> says, in the page's words for the table.
export const READING_WORDS = {
  alone: 'read on its own',
  together: 'not told apart from other axes (below)',
  unseen: 'not shown by the face',
  locked: 'locked',
};

// The change over the motion range the program runs (correction.axisChangeOverFace) where it
// says more than correction.axisChange (over the range the face measured spans): measured points
// that span less than the grid (the module gives axisChange itself unless the program's is larger
// by more than half a machine step); null where it is not larger by 1 part in 1000, or not given.
function overFace(c, axis) {
  const whole = pick(c.axisChangeOverFace, axis), change = pick(c.axisChange, axis);
  if (whole === null || change === null) return null;
  return Math.abs(whole) - Math.abs(change) > 1e-3 * Math.abs(whole) ? whole : null;
}

// Rows {axis, reading, error, errorUnit, uncertainty, secondOrder, secondOrderLabel, change, changeUnit,
// changeOverFace} for the axes the result names. error, uncertainty and secondOrder (how far the
// error's second order may move it, correction.identifiedAloneSecondOrder, in the module's words:
// secondOrderLabel, labelOf(path), result-fields.js) are the value read on its own
// (correction.identifiedAlone): null unless the face tells that axis from the others. A result
// without identifiedAxes (an older one) has no value read on its own.
export function errorRows(c, axes, unitOf, labelOf = fieldLabel) {
  if (!isObject(c.identifiedAxes) && !isObject(c.axisChange)) return [];
  return axes.map((axis) => {
    const reading = isObject(c.identifiedAxes) && typeof c.identifiedAxes[axis] === 'string' ? c.identifiedAxes[axis] : null;
    const alone = reading === 'alone';
    return {
      axis, reading,
      error: alone ? pick(c.identifiedAlone, axis) : null,
      errorUnit: unitOf(`correction.identifiedAlone.${axis}`),
      uncertainty: alone ? pick(c.identifiedAloneUncertainty, axis) : null,
      secondOrder: alone ? pick(c.identifiedAloneSecondOrder, axis) : null,
      secondOrderLabel: labelOf(`correction.identifiedAloneSecondOrder.${axis}`),
      change: pick(c.axisChange, axis),
      changeUnit: unitOf(`correction.axisChange.${axis}`),
      changeOverFace: overFace(c, axis),
    };
  });
}

// The sentences of correction.identifiedCombinations (strings only).
export function combinationSentences(c) {
  return Array.isArray(c.identifiedCombinations) ? c.identifiedCombinations.filter((s) => typeof s === 'string' && s) : [];
}

// The precision demand as a table {columns: [{key, label, unit(axis)}], rows: [{axis, values}]}:
// correction.precision.facePerError and correction.precision.changePerNoise, each {axis: value},
// labelled as the module labels them (labelOf(path), result-fields.js).
const PRECISION = ['facePerError', 'changePerNoise'];
export function precisionTable(precision, axes, unitOf, labelOf = fieldLabel) {
  if (!isObject(precision)) return null;
  const known = PRECISION.filter((key) => isObject(precision[key]));
  if (!known.length) return null;
  const columns = known.map((key) => ({
    key, label: labelOf(`correction.precision.${key}.${axes[0]}`), unit: (a) => unitOf(`correction.precision.${key}.${a}`),
  }));
  const rows = axes.map((axis) => ({ axis, values: known.map((key) => pick(precision[key], axis)) }));
  return { columns, rows };
}

// The solver's status in words: correction.status ("converged", "aboveNoise", "notConverged", "stalled",
// "failed"; or an object with a code and a reason), correction.statusReason, correction.usable,
// correction.iterations and correction.method.
const STATUS_WORDS = { converged: 'converged', aboveNoise: 'ended above the probe noise', notConverged: 'not converged (the iterations ran out)', stalled: 'stalled', failed: 'failed' };
export function statusText(c) {
  const s = c.status;
  let code = '', why = typeof c.statusReason === 'string' ? c.statusReason : '';
  if (typeof s === 'string') code = STATUS_WORDS[s] || s;
  else if (isObject(s)) {
    code = STATUS_WORDS[s.code] || s.code || '';
    why = why || s.reason || s.message || '';
  }
  const n = num(c.iterations);
  if (!code && !why && n === null) return '';
  const method = c.method === 'linear' ? 'one linear step (Eq. 17)' : c.method === 'nonlinear' ? 'nonlinear identification' : '';
  const parts = [`Solver${method ? ` (${method})` : ''}: ${code || 'status not given'}`];
  if (n !== null) parts.push(`${n} iteration${n === 1 ? '' : 's'}`);
  let text = `${parts.join(', ')}.`;
  if (why) text += ` ${why[0].toUpperCase()}${why.slice(1).replace(/\.?$/, '.')}`;
  if (c.usable === false) text += ' The proposal is not usable: do not run it.';
  return text;
}

// The face predicted with the rounded axes beside the exact proposal's, or null without them.
export function roundedFigures(c) {
  if (!isObject(c.roundedAxes)) return null;
  return {
    rounded: { sse: num(c.sseRounded), max: num(c.maxRounded), thickness: num(c.thicknessRounded) },
    exact: { sse: num(c.sseAfter), max: num(c.maxAfter), thickness: num(c.thicknessAfter) },
  };
}
