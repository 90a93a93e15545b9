// The WebAssembly half of ./hobsharp.sh bench: the same correction cycles and dense topography as
// tests/benchmark.cpp, run under Node in the benchmark module (build/wasm/hobsharp-bench.js: the
// page's module plus the timing hooks of wasm/bench_bindings.cpp), printed beside the native
// figures that the native benchmark wrote to the JSON file given as the first argument.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadHobSharp } from '../wasm/hobsharp.mjs';
import { readPoints } from '../wasm/lib/points-csv.js';

const root = path.join(path.dirname(fileURLToPath(import.meta.url)), '..');
const nativeFile = process.argv[2];
const native = {};
for (const b of JSON.parse(readFileSync(nativeFile, 'utf8')).benchmarks) {
  const perMs = { ns: 1e-6, us: 1e-3, ms: 1, s: 1e3 }[b.time_unit];
  native[b.name] = b.real_time * perMs;
}

const hobsharp = await loadHobSharp(path.join(root, 'build', 'wasm', 'hobsharp-bench.js'));
const paper = JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
const withError = (c, changes) => {
  const axes = hobsharp.evaluate(c).axes;
  for (const [axis, k, d] of changes) axes[axis][k] += d;
  return axes;
};

// The cycle: Tab. 1 on 9 x 5 with the benchmark's machine error as the measured topography.
const cycleError = [['Y', 0, 0.01], ['Z', 0, -0.01], ['Z', 1, 0.003], ['A', 0, 0.0002], ['B', 2, 0.001]];
const measured = hobsharp.evaluate({ ...paper, axes: withError(paper, cycleError) }).topography.normal;
const cycleCase = { ...paper, measured };
// The same at degree 6 on 51 x 26 (51 along the gash, 26 radially).
const big = { ...paper, degree: 6, grid: { ...paper.grid, radial: 26, axial: 51 } };
const bigCase = { ...big, measured: hobsharp.evaluate({ ...big, axes: withError(big, cycleError) }).topography.normal };
// The dense topography: 101 x 101 with its machine error.
const dense = { ...paper, grid: { ...paper.grid, radial: 101, axial: 101 } };
const denseCase = { ...dense, axes: withError(dense, [['Z', 0, -0.01], ['B', 2, 0.001]]) };

// The wheel-profile correction (docs/method.md §Wheel-profile correction): the cycle's machine error ground
// by a wheel 10 µm out of profile (a second-degree shape along the radius, as tests/benchmark.cpp),
// corrected with correction.wheel on.
const contactR = hobsharp.evaluate(paper).wheelProfile.R;
const [rMin, rMax] = [Math.min(...contactR), Math.max(...contactR)];
const worn = { ...paper, wheel: { ...paper.wheel, profileOffset: {
  R: Array.from({ length: 9 }, (_, k) => rMin + (rMax - rMin) * k / 8),
  offset: Array.from({ length: 9 }, (_, k) => 10 * (k / 4 - 1) ** 2 - 5) } } };
const wheelCase = { ...paper, measured: hobsharp.evaluate({ ...worn, axes: withError(paper, cycleError) }).topography.normal,
  correction: { ...paper.correction, wheel: true } };

// The rake-face inspection of the cycle's case with 12 gashes' deviations (as tests/benchmark.cpp).
const inspectionCase = { ...cycleCase, inspection: { gashDeviations: [0, 1.5, -2, 0.5, 3, 0, -1, 0.25, 0, 2, -0.5, 1] } };
// The same with the gear effect: a relief of 4.5 mm over 12 gashes (as tests/benchmark.cpp).
const gearCase = { ...inspectionCase, hob: { ...inspectionCase.hob, gashes: 12, relief: 4.5 } };

const best = (f, runs, repeats = 5) => Math.min(...Array.from({ length: repeats }, () => f(runs)));
// Reading and correcting 2,000 measured points (docs/measured-points.md): the page's and the
// CLI's reader (wasm/lib/points-csv.js) on tests/data/points-2000.csv, plus evaluate() in the module.
const pointsCsv = readFileSync(path.join(root, 'tests', 'data', 'points-2000.csv'), 'utf8');
const pointsCase = { ...paper, measuredPoints: readPoints(pointsCsv).points };
const readPointsMs = best((n) => {
  const t = performance.now();
  for (let i = 0; i < n; i++) readPoints(pointsCsv);
  return (performance.now() - t) / n;
}, 20);
const wasm = {
  CorrectionCycle: best((n) => hobsharp.timeCorrectionCycle(JSON.stringify(cycleCase), n), 200),
  WheelCorrectionCycle: best((n) => hobsharp.timeCorrectionCycle(JSON.stringify(wheelCase), n), 200),
  CorrectionCycle51x26Degree6: best((n) => hobsharp.timeCorrectionCycle(JSON.stringify(bigCase), n), 5, 3),
  DenseTopography101: best((n) => hobsharp.timeTopography(JSON.stringify(denseCase), n), 10),
  InspectionPaperCase: best((n) => hobsharp.timeInspection(JSON.stringify(inspectionCase), n), 2000),
  CorrectPoints2000: readPointsMs + best((n) => hobsharp.timeCorrectionCycle(JSON.stringify(pointsCase), n), 3, 3),
  InspectionAndGearEffectPaperCase: best((n) => hobsharp.timeInspectionAndGearEffect(JSON.stringify(gearCase), n), 100),
};
// End to end from JS, with the case in and the plain-JS result out (what the page's worker pays).
const t0 = performance.now();
for (let i = 0; i < 100; i++) hobsharp.evaluate(cycleCase);
const endToEnd = (performance.now() - t0) / 100;

const rows = [
  ['correction cycle (Tab. 1, 9 x 5, 25 coefficients)', 'CorrectionCycle', 1],
  ['correction cycle with the wheel (Tab. 1, 9 x 5, degree 4)', 'WheelCorrectionCycle', 2],
  ['correction cycle (51 x 26, degree 6, 35 coefficients)', 'CorrectionCycle51x26Degree6', 50],
  ['dense 101 x 101 topography', 'DenseTopography101', 15],
  ['rake-face inspection (Tab. 1, 9 x 5, 12 gashes)', 'InspectionPaperCase', 5],
  ['reading and correcting 2,000 measured points (CSV)', 'CorrectPoints2000', 20],
  ['inspection and gear effect (Tab. 1, 12 gashes, relief)', 'InspectionAndGearEffectPaperCase', 5],
];
console.log('\nnative versus WebAssembly (Node ' + process.version + '), ms per run:');
console.log('benchmark'.padEnd(52) + 'native'.padStart(10) + 'wasm'.padStart(10) + 'wasm/native'.padStart(13));
for (const [label, key] of rows) {
  const n = native[key], w = wasm[key];
  console.log(label.padEnd(52) + n.toFixed(3).padStart(10) + w.toFixed(3).padStart(10) + (w / n).toFixed(2).padStart(12) + 'x');
}
console.log(`evaluate(case) end to end in JS, with the result as plain JS data: ${endToEnd.toFixed(3)} ms`);
console.log(`of the 2,000 points, reading the CSV in JS: ${readPointsMs.toFixed(3)} ms`);
console.log('target: wasm within 1.5x native');
