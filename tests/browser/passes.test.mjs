// Grinding passes (issue 10, item 6): measure → correct → use as next run → measure again, with
// the history's table and plot; the history survives a saved case and the link.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { afterResult, base, colours, ON_DEMAND, openPage, root, shots, useBrowser } from './support.mjs';

useBrowser();
const desk = { viewport: { width: 1366, height: 900 }, open: ON_DEMAND };
// The machine's error: 10 µm along the wheel axis, and a wheel swivel of 1 mrad/rad² of motion.
const machineError = { 'Z 0': '-0.01', 'B 2': '0.001' };

// Measures the face the machine grinds now: ground with its error (the what-if), and pasted as
// CSV, as a measured grid is (the correction then assumes the probe's noise, the same every pass).
async function measure(page) {
  await afterResult(page, () => page.click('#generate-error'));
  const csv = await page.inputValue('#measured-csv');
  await afterResult(page, () => page.click('#clear-measured'));
  await page.fill('#measured-csv', csv);
  await afterResult(page, () => page.click('#use-measured'));
  return csv;
}

// The history table as rows of cell texts, once every kept pass's figures are in and plotted.
async function table(page) {
  await page.waitForFunction(() => {
    const s = document.querySelector('#passes-section');
    const rows = document.querySelectorAll('#pass-table tbody tr');
    return !document.querySelector('#pass-history').hidden && rows.length > 0 && s.dataset.drawn === String(rows.length) &&
      ![...document.querySelectorAll('#pass-table .pass-note')].some((n) => /computing/.test(n.textContent));
  }, null, { timeout: 30000 });
  return page.$$eval('#pass-table tbody tr', (rows) => rows.map((r) => [...r.children].map((c) => c.textContent.trim())));
}
// Columns: pass, measured rms, sum of squares, largest |deviation|, thickness; the same predicted; note.
// A sum of squares as the table shows it; "below 1e-6" (issue 22: no solver-size numbers) is
// taken at its bound, so that a comparison with it still holds.
const sseOf = (row, set) => Number(row[set === 'measured' ? 2 : 6].replace(/^below /, ''));

async function plotDrawn(page) {
  const traces = await page.evaluate(() => document.querySelector('#plot-passes').data.map((t) => [t.name, t.y.length]));
  assert.equal(traces.length, 9, 'the probe noise, and measured and predicted for the rms, the sum of squares, the largest deviation and the thickness');
  assert.match(traces[0][0], /^probe noise σ/);
  assert.ok(traces.every(([, n]) => n > 0), JSON.stringify(traces));
  assert.ok(await colours(page, '#plot-passes') > 20, 'the plot is not blank');
}

// The machine error identified (issue 10, item 5): status and iterations, per axis the error,
// its uncertainty and the change with units, the precision demand, the rounded axes.
async function identification(page) {
  assert.equal(await page.isVisible('#identification'), true);
  assert.match(await page.textContent('#solver-status'), /^Solver \(nonlinear identification\): converged, \d+ iterations?\./);
  const errors = await page.$$eval('#identified-error tbody tr', (rows) => rows.map((r) => [...r.children].map((c) => c.textContent.trim())));
  assert.deepEqual(errors.map((r) => r[0]), ['X', 'Y', 'Z', 'A', 'B']);
  for (const r of errors) {
    const unit = ['A', 'B'].includes(r[0]) ? 'µrad' : 'µm';
    // Read on its own: its value and uncertainty; otherwise why not, in words (issue 20, item 5).
    if (r.length === 5) {
      assert.match(r[1], new RegExp(`^−?[\\d.e+-]+ ${unit}$`), r.join(' | '));
      assert.match(r[2], new RegExp(`^± [\\d.e+-]+ ${unit}$`), r.join(' | '));
    } else {
      assert.match(r[1], /^(not told apart from other axes \(below\)|not shown by the face|locked)$/, r.join(' | '));
    }
    assert.match(r[r.length - 1], new RegExp(`^−?[\\d.e+-]+ ${unit}$`), r.join(' | '));
  }
  const demand = await page.$$eval('#precision-demand tr', (rows) => rows.map((r) => [...r.children].map((c) => c.textContent.trim())));
  assert.deepEqual(demand[0], ['axis', 'face per unit of axis error, largest over the grid', 'axis change per µm of probe noise were every direction the face shows taken']);
  assert.match(demand[1].join(' | '), /^X \| [\d.e+-]+ µm per µm \| [\d.e+-]+ µm per µm$/);
  assert.match(demand[5].join(' | '), /^B \| [\d.e+-]+ µm per µrad \| [\d.e+-]+ µrad per µm$/);
  assert.equal(await page.locator('[data-rounded-axis]').count(), 5);
  assert.match(await page.textContent('#rounded-sse'), /^On the identified machine, re-simulated, the rounded axes leave sum of squares [\d.e+-]+ µm², largest \|deviation\| [\d.]+ µm, thickness error [+−-]?[\d.]+ µm; the exact proposal sum of squares [\d.e+-]+ µm².*The exact axes leave at most the verdict's bound\.$/);
  assert.doesNotMatch(await page.textContent('#identification'), /NaN|undefined|Infinity|—/);
  await page.locator('#measured-section').screenshot({ path: path.join(shots, 'passes-identification.png') });
}

async function save(page) {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-case')]);
  return { file: await download.path(), saved: JSON.parse(readFileSync(await download.path(), 'utf8')) };
}

test('measure, correct, use as next run, measure again; the history is saved and linked', async () => {
  const page = await openPage(base, desk);
  assert.equal(await page.isDisabled('#next-run'), true, 'nothing measured yet');
  // Measure: the face the machine grinds with its error, pasted as CSV.
  for (const [k, v] of Object.entries(machineError)) {
    await page.fill(`[data-offset="${k}"]`, v);
    await page.dispatchEvent(`[data-offset="${k}"]`, 'change');
  }
  const csv = await measure(page);
  // Correct: the pass under way, measured, and the next one predicted.
  let rows = await table(page);
  assert.deepEqual(rows.map((r) => r[0]), ['1 (under way)', '2 (next, predicted)']);
  const first = sseOf(rows[0], 'measured');
  assert.ok(first > 100, `pass 1 measured ${first} µm²`);
  assert.ok(sseOf(rows[1], 'predicted') < first / 100, 'the correction predicts a far better face');
  assert.equal(await page.isDisabled('#next-run'), false);
  await identification(page);

  // Use as next run: pass 1 kept, the proposal runs, nothing measured yet.
  await afterResult(page, () => page.click('#next-run'));
  assert.equal(await page.isVisible('#run-axes'), true);
  assert.equal(await page.inputValue('#measured-csv'), '');
  // The next step is the pass's, not the first open's: grind with these axes, load the new face.
  assert.equal(await page.textContent('#first-step'), 'Grind with the axes to run below (the run axes in use), measure the face and load '
    + 'the new measurement in step 2; the verdict, the class and the next axes to run show here.');
  await page.locator('#summary').screenshot({ path: path.join(shots, 'passes-next-run-summary.png') });
  rows = await table(page);
  assert.deepEqual(rows.map((r) => [r[0], r[9]]), [['1', ''], ['2 (under way)', 'not measured yet']]);
  assert.equal(sseOf(rows[0], 'measured'), first, 'the kept pass, computed again from its axes and grid');
  const predicted = sseOf(rows[1], 'predicted');
  // Undo takes the step back (the grid in use again, no history), Redo makes it again.
  await afterResult(page, () => page.click('#undo'));
  const numbers = (text) => text.trim().split(/[\s,]+/).map(Number);
  assert.deepEqual(numbers(await page.inputValue('#measured-csv')), numbers(csv));
  assert.deepEqual((await table(page)).map((r) => r[0]), ['1 (under way)', '2 (next, predicted)']);
  await afterResult(page, () => page.click('#redo'));
  assert.deepEqual(await table(page), rows);

  // Measure again: the same machine, now with the corrected axes. What is left is within the
  // probe's noise (0.5 µm): stop; no third pass is predicted or offered.
  await measure(page);
  rows = await table(page);
  assert.deepEqual(rows.map((r) => [r[0], r[9]]), [['1', ''], ['2 (under way)', 'within the probe noise: stop']]);
  const second = sseOf(rows[1], 'measured');
  assert.ok(second < first / 100, `pass 2 measured ${second} µm², pass 1 ${first} µm²`);
  assert.equal(sseOf(rows[1], 'predicted'), predicted);
  assert.doesNotMatch(JSON.stringify(rows), /NaN|undefined|Infinity/);
  assert.match(await page.textContent('#verdict'), /^Stop: /);
  assert.equal(await page.isDisabled('#next-run'), true);
  assert.match(await page.textContent('#next-run-why'), /^Stop: .* Keep the axes run\.$/);
  await plotDrawn(page);
  await page.locator('#passes-section').screenshot({ path: path.join(shots, 'passes-two.png') });
  // A finer probe (0.01 µm) sees what is left: no longer within its noise, a third pass is predicted.
  await afterResult(page, async () => { await page.fill('#probe-noise', '0.01'); await page.dispatchEvent('#probe-noise', 'change'); });
  rows = await table(page);
  assert.deepEqual(rows.map((r) => r[0]), ['1', '2 (under way)', '3 (next, predicted)']);
  assert.equal(await page.isDisabled('#next-run'), false);
  // The kept pass's face is in the identification too (docs/method.md §Correction from the pass history).
  assert.match(await page.textContent('#verdict'), /The machine's error was identified from this face and the 1 earlier pass's face together: one error explains them all to the probe noise\./);
  await page.locator('#verdict').screenshot({ path: path.join(shots, 'passes-history-verdict.png') });

  // Kept again: two passes in the history; the case and the link hold them.
  await afterResult(page, () => page.click('#next-run'));
  const kept = await table(page);
  assert.deepEqual(kept.map((r) => r[0]), ['1', '2', '3 (under way)']);
  const { file, saved } = await save(page);
  assert.equal(saved.passes.length, 2);
  assert.equal(saved.passes[0].measured.length, 5);
  assert.notDeepEqual(saved.passes[1].axes, saved.passes[0].axes, 'pass 2 ran the corrected axes');
  assert.deepEqual(saved.passes[1].axes, JSON.parse(decodeURIComponent(page.url().split('#case=')[1])).passes[1].axes);

  const loaded = await openPage(base, desk);
  await afterResult(loaded, () => loaded.setInputFiles('#load-case', file));
  assert.deepEqual(await table(loaded), kept, 'the history from the saved case');
  await loaded.locator('#passes-section').screenshot({ path: path.join(shots, 'passes-loaded.png') });
  const linked = await openPage(page.url(), desk);
  assert.deepEqual(await table(linked), kept, 'the history from the link');
  await plotDrawn(linked);
  for (const p of [page, loaded, linked]) assert.deepEqual(p.problems, []);
  for (const p of [page, loaded, linked]) await p.context().close();
});

test('a saved history that no longer fits the grid is left out, the rest loads, and the page says why', async () => {
  const paper = JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
  const axes = { X: [22.4003, 139.5089, 0, 0, 0], Y: [39.3076, 0, 0, 0, 0], Z: [-116.446, 0, 0, 0, 0], A: [0, 1, 0, 0, 0], B: [0.220365, 0, 0, 0, 0] };
  const c = { ...paper, axes, passes: [{ axes, measured: Array.from({ length: 4 }, () => Array(9).fill(1)) }] };
  const page = await openPage(`${base}#case=${encodeURIComponent(JSON.stringify(c))}`, desk);
  assert.match(await page.textContent('#notice-text'), /history of grinding passes is left out: Pass 1, measured grid: needs 5 rows/);
  assert.equal(await page.isVisible('#run-axes'), true, 'the rest of the case is loaded');
  assert.equal(await page.isHidden('#pass-history'), true);
  await page.context().close();
});

// A pass measured at the measuring machine's own points (a points CSV) is kept with its points:
// the history computes it again from them, and the saved case holds them in the pass.
test('points measured, used as next run: the pass keeps its points', async () => {
  const page = await openPage(base, desk);
  await page.waitForFunction(() => window.hobsharpTimings.results > 0);
  const csv = readFileSync(path.join(root, 'tests', 'data', 'points-2000.csv'));
  await afterResult(page, () => page.setInputFiles('#measured-file', { name: 'probe-run.csv', mimeType: 'text/csv', buffer: csv }));
  assert.match(await page.textContent('#before-title'), /^Measured at 2000 points/);
  let rows = await table(page);
  assert.deepEqual(rows.map((r) => r[0]), ['1 (under way)', '2 (next, predicted)']);
  const first = sseOf(rows[0], 'measured');
  const sseBefore = Number(await page.getAttribute('#verdict', 'data-sse-before'));
  assert.ok(sseBefore > 100 && Math.abs(first - sseBefore) < 1e-5 * sseBefore, `pass 1 measured ${first} µm², the correction's ${sseBefore} µm²`);
  assert.equal(await page.isDisabled('#next-run'), false, 'points can be used as a pass');

  await afterResult(page, () => page.click('#next-run'));
  rows = await table(page);
  assert.deepEqual(rows.map((r) => [r[0], r[9]]), [['1', ''], ['2 (under way)', 'not measured yet']]);
  assert.equal(sseOf(rows[0], 'measured'), first, 'the kept pass, computed again from its axes and points');
  assert.doesNotMatch(await page.textContent('#before-title'), /Measured at/, 'the pass under way is not measured yet');
  const { saved } = await save(page);
  assert.equal(saved.passes.length, 1);
  assert.equal(saved.passes[0].measuredPoints.length, 2000);
  assert.equal('measured' in saved.passes[0], false);
  assert.equal('measuredPoints' in saved, false, 'the points went with their pass');
  await page.locator('#passes-section').screenshot({ path: path.join(shots, 'passes-points.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

// A measuring machine that signs deviations the other way round (docs/conventions.md §Sign): the
// first pass's correction adds to the error, and the second pass, measured the same way, moves the
// face against the change of the axes. The verdict says so first (core/correction/history_sign.h).
test('faces measured with the other sign: the second pass says to check the sign', async () => {
  const page = await openPage(base, desk);
  for (const [k, v] of Object.entries(machineError)) {
    await page.fill(`[data-offset="${k}"]`, v);
    await page.dispatchEvent(`[data-offset="${k}"]`, 'change');
  }
  // The face the machine grinds, as such a measuring machine reports it: every value negated.
  const measureNegated = async () => {
    await afterResult(page, () => page.click('#generate-error'));
    const csv = await page.inputValue('#measured-csv');
    const negated = csv.replace(/-?\d+(\.\d+)?(e[-+]?\d+)?/gi, (v) => (v.startsWith('-') ? v.slice(1) : `-${v}`));
    assert.notEqual(negated, csv);
    await afterResult(page, () => page.click('#clear-measured'));
    await page.fill('#measured-csv', negated);
    await afterResult(page, () => page.click('#use-measured'));
  };
  await measureNegated();
  assert.doesNotMatch(await page.textContent('#verdict'), /Check the sign/, 'a first pass has nothing to check against');
  await afterResult(page, () => page.click('#next-run'));
  await measureNegated();
  const verdict = await page.textContent('#verdict');
  assert.match(verdict, /^Check the sign: from the last pass measured on the grid to this one the axes changed by what moves the face by [\d.]+ µm rms as this calculator signs deviations \(plus = excess material\), and the faces measured moved the opposite way \(−?-?[\d.]+ times that\)\./);
  assert.doesNotMatch(verdict, /NaN|undefined|Infinity/);
  // No figure after the pass stands, and the first thing to do is the sign.
  assert.match(await page.textContent('#first-step'), /^Do not run the axes below yet: the faces measured moved against the change of the axes/);
  assert.match(await page.textContent('#summary-rms'), /; nothing is predicted after the pass until the measuring machine's sign is checked\.$/);
  const rows = await table(page);
  assert.deepEqual(rows.map((r) => r[0]), ['1', '2 (under way)', '3 (next, predicted)']);
  assert.match(rows[2][9], /^nothing predicted: the faces measured moved against the change of the axes/);
  await page.locator('#verdict').screenshot({ path: path.join(shots, 'passes-sign-reversed.png') });
  await page.locator('#summary').screenshot({ path: path.join(shots, 'passes-sign-reversed-summary.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
