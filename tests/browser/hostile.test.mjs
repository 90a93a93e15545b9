// Files that are huge or hostile (issue 22, item 4), as the page meets them: each is refused in
// under 2 s with a message naming it, the page never freezes (no long task on its thread), and
// the next edit computes. And a loaded case is evaluated once; a computation can be cancelled.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { unzipSync } from 'fflate';
import { afterError, afterResult, base, count, ON_DEMAND, openPage, plotted, root, shots, useBrowser } from './support.mjs';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { writeX3p } from '../../wasm/lib/x3p.js';
import { longGridCsv, runOnX3p, wheelCsv } from '../js/hostile-files.mjs';

useBrowser();

const paper = JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
const file = (name, content) => ({ name, mimeType: 'application/octet-stream', buffer: Buffer.from(content) });

// The page's own time from a file chosen (its input's change event) to now, ms: what handing the
// file to the page takes (Playwright sends it over a socket) is not the page's.
async function startClock(page, selector) {
  await page.evaluate((s) => document.querySelector(s).addEventListener('change', () => { window.chosenAt = performance.now(); }, { capture: true }), selector);
}
const sinceChosen = (page) => page.evaluate(() => performance.now() - window.chosenAt);

// Cancel, clicked in the page the moment it shows (a computation of a second shows it for a few
// hundred ms, which Playwright's polling can miss), during `action`: the page's own time from the
// click to the page saying the computation was cancelled (the status or the notice), ms.
async function cancelWhenShown(page, action) {
  await page.evaluate(() => {
    window.cancelClickedAt = undefined; window.cancelSaidAt = undefined;
    const button = document.querySelector('#cancel-computation');
    const said = () => /cancelled/i.test(document.querySelector('#status').textContent + document.querySelector('#notice-text').textContent);
    const observer = new MutationObserver(() => {
      if (window.cancelClickedAt === undefined && !button.hidden) {
        window.cancelClickedAt = performance.now();
        button.click();
      }
      if (window.cancelClickedAt !== undefined && said()) { window.cancelSaidAt = performance.now(); observer.disconnect(); }
    });
    observer.observe(document.body, { subtree: true, childList: true, characterData: true, attributes: true, attributeFilter: ['hidden'] });
  });
  await action();
  await page.waitForFunction(() => window.cancelSaidAt !== undefined, null, { timeout: 10000 });
  return page.evaluate(() => window.cancelSaidAt - window.cancelClickedAt);
}

// Records the page's long tasks (the main thread busy for more than 50 ms at a stretch), once
// the page has drawn its plots.
async function watchLongTasks(page) {
  await plotted(page);
  await page.evaluate(() => {
    window.longTasks = [];
    new PerformanceObserver((list) => { for (const e of list.getEntries()) window.longTasks.push(e.duration); }).observe({ type: 'longtask', buffered: false });
  });
}
const longestTask = (page) => page.evaluate(() => Math.max(0, ...window.longTasks));

// The next edit computes: the tilt changed gives a result.
async function nextEditComputes(page, tilt = '15.5') {
  await afterResult(page, () => page.fill('[data-field="setup.tilt"]', tilt));
  assert.equal(await page.getAttribute('#status', 'class'), 'ok');
}

test('an X3P whose points run on past their declared size is refused off the page\'s thread, quickly, naming it; the next edit computes', async () => {
  const hobsharp = await loadHobSharp();
  const t = hobsharp.evaluate(paper).topography;
  const entries = unzipSync(writeX3p({ r: t.r, x: t.x, values: t.normal }));
  const bomb = runOnX3p(entries, 'bindata/data.bin', 512 * 1024 * 1024);  // 0.5 MB that inflate to 512 MB
  const page = await openPage(base, { viewport: { width: 1366, height: 900 } });
  await watchLongTasks(page);
  await startClock(page, '#measured-x3p-file');
  await afterError(page, () => page.setInputFiles('#measured-x3p-file', file('bomb.x3p', bomb)));
  const ms = await sinceChosen(page);
  assert.match(await page.textContent('#measured-error'), /^bomb\.x3p is refused: bindata\/data\.bin in the X3P container inflates to more than the 360 bytes its entry declares: a damaged or hostile file; refused\./);
  assert.ok(ms < 2000, `refused after ${ms} ms`);
  assert.ok(await longestTask(page) < 1000, `the page's thread was busy ${await longestTask(page)} ms at a stretch`);
  assert.equal(await page.inputValue('#measured-csv'), '', 'nothing went into the box');
  await nextEditComputes(page);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('a wheel file of 150,000 points is refused naming the count; the wheel in use stays and the next edit computes', async () => {
  const page = await openPage(base, { viewport: { width: 1366, height: 900 } });
  const source = await page.textContent('#wheel-source');
  await startClock(page, '#wheel-file');
  await page.setInputFiles('#wheel-file', file('dresser.csv', wheelCsv(150000)));
  await page.waitForFunction(() => !document.querySelector('#wheel-error').hidden);
  const ms = await sinceChosen(page);
  assert.equal(await page.textContent('#wheel-error'),
    "dresser.csv: The wheel file has 150,000 points; at most 2,000 are read (a dressed wheel's profile is a few hundred). The wheel in use is unchanged.");
  assert.ok(ms < 2000, `refused after ${ms} ms`);
  assert.equal(await page.textContent('#wheel-source'), source);
  await nextEditComputes(page);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('a grid CSV of 990,000 rows is refused at once naming the line and the limit; the next edit computes', async () => {
  const page = await openPage(base, { viewport: { width: 1366, height: 900 } });
  await watchLongTasks(page);
  await startClock(page, '#measured-file');
  await afterError(page, () => page.setInputFiles('#measured-file', file('long.csv', longGridCsv(990000))));
  const ms = await sinceChosen(page);
  assert.equal(await page.inputValue('#measured-csv'), '', 'the text did not go into the box');
  // Refused as a file, as every refused measurement file is (issue 22, item 3): its name, why, and what stays in use.
  assert.match(await page.textContent('#measured-error'), /^long\.csv is refused: Line 50,001: the text holds more than 50,000 values; a measured grid has at most 201 × 201, 40,804 with its positions\. Is this the right file\? In use: no measurement/);
  assert.ok(ms < 2000, `refused after ${ms} ms`);
  assert.ok(await longestTask(page) < 1000, `the page's thread was busy ${await longestTask(page)} ms at a stretch`);
  // Pasted into the box: refused the same, nothing inserted.
  await afterError(page, () => page.evaluate((text) => {
    const data = new DataTransfer();
    data.setData('text/plain', text);
    document.querySelector('#measured-csv').dispatchEvent(new ClipboardEvent('paste', { clipboardData: data, bubbles: true, cancelable: true }));
  }, longGridCsv(990000)));
  assert.match(await page.textContent('#measured-error'), /^The pasted text: Line 50,001: the text holds more than 50,000 values/);
  assert.equal(await page.inputValue('#measured-csv'), '');
  await nextEditComputes(page);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('101 per-gash files are refused by their count; a set the calculator refuses leaves the set in use; the next edit computes', async () => {
  const page = await openPage(base, { viewport: { width: 1366, height: 900 }, open: ['inspection-details'] });
  await page.click('#tolerance-editor summary');
  const grid = (v) => Array.from({ length: 5 }, () => Array(9).fill(v).join(', ')).join('\n');
  const csv = (name, text) => ({ name, mimeType: 'text/csv', buffer: Buffer.from(text) });
  // A set in use: three gashes.
  await afterResult(page, () => page.setInputFiles('#gash-files', [1, 2, 3].map((k) => csv(`gash-${k}.csv`, grid(k)))));
  const inUse = await page.textContent('#gash-files-read');
  assert.equal(inUse, 'Gashes 1 to 3: gash-1.csv, gash-2.csv, gash-3.csv.');
  const rows = () => page.$$eval('#per-gash tbody tr', (trs) => trs.length);
  assert.equal(await rows(), 3);
  // 101 files: refused before any is read.
  await startClock(page, '#gash-files');
  await page.setInputFiles('#gash-files', Array.from({ length: 101 }, (_, k) => csv(`gash-${k + 1}.csv`, grid(1))));
  await page.waitForFunction(() => document.querySelector('#tolerance-error').textContent !== '');
  assert.ok(await sinceChosen(page) < 2000, `refused after ${await sinceChosen(page)} ms`);
  assert.equal(await page.textContent('#tolerance-error'), '101 files chosen, one per gash; a hob has at most 100 gashes. The gashes in use are unchanged.');
  assert.equal(await page.textContent('#gash-files-read'), inUse);
  await nextEditComputes(page, '15.5');
  assert.equal(await rows(), 3, 'the set in use still computes');
  // A set the page reads but the calculator refuses (a value beyond ±10 mm): the set in use stays.
  await afterResult(page, () => page.setInputFiles('#gash-files', [csv('a.csv', grid(1)), csv('b.csv', grid(20000))]));
  assert.ok(await sinceChosen(page) < 2000, `refused and the set in use computed again after ${await sinceChosen(page)} ms`);
  assert.match(await page.textContent('#tolerance-error'), /10000 µm.* The gashes in use are unchanged\.$/);
  assert.equal(await page.textContent('#gash-files-read'), inUse);
  assert.equal(await rows(), 3);
  await nextEditComputes(page, '15.25');
  assert.equal(await rows(), 3);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('a case with per-gash topographies: the link holds what fits, says what it left out, and reloads to the same case without it', async () => {
  // 32 gashes on a 57 x 57 grid, full digits: 2.2 MB as a whole link.
  const c = structuredClone(paper);
  c.setup.tilt = 15.25;  // not the paper example
  c.grid = { ...c.grid, radial: 57, axial: 57 };
  c.inspection = {
    uncertainty: 1.5,
    gashTopographies: Array.from({ length: 32 }, (_, g) => Array.from({ length: 57 }, (_, i) => Array.from({ length: 57 }, (_, j) => Math.sin(g + i * 0.1 + j * 0.37) * 3.3))),
  };
  assert.ok(encodeURIComponent(JSON.stringify(c)).length > 2e6);
  const page = await openPage(base, { viewport: { width: 1366, height: 900 }, permissions: ['clipboard-read', 'clipboard-write'], open: ['files-menu'] });
  await afterResult(page, () => page.setInputFiles('#load-case', file('gashes.json', JSON.stringify(c))));
  const hash = await page.evaluate(() => location.hash);
  assert.ok(hash.length <= 64 * 1024 + 1 && hash.startsWith('#case='), `the address holds ${hash.length} characters`);
  await page.click('#copy-link');
  await page.waitForFunction(() => /clipboard/.test(document.querySelector('#status').textContent));
  assert.equal(await page.textContent('#status'),
    'The link to this job is on the clipboard. The link leaves out the per-gash topographies: save the case (a file) to keep it.');
  const link = await page.evaluate(() => navigator.clipboard.readText());
  assert.ok(link.endsWith(hash), 'the link handed out is the address');
  // Reloaded: the same case, without the per-gash topographies.
  const again = await openPage(link, { viewport: { width: 1366, height: 900 } });
  const expected = structuredClone(c);
  delete expected.inspection.gashTopographies;
  const back = JSON.parse(decodeURIComponent((await again.evaluate(() => location.hash)).slice('#case='.length)));
  assert.deepEqual(back, JSON.parse(decodeURIComponent(hash.slice('#case='.length))));
  for (const key of ['hob', 'setup', 'grid', 'inspection']) assert.deepEqual(back[key], expected[key], key);
  assert.equal(await again.inputValue('[data-field="setup.tilt"]'), '15.25');
  assert.equal(await again.isVisible('#notice'), false, 'no refusal on opening');
  assert.deepEqual(page.problems, []);
  assert.deepEqual(again.problems, []);
  await page.context().close();
  await again.context().close();
});

test('a loaded case is evaluated once; a slow computation shows Cancel, which returns control at once, and the next edit computes', async () => {
  const hobsharp = await loadHobSharp();
  const page = await openPage(base, { viewport: { width: 1366, height: 900 }, open: ON_DEMAND });
  // A case file: one evaluation from choosing it to its numbers.
  const c = structuredClone(paper);
  c.setup.tilt = 15.25;
  const before = await count(page, 'evaluations');
  await afterResult(page, () => page.setInputFiles('#load-case', file('job.json', JSON.stringify(c))));
  assert.equal(await count(page, 'evaluations') - before, 1, 'one evaluation per load');
  // A slow case: a measured 201 x 201 grid at degree 6 with the wheel corrected too (1 to 3 s in
  // Node, with the machine's load).
  const slow = structuredClone(paper);
  slow.degree = 6;
  slow.correction = { ...slow.correction, wheel: true };
  slow.grid = { ...slow.grid, radial: 201, axial: 201 };
  const axes = hobsharp.evaluate(slow).axes;
  axes.Z[0] += 0.01;
  slow.measured = hobsharp.evaluate({ ...slow, axes }).topography.normal;
  // Cancelled while the loaded case is checked: nothing changes.
  const firstCancelMs = await cancelWhenShown(page, () => page.setInputFiles('#load-case', file('slow.json', JSON.stringify(slow))));
  assert.ok(firstCancelMs < 1000, `cancelled after ${firstCancelMs} ms`);
  assert.equal(await page.textContent('#notice-text'), 'slow.json: The computation was cancelled. Nothing was changed.');
  assert.ok(await page.isHidden('#cancel-computation'));
  assert.equal(await page.inputValue('[data-field="setup.tilt"]'), '15.25', 'the case before stays');
  // Loaded in full: one evaluation, its numbers after one computation's time.
  let evaluations = await count(page, 'evaluations');
  let started = Date.now();
  await afterResult(page, () => page.setInputFiles('#load-case', file('slow.json', JSON.stringify(slow))));
  const loadMs = Date.now() - started;
  assert.equal(await count(page, 'evaluations') - evaluations, 1, 'one evaluation per load');
  assert.match(await page.textContent('#status'), /^Updated/);
  // Cancelled while an edit computes: the last result stays, and the status says so.
  const results = await count(page, 'results');
  evaluations = await count(page, 'evaluations');
  const cancelMs = await cancelWhenShown(page, () => page.fill('[data-field="setup.tilt"]', '15.75'));
  assert.equal(await count(page, 'cancelled'), 1);
  assert.ok(cancelMs < 1000, `cancelled after ${cancelMs} ms`);
  assert.equal(await count(page, 'results'), results, 'no result for the cancelled inputs');
  assert.equal(await page.textContent('#status'), 'Cancelled: nothing was computed for the inputs now in the form. The results below are from the last good input.');
  assert.ok(await page.isHidden('#cancel-computation'));
  assert.ok(await page.isVisible('#tab2'));
  await page.screenshot({ path: path.join(shots, 'cancelled.png') });
  // The next edit computes, in a fresh worker.
  started = Date.now();
  await nextEditComputes(page, '15.5');
  const nextMs = Date.now() - started;
  assert.equal(await count(page, 'evaluations') - evaluations, 2, 'the cancelled edit and the next');
  console.log(`slow case loaded in ${loadMs} ms; cancelled in ${cancelMs} ms; the next edit computed in ${nextMs} ms`);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
