// The grinding passes (pure, with Node tests). A pass is the axes the machine ran, the face
// measured after it (a grid, `measured`, or the measuring machine's points, `measuredPoints`), and
// the options its correction was computed with. The history keeps the passes done (state.passes,
// oldest first); the pass under way is the run axes (state.axes, or the nominal axes) with the
// measured grid or points (state.extra.measuredPoints), once there are some.
// "Use as next run" keeps the pass under way and makes the proposed axes the run of the next.
//
// Per pass the page shows, measured and predicted, the sum of squares (µm²), the largest
// |deviation| (µm) and the thickness error (µm). The measured figures are the correction's
// "before"; the prediction for a pass is what the previous pass's correction predicted (its
// "after"), and for the first pass the face simulated for its axes, with no machine error known.
import { caseOf } from './store.js';

const finiteOr = (v) => (typeof v === 'number' && Number.isFinite(v) ? v : null);
const figures = (sse, max, thickness) => ({ sse: finiteOr(sse), max: finiteOr(max), thickness: finiteOr(thickness) });

// A result's figures: the face measured, the one predicted after its correction, and the one
// simulated for the axes run. A number that is not finite becomes null (shown as a dash).
export function resultFigures(result) {
  const c = result.correction, t = result.topography;
  return {
    measured: c ? figures(c.sseBefore, c.maxBefore, c.thicknessBefore) : null,
    next: c ? figures(c.sseAfter, c.maxAfter, c.thicknessAfter) : null,
    simulated: figures(t.sse, t.max, t.thickness),
  };
}

// Whether the result on screen is of the inputs now (not one for older inputs, still shown).
export function resultIsCurrent(state) {
  return Boolean(state.result && state.resultCase) && JSON.stringify(state.resultCase) === JSON.stringify(caseOf(state));
}

// The inputs after "Use as next run", or a sentence saying why it cannot be done now.
export function nextRunInputs(state) {
  const { measuredPoints, ...extra } = state.extra || {};
  if (!state.measured && !measuredPoints) return { why: 'Measure the face first: paste or generate a measured grid, or load measured points.' };
  if (!resultIsCurrent(state)) return { why: 'Wait for the correction of the measurement now in use.' };
  const c = state.result.correction;
  if (!c || !c.axes) return { why: 'There is no correction to run.' };
  const measurement = state.measured ? { measured: structuredClone(state.measured) } : { measuredPoints: structuredClone(measuredPoints) };
  const pass = { axes: structuredClone(state.axes || state.result.axes), ...measurement,
    correction: structuredClone(caseOf(state).correction) };
  return { inputs: { passes: [...state.passes, pass], axes: structuredClone(c.axes), measured: null, extra } };
}

// The case that gives a kept pass's figures: the form, with the pass's axes and grid, and the
// correction's options the pass kept (a pass from an older case without them: those in use now).
export function passCase(state, pass) {
  const { measuredPoints, ...extra } = state.extra || {};
  const c = caseOf({ ...state, axes: pass.axes, measured: pass.measured || null,
    extra: pass.measuredPoints ? { ...extra, measuredPoints: pass.measuredPoints } : extra });
  if (pass.correction) c.correction = structuredClone(pass.correction);
  return c;
}

// The rows of the history table and plot. kept: per kept pass, its figures (resultFigures of its
// passCase), or {error} (the message), or null while computed; current: resultFigures of the
// result now. Rows: the passes kept, the pass under way, then the next pass when the correction
// predicts it. Each row: {pass (1, 2, ...), label, measured, predicted, note}.
export function historyRows(kept, current) {
  const rows = [];
  let previous = null;  // the figures of the pass before
  const predictionFor = (k) => (k === 0 ? null : previous && previous.next);
  kept.forEach((f, k) => {
    const note = f === null ? 'computing…' : f.error ? f.error : '';
    const ok = f && !f.error ? f : null;
    rows.push({ pass: k + 1, label: `${k + 1}`, measured: ok && ok.measured,
      predicted: k === 0 ? ok && ok.simulated : predictionFor(k), note });
    previous = ok;
  });
  const k = kept.length;
  if (current) {
    rows.push({ pass: k + 1, label: `${k + 1} (under way)`, measured: current.measured,
      predicted: k === 0 ? current.simulated : predictionFor(k), note: current.measured ? '' : 'not measured yet' });
    if (current.next) rows.push({ pass: k + 2, label: `${k + 2} (next, predicted)`, measured: null, predicted: current.next, note: '' });
  }
  return rows;
}

// The plot's series: per quantity, the passes and the measured and predicted values (nulls left
// out, so that nothing that is not finite reaches the plot).
export function historySeries(rows) {
  const out = {};
  for (const q of ['sse', 'max', 'thickness']) {
    const pick = (set) => rows.filter((r) => r[set] && r[set][q] !== null).map((r) => [r.pass, r[set][q]]);
    const measured = pick('measured'), predicted = pick('predicted');
    out[q] = {
      measured: { x: measured.map((p) => p[0]), y: measured.map((p) => p[1]) },
      predicted: { x: predicted.map((p) => p[0]), y: predicted.map((p) => p[1]) },
    };
  }
  return out;
}
