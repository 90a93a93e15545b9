// The measured data's state in the store (web/src/measurement.js) with the recompute and a
// stand-in calculator whose answers the test releases: a file refused, by the page or by the
// calculator, leaves what is in use, the inputs and the box's text as they were, and says why;
// an undo step with another grid puts it into the box and names it from its result.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createStore } from '../../web/src/store.js';
import { startRecompute } from '../../web/src/recompute.js';
import { settle, standIn } from './stand-in-calculator.mjs';
import { giveText, inUseText, mountMeasurement, typed, useFile, useMeasurement } from '../../web/src/measurement.js';

const topography = { r: [10, 20], x: [-5, 0, 5] };  // 2 radial lines of 3 values
const gridA = '1, 2, 3\n4, 5, 6\n';
const gridB = '7, 8, 9\n10, 11, 12\n';

// A page with the paper's form computed, and the measured state kept from the store's events.
async function page() {
  const store = createStore();
  const calc = standIn();
  startRecompute(store, calc);
  mountMeasurement(store);
  const events = [];
  for (const e of ['measured-text', 'measurement', 'aside']) store.on(e, (d) => events.push([e, d]));
  store.setInputs({ form: { format: 'hobsharp-case/1', setup: { tilt: 15 } } }, { source: 'form' });
  calc.calls.at(-1).resolve({ result: { topography }, ms: 1 });
  await settle();
  return { store, calc, events };
}
// The calculator's answer to the newest case: a result, or a refusal naming its field.
async function answer(calc, refusal = null) {
  const call = calc.calls.at(-1);
  if (refusal) call.reject(Object.assign(new Error(refusal.message), { code: 'InvalidInput', field: refusal.field }));
  else call.resolve({ result: { topography, measuredRms: call.caseObject.measured ? 1 : 0 }, ms: 1 });
  await settle();
}

test('a file used is in use once its result comes, named with what it holds', async () => {
  const { store, calc } = await page();
  assert.equal(store.state.measuredSource, null);
  useFile(store, gridA, 'a.csv');
  assert.equal(store.state.measuredText, gridA, 'the file\'s text is in the box');
  assert.deepEqual(calc.calls.at(-1).caseObject.measured, [[1, 2, 3], [4, 5, 6]]);
  assert.equal(store.state.measuredSource, null, 'not in use before its result');
  assert.equal(store.state.measuredAttempt.name, 'a.csv');
  await answer(calc);
  assert.deepEqual(store.state.measuredSource, { name: 'a.csv', what: '2 × 3 values', meta: {}, text: gridA });
  assert.equal(store.state.measuredAttempt, null);
  assert.equal(inUseText(store.state.measuredSource), 'In use: a.csv (2 × 3 values).');
});

test('a file the calculator refuses leaves the measurement in use, the inputs and the box as they were', async () => {
  const { store, calc, events } = await page();
  useFile(store, gridA, 'a.csv');
  await answer(calc);
  const inputsBefore = structuredClone({ measured: store.state.measured, extra: store.state.extra, tuning: store.state.tuning });
  useFile(store, gridB, 'b.csv');
  assert.deepEqual(store.state.measured, [[7, 8, 9], [10, 11, 12]]);
  const sent = calc.calls.length;
  await answer(calc, { field: 'measured[1][2]', message: 'Measured grid, row 2, value 3: 12 µm is too large.' });
  // The inputs before are sent again, and the grid refused is not set aside (it is no longer in use).
  assert.equal(calc.calls.length, sent + 1);
  assert.deepEqual({ measured: store.state.measured, extra: store.state.extra, tuning: store.state.tuning }, inputsBefore);
  assert.equal(events.filter(([e]) => e === 'aside').length, 0);
  assert.equal(store.state.measuredText, gridA, 'the box has the text in use again');
  assert.equal(store.state.measuredSource.name, 'a.csv');
  assert.equal(store.state.measuredAttempt, null);
  const note = 'b.csv is refused: Measured grid, row 2, value 3: 12 µm is too large. In use: a.csv (2 × 3 values).';
  assert.equal(store.state.measuredMessage, note);
  // The measurement in use computed again: the status says what was refused, and the note stays.
  await answer(calc);
  assert.deepEqual(store.state.status, { text: 'b.csv is refused (a.csv stays in use): Measured grid, row 2, value 3: 12 µm is too large.', kind: 'error' });
  assert.equal(store.state.measuredMessage, note);
  assert.equal(store.state.measuredSource.name, 'a.csv');
  // The next measurement computed ends the note.
  typed(store, gridB.replace('7', '6'));
  assert.equal(store.state.measuredRefusal, null);
  useMeasurement(store, store.state.measuredText);
  await answer(calc);
  assert.equal(store.state.measuredMessage, null);
  assert.equal(store.state.measuredSource.name, 'the grid in the box');
});

test('a file the page refuses changes no input, and says so at once', async () => {
  const { store, calc } = await page();
  useFile(store, gridA, 'a.csv');
  await answer(calc);
  const sent = calc.calls.length;
  const { measured, extra } = store.state;
  useFile(store, '1, 2\n3, 4\n', 'small.csv');
  assert.equal(calc.calls.length, sent, 'nothing sent');
  assert.equal(store.state.measured, measured);
  assert.equal(store.state.extra, extra);
  assert.equal(store.state.measuredText, gridA, 'the box put back');
  assert.equal(store.state.measuredSource.name, 'a.csv');
  assert.equal(store.state.status.kind, 'error');
  assert.match(store.state.status.text, /^small\.csv is refused \(a\.csv stays in use\): /);
  assert.match(store.state.measuredMessage, /^small\.csv is refused: .* In use: a\.csv \(2 × 3 values\)\.$/);
  // The box's own text refused: the reader's message alone, and no refusal to put anything back.
  useMeasurement(store, 'nonsense');
  assert.equal(calc.calls.length, sent);
  assert.equal(store.state.measuredRefusal, null);
  assert.doesNotMatch(store.state.measuredMessage, /is refused/);
});

test('an undo step with another grid puts it into the box and names it from its result', async () => {
  const { store, calc, events } = await page();
  const empty = structuredClone({ form: store.state.form, measured: null, extra: {}, tuning: {} });
  useFile(store, gridA, 'a.csv');
  await answer(calc);
  events.length = 0;
  store.restore(empty);
  assert.equal(store.state.measuredText, '');
  assert.equal(store.state.measuredSource, null);
  assert.deepEqual(events.find(([e]) => e === 'measured-text')[1], { source: 'restore' });
  await answer(calc);
  assert.equal(store.state.measuredSource, null, 'no measurement in use');
  // Back to the grid: its text, named as the measured grid (its file's name is not an input).
  store.restore({ ...empty, measured: [[1, 2, 3], [4, 5, 6]] });
  assert.equal(store.state.measuredText, '1, 2, 3\n4, 5, 6');
  await answer(calc);
  assert.deepEqual(store.state.measuredSource, { name: 'the measured grid', what: '2 × 3 values', meta: {}, text: '1, 2, 3\n4, 5, 6' });
  // An undo step with the same grid leaves the box and what is in use.
  typed(store, 'typed text');
  store.restore({ ...empty, measured: [[1, 2, 3], [4, 5, 6]], tuning: { truncation: 1e-3 } });
  assert.equal(store.state.measuredText, 'typed text');
  assert.equal(store.state.measuredSource.name, 'the measured grid');
  // A grid given by a loaded case goes into the box and ends the message.
  store.setMeasurement({ measuredMessage: 'old' });
  giveText(store, 'given');
  assert.equal(store.state.measuredText, 'given');
  assert.equal(store.state.measuredMessage, null);
});
