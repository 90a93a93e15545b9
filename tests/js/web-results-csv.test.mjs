// The results and the wheel profile as CSV (web/src/io/results-csv.js), from the module's result
// for the paper's case, with and without a correction.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { profileCsv, resultsCsv } from '../../web/src/io/results-csv.js';
import { setModuleLimits } from '../../web/src/limits.js';

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const hobsharp = await loadHobSharp();
setModuleLimits(hobsharp.limits());  // as the page does once its calculator is ready
const numbers = (line) => line.split(',').slice(1).map(Number);

test('the results CSV holds every coefficient with its unit, and each grid row by row', () => {
  const r = hobsharp.evaluate(paper);
  const lines = resultsCsv(r).split('\n');
  assert.equal(lines[2], 'coefficient,unit,nominal,corrected');
  assert.equal(lines.filter((l) => /^[XYZAB] a\d,/.test(l)).length, 25);
  assert.ok(lines.includes(`X a1,mm/rad,${r.axes.X[1]},`));
  assert.ok(lines.includes(`B a2,rad/rad²,${r.axes.B[2]},`));
  const header = lines.indexOf('# simulated normal deviation (µm) for the axes run; rows r (mm) root to tip, columns x (mm) along the gash');
  assert.deepEqual(numbers(lines[header + 1]), r.topography.x);
  for (let i = 0; i < 5; i++) {
    assert.equal(Number(lines[header + 2 + i].split(',')[0]), r.topography.r[i]);
    assert.deepEqual(numbers(lines[header + 2 + i]), r.topography.normal[i]);
  }
  assert.ok(!resultsCsv(r).includes('after correction'));
  assert.equal(lines.at(-2), `# thickness error at the mean point (µm),${r.topography.thickness}`);
});

test('with a measured grid, the corrected coefficients and the predicted grid are in it', () => {
  const measured = Array.from({ length: 5 }, () => Array(9).fill(1));
  const r = hobsharp.evaluate({ ...paper, measured });
  const csv = resultsCsv(r);
  assert.ok(csv.split('\n').includes(`Z a0,mm,${r.axes.Z[0]},${r.correction.axes.Z[0]}`));
  const lines = csv.split('\n');
  const at = lines.findIndex((l) => l.startsWith('# predicted normal deviation after correction'));
  assert.ok(at > 0);
  assert.deepEqual(numbers(lines[at + 2]), r.correction.residual[0]);
});

test('the wheel profile CSV has its 41 points, r, R and Z in mm', () => {
  const r = hobsharp.evaluate(paper);
  const lines = profileCsv(r).trim().split('\n');
  assert.equal(lines[1], 'r_mm,R_mm,Z_mm');
  assert.equal(lines.length, 2 + 41);
  assert.deepEqual(lines[2].split(',').map(Number), [r.wheelProfile.r[0], r.wheelProfile.R[0], r.wheelProfile.Z[0]]);
  assert.ok(Math.abs(r.wheelProfile.R[0] - 49.999828) < 1e-5);
});
