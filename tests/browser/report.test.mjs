// The printed report (issue 11, item 4): printed to PDF on A4 and on Letter, each page rendered to
// PNG and looked at: the head with the date, the data and the link on the first page; every plot
// and table kept whole (each fits a page and may not be broken); no page blank.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { afterResult, base, openPage, pngStats, shots, useBrowser } from './support.mjs';

useBrowser();
const mmToPx = (mm) => (mm / 25.4) * 96;
const PAPER = { A4: { width: 210, height: 297 }, Letter: { width: 215.9, height: 279.4 } };
const MARGIN = 12;  // mm, the stylesheet's @page margin

test('the report prints on A4 and Letter: nothing cut, nothing blank', async () => {
  const page = await openPage(base, { viewport: { width: 1366, height: 900 } });
  await page.fill('[data-offset="Z 0"]', '-0.01');
  await page.dispatchEvent('[data-offset="Z 0"]', 'change');
  await afterResult(page, () => page.click('#generate-error'));
  await page.waitForFunction(() => window.hobsharpTimings.draws > 1);
  const out = path.join(shots, 'report');
  mkdirSync(out, { recursive: true });
  for (const [format, paper] of Object.entries(PAPER)) {
    const width = Math.floor(mmToPx(paper.width - 2 * MARGIN)), height = Math.floor(mmToPx(paper.height - 2 * MARGIN));
    await page.setViewportSize({ width, height: 900 });
    await page.emulateMedia({ media: 'print' });
    await page.waitForFunction((w) => [...document.querySelectorAll('.plot')].filter((e) => e.offsetParent && e.data)
      .every((e) => e.querySelector('.main-svg').getBoundingClientRect().width <= w + 1), width);
    // Every plot and table shown fits the printable page and may not be broken across pages.
    const blocks = await page.evaluate(() => [...document.querySelectorAll('.plot, table')].filter((e) => e.offsetParent !== null)
      .map((e) => {
        const svg = e.querySelector('.main-svg');
        const box = e.getBoundingClientRect(), inner = svg ? svg.getBoundingClientRect() : box;
        return { id: e.id || e.className, h: box.height, w: box.width, avoid: getComputedStyle(e).breakInside,
          innerH: inner.height, innerW: inner.width, clips: getComputedStyle(e).contain };
      }));
    assert.ok(blocks.length >= 8, JSON.stringify(blocks));
    for (const b of blocks) {
      assert.equal(b.avoid, 'avoid', `${format}: ${b.id} may be broken`);
      assert.ok(b.h <= height, `${format}: ${b.id} is ${b.h} px high, the page ${height} px`);
      assert.ok(b.w <= width + 1, `${format}: ${b.id} is ${b.w} px wide, the page ${width} px`);
      // The drawing inside a plot is not cut by its box.
      assert.ok(b.innerH <= b.h + 1 && b.innerW <= b.w + 1, `${format}: ${b.id} draws ${b.innerW} x ${b.innerH} px in ${b.w} x ${b.h}`);
    }
    const pdf = path.join(out, `report-${format}.pdf`);
    writeFileSync(pdf, await page.pdf({ format, printBackground: true }));
    const pages = Number(/Pages:\s+(\d+)/.exec(execFileSync('pdfinfo', [pdf], { encoding: 'utf8' }))[1]);
    assert.ok(pages >= 3 && pages <= 8, `${format}: ${pages} pages`);
    const first = execFileSync('pdftotext', ['-f', '1', '-l', '1', '-layout', pdf, '-'], { encoding: 'utf8' });
    assert.match(first, /HobSharp report/);
    assert.match(first, /Printed \d{4}-\d\d-\d\d/);
    assert.match(first, /normalModule/);
    assert.match(first, /Case link: http/);
    const all = execFileSync('pdftotext', ['-layout', pdf, '-'], { encoding: 'utf8' });
    for (const words of ['Axes to run, in the control', 'Deviation topography', 'Correctable', 'Machine error identified']) assert.ok(all.includes(words), `${format}: ${words}`);
    execFileSync('pdftoppm', ['-r', '60', '-png', pdf, path.join(out, format)]);
    const pngs = readdirSync(out).filter((f) => f.startsWith(`${format}-`) && f.endsWith('.png')).sort();
    assert.equal(pngs.length, pages);
    for (const f of pngs) {
      const s = await pngStats(page, readFileSync(path.join(out, f)));
      assert.ok(s.inked > 0.01 && s.colours > 20, `${format} ${f}: ${JSON.stringify(s)}`);
    }
    await page.emulateMedia({ media: 'screen' });
  }
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
