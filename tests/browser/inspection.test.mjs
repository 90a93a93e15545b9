// The rake-face class on the page (issue 11, item 2): the verdict at the top of the topography,
// above its maps, and the checks with their class tolerances, measured and after the correction.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { afterError, afterResult, base, openPage, root, shots, useBrowser } from './support.mjs';

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

test('the tolerance table and the gash deviations are edited on the page, refused cells named, and kept in the link', async () => {
  const page = await openPage(base, { viewport: { width: 1366, height: 900 } });
  await page.click('#tolerance-editor summary');
  assert.match(await page.textContent('#tolerance-band'), /band over 6\.3 to 10 mm of normal module, from the default table/);
  const cell = (check, k) => `#tolerance-table input[data-check="${check}"][data-class="${k}"]`;
  assert.equal(await page.inputValue(cell('radialAlignment', 'A')), '', 'no public value: blank');
  assert.equal(await page.inputValue(cell('adjacentSpacing', 'AA')), '25');
  assert.ok(await page.isDisabled('#tolerance-default'));
  const grade = (check) => page.textContent(`#inspection-table tr[data-check="${check}"] td:nth-child(3)`);
  assert.equal(await grade('radialAlignment'), 'not graded');

  await afterResult(page, async () => { await page.fill('#gash-deviations', '0; 3; −2; 1,5'); await page.dispatchEvent('#gash-deviations', 'change'); });
  assert.equal(await page.textContent('#inspection-table tr[data-check="cumulativeSpacing"] td:nth-child(2)'), '5.000 µm');
  assert.match(await page.textContent('#inspection-verdict'), /class AA \(limited by the (cumulative|adjacent) spacing\)/);
  await afterResult(page, async () => { await page.fill(cell('radialAlignment', 'A'), '25'); await page.dispatchEvent(cell('radialAlignment', 'A'), 'change'); });
  assert.equal(await grade('radialAlignment'), 'A');
  assert.match(await page.textContent('#inspection-table tr[data-check="radialAlignment"]'), /A 25\.0/);
  assert.match(await page.textContent('#tolerance-band'), /the table this case carries \(edited\)/);
  const linked = decodeURIComponent(await page.evaluate(() => location.hash));
  assert.match(linked, /"gashDeviations":\[0,3,-2,1\.5\]/);
  assert.match(linked, /"radialAlignment":\{"A":\[null,null,null,null,null,25,null,null,null\],"source":"edited on the page"\}/);
  await page.locator('#inspection').screenshot({ path: path.join(shots, 'tolerance-editor.png') });

  // A cell that is not a number: named at the table, the rest of the page as it was.
  await afterError(page, async () => { await page.fill(cell('gashLead', 'B'), '1e'); await page.dispatchEvent(cell('gashLead', 'B'), 'change'); });
  assert.match(await page.textContent('#tolerance-error'), /inspection\.tolerances\.checks\.gashLead\.B|gash lead/i);
  assert.ok(await page.isHidden('#form-error'));
  await afterResult(page, async () => { await page.fill(cell('gashLead', 'B'), ''); await page.dispatchEvent(cell('gashLead', 'B'), 'change'); });
  assert.ok(await page.isHidden('#tolerance-error'));
  // A gash list the page cannot read changes nothing.
  await page.fill('#gash-deviations', '1, 2, x');
  await page.dispatchEvent('#gash-deviations', 'change');
  assert.match(await page.textContent('#tolerance-error'), /Gash deviation 3: "x" is not a number \(µm\)\. The gash deviations in use are unchanged\./);

  await afterResult(page, () => page.click('#tolerance-default'));
  assert.equal(await grade('radialAlignment'), 'not graded');
  assert.equal(await page.textContent('#inspection-table tr[data-check="cumulativeSpacing"] td:nth-child(2)'), '5.000 µm', 'the gashes stay');
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('one topography per gash from CSV files: the per-gash table, the spacing, and a file that does not fit named', async () => {
  const page = await openPage(base, { viewport: { width: 1366, height: 900 } });
  await page.click('#tolerance-editor summary');
  const grid = (shift) => Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, () => (shift + 0.5 * i).toFixed(3)).join(', ')).join('\n');
  const file = (name, text) => ({ name, mimeType: 'text/csv', buffer: Buffer.from(text) });
  // A file of the wrong shape: named, nothing changes.
  await page.setInputFiles('#gash-files', [file('gash-1.csv', grid(0)), file('gash-2.csv', '1, 2\n3, 4\n')]);
  // The files are read asynchronously: the message comes when they have been.
  await page.waitForFunction(() => document.querySelector('#tolerance-error').textContent !== '');
  assert.match(await page.textContent('#tolerance-error'), /^gash-2\.csv: The grid has 5 radial lines .* The gashes in use are unchanged\.$/);
  assert.ok(await page.isHidden('#per-gash'));
  await afterResult(page, () => page.setInputFiles('#gash-files', ['gash-1.csv', 'gash-2.csv', 'gash-3.csv', 'gash-10.csv']
    .map((name, k) => file(name, grid(k === 2 ? 12 : 2)))));
  assert.match(await page.textContent('#gash-files-read'), /^Gashes 1 to 4: gash-1\.csv, gash-2\.csv, gash-3\.csv, gash-10\.csv\.$/);
  assert.match(await page.textContent('#inspection-verdict'), /the worst of the gash topographies\): class/);
  const rows = await page.$$eval('#per-gash tbody tr', (trs) => trs.map((r) => [...r.children].map((x) => x.textContent.trim())));
  assert.equal(rows.length, 4);
  const deviations = rows.map((r) => Number(r[1]));
  assert.ok(Math.abs(deviations[2] - deviations[0] - 10) < 1e-9 && deviations[0] === deviations[1] && deviations[1] === deviations[3], JSON.stringify(rows));
  assert.equal(await page.textContent('#inspection-table tr[data-check="cumulativeSpacing"] td:nth-child(2)'), '10.000 µm');
  assert.equal(await page.getAttribute('#gash-deviations', 'placeholder'), 'from the 4 gash topographies');
  await page.locator('#inspection').screenshot({ path: path.join(shots, 'per-gash.png') });
  await afterResult(page, () => page.click('#gash-files-clear'));
  assert.ok(await page.isHidden('#per-gash'));
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
