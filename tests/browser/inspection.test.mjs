// The rake-face class on the page (issue 11, item 2): the verdict at the top of the topography,
// above its maps, and the checks with their class tolerances, measured and after the correction.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { base, openPage, root, shots, useBrowser } from './support.mjs';

useBrowser();

test('the class verdict sits above the topography maps, with its checks', async () => {
  const paper = JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
  const measured = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (_, j) => 3 * i - 0.2 * j));
  const c = { ...paper, measured, inspection: { gashDeviations: [0, 1.5, -2, 0.5, 3, 0, -1, 0.25, 0, 2, -0.5, 1] } };
  const page = await openPage(`${base}#case=${encodeURIComponent(JSON.stringify(c))}`, { viewport: { width: 1366, height: 900 } });
  await page.waitForFunction(() => window.hobsharpTimings.results > 0 && !document.querySelector('#inspection').hidden);
  const verdict = await page.textContent('#inspection-verdict');
  assert.match(verdict, /^Rake face \(DIN 3968, module band over 6\.3 to 10 mm, measured face\): class (AA|A|B|C|D|outside D) \(limited by the cumulative spacing\); predicted after the correction: class /);
  const [v, maps] = await page.evaluate(() => [document.querySelector('#inspection-verdict'), document.querySelector('#plot-before-2d')]
    .map((e) => e.getBoundingClientRect().top + window.scrollY));
  assert.ok(v < maps, 'the verdict comes before the maps');
  const rows = await page.$$eval('#inspection-table tbody tr', (trs) => trs.map((r) => [...r.children].map((x) => x.textContent.trim())));
  assert.deepEqual(rows.map((r) => r[0]), ['cutting-face form', 'radial alignment', 'gash lead', 'adjacent spacing', 'cumulative spacing']);
  assert.deepEqual(rows[4].slice(0, 2), ['cumulative spacing', '5.000 µm']);
  assert.match(rows[4][3], /^AA [\d.]+ · A [\d.]+ · B [\d.]+ · C [\d.]+ · D [\d.]+$/);
  assert.equal(rows[1][1], '12.000 µm');
  assert.equal(rows[1][3], 'none in the table');
  assert.equal(rows[0].length, 6, 'with the columns after the correction');
  assert.doesNotMatch(JSON.stringify(rows), /NaN|undefined|Infinity/);
  await page.locator('#topography-section').screenshot({ path: path.join(shots, 'inspection.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
