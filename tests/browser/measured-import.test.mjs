// A measured grid as real files bring it (issue 11, item 1): the page's own exported grid, with
// its positions and written by a German spreadsheet (semicolons, decimal commas), values in mm by
// mistake, and a transposed grid, each shown on a preview with orientation options before use.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { afterResult, base, openPage, root, shots, useBrowser } from './support.mjs';

useBrowser();
const desk = { viewport: { width: 1366, height: 900 }, open: ['files-menu'] };  // the results CSV: under "Report and files…"

// The grid block of the page's results CSV in its German style (semicolons, decimal commas), as
// a spreadsheet saves it again (CRLF).
async function exportedGerman(page) {
  await page.selectOption('#csv-style', 'semicolon');
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-results')]);
  assert.match(download.suggestedFilename(), /^hobsharp-m\d+(\.\d+)?-helical-right-\d{4}-\d\d-\d\d\.csv$/);
  const text = readFileSync(await download.path(), 'utf8');
  assert.ok(text.startsWith('\uFEFF'), 'a BOM');
  const lines = text.split('\n');
  const start = lines.findIndex((l) => l.startsWith('# simulated normal deviation'));
  return lines.slice(start + 1, lines.indexOf('', start)).join('\r\n');
}
const previewValues = (page) => page.$$eval('#measured-preview-table tbody tr', (rows) => rows.map((r) => [...r.querySelectorAll('td')].map((c) => Number(c.textContent))));
const typed = async (page, text) => {
  const n = Number(await page.getAttribute('#measured-preview', 'data-previews'));
  await page.fill('#measured-csv', text);
  await page.waitForFunction((k) => Number(document.querySelector('#measured-preview').dataset.previews) > k &&
    !document.querySelector('#measured-preview').hidden, n);
};

test("the page's own export, as a German spreadsheet writes it, is read back; mm and a transposed grid are flagged", async () => {
  // Run axes as an engineer types them, Z 10 µm off: the face they grind is a plausible grid.
  const paper = JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
  const axes = { X: [22.4003, 139.5089, 0, 0, 0], Y: [39.3076, 0, 0, 0, 0], Z: [-116.436, 0, 0, 0, 0], A: [0, 1, 0, 0, 0], B: [0.220365, 0, 0, 0, 0] };
  const page = await openPage(`${base}#case=${encodeURIComponent(JSON.stringify({ ...paper, axes }))}`, desk);
  await page.waitForFunction(() => window.hobsharpTimings.results > 0);
  const german = await exportedGerman(page);
  assert.match(german, /^r \\ x;-?\d+(,\d+)?;/);
  await typed(page, german);
  assert.equal(await page.textContent('#measured-read'),
    'Read 5 × 9 values, with semicolons or tabs with decimal commas, a header row of 9 x positions (mm), a first column of 5 r positions (mm). Preview (µm, as it would be used):');
  assert.equal(await page.isHidden('#measured-warning'), true);
  await page.locator('#measured-section .pair > div:first-child').screenshot({ path: path.join(shots, 'measured-import-german.png') });
  await afterResult(page, () => page.click('#use-measured'));
  assert.equal(await page.isHidden('#measured-error'), true);
  assert.ok(Number(await page.getAttribute('#verdict', 'data-sse-before')) >= 0);

  // The same values in mm: flagged, and the option makes them µm again.
  const grid = await previewValues(page);
  await typed(page, grid.map((row) => row.map((v) => v / 1000).join(', ')).join('\n'));
  assert.match(await page.textContent('#measured-warning'), /these look like mm\. Tick "values in mm"/);
  await page.check('[data-orient="mm"]');
  await page.waitForFunction(() => Number(document.querySelector('#measured-preview-table td').textContent) > 0.05 ||
    Number(document.querySelector('#measured-preview-table td').textContent) < -0.05);
  assert.deepEqual(await previewValues(page), grid);
  assert.equal(await page.isHidden('#measured-warning'), true, 'the option answers the warning');
  assert.match(await page.textContent('#measured-read'), /the values in mm multiplied by 1000\):$/);
  await page.locator('#measured-section .pair > div:first-child').screenshot({ path: path.join(shots, 'measured-import-mm.png') });
  await page.uncheck('[data-orient="mm"]');

  // Transposed: 9 rows of 5; the preview says so, and "transpose" makes it fit.
  const transposed = grid[0].map((_, j) => grid.map((row) => row[j]));
  await typed(page, transposed.map((row) => row.join('\t')).join('\n'));
  assert.match(await page.textContent('#measured-warning'), /9 rows of 5 values: the grid written along the other direction\? Tick "transpose"\./);
  assert.equal(await page.isHidden('#measured-preview-table'), true, 'no preview of a grid that does not fit');
  await page.check('[data-orient="transpose"]');
  await page.waitForFunction(() => !document.querySelector('#measured-preview-table').hidden);
  assert.deepEqual(await previewValues(page), grid);
  await afterResult(page, () => page.click('#use-measured'));
  assert.equal(await page.isHidden('#measured-error'), true);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
