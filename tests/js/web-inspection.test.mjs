// The rake-face inspection as the page shows it (web/src/inspection-table.js), from the module's
// result: the verdict sentence and the rows of checks, measured and after the correction.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { inspectionRows, verdictSentence } from '../../web/src/inspection-table.js';

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const hobsharp = await loadHobSharp();

test('the verdict names the class, the limiting check and the class after the correction', () => {
  const measured = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, () => 3 * i));
  const gashDeviations = [0, 1.5, -2, 0.5, 3, 0, -1, 0.25, 0, 2, -0.5, 1];
  const r = hobsharp.evaluate({ ...paper, measured, inspection: { gashDeviations } });
  const text = verdictSentence(r.inspection);
  assert.match(text, new RegExp(`^Rake face \\(DIN 3968, module band over 6\\.3 to 10 mm, measured face\\): class ${r.inspection.class} \\(limited by the cumulative spacing\\); predicted after the correction: class ${r.inspection.after.class}`));
  const rows = inspectionRows(r.inspection);
  assert.deepEqual(rows.map((x) => x.check), ['cuttingFaceForm', 'radialAlignment', 'gashLead', 'adjacentSpacing', 'cumulativeSpacing']);
  const cumulative = rows.find((x) => x.check === 'cumulativeSpacing');
  assert.equal(cumulative.value, 5);
  assert.equal(cumulative.grade, r.inspection.checks.cumulativeSpacing.grade);
  assert.match(cumulative.tolerances, /^AA [\d.]+ · A [\d.]+/);
  assert.ok(Math.abs(cumulative.after.value - r.inspection.after.cumulativeSpacing) < 1e-12);
  const radial = rows.find((x) => x.check === 'radialAlignment');
  assert.equal(radial.value, 12, 'a 3 µm rise per radial line over 4 steps');
  assert.equal(radial.tolerances, 'none in the table');
  assert.equal(radial.unit, 'µm');
});

test('without a measured face or gash deviations: the simulated face, no after column, and not graded said in words', () => {
  const r = hobsharp.evaluate(paper);
  const text = verdictSentence(r.inspection);
  assert.match(text, /simulated face\): not graded \(the tolerance table has no value for this module on any check computed\)\.$/);
  assert.ok(inspectionRows(r.inspection).every((x) => x.after === null));
  assert.equal(verdictSentence(undefined), '');
});
