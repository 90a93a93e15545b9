// The passes' plot (web/src/plots/pass-history.js) on a scale that means something (issue 22):
// the rms in µm on a log axis that stops at a tenth of the probe noise, never below 0.01 µm, so
// that a solver's 1e-20 does not stretch it over eighteen decades; a figure below the axis is
// drawn on its floor as a downward triangle, its own value in the hover; the noise floor drawn.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { LEAST_RMS_SHOWN, drawPassHistory, rmsAxisFloor } from '../../web/src/plots/pass-history.js';

// A Plotly that keeps what it is given.
const fake = () => { const got = {}; return { got, react: (el, traces, layout) => Object.assign(got, { traces, layout }) }; };
const series = (measured, predicted, high, sigma) => ({
  rms: { measured: { x: measured.map((_, i) => i + 1), y: measured }, predicted: { x: predicted.map((_, i) => i + 2), y: predicted, high } },
  sse: { measured: { x: [1], y: [4146] }, predicted: { x: [2], y: [1e-20] } },
  max: { measured: { x: [1], y: [9.7] }, predicted: { x: [2], y: [0] } },
  thickness: { measured: { x: [1], y: [9.8] }, predicted: { x: [2], y: [0] } },
  floor: { x: measured.map((_, i) => i + 1), y: measured.map(() => sigma) },
});

test('the rms axis stops at a tenth of the probe noise, at least 0.01 µm', () => {
  assert.equal(LEAST_RMS_SHOWN, 0.01);
  assert.equal(rmsAxisFloor([0.5]), 0.05);
  assert.equal(rmsAxisFloor([0.5, 0.3]), 0.03);
  assert.equal(rmsAxisFloor([1e-4]), 0.01, "a what-if's noise-free sigma does not pull the axis down");
  assert.equal(rmsAxisFloor([]), 0.01);
  assert.equal(rmsAxisFloor([NaN, 0]), 0.01);
});

test('a figure below the axis is drawn on its floor, marked, its value kept in the hover; the sum of squares is linear', () => {
  const P = fake();
  drawPassHistory(P, null, series([9.6], [3.1e-11], [null], 0.5), 2, { rms: 'µm', sse: 'µm²', max: 'µm', thickness: 'µm' });
  const { traces, layout } = P.got;
  assert.equal(layout.yaxis.type, 'log');
  assert.deepEqual(layout.yaxis.range.map((v) => Number(v.toFixed(6))), [Math.log10(0.05), Number((Math.log10(9.6) + 0.15).toFixed(6))].map((v) => Number(v.toFixed(6))));
  const rms = traces.filter((t) => t.xaxis === 'x');
  assert.deepEqual(rms.map((t) => t.name), ['probe noise σ 0.5 µm', 'measured', 'predicted']);
  const predicted = rms[2];
  assert.deepEqual(predicted.y, [0.05], 'drawn on the floor');
  assert.deepEqual(predicted.marker.symbol, ['triangle-down']);
  assert.equal(predicted.customdata[0], "3.1e-11 µm, below the axis's 0.05 µm");
  // With a bound, the point is the bound (what the pass leaves), a bar down to the identified
  // machine's figure as drawn (here the axis's floor), both in the hover.
  const B = fake();
  drawPassHistory(B, null, series([9.6], [3.1e-11], [0.2], 0.5), 2, { rms: 'µm', sse: 'µm²', max: 'µm', thickness: 'µm' });
  const bounded = B.got.traces.filter((t) => t.xaxis === 'x')[2];
  assert.deepEqual(bounded.y, [0.2]);
  assert.deepEqual(bounded.marker.symbol, 'circle-open');
  assert.equal(bounded.customdata[0], 'at most 0.2 µm; 3.1e-11 µm on the identified machine');
  assert.ok(Math.abs(bounded.error_y.arrayminus[0] - 0.15) < 1e-12, 'the bar reaches from the bound down to the floor');
  assert.deepEqual(bounded.error_y.array, [0]);
  assert.deepEqual(rms[1].y, [9.6]);
  assert.equal(rms[1].marker.symbol, 'circle');
  assert.equal(layout.yaxis2.type, 'linear', 'the sum of squares is not on a log scale running to 1e-20');
  assert.equal(layout.yaxis2.range, undefined);
});
