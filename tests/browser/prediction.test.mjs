// What a pass will leave (correction.predictedRms, correction.predictedRmsHigh) and the stop verdict
// (correction.stop) on the page: under the verdict "Predicted after the pass: at most Y µm rms at the
// probe points (if the identified error is all of the machine's: X µm rms)", with the units the module gives; in the grinding passes' table and plot the rms with its
// bound and the probe noise's floor; and, for a face measured within the probe noise, a stop
// verdict set apart, no prediction, no next pass offered and the axes run kept as the axes to run.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { afterResult, base, dataCase, openPage, plotted, root, shots, useBrowser } from './support.mjs';

useBrowser();
const hobsharp = await loadHobSharp();
const desk = { viewport: { width: 1366, height: 900 } };
const paper = () => JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
// The paper's 5 x 9 grid measured: a shape the axes make (about 2 µm rms), or a face within the
// probe noise (0.2 µm rms against the default sigma of 0.5 µm).
const shaped = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (__, j) => (i - 2) * (j - 4) * 0.5 + 0.3 * (j - 4)));
const withinNoise = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (__, j) => 0.3 * Math.sin(7 * i + 3 * j + 9 * i * j)));
const link = (c) => `${base}#case=${encodeURIComponent(JSON.stringify(c))}`;
const figure = (v) => String(Number(v.toPrecision(3)));
// The passes' table: below 0.001 µm an rms reads "below 0.001" (issue 22: no solver-size numbers).
const tableFigure = (v) => (v !== 0 && Math.abs(v) < 0.001 ? 'below 0.001' : figure(v));

// The passes' table as rows of cell texts once it is drawn (its plot too).
async function passTable(page) {
  await page.waitForFunction(() => {
    const rows = document.querySelectorAll('#pass-table tbody tr');
    return !document.querySelector('#pass-history').hidden && rows.length > 0 &&
      document.querySelector('#passes-section').dataset.drawn === String(rows.length);
  }, null, { timeout: 30000 });
  return page.$$eval('#pass-table tr', (rows) => rows.map((r) => [...r.children].map((c) => c.textContent.trim())));
}

// The rms panel's traces of the passes' plot: name, y values, and the bars' lengths.
const rmsTraces = (page) => page.evaluate(() => document.querySelector('#plot-passes').data
  .filter((t) => t.xaxis === 'x').map((t) => ({ name: t.name, y: [...t.y], bars: t.error_y ? [...t.error_y.arrayminus] : null, hover: t.customdata ? [...t.customdata] : [] })));

test('a measured face: the prediction and its bound under the verdict, in µm rms, and in the passes\' table and plot', async () => {
  const c = { ...paper(), measured: shaped };
  const expected = hobsharp.evaluate(c).correction;
  assert.equal(expected.stop, false);
  const page = await openPage(link(c), desk);
  await page.waitForSelector('#prediction:not([hidden])');
  const line = await page.textContent('#prediction');
  const model = expected.predictedRms === 0 ? 'within the probe noise' : `${figure(expected.predictedRms)} µm rms`;
  assert.equal(line, `Predicted after the pass: at most ${figure(expected.predictedRmsHigh)} µm rms at the probe points (if the identified error is all of the machine's: ${model}).`);
  assert.match(await page.getAttribute('#prediction', 'title'), /on the probe grid.*At most: at most this rms/);
  const verdict = await page.textContent('#verdict');
  assert.match(verdict, /^Correctable: /);
  assert.equal(await page.$eval('#verdict', (el) => el.classList.contains('stop')), false, 'no stop');
  assert.equal(await page.isDisabled('#next-run'), false, 'the next pass is offered');

  // The passes: the rms measured, and the next pass's rms predicted with its bound.
  const rows = await passTable(page);
  assert.deepEqual(rows[1], ['rms (µm)', 'sum of squares (µm²)', 'largest |deviation| (µm)', 'thickness error (µm)',
    'rms, probe noise taken out (µm)', 'sum of squares (µm²)', 'largest |deviation| (µm)', 'thickness error (µm)']);
  const [current, next] = rows.slice(2);
  assert.equal(current[0], '1 (under way)');
  assert.equal(Number(current[1]), Number(expected.rmsBefore.toPrecision(4)));
  assert.equal(next[0], '2 (next, predicted)');
  assert.equal(next[5], `at most ${tableFigure(Math.max(expected.predictedRmsHigh, 0.001))} (on the identified machine: ${expected.predictedRms === 0 ? 'within the probe noise' : tableFigure(expected.predictedRms)})`);
  // The plot's rms panel: the noise floor at the correction's sigma, the bound as a bar.
  const traces = await rmsTraces(page);
  assert.deepEqual(traces.map((t) => t.name), ['probe noise σ 0.5 µm', 'measured', 'predicted']);
  assert.ok(traces[0].y.every((v) => v === expected.probeNoise));
  const predicted = traces[2];
  // The rms axis stops at a tenth of the probe noise (issue 22): a prediction below it is drawn
  // on the axis's floor, its own value in the hover.
  const floor = Math.max(0.01, expected.probeNoise / 10);
  // The point is the bound, what the pass leaves; a bar down to the identified machine's figure.
  assert.equal(predicted.y.at(-1), Math.max(expected.predictedRmsHigh, floor));
  assert.ok(predicted.hover.at(-1).startsWith(`at most ${Number(expected.predictedRmsHigh.toPrecision(4))} µm`), predicted.hover.at(-1));
  assert.ok(predicted.hover.at(-1).endsWith(`; ${Number(expected.predictedRms.toPrecision(4))} µm on the identified machine`), predicted.hover.at(-1));
  assert.ok(Math.abs(predicted.y.at(-1) - predicted.bars.at(-1) - Math.max(expected.predictedRms, floor)) < 1e-12, 'the bar reaches down to the identified machine\'s figure');
  assert.equal(await page.evaluate(() => document.querySelector('#plot-passes').data.length), 9, 'four panels of measured and predicted, and the floor');
  for (const text of [await page.textContent('#measured-section'), await page.textContent('#passes-section')]) {
    assert.doesNotMatch(text, /NaN|undefined|Infinity/);
  }
  assert.doesNotMatch(await page.textContent('#prediction'), /correction\.|predictedRms/, 'no field paths on the page');
  await page.locator('#verdict').scrollIntoViewIfNeeded();
  await page.locator('#measured-section').screenshot({ path: path.join(shots, 'prediction-measured.png') });
  await page.locator('#passes-section').screenshot({ path: path.join(shots, 'prediction-passes.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('a face measured within the probe noise: Stop, set apart; nothing predicted, no next pass, the axes run kept', async () => {
  const c = { ...paper(), measured: withinNoise };
  const expected = hobsharp.evaluate(c).correction;
  assert.equal(expected.stop, true);
  const page = await openPage(link(c), desk);
  await page.waitForSelector('#verdict.stop');
  assert.equal(await page.textContent('#verdict strong'), 'Stop:');
  const verdict = await page.textContent('#verdict');
  assert.match(verdict, /^Stop: the measured face \([\d.]+ µm rms\) is within the probe noise \(sigma 0\.5 µm\); another pass would only move noise\. Keep the axes run\. Measured: RMS [\d.]+ µm; /);
  assert.equal(await page.isHidden('#prediction'), true, 'no prediction: there is no pass to run');
  assert.equal(await page.isDisabled('#next-run'), true);
  assert.match(await page.textContent('#next-run-why'), /^Stop: the face measured is within the probe noise; another pass would only move noise\. Keep the axes run\.$/);
  assert.equal(await page.getAttribute('#next-run-why', 'class'), 'hint stop');
  assert.equal(await page.textContent('#machine-axes-source'), '(the axes run: keep them; the face measured is within the probe noise)');
  // Set apart: a box of its own, larger than the text around it.
  const look = await page.$eval('#verdict', (el) => {
    const s = getComputedStyle(el);
    return { border: s.borderLeftWidth, size: parseFloat(getComputedStyle(el.querySelector('strong')).fontSize), body: parseFloat(getComputedStyle(document.body).fontSize) };
  });
  assert.equal(look.border, '6px');
  assert.ok(look.size > look.body, `Stop: at ${look.size} px, the page at ${look.body} px`);

  const rows = await passTable(page);
  assert.deepEqual(rows.slice(2).map((r) => [r[0], r.at(-1)]), [['1 (under way)', 'within the probe noise: stop']], 'no next pass predicted');
  const traces = await rmsTraces(page);
  assert.equal(traces[0].name, 'probe noise σ 0.5 µm');
  assert.ok(traces[1].y[0] < expected.probeNoise, 'the rms measured lies under the noise floor');
  for (const text of [await page.textContent('#measured-section'), await page.textContent('#passes-section')]) {
    assert.doesNotMatch(text, /NaN|undefined|Infinity/);
  }
  await page.locator('#verdict').scrollIntoViewIfNeeded();
  await page.locator('#measured-section').screenshot({ path: path.join(shots, 'prediction-stop.png') });
  await page.locator('#passes-section').screenshot({ path: path.join(shots, 'prediction-stop-passes.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

// A face of a shape no axis makes, within twice the probe noise (a checkerboard of 0.95 µm at sigma
// 0.5 µm): nothing is changed, and the verdict, the rms line and the printed report's line say so;
// an independent review (2026-12-07) had "Correctable" and "at most 0.9 µm rms after the pass" here.
test('a face nothing in the axes explains, within twice the noise: No change proposed, the axes run stay', async () => {
  const checker = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (__, j) => ((i + j) % 2 ? -0.95 : 0.95)));
  const c = { ...paper(), measured: checker, correction: { probeNoise: 0.5 } };
  const expected = hobsharp.evaluate(c).correction;
  assert.equal(expected.stop, false);
  assert.ok(expected.change.every((v) => v === 0));
  const page = await openPage(link(c), desk);
  await page.waitForFunction(() => /^No change proposed/.test(document.querySelector('#verdict').textContent), null, { timeout: 20000 });
  const verdict = await page.textContent('#verdict');
  assert.match(verdict, /^No change proposed: no shape the axes make stands out of the probe noise \(sigma 0\.5 µm\) in the face measured \(0\.95 µm rms\); what is left is a shape they do not produce, within twice the probe noise \(rms\)\. The axes run stay as they are/);
  assert.doesNotMatch(verdict, /Correctable/);
  assert.match(await page.textContent('#summary-rms'), /^Face rms: 0\.950 µm measured: no change proposed, the axes run stay\.$/);
  assert.equal(await page.isHidden('#prediction'), true, 'no pass to predict');
  assert.match(verdict, /Measured: RMS 0\.950 µm; /, 'the figures measured, nothing "after"');
  assert.equal(await page.textContent('#first-step'), 'No change is proposed: there is no pass to run (the verdict says why).');
  assert.equal(await page.isDisabled('#next-run'), true);
  assert.match(await page.textContent('#next-run-why'), /^No change proposed: another pass with the axes run grinds the same face/);
  assert.equal(await page.textContent('#machine-axes-source'), '(the axes run: keep them; no change proposed)');
  assert.equal(await page.textContent('#machine-axes-figures'), '', 'no proposal to speak of');
  assert.doesNotMatch(await page.textContent('#measured-section'), /NaN|undefined|Infinity/);
  await page.locator('#summary-rms').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(shots, 'prediction-no-change.png') });
  await page.locator('#verdict').screenshot({ path: path.join(shots, 'prediction-no-change-verdict.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

// A proposal with which some of the errors the face cannot show leave part of the face unground says
// "Uncertain:" with that warning, although its bound lies below the face measured (correction.h,
// uncertain()): seed 7005's scenario 344 of the campaign (tests/data/unground-sample-pass.json, a
// 150 µm rms machine error on a straight gash; the true machine leaves part of the face unground at
// the hob's end). It said "Correctable" with no word of it before.
test('a proposal that may leave part of the face unground says Uncertain with the warning, whatever its bound', async () => {
  const page = await openPage(base, desk);
  await plotted(page);
  await afterResult(page, () => page.setInputFiles('#load-case', dataCase('unground-sample-pass.json')));
  const verdict = await page.textContent('#verdict');
  const m = verdict.match(/^Uncertain: the face does not show enough of the machine's error to say that this pass improves it; the face measured ([\d.]+) µm rms will be left at most ([\d.]+) µm rms/);
  assert.ok(m, verdict);
  assert.ok(Number(m[2]) < Number(m[1]), `the bound ${m[2]} µm lies below the face measured, ${m[1]} µm`);
  assert.match(verdict, /with some of the errors it cannot show the wheel would not reach part of the face \(part of it would stay unground\)/);
  await page.locator('#verdict').screenshot({ path: path.join(shots, 'unground-sample-verdict.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
