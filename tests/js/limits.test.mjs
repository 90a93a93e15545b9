// limits(): the case's limits and defaults as the C++ core has them, each checked against what the
// module accepts and refuses.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadHobSharp, HobSharpError } from '../../wasm/hobsharp.mjs';

const hobsharp = await loadHobSharp();
const limits = hobsharp.limits();
const paper = () => JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));

function refused(c, field, message) {
  assert.throws(() => hobsharp.evaluate(c), (e) => {
    assert.ok(e instanceof HobSharpError);
    assert.equal(e.code, 'InvalidInput');
    assert.equal(e.field, field);
    assert.match(e.message, message);
    return true;
  });
}

test('limits() has the documented form, every value from the module', () => {
  assert.deepEqual(Object.keys(limits), ['format', 'maxGridLines', 'gridTolerance', 'degree', 'defaultGrid',
    'wheelProfilePoints', 'maxWheelPoints', 'axes', 'motionUnits', 'correction', 'inspection']);
  assert.equal(limits.format, paper().format);
  assert.equal(limits.maxGridLines, 201);
  assert.deepEqual(limits.degree, { min: 1, max: 6, default: 4 });
  assert.deepEqual(limits.defaultGrid, { radial: 5, axial: 9 });
  assert.deepEqual(limits.axes.map((a) => `${a.name} ${a.kind} ${a.unit}`),
    ['X linear mm', 'Y linear mm', 'Z linear mm', 'A rotary rad', 'B rotary rad']);
  assert.deepEqual(limits.motionUnits, { helical: 'rad', straight: 'mm' });
  limits.degree.max = 99;
  assert.equal(hobsharp.limits().degree.max, 6, 'each call gives a fresh object');
  limits.degree.max = 6;
});

test('maxGridLines lines are taken in each direction, one more is refused', () => {
  const n = limits.maxGridLines;
  for (const [dir, other] of [['axial', 'radial'], ['radial', 'axial']]) {
    const c = paper();
    c.grid[dir] = n;
    c.grid[other] = 2;
    const r = hobsharp.evaluate(c);
    assert.equal(dir === 'axial' ? r.topography.x.length : r.topography.r.length, n);
    c.grid[dir] = n + 1;
    refused(c, `grid.${dir}`, new RegExp(`from 2 to ${n}; got ${n + 1}`));
  }
});

// A wheel's profile of maxWheelPoints points is read; one more is refused before the wheel is
// fitted (it would take seconds, and near 12,000 points more memory than the module has). The
// page's wheel-file reader counts against the same number.
test('maxWheelPoints points of a wheel are read, one more is refused; the page reads the same limit', async () => {
  const { MAX_WHEEL_POINTS } = await import('../../wasm/lib/wheel-csv.js');
  assert.equal(limits.maxWheelPoints, 2000);
  assert.equal(MAX_WHEEL_POINTS, limits.maxWheelPoints);
  const wheel = (n) => {
    const c = paper();
    const R = Array.from({ length: n }, (_, i) => 30 + 20 * i / (n - 1));
    c.wheel = { ...c.wheel, profileOffset: { R, offset: R.map(() => 0) } };
    return c;
  };
  refused(wheel(limits.maxWheelPoints + 1), 'wheel.profileOffset.R', /has 2001 points; at most 2000 are taken/);
  let message = '';
  try {
    hobsharp.evaluate(wheel(limits.maxWheelPoints));
  } catch (e) {
    message = e.message;  // the contact range, say: anything but the count
  }
  assert.doesNotMatch(message, /are taken/);
});

test('a grid may reach gridTolerance past the gash root, no further', () => {
  const c = paper();
  const root = hobsharp.evaluate(c).setup.rootRadius;
  c.grid.rMin = root - limits.gridTolerance / 2;
  assert.equal(hobsharp.evaluate(c).topography.r[0], c.grid.rMin);
  c.grid.rMin = root - 2 * limits.gridTolerance;
  refused(c, 'grid.rMin', /below the gash root/);
});

test('the degree range and the default degree', () => {
  const { min, max } = limits.degree;
  for (const d of [min, max]) {
    const c = paper();
    c.degree = d;
    assert.equal(hobsharp.evaluate(c).axes.X.length, d + 1);
  }
  for (const d of [min - 1, max + 1]) {
    const c = paper();
    c.degree = d;
    refused(c, 'degree', new RegExp(`from ${min} to ${max}; got ${d}`));
  }
  const c = paper();
  delete c.degree;
  assert.equal(hobsharp.evaluate(c).axes.X.length, limits.degree.default + 1);
});

test('the default grid and the wheel profile points', () => {
  const c = paper();
  delete c.grid;
  const r = hobsharp.evaluate(c);
  assert.equal(r.topography.r.length, limits.defaultGrid.radial);
  assert.equal(r.topography.x.length, limits.defaultGrid.axial);
  assert.equal(r.topography.normal.length, limits.defaultGrid.radial);
  assert.equal(r.wheelProfile.r.length, limits.wheelProfilePoints);
  assert.equal(r.wheelProfile.R.length, limits.wheelProfilePoints);
});

test('the axes and motion units are those of the result', () => {
  const helical = hobsharp.evaluate(paper());
  assert.deepEqual(Object.keys(helical.axes), limits.axes.map((a) => a.name));
  assert.equal(helical.setup.motionUnit, limits.motionUnits.helical);
  const c = paper();
  c.hob.gash = 'straight';
  delete c.hob.gashLead;
  delete c.hob.hand;
  c.setup.settingAngle = 0;
  delete c.setup.centerDistance;
  const straight = hobsharp.evaluate(c);
  assert.equal(straight.setup.motionUnit, limits.motionUnits.straight);
  assert.equal(straight.setup.gashLead, undefined, 'no lead for a straight gash');
  // The rotary axes turn with the motion parameter of a helical gash: A = phi_1 (rad per rad).
  assert.equal(helical.axes.A[1], 1);
  assert.equal(straight.axes.A[1], 0);
});

test("limits().correction gives the correction's options, each checked against the module", () => {
  const k = limits.correction;
  assert.deepEqual(k.methods, ['nonlinear', 'linear']);
  assert.equal(k.defaultMethod, 'nonlinear');
  assert.deepEqual(k.probeNoise, { default: 0.5, max: 10000, unit: 'µm' });
  assert.deepEqual(Object.keys(k.resolution), ['X', 'Y', 'Z', 'A', 'B']);
  assert.deepEqual(k.resolution.X, { default: 0.1, min: 0.001, max: 1000, unit: 'µm' });
  assert.deepEqual(k.resolution.B, { default: 0.0001, min: 1e-9, max: 1, unit: 'deg' });
  assert.equal(k.coefficientDigits, 10);
  const measured = Array.from({ length: 5 }, () => Array(9).fill(1));
  // The defaults are what a case without them gets.
  const r = hobsharp.evaluate({ ...paper(), measured });
  assert.equal(r.correction.method, k.defaultMethod);
  assert.equal(r.correction.probeNoise, k.probeNoise.default);
  // The ends are taken, one step beyond is refused.
  for (const a of ['X', 'A']) {
    const { min, max } = k.resolution[a];
    for (const v of [min, max]) assert.ok(hobsharp.evaluate({ ...paper(), measured, correction: { resolution: { [a]: v } } }).correction);
    refused({ ...paper(), measured, correction: { resolution: { [a]: max * 1.01 } } }, `correction.resolution.${a}`, /must lie between/);
    refused({ ...paper(), measured, correction: { resolution: { [a]: min * 0.99 } } }, `correction.resolution.${a}`, /must lie between/);
  }
  assert.ok(hobsharp.evaluate({ ...paper(), measured, correction: { probeNoise: k.probeNoise.max } }).correction);
  refused({ ...paper(), measured, correction: { probeNoise: k.probeNoise.max * 1.01 } }, 'correction.probeNoise', /at most/);
});
