// The bound of the pass proposed (wasm/lib/pass-bound.js): the bound where a pass is proposed,
// null where none is (a stop, a run kept, a proposal not to be used) or the bound is not a number.
import test from 'node:test';
import assert from 'node:assert/strict';
import { changesNothing, floorAboveBound, keepsAxesRun, passBound } from '../../wasm/lib/pass-bound.js';

test('the bound of the pass proposed, and none where no pass is proposed', () => {
  const c = { predictedRmsHigh: 0.446, predictedRms: 0.012 };
  assert.equal(passBound(c), 0.446);
  assert.equal(passBound({ ...c, usable: true, stop: false, runKept: false, signReversed: false }), 0.446);
  for (const none of [{ stop: true }, { runKept: true }, { change: [0, 0] }, { change: [] }, { usable: false }, { signReversed: true }, { predictedRmsHigh: NaN }, { predictedRmsHigh: undefined }]) {
    assert.equal(passBound({ ...c, ...none }), null, JSON.stringify(none));
  }
  assert.equal(passBound(null), null);
  assert.equal(passBound(undefined), null);
});

test('the pass floor where it lies above the bound, and none where it lies below or no pass is proposed', () => {
  const c = { predictedRmsHigh: 0.00575, resolutionFloor: 0.0329 };
  assert.equal(floorAboveBound(c), 0.0329);
  assert.equal(floorAboveBound({ ...c, predictedRmsHigh: 0.2 }), null);
  for (const none of [{ stop: true }, { runKept: true }, { usable: false }, { resolutionFloor: NaN }, { resolutionFloor: undefined }]) {
    assert.equal(floorAboveBound({ ...c, ...none }), null, JSON.stringify(none));
  }
});

test('the axes run stay where the correction stops or changes nothing', () => {
  assert.equal(changesNothing({ change: [0, 1e-9] }), false);
  assert.equal(changesNothing({ change: [0, 0] }), true);
  assert.equal(changesNothing({ runKept: true, change: [1] }), true);
  assert.equal(changesNothing({ stop: true, change: [1] }), false, 'a stop says so in its own words');
  assert.equal(keepsAxesRun({ stop: true, change: [1] }), true);
  assert.equal(keepsAxesRun({ change: [0] }), true);
  assert.equal(keepsAxesRun({ change: [2] }), false);
  assert.equal(keepsAxesRun(null), false);
});
