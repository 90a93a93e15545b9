// The rake-face inspection through the WebAssembly module (README "Rake-face inspection"): a
// measured face with a known radial tilt and gash lead slope, one gash mis-indexed by 10 µm and
// its indexing correction, an edited tolerance table, the same figures as the native build, and
// bad inspection input refused with the field named while the module stays usable.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { loadHobSharp, HobSharpError } from '../../wasm/hobsharp.mjs';
import { native, paper, root } from './native-build.mjs';

const hobsharp = await loadHobSharp();

// The paper's grid: radii 19 .. 40 mm (5), axial positions -70 .. 70 mm (9).
const R = [19, 24.25, 29.5, 34.75, 40];
const X = [-70, -52.5, -35, -17.5, 0, 17.5, 35, 52.5, 70];
const grid = (f) => R.map((r) => X.map((x) => f(r, x)));

test('a measured tilt along the radius and a gash lead slope, each known by hand', () => {
  // 0.5 µm per mm of radius rises 10.5 µm from root to tip; 0.04 µm per mm along the hob is 4 µm per 100 mm.
  const c = { ...paper(), measured: grid((r, x) => 0.5 * (r - 19) + 0.04 * x), correction: { probeNoise: 1e-4 } };
  const inspection = hobsharp.evaluate(c).inspection;
  assert.equal(inspection.source, 'measured');
  assert.ok(Math.abs(inspection.radialAlignment - 10.5) < 1e-9, `radial alignment ${inspection.radialAlignment}`);
  assert.ok(Math.abs(inspection.gashLead - 4) < 1e-9, `gash lead ${inspection.gashLead}`);
  assert.ok(Math.abs(inspection.cuttingFaceForm) < 1e-9, `form ${inspection.cuttingFaceForm}`);
  // No tolerance for these in the default table: not graded, said so.
  assert.equal(inspection.class, 'not graded');
  assert.equal(inspection.limitingCheck, '');
  assert.equal(inspection.checks.radialAlignment.grade, 'not graded');
  assert.deepEqual(inspection.checks.radialAlignment.classes, []);
  // The correction exists, so the verdict after it is there, side by side.
  assert.ok(inspection.after, 'inspection.after');
  assert.equal(typeof inspection.after.radialAlignment, 'number');
});

test('one gash mis-indexed by 10 µm: spacing, its class, the indexing correction, the class after', () => {
  const d = Array(12).fill(0);
  d[2] = 10;
  const c = { ...paper(), inspection: { gashDeviations: d } };
  const r = hobsharp.evaluate(c);
  const i = r.inspection;
  assert.equal(i.adjacentSpacing, 10);
  assert.equal(i.cumulativeSpacing, 10);
  assert.deepEqual(Array.from(i.spacing.adjacent), [0, 10, -10, 0, 0, 0, 0, 0, 0, 0, 0, 0]);
  // Module 7 is over 6.3 to 10: AA 25 µm for both spacing checks.
  assert.equal(i.moduleBand, 'over 6.3 to 10 mm');
  assert.equal(i.class, 'AA');
  assert.deepEqual(Array.from(i.checks.adjacentSpacing.tolerances), [25, 40, 80, 160, 315]);
  // Gash 3 turns back against the others by 10 µm worth of A.
  const perRadian = 10 / ((i.indexCorrection[0] - i.indexCorrection[2]) * 1e-6);
  assert.ok(perRadian > 29000 && perRadian < 32000, `about 30 mm of normal deviation per rad at the pitch radius: ${perRadian}`);
  assert.ok(i.indexCorrectionDeg.every((a, k) => Math.abs(a - i.indexCorrection[k] * 1e-6 * 180 / Math.PI) <= 0.5e-4 + 1e-12),
    'rounded to 0.0001 deg');
  assert.ok(i.after.cumulativeSpacing < i.cumulativeSpacing / 10, `after: ${i.after.cumulativeSpacing}`);
  assert.equal(i.after.class, 'AA');
  // The native build gives the same figures.
  const n = native(c).inspection;
  assert.deepEqual(Array.from(i.indexCorrection), n.indexCorrection);
  assert.equal(i.after.cumulativeSpacing, n.after.cumulativeSpacing);
});

test('an edited tolerance table grades the face checks and names the one that limits', () => {
  const c = {
    ...paper(),
    measured: grid((r) => 1.0 * (r - 19)),  // 21 µm root to tip
    inspection: {
      gashDeviations: [0, 30, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0],
      tolerances: {
        moduleBands: [6.3, 10],
        checks: {
          radialAlignment: { AA: [10], A: [16], B: [32], C: [63] },
          adjacentSpacing: { AA: [25], A: [40] },
        },
      },
    },
  };
  const i = hobsharp.evaluate(c).inspection;
  assert.equal(i.checks.radialAlignment.grade, 'B');
  assert.equal(i.checks.adjacentSpacing.grade, 'A');
  assert.equal(i.checks.cumulativeSpacing.grade, 'not graded');
  assert.equal(i.class, 'B');
  assert.equal(i.limitingCheck, 'radialAlignment');
  assert.deepEqual(Array.from(i.checks.radialAlignment.classes), ['AA', 'A', 'B', 'C']);
});

test('bad inspection input is refused naming the field, and the module stays usable', () => {
  const cases = [
    [{ gashDeviations: [3] }, 'inspection.gashDeviations'],
    [{ gashDeviations: [3, 'x'] }, 'inspection.gashDeviations[1]'],
    [{ gashDeviations: [3, 1e6] }, 'inspection.gashDeviations[1]'],
    [{ tolerances: { moduleBands: [1, 2], checks: { adjacentSpacing: { AA: [-4] } } } },
      'inspection.tolerances.checks.adjacentSpacing.AA[0]'],
    [{ tolerances: { moduleBands: [2, 1], checks: {} } }, 'inspection.tolerances.moduleBands[1]'],
    [{ tolerances: { moduleBands: [1, 2] } }, 'inspection.tolerances.checks'],
    [{ verdict: 'A' }, 'inspection.verdict'],
  ];
  for (const [inspection, field] of cases) {
    assert.throws(() => hobsharp.evaluate({ ...paper(), inspection }), (e) => {
      assert.ok(e instanceof HobSharpError, `a HobSharpError for ${field}`);
      assert.equal(e.field, field);
      assert.ok(e.message.startsWith(`${field}: `), e.message);
      return true;
    });
  }
  assert.equal(hobsharp.evaluate(paper()).inspection.source, 'simulated');
});

test('limits() gives the default tolerance table as data/din3968-cutting-face.json has it, in the shape a case takes', () => {
  const limits = hobsharp.limits().inspection;
  assert.deepEqual(limits.checks, ['cuttingFaceForm', 'radialAlignment', 'gashLead', 'adjacentSpacing', 'cumulativeSpacing']);
  assert.deepEqual(limits.classes, ['AA', 'A', 'B', 'C', 'D']);
  assert.equal(limits.maxGashes, 100);
  const data = JSON.parse(readFileSync(path.join(root, 'data', 'din3968-cutting-face.json'), 'utf8'));
  const table = limits.defaultTolerances;
  assert.deepEqual(table.moduleBands, data.moduleBands);
  assert.deepEqual(Object.keys(table.checks), Object.keys(data.checks));
  for (const [check, rows] of Object.entries(data.checks)) assert.deepEqual(table.checks[check], rows, check);
  // Given back as the case's table, it grades exactly as the default does.
  const d = [0, 0, 30, 0, 0, 0, 0, 0, 0, 0, 0, 0];
  const byDefault = hobsharp.evaluate({ ...paper(), inspection: { gashDeviations: d } }).inspection;
  const byCase = hobsharp.evaluate({ ...paper(), inspection: { gashDeviations: d, tolerances: table } }).inspection;
  assert.deepEqual(byCase.checks, byDefault.checks);
  assert.equal(byCase.class, 'A');
});

test('measuredPoints at the grid positions give the grid result exactly; a point off the face is refused by name', () => {
  const measured = grid((r, x) => 0.3 * (r - 19) - 0.02 * x + 0.01 * (r - 29.5) ** 2);
  const byGrid = hobsharp.evaluate({ ...paper(), measured });
  const points = R.flatMap((r, i) => X.map((x, j) => [r, x, measured[i][j]])).reverse();
  const byPoints = hobsharp.evaluate({ ...paper(), measuredPoints: points });
  assert.equal(byPoints.inspection.source, 'measuredPoints');
  assert.deepEqual(byPoints.correction, byGrid.correction);
  assert.deepEqual({ ...byPoints.inspection, source: '' }, { ...byGrid.inspection, source: '' });
  points[5] = [5, 0, 1];
  assert.throws(() => hobsharp.evaluate({ ...paper(), measuredPoints: points }), (e) => {
    assert.ok(e instanceof HobSharpError);
    assert.equal(e.field, 'measuredPoints[5]');
    assert.match(e.message, /off the rake face/);
    return true;
  });
});
