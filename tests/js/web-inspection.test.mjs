// The rake-face inspection as the page shows it (web/src/inspection-table.js), from the module's
// result: the class with its conformity and proven class, the verdict sentence, the uncertainty's
// warning, the rake error, and the rows of checks, measured and after the correction.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { checkValueText, classLead, cumulativeText, inspectionRows, rakeText, uncertaintyWarningText, verdictSentence, withUnit } from '../../web/src/inspection-table.js';
import { setResultFields } from '../../web/src/result-fields.js';
import { cellConfidence, cellConfidenceOf, tableInUse, withCell } from '../../web/src/tolerance-edit.js';

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const hobsharp = await loadHobSharp();
setResultFields(hobsharp.resultFields());  // the units, as the page has them once the calculator is ready
const grid = (f) => Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (_, j) => f(i, j)));

test('the verdict names the class, the limiting check and the class after the correction', () => {
  const measured = grid((i) => 3 * i);
  const gashDeviations = [0, 1.5, -2, 0.5, 3, 0, -1, 0.25, 0, 2, -0.5, 1];
  const r = hobsharp.evaluate({ ...paper, measured, inspection: { gashDeviations } });
  const text = verdictSentence(r.inspection);
  // The pitch jump (6 of 25 µm) limits, just before the radial alignment (5.9 of 25 µm).
  assert.match(text, new RegExp(`^Rake face \\(DIN 3968, module band over 6\\.3 to 10 mm, measured face\\): class ${r.inspection.class} \\(limited by the pitch jump\\); after the correction, if the identified error is all of the machine's: class ${r.inspection.after.class}`));
  const rows = inspectionRows(r.inspection);
  assert.deepEqual(rows.map((x) => x.check), ['cuttingFaceForm', 'radialAlignment', 'gashLead', 'adjacentSpacing', 'pitchJump']);
  assert.deepEqual(rows.map((x) => x.label), ['cutting-face form', 'radial alignment', 'gash lead', 'single pitch (adjacent spacing)', 'pitch jump']);
  const jump = rows.find((x) => x.check === 'pitchJump');
  assert.equal(jump.value, 6);
  assert.equal(jump.grade, r.inspection.checks.pitchJump.grade);
  assert.match(jump.tolerances, /^AA [\d.]+ · A [\d.]+/);
  assert.ok(Math.abs(jump.after.value - r.inspection.after.pitchJump) < 1e-12);
  // The cumulative spread is information under the table, not a row.
  assert.equal(cumulativeText(r.inspection), `Cumulative spread of the cutting faces (largest minus smallest gash deviation; information, not graded): 5.000 µm; predicted after the correction ${
    r.inspection.after.cumulativeSpacing.toFixed(3)} µm.`);
  const radial = rows.find((x) => x.check === 'radialAlignment');
  assert.ok(radial.value < -5.9 && radial.value > -6, `the indicator zeroed at the tip: ${radial.value}`);
  assert.equal(radial.tolerances, 'AA 25 · A 40 · B 80 · C 160 · D 315');
  assert.equal(radial.unit, 'µm');
  assert.equal(rows.find((x) => x.check === 'gashLead').unit, 'µm per 100 mm', 'the unit the result states');
  const form = rows.find((x) => x.check === 'cuttingFaceForm');
  assert.equal(form.tolerances, 'none in the table');
  assert.equal(form.grade, 'not graded');
  assert.equal(form.proven, '');
});

test('the class leads with its conformity and the proven class; side by side when they differ', () => {
  const d = Array(12).fill(0);
  d[2] = 10;
  const c = structuredClone(paper);
  c.hob.normalModule = 5;
  c.measured = grid(() => 0);  // a measured face: the conformity is decided on it
  const i = hobsharp.evaluate({ ...c, inspection: { gashDeviations: d } }).inspection;
  const lead = classLead(i);
  assert.equal(lead.graded, true);
  assert.equal(lead.same, false);
  assert.equal(lead.classText, 'Class AA — undecided (ISO 14253-1, U95 = 2 µm)');
  assert.equal(lead.provenText, 'proven class A');
  assert.equal(lead.text, 'Class AA — undecided (ISO 14253-1, U95 = 2 µm); proven class A');
  const exact = classLead(hobsharp.evaluate({ ...c, inspection: { gashDeviations: d, uncertainty: 0 } }).inspection);
  assert.equal(exact.same, true);
  assert.equal(exact.text, 'Class AA — conforms (ISO 14253-1, U95 = 0 µm); proven class AA');
  assert.equal(classLead(undefined), null);
});

test('on the simulated face the class decides nothing: no conformity, no proven class, none per check', () => {
  // Nothing measured: the face inspected is the one simulated for the axes run.
  const i = hobsharp.evaluate(paper).inspection;
  assert.equal(i.source, 'simulated');
  const lead = classLead(i);
  assert.equal(lead.simulated, true);
  assert.equal(lead.text, `Class ${i.class} on the simulated face (nothing measured: no conformity is decided)`);
  assert.doesNotMatch(lead.text, /conforms|proven|ISO 14253/);
  assert.equal(lead.provenText, '');
  assert.ok(inspectionRows(i).filter((r) => r.grade !== 'not graded').every((r) => r.decided === false));
  // Gash deviations given are measured: their checks decide; the face's do not, nor does the class.
  const d = Array(12).fill(0);
  d[2] = 10;
  const withGashes = hobsharp.evaluate({ ...paper, inspection: { gashDeviations: d } }).inspection;
  assert.equal(classLead(withGashes).text, `Class ${withGashes.class} on the simulated face (the face is not measured: no conformity is decided)`);
  const rows = inspectionRows(withGashes);
  assert.deepEqual(rows.map((r) => [r.check, r.decided]), [['cuttingFaceForm', false], ['radialAlignment', false], ['gashLead', false],
    ['adjacentSpacing', true], ['pitchJump', true]]);
  // A measured face decides as before.
  const measured = classLead(hobsharp.evaluate({ ...paper, measured: grid(() => 1), correction: { probeNoise: 1e-4 } }).inspection);
  assert.equal(measured.simulated, false);
  assert.match(measured.text, /^Class \w+ — (conforms|undecided|does not conform) \(ISO 14253-1, U95 = 2 µm\); proven class/);
});

test('the warning names the checks whose U95 exceeds a tenth of their tolerance', () => {
  const d = Array(12).fill(0);
  d[2] = 10;
  const i = hobsharp.evaluate({ ...paper, inspection: { gashDeviations: d, uncertainty: 3 } }).inspection;
  assert.equal(i.uncertaintyWarning, 'radialAlignment, adjacentSpacing, pitchJump');
  assert.equal(uncertaintyWarningText(i), "The measurement's uncertainty U95 exceeds a tenth of the tolerance for the radial alignment (U 3 µm, tolerance AA 25 µm), "
    + 'single pitch (U 3 µm, tolerance AA 25 µm) and pitch jump (U 3 µm, tolerance AA 25 µm): their class rests on a measurement too coarse for it. '
    + 'Measure with a smaller uncertainty.');
  assert.equal(uncertaintyWarningText({ ...i, uncertaintyWarning: '' }), '');
});

// Measured points the axes' model of the face does not explain (a shape no axis makes): the verdict,
// the rake error and the rows say that the face's checks are not graded, and give no figure after the
// correction read off that model; a gash spacing is still graded, and the sentence says the rest is not.
test('points the axes do not explain: not graded in the verdict, no rake error, no figures after', () => {
  const points = [];
  for (let i = 0; i < 21; i += 1) {
    for (let k = 0; k < 11; k += 1) {
      const r = 19.1 + 20.8 * i / 20;
      points.push([r, -68 + 136 * k / 10, 28 * Math.sin(4 * Math.PI * (r - 19) / 21)]);
    }
  }
  const r = hobsharp.evaluate({ ...paper, measuredPoints: points, correction: { probeNoise: 0.5 } });
  assert.match(r.inspection.faceNotGraded, /leaves 18 µm rms of the points unexplained/);
  assert.equal(verdictSentence(r.inspection), 'Rake face (DIN 3968, module band over 6.3 to 10 mm, measured points): not graded (the axes\' model of the face does not explain the measured points: see the checks); '
    + 'after the correction, if the identified error is all of the machine\'s: not graded (the axes\' model of the face does not explain the measured points: see the checks).');
  assert.equal(rakeText(r.inspection, r.gearEffect), 'Rake error: not read, as the face\'s checks are not graded (see the checks).');
  const rows = inspectionRows(r.inspection);
  assert.ok(rows.filter((x) => x.check !== 'cuttingFaceForm').every((x) => x.grade === 'not graded' && x.value !== null && x.after === null), JSON.stringify(rows));
  const spaced = hobsharp.evaluate({ ...paper, measuredPoints: points, correction: { probeNoise: 0.5 }, inspection: { gashDeviations: [0, 1.5, -2, 0.5, 3, 0, -1, 0.25, 0, 2, -0.5, 1] } });
  assert.match(verdictSentence(spaced.inspection), /: class \w+ \(limited by the (pitch jump|single pitch \(adjacent spacing\))\), the face's checks not graded \(see the checks\)/);
  assert.equal(hobsharp.evaluate({ ...paper, measured: grid(() => 30) }).inspection.faceNotGraded, '');
});

test('the rake error in a line: hook or drag, the offset, and the gear effect with the relief', () => {
  const hook = hobsharp.evaluate({ ...paper, measured: grid(() => -30), correction: { probeNoise: 1e-4 } });
  const text = rakeText(hook.inspection, hook.gearEffect);
  assert.match(text, /^Rake error: hook \d+\.\d′ \(0\.0\d\d mm into the tooth\)\. Enter the hob's relief \(gashes z and relief K, or the side relief angle\) to see what it does to the gear's pressure angle\.$/);
  const relieved = hobsharp.evaluate({ ...paper, hob: { ...paper.hob, gashes: 12, relief: 4.5 }, measured: grid(() => -30), correction: { probeNoise: 1e-4 } });
  assert.match(rakeText(relieved.inspection, relieved.gearEffect),
    /^Rake error: hook \d+\.\d′ \(0\.0\d\d mm into the tooth\); the gear's pressure angle changes by −\d+\.\d\d′ \(−\d+\.\d′ per degree of hook\)\.$/);
  const drag = hobsharp.evaluate({ ...paper, measured: grid(() => 30), correction: { probeNoise: 1e-4 } });
  assert.match(rakeText(drag.inspection, drag.gearEffect), /^Rake error: drag \d+\.\d′ \(0\.0\d\d mm out of the tooth\)\./);
  const none = hobsharp.evaluate(paper);
  assert.match(rakeText(none.inspection, none.gearEffect), /^Rake error: none \(0\.0′\)\./);
  assert.equal(withUnit('2.1', 'arc-min'), '2.1′');
  assert.equal(withUnit('−4.8', 'arc-min per deg'), '−4.8′ per degree');
  assert.equal(withUnit('3', 'µm per 100 mm'), '3 µm per 100 mm');
});

test('a grade that rests on a series value carries a *, and so do the series cells of the class tolerances', () => {
  // About 29 µm on the indicator: A over 6.3 to 10 mm, whose 40 µm is a series value.
  const r = hobsharp.evaluate({ ...paper, measured: grid(() => 57), correction: { probeNoise: 1e-4 } });
  const defaults = hobsharp.limits().inspection.defaultTolerances;
  const band = r.inspection.moduleBandIndex;
  const confidenceOf = (check, klass) => cellConfidence(tableInUse({}, defaults), { band, check, klass, edited: false });
  const radial = inspectionRows(r.inspection, { confidenceOf }).find((x) => x.check === 'radialAlignment');
  assert.equal(radial.grade, 'A');
  assert.equal(radial.gradeText, 'A*');
  // The proven class rests on its own class's tolerance: a series value from A on.
  assert.ok(['A', 'B', 'C', 'D'].includes(radial.proven), radial.proven);
  assert.equal(radial.provenText, `${radial.proven}*`);
  const noTable = inspectionRows(r.inspection).find((x) => x.check === 'radialAlignment');
  assert.equal(noTable.provenText, radial.proven === 'A' ? 'A*' : radial.proven, 'without the table, the grade\'s own mark');
  assert.equal(radial.series, true);
  assert.equal(radial.confidence, 'series');
  assert.match(radial.source, /^Luren Precision.*series, not confirmed$/);
  assert.equal(radial.tolerances, 'AA 25 · A 40* · B 80* · C 160* · D 315*');
  // A cell typed on the page is the engineer's: no longer a series value.
  const extra = withCell({}, defaults, { band, check: 'radialAlignment', klass: 'A', text: '38' });
  const typed = hobsharp.evaluate({ ...paper, measured: grid(() => 57), correction: { probeNoise: 1e-4 }, ...extra }).inspection;
  assert.equal(typed.checks.radialAlignment.confidence, 'entered');
  assert.equal(typed.checks.radialAlignment.grade, 'A');
  assert.equal(cellConfidence(tableInUse(extra, defaults), { band, check: 'radialAlignment', klass: 'B', edited: true }), 'series', 'the others keep their marks');
  assert.equal(cellConfidence(tableInUse(extra, defaults), { band, check: 'pitchJump', klass: 'AA', edited: true }), 'printed');
});

test('a class and a proven class that rest on a series value carry its * and say so in the lead', () => {
  // The sample pass: the radial alignment graded B on B's series value, proven B on the same.
  const sample = JSON.parse(readFileSync(new URL('../data/unground-sample-pass.json', import.meta.url), 'utf8'));
  const i = hobsharp.evaluate(sample).inspection;
  assert.equal(i.class, 'B');
  assert.equal(i.checks.radialAlignment.confidence, 'series');
  const note = "* the class and the proven class rest on a series value, not confirmed: enter the hob maker's table";
  const rows = inspectionRows(i, { confidenceOf: cellConfidenceOf({}, hobsharp.limits().inspection.defaultTolerances, i.moduleBandIndex) });
  for (const lead of [classLead(i), classLead(i, undefined, rows)]) {
    assert.equal(lead.classText, 'Class B* — conforms (ISO 14253-1, U95 = 2 µm)');
    assert.equal(lead.provenText, 'proven class B*');
    assert.equal(lead.seriesNote, note);
    assert.equal(lead.text, `Class B* — conforms (ISO 14253-1, U95 = 2 µm); proven class B* (${note})`);
  }
  // The table's own cell typed (entered, not a series value): no * and no note.
  const defaults = hobsharp.limits().inspection.defaultTolerances;
  const extra = withCell({}, defaults, { band: i.moduleBandIndex, check: 'radialAlignment', klass: 'B', text: '80' });
  const typed = hobsharp.evaluate({ ...sample, ...extra }).inspection;
  const typedLead = classLead(typed, undefined, inspectionRows(typed, { confidenceOf: cellConfidenceOf(extra, defaults, typed.moduleBandIndex) }));
  assert.equal(typedLead.text, 'Class B — conforms (ISO 14253-1, U95 = 2 µm); proven class B');
  // Printed values (the paper's face): none.
  assert.equal(classLead(hobsharp.evaluate({ ...paper, measured: grid(() => 1), correction: { probeNoise: 1e-4 } }).inspection).seriesNote, '');
});

// DIN 3968's spacing checks need the gashes measured: without gash deviations the class rests on
// the face's checks alone, and the result and the verdict say so (an independent review).
test('without gash deviations the single pitch and pitch jump are said not measured; with them, nothing is', () => {
  const measured = grid((i) => 3 * i);
  const without = hobsharp.evaluate({ ...paper, measured }).inspection;
  assert.match(without.notMeasured, /^Not measured: single pitch \(adjacent spacing\) and pitch jump \(the case gives no gash deviations or per-gash topographies\), so the class rests on the face's checks alone\./);
  assert.ok(!('adjacentSpacing' in without.checks) && !('pitchJump' in without.checks));
  assert.match(verdictSentence(without), new RegExp(`: class ${without.class} \\(limited by the [a-z -]+\\), the gashes' spacing not measured \\(see the checks\\)`));
  const gashDeviations = [0, 1.5, -2, 0.5, 3, 0, -1, 0.25, 0, 2, -0.5, 1];
  const withGashes = hobsharp.evaluate({ ...paper, measured, inspection: { gashDeviations } }).inspection;
  assert.equal(withGashes.notMeasured, '');
  assert.doesNotMatch(verdictSentence(withGashes), /not measured/);
});

test('outside the table\'s bands: no after column, and not graded said in words with what to enter', () => {
  const tolerances = { moduleBands: [1, 2], checks: { pitchJump: { AA: [5] } } };
  const r = hobsharp.evaluate({ ...paper, inspection: { tolerances } });
  const text = verdictSentence(r.inspection);
  assert.match(text, /simulated face\): not graded \(the tolerance table has no value for this module on any check computed\)\.$/);
  assert.ok(inspectionRows(r.inspection).every((x) => x.after === null));
  assert.equal(verdictSentence(undefined), '');
  const lead = classLead(r.inspection);
  assert.equal(lead.graded, false);
  assert.match(r.inspection.notGraded, /^Not graded: cutting-face form, radial alignment, gash lead \(the tolerance table has no value for this module: it is outside the table's module bands\)\. Enter/);
});

// A value is shown with the digits that keep it from reading as a limit it is not (an independent
// review: 25.0004 µm graded A against AA 25 µm was shown "25.000 µm").
test("a check's value near a tolerance or a conformity limit is shown with the digits that tell them apart", () => {
  assert.equal(checkValueText(25.0004, [25, 40, 80], 2), '25.0004');
  assert.equal(checkValueText(-25.0004, [25, 40, 80], 2), '-25.0004');
  assert.equal(checkValueText(23.0004, [25, 40, 80], 2), '23.0004', 'T - U = 23 µm');
  assert.equal(checkValueText(25.0000004, [25], 2), '25.000000', 'at most 6 decimals, the grading\'s 1e-6 µm');
  assert.equal(checkValueText(25, [25], 2), '25.000', 'at the tolerance itself');
  assert.equal(checkValueText(24.467, [25], 2), '24.467');
  assert.equal(checkValueText(null, [25], 2), null);
  // Limits binary cannot hold (10 - 1.12 is 8.879999999999999): compared as written.
  assert.equal(checkValueText(8.8804, [10], 1.12), '8.8804');
  assert.equal(checkValueText(8.8796, [10], 1.12), '8.8796');
  assert.equal(checkValueText(0.2004, [0.3], 0.1), '0.2004');
  assert.equal(checkValueText(8.88, [10], 1.12), '8.880', 'at the limit itself');
  // Through the module: the review's case, a radial alignment of 25.0004 µm at module 8.19 (AA 25 µm), graded A.
  const c = JSON.parse(readFileSync(new URL('../data/inspection-near-tolerance.json', import.meta.url), 'utf8'));
  const row = inspectionRows(hobsharp.evaluate(c).inspection).find((r) => r.check === 'radialAlignment');
  assert.equal(row.grade, 'A');
  assert.equal(row.valueText, '25.0004');
});


// "Outside B" by a check whose table stops at B names the checks graded C or worse (an
// independent review: the gash lead's "outside B" had hidden a radial alignment of class D).
test('a class outside a table that stops early names the checks graded worse than its last class', () => {
  const c = JSON.parse(readFileSync(new URL('../data/inspection-outside-b.json', import.meta.url), 'utf8'));
  const i = hobsharp.evaluate(c).inspection;
  assert.equal(i.class, 'outside B');
  assert.equal(i.limitingCheck, 'gashLead');
  assert.equal(i.checks.radialAlignment.grade, 'D');
  assert.match(verdictSentence(i), /: class outside B \(limited by the gash lead, whose table stops at B; the radial alignment D\)/);
  // A class inside the table names nothing more.
  const measured = Array.from({ length: 5 }, (_, k) => Array(9).fill(3 * k));
  assert.doesNotMatch(verdictSentence(hobsharp.evaluate({ ...paper, measured }).inspection), /table stops/);
});
