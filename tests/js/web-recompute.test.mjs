// The store and the recompute (web/src/store.js, web/src/recompute.js) with a stand-in
// calculator whose answers the test releases: the newest input wins, nothing waits on a timer,
// and a measured grid the calculator refuses is not sent again.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { caseOf, createStore } from '../../web/src/store.js';
import { startRecompute } from '../../web/src/recompute.js';
import { settle, standIn } from './stand-in-calculator.mjs';

const form = (tilt) => ({ format: 'hobsharp-case/1', setup: { tilt } });

function watch(store) {
  const seen = [];
  for (const e of ['inputs', 'computing', 'result', 'refusal', 'aside']) store.on(e, (d) => seen.push([e, d]));
  return seen;
}

test('an input is sent at once; while it computes, only the newest waits, and only its result shows', async () => {
  const store = createStore();
  const calc = standIn();
  startRecompute(store, calc);
  const seen = watch(store);
  store.setInputs({ form: form(15) }, { source: 'form', at: 1 });
  assert.equal(calc.calls.length, 1, 'sent without a wait');
  store.setInputs({ form: form(16) }, { source: 'form' });
  store.setInputs({ form: form(17) }, { source: 'form' });
  assert.equal(calc.calls.length, 1, 'nothing more is sent while one computes');
  calc.calls[0].resolve({ result: { tilt: 15 }, ms: 1 });
  await settle();
  assert.equal(calc.calls.length, 2);
  assert.equal(calc.calls[1].caseObject.setup.tilt, 17, 'the newest input, not 16');
  assert.equal(seen.filter(([e]) => e === 'result').length, 0, 'an answer overtaken by a newer input is not shown');
  calc.calls[1].resolve({ result: { tilt: 17 }, ms: 1 });
  await settle();
  const results = seen.filter(([e]) => e === 'result');
  assert.equal(results.length, 1);
  assert.equal(results[0][1].caseObject.setup.tilt, 17);
  assert.deepEqual(store.state.result, { tilt: 17 });
  assert.equal(store.state.status.text, 'Computing…');  // the status view, not mounted here, words the result
});

test('an unchanged case is not sent again', async () => {
  const store = createStore();
  const calc = standIn();
  startRecompute(store, calc);
  store.setInputs({ form: form(15) });
  calc.calls[0].resolve({ result: {}, ms: 1 });
  await settle();
  store.setInputs({ form: form(15) });
  assert.equal(calc.calls.length, 1);
  store.setInputs({ form: form(15) }, { force: true });
  assert.equal(calc.calls.length, 2);
});

test('a refusal keeps the last good result and reports the field', async () => {
  const store = createStore();
  const calc = standIn();
  startRecompute(store, calc);
  const seen = watch(store);
  store.setInputs({ form: form(15) });
  calc.calls[0].resolve({ result: { good: true }, ms: 1 });
  await settle();
  store.setInputs({ form: form(95) });
  calc.calls[1].reject(Object.assign(new Error('setup.tilt: too large'), { code: 'InvalidInput', field: 'setup.tilt' }));
  await settle();
  const refusal = seen.find(([e]) => e === 'refusal')[1];
  assert.equal(refusal.error.field, 'setup.tilt');
  assert.equal(refusal.caseObject.setup.tilt, 95);
  assert.deepEqual(store.state.result, { good: true });
});

test('a measured grid the calculator refuses is set aside and not sent with later edits', async () => {
  const store = createStore();
  const calc = standIn();
  startRecompute(store, calc);
  const seen = watch(store);
  store.setInputs({ form: form(15), measured: [[1, 2]], lockedAxes: ['A'] });
  assert.deepEqual(calc.calls[0].caseObject.measured, [[1, 2]]);
  assert.deepEqual(calc.calls[0].caseObject.correction, { lockedAxes: ['A'], locked: [] });
  calc.calls[0].reject(Object.assign(new Error('measured: must have 5 rows'), { code: 'InvalidInput', field: 'measured' }));
  await settle();
  assert.equal(seen.filter(([e]) => e === 'aside').length, 1);
  assert.equal(store.state.measured, null);
  assert.equal(calc.calls.length, 2, 'the rest is computed at once');
  assert.equal(calc.calls[1].caseObject.measured, undefined);
  calc.calls[1].resolve({ result: {}, ms: 1 });
  await settle();
  store.setInputs({ form: form(16) });
  assert.equal(calc.calls.length, 3);
  assert.equal(calc.calls[2].caseObject.measured, undefined, 'a later edit does not send it again');
  assert.equal(caseOf(store.state).correction, undefined);
});

// Issue 22: a grid just given that the calculator refuses leaves the measurement in use before in
// use (views/measured.js puts it back on the refusal); nothing is set aside then.
test('a refused grid that a view replaces by the grid in use before is not set aside', async () => {
  const store = createStore();
  const calc = standIn();
  startRecompute(store, calc);
  store.setInputs({ form: form(15), measured: [[1, 2]] });
  calc.calls[0].resolve({ result: { good: 1 }, ms: 1 });
  await settle();
  store.on('refusal', () => store.setInputs({ measured: [[1, 2]] }));  // the view's put-back
  store.setInputs({ measured: [[3, 2e4]] });
  const seen = watch(store);
  calc.calls[1].reject(Object.assign(new Error('Measured grid, row 1, value 2: must lie within ±10000 µm'), { code: 'InvalidInput', field: 'measured[0][1]' }));
  await settle();
  assert.equal(seen.filter(([e]) => e === 'aside').length, 0, 'nothing set aside');
  assert.deepEqual(store.state.measured, [[1, 2]], 'the grid before is in use');
  assert.equal(calc.calls.length, 3, 'computed again once');
  assert.deepEqual(calc.calls[2].caseObject.measured, [[1, 2]]);
});

// A grid in use that no longer fits the grid lines (the lines changed under it) is set aside; on
// other lines it is sent again, for the calculator to name them; back on its shape it is in use
// again (nothing stale: the refusal named lines no longer asked for). Another measurement drops it.
test('a grid set aside for not fitting the grid lines is used again once they are back to its shape', async () => {
  const store = createStore();
  const calc = standIn();
  startRecompute(store, calc);
  const seen = watch(store);
  const lines = (radial) => ({ format: 'hobsharp-case/1', grid: { radial, axial: 2 } });
  const grid = [[1, 2], [3, 4], [5, 6]];
  const source = { name: 'probe.csv', what: '3 × 2 values', meta: {}, text: '1,2\n3,4\n5,6' };
  store.setInputs({ form: lines(3), measured: grid, measuredSource: source }, { source: 'measured' });
  calc.calls[0].resolve({ result: { n: 0 }, ms: 1 });
  await settle();
  const notFit = (k) => Object.assign(new Error(`Measured grid: needs ${k} rows (the radial grid lines) of 2 values (the axial grid lines); got 3 x 2.`),
    { code: 'InvalidInput', field: 'measured' });
  // 3 -> 2: refused, set aside, the rest computed without it.
  store.setInputs({ form: lines(2) }, { source: 'form' });
  calc.calls[1].reject(notFit(2));
  await settle();
  assert.equal(seen.filter(([e]) => e === 'aside').length, 1);
  assert.equal(seen.find(([e]) => e === 'aside')[1].untilFits, true);
  assert.equal(store.state.measured, null);
  assert.equal(calc.calls[2].caseObject.measured, undefined);
  calc.calls[2].resolve({ result: { n: 2 }, ms: 1 });
  await settle();
  // Another edit on the same lines: not sent again.
  store.setInputs({ form: { ...lines(2), setup: { tilt: 16 } } }, { source: 'form' });
  assert.equal(calc.calls[3].caseObject.measured, undefined, 'not resent on the lines it did not fit');
  calc.calls[3].resolve({ result: { n: 3 }, ms: 1 });
  await settle();
  // 2 -> 4: sent again, so that the refusal names 4 rows, not 2.
  store.setInputs({ form: { ...lines(4), setup: { tilt: 16 } } }, { source: 'form' });
  assert.deepEqual(calc.calls[4].caseObject.measured, grid);
  calc.calls[4].reject(notFit(4));
  await settle();
  assert.equal(seen.filter(([e]) => e === 'aside').length, 2);
  calc.calls[5].resolve({ result: { n: 5 }, ms: 1 });
  await settle();
  // 4 -> 3, its shape: in use again, with its source, and the result is the measured face's.
  store.setInputs({ form: { ...lines(3), setup: { tilt: 16 } } }, { source: 'form' });
  assert.deepEqual(calc.calls[6].caseObject.measured, grid);
  assert.equal(store.state.measured, grid);
  assert.equal(store.state.measuredSource, source);
  calc.calls[6].resolve({ result: { n: 6 }, ms: 1 });
  await settle();
  assert.deepEqual(store.state.result, { n: 6 });
  assert.equal(seen.filter(([e]) => e === 'aside').length, 2, 'not set aside again');

  // Set aside again, then another measurement (here "Clear"): the grid is not put back.
  store.setInputs({ form: { ...lines(2), setup: { tilt: 16 } } }, { source: 'form' });
  calc.calls[7].reject(notFit(2));
  await settle();
  calc.calls[8].resolve({ result: { n: 8 }, ms: 1 });
  await settle();
  store.setInputs({ measured: null }, { source: 'measured', force: true });
  calc.calls[9].resolve({ result: { n: 9 }, ms: 1 });
  await settle();
  store.setInputs({ form: { ...lines(3), setup: { tilt: 16 } } }, { source: 'form' });
  assert.equal(calc.calls[10].caseObject.measured, undefined, 'cleared: not put back');
  assert.equal(store.state.measured, null);
});
