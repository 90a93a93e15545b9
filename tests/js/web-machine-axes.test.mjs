// The axes in the control's units (web/src/machine-axes.js): the converted polynomials give the
// same positions as the calculator's (a second evaluation, in rad), the table's rows and ends,
// and a bad step refused.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { setModuleLimits } from '../../web/src/limits.js';
import { axisPositions, coefficientsText, machineUnit, positionsCsv, programmed, roundedFiguresText } from '../../web/src/machine-axes.js';
import { machineCoefficients } from '../../wasm/lib/axes-to-run.js';

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const hobsharp = await loadHobSharp();
setModuleLimits(hobsharp.limits());
const inRad = (c, phi) => c.reduce((s, a, k) => s + a * phi ** k, 0);

test('the converted polynomials give the same positions as the calculator\'s in rad', () => {
  const r = hobsharp.evaluate(paper);
  const m = machineCoefficients(r.axes, true);
  assert.ok(Math.abs(m.A[1] - 1) < 1e-12, 'A turns with the hob: 1 deg per deg');
  for (const phi of [r.motion.min, 0.3 * r.motion.max, r.motion.max]) {
    const deg = phi * 180 / Math.PI;
    for (const a of ['X', 'Y', 'Z']) {
      assert.ok(Math.abs(inRad(m[a].map((c, k) => c), deg) - inRad(r.axes[a], phi)) < 1e-9, a);
    }
    for (const a of ['A', 'B']) assert.ok(Math.abs(inRad(m[a], deg) - inRad(r.axes[a], phi) * 180 / Math.PI) < 1e-9, a);
  }
  assert.equal(machineUnit('B', 2, true), 'deg/deg^2');
  assert.equal(machineUnit('X', 1, false), 'mm/mm');
  // The nominal X is linear in phi: no "+ 0 * phi (deg)^2" terms (issue 22).
  assert.match(coefficientsText(m, true, 10), /^X \(mm\) = [-\d.e]+ [+-] [\d.e-]+ \* phi \(deg\)\n/);
});

// With a correction: the rounded axes as the program carries them, copied to the same digits, and
// the face predicted with them beside the floor, in the units the module's fields give.
test('the rounded axes: the program\'s digits, the predicted face and the floor with the schema\'s units', () => {
  const actual = structuredClone(hobsharp.evaluate(paper).axes);
  actual.Z[0] -= 0.01; actual.B[2] += 0.001;
  const measured = hobsharp.evaluate({ ...paper, axes: actual }).topography.normal;
  const c = hobsharp.evaluate({ ...paper, measured, correction: { probeNoise: 1e-4 } }).correction;
  const digits = hobsharp.limits().correction.coefficientDigits;
  const m = machineCoefficients(c.roundedAxes, true);
  for (const a of ['X', 'Y', 'Z', 'A', 'B']) {
    for (const v of m[a]) assert.ok(Math.abs(Number(programmed(v, digits)) - v) <= 1e-14 * Math.abs(v), `${a}: ${v}`);
  }
  assert.equal(programmed(1.23456789012345e-11, 10), '1.23456789e-11');
  const copied = coefficientsText(m, true, digits);
  const numbers = copied.match(/-?\d[\d.]*(e[-+]?\d+)?/g).filter((s) => s.includes('.') || s.includes('e'));
  assert.ok(numbers.every((s) => s.replace(/^-/, '').replace(/e.*$/, '').replace('.', '').replace(/^0+/, '').length <= digits), copied);
  const units = Object.fromEntries(hobsharp.resultFields().map((f) => [f.path, f.unit]));
  const text = roundedFiguresText(c, (path) => units[path]);
  assert.match(text, /^With these axes the identified machine grinds [\d.e-]+ µm rms \(re-simulated, this measurement's misfit kept; the exact axes leave at most the verdict's bound\)\. /);
  assert.ok(text.includes(`${Number(c.resolutionFloor.toPrecision(3))} µm rms.`), text);
  assert.equal(roundedFiguresText({ sseAfter: 1 }, () => 'µm'), '');
  assert.equal(roundedFiguresText(undefined, () => 'µm'), '');
});

test('the table of positions: every step from the start, both ends, the values of the polynomials', () => {
  const r = hobsharp.evaluate(paper);
  const rows = axisPositions(r.axes, r.motion.min, r.motion.max, 1, true);
  const lo = r.motion.min * 180 / Math.PI, hi = r.motion.max * 180 / Math.PI;
  assert.equal(rows[0][0], lo);
  assert.ok(Math.abs(rows.at(-1)[0] - hi) < 1e-9);
  assert.equal(rows.length, Math.floor(hi - lo) + (Number.isInteger(hi - lo) ? 1 : 2));
  const [phi, X, , , A, B] = rows[3];
  assert.ok(Math.abs(X - inRad(r.axes.X, phi * Math.PI / 180)) < 1e-9);
  assert.ok(Math.abs(A - phi) < 1e-9);
  assert.ok(Math.abs(B - inRad(r.axes.B, phi * Math.PI / 180) * 180 / Math.PI) < 1e-9);
  const csv = positionsCsv(rows, true).split('\n');
  assert.equal(csv[0], '\uFEFFhob rotation (deg),X (mm),Y (mm),Z (mm),A (deg),B (deg)');
  // Written to 6 decimals (1 nm, 1e-6 deg): no floating-point noise (issue 22).
  assert.ok(csv[1].split(',').every((v, k) => /^-?\d+\.\d{6}$/.test(v) && Math.abs(Number(v) - rows[0][k]) <= 5e-7), csv[1]);
  assert.throws(() => axisPositions(r.axes, r.motion.min, r.motion.max, 0, true), /^Error: Step: must be a positive number of degrees; got 0\.$/);
  assert.throws(() => axisPositions(r.axes, r.motion.min, r.motion.max, 1e-6, true), /more than 10001 rows/);
  assert.throws(() => axisPositions(r.axes, r.motion.min, r.motion.max, NaN, true), /positive number/);
});
