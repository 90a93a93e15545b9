// The undo history of the inputs (web/src/undo-stack.js) and the store's side of it: inputsOf
// and restore (web/src/store.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createUndoStack } from '../../web/src/undo-stack.js';
import { createStore, inputsOf } from '../../web/src/store.js';

const at = (tilt) => ({ form: { setup: { tilt } } });

test('commits make steps; an unchanged commit makes none', () => {
  const s = createUndoStack();
  assert.equal(s.step, -1);
  assert.equal(s.canUndo(), false);
  s.start(at(15));
  assert.equal(s.commit(at(15)), null, 'the same inputs are no new step');
  assert.equal(s.commit(at(16)), 1);
  assert.equal(s.commit(at(17)), 2);
  assert.deepEqual(s.inputs, at(17));
  assert.equal(s.canUndo(), true);
  assert.equal(s.canRedo(), false);
});

test('going back and forth, and a new commit after going back drops the steps after it', () => {
  const s = createUndoStack();
  s.start(at(15));
  s.commit(at(16));
  s.commit(at(17));
  s.moveTo(1, at(16));
  assert.deepEqual([s.step, s.canUndo(), s.canRedo()], [1, true, true]);
  s.moveTo(0, at(15));
  assert.deepEqual([s.step, s.canUndo(), s.canRedo()], [0, false, true]);
  s.moveTo(2, at(17));
  assert.equal(s.canRedo(), false);
  s.moveTo(1, at(16));
  assert.equal(s.commit(at(20)), 2, 'the new step takes the place of the dropped one');
  assert.equal(s.canRedo(), false);
  assert.deepEqual(s.inputs, at(20));
});

test('an entry the stack did not make (from before a reload) starts the history there', () => {
  const s = createUndoStack();
  s.start(at(15), 4);  // reopened at the browser's fifth entry
  assert.deepEqual([s.step, s.canUndo(), s.canRedo()], [4, true, false]);
  s.moveTo(3, at(14));  // Back: the entry holds its inputs
  assert.deepEqual([s.step, s.canUndo(), s.canRedo()], [3, true, false], 'what came after it is not known');
  assert.deepEqual(s.inputs, at(14));
  s.start(at(1));
  s.commit(at(2));
  s.moveTo(1, at(99));  // the same step number, other inputs: not ours
  assert.deepEqual(s.inputs, at(99));
});

test('the store restores a step: the restore event, and a recompute only when the case changed', () => {
  const store = createStore();
  const seen = [];
  for (const e of ['restore', 'inputs']) store.on(e, (d) => seen.push([e, d.source]));
  store.setInputs({ form: { format: 'hobsharp-case/1', setup: { tilt: 15 } }, offsets: { Y: [0.01] } });
  const step = inputsOf(store.state);
  assert.deepEqual(Object.keys(step).sort(), ['axes', 'extra', 'form', 'lockedAxes', 'locked', 'measured', 'offsets', 'paper', 'passes', 'tuning'].sort());
  store.state.offsets.Y[0] = 0.5;  // a copy: later changes do not reach the step
  assert.deepEqual(step.offsets, { Y: [0.01] });
  seen.length = 0;
  store.restore(step);
  assert.deepEqual(seen, [['restore', undefined]], 'only the offsets differed: nothing to recompute');
  assert.deepEqual(store.state.offsets, { Y: [0.01] });
  store.setInputs({ form: { format: 'hobsharp-case/1', setup: { tilt: 16 } } });
  seen.length = 0;
  store.restore(step);
  assert.deepEqual(seen, [['restore', undefined], ['inputs', 'restore']]);
  assert.equal(store.state.form.setup.tilt, 15);
});
