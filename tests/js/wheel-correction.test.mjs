// The wheel-profile correction (issue 12 item 3, docs/method.md §Wheel-profile correction) through the
// WebAssembly module: correction.wheel on a face ground by a wheel out of profile with a machine
// error; the new result fields are there, finite, of their shapes, and match the native build.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadHobSharp, HobSharpError } from '../../wasm/hobsharp.mjs';
import { native, paper } from './native-build.mjs';

const hobsharp = await loadHobSharp();

const conjugate = hobsharp.evaluate(paper());
const Rmin = Math.min(...conjugate.wheelProfile.R), Rmax = Math.max(...conjugate.wheelProfile.R);
// The measured face: a wheel 10 µm out of profile (a second-degree shape along R) and a machine error.
const worn = paper();
worn.wheel.profileOffset = {
  R: Array.from({ length: 9 }, (_, k) => Rmin + (Rmax - Rmin) * k / 8),
  offset: Array.from({ length: 9 }, (_, k) => 10 * (k / 4 - 1) ** 2 - 5),
};
const axes = conjugate.axes;
axes.Z[1] += 0.002;
axes.B[2] += 0.0005;
worn.axes = axes;
const measured = hobsharp.evaluate(worn).topography.normal;
const wheelCase = () => ({ ...paper(), measured, correction: { probeNoise: 1e-4, wheel: true } });

const close = (a, b, tol, what) =>
  assert.ok(Math.abs(a - b) <= tol * Math.max(1, Math.abs(a)), `${what}: ${a} against ${b}`);

test('correction.wheel: the new fields, finite, of their shapes', () => {
  const r = hobsharp.evaluate(wheelCase());
  const c = r.correction;
  assert.equal(c.wheelProfileOffset.R.length, 5);
  assert.equal(c.wheelProfileOffset.offset.length, 5);
  assert.equal(c.dresserPath.R.length, r.wheelProfile.R.length);
  assert.equal(c.dresserPath.Z.length, r.wheelProfile.Z.length);
  assert.equal(c.dresserPath.offset.length, r.wheelProfile.R.length);
  for (const grid of ['removedByAxes', 'removedByWheel', 'residual']) {
    assert.equal(c[grid].length, 5, grid);
    for (const row of c[grid]) assert.equal(row.length, 9, grid);
  }
  const all = [...c.wheelProfileOffset.R, ...c.wheelProfileOffset.offset, ...c.dresserPath.R, ...c.dresserPath.Z, ...c.dresserPath.offset,
    ...c.removedByAxes.flat(), ...c.removedByWheel.flat(), c.wheelShare, c.axesShare];
  assert.ok(all.every(Number.isFinite));
  for (const s of [c.wheelShare, c.axesShare]) assert.ok(s >= 0 && s <= 1);
  assert.ok(c.wheelShare > 0.05, `the wheel takes the shape: ${c.wheelShare}`);
  close(c.wheelShare + c.axesShare + c.uncorrectableShare, 1, 1e-6, 'shares');
  // The wheel out by + (10 z² - 5) µm: the dressing bends the other way.
  const o = c.wheelProfileOffset.offset;
  assert.ok(o[0] - 2 * o[2] + o[4] < 0, `dressing ${o}`);
  // measured = removed by the axes + removed by the wheel + what is left.
  measured.forEach((row, i) => row.forEach((m, j) =>
    close(c.removedByAxes[i][j] + c.removedByWheel[i][j] + c.residual[i][j], m, 1e-9, `[${i}][${j}]`)));
  assert.ok(c.sseAfter < 0.05 * c.sseBefore);
  // Without correction.wheel there are no such fields.
  const plain = hobsharp.evaluate({ ...paper(), measured, correction: { probeNoise: 1e-4 } }).correction;
  for (const key of ['wheelProfileOffset', 'dresserPath', 'removedByAxes', 'removedByWheel', 'wheelShare', 'axesShare'])
    assert.equal(plain[key], undefined, key);
});

test('correction.wheel: the module agrees with the native build', () => {
  const c = wheelCase();
  const w = hobsharp.evaluate(c).correction, n = native(c).correction;
  for (const [a, b, what] of [[w.wheelProfileOffset.R, n.wheelProfileOffset.R, 'R'],
    [w.dresserPath.R, n.dresserPath.R, 'dresserPath.R'], [w.dresserPath.Z, n.dresserPath.Z, 'dresserPath.Z']])
    a.forEach((x, i) => close(x, b[i], 1e-9, `${what}[${i}]`));
  // The offsets, the split and the figures come out of the iterative solve, whose derivatives
  // differ between the builds (see the KNOWN GAP of wheel.test.mjs; here 4 against 7 iterations):
  // the dressing to 1e-5 µm (measured 7e-6), the residual to 1e-6 µm (7e-8), the split along the
  // axes' span at the solution to 1e-3 µm (1.1e-4), the shares to 1e-5 (1.7e-6).
  w.wheelProfileOffset.offset.forEach((x, i) => assert.ok(Math.abs(x - n.wheelProfileOffset.offset[i]) < 1e-5, `offset[${i}]`));
  for (const [grid, tol] of [['removedByAxes', 1e-3], ['removedByWheel', 1e-3], ['residual', 1e-6]])
    w[grid].forEach((row, i) => row.forEach((x, j) => assert.ok(Math.abs(x - n[grid][i][j]) < tol, `${grid}[${i}][${j}]`)));
  assert.ok(Math.abs(w.wheelShare - n.wheelShare) < 1e-5, 'wheelShare');
  assert.ok(Math.abs(w.axesShare - n.axesShare) < 1e-5, 'axesShare');
  assert.ok(Math.abs(w.sseAfter - n.sseAfter) < 1e-4, `sseAfter ${w.sseAfter} against ${n.sseAfter}`);
});

test('correction.wheel: refusals name the field, and the module stays usable', () => {
  assert.throws(() => hobsharp.evaluate({ ...wheelCase(), correction: { wheel: 'yes' } }),
    (e) => e instanceof HobSharpError && e.field === 'correction.wheel' && /true or false/.test(e.message));
  assert.throws(() => hobsharp.evaluate({ ...wheelCase(), correction: { wheel: true, method: 'linear' } }),
    (e) => e instanceof HobSharpError && e.field === 'correction.wheel' && /nonlinear/.test(e.message));
  assert.ok(hobsharp.evaluate(wheelCase()).correction.wheelProfileOffset);
});
