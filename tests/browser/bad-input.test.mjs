// Bad input through a link, a file, the paste box and a worker that stops answering: each is
// refused or recovered from with a message that stays, and the page goes on working.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync, mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterError, afterResult, base, count, openPage, plotted, root, shots, tab2, useBrowser } from './support.mjs';

useBrowser();

const paper = () => JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
const link = (c) => `${base}#case=${encodeURIComponent(typeof c === 'string' ? c : JSON.stringify(c))}`;
const paperX = '22.40001 + 139.5089 φ₁';  // the paper example with gamma_m derived
const notice = (page) => page.textContent('#notice-text');

// The notice is still there once everything has settled: not overwritten at once.
async function noticeStays(page, pattern) {
  await plotted(page);  // settled: nothing left that could overwrite it
  assert.equal(await page.isVisible('#notice'), true, 'the notice is on screen');
  assert.match(await notice(page), pattern);
}

test('a link nested 5,000 deep is refused with a message that stays, and the paper case loads', async () => {
  const c = paper();
  c.machine.K1 = 120;
  c.measured = 'DEEP';  // written as text: Node's own JSON.stringify runs out of stack at this depth
  const page = await openPage(link(JSON.stringify(c).replace('"DEEP"', '['.repeat(5000) + ']'.repeat(5000))));
  assert.equal((await tab2(page, 'nominal')).X, paperX);
  assert.equal(await page.inputValue('[data-field="machine.K1"]'), '100');
  await noticeStays(page, /^The link: the case holds lists or objects nested more than 32 deep.*The paper example is loaded instead\.$/);
  await page.locator('#status-bar').screenshot({ path: path.join(shots, 'bad-link.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('a link whose measured rows are not lists loads the rest, the grid set aside as text', async () => {
  const c = paper();
  c.machine.K1 = 120;
  c.measured = [1, 2, 3, 4, 5];
  const page = await openPage(link(c));
  assert.equal(await page.inputValue('[data-field="machine.K1"]'), '120');
  assert.notEqual((await tab2(page, 'nominal')).X, paperX);
  assert.equal(await page.inputValue('#measured-csv'), '[1,2,3,4,5]');
  // In words, the row counted from 1 (issue 22), never the path measured[0].
  assert.equal(await page.textContent('#measured-error'), 'Measured grid, row 1: must be a list of values; got a number.');
  await noticeStays(page, /^The link: the measured grid is set aside, not used: Measured grid, row 1: must be a list of values; got a number\. /);
  assert.equal(await page.getAttribute('#verdict', 'data-sse-after'), null);
  await page.context().close();
});

for (const [what, correction, field] of [
  ['correction.locked is not a list', { locked: 'X a0' }, 'Locked coefficients'],
  ['correction.lockedAxes is not a list', { lockedAxes: { A: true } }, 'Locked axes'],
]) {
  test(`a link whose ${what} loads the rest and says why the locks are left out`, async () => {
    const c = paper();
    c.measured = Array.from({ length: 5 }, () => Array(9).fill(1));
    c.correction = correction;
    const page = await openPage(link(c));
    await noticeStays(page, new RegExp(`^The link: its correction settings are left out: ${field} must be a list`));
    assert.equal(Number(await page.getAttribute('#verdict', 'data-sse-before')), 45, 'the measured grid is used');
    assert.equal(await page.locator('[data-lock]:checked, [data-lock-axis]:checked').count(), 0);
    await page.context().close();
  });
}

test('a case file whose measured grid has the wrong shape: refused once, its text kept, never resent', async () => {
  const page = await openPage();
  const c = paper();
  c.machine.K1 = 120;
  c.measured = Array.from({ length: 4 }, () => Array(9).fill(2.5));
  const file = path.join(mkdtempSync(path.join(tmpdir(), 'hobsharp-')), 'wrong-shape.json');
  writeFileSync(file, JSON.stringify(c));
  await afterResult(page, () => page.setInputFiles('#load-case', file));
  assert.equal(await page.inputValue('[data-field="machine.K1"]'), '120');
  assert.equal((await page.inputValue('#measured-csv')).split('\n').length, 4, "the user's grid stays in the box");
  assert.match(await page.textContent('#measured-error'), /^Measured grid: needs 5 rows \(the radial grid lines\) of 9 values \(the axial grid lines\); got 4 x 9\.$/);
  await noticeStays(page, /^wrong-shape\.json: the measured grid is set aside/);
  // Later edits are computed, without the refused grid.
  const errors = await count(page, 'errors');
  for (const tilt of ['16', '17']) {
    await afterResult(page, () => page.fill('[data-field="setup.tilt"]', tilt));
  }
  assert.equal(await count(page, 'errors'), errors, 'no refusal: the grid was not sent again');
  assert.equal(await page.getAttribute('#verdict', 'data-sse-after'), null);
  assert.equal((await page.inputValue('#measured-csv')).split('\n').length, 4);
  // A good file afterwards loads, and the old notice goes.
  const good = path.join(path.dirname(file), 'good.json');
  writeFileSync(good, JSON.stringify({ ...c, measured: Array.from({ length: 5 }, () => Array(9).fill(2.5)) }));
  await afterResult(page, () => page.setInputFiles('#load-case', good));
  assert.equal(Number(await page.getAttribute('#verdict', 'data-sse-before')), 5 * 9 * 2.5 * 2.5);
  assert.equal(await page.isVisible('#notice'), false);
  assert.equal(await page.isVisible('#measured-error'), false);
  await page.context().close();
});

// A grid in use that no longer fits the grid lines is set aside while they differ, its refusal
// naming the lines asked for; back on its shape it is in use again and the refusal is gone.
test('the grid lines changed under a measured grid and back: the grid in use again, no stale refusal', async () => {
  const c = paper();
  c.measured = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (_, j) => 2 + 0.5 * i - 0.25 * j));
  const page = await openPage(link(c), { viewport: { width: 1366, height: 900 }, open: ['machine-grid-details'] });
  const radial = '[data-field="grid.radial"]';
  const setRadial = (v) => afterResult(page, async () => { await page.fill(radial, v); await page.dispatchEvent(radial, 'change'); });
  const measuring = async () => (await page.textContent('#summary-rms')).includes('µm measured');
  assert.ok(await measuring(), 'the measured face is corrected');
  await setRadial('3');
  assert.equal(await page.textContent('#measured-error'), 'Measured grid: needs 3 rows (the radial grid lines) of 9 values (the axial grid lines); got 5 x 9.');
  assert.match(await notice(page), /set aside, not used: .* set the grid lines back to its shape and it is used again/);
  assert.ok(!(await measuring()));
  // Other lines that do not fit either: the refusal names them, not the 3 rows before.
  await setRadial('4');
  await plotted(page);
  assert.equal(await page.textContent('#measured-error'), 'Measured grid: needs 4 rows (the radial grid lines) of 9 values (the axial grid lines); got 5 x 9.');
  // Back to 5 lines: the grid is in use again, corrected; nothing of the refusal stays.
  await setRadial('5');
  await plotted(page);
  assert.ok(await measuring(), await page.textContent('#summary-rms'));
  assert.equal(await page.isHidden('#measured-error'), true, await page.textContent('#measured-error'));
  assert.equal(await page.isHidden('#notice'), true);
  assert.doesNotMatch(await page.textContent('#inspection-lead'), /simulated/);
  assert.match(await page.textContent('#verdict'), /^(Correctable|Uncertain|Partly uncorrectable)/);
  assert.deepEqual(JSON.parse(decodeURIComponent(await page.evaluate(() => location.hash.slice('#case='.length)))).measured, c.measured);
  await page.locator('#summary').screenshot({ path: path.join(shots, 'grid-lines-back.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('a paste larger than 2 MB is refused before it reaches the box; a small one goes in', async () => {
  const page = await openPage(undefined, { permissions: ['clipboard-read', 'clipboard-write'] });
  const paste = async (text) => {
    await page.evaluate((t) => navigator.clipboard.writeText(t), text);
    await page.focus('#measured-csv');
    await page.keyboard.press('Control+V');
  };
  const small = '1, 2, 3\n4, 5, 6';
  await paste(small);
  assert.equal(await page.inputValue('#measured-csv'), small, 'pasting works here');
  await page.fill('#measured-csv', '');
  const started = Date.now();
  await afterError(page, () => paste('0.5, '.repeat(600_000)));
  assert.ok(Date.now() - started < 10000, `the page answered within ${Date.now() - started} ms`);
  assert.equal(await page.inputValue('#measured-csv'), '');
  assert.match(await page.textContent('#measured-error'), /^The pasted text is 2\.9 MB; .*the limit is 2 MB/);
  assert.equal(await page.isVisible('#measured-error'), true);
  await page.context().close();
});

test('a worker that stops answering is restarted by the watchdog, which says so', async () => {
  const page = await openPage();
  const before = await tab2(page, 'nominal');
  await page.evaluate(() => window.hobsharpTest.stallWorker(1500));
  await afterError(page, () => page.fill('[data-field="setup.tilt"]', '16'));
  assert.match(await page.textContent('#status'), /did not answer within 1\.5 s and was restarted/);
  await noticeStays(page, /^The calculator did not answer within 1\.5 s and was restarted\. .*Change an input to compute again\.$/);
  assert.deepEqual(await tab2(page, 'nominal'), before, 'the last good results stay');
  await afterResult(page, () => page.fill('[data-field="setup.tilt"]', '17'));
  assert.notDeepEqual(await tab2(page, 'nominal'), before, 'the new worker computes');
  assert.equal(await page.isVisible('#notice'), false, "the user's change ends the notice");
  await page.context().close();
});
