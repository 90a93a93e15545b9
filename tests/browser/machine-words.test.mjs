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
