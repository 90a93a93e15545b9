// The grinding passes (pure, with Node tests). A pass is the axes the machine ran, the face
// measured after it (a grid, `measured`, or the measuring machine's points, `measuredPoints`), and
// the options its correction was computed with. The history keeps the passes done (state.passes,
// oldest first); the pass under way is the run axes (state.axes, or the nominal axes) with the
// measured grid or points (state.extra.measuredPoints), once there are some.
// "Use as next run" keeps the pass under way and makes the proposed axes the run of the next.
//
// Per pass the page shows, measured and predicted, the rms (µm), the sum of squares (µm²), the
// largest |deviation| (µm) and the thickness error (µm). The measured figures are the correction's
// "before"; the prediction for a pass is what the previous pass's correction predicted (its
// "after"; for the rms, correction.predictedRms with its bound correction.predictedRmsHigh), and
// for the first pass the face simulated for its axes, with no machine error known, at the
// measurement's points and its thickness read as the measurement's is. A predicted sum of squares
// over another number of values than the measurement's is left out (the note says so). Beside them,
// per pass, the probe noise its correction assumed (correction.probeNoise, sigma, µm rms): what
// noise alone measures. The stop (correction.stop) takes the same chi-square test as the
// identification's status, up to 3 of its standard deviations above n sigma² (1.28 sigma in rms
// on 45 points), so a face a little above the drawn floor may be told to stop, unless a shape the
// axes make stands out of the noise in it (docs/method.md). When the correction says stop (the face
// measured is within the probe noise), no next pass is predicted or offered.
import { LEAST_RMS, faceFigure } from './format.js';
import { caseOf } from './store.js';
import { changesNothing } from '../../wasm/lib/pass-bound.js';

const finiteOr = (v) => (typeof v === 'number' && Number.isFinite(v) ? v : null);
const figures = (rms, sse, max, thickness) => ({ rms: finiteOr(rms), sse: finiteOr(sse), max: finiteOr(max), thickness: finiteOr(thickness) });

// Why no next pass is offered when the correction says stop.
export const STOP_WHY = 'Stop: the face measured is within the probe noise; another pass would only move noise. Keep the axes run.';
// Why the next pass has no prediction when the faces moved against the change of the axes.
export const SIGN_WHY = 'nothing predicted: the faces measured moved against the change of the axes; check the measuring machine\'s sign';
export const NO_CHANGE_WHY = 'No change proposed: another pass with the axes run grinds the same face (the verdict says why). Keep the axes run.';

// A result's figures: the face measured, the one predicted after its correction (with the rms's
// bound, rmsHigh), and the one simulated for the axes run (with a measurement, at its points and
// read as it is: correction.*Simulated; before one, the topography); the probe noise the correction assumed
// (sigma) and whether it says stop. A number that is not finite becomes null (shown as a dash).
// The rms predicted, in the table's words: its bound, what the pass leaves, and the identified
// machine's figure below it with that condition, "at most 0.446 (on the identified machine:
// 0.012)"; a figure the noise takes to 0 (correction.predictedRms: the misfit less the noise,
// clipped) is said in words, not as a certain-looking 0. Without a bound, the figure alone.
export function predictedRmsText(f) {
  if (f.rms === null || typeof f.rmsHigh !== 'number') return faceFigure(f.rms, LEAST_RMS, 4);
  const model = f.rms === 0 ? 'within the probe noise' : faceFigure(f.rms, LEAST_RMS);
  return `at most ${faceFigure(Math.max(f.rmsHigh, LEAST_RMS), LEAST_RMS)} (on the identified machine: ${model})`;  // "at most 0.001", not "at most below 0.001"
}

export function resultFigures(result) {
  const c = result.correction, t = result.topography;
  return {
    measured: c ? figures(c.rmsBefore, c.sseBefore, c.maxBefore, c.thicknessBefore) : null,
    // No prediction stands while the faces moved against the change of the axes (correction.signReversed).
    next: !c ? null : c.signReversed === true ? { ...figures(null, null, null, null), rmsHigh: null }
      : { ...figures(c.predictedRms, c.sseAfter, c.maxAfter, c.thicknessAfter), rmsHigh: finiteOr(c.predictedRmsHigh) },
    simulated: c ? figures(c.rmsSimulated, c.sseSimulated, c.maxSimulated, c.thicknessSimulated) : figures(t.rms, t.sse, t.max, t.thickness),
    unsimulated: Boolean(c) && c.linearisedAtNominal === true,
    sigma: c ? finiteOr(c.probeNoise) : null,
    stop: Boolean(c) && c.stop === true,
    signReversed: Boolean(c) && c.signReversed === true,
    points: c ? pointCount(c) : null,
  };
}

// How many values the correction's figures are over: the measured points, or the grid's nodes.
function pointCount(c) {
  if (Array.isArray(c.pointMeasured)) return c.pointMeasured.length;
  if (Array.isArray(c.residual) && Array.isArray(c.residual[0])) return c.residual.length * c.residual[0].length;
  return null;
}

// A sum of squares grows with the number of values: a prediction over another set of points than
// the measurement's (a pass measured on the grid, the next at points) is not compared (the rms is).
function comparable(predicted, from, measuredOver) {
  if (!predicted || !from || from.points === null || measuredOver === null || from.points === measuredOver) return { predicted, note: '' };
  return { predicted: { ...predicted, sse: null },
    note: `sum of squares predicted over ${from.points} values, measured over ${measuredOver}: not compared` };
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
  if (c.stop === true) return { why: STOP_WHY };
  if (changesNothing(c)) return { why: NO_CHANGE_WHY };
  const measurement = state.measured ? { measured: structuredClone(state.measured) } : { measuredPoints: structuredClone(measuredPoints) };
  const pass = { axes: structuredClone(state.axes || state.result.axes), ...measurement,
    correction: structuredClone(caseOf(state).correction) };
  return { inputs: { passes: [...state.passes, pass], axes: structuredClone(c.axes), measured: null, extra } };
}

// The case that gives a kept pass's figures: the form, with the pass's axes and grid, the
// correction's options the pass kept (a pass from an older case without them: those in use now),
// and the history as it was then: the passes before it.
export function passCase(state, pass) {
  const { measuredPoints, ...extra } = state.extra || {};
  const at = state.passes.indexOf(pass);
  const c = caseOf({ ...state, axes: pass.axes, measured: pass.measured || null, passes: at < 0 ? state.passes : state.passes.slice(0, at),
    extra: pass.measuredPoints ? { ...extra, measuredPoints: pass.measuredPoints } : extra });
  if (pass.correction) c.correction = structuredClone(pass.correction);
  return c;
}

const WITHIN_NOISE = 'within the probe noise: stop';
// A first pass whose axes alone grind no face the wheel envelops (correction.linearisedAtNominal):
// nothing to predict it by.
const UNSIMULATED = 'the axes run alone grind no face the wheel envelops: not predicted';

// A first pass's prediction: the face simulated for its axes, or why there is none.
const first = (f) => (f && f.unsimulated ? { predicted: null, note: UNSIMULATED } : { predicted: f && f.simulated, note: '' });

// The rows of the history table and plot. kept: per kept pass, its figures (resultFigures of its
// passCase), or {error} (the message), or null while computed; current: resultFigures of the
// result now. Rows: the passes kept, the pass under way, then the next pass when the correction
// predicts one (not when it says stop). Each row: {pass (1, 2, ...), label, measured, predicted,
// sigma (the probe noise its correction assumed, µm, or null), note}.
export function historyRows(kept, current) {
  const rows = [];
  let previous = null;  // the figures of the pass before
  const predictionFor = (k) => (k === 0 ? null : previous && previous.next);
  const join = (...notes) => notes.filter(Boolean).join('; ');
  kept.forEach((f, k) => {
    const ok = f && !f.error ? f : null;
    const note = f === null ? 'computing…' : f.error ? f.error : ok.stop ? WITHIN_NOISE : '';
    const p = k === 0 ? first(ok) : comparable(predictionFor(k), previous, ok ? ok.points : null);
    rows.push({ pass: k + 1, label: `${k + 1}`, measured: ok && ok.measured,
      predicted: p.predicted, sigma: ok ? ok.sigma : null, note: join(note, p.note) });
    previous = ok;
  });
  const k = kept.length;
  if (current) {
    const note = !current.measured ? 'not measured yet' : current.stop ? WITHIN_NOISE : '';
    const p = k === 0 ? first(current) : comparable(predictionFor(k), previous, current.measured ? current.points : null);
    rows.push({ pass: k + 1, label: `${k + 1} (under way)`, measured: current.measured,
      predicted: p.predicted, sigma: current.sigma, note: join(note, p.note) });
    if (current.next && !current.stop) {
      rows.push({ pass: k + 2, label: `${k + 2} (next, predicted)`, measured: null, predicted: current.next, sigma: current.sigma,
        note: current.signReversed ? SIGN_WHY : '' });
    }
  }
  return rows;
}

// The plot's series: per quantity, the passes and the measured and predicted values (nulls left
// out, so that nothing that is not finite reaches the plot); for the rms, the predicted values'
// bounds (high: a number, or null where there is none); and the probe noise's floor, per pass
// whose correction assumed one (floor: {x, y}, µm rms).
export function historySeries(rows) {
  const out = {};
  for (const q of ['rms', 'sse', 'max', 'thickness']) {
    const pick = (set) => rows.filter((r) => r[set] && r[set][q] !== null).map((r) => [r.pass, r[set][q], r[set]]);
    const measured = pick('measured'), predicted = pick('predicted');
    out[q] = {
      measured: { x: measured.map((p) => p[0]), y: measured.map((p) => p[1]) },
      predicted: { x: predicted.map((p) => p[0]), y: predicted.map((p) => p[1]) },
    };
    if (q === 'rms') out[q].predicted.high = predicted.map((p) => finiteOr(p[2].rmsHigh));
  }
  const floor = rows.filter((r) => finiteOr(r.sigma) !== null && r.sigma > 0);
  out.floor = { x: floor.map((r) => r.pass), y: floor.map((r) => r.sigma) };
  return out;
}
