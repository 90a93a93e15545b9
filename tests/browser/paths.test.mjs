// No path of the case file reaches the page: a case file refused for a member the form has no
// input for (a pass's axes, the inspection's gash deviations, the correction's method, the job)
// names it in words, counted from 1, in the notice, the status and at the options.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { openPage, root, settled, useBrowser } from './support.mjs';

useBrowser();

const paper = () => JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
const caseFile = (name, c) => ({ name, mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(c)) });
const zeros = (n) => Array(n).fill(0);
const axes = () => ({ X: zeros(5), Y: zeros(5), Z: zeros(5), A: zeros(5), B: zeros(5) });
// A JSON path: a member of the case and a dot or an index ("passes[0].axes", "inspection.gashDeviations").
const PATH = /\b(format|hob|wheel|setup|machine|degree|grid|axes|measured|measuredPoints|correction|passes|inspection|job|page)(\.[A-Za-z]\w*|\[\d+\])+/;

const files = [
  ['a pass\'s axis coefficient', (c) => { c.passes = [{ axes: { ...axes(), X: [0, 'a', 0, 0, 0] }, measured: c.measured }]; },
    /Pass 1, run axis X, coefficient a1 must be a number/],
  ['a gash deviation', (c) => { c.inspection = { gashDeviations: [1, 'x', 2] }; }, /Inspection, gash 2's deviation must be a number/],
  ['the correction method', (c) => { c.correction = { method: 'guess' }; }, /Correction method must be one of/],
  ['the job number', (c) => { c.job = { number: 5 }; }, /job number|Job/i],
];

for (const [what, spoil, words] of files) {
  test(`a case file refused for ${what} names it in words, not by its path`, async () => {
    const page = await openPage();
    const c = paper();
    c.measured = Array.from({ length: c.grid.radial }, () => zeros(c.grid.axial));
    spoil(c);
    await page.setInputFiles('#load-case', caseFile('spoilt.json', c));
    await page.waitForFunction(() => /spoilt\.json/.test(document.querySelector('#notice-text').textContent + document.querySelector('#status').textContent));
    await settled(page);  // the loader's checks too (the calculator is busy while it checks)
    const shown = [await page.textContent('#notice-text'), await page.textContent('#status'),
      await page.textContent('#correction-options-error')].join(' | ');
    assert.match(shown, words, shown);
    assert.doesNotMatch(shown, PATH, shown);
    await page.context().close();
  });
}
