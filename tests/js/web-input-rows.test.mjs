// The case's inputs as the job's record lists them (web/src/io/input-rows.js), shared by the
// results CSV and the printed report (web/src/views/report.js, its rows by group).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { inputRows } from '../../web/src/io/input-rows.js';
import { reportDateLine, reportInspectionLine, reportRows } from '../../web/src/views/report.js';
import { setResultFields } from '../../web/src/result-fields.js';
import { setModuleLimits } from '../../web/src/limits.js';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const hobsharp = await loadHobSharp();
setModuleLimits(hobsharp.limits());  // the axes' names, as the page has them
setResultFields(hobsharp.resultFields());  // and the results' units

test('every value of the case by its path, in its order; the measured data, axes, passes and page left out', () => {
  const c = { ...paper, measuredPoints: [[20, 0, 1]], measured: [[1]], axes: { X: [1] }, passes: [{}], page: { view: 'normal' },
    correction: { probeNoise: 0.5, lockedAxes: ['A', 'B'], resolution: { X: 1 } } };
  const rows = inputRows(c);
  assert.deepEqual(rows[0], ['format', 'hobsharp-case/1']);
  assert.deepEqual(rows[1], ['hob.normalModule', 7]);
  assert.deepEqual(rows.find(([p]) => p === 'grid.xMax'), ['grid.xMax', 70]);
  assert.deepEqual(rows.find(([p]) => p === 'correction.lockedAxes'), ['correction.lockedAxes', ['A', 'B']]);
  assert.deepEqual(rows.find(([p]) => p === 'correction.resolution.X'), ['correction.resolution.X', 1]);
  assert.equal(rows.length, 1 + 10 + 1 + 3 + 2 + 1 + 6 + 3);
  for (const left of ['measured', 'measuredPoints', 'axes', 'passes', 'page']) assert.ok(!rows.some(([p]) => p.split('.')[0] === left), left);
  assert.deepEqual(inputRows(null), []);
});

test("the report's rows: the hob, wheel, setup, machine and grid values by group, the degree, what was derived", () => {
  const result = { setup: { settingAngle: 12.6260001234 } };
  const rows = reportRows(result, paper);
  assert.deepEqual(rows[0], ['hob', 'normalModule', '7']);
  assert.deepEqual(rows.find((r) => r[1] === 'gashLead'), ['hob', 'gashLead', '876.56']);
  assert.deepEqual(rows.map((r) => r[0]).filter((g, i, a) => a.indexOf(g) === i), ['hob', 'wheel', 'setup', 'machine', 'grid', 'axes']);
  assert.equal(rows.length, 10 + 1 + 3 + 2 + 6 + 1);
  assert.deepEqual(rows.at(-1), ['axes', 'degree', '4']);
  // The setting angle left to the calculator: the derived one, to 8 digits; the axes run named.
  const { settingAngle, ...setup } = paper.setup;
  const derived = reportRows(result, { ...paper, setup, axes: { X: [1] }, grid: { ...paper.grid, extra: { a: 1 } } });
  assert.ok(!derived.some((r) => r[1] === 'settingAngle'));
  assert.ok(!derived.some((r) => r[1] === 'extra' || r[1] === 'a'), 'nested values stay out of the report');
  assert.deepEqual(derived.at(-2), ['setup', 'settingAngle (derived)', '12.626 deg']);
  assert.deepEqual(derived.at(-1), ['axes', 'run', 'X, Y, Z, A, B as in the case']);
});

test("the report's first line names the day and what was measured: a grid, the machine's points, or nothing", () => {
  const day = new Date('2026-11-23T22:00:00Z');
  assert.equal(reportDateLine(paper, day), 'Printed 2026-11-23; no measured topography.');
  assert.equal(reportDateLine({ ...paper, measured: [[1]] }, day), 'Printed 2026-11-23; with a measured topography.');
  assert.equal(reportDateLine({ ...paper, measuredPoints: [[20, 0, 1], [30, 5, 2]] }, day),
    'Printed 2026-11-23; with a measured topography at 2 probe points.');
});

test("the report's head: the rake face's class with its conformity and the proven class", () => {
  const d = Array(12).fill(0);
  d[2] = 10;
  const c = structuredClone(paper);
  c.hob.normalModule = 5;  // pitch jump -20 µm against AA 20 µm: undecided with U95 = 2 µm, proven A
  const line = reportInspectionLine(hobsharp.evaluate({ ...c, inspection: { gashDeviations: d } }).inspection);
  assert.equal(line, 'Rake face (DIN 3968): Class AA — undecided (ISO 14253-1, U95 = 2 µm); proven class A.');
  const outside = hobsharp.evaluate({ ...paper, inspection: { tolerances: { moduleBands: [1, 2], checks: { pitchJump: { AA: [5] } } } } }).inspection;
  assert.match(reportInspectionLine(outside), /^Rake face \(DIN 3968\): Not graded: cutting-face form, radial alignment, gash lead \(/);
  assert.equal(reportInspectionLine(undefined), '');
});
