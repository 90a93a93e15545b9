// The rake-face inspection through the WebAssembly module (docs/inspection.md): a measured face
// with a known radial tilt and gash lead slope, one gash mis-indexed by 10 µm and its indexing
// correction, the single pitch and the pitch jump, the measurement's uncertainty and ISO 14253-1
// conformity, the rake error, an edited tolerance table, the same figures as the native build, and
// bad inspection input refused with the field named while the module stays usable.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { loadHobSharp, HobSharpError } from '../../wasm/hobsharp.mjs';
import { native, paper, root } from './native-build.mjs';
import { classLead } from '../../web/src/inspection-table.js';

const hobsharp = await loadHobSharp();

// The paper's grid: radii 19 .. 40 mm (5), axial positions -70 .. 70 mm (9).
const R = [19, 24.25, 29.5, 34.75, 40];
const X = [-70, -52.5, -35, -17.5, 0, 17.5, 35, 52.5, 70];
const grid = (f) => R.map((r) => X.map((x) => f(r, x)));

// DIN 3968's indicator by hand (docs/inspection.md, section 1): on the paper's helical zero-rake
// face the line's distance from the axis is s = r, the offset across the line d = δn / cos λ with
// tan λ = r / p (p the gash lead over 2π), and the reading d(r) - d(r_tip) r / r_tip, zeroed at the
// tip. The figure: the reading of largest magnitude over every row of every axial line, signed.
const P = 876.56 / (2 * Math.PI);
const acrossLine = (r) => 1 / Math.sqrt(1 + (r / P) ** 2);
function indicator(f) {
  let best = 0;
  for (const x of X) {
    const d = (r) => f(r, x) / acrossLine(r);
    for (const r of R) {
      const reading = d(r) - d(40) * r / 40;
      if (Math.abs(reading) > Math.abs(best)) best = reading;
    }
  }
  return best;
}

test('a measured tilt along the radius and a gash lead slope, each known by hand', () => {
  // 0.5 µm per mm of radius rises 10.5 µm from root to tip; 0.04 µm per mm along the hob is 4 µm per 100 mm.
  const f = (r, x) => 0.5 * (r - 19) + 0.04 * x;
  const c = { ...paper(), measured: grid(f), correction: { probeNoise: 1e-4 } };
  const inspection = hobsharp.evaluate(c).inspection;
  assert.equal(inspection.source, 'measured');
  // The indicator zeroed at the tip: at the root of the axial line at x = -70 mm, about -6.63 µm.
  const expected = indicator(f);
  assert.ok(Math.abs(expected + 6.6307) < 1e-3, `by hand ${expected}`);
  assert.ok(Math.abs(inspection.radialAlignment - expected) < 1e-6, `radial alignment ${inspection.radialAlignment}, by hand ${expected}`);
  assert.ok(Math.abs(inspection.gashLead - 4) < 1e-9, `gash lead ${inspection.gashLead}`);
  assert.ok(Math.abs(inspection.cuttingFaceForm) < 1e-9, `form ${inspection.cuttingFaceForm}`);
  // The default table grades the radial alignment (AA 25 µm over 6.3 to 10 mm, printed) and the
  // gash lead (AA 50 µm per 100 mm); the form has no row: not graded, said so with what to enter.
  assert.equal(inspection.class, 'AA');
  assert.equal(inspection.limitingCheck, 'radialAlignment');
  assert.equal(inspection.checks.radialAlignment.grade, 'AA');
  assert.equal(inspection.checks.radialAlignment.confidence, 'printed');
  assert.deepEqual(inspection.checks.radialAlignment.classes, ['AA', 'A', 'B', 'C', 'D']);
  assert.equal(inspection.checks.gashLead.grade, 'AA');
  assert.deepEqual(inspection.checks.gashLead.classes, ['AA', 'A', 'B']);
  assert.equal(inspection.checks.cuttingFaceForm.grade, 'not graded');
  assert.equal(inspection.checks.cuttingFaceForm.confidence, '');
  assert.match(inspection.notGraded, /^Not graded: cutting-face form \(the tolerance table has no value for the module band over 6\.3 to 10 mm\)\. Enter the hob maker's tolerances/);
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
  // The pitch jump f_uN: each single pitch deviation minus the one before (pitch 1 minus pitch 12).
  assert.equal(i.pitchJump, -20);
  assert.deepEqual(Array.from(i.spacing.pitchJump), [0, 10, -20, 10, 0, 0, 0, 0, 0, 0, 0, 0]);
  assert.ok(!('cumulativeSpacing' in i.checks), 'the cumulative spread is information, not graded');
  // Module 7 is over 6.3 to 10: AA 25 µm for both spacing checks.
  assert.equal(i.moduleBand, 'over 6.3 to 10 mm');
  assert.equal(i.class, 'AA');
  assert.deepEqual(Array.from(i.checks.adjacentSpacing.tolerances), [25, 40, 80, 160, 315]);
  assert.deepEqual(Array.from(i.checks.pitchJump.tolerances), [25, 40, 80, 160, 315]);
  assert.equal(i.checks.pitchJump.grade, 'AA');
  assert.equal(i.limitingCheck, 'pitchJump', 'the pitch jump (20 of 25 µm) before the single pitch (10 of 25 µm)');
  // Gash 3 turns back against the others by 10 µm worth of A.
  const perRadian = 10 / ((i.indexCorrection[0] - i.indexCorrection[2]) * 1e-6);
  assert.ok(perRadian > 29000 && perRadian < 32000, `about 30 mm of normal deviation per rad at the pitch radius: ${perRadian}`);
  assert.ok(i.indexCorrectionDeg.every((a, k) => Math.abs(a - i.indexCorrection[k] * 1e-6 * 180 / Math.PI) <= 0.5e-4 + 1e-12),
    'rounded to 0.0001 deg');
  assert.ok(i.after.cumulativeSpacing < i.cumulativeSpacing / 10, `after: ${i.after.cumulativeSpacing}`);
  assert.ok(Math.abs(i.after.pitchJump) < Math.abs(i.pitchJump) / 10, `after: ${i.after.pitchJump}`);
  assert.equal(i.after.class, 'AA');
  // The native build gives the same figures.
  const n = native(c).inspection;
  assert.deepEqual(Array.from(i.indexCorrection), n.indexCorrection);
  assert.equal(i.after.cumulativeSpacing, n.after.cumulativeSpacing);
  assert.deepEqual(Array.from(i.spacing.pitchJump), n.spacing.pitchJump);
  assert.equal(i.after.pitchJump, n.after.pitchJump);
});

test('an edited tolerance table grades the face checks and names the one that limits', () => {
  const c = {
    ...paper(),
    // 42 µm root to tip: the indicator zeroed at the tip reads about -20.8 µm at the root.
    measured: grid((r) => 2.0 * (r - 19)),
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
  assert.ok(Math.abs(i.radialAlignment - indicator((r) => 2.0 * (r - 19))) < 1e-6, `radial alignment ${i.radialAlignment}`);
  assert.equal(i.checks.adjacentSpacing.grade, 'A');
  assert.equal(i.checks.pitchJump.grade, 'not graded', 'the case\'s table has no pitch jump row');
  assert.equal(i.class, 'B');
  assert.equal(i.limitingCheck, 'radialAlignment');
  assert.deepEqual(Array.from(i.checks.radialAlignment.classes), ['AA', 'A', 'B', 'C']);
  // The case's own table: its cells "entered", its source named as such.
  assert.equal(i.checks.radialAlignment.confidence, 'entered');
  assert.equal(i.checks.radialAlignment.source, "the case's own table (inspection.tolerances)");
  assert.match(i.notGraded, /pitch jump/);
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
    [{ tolerances: { moduleBands: [1, 2], checks: { cumulativeSpacing: { AA: [4] } } } }, 'inspection.tolerances.checks.cumulativeSpacing'],
    [{ tolerances: { moduleBands: [1, 2], checks: { pitchJump: { AA: [4], confidence: { AA: ['guessed'] } } } } },
      'inspection.tolerances.checks.pitchJump.confidence.AA[0]'],
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
  assert.deepEqual(limits.checks, ['cuttingFaceForm', 'radialAlignment', 'gashLead', 'adjacentSpacing', 'pitchJump']);
  assert.deepEqual(limits.classes, ['AA', 'A', 'B', 'C', 'D']);
  assert.equal(limits.maxGashes, 100);
  assert.deepEqual(limits.uncertainty, { default: 2, min: 0, max: 100, unit: 'µm' });
  const data = JSON.parse(readFileSync(path.join(root, 'data', 'din3968-cutting-face.json'), 'utf8'));
  const table = limits.defaultTolerances;
  assert.deepEqual(table.moduleBands, data.moduleBands);
  assert.deepEqual(Object.keys(table.checks), Object.keys(data.checks));
  for (const [check, rows] of Object.entries(data.checks)) assert.deepEqual(table.checks[check], rows, check);
  // Given back as the case's table, it grades exactly as the default does.
  const d = [0, 0, 30, 0, 0, 0, 0, 0, 0, 0, 0, 0];
  const byDefault = hobsharp.evaluate({ ...paper(), inspection: { gashDeviations: d } }).inspection;
  const byCase = hobsharp.evaluate({ ...paper(), inspection: { gashDeviations: d, tolerances: table } }).inspection;
  // The same grades; only where the tolerances come from differs: the case's own table, whose
  // cells the data file marks keep their marks (radial alignment), the others are "entered".
  const bare = (checks) => Object.fromEntries(Object.entries(checks).map(([k, { source, confidence, ...rest }]) => [k, rest]));
  assert.deepEqual(bare(byCase.checks), bare(byDefault.checks));
  assert.equal(byCase.checks.radialAlignment.confidence, byDefault.checks.radialAlignment.confidence);
  assert.equal(byCase.checks.adjacentSpacing.confidence, 'entered');
  assert.equal(byDefault.checks.adjacentSpacing.confidence, 'printed');
  // Gash 3 at 30 µm: single pitch 30 µm (A), pitch jump -60 µm (B, DIN 3968 item 9).
  assert.equal(byCase.pitchJump, -60);
  assert.equal(byCase.class, 'B');
  assert.equal(byCase.limitingCheck, 'pitchJump');
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

test("the docs' worked example: 12 gashes, gash 3 at +10 µm, module 5: single pitch +10, pitch jump -20, AA but undecided", () => {
  const d = Array(12).fill(0);
  d[2] = 10;
  const c = paper();
  c.hob.normalModule = 5;  // the band over 4 to 6.3 mm: AA 20 µm for both spacing rows
  const i = hobsharp.evaluate({ ...c, inspection: { gashDeviations: d } }).inspection;
  assert.equal(i.moduleBand, 'over 4 to 6.3 mm');
  assert.equal(i.adjacentSpacing, 10);
  assert.equal(i.pitchJump, -20);
  assert.equal(i.cumulativeSpacing, 10);
  assert.equal(i.uncertainty, 2, 'U95 2 µm when the case gives none');
  const jump = i.checks.pitchJump;
  assert.equal(jump.grade, 'AA');
  assert.equal(jump.conformity, 'undecided', '20 µm lies within U of the tolerance 20 µm');
  assert.equal(jump.provenGrade, 'A', 'A: 32 - 2 = 30 µm holds 20 µm');
  assert.equal(jump.confidence, 'printed');
  assert.match(jump.source, /Tungaloy .* item 9/);
  assert.equal(jump.uncertainty, 2);
  assert.equal(i.checks.adjacentSpacing.conformity, 'conforms');
  assert.equal(i.class, 'AA');
  assert.equal(i.limitingCheck, 'pitchJump');
  // The face is the simulated one (nothing measured): the hob's conformity and proven class rest on
  // it too, so neither is decided; the measured gash deviations keep their own.
  assert.equal(i.source, 'simulated');
  assert.equal(i.conformity, 'not decided');
  assert.equal(i.provenClass, 'not decided');
  assert.equal(i.checks.radialAlignment.conformity, 'not decided');
  assert.equal(i.checks.radialAlignment.provenGrade, 'not decided');
  assert.equal(i.uncertaintyWarning, '', 'U = 2 µm is a tenth of 20 µm, not more');
  // Measured on the grid (the same face, as measured), the class is decided as the pitch jump says.
  const measured = hobsharp.evaluate({ ...c, measured: grid(() => 0), correction: { probeNoise: 1e-4 }, inspection: { gashDeviations: d } }).inspection;
  assert.equal(measured.source, 'measured');
  assert.equal(measured.conformity, 'undecided');
  assert.equal(measured.provenClass, 'A');
});

// A measured gash spacing beyond the table plus U decides on a simulated face too: the hob does not
// conform, whatever the face (an independent review: it read "not decided").
test('on a simulated face a measured gash spacing beyond the table plus U still decides: does not conform, proven none', () => {
  const c = paper();
  c.hob.normalModule = 5;
  const d = Array(12).fill(0);
  d[2] = 500;
  const i = hobsharp.evaluate({ ...c, inspection: { gashDeviations: d } }).inspection;
  assert.equal(i.source, 'simulated');
  assert.equal(i.class, 'outside D');
  assert.equal(i.checks.pitchJump.conformity, 'does not conform');
  assert.equal(i.conformity, 'does not conform');
  assert.equal(i.provenClass, 'none');
  const lead = classLead(i);
  assert.equal(lead.conformity, 'does not conform');
  assert.match(lead.text, /^Class outside D — does not conform \(ISO 14253-1: the gashes' spacing measured is beyond the tolerance plus U95; the face is not measured\); proven class: none$/);
});

test('a simulated face (nothing measured) proves no class: conformity and proven class "not decided"', () => {
  const i = hobsharp.evaluate(paper()).inspection;
  assert.equal(i.source, 'simulated');
  assert.notEqual(i.class, 'not graded');
  assert.equal(i.conformity, 'not decided');
  assert.equal(i.provenClass, 'not decided');
  for (const k of ['radialAlignment', 'gashLead']) {
    assert.equal(i.checks[k].conformity, 'not decided', k);
    assert.equal(i.checks[k].provenGrade, 'not decided', k);
  }
});

test('the uncertainty from the case changes the conformity and the proven class, not the class', () => {
  // The paper's face moved 47.5 µm out of the tooth (excess material): the indicator zeroed at the
  // tip reads about 24.47 µm at the root, within AA's 25 µm (printed); A's 40 µm is a series value.
  const u = 47.5;
  const measured = grid(() => u);
  const expected = indicator(() => u);
  assert.ok(Math.abs(expected - 24.467) < 1e-3, `by hand ${expected}`);
  const at = (uncertainty) => hobsharp.evaluate({ ...paper(), measured, correction: { probeNoise: 1e-4 },
    inspection: uncertainty === undefined ? undefined : { uncertainty } }).inspection;
  const exact = at(0), shop = at(undefined), coarse = at(3);
  for (const i of [exact, shop, coarse]) {
    assert.ok(Math.abs(i.radialAlignment - expected) < 1e-6, `radial alignment ${i.radialAlignment}`);
    assert.equal(i.class, 'AA');
    assert.equal(i.checks.radialAlignment.grade, 'AA');
    assert.equal(i.checks.radialAlignment.confidence, 'printed');
  }
  assert.equal(exact.uncertainty, 0);
  assert.equal(exact.conformity, 'conforms');
  assert.equal(exact.provenClass, 'AA');
  assert.equal(exact.uncertaintyWarning, '');
  // U = 2 µm: 24.47 µm lies between 25 - 2 and 25 + 2 µm. Proven is A, whose value is a series one.
  assert.equal(shop.uncertainty, 2);
  assert.equal(shop.checks.radialAlignment.conformity, 'undecided');
  assert.equal(shop.checks.radialAlignment.provenGrade, 'A');
  assert.equal(shop.conformity, 'undecided');
  assert.equal(shop.provenClass, 'A');
  // U = 3 µm: more than a tenth of 25 µm, named.
  assert.equal(coarse.uncertaintyWarning, 'radialAlignment');
  assert.equal(coarse.checks.radialAlignment.uncertainty, 3);
  // The gash lead's U is per 100 mm over the 140 mm measured along the hob.
  assert.ok(Math.abs(coarse.checks.gashLead.uncertainty - 3 * 100 / 140) < 1e-12, `${coarse.checks.gashLead.uncertainty}`);
  // The excess material is a drag: the rake error as an angle at the tip and as an offset.
  assert.ok(exact.rakeOffset < 0 && exact.rakeAngle < 0, `${exact.rakeOffset} mm, ${exact.rakeAngle} arc-min`);
  assert.ok(Math.abs(exact.rakeOffset + u / 1000) < 0.05 * u / 1000, `rake offset ${exact.rakeOffset} mm`);
  assert.ok(Math.abs(exact.rakeAngle - exact.rakeOffset / 40 * 10800 / Math.PI) < 1e-9, `rake angle ${exact.rakeAngle} arc-min`);
});

test("with the hob's relief the rake error's effect on the gear's pressure angle; without it none", () => {
  const measured = grid(() => -30);  // material taken off: a hook
  const c = { ...paper(), measured, correction: { probeNoise: 1e-4 } };
  const bare = hobsharp.evaluate(c);
  assert.ok(bare.inspection.rakeAngle > 0, `hook ${bare.inspection.rakeAngle}`);
  assert.equal(bare.gearEffect.pressureAnglePerDegreeOfRake, undefined);
  assert.equal(bare.gearEffect.rakeErrorPressureAngle, undefined);
  const relieved = hobsharp.evaluate({ ...c, hob: { ...c.hob, gashes: 12, relief: 4.5 } });
  const g = relieved.gearEffect;
  // A hook gives the gear a smaller pressure angle (docs/inspection.md, section 2).
  assert.ok(g.pressureAnglePerDegreeOfRake < 0, `${g.pressureAnglePerDegreeOfRake} arc-min per deg`);
  const expected = g.pressureAnglePerDegreeOfRake * relieved.inspection.rakeAngle / 60;
  assert.ok(Math.abs(g.rakeErrorPressureAngle - expected) <= 1e-9 * Math.abs(expected), `${g.rakeErrorPressureAngle} against ${expected}`);
  assert.ok(g.rakeErrorPressureAngle < 0);
});

test('inspection.uncertainty out of range is refused with a clear Error naming it; the module lives on', () => {
  for (const uncertainty of [-1, 100.5, 1e9, 'two', null]) {
    assert.throws(() => hobsharp.evaluate({ ...paper(), inspection: { uncertainty } }), (e) => {
      assert.ok(e instanceof HobSharpError && e instanceof Error, `an Error for ${uncertainty}`);
      assert.equal(e.field, 'inspection.uncertainty');
      assert.ok(e.message.startsWith('inspection.uncertainty: '), e.message);
      if (typeof uncertainty === 'number') assert.match(e.message, /U95 in µm, 0 to 100/);
      return true;
    });
  }
  for (const uncertainty of [0, 100]) assert.equal(hobsharp.evaluate({ ...paper(), inspection: { uncertainty } }).inspection.uncertainty, uncertainty);
  assert.equal(hobsharp.evaluate(paper()).inspection.uncertainty, 2);
});

test("a case table's own marks: a series cell is said so, with the case's table as the source", () => {
  const c = {
    ...paper(),
    measured: grid((r) => 2.0 * (r - 19)),  // about -20.8 µm on the indicator
    correction: { probeNoise: 1e-4 },
    inspection: {
      tolerances: {
        moduleBands: [6.3, 10],
        checks: { radialAlignment: { seriesSource: 'a series', AA: [10], A: [16], B: [32], confidence: { AA: ['printed'], B: ['series'] } } },
      },
    },
  };
  const i = hobsharp.evaluate(c).inspection;
  assert.equal(i.checks.radialAlignment.grade, 'B');
  assert.equal(i.checks.radialAlignment.confidence, 'series');
  assert.equal(i.checks.radialAlignment.source, "the case's own table (inspection.tolerances)");
  assert.equal(i.checks.gashLead.grade, 'not graded');
  assert.match(i.notGraded, /^Not graded: cutting-face form, gash lead \(/);
});

// With a measured grid and one topography per gash, "after" is each gash less what the pass removes
// on the grid (the same axes grind every gash), the worst of them, as "before" is: not the measured
// grid's residual alone (an independent review: gash 3 at 200 µm read class D before and AA after).
test('with per-gash topographies, after is every gash less what the pass removes, the worst of them', () => {
  const measured = grid((r, x) => 0.5 * (r - 19) + 0.04 * x);
  const c = { ...paper(), measured, correction: { probeNoise: 1e-4 } };
  const alone = hobsharp.evaluate(c).inspection;
  // Every gash as measured: the same figures after as the measured grid's alone.
  const same = hobsharp.evaluate({ ...c, inspection: { gashTopographies: [measured, measured, measured, measured] } }).inspection;
  assert.equal(same.source, 'gashTopographies');
  for (const k of ['cuttingFaceForm', 'radialAlignment', 'gashLead']) {
    assert.ok(Math.abs(same.after[k] - alone.after[k]) < 1e-9, `${k}: ${same.after[k]} against ${alone.after[k]}`);
  }
  // Gash 3 stands out 200 µm more at the tip than at the root: its pitch jump makes the class D,
  // its radial alignment about -105 µm (C). After the pass and the re-indexing the spacing is gone
  // and gash 3's alignment stays about as it was (the pass removes the measured grid's error, not
  // gash 3's own): class C, limited by the radial alignment; the measured grid alone would read AA.
  const tilted = grid((r, x) => 0.5 * (r - 19) + 0.04 * x + 200 * (r - 19) / 21);
  const worst = hobsharp.evaluate({ ...c, inspection: { gashTopographies: [measured, measured, tilted, measured] } }).inspection;
  assert.equal(worst.class, 'D');
  assert.equal(worst.checks.radialAlignment.grade, 'C');
  assert.equal(worst.after.class, 'C');
  assert.equal(worst.after.limitingCheck, 'radialAlignment');
  assert.ok(Math.abs(worst.after.radialAlignment) > 0.9 * Math.abs(worst.radialAlignment), `${worst.after.radialAlignment} against ${worst.radialAlignment}`);
  assert.ok(Math.abs(alone.after.radialAlignment) < 1, `the measured grid's own after: ${alone.after.radialAlignment}`);
});
