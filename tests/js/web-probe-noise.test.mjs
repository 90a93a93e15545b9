// The probe noise the page declares (web/src/probe-noise.js): a what-if's grid is noise-free, a
// pasted or uploaded one measured.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { SIMULATED_NOISE, tuningFor } from '../../web/src/probe-noise.js';

test('a simulated grid is declared noise-free; a measured one gets back the case\'s own sigma or the default', () => {
  assert.equal(SIMULATED_NOISE, 1e-4);
  assert.deepEqual(tuningFor({}, true), { probeNoise: 1e-4 });
  assert.deepEqual(tuningFor({ probeNoise: 0.8, method: 'linear' }, true), { method: 'linear', probeNoise: 1e-4 });
  assert.deepEqual(tuningFor({ probeNoise: 1e-4, method: 'linear' }, false), { method: 'linear' }, 'the default sigma again');
  assert.deepEqual(tuningFor({ probeNoise: 0.8 }, false), { probeNoise: 0.8 }, 'a case\'s own sigma stays');
  assert.deepEqual(tuningFor({}, false), {});
});
