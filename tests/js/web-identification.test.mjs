// What the engineer reads of the machine error's identification (web/src/identification.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { axisUnit, errorRows, precisionTable, roundedFigures, statusText } from '../../web/src/identification.js';

const AXES = ['X', 'Y', 'Z', 'A', 'B'];

test('per axis: identified error, its uncertainty and the change, µm for X, Y, Z and µrad for A, B', () => {
  const c = {
    identifiedError: { X: 1.5, Y: -2, Z: 0, A: 12, B: NaN },
    uncertainty: { X: 0.1, Y: 0.2, Z: 0.3, A: 4 },
    axisChange: { X: -1.5, Y: 2, Z: 0, A: -12, B: 0 },
  };
  const rows = errorRows(c, AXES);
  assert.deepEqual(rows.map((r) => r.unit), ['µm', 'µm', 'µm', 'µrad', 'µrad']);
  assert.deepEqual(rows[0], { axis: 'X', unit: 'µm', error: 1.5, uncertainty: 0.1, change: -1.5 });
  assert.equal(rows[4].error, null, 'NaN never reaches the table');
  assert.equal(rows[4].uncertainty, null);
  assert.deepEqual(errorRows({ sseAfter: 1 }, AXES), [], 'no rows without the fields');
  assert.equal(axisUnit('B'), 'µrad');
});

test('the precision demand, given per axis or per quantity, with words and units', () => {
  const perAxis = Object.fromEntries(AXES.map((a, i) => [a, { facePerError: i + 1, changePerNoise: 10 * (i + 1) }]));
  const t = precisionTable(perAxis, AXES);
  assert.deepEqual(t.columns.map((q) => q.label), ['face per unit of axis error, largest over the grid', 'axis change per µm of probe noise']);
  assert.deepEqual(t.columns.map((q) => q.unit('X')), ['µm/µm', 'µm/µm']);
  assert.deepEqual(t.columns.map((q) => q.unit('A')), ['µm/µrad', 'µrad/µm']);
  assert.deepEqual(t.rows[3], { axis: 'A', values: [4, 40] });
  const perQuantity = { facePerError: { X: 1, Y: 2, Z: 3, A: 4, B: Infinity }, changePerNoise: { X: 10, Y: 20, Z: 30, A: 40, B: 50 } };
  const u = precisionTable(perQuantity, AXES);
  assert.deepEqual(u.rows.map((r) => r.values), [[1, 10], [2, 20], [3, 30], [4, 40], [null, 50]]);
  assert.equal(precisionTable(undefined, AXES), null);
  assert.equal(precisionTable({}, AXES), null);
});

test('the status, its reason, the iterations and the method in words', () => {
  assert.equal(statusText({ status: 'converged', iterations: 4, method: 'nonlinear', statusReason: 'the step fell below its tolerance', usable: true }),
    'Solver (nonlinear identification): converged, 4 iterations. The step fell below its tolerance.');
  assert.equal(statusText({ status: 'notConverged', iterations: 1, method: 'linear' }),
    'Solver (one linear step (Eq. 17)): not converged (the iterations ran out), 1 iteration.');
  assert.equal(statusText({ status: { code: 'stalled', reason: 'no lower sum of squares' }, iterations: NaN }),
    'Solver: stalled. No lower sum of squares.');
  assert.match(statusText({ status: 'failed', usable: false }), /failed\. The proposal is not usable: do not run it\.$/);
  assert.equal(statusText({}), '');
});

test('the rounded axes: their predicted face beside the exact proposal\'s, nothing that is not finite', () => {
  const c = { roundedAxes: { X: [1] }, sseRounded: 0.02, maxRounded: 0.1, thicknessRounded: NaN, sseAfter: 1e-5, maxAfter: 0.002, thicknessAfter: 0 };
  assert.deepEqual(roundedFigures(c), { rounded: { sse: 0.02, max: 0.1, thickness: null }, exact: { sse: 1e-5, max: 0.002, thickness: 0 } });
  assert.equal(roundedFigures({ sseRounded: 1 }), null);
});
