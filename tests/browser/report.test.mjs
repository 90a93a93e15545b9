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
  // Without the hob's relief the report says why there is no effect on the gear, and no figures.
  await page.emulateMedia({ media: 'print' });
  const out = path.join(shots, 'report');
  mkdirSync(out, { recursive: true });
  const noRelief = path.join(out, 'report-no-relief.pdf');
  writeFileSync(noRelief, await page.pdf({ format: 'A4', printBackground: true }));
  const noReliefText = execFileSync('pdftotext', [noRelief, '-'], { encoding: 'utf8' }).replace(/\s+/g, ' ');
  // Issue 22: in the hob form's words, no JSON name (this assertion read "hob.gashes with hob.relief" before).
  assert.match(noReliefText, /Effect on the gear .{0,80}no relief is given\. Give the number of gashes z and the\s+relief K/);
  assert.doesNotMatch(noReliefText, /hob\.gashes|hob\.relief/);
  assert.doesNotMatch(noReliefText, /fHα|arc-min/);
  await page.emulateMedia({ media: 'screen' });
  // The hob's relief, so that the effect on the gear is in the record.
  await afterResult(page, () => page.fill('[data-field="hob.gashes"]', '12'));
  await afterResult(page, () => page.fill('[data-field="hob.relief"]', '4.5'));
  await page.fill('[data-offset="Z 0"]', '-0.01');
  await page.dispatchEvent('[data-offset="Z 0"]', 'change');
  await afterResult(page, () => page.click('#generate-error'));
  await page.waitForFunction(() => window.hobsharpTimings.draws > 1);
  // The gear's figures as the page shows them (each with its unit), for the printed pages below.
  await page.waitForFunction(() => !document.querySelector('#gear-effect').hidden);
  const gearRows = await page.$$eval('#gear-effect-table tbody tr', (trs) => trs.map((t) => [...t.children].map((c) => c.textContent.trim())));
  assert.equal(gearRows.length, 4);
  for (const t of gearRows) for (const cell of t.slice(1)) assert.match(cell, /^-?\d+\.\d{3} (µm|arc-min)$/, cell);
  // fHα does not change along the hob here (the error is a Z offset): drawn flat, its axis not
  // magnified onto rounding noise.
  await page.waitForFunction(() => document.querySelector('#plot-gear-along')._fullLayout);
  const along = await page.evaluate(() => document.querySelector('#plot-gear-along')._fullLayout.yaxis.range);
  assert.ok(along[1] - along[0] >= 0.1 - 1e-9, `fHα axis ${along}`);
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
    // The rake face's class with its conformity and the proven class lead the record.
    assert.match(first.replace(/\s+/g, ' '), /Rake face \(DIN 3968\): Class (AA|A|B|C|D) — (conforms|undecided|does not conform) \(ISO 14253-1, U95 = 2 µm\); proven class (AA|A|B|C|D|none)\./);
    const all = execFileSync('pdftotext', ['-layout', pdf, '-'], { encoding: 'utf8' });
    for (const words of ['Axes to run, in the control', 'Deviation topography', 'Correctable', 'Machine error identified']) assert.ok(all.includes(words), `${format}: ${words}`);
    // The effect on the gear: each figure with its value and unit for both flanks, on one page.
    const flat = execFileSync('pdftotext', [pdf, '-'], { encoding: 'utf8' }).replace(/\s+/g, ' ');
    assert.match(flat, /Effect on the gear/);
    for (const [label, left, right] of gearRows) {
      const words = label.replace(/[()]/g, '').split(' ').slice(0, 3).join(' ');
      assert.ok(flat.includes(words) && flat.includes(left) && flat.includes(right), `${format}: ${label} ${left} ${right}`);
    }
    const gearPages = [];
    for (let k = 1; k <= pages; k++) {
      if (/profile slope deviation/.test(execFileSync('pdftotext', ['-f', String(k), '-l', String(k), pdf, '-'], { encoding: 'utf8' }))) gearPages.push(k);
    }
    assert.equal(gearPages.length, 1, `${format}: the gear's table on one page, ${gearPages}`);
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
