// Differences to a pinned result (web/src/pin-diff.js): now minus pinned, and null wherever the
// two cannot be compared.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { axesDifference, changedInputs, figuresDifference, gridDifference, profileDifference } from '../../web/src/pin-diff.js';
import { setModuleLimits } from '../../web/src/limits.js';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';

setModuleLimits((await loadHobSharp()).limits());  // the axes, as the page has them once its calculator is ready

const result = (unit, r = [19, 40], x = [-70, 0, 70]) => ({ setup: { motionUnit: unit }, topography: { r, x } });
const axes = (y) => ({ X: [1, 2], Y: [y, 0], Z: [0, 0], A: [0, 1], B: [0.2, 0] });

test('axis coefficients: now minus pinned; another degree or motion parameter is not comparable', () => {
  const d = axesDifference(axes(39.5), axes(39.25), result('rad'), result('rad'));
  assert.deepEqual(d.Y, [0.25, 0]);
  assert.deepEqual(d.X, [0, 0]);
  assert.equal(axesDifference(axes(1), axes(1), result('mm'), result('rad')), null);
  assert.equal(axesDifference(axes(1), { ...axes(1), X: [1, 2, 3] }, result('rad'), result('rad')), null);
  assert.equal(axesDifference(undefined, axes(1), result('rad'), result('rad')), null, 'no correction on one side');
});

test('grids: point by point, or null for another grid', () => {
  const now = [[1, 2, 3], [4, 5, 6]], then = [[1, 1, 1], [0, 0, 6]];
  assert.deepEqual(gridDifference(now, then, result('rad'), result('rad')), [[0, 1, 2], [4, 5, 0]]);
  assert.equal(gridDifference(now, then, result('rad'), result('rad', [19, 39])), null, 'other radii');
  assert.equal(gridDifference(now, then, result('rad'), result('rad', [19, 40], [-70, 0, 71])), null, 'other axial positions');
  assert.equal(gridDifference(now, [[1, 2, 3]], result('rad'), result('rad')), null, 'other shape');
  assert.equal(gridDifference(now, null, result('rad'), result('rad')), null);
});

test('wheel profiles: at the same tooth-face radius, in µm, with the largest of each', () => {
  const pinned = { r: [20, 30, 40], R: [50, 45, 40], Z: [0, 1, 2] };
  const now = { r: [20, 25, 40, 45], R: [50.001, 47.5, 39.998, 38], Z: [0, 0.5, 2.0005, 3] };
  const d = profileDifference(now, pinned);
  assert.ok(Math.abs(d.dR[0] - 1) < 1e-9);
  assert.ok(Math.abs(d.dR[1]) < 1e-9, 'between points, along the straight line');
  assert.ok(Math.abs(d.dR[2] + 2) < 1e-9);
  assert.equal(d.dR[3], null, 'outside the pinned profile');
  assert.equal(d.maxR.r, 40);
  assert.ok(Math.abs(d.maxR.value + 2) < 1e-9);
  assert.ok(Math.abs(d.maxZ.value - 0.5) < 1e-9);
  // Radii that run tip to root are read as well.
  const reversed = { r: [40, 30, 20], R: [40, 45, 50], Z: [2, 1, 0] };
  assert.ok(Math.abs(profileDifference(now, reversed).dR[0] - 1) < 1e-9);
  assert.equal(profileDifference({ r: [50, 60], R: [1, 1], Z: [0, 0] }, pinned), null, 'no radius in common');
});

test('figures: by name, null where the pinned result has none', () => {
  assert.deepEqual(figuresDifference({ sse: 180, max: 2, thickness: undefined }, { sse: 45, max: 1, thickness: 1 }),
    { sse: 135, max: 1, thickness: null });
});

test('changed inputs: the form by path, a grid, run axes or locks as a whole', () => {
  const pinned = { hob: { hand: 'right' }, setup: { tilt: 15 }, measured: [[1]] };
  const now = { hob: { hand: 'left' }, setup: { tilt: 15, settingAngle: 12 }, measured: [[2]], axes: { X: [1] } };
  assert.deepEqual(changedInputs(now, pinned), [
    { path: 'hob.hand', from: 'right', to: 'left' },
    { path: 'setup.settingAngle', from: undefined, to: 12 },
    { path: 'measured', from: [[1]], to: [[2]] },
    { path: 'axes', from: undefined, to: { X: [1] } },
  ]);
  assert.deepEqual(changedInputs(pinned, structuredClone(pinned)), []);
});
