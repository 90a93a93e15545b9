// The correction's options as the page edits them (web/src/correction-options.js): blank is the
// default and is left out of the case, numbers are numbers, and the calculator reads the result.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { OPTION_FIELD, optionTexts, withOption } from '../../web/src/correction-options.js';
import { SIMULATED_NOISE } from '../../web/src/probe-noise.js';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));

test('an option typed, changed and blanked again: the case holds only what differs from the default', () => {
  let t = withOption({}, 'probeNoise', '1.5', 'nonlinear');
  assert.deepEqual(t, { probeNoise: 1.5 });
  t = withOption(t, 'resolution.B', '0.001', 'nonlinear');
  t = withOption(t, 'method', 'linear', 'nonlinear');
  assert.deepEqual(t, { probeNoise: 1.5, resolution: { B: 0.001 }, method: 'linear' });
  t = withOption(t, 'resolution.B', ' ', 'nonlinear');
  t = withOption(t, 'method', 'nonlinear', 'nonlinear');
  t = withOption(t, 'probeNoise', '', 'nonlinear');
  assert.deepEqual(t, {});
  const kept = { truncation: 1e-5 };
  assert.deepEqual(withOption(kept, 'probeNoise', '2', 'nonlinear'), { truncation: 1e-5, probeNoise: 2 });
  assert.deepEqual(kept, { truncation: 1e-5 }, 'the state is not changed in place');
  assert.deepEqual(withOption({}, 'probeNoise', '1e', 'nonlinear'), { probeNoise: '1e' }, 'not a number: the calculator names it');
});

test('what the inputs show, and whether the noise is the page\'s own for a simulated grid', () => {
  assert.deepEqual(optionTexts({}, 'nonlinear'), { method: 'nonlinear', probeNoise: '', resolution: {}, simulated: false, wheel: false });
  const t = optionTexts({ probeNoise: SIMULATED_NOISE, resolution: { X: 0.5 }, method: 'linear' }, 'nonlinear');
  assert.deepEqual(t, { method: 'linear', probeNoise: '0.0001', resolution: { X: '0.5' }, simulated: true, wheel: false });
});

test('the wheel tick: true is kept in the case, unticking leaves it out', () => {
  const t = withOption({ probeNoise: 1 }, 'wheel', true, 'nonlinear');
  assert.deepEqual(t, { probeNoise: 1, wheel: true });
  assert.equal(optionTexts(t, 'nonlinear').wheel, true);
  assert.deepEqual(withOption(t, 'wheel', false, 'nonlinear'), { probeNoise: 1 });
  assert.ok(OPTION_FIELD.test('correction.wheel'));
});

test('the option fields are told from the grid and the locks', () => {
  for (const f of ['correction.method', 'correction.probeNoise', 'correction.resolution.B', 'correction.resolution']) assert.ok(OPTION_FIELD.test(f), f);
  for (const f of ['measured', 'measured[2][3]', 'correction.locked', 'correction.lockedAxes', 'passes[0].correction.probeNoise']) assert.ok(!OPTION_FIELD.test(f), f);
});

test('the calculator takes the options the page writes and refuses a bad one naming it', async () => {
  const hobsharp = await loadHobSharp();
  const measured = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (_, j) => 2 + 0.5 * i - 0.25 * j));
  let tuning = withOption({}, 'method', 'linear', 'nonlinear');
  tuning = withOption(tuning, 'resolution.A', '0.001', 'nonlinear');
  const linear = hobsharp.evaluate({ ...paper, measured, correction: { ...tuning, lockedAxes: [], locked: [] } });
  assert.equal(linear.correction.method, 'linear');
  const coarse = withOption(tuning, 'method', 'nonlinear', 'nonlinear');
  const fine = withOption(coarse, 'resolution.A', '', 'nonlinear');
  const a = hobsharp.evaluate({ ...paper, measured, correction: coarse });
  const b = hobsharp.evaluate({ ...paper, measured, correction: fine });
  assert.equal(a.correction.method, 'nonlinear');
  assert.ok(a.correction.resolutionFloor > b.correction.resolutionFloor, 'a coarser A resolution raises the floor');
  for (const [key, text, field] of [['probeNoise', '-1', 'correction.probeNoise'], ['resolution.Z', '0', 'correction.resolution.Z'],
    ['probeNoise', '1e', 'correction.probeNoise']]) {
    assert.throws(() => hobsharp.evaluate({ ...paper, measured, correction: withOption({}, key, text, 'nonlinear') }),
      (e) => e.field === field && e.code === 'InvalidInput', `${key} = ${text}`);
  }
  assert.equal(hobsharp.evaluate({ ...paper, measured }).correction.method, 'nonlinear', 'the module stays usable');
});
