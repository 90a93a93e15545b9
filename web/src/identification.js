// What the engineer reads of a correction's identification of the machine error (pure, with Node
// tests): per axis the identified error with its standard uncertainty and the change proposed
// (µm for X, Y, Z; µrad for A, B: the largest over the motion range), the precision demand, the
// solver's status and iterations, and the axes as the NC program carries them. Each part is
// there only when the result has its fields; a number that is not finite is null (a dash).
const LINEAR = ['X', 'Y', 'Z'];
export const axisUnit = (axis) => (LINEAR.includes(axis) ? 'µm' : 'µrad');
const num = (v) => (typeof v === 'number' && Number.isFinite(v) ? v : null);
const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

// Rows {axis, unit, error, uncertainty, change} for the axes the result names.
export function errorRows(c, axes) {
  if (!isObject(c.identifiedError) && !isObject(c.axisChange)) return [];
  const pick = (o, a) => (isObject(o) ? num(o[a]) : null);
  return axes.map((axis) => ({
    axis, unit: axisUnit(axis),
    error: pick(c.identifiedError, axis), uncertainty: pick(c.uncertainty, axis), change: pick(c.axisChange, axis),
  }));
}

// The precision demand as a table {columns: [{key, label, unit(axis)}], rows: [{axis, values}]}.
// correction.precision holds, per axis, the face's µm per µm or µrad of axis error (largest over
// the grid) and the axis change per µm of probe noise: either axis -> {quantity: value} or
// quantity -> {axis: value}. Known quantities get their words and units; others their name.
const QUANTITY_WORDS = [
  [/noise/i, 'axis change per µm of probe noise', (a) => `${axisUnit(a)}/µm`],
  [/face|sensitiv|per.?error|demand/i, 'face per unit of axis error, largest over the grid', (a) => `µm/${axisUnit(a)}`],
];
function quantityOf(key) {
  const known = QUANTITY_WORDS.find(([re]) => re.test(key));
  return known ? { key, label: known[1], unit: known[2] } : { key, label: key, unit: () => '' };
}

export function precisionTable(precision, axes) {
  if (!isObject(precision)) return null;
  const byAxis = axes.some((a) => isObject(precision[a]));
  const perAxis = byAxis ? precision : Object.fromEntries(axes.map((a) => [a, Object.fromEntries(
    Object.entries(precision).filter(([, v]) => isObject(v)).map(([q, v]) => [q, v[a]]))]));
  const keys = [...new Set(axes.flatMap((a) => (isObject(perAxis[a]) ? Object.keys(perAxis[a]) : [])))];
  if (!keys.length) return null;
  const columns = keys.map(quantityOf);
  const rows = axes.map((axis) => ({ axis, values: keys.map((k) => (isObject(perAxis[axis]) ? num(perAxis[axis][k]) : null)) }));
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
