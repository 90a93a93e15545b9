// The page on a phone or tablet at the machine, 390 x 844: every field of the form on screen.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { openPage, plotted, shots, useBrowser } from './support.mjs';

useBrowser();

test('at 390 x 844 every input and select of the form is within the screen and visible', async () => {
  const width = 390;
  const page = await openPage(undefined, { viewport: { width, height: 844 } });
  await plotted(page);
  assert.equal(await page.evaluate(() => window.scrollX), 0);
  const fields = await page.$$eval('#inputs input, #inputs select', (els) => els
    .filter((el) => !el.closest('[hidden]'))
    .map((el) => {
      // Scrolled down to it, never sideways: what is off to the right stays off screen.
      window.scrollTo(0, el.getBoundingClientRect().top + window.scrollY - 300);
      const r = el.getBoundingClientRect();
      const hit = document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2);
      return {
        name: el.dataset.field || el.id, left: r.left, right: r.right, width: r.width, height: r.height,
        shown: getComputedStyle(el).visibility === 'visible', onTop: hit === el || el.contains(hit),
      };
    }));
  assert.ok(fields.length >= 22, `${fields.length} fields`);
  for (const name of ['hob.gash', 'hob.hand', 'gash-by', 'hob.gashLead', 'grid.xMax']) {
    assert.ok(fields.some((f) => f.name === name), `${name} is in the form`);
  }
  for (const f of fields) {
    assert.ok(f.left >= 0 && f.right <= width, `${f.name} spans ${f.left.toFixed(0)}..${f.right.toFixed(0)} px`);
    assert.ok(f.width >= 60 && f.height >= 16 && f.shown && f.onTop, `${f.name} is visible: ${JSON.stringify(f)}`);
  }
  assert.ok(await page.evaluate(() => document.documentElement.scrollWidth) <= width, 'the page does not scroll sideways');
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: path.join(shots, 'phone.png') });
  await page.screenshot({ path: path.join(shots, 'phone-page.png'), fullPage: true });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
