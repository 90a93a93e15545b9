// The page on a phone or tablet at the machine, 390 x 844: every field of the form on screen.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { openPage, plotted, shots, useBrowser } from './support.mjs';

useBrowser();

test('at 390 x 844 every input and select of the form is within the screen and visible', async () => {
  const width = 390;
  // The machine constants and the grid are on demand (issue 23): opened, as the user opens them.
  const page = await openPage(undefined, { viewport: { width, height: 844 }, open: ['machine-grid-details'] });
  await plotted(page);
  assert.equal(await page.evaluate(() => window.scrollX), 0);
  await page.click('#job-details > summary');  // the job's fields (issue 22), folded until opened
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
  for (const name of ['job.number', 'job.operator', 'hob.gash', 'hob.hand', 'gash-by', 'hob.gashLead', 'grid.xMax']) {
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

// The import preview at 390 px: every labelled control of it (the orientation options, the
// buttons of the box) and the warning lie wholly inside the screen, none clipped by its box.
test('at 390 x 844 the measured grid preview shows every labelled control whole', async () => {
  const width = 390;
  const page = await openPage(undefined, { viewport: { width, height: 844 } });
  await plotted(page);
  // A grid in mm by mistake: the preview, its warning and its options.
  const grid = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (_, j) => ((i - 2) * 0.004 + j * 0.001).toFixed(4)));
  await page.fill('#measured-csv', grid.map((row) => row.join(', ')).join('\n'));
  await page.waitForFunction(() => !document.querySelector('#measured-preview').hidden && !document.querySelector('#measured-warning').hidden);
  await page.locator('#measured-preview').scrollIntoViewIfNeeded();
  const controls = await page.$$eval('#measured-preview label, #measured-preview .warning, #measured-section .pair > div:first-child button',
    (els) => els.filter((el) => !el.closest('[hidden]')).map((el) => {
      const r = el.getBoundingClientRect();
      // Clipped by a box between it and the page: an ancestor that hides what overflows it.
      let clip = null;
      for (let a = el.parentElement; a && a !== document.body; a = a.parentElement) {
        const s = getComputedStyle(a);
        if (s.overflowX !== 'visible' || s.contain.includes('paint')) {
          const b = a.getBoundingClientRect();
          if (r.left < b.left - 0.5 || r.right > b.right + 0.5) clip = a.id || a.className;
        }
      }
      return { text: el.textContent.trim().slice(0, 40), left: r.left, right: r.right, width: r.width, height: r.height,
        overflows: el.scrollWidth > el.clientWidth + 1, clip };
    }));
  const labels = controls.map((c) => c.text);
  for (const words of ['transpose', 'rows tip first', 'columns reversed', 'change sign', 'values in mm', 'Use this grid']) {
    assert.ok(labels.includes(words), `${words} in ${JSON.stringify(labels)}`);
  }
  for (const c of controls) {
    assert.ok(c.left >= 0 && c.right <= width, `"${c.text}" spans ${c.left.toFixed(1)}..${c.right.toFixed(1)} px of ${width}`);
    assert.ok(c.width > 0 && c.height > 0 && !c.overflows && !c.clip, `"${c.text}" is whole: ${JSON.stringify(c)}`);
  }
  assert.ok(await page.evaluate(() => document.documentElement.scrollWidth) <= width, 'the page does not scroll sideways');
  await page.locator('#measured-section .pair > div:first-child').screenshot({ path: path.join(shots, 'phone-measured-preview.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
