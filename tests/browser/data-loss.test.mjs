// Item 6, "data loss": nothing the user gave is dropped silently. A loaded case's run axes (a
// second pass) are used, shown, clearable and saved; the what-if offsets are saved and loaded (in
// the case's page member); the paper example asks before it replaces a measured grid.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterResult, base, ON_DEMAND, openPage, root, settled, shots, useBrowser } from './support.mjs';

useBrowser();
const desk = { viewport: { width: 1366, height: 768 }, open: ON_DEMAND };  // the engineer's screen
const dir = mkdtempSync(path.join(tmpdir(), 'hobsharp-'));
const paper = JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
// The paper's Tab. 2 with the wheel 10 µm off along its axis: a second pass that ran the axes off.
const runAxes = { X: [22.4003, 139.5089, 0, 0, 0], Y: [39.30757, 0, 0, 0, 0], Z: [-116.436, 0, 0, 0, 0], A: [0, 1, 0, 0, 0], B: [0.2203653, 0, 0, 0, 0] };

function caseFile(name, c) {
  const file = path.join(dir, name);
  writeFileSync(file, JSON.stringify(c));
  return file;
}
async function save(page) {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-case')]);
  return JSON.parse(readFileSync(await download.path(), 'utf8'));
}
const sse = async (page) => Number(/sum of squares ([\d.e+-]+)/.exec(await page.textContent('#figures-before'))[1]);

test('a case\'s run axes are used, shown, saved, and can be cleared', async () => {
  const page = await openPage(base, desk);
  await afterResult(page, () => page.setInputFiles('#load-case', caseFile('second-pass.json', { ...paper, axes: runAxes })));
  assert.equal(await page.isVisible('#run-axes'), true);
  assert.match(await page.textContent('[data-run-axis="Z"]'), /−116\.436$/);
  assert.ok(await sse(page) > 1000, 'the face is ground with the run axes: about 10 µm off');
  await page.locator('#axes-section').screenshot({ path: path.join(shots, 'run-axes.png') });
  assert.deepEqual((await save(page)).axes, runAxes);
  await afterResult(page, () => page.click('#clear-run-axes'));
  assert.equal(await page.isVisible('#run-axes'), false);
  assert.ok(await sse(page) < 1e-3, 'the nominal axes again');
  assert.equal((await save(page)).axes, undefined);
  await page.context().close();
});

test('save and load keep the run axes, the what-if offsets, the measured grid and the locks', async () => {
  const page = await openPage(base, desk);
  await afterResult(page, () => page.setInputFiles('#load-case', caseFile('pass.json', { ...paper, axes: runAxes })));
  for (const [k, v] of Object.entries({ 'Z 0': '-0.01', 'B 2': '0.001' })) {
    await page.fill(`[data-offset="${k}"]`, v);
    await page.dispatchEvent(`[data-offset="${k}"]`, 'change');
  }
  await afterResult(page, () => page.click('#generate-error'));
  await afterResult(page, () => page.check('[data-lock-axis="A"]'));
  await afterResult(page, () => page.check('[data-lock="B a2"]'));
  const saved = await save(page);
  assert.deepEqual(saved.axes, runAxes);
  assert.deepEqual(saved.page, { whatIf: { Z: [-0.01], B: [0, 0, 0.001] } });
  assert.equal(saved.measured.length, 5);
  // The what-if's grid is noise-free, and the correction is told so (web/src/probe-noise.js).
  assert.deepEqual(saved.correction, { probeNoise: 1e-4, lockedAxes: ['A'], locked: ['B a2'] });

  const again = await openPage(base, desk);
  await afterResult(again, () => again.setInputFiles('#load-case', caseFile('saved.json', saved)));
  assert.equal(await again.inputValue('[data-offset="Z 0"]'), '-0.01');
  assert.equal(await again.inputValue('[data-offset="B 2"]'), '0.001');
  assert.equal(await again.isChecked('[data-lock-axis="A"]'), true);
  assert.equal(await again.isChecked('[data-lock="B a2"]'), true);
  assert.equal(await again.isVisible('#run-axes'), true);
  assert.notEqual(await again.getAttribute('#verdict', 'data-sse-after'), null, 'the measured grid is used');
  assert.deepEqual(await save(again), saved);
  await again.context().close();
  await page.context().close();
});

test('locks without a measured grid are saved too', async () => {
  const page = await openPage(base, desk);
  await page.check('[data-lock="X a1"]');
  const saved = await save(page);
  assert.deepEqual(saved.correction, { lockedAxes: [], locked: ['X a1'] });
  const again = await openPage(base, desk);
  await afterResult(again, () => again.setInputFiles('#load-case', caseFile('locks.json', saved)));
  assert.equal(await again.isChecked('[data-lock="X a1"]'), true);
  await again.context().close();
  await page.context().close();
});

test('the paper example asks before it replaces a measured grid', async () => {
  const page = await openPage(base, desk);
  await page.fill('#measured-csv', Array.from({ length: 5 }, () => Array(9).fill('1.0').join(', ')).join('\n'));
  await afterResult(page, () => page.click('#use-measured'));
  const asked = [];
  const dialog = page.waitForEvent('dialog');
  page.once('dialog', (d) => { asked.push(d.message()); d.dismiss(); });
  await page.click('#preset-paper');
  await dialog;
  await settled(page);
  assert.match(asked[0] || '', /replaces the measured grid \(5 × 9 values\)/);
  assert.equal(Number(await page.getAttribute('#verdict', 'data-sse-before')), 45, 'kept when the user says no');
  page.once('dialog', (d) => d.accept());
  await afterResult(page, () => page.click('#preset-paper'));
  assert.equal(await page.getAttribute('#verdict', 'data-sse-before'), null);
  assert.equal(await page.inputValue('#measured-csv'), '');
  // And Undo brings it back.
  await afterResult(page, () => page.click('#undo'));
  assert.equal(Number(await page.getAttribute('#verdict', 'data-sse-before')), 45);
  assert.match(await page.inputValue('#measured-csv'), /^1, 1, 1/);
  await page.context().close();
});
