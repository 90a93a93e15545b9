// What the engineer reads about the machine (issue 20, item 5): an error of +8 µm on Y alone; the
// page shows a value per axis only where the face tells that axis from the others, and the
// combinations it does not split in words, with the units of the result's own field list.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { afterResult, base, ON_DEMAND, openPage, shots, useBrowser } from './support.mjs';

useBrowser();

async function setNoise(page, value) {
  await afterResult(page, async () => { await page.fill('#probe-noise', value); await page.dispatchEvent('#probe-noise', 'change'); });
}

test('+8 µm on Y: the words name Y with the axes it grinds alike; no axis gets a value the face cannot tell apart', async () => {
  const page = await openPage(base, { viewport: { width: 1366, height: 900 }, open: ON_DEMAND });
  await page.fill('[data-offset="Y 0"]', '0.008');
  await page.dispatchEvent('[data-offset="Y 0"]', 'change');
  await afterResult(page, () => page.click('#generate-error'));
  await setNoise(page, '0.5');  // as a measuring machine's probe would see it
  assert.equal(await page.isVisible('#identification'), true);

  const rows = await page.$$eval('#identified-error tbody tr', (trs) => trs.map((r) => ({
    axis: r.dataset.axis, reading: r.dataset.reading,
    error: r.querySelector('[data-col="error"]')?.textContent.trim() ?? null,
    uncertainty: r.querySelector('[data-col="uncertainty"]')?.textContent.trim() ?? null,
    words: r.querySelector('[data-col="reading"]')?.textContent.trim() ?? null,
    change: r.querySelector('[data-col="change"]').textContent.trim(),
  })));
  assert.deepEqual(rows.map((r) => r.axis), ['X', 'Y', 'Z', 'A', 'B']);
  const y = rows.find((r) => r.axis === 'Y');
  assert.notEqual(y.reading, 'alone', 'Y is not read on its own on the paper\'s hob');
  assert.equal(y.error, null, 'no value shown for Y');
  for (const r of rows) {
    const unit = ['A', 'B'].includes(r.axis) ? 'µrad' : 'µm';
    assert.match(r.change, new RegExp(` ${unit}$`), `${r.axis}: the change in the field's unit`);
    if (r.reading === 'alone') {
      assert.match(r.error, new RegExp(`^[−-]?[\\d.e+-]+ ${unit}$`), JSON.stringify(r));
      assert.match(r.uncertainty, new RegExp(`^± [\\d.e+-]+ ${unit}$`), JSON.stringify(r));
    } else {
      assert.equal(r.error, null, `${r.axis} is ${r.reading}: no value of its own`);
      assert.match(r.words, /not told apart from other axes|not shown by the face|locked/, JSON.stringify(r));
    }
  }

  const words = await page.$$eval('#identified-words li', (lis) => lis.map((li) => li.textContent));
  assert.ok(words.length > 0, 'the combinations in words');
  const aboutY = words.filter((w) => /(^|[ ,])Y([ ,:-]|$)/.test(w));
  assert.ok(aboutY.length > 0, `a sentence names Y: ${words.join(' | ')}`);
  assert.match(aboutY[0], /together: \+1 (µm|µrad) on [XYZAB] grinds (nearly the face of|the same face as) /);
  assert.match(aboutY[0], /It shows their combination: [+−]?[\d.]+ ± [\d.]+ (µm|µrad) of [XYZAB]-equivalent/);
  const text = await page.textContent('#identification');
  assert.doesNotMatch(text, /correction\.|identified(Axes|Alone|Combinations)|NaN|undefined|Infinity/, 'never a field path on the page');
  await page.locator('#identification').screenshot({ path: path.join(shots, 'machine-words.png') });
  assert.deepEqual(page.problems, []);
});

// A value read on its own with its second-order clause: Z 100 µm off, the other axes locked, a probe
// of 0.01 µm. Z reads -100 ± 0.0016 µm, and its second order may move it up to 0.0052 µm, more than
// its uncertainty (tests/js/correction.test.mjs: the words are the module's label). At 390 px too.
test('Z 100 µm off with the other axes locked: Z read on its own, with how far its second order may move it', async () => {
  const page = await openPage(base, { viewport: { width: 1366, height: 900 }, open: ON_DEMAND });
  await page.fill('[data-offset="Z 0"]', '-0.1');
  await page.dispatchEvent('[data-offset="Z 0"]', 'change');
  await afterResult(page, () => page.click('#generate-error'));
  for (const a of ['X', 'Y', 'A', 'B']) await afterResult(page, () => page.check(`[data-lock-axis="${a}"]`));
  await setNoise(page, '0.01');
  const z = page.locator('#identified-error tr[data-axis="Z"]');
  assert.equal(await z.getAttribute('data-reading'), 'alone');
  assert.match(await z.locator('[data-col="error"]').textContent(), /^[−-](99\.99\d*|100(\.0*)?) µm$/);
  const clause = (await z.locator('[data-col="second-order"]').textContent()).trim();
  const m = clause.match(/^; the error's second order may move it up to ([\d.]+) µm$/);
  assert.ok(m, clause);
  const u = Number((await z.locator('[data-col="uncertainty"]').textContent()).match(/^± ([\d.e-]+) µm/)[1]);
  assert.ok(Number(m[1]) > u, `${m[1]} µm beyond ± ${u} µm`);
  for (const a of ['X', 'Y', 'A', 'B']) {
    assert.equal(await page.getAttribute(`#identified-error tr[data-axis="${a}"]`, 'data-reading'), 'locked', a);
  }
  await page.locator('#identified-error').screenshot({ path: path.join(shots, 'second-order-clause.png') });
  await page.setViewportSize({ width: 390, height: 844 });
  await page.locator('#identified-error').screenshot({ path: path.join(shots, 'second-order-clause-390.png') });
  const box = await page.locator('#identified-error').boundingBox();
  assert.ok(box.width <= 390, `the table fits the phone's width: ${box.width} px`);
  assert.deepEqual(page.problems, []);
});
