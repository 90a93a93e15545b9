// The correction's options at the measured grid (issue 10): the method, the probe noise and the
// machine's resolution are inputs; the page declares a simulated grid noise-free by itself; a bad
// option is shown at its input and the grid stays in use; a kept pass keeps its own options.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { afterError, afterResult, base, ON_DEMAND, openPage, shots, useBrowser } from './support.mjs';

useBrowser();
const desk = { viewport: { width: 1366, height: 900 }, open: ON_DEMAND };

async function setOption(page, selector, value) {
  if (selector === '#correction-method') return afterResult(page, () => page.selectOption(selector, value));
  return afterResult(page, async () => { await page.fill(selector, value); await page.dispatchEvent(selector, 'change'); });
}
const uncertainty = async (page, axis) => Number((await page.textContent(`#identified-error tr[data-axis="${axis}"] [data-col="uncertainty"]`)).replace(/^± /, '').split(' ')[0]);
const predictedRow = (page, pass) => page.$eval(`#pass-table tr[data-pass="${pass}"]`, (r) => [...r.children].map((c) => c.textContent.trim()).slice(5, 9).join(' | '));

test('the options are inputs with the defaults shown; a simulated grid is declared noise-free by the page', async () => {
  const page = await openPage(base, desk);
  assert.equal(await page.inputValue('#correction-method'), 'nonlinear');
  assert.equal(await page.getAttribute('#probe-noise', 'placeholder'), '0.5');
  assert.equal(await page.getAttribute('[data-resolution="X"]', 'placeholder'), '0.1');
  assert.equal(await page.getAttribute('[data-resolution="B"]', 'placeholder'), '0.0001');
  assert.equal(await page.textContent('[data-resolution="B"] + .unit'), 'deg');
  // A what-if grid: simulated, so noise-free (1e-4 µm), said beside the input.
  await page.fill('[data-offset="Z 0"]', '-0.01');
  await page.dispatchEvent('[data-offset="Z 0"]', 'change');
  await afterResult(page, () => page.click('#generate-error'));
  assert.equal(await page.inputValue('#probe-noise'), '0.0001');
  assert.match(await page.textContent('#probe-noise-note'), /simulated what-if: declared noise-free/);
  // The same grid pasted is measured: the default noise again.
  const csv = await page.inputValue('#measured-csv');
  await afterResult(page, () => page.click('#clear-measured'));
  await page.fill('#measured-csv', csv);
  await afterResult(page, () => page.click('#use-measured'));
  assert.equal(await page.inputValue('#probe-noise'), '');
  assert.match(await page.textContent('#probe-noise-note'), /standard deviation/);

  // The axis change per µm of noise (the precision demand's last column) is one quantity over every
  // direction the face shows, whatever sigma decides (issue 20, item 5): about the same at the
  // default 0.5 µm and at 2 µm as typed (within 10 %: it is taken at the identified error, which
  // sigma moves, and the directions the face nearly does not show make it large and touchy); a value
  // read on its own has an uncertainty 4 times as large at 2 µm.
  const perNoise = (axis) => page.textContent(`#precision-demand tr[data-axis="${axis}"] td:last-child`).then((t) => Number(t.split(' ')[0]));
  const demandBefore = { Y: await perNoise('Y'), B: await perNoise('B') };
  const alone = await page.$$eval('#identified-error tr[data-reading="alone"]', (rows) => rows.map((r) => r.dataset.axis));
  const aloneBefore = await Promise.all(alone.map((a) => uncertainty(page, a)));
  await setOption(page, '#probe-noise', '2');
  for (const axis of ['Y', 'B']) {
    const after = await perNoise(axis);
    assert.ok(Math.abs(after - demandBefore[axis]) <= 0.1 * demandBefore[axis], `${axis}: ${after} per µm against ${demandBefore[axis]} at 0.5 µm`);
  }
  for (const [i, axis] of alone.entries()) {
    if (await page.getAttribute(`#identified-error tr[data-axis="${axis}"]`, 'data-reading') !== 'alone') continue;
    const u = await uncertainty(page, axis);
    assert.ok(Math.abs(u - 4 * aloneBefore[i]) <= 2e-2 * u, `${axis}: ± ${u} against 4 × ${aloneBefore[i]}`);
  }
  // A coarser A resolution raises the floor it sets (the rounded axes are the program's digits).
  const floor = async () => Number((await page.textContent('#machine-axes-figures')).match(/([\d.e-]+) µm rms\.$/)[1]);
  const fine = await floor();
  await setOption(page, '[data-resolution="A"]', '0.01');
  assert.ok(await floor() > 10 * fine, 'the floor grows with the A step');
  // The paper's linear step.
  await setOption(page, '#correction-method', 'linear');
  assert.match(await page.textContent('#solver-status'), /^Solver \(one linear step \(Eq\. 17\)\)/);
  await page.locator('#correction-options').screenshot({ path: path.join(shots, 'correction-options.png') });

  // A bad option: shown at its input; the grid stays in use, and the fix clears it.
  await afterError(page, async () => { await page.fill('#probe-noise', '-1'); await page.dispatchEvent('#probe-noise', 'change'); });
  assert.match(await page.textContent('#correction-options-error'), /^Probe noise σ: the probe's standard deviation must be positive; got -1 µm\.$/);
  assert.equal(await page.getAttribute('#probe-noise', 'aria-invalid'), 'true');
  assert.equal(await page.isHidden('#measured-error'), true, 'not the grid\'s error');
  assert.equal(await page.isHidden('#notice'), true, 'nothing set aside');
  await page.locator('#measured-section').screenshot({ path: path.join(shots, 'correction-options-refused.png') });
  await setOption(page, '#probe-noise', '1');
  assert.equal(await page.isHidden('#correction-options-error'), true);
  assert.equal(await page.getAttribute('#probe-noise', 'aria-invalid'), null);
  assert.match(await page.textContent('#verdict'), /.+/);

  // Kept with its pass: pass 1 corrected by the linear step. Pass 2 measured, then the method
  // switched to the nonlinear one: that changes the correction of pass 2, not what pass 1's
  // correction predicted for it. (The machine drifts meanwhile, a wheel swivel of 1 mrad/rad²:
  // without it pass 1 leaves 4e-5 µm rms, within the noise declared, and pass 2 says stop.)
  await afterResult(page, () => page.click('#next-run'));
  await page.fill('[data-offset="B 2"]', '0.001');
  await page.dispatchEvent('[data-offset="B 2"]', 'change');
  await afterResult(page, () => page.click('#generate-error'));
  const settled = () => page.waitForFunction(() => document.querySelector('#pass-table tr[data-pass="3"]') &&
    !/computing/.test(document.querySelector('#pass-table').textContent), null, { timeout: 30000 });
  await settled();
  const before = await predictedRow(page, 2), next = await predictedRow(page, 3);
  await setOption(page, '#correction-method', 'nonlinear');
  await settled();
  assert.equal(await predictedRow(page, 2), before);
  assert.notEqual(await predictedRow(page, 3), next, 'the pass under way is corrected with the options now');
  await page.locator('#passes-section').screenshot({ path: path.join(shots, 'correction-options-passes.png') });
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-case')]);
  const saved = JSON.parse(readFileSync(await download.path(), 'utf8'));
  assert.deepEqual(saved.passes[0].correction, { probeNoise: 1, resolution: { A: 0.01 }, method: 'linear', lockedAxes: [], locked: [] });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
