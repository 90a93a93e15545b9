// The inspection's inputs as the page edits them (web/src/tolerance-edit.js): a cell of the
// tolerance table in the hob's band, the default table back, the gash deviations; and the
// calculator grading with what the page writes.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { cellConfidence, cellTexts, gashText, isEdited, parseGashDeviations, tableInUse, uncertaintyText, withCell, withDefaultTable, withGashDeviations,
  withUncertainty } from '../../web/src/tolerance-edit.js';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const defaults = { moduleBands: [1, 2, 4], checks: { adjacentSpacing: { source: 'catalogue', AA: [5, 6], A: [8, 9] } } };

test('a cell typed: the case carries the edited table, the default is not changed, the source says so', () => {
  const extra = { wheel: { profileOffset: { R: [30, 50], offset: [0, 1] } } };
  let e = withCell(extra, defaults, { band: 1, check: 'radialAlignment', klass: 'B', text: '12,5' });
  assert.deepEqual(e.inspection.tolerances.checks.radialAlignment, { B: [null, 12.5], source: 'edited on the page' });
  assert.deepEqual(e.wheel, extra.wheel, 'the rest of the case stays');
  assert.deepEqual(defaults.checks.adjacentSpacing.AA, [5, 6], 'the default table is not changed in place');
  e = withCell(e, defaults, { band: 0, check: 'adjacentSpacing', klass: 'AA', text: '' });
  e = withCell(e, defaults, { band: 0, check: 'adjacentSpacing', klass: 'A', text: '7' });
  // The default table's cells are printed in its source (docs/inspection.md); a cell typed is entered.
  assert.deepEqual(e.inspection.tolerances.checks.adjacentSpacing, { source: 'catalogue; edited on the page', AA: [null, 6], A: [7, 9],
    confidence: { AA: ['entered', 'printed'], A: ['entered', 'printed'] } });
  assert.equal(cellConfidence(tableInUse(e, defaults), { band: 1, check: 'adjacentSpacing', klass: 'A', edited: true }), 'printed');
  assert.equal(cellConfidence(tableInUse(e, defaults), { band: 0, check: 'adjacentSpacing', klass: 'A', edited: true }), 'entered');
  assert.equal(cellConfidence(tableInUse(e, defaults), { band: 1, check: 'radialAlignment', klass: 'B', edited: true }), 'entered');
  assert.equal(cellConfidence(defaults, { band: 1, check: 'adjacentSpacing', klass: 'A', edited: false }), 'printed');
  assert.ok(isEdited(e));
  assert.deepEqual(cellTexts(tableInUse(e, defaults), 1, ['adjacentSpacing', 'gashLead'], ['AA', 'A', 'B']),
    { adjacentSpacing: { AA: '6', A: '9', B: '' }, gashLead: { AA: '', A: '', B: '' } });
  assert.equal(withCell(e, defaults, { band: 1, check: 'gashLead', klass: 'A', text: '1e' }).inspection.tolerances.checks.gashLead.A[1], '1e',
    'not a number: kept, for the calculator to name');
  const back = withDefaultTable(e);
  assert.ok(!isEdited(back));
  assert.deepEqual(back, { wheel: extra.wheel }, 'an empty inspection member is left out');
});

test('gash deviations: commas, blanks or semicolons with decimal commas; a value that is not a number is named', () => {
  assert.deepEqual(parseGashDeviations('0, 1.5  -2\t0.5'), [0, 1.5, -2, 0.5]);
  assert.deepEqual(parseGashDeviations('0,5; −1,25; 3'), [0.5, -1.25, 3]);
  assert.equal(parseGashDeviations('  '), null);
  assert.throws(() => parseGashDeviations('1, 2, x3'), /^Error: Gash deviation 3: "x3" is not a number \(µm\)\.$/);
  const e = withGashDeviations({}, [1, 2, 3]);
  assert.deepEqual(e, { inspection: { gashDeviations: [1, 2, 3] } });
  assert.equal(gashText(e), '1, 2, 3');
  assert.deepEqual(withGashDeviations(e, null), {});
});

test('the calculator grades with the table the page writes, in the band it names', async () => {
  const hobsharp = await loadHobSharp();
  const table = hobsharp.limits().inspection.defaultTolerances;
  const plain = hobsharp.evaluate(paper).inspection;
  const band = plain.moduleBandIndex;
  assert.equal(plain.moduleBand, `over ${table.moduleBands[band]} to ${table.moduleBands[band + 1]} mm`);
  assert.ok(table.moduleBands[band] < paper.hob.normalModule && paper.hob.normalModule <= table.moduleBands[band + 1]);
  // The default table has no row for the form (DIN 3968 grades form and position together).
  assert.equal(plain.checks.cuttingFaceForm.grade, 'not graded');
  let extra = withCell({}, table, { band, check: 'cuttingFaceForm', klass: 'A', text: '25' });
  extra = withGashDeviations(extra, parseGashDeviations('0, 3, -2, 1'));
  const i = hobsharp.evaluate({ ...paper, ...extra }).inspection;
  assert.equal(i.checks.cuttingFaceForm.grade, 'A', 'the simulated nominal face is within any tolerance');
  assert.deepEqual(i.checks.cuttingFaceForm.tolerances, [25]);
  assert.equal(i.checks.cuttingFaceForm.confidence, 'entered');
  // The default table's other cells keep their marks in the case's copy.
  assert.equal(i.checks.radialAlignment.confidence, plain.checks.radialAlignment.confidence);
  assert.equal(i.checks.adjacentSpacing.confidence, 'printed');
  assert.equal(i.cumulativeSpacing, 5);
  assert.deepEqual(i.checks.adjacentSpacing.tolerances, [0, 1, 2, 3, 4].map((k) => table.checks.adjacentSpacing[['AA', 'A', 'B', 'C', 'D'][k]][band]));
  const bad = withCell({}, table, { band, check: 'gashLead', klass: 'A', text: '1e' });
  assert.throws(() => hobsharp.evaluate({ ...paper, ...bad }), (e) => /^inspection\.tolerances\.checks\.gashLead\.A/.test(e.field), 'the cell is named');
  assert.equal(hobsharp.evaluate(paper).inspection.class, plain.class, 'the module stays usable');
});

test('the uncertainty U95: typed, kept in the case; blank is the default; a text is kept for the calculator to name', async () => {
  const extra = { inspection: { gashDeviations: [1, 2, 3] } };
  const e = withUncertainty(extra, ' 1,5 ');
  assert.deepEqual(e, { inspection: { gashDeviations: [1, 2, 3], uncertainty: 1.5 } });
  assert.equal(uncertaintyText(e), '1.5');
  assert.deepEqual(extra, { inspection: { gashDeviations: [1, 2, 3] } }, 'not changed in place');
  assert.deepEqual(withUncertainty(e, ''), extra);
  assert.deepEqual(withUncertainty({}, '0'), { inspection: { uncertainty: 0 } });
  assert.equal(uncertaintyText({}), '');
  assert.deepEqual(withUncertainty({}, '2x'), { inspection: { uncertainty: '2x' } });
  const hobsharp = await loadHobSharp();
  assert.equal(hobsharp.evaluate({ ...paper, ...withUncertainty({}, '4') }).inspection.uncertainty, 4);
  assert.throws(() => hobsharp.evaluate({ ...paper, ...withUncertainty({}, '2x') }), (err) => err.field === 'inspection.uncertainty');
  assert.throws(() => hobsharp.evaluate({ ...paper, ...withUncertainty({}, '101') }), (err) => err.field === 'inspection.uncertainty');
});
