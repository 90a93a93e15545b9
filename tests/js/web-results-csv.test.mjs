// The results and the wheel profile as CSV (web/src/io/results-csv.js), from the module's result
// for the paper's case, with and without a correction.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { profileCsv, resultsCsv, resultsFileName } from '../../web/src/io/results-csv.js';
import { readMeasured } from '../../wasm/lib/measured-grid.js';
import { setModuleLimits } from '../../web/src/limits.js';
import { setResultFields } from '../../web/src/result-fields.js';

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const hobsharp = await loadHobSharp();
setModuleLimits(hobsharp.limits());  // as the page does once its calculator is ready
setResultFields(hobsharp.resultFields());  // and the results' labels and units
const numbers = (line) => line.split(',').slice(1).map(Number);

test('the results CSV holds every coefficient with its unit, and each grid row by row', () => {
  const r = hobsharp.evaluate(paper);
  const text = resultsCsv(r);
  assert.ok(text.startsWith('\uFEFF# HobSharp results'), 'a BOM, so that µ and ² survive spreadsheet programs');
  const lines = text.split('\n');
  assert.ok(lines.includes('coefficient,unit,nominal,run,corrected,change'));
  assert.equal(lines.filter((l) => /^[XYZAB] a\d,/.test(l)).length, 25);
  assert.ok(lines.includes(`X a1,mm/rad,${r.axes.X[1]},${r.axes.X[1]},,`));
  assert.ok(lines.includes(`B a2,rad/rad²,${r.axes.B[2]},${r.axes.B[2]},,`));
  const header = lines.indexOf('# simulated normal deviation (µm) for the axes run; rows r (mm) root to tip, columns x (mm) along the gash');
  assert.deepEqual(numbers(lines[header + 1]), r.topography.x);
  for (let i = 0; i < 5; i++) {
    assert.equal(Number(lines[header + 2 + i].split(',')[0]), r.topography.r[i]);
    assert.deepEqual(numbers(lines[header + 2 + i]), r.topography.normal[i]);
  }
  assert.ok(!text.includes('after correction'));
  assert.ok(lines.includes(`rms,µm,${r.topography.rms}`));
  assert.equal(lines.at(-2), `# thickness error at the mean point (µm),${r.topography.thickness}`);
});

// The inputs as the form shows them (issue 22's "units on every number"): each by its name, with
// its value, its unit and its case field; without the page's words, the field's path is its name.
test('the inputs block: each input by its name, with its unit and its case field', () => {
  const r = hobsharp.evaluate(paper);
  const caseObject = { ...paper, correction: { probeNoise: 0.5 } };
  const inputWords = {
    names: { 'hob.normalModule': 'Normal module m_n', 'setup.tilt': 'Wheel tilt ψ_c', 'correction.probeNoise': 'Probe noise σ' },
    units: { 'hob.normalModule': 'mm', 'setup.tilt': 'deg', 'correction.probeNoise': 'µm', 'grid.radial': '' },
  };
  const lines = resultsCsv(r, { caseObject, inputWords }).split('\n');
  const at = lines.indexOf('input,value,unit,case field');
  assert.ok(at > 0, 'the inputs block with a unit column');
  assert.ok(lines.includes('Normal module m_n,7,mm,hob.normalModule'));
  assert.ok(lines.includes('Wheel tilt ψ_c,15,deg,setup.tilt'));
  assert.ok(lines.includes('Probe noise σ,0.5,µm,correction.probeNoise'));
  assert.ok(lines.includes('grid.radial,5,,grid.radial'));
  const semicolon = resultsCsv(r, { caseObject, inputWords, style: 'semicolon' }).split('\n');
  assert.ok(semicolon.includes('Probe noise σ;0,5;µm;correction.probeNoise'));
});

test('a record of the job: its inputs, the measured grid, the verdict, the figures before and after, the change to type in', () => {
  const measured = Array.from({ length: 5 }, (_, i) => Array(9).fill(1 + i / 4));
  const nominal = hobsharp.evaluate(paper).axes;
  const axes = { ...nominal, Y: [nominal.Y[0] + 0.002, ...nominal.Y.slice(1)] };  // the run: Y 2 µm off nominal
  const caseObject = { ...paper, axes, measured, correction: { probeNoise: 0.5, lockedAxes: ['A'], locked: [] } };
  const r = hobsharp.evaluate(caseObject);
  const lines = resultsCsv(r, { caseObject, date: new Date('2026-11-23T10:00:00Z') }).split('\n');
  assert.ok(lines.includes('# date,2026-11-23'));
  assert.ok(lines.includes(`hob.normalModule,${paper.hob.normalModule},,hob.normalModule`));
  assert.ok(lines.includes('correction.lockedAxes,A,,correction.lockedAxes'));
  assert.ok(lines.includes(`verdict,"${r.correction.verdict.replace(/"/g, '""')}"`) || lines.includes(`verdict,${r.correction.verdict}`));
  assert.ok(lines.includes(`rms,µm,${r.correction.rmsBefore},${r.correction.rmsAfter}`));
  assert.ok(lines.includes(`sum of squares,µm²,${r.correction.sseBefore},${r.correction.sseAfter}`));
  assert.ok(lines.includes("figure,unit,measured,after the pass on the identified machine (the measurement's noise and all)"), 'the figures after are the identified machine\'s, said so');
  assert.ok(lines.includes(`rms the pass leaves at most (the bound without this measurement's noise),µm,,${r.correction.predictedRmsHigh}`), 'the bound is a row of its own');
  // No pass, no bound: a stop, a run kept, a proposal not to be used.
  for (const none of [{ stop: true }, { runKept: true }, { usable: false }]) {
    const text = resultsCsv({ ...r, correction: { ...r.correction, ...none } }, { caseObject });
    assert.ok(!text.includes('rms the pass leaves at most'), JSON.stringify(none));
  }
  assert.ok(lines.includes(`Y a0,mm,${nominal.Y[0]},${axes.Y[0]},${r.correction.axes.Y[0]},${r.correction.axes.Y[0] - axes.Y[0]}`));
  const at = lines.findIndex((l) => l.startsWith('# measured normal deviation (µm)'));
  for (let i = 0; i < 5; i++) assert.deepEqual(numbers(lines[at + 2 + i]), measured[i]);
  const predicted = lines.findIndex((l) => l.startsWith('# predicted normal deviation after correction, on the identified machine (µm)'));
  assert.deepEqual(numbers(lines[predicted + 2]), r.correction.residual[0]);
  assert.equal(resultsFileName(caseObject, new Date('2026-11-23T10:00:00Z')), `hobsharp-m${paper.hob.normalModule}-helical-right-2026-11-23.csv`);
  assert.equal(resultsFileName({ hob: { normalModule: 4, gash: 'straight' } }, new Date('2026-01-02T00:00:00Z')), 'hobsharp-m4-straight-2026-01-02.csv');
  // A module typed or loaded to 15 digits is named to 4 significant ones, as a hob is (not m8.11031724285288).
  const day = new Date('2026-12-07T10:00:00Z');
  assert.equal(resultsFileName({ hob: { normalModule: 8.11031724285288, gash: 'helical', hand: 'left' } }, day), 'hobsharp-m8.11-helical-left-2026-12-07.csv');
  assert.equal(resultsFileName({ hob: { normalModule: 0.125, gash: 'straight' } }, day), 'hobsharp-m0.125-straight-2026-12-07.csv');
  assert.equal(resultsFileName({ hob: { normalModule: 12.75, gash: 'straight' } }, day), 'hobsharp-m12.75-straight-2026-12-07.csv');
});

test('semicolons with decimal commas, read back by the measured grid import', () => {
  const measured = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (_, j) => 1.25 + i / 8 - j / 16));
  const caseObject = { ...paper, measured };
  const r = hobsharp.evaluate(caseObject);
  const text = resultsCsv(r, { caseObject, style: 'semicolon' });
  const lines = text.split('\n');
  assert.ok(lines.some((l) => /^X a1;mm\/rad;\d+,\d+;/.test(l)), 'decimal commas');
  assert.ok(!lines.some((l) => /^[XYZAB] a\d,/.test(l)), 'no comma separators');
  const at = lines.findIndex((l) => l.startsWith('# measured normal deviation (µm)'));
  const block = lines.slice(at, lines.indexOf('', at)).join('\n');
  assert.deepEqual(readMeasured(block, r.topography).values, measured);
});

test('the wheel profile CSV has its 41 points, r, R and Z in mm', () => {
  const r = hobsharp.evaluate(paper);
  const lines = profileCsv(r).trim().split('\n');
  assert.equal(lines[1], 'r_mm,R_mm,Z_mm');
  assert.equal(lines.length, 2 + 41);
  assert.deepEqual(lines[2].split(',').map(Number), [r.wheelProfile.r[0], r.wheelProfile.R[0], r.wheelProfile.Z[0]]);
  assert.ok(Math.abs(r.wheelProfile.R[0] - 49.999828) < 1e-5);
  assert.match(lines[0], /conjugate wheel/);
  // A dressed wheel's profile beside the conjugate one (the review of 2026-12-07: the CSV gave the
  // conjugate wheel alone, headed as the wheel's).
  const d = hobsharp.evaluate({ ...paper, wheel: { ...paper.wheel, profileOffset: { R: [30, 40, 50], offset: [2, -3, 4] } } });
  const dl = profileCsv(d).trim().split('\n');
  assert.equal(dl[1], 'r_mm,R_mm,Z_mm,R_dressed_mm,Z_dressed_mm');
  assert.equal(dl.length, 2 + 41);
  assert.deepEqual(dl[2].split(',').map(Number), [d.wheelProfile.r[0], d.wheelProfile.R[0], d.wheelProfile.Z[0], d.wheelProfile.dressedR[0], d.wheelProfile.dressedZ[0]]);
  assert.ok(d.wheelProfile.dressedR.some((v, i) => v !== d.wheelProfile.R[i]), 'the dressed wheel differs');
});

// The effect on the gear in the record (docs/gear-effect.md): with the hob's relief,
// each figure per flank with its unit (µm, arc-min) as the module gives it; without, the reason.
test('the effect on the gear: its figures per flank with their units, or why there are none', () => {
  const measured = [19, 24.25, 29.5, 34.75, 40].map((ri) => [-70, -52.5, -35, -17.5, 0, 17.5, 35, 52.5, 70].map((xj) => (ri - 29.5) + 0.1 * xj));
  const caseObject = { ...paper, hob: { ...paper.hob, gashes: 12, relief: 4.5 }, measured };
  const r = hobsharp.evaluate(caseObject);
  const g = r.gearEffect;
  assert.equal(g.reason, '');
  for (const style of ['comma', 'semicolon']) {
    const sep = style === 'comma' ? ',' : ';';
    const num = (v) => (style === 'comma' ? String(v) : String(v).replace('.', ','));
    const lines = resultsCsv(r, { caseObject, style }).split('\n');
    const at = lines.indexOf('# effect on the gear, from the measured rake face');
    assert.ok(at > 0, style);
    assert.equal(lines[at + 1], ['figure', 'unit', 'left flank (faces −x₁)', 'right flank (faces +x₁)'].join(sep));
    const expected = [
      ['profile slope deviation fHα (largest over the teeth)', 'µm', g.left.profileSlope, g.right.profileSlope],
      ['pressure-angle error of that tooth', 'arc-min', g.left.pressureAngleError, g.right.pressureAngleError],
      ['profile form deviation ffα (largest)', 'µm', g.left.profileForm, g.right.profileForm],
      ['scatter of fHα along the hob', 'µm', g.left.slopeScatter, g.right.slopeScatter]];
    expected.forEach(([label, unit, left, right], k) => assert.equal(lines[at + 2 + k], [label, unit, num(left), num(right)].join(sep)));
    assert.equal(lines[at + 6], '', 'the block ends after its four figures');
    // The tilt (more material toward the tip) gives fHα plus and a smaller pressure angle.
    assert.ok(g.left.profileSlope > 0 && g.left.pressureAngleError < 0);
    assert.doesNotMatch(lines.slice(at, at + 6).join('\n'), /NaN|undefined|Infinity/);
  }
  // The inputs of the relief are in the record's inputs.
  const lines = resultsCsv(r, { caseObject }).split('\n');
  assert.ok(lines.includes('hob.gashes,12,,hob.gashes') && lines.includes('hob.relief,4.5,,hob.relief'));

  const without = hobsharp.evaluate(paper);
  assert.match(without.gearEffect.reason, /no relief/);
  const text = resultsCsv(without, { caseObject: paper });
  assert.ok(!text.includes('fHα'), 'no figures without the relief');
  const at = text.split('\n').indexOf('# effect on the gear');
  assert.ok(at > 0);
  const reason = without.gearEffect.reason;
  assert.equal(text.split('\n')[at + 1], /[",;\n]/.test(reason) ? `no figures,"${reason.replace(/"/g, '""')}"` : `no figures,${reason}`);
});

// Axes run that alone grind no face the wheel envelops (Z a0 45 mm off the nominal): the
// correction is linearised at the nominal axes, and the module's topography is the nominal axes'
// face (about 0 everywhere), not a face of the axes run: the record writes no grid, and no
// thickness, as the axes run's (a review found the nominal face written as theirs).
test('axes run that grind no face: no simulated grid or thickness written as theirs', () => {
  const measured = Array.from({ length: 5 }, (_, i) => Array(9).fill(1 + i / 4));
  const nominal = hobsharp.evaluate(paper).axes;
  const axes = { ...nominal, Z: [nominal.Z[0] + 45, ...nominal.Z.slice(1)] };
  const caseObject = { ...paper, axes, measured };
  const r = hobsharp.evaluate(caseObject);
  assert.equal(r.correction.linearisedAtNominal, true);
  assert.ok(r.topography.rms < 1e-6, 'the nominal axes\' face stands in');
  const text = resultsCsv(r, { caseObject });
  assert.ok(text.includes('\n# no simulated face for the axes run: the axes run alone grind no face the wheel envelops'));
  assert.ok(!text.includes('simulated normal deviation'));
  assert.ok(!text.includes('simulated circular deviation'));
  assert.ok(!text.includes('# thickness error at the mean point'));
  assert.ok(text.includes('# measured normal deviation (µm)'), 'the measurement is kept');
  // With axes that grind a face, the grids are written (the first test's case, with a measurement).
  const ground = resultsCsv(hobsharp.evaluate({ ...paper, measured }), { caseObject: { ...paper, measured } });
  assert.ok(ground.includes('# simulated normal deviation (µm) for the axes run'));
});

// With the wheel's correction the record holds the dressing proposed: at its spline points, in µm
// with its words from the module, and the dresser path (R, Z, offset), which may reach past the
// points; an independent review found the record without it.
test('the results CSV holds the wheel dressing proposed and the dresser path', () => {
  const measured = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (_, k) => 2 * Math.sin(i) + 0.1 * k));
  const caseObject = { ...paper, measured, correction: { wheel: true } };
  const r = hobsharp.evaluate(caseObject);
  const w = r.correction.wheelProfileOffset;
  assert.ok(w.R.length >= 2);
  const text = resultsCsv(r, { caseObject });
  const lines = text.split('\n');
  const at = lines.findIndex((l) => l.startsWith('# wheel dressing proposed: '));
  assert.ok(at > 0, 'a dressing block');
  assert.match(lines[at], /\+ = more wheel/);
  assert.ok(lines[at + 1].includes('µm'));
  assert.match(lines[at + 2 + w.R.length], /axes remove|share/);
  for (let i = 0; i < w.R.length; i++) {
    const cells = lines[at + 2 + i].split(',');
    assert.equal(Number(cells[0]), w.R[i]);
    assert.equal(cells[1], 'mm');
    assert.equal(Number(cells[2]), w.offset[i]);
    assert.equal(cells[3], 'µm');
  }
  const path = lines.findIndex((l) => l.startsWith('# dresser path: '));
  assert.ok(path > at);
  assert.equal(lines.slice(path + 2).findIndex((l) => l === '') , r.correction.dresserPath.R.length);
  assert.ok(text.includes(`\n${r.correction.dresserPath.R[3]},${r.correction.dresserPath.Z[3]},${r.correction.dresserPath.offset[3]}\n`));
  // Without the wheel's correction, no such block.
  assert.ok(!resultsCsv(hobsharp.evaluate({ ...paper, measured }), { caseObject: { ...paper, measured } }).includes('# wheel dressing proposed'));
});
