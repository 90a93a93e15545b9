// The grinding passes (web/src/pass-history.js): "Use as next run", the case that gives a kept
// pass's figures, and the table's rows and the plot's series, measured and predicted per pass.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { STOP_WHY, historyRows, historySeries, nextRunInputs, passCase, predictedRmsText, resultFigures, resultIsCurrent } from '../../web/src/pass-history.js';
import { caseOf, initialState } from '../../web/src/store.js';

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const nominal = { X: [22.4, 139.5, 0, 0, 0], Y: [39.3, 0, 0, 0, 0], Z: [-116.4, 0, 0, 0, 0], A: [0, 1, 0, 0, 0], B: [0.22, 0, 0, 0, 0] };
const proposed = { ...nominal, Y: [39.29, 0, 0, 0, 0] };
const topography = { sse: 1e-9, max: 2e-5, thickness: -1e-5 };
const correction = { axes: proposed, sseBefore: 120, maxBefore: 6, thicknessBefore: 4.5, sseAfter: 0.02, maxAfter: 0.1, thicknessAfter: -0.01 };

// A state whose result is of its own inputs, as after a calculation.
function computed(patch, result = { axes: nominal, topography, correction }) {
  const state = Object.assign(initialState(), { form: structuredClone(paper) }, patch);
  return Object.assign(state, { result, resultCase: caseOf(state) });
}

test('"Use as next run" keeps the pass under way and runs the proposed axes, with no measured grid yet', () => {
  const measured = [[1, 2], [3, 4]];
  const first = computed({ measured });
  const { inputs } = nextRunInputs(first);
  const options = { lockedAxes: [], locked: [] };  // the correction's options in use: none beyond the defaults
  assert.deepEqual(inputs.passes, [{ axes: nominal, measured, correction: options }], 'the nominal axes ran in the first pass');
  assert.deepEqual(inputs.axes, proposed);
  assert.equal(inputs.measured, null);
  inputs.passes[0].measured[0][0] = 99;
  assert.equal(measured[0][0], 1, 'the history holds its own copy');
  // The second pass ran the proposed axes; its pass is kept after the first.
  const second = computed({ passes: nextRunInputs(first).inputs.passes, axes: proposed, measured: [[0.1, 0], [0, 0]],
    tuning: { probeNoise: 1, method: 'linear' } },
    { axes: nominal, topography, correction: { ...correction, axes: nominal } });
  const next = nextRunInputs(second).inputs;
  assert.equal(next.passes.length, 2);
  assert.deepEqual(next.passes[1], { axes: proposed, measured: [[0.1, 0], [0, 0]],
    correction: { probeNoise: 1, method: 'linear', lockedAxes: [], locked: [] } }, 'each pass keeps the options of its own correction');
  assert.deepEqual(next.passes[0].correction, options);
  assert.deepEqual(next.axes, nominal);
});

test('"Use as next run" with the measuring machine\'s points: the pass keeps them, the next run has none yet', () => {
  const points = [[19.5, -60, 1.25], [30, 0, -0.5], [38, 60.5, 2]];
  const inspection = { gashDeviations: [1, 2] };
  const first = computed({ extra: { measuredPoints: points, inspection } });
  const { inputs } = nextRunInputs(first);
  assert.deepEqual(inputs.passes, [{ axes: nominal, measuredPoints: points, correction: { lockedAxes: [], locked: [] } }]);
  assert.equal('measured' in inputs.passes[0], false);
  assert.deepEqual(inputs.axes, proposed);
  assert.equal(inputs.measured, null);
  assert.deepEqual(inputs.extra, { inspection }, 'the points leave the pass under way; the rest stays');
  inputs.passes[0].measuredPoints[0][2] = 99;
  assert.equal(points[0][2], 1.25, 'the history holds its own copy');
  // The kept pass's case: its points, not those of the pass under way, and no grid.
  const second = computed({ passes: nextRunInputs(first).inputs.passes, axes: proposed, measured: [[0.1]] , extra: { inspection } });
  const c = passCase(second, second.passes[0]);
  assert.deepEqual(c.measuredPoints, points);
  assert.equal('measured' in c, false);
  assert.deepEqual(c.axes, nominal);
  assert.deepEqual(c.inspection, inspection);
  assert.equal('passes' in c, false, 'the first pass had no history');
  // A later kept pass is computed with the history as it was then: the passes before it.
  const later = { ...second, passes: [...second.passes, { axes: proposed, measured: [[0.1]] }, { axes: nominal, measured: [[0.2]] }] };
  assert.deepEqual(passCase(later, later.passes[1]).passes, [second.passes[0]]);
  assert.deepEqual(passCase(later, later.passes[2]).passes, later.passes.slice(0, 2));
  // A grid pass kept while points are under way: the pass's case has its grid and no points.
  const gridPass = passCase(computed({ extra: { measuredPoints: points } }), { axes: nominal, measured: [[1, 2]] });
  assert.deepEqual(gridPass.measured, [[1, 2]]);
  assert.equal('measuredPoints' in gridPass, false);
});

test('"Use as next run" says why it cannot be done: no grid, an older result, no correction', () => {
  assert.match(nextRunInputs(computed({})).why, /Measure the face first/);
  const stale = computed({ measured: [[1]] });
  stale.measured = [[2]];
  assert.equal(resultIsCurrent(stale), false);
  assert.match(nextRunInputs(stale).why, /Wait for the correction/);
  assert.match(nextRunInputs(computed({ measured: [[1]] }, { axes: nominal, topography })).why, /no correction/);
  assert.match(nextRunInputs(Object.assign(initialState(), { measured: [[1]] })).why, /Wait/);
});

test("a kept pass's case: the form with its axes, its grid and its own correction's options", () => {
  const state = computed({ axes: proposed, measured: [[9]], locked: ['B a2'], tuning: { truncation: 1e-5 } });
  const c = passCase(state, { axes: nominal, measured: [[1, 2]] });
  assert.deepEqual(c.axes, nominal);
  assert.deepEqual(c.measured, [[1, 2]]);
  assert.deepEqual(c.correction, { truncation: 1e-5, lockedAxes: [], locked: ['B a2'] });
  assert.equal(c.hob.gashLead, paper.hob.gashLead);
  assert.equal('passes' in c, false);
  // A pass that kept its options is computed with them, whatever the options now.
  const kept = { probeNoise: 1e-4, method: 'linear', resolution: { B: 0.001 }, lockedAxes: ['A'], locked: [] };
  assert.deepEqual(passCase(state, { axes: nominal, measured: [[1, 2]], correction: kept }).correction, kept);
});

test('figures: measured, predicted next (the rms with its bound) and simulated, the probe noise; nothing that is not finite', () => {
  const f = resultFigures({ topography: { ...topography, rms: 4e-6 },
    correction: { ...correction, maxAfter: NaN, thicknessAfter: Infinity, rmsBefore: 1.6, predictedRms: 0.01, predictedRmsHigh: NaN, probeNoise: 0.5 } });
  assert.deepEqual(f.measured, { rms: 1.6, sse: 120, max: 6, thickness: 4.5 });
  assert.deepEqual(f.next, { rms: 0.01, rmsHigh: null, sse: 0.02, max: null, thickness: null });
  // With a measurement, the face simulated for the axes run at its points, read as it is
  // (correction.*Simulated: here a thickness interpolated at the grid's centre), not the topography's.
  assert.deepEqual(f.simulated, { rms: null, sse: null, max: null, thickness: null });
  const read = resultFigures({ topography: { ...topography, rms: 4e-6 },
    correction: { ...correction, rmsSimulated: 5e-6, sseSimulated: 2e-9, maxSimulated: 3e-5, thicknessSimulated: -2e-5 } });
  assert.deepEqual(read.simulated, { rms: 5e-6, sse: 2e-9, max: 3e-5, thickness: -2e-5 });
  // Before a measurement: the topography.
  assert.deepEqual(resultFigures({ topography: { ...topography, rms: 4e-6 } }).simulated, { rms: 4e-6, sse: 1e-9, max: 2e-5, thickness: -1e-5 });
  assert.equal(f.sigma, 0.5);
  assert.equal(f.stop, false);
  assert.deepEqual(resultFigures({ topography }).measured, null);
  assert.equal(resultFigures({ topography }).sigma, null);
  assert.equal(resultFigures({ topography, correction: { ...correction, stop: true } }).stop, true);
  // Faces that moved against the change of the axes (correction.signReversed): no prediction stands.
  const reversed = resultFigures({ topography, correction: { ...correction, predictedRms: 0.01, predictedRmsHigh: 0.2, signReversed: true } });
  assert.equal(reversed.signReversed, true);
  assert.deepEqual(reversed.next, { rms: null, rmsHigh: null, sse: null, max: null, thickness: null });
  assert.equal(f.signReversed, false);
});

test('a first pass whose axes alone grind no face the wheel envelops is not predicted, and says why', () => {
  const lost = resultFigures({ topography, correction: { ...correction, rmsBefore: 40, linearisedAtNominal: true } });
  const rows = historyRows([], lost);
  assert.equal(rows[0].predicted, null, 'not the nominal axes\' face as the run\'s');
  assert.equal(rows[0].note, 'the axes run alone grind no face the wheel envelops: not predicted');
  assert.equal(historyRows([lost], lost)[0].note, 'the axes run alone grind no face the wheel envelops: not predicted');
});

test('a sum of squares predicted over other values than the measurement is not compared; the rms is', () => {
  const grid = Array.from({ length: 5 }, () => Array(9).fill(0.1));
  const points = Array.from({ length: 2000 }, () => [30, 0, 0.1]);
  const onGrid = resultFigures({ topography, correction: { ...correction, rmsBefore: 9, predictedRms: 0.2, residual: grid } });
  const atPoints = resultFigures({ topography, correction: { ...correction, rmsBefore: 0.3, residual: grid, pointMeasured: points } });
  assert.equal(onGrid.points, 45);
  assert.equal(atPoints.points, 2000, 'the points, not the grid the maps show');
  const rows = historyRows([onGrid], atPoints);
  assert.equal(rows[1].predicted.sse, null, 'predicted over the 45 grid values, measured over 2000 points');
  assert.equal(rows[1].predicted.rms, 0.2, 'the rms is compared');
  assert.equal(rows[1].note, 'sum of squares predicted over 45 values, measured over 2000: not compared');
  assert.equal(historySeries(rows).sse.predicted.x.includes(2), false, 'nor drawn');
  // The same grid twice: compared, no note.
  const again = historyRows([onGrid], onGrid);
  assert.equal(again[1].predicted.sse, onGrid.next.sse);
  assert.equal(again[1].note, '');
});

test('stop: the face measured is within the probe noise; no next pass is predicted or offered, and the row says why', () => {
  const stopped = { ...correction, stop: true, probeNoise: 0.5, rmsBefore: 0.11, predictedRms: 0, predictedRmsHigh: 0.29 };
  const state = computed({ measured: [[0.1]] }, { axes: nominal, topography, correction: stopped });
  assert.deepEqual(nextRunInputs(state), { why: STOP_WHY });
  assert.match(STOP_WHY, /^Stop: .*probe noise.*Keep the axes run\.$/);
  const current = resultFigures(state.result);
  const kept = resultFigures({ topography, correction: { ...correction, rmsBefore: 9.7, predictedRms: 0, predictedRmsHigh: 0.29, probeNoise: 0.5 } });
  const rows = historyRows([kept], current);
  assert.deepEqual(rows.map((r) => r.label), ['1', '2 (under way)'], 'no next row');
  assert.deepEqual(rows.map((r) => r.note), ['', 'within the probe noise: stop']);
  assert.deepEqual(rows[1].predicted, kept.next, 'pass 2 as pass 1\'s correction predicted it, with its bound');
  assert.deepEqual(rows.map((r) => r.sigma), [0.5, 0.5]);
  // The same figures not stopped: the next pass predicted.
  assert.equal(historyRows([kept], { ...current, stop: false }).length, 3);
});

test('rows: each pass predicted by the correction of the pass before, the first by its simulated face', () => {
  const fig = (s) => ({ measured: { sse: s, max: 1, thickness: 0.5 }, next: { sse: s / 100, max: 0.1, thickness: 0 }, simulated: { sse: 0, max: 0, thickness: 0 } });
  const rows = historyRows([fig(1e4), fig(50)], fig(3));
  assert.deepEqual(rows.map((r) => r.label), ['1', '2', '3 (under way)', '4 (next, predicted)']);
  assert.deepEqual(rows.map((r) => r.measured && r.measured.sse), [1e4, 50, 3, null]);
  assert.deepEqual(rows.map((r) => r.predicted.sse), [0, 100, 0.5, 0.03]);
  // A pass still computed, or refused, shows so; the one after has no prediction then.
  const odd = historyRows([null, { error: 'not computed: passes[0].measured needs 5 rows' }], { measured: null, next: null, simulated: fig(1).simulated });
  assert.deepEqual(odd.map((r) => r.note), ['computing…', 'not computed: passes[0].measured needs 5 rows', 'not measured yet']);
  assert.deepEqual(odd.map((r) => r.predicted), [null, null, null]);
  assert.equal(odd.length, 3, 'no next row without a correction');
  // No pass kept: the pass under way is the first, predicted by its simulated face.
  assert.deepEqual(historyRows([], fig(7))[0].predicted, fig(7).simulated);
});

test('series: per quantity the passes with a value, measured and predicted apart; the rms\'s bounds; the noise floor', () => {
  const rows = [
    { pass: 1, measured: { rms: 1.5, sse: 100, max: 5, thickness: null }, predicted: { rms: 0, sse: 0, max: 0, thickness: 0 }, sigma: 0.5 },
    { pass: 2, measured: null, predicted: { rms: 0.01, rmsHigh: 0.3, sse: 0.5, max: null, thickness: 0.1 }, sigma: null },
    { pass: 3, measured: null, predicted: { rms: null, rmsHigh: 0.2, sse: 0.1, max: 0, thickness: 0 }, sigma: 0.25 },
  ];
  const s = historySeries(rows);
  assert.deepEqual(s.sse, { measured: { x: [1], y: [100] }, predicted: { x: [1, 2, 3], y: [0, 0.5, 0.1] } });
  assert.deepEqual(s.max.predicted, { x: [1, 3], y: [0, 0] });
  assert.deepEqual(s.thickness.measured, { x: [], y: [] });
  assert.deepEqual(s.rms, { measured: { x: [1], y: [1.5] }, predicted: { x: [1, 2], y: [0, 0.01], high: [null, 0.3] } });
  assert.deepEqual(s.floor, { x: [1, 3], y: [0.5, 0.25] }, 'the probe noise of the passes that have one');
  for (const [q, v] of Object.entries(s)) {
    if (q === 'floor') { assert.ok(v.y.every(Number.isFinite)); continue; }
    for (const set of Object.values(v)) assert.ok(set.y.every(Number.isFinite));
  }
});

test('the rms predicted in the table: the bound first, the identified machine\'s figure with its condition, a 0 in words', () => {
  assert.equal(predictedRmsText({ rms: 0.012, rmsHigh: 0.446 }), 'at most 0.446 (on the identified machine: 0.012)');
  // The noise taken out clips the figure to 0: said in words, not as a certain-looking 0 (a review found "0").
  assert.equal(predictedRmsText({ rms: 0, rmsHigh: 0.00575 }), 'at most 0.00575 (on the identified machine: within the probe noise)');
  assert.equal(predictedRmsText({ rms: 3e-11, rmsHigh: 2e-4 }), 'at most 0.001 (on the identified machine: below 0.001)');
  assert.equal(predictedRmsText({ rms: 1.23456, rmsHigh: null }), '1.235');
  assert.equal(predictedRmsText({ rms: null, rmsHigh: 0.4 }), '—');
});
