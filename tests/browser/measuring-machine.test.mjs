// A measuring machine's files on the page (issue 22, item 3): a grid and a points file with lines
// above the table are read, their record (part, date, operator) and what was skipped shown; a points
// or grid file the calculator refuses leaves the page showing what is in use: the status says it was
// refused and why, in words; the box, its preview and the verdict are the measurement in use.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync, mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterResult, after_, openPage, root, shots, useBrowser } from './support.mjs';

useBrowser();
const desk = { viewport: { width: 1366, height: 900 } };
const data = (name) => readFileSync(path.join(root, 'tests', 'data', name), 'utf8');
const pointsText = data('points-preamble.csv');
const dir = mkdtempSync(path.join(tmpdir(), 'hobsharp-machine-'));
const file = (name, text) => {
  const p = path.join(dir, name);
  writeFileSync(p, text);
  return p;
};
const shown = (page) => page.evaluate(() => ({
  status: document.querySelector('#status').textContent,
  statusKind: document.querySelector('#status').className,
  error: document.querySelector('#measured-error').hidden ? '' : document.querySelector('#measured-error').textContent,
  read: document.querySelector('#measured-read').textContent,
  previewHidden: document.querySelector('#measured-preview').hidden,
  box: document.querySelector('#measured-csv').value,
  verdict: document.querySelector('#verdict').textContent,
  sseBefore: document.querySelector('#verdict').dataset.sseBefore,
  title: document.querySelector('#before-title').textContent,
  body: document.body.innerText,
}));
// The machine's file with two points off the rake face (the 81st and the 120th).
const offFace = (() => {
  const lines = pointsText.split('\r\n');
  lines[8 + 80] = '5;0;1';
  lines[8 + 119] = '6;0;1';
  return lines.join('\r\n');
})();
// Waits until the refusal is in the status (after the measurement in use is computed again).
const afterRefusal = async (page, action) => {
  await after_(page, 'errors', action);
  await page.waitForFunction(() => document.querySelector('#status').className === 'error' &&
    /is refused/.test(document.querySelector('#status').textContent), null, { timeout: 20000 });
};

test('a points file with a preamble is read; one with points off the face is refused and the page shows what is in use', async () => {
  const page = await openPage(undefined, desk);
  await afterResult(page, () => page.setInputFiles('#measured-file', file('points-preamble.csv', pointsText)));
  await page.waitForFunction(() => /^Measured at 300 points/.test(document.querySelector('#before-title').textContent));
  const good = await shown(page);
  assert.equal(good.read, 'Read a points file: 300 points, semicolons with decimal commas. Part Wälzfräser 4711, date 26.11.2026, ' +
    'operator Meier. Skipped 6 lines above the table: line 1 "Klingelnberg P 26;Spanflächenprüfung", line 2 "Datum;26.11.2026", ' +
    'line 3 "Uhrzeit;14:32", line 4 "Werkstück;Wälzfräser 4711", line 5 "Bediener;Meier", line 6 "Messprogramm;SPANFL_01". ' +
    'Preview (r and x in mm, deviation in µm, as it would be used):');
  assert.match(good.verdict, /Correctable/);
  assert.match(good.status, /^Updated/);
  assert.equal(good.error, '');
  // Kept for the record (the report): the file's name and its metadata.
  assert.deepEqual(await page.evaluate(() => window.hobsharpTest.measuredSource()), {
    name: 'points-preamble.csv', what: '300 points', meta: { date: '26.11.2026', part: 'Wälzfräser 4711', operator: 'Meier' } });

  await afterRefusal(page, () => page.setInputFiles('#measured-file', file('off-face.csv', offFace)));
  const s = await shown(page);
  // The status: refused, why, in words, the point counted from 1 (not `measuredPoints[80]`).
  assert.match(s.status, /^off-face\.csv is refused \(points-preamble\.csv stays in use\): Measured point 81: \(r, x\) = \(5, 0\) mm is off the rake face/);
  assert.equal(s.statusKind, 'error');
  assert.match(s.error, /^off-face\.csv is refused: Measured point 81: \(r, x\) = \(5, 0\) mm is off the rake face, .* In use: points-preamble\.csv \(300 points\)\.$/);
  // The preview and the verdict: the measurement in use, said so.
  assert.equal(s.box, good.box, 'the box holds the file in use again');
  assert.match(s.read, /^In use, points-preamble\.csv: Read a points file: 300 points, /);
  assert.equal(s.previewHidden, false);
  assert.equal(s.sseBefore, good.sseBefore, 'the verdict is the one of the points in use');
  assert.equal(s.verdict, good.verdict);
  assert.match(s.title, /^Measured at 300 points/);
  assert.doesNotMatch(s.body, /measuredPoints|hob\.gashes|hob\.relief|correction\.wheel/, 'no JSON path on the page');
  await page.locator('#measured-section .pair > div:first-child').screenshot({ path: path.join(shots, 'machine-points-refused.png') });
  await page.locator('#status').screenshot({ path: path.join(shots, 'machine-points-refused-status.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('a first points file refused leaves no measurement in use, and says so', async () => {
  const page = await openPage(undefined, desk);
  const before = await shown(page);
  await afterRefusal(page, () => page.setInputFiles('#measured-file', file('off-face.csv', offFace)));
  const s = await shown(page);
  assert.match(s.status, /^off-face\.csv is refused \(no measurement in use\): Measured point 81: /);
  assert.match(s.error, /In use: no measurement \(the face simulated for the axes run\)\.$/);
  assert.equal(s.box, '', 'nothing in the box: nothing is in use');
  assert.equal(s.previewHidden, true);
  assert.equal(s.verdict, before.verdict);
  assert.doesNotMatch(s.title, /^Measured/);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('a grid file with a preamble is read with its record; a later file the page refuses leaves it in use', async () => {
  const page = await openPage(undefined, desk);
  await afterResult(page, () => page.setInputFiles('#measured-file', file('grid-preamble.csv', data('grid-preamble.csv'))));
  const good = await shown(page);
  assert.match(good.read, /^Read 5 × 9 values, with semicolons or tabs with decimal commas, a header row of 9 x positions \(mm\), a first column of 5 r positions \(mm\)\. Part hob 4711, date 2026-11-26, operator Meier\. Skipped 5 lines above the table: line 1 "Zeiss O-INSPECT; rake face", /);
  assert.ok(Number(good.sseBefore) > 0, 'the grid is corrected');
  await after_(page, 'errors', () => page.setInputFiles('#measured-file', file('bad.csv', '1;2;x\n4;5;6\n')));
  const s = await shown(page);
  assert.match(s.status, /^bad\.csv is refused \(grid-preamble\.csv stays in use\): Line 1, column 3: "x" is not a number/);
  assert.match(s.error, /^bad\.csv is refused: Line 1, column 3: .* In use: grid-preamble\.csv \(5 × 9 values\)\.$/);
  assert.equal(s.box, good.box);
  assert.match(s.read, /^In use, grid-preamble\.csv: Read 5 × 9 values/);
  assert.equal(s.sseBefore, good.sseBefore);
  await page.locator('#measured-section .pair > div:first-child').screenshot({ path: path.join(shots, 'machine-grid-refused.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

// The calculator (not the page's reader) refuses a grid: a value beyond 10 mm. The grid in use stays
// in use, as with points: nothing is set aside, the box and the preview are the grid in use.
test('a grid file the calculator refuses leaves the grid in use, and says why in words', async () => {
  const page = await openPage(undefined, desk);
  await afterResult(page, () => page.setInputFiles('#measured-file', file('grid-preamble.csv', data('grid-preamble.csv'))));
  const good = await shown(page);
  const wild = data('grid-preamble.csv').replace('29,5;4,862;4,063;3,367;2,773;', '29,5;4,862;4,063;3,367;20000;');
  assert.notEqual(wild, data('grid-preamble.csv'));
  await afterRefusal(page, () => page.setInputFiles('#measured-file', file('wild.csv', wild)));
  const s = await shown(page);
  const why = 'Measured grid, row 3 (r = 29.5 mm), value 4 (x = -17.5 mm): must lie within ±10000 µm (10 mm); got 20000 µm.';
  assert.equal(s.status, `wild.csv is refused (grid-preamble.csv stays in use): ${why}`);
  assert.equal(s.statusKind, 'error');
  assert.equal(s.error, `wild.csv is refused: ${why} In use: grid-preamble.csv (5 × 9 values).`);
  assert.equal(s.box, good.box, 'the box holds the grid in use again');
  assert.match(s.read, /^In use, grid-preamble\.csv: Read 5 × 9 values/);
  assert.equal(s.sseBefore, good.sseBefore, 'the verdict is the grid in use');
  assert.equal(s.verdict, good.verdict);
  assert.equal(await page.evaluate(() => document.querySelector('#notice').hidden), true, 'nothing set aside');
  assert.equal((await page.evaluate(() => window.hobsharpTest.measuredSource())).name, 'grid-preamble.csv');
  assert.doesNotMatch(s.body, /measured\[|grid\.radial|measuredPoints/, 'no JSON path on the page');
  await page.locator('#measured-section .pair > div:first-child').screenshot({ path: path.join(shots, 'machine-grid-calculator-refused.png') });
  // The same grid typed into the box and used: refused as the box's, its text kept there to be
  // corrected; the grid in use stays in use.
  await page.fill('#measured-csv', wild);
  await afterRefusal(page, () => page.click('#use-measured'));
  const typed = await shown(page);
  assert.equal(typed.status, `The grid in the box is refused (grid-preamble.csv stays in use): ${why}`);
  assert.equal(typed.box.replace(/\r\n?/g, '\n'), wild.replace(/\r\n?/g, '\n'), 'the typed text stays, to be corrected');
  assert.equal(typed.sseBefore, good.sseBefore);
  // The next edit computes with the grid in use.
  await page.fill('#measured-csv', good.box);
  await afterResult(page, () => page.click('#use-measured'));
  assert.equal((await shown(page)).sseBefore, good.sseBefore);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('a wheel file the page refuses clears the earlier file\'s "Read ..." note', async () => {
  const page = await openPage(undefined, desk);
  await afterResult(page, () => page.setInputFiles('#wheel-file', file('dressed.csv', 'R (mm);offset (µm)\n29,6;0\n40;4\n49,9;0\n')));
  assert.match(await page.textContent('#wheel-read'), /^Read dressed\.csv: 3 points/);
  await page.setInputFiles('#wheel-file', file('bad.csv', 'R (mm),offset\n30,1\n40,2\n'));
  await page.waitForFunction(() => !document.querySelector('#wheel-error').hidden);
  assert.equal(await page.textContent('#wheel-read'), '', 'no note of the earlier file beside the refusal');
  assert.match(await page.textContent('#wheel-source'), /offset at 3 points/, 'what is in use is said there');
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
