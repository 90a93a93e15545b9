// The case's inputs as the job's record lists them (web/src/io/input-rows.js), shared by the
// results CSV and the printed report (web/src/report-lines.js: its rows by label and unit, the
// verdict line, the job).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { inputRows } from '../../web/src/io/input-rows.js';
import { jobRows, reportDateLine, reportInputRows, reportInspectionLine, verdictLine, verdictWord } from '../../web/src/report-lines.js';
import { fieldUnit } from '../../web/src/result-fields.js';
import { fmt, fixed } from '../../web/src/format.js';
import { firstStepText, rmsText } from '../../web/src/views/summary.js';
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

// The form's words for a few fields, as views/field-names.js reads them from its labels.
const words = {
  labels: { 'hob.normalModule': 'Normal module m_n', 'hob.gashLead': 'Gash lead L_c', 'hob.gash': 'Gash', 'wheel.outerDiameter': 'Outer diameter d_w',
    'setup.tilt': 'Tilt of the wheel η', 'setup.settingAngle': 'Setting angle γ_m', 'setup.centerDistance': 'Centre distance E_t',
    'machine.K1': 'K_1', degree: 'Polynomial degree', 'grid.rMin': 'r from' },
  units: { 'hob.normalModule': 'mm', 'hob.gashLead': 'mm', 'wheel.outerDiameter': 'mm', 'setup.tilt': 'deg', 'setup.settingAngle': 'deg',
    'setup.centerDistance': 'mm', 'machine.K1': 'mm', 'grid.rMin': 'mm' },
  groups: { hob: 'Hob data', wheel: 'Wheel data', setup: 'Universal machine settings', machine: 'Machine constants', grid: 'Polynomials and measuring grid' },
};

test("the report's inputs: by the form's labels with their units, by group, the degree, what was derived; never a path", () => {
  const result = { setup: { settingAngle: 12.6260001234, centerDistance: 155.1 } };
  const rows = reportInputRows(result, paper, words);
  assert.deepEqual(rows[0], { group: 'Hob data', label: 'Normal module m_n', value: '7', unit: 'mm', derived: false });
  assert.deepEqual(rows.find((r) => r.label === 'Gash lead L_c'), { group: 'Hob data', label: 'Gash lead L_c', value: '876.56', unit: 'mm', derived: false });
  assert.deepEqual(rows.find((r) => r.label === 'Gash'), { group: 'Hob data', label: 'Gash', value: 'helical', unit: '', derived: false });
  assert.deepEqual(rows.map((r) => r.group).filter((g, i, a) => a.indexOf(g) === i), Object.values(words.groups));
  assert.deepEqual(rows.at(-1), { group: 'Polynomials and measuring grid', label: 'Polynomial degree', value: '4', unit: '', derived: false });
  // A field without a label in the form is left out, never shown by its path.
  assert.ok(!rows.some((r) => /\w\.\w/.test(r.label) || r.label === 'normalPressureAngle'), JSON.stringify(rows));
  // The paper gives the setting angle and the centre distance: none derived.
  assert.ok(!rows.some((r) => r.derived));
  // The setting angle left to the calculator: the derived one, to 8 digits, marked so.
  const { settingAngle, ...setup } = paper.setup;
  const derived = reportInputRows(result, { ...paper, setup, axes: { X: [1] }, grid: { ...paper.grid, extra: { a: 1 } } }, words);
  assert.deepEqual(derived.filter((r) => r.label === 'Setting angle γ_m'), [{ group: 'Universal machine settings', label: 'Setting angle γ_m', value: '12.626', unit: 'deg', derived: true }]);
  assert.ok(!derived.some((r) => r.label === 'extra' || r.label === 'a'), 'nested values stay out of the report');
});

test("the report's job: the form's labels, in the case's order, blanks left out", () => {
  const names = { 'job.number': 'Job number', 'job.customer': 'Customer', 'job.hobSerial': 'Hob serial number', 'job.operator': 'Operator', 'job.notes': 'Notes' };
  assert.deepEqual(jobRows({ notes: 'Second pass.\nDressed.', number: ' A-117 ', customer: '', operator: 'K. Weber' }, names),
    [['Job number', 'A-117'], ['Operator', 'K. Weber'], ['Notes', 'Second pass.\nDressed.']]);
  assert.deepEqual(jobRows(undefined, names), []);
});

// The verdict line with the module's figures and units: the class with its conformity and the
// face's rms measured and predicted (with the bound), or the face simulated when nothing is measured.
test("the report's verdict line: the class with its conformity, the face's rms before and after, with units", () => {
  const unitOf = (p) => fieldUnit(p) || '';
  const nominal = hobsharp.evaluate(paper);
  const line = verdictLine(nominal, unitOf);
  // Nothing measured: the simulated face's class, with no conformity decided on it.
  assert.match(line, /^Class (AA|A|B|C|D) on the simulated face, no conformity decided; face (below 0\.001|[\d.]+) µm rms simulated for the axes run; nothing measured, no correction\.$/);
  assert.ok(line.startsWith(`Class ${nominal.inspection.class} on the simulated face`), line);
  assert.doesNotMatch(line, /conforms|proven/);
  // A measured face: a what-if's Z offset of 10 µm, noise-free.
  const radial = paper.grid.radial, axial = paper.grid.axial;
  const measured = Array.from({ length: radial }, (_, i) => Array.from({ length: axial }, (_, j) => 3 + 0.5 * i - 0.2 * j));
  const r = hobsharp.evaluate({ ...paper, measured, correction: { probeNoise: 0.5 } });
  const c = r.correction;
  assert.equal(c.stop, false);
  const f = (v) => fmt(v, 3);
  // No gash deviations: the class says that the gashes' spacing is not measured (inspection.notMeasured).
  assert.notEqual(r.inspection.notMeasured, '');
  // What the pass leaves by its bound alone, not the model's figure below it, led by the verdict's
  // word and with the condition the bound holds on, as the verdict states them.
  assert.match(c.verdict, /^Correctable: .* if the error the face cannot show is no larger than the one it shows\./);
  assert.equal(verdictLine(r, unitOf), `Class ${r.inspection.class} — ${r.inspection.conformity}, the gashes' spacing not measured; Correctable: face ${f(c.rmsBefore)} µm rms measured, at most ${
    f(c.predictedRmsHigh)} µm rms after the correction if the error the face cannot show is no larger than the one it shows.`);
  assert.equal(verdictLine({ ...r, correction: { ...c, runKept: true } }, unitOf), `Class ${r.inspection.class} — ${r.inspection.conformity}, the gashes' spacing not measured; face ${f(c.rmsBefore)} µm rms measured: no change proposed, keep the axes run.`);
  // Nothing changed (no axis direction above the noise: every change 0): the same, not "at most … after".
  const unchanged = { ...c, change: c.change.map(() => 0) };
  assert.equal(verdictLine({ ...r, correction: unchanged }, unitOf), `Class ${r.inspection.class} — ${r.inspection.conformity}, the gashes' spacing not measured; face ${f(c.rmsBefore)} µm rms measured: no change proposed, keep the axes run.`);
  // Faces that moved against the change of the axes (correction.signReversed): no figure after.
  assert.equal(verdictLine({ ...r, correction: { ...c, signReversed: true } }, unitOf), `Class ${r.inspection.class} — ${r.inspection.conformity}, the gashes' spacing not measured; Check the sign: face ${f(c.rmsBefore)} µm rms measured, moved against the change of the axes since the last pass; no figure after the correction until the measuring machine's sign is checked.`);
  assert.equal(c.signReversed, false, 'a first pass has no history to check against');
  assert.equal(verdictLine({ ...r, correction: { ...c, predictedRmsHigh: NaN } }, unitOf), `Class ${r.inspection.class} — ${r.inspection.conformity}, the gashes' spacing not measured; Correctable: face ${f(c.rmsBefore)} µm rms measured.`);
  // Within the probe noise: stop, the axes run stay.
  const quiet = hobsharp.evaluate({ ...paper, measured: measured.map((row) => row.map(() => 0.01)), correction: { probeNoise: 0.5 } });
  assert.equal(quiet.correction.stop, true);
  assert.match(verdictLine(quiet, unitOf), /; face 0\.01 µm rms measured: within the probe noise, keep the axes run\.$/);
  assert.doesNotMatch(line + verdictLine(r, unitOf), /NaN|undefined|correction\.[a-z]|rms[A-Z]|e-\d/);
});

test("the answer's rms line: after the pass the prediction's bound, never the identified machine's figure below it", () => {
  setResultFields(hobsharp.resultFields());
  const radial = paper.grid.radial, axial = paper.grid.axial;
  const measured = Array.from({ length: radial }, (_, i) => Array.from({ length: axial }, (_, j) => 3 + 0.5 * i - 0.2 * j));
  const r = hobsharp.evaluate({ ...paper, measured, correction: { probeNoise: 0.5 } });
  const c = r.correction;
  assert.ok(c.predictedRmsHigh > c.rmsAfter, 'the case has a bound above the model\'s figure');
  assert.equal(rmsText(r, fieldUnit), `Face rms: ${fixed(c.rmsBefore, 3)} µm measured → at most ${fixed(c.predictedRmsHigh, 3)} µm after the pass.`);
  // No bound (not a number): the model's figure, with its condition.
  assert.equal(rmsText({ ...r, correction: { ...c, predictedRmsHigh: NaN } }, fieldUnit),
    `Face rms: ${fixed(c.rmsBefore, 3)} µm measured → ${fixed(c.rmsAfter, 3)} µm after the pass if the identified error is all of the machine's.`);
  // A stop: no pass, nothing after it.
  const quiet = hobsharp.evaluate({ ...paper, measured: measured.map((row) => row.map(() => 0.01)), correction: { probeNoise: 0.5 } });
  assert.equal(quiet.correction.stop, true);
  assert.equal(rmsText(quiet, fieldUnit), 'Face rms: 0.010 µm measured: within the probe noise, the axes run stay.');
  // A proposal not to be run: nothing after it; a bound below a nanometre reads as 0.001, not 0.000.
  assert.equal(rmsText({ ...r, correction: { ...c, usable: false } }, fieldUnit), `Face rms: ${fixed(c.rmsBefore, 3)} µm measured.`);
  assert.equal(rmsText({ ...r, correction: { ...c, runKept: true } }, fieldUnit), `Face rms: ${fixed(c.rmsBefore, 3)} µm measured: no change proposed, the axes run stay.`);
  // Faces that moved against the change of the axes (correction.signReversed): nothing after.
  assert.equal(rmsText({ ...r, correction: { ...c, signReversed: true } }, fieldUnit), `Face rms: ${fixed(c.rmsBefore, 3)} µm measured; nothing is predicted after the pass until the measuring machine's sign is checked.`);
  assert.equal(rmsText({ ...r, correction: { ...c, change: c.change.map(() => 0) } }, fieldUnit), `Face rms: ${fixed(c.rmsBefore, 3)} µm measured: no change proposed, the axes run stay.`);
  // ... and below the pass's floor (the position resolution's), the floor follows it.
  assert.ok(c.resolutionFloor > 2e-4 && c.resolutionFloor < c.predictedRmsHigh, `floor ${c.resolutionFloor} µm`);
  assert.match(rmsText({ ...r, correction: { ...c, predictedRmsHigh: 2e-4 } }, fieldUnit),
    new RegExp(`→ at most 0\\.001 µm after the pass; that is with the exact axes, and the machine's position resolution sets a floor of about ${Number(c.resolutionFloor.toPrecision(3))} µm rms\\.$`));
});

test("the answer's first line: what to do next, by where the job is", () => {
  const nominal = hobsharp.evaluate(paper);
  assert.match(firstStepText(nominal, paper), /^First type the hob's data at the left \(or load a case\); then load the measured face/);
  assert.match(firstStepText(null, null), /^First type the hob's data/);
  // After "Use as next run": the proposal is the run and a pass is kept; nothing measured yet. The
  // hob is there: the next step is to grind with those axes and load the new measurement.
  const radial = paper.grid.radial, axial = paper.grid.axial;
  const measured = Array.from({ length: radial }, (_, i) => Array.from({ length: axial }, (_, j) => 3 + 0.5 * i - 0.2 * j));
  const first = hobsharp.evaluate({ ...paper, measured, correction: { probeNoise: 0.5 } });
  const next = { ...paper, axes: first.correction.axes, passes: [{ axes: first.axes, measured }] };
  const text = firstStepText(hobsharp.evaluate(next), next);
  assert.equal(text, 'Grind with the axes to run below (the run axes in use), measure the face and load the new measurement in step 2; '
    + 'the verdict, the class and the next axes to run show here.');
  assert.doesNotMatch(text, /type the hob/);
  // A correction: run its axes.
  assert.match(firstStepText(first, { ...paper, measured }), /^Run the axes below, measure the face and load it in step 2/);
  // Faces that moved against the change of the axes: the sign first.
  assert.match(firstStepText({ ...first, correction: { ...first.correction, signReversed: true } }, { ...paper, measured }),
    /^Do not run the axes below yet: the faces measured moved against the change of the axes .* load every face again with "change sign" \(the earlier passes' too\)/);
});

test("the report's first line names the day and what was measured: a grid, the machine's points, or nothing", () => {
  const day = new Date('2026-11-23T22:00:00Z');
  assert.equal(reportDateLine(paper, day), 'Printed 2026-11-23; no measured topography.');
  assert.equal(reportDateLine({ ...paper, measured: [[1]] }, day), 'Printed 2026-11-23; with a measured topography.');
  assert.equal(reportDateLine({ ...paper, measuredPoints: [[20, 0, 1], [30, 5, 2]] }, day),
    'Printed 2026-11-23; with a measured topography at 2 probe points.');
});

test("the report's page 1 carries the class's * where it rests on a series value, as the inspection's table", () => {
  const unitOf = (p) => fieldUnit(p) || '';
  const sample = JSON.parse(readFileSync(new URL('../data/unground-sample-pass.json', import.meta.url), 'utf8'));
  const r = hobsharp.evaluate(sample);
  assert.match(verdictLine(r, unitOf), /^Class B\* — conforms, the gashes' spacing not measured \(\* on a series value, not confirmed\); /);
  assert.equal(reportInspectionLine(r.inspection), "Rake face (DIN 3968): Class B* — conforms (ISO 14253-1, U95 = 2 µm); proven class B* "
    + "(* the class and the proven class rest on a series value, not confirmed: enter the hob maker's table). The gashes' spacing is not measured: the class rests on the face's checks alone.");
});

test("the report's verdict line carries the verdict's word, the condition its bound holds on, and part of the face left unground", () => {
  const unitOf = (p) => fieldUnit(p) || '';
  const read = (name) => JSON.parse(readFileSync(new URL(`../data/${name}`, import.meta.url), 'utf8'));
  // Uncertain: some errors the face cannot show keep the wheel from part of it.
  const sample = hobsharp.evaluate(read('unground-sample-pass.json'));
  assert.match(sample.correction.verdict, /^Uncertain: .* if the error the face cannot show is no larger than the one it shows, .*\(part of it would stay unground\)/);
  assert.equal(verdictLine(sample, unitOf), 'Class B* — conforms, the gashes\' spacing not measured (* on a series value, not confirmed); Uncertain: face 149 µm rms measured, at most 106 µm rms after the correction '
    + 'if the error the face cannot show is no larger than the one it shows; part of the face may stay unground.');
  // A fold near a point, and the top of the face past the wheel's edge: unground said too.
  const edge = hobsharp.evaluate(read('wheel-edge-pass.json'));
  assert.match(verdictLine(edge, unitOf), /; Uncertain: face [\d.]+ µm rms measured, at most [\d.]+ µm rms after the correction if the error the face cannot show is no larger than the one it shows; part of the face may stay unground\.$/);
  // The verdict's word: what comes before its colon.
  assert.equal(verdictWord('Partly uncorrectable: 35 % of the sum of squares ...'), 'Partly uncorrectable');
  assert.equal(verdictWord('Correctable with the wheel: run the axes proposed ...'), 'Correctable with the wheel');
  assert.equal(verdictWord('Identification stalled; the best estimate is proposed: the face ...'), 'Identification stalled; the best estimate is proposed');
  assert.equal(verdictWord(''), '');
  assert.equal(verdictWord(undefined), '');
});

test("the report's head: the rake face's class with its conformity and the proven class", () => {
  const d = Array(12).fill(0);
  d[2] = 10;
  const c = structuredClone(paper);
  c.hob.normalModule = 5;  // pitch jump -20 µm against AA 20 µm: undecided with U95 = 2 µm, proven A
  const line = reportInspectionLine(hobsharp.evaluate({ ...c, inspection: { gashDeviations: d } }).inspection);
  assert.equal(line, 'Rake face (DIN 3968): Class AA on the simulated face (the face is not measured: no conformity is decided).');
  // A measured face: the conformity and the proven class.
  const measured = Array.from({ length: c.grid.radial }, () => Array(c.grid.axial).fill(0));
  assert.equal(reportInspectionLine(hobsharp.evaluate({ ...c, measured, inspection: { gashDeviations: d } }).inspection),
    'Rake face (DIN 3968): Class AA — undecided (ISO 14253-1, U95 = 2 µm); proven class A.');
  // Nothing measured: the simulated face's class, nothing proven.
  assert.equal(reportInspectionLine(hobsharp.evaluate(paper).inspection), 'Rake face (DIN 3968): Class AA on the simulated face (nothing measured: no conformity is decided).');
  const outside = hobsharp.evaluate({ ...paper, inspection: { tolerances: { moduleBands: [1, 2], checks: { pitchJump: { AA: [5] } } } } }).inspection;
  assert.match(reportInspectionLine(outside), /^Rake face \(DIN 3968\): Not graded: cutting-face form, radial alignment, gash lead \(/);
  assert.equal(reportInspectionLine(undefined), '');
});
