// The printed report (issue 11, item 4; issue 22, item 2): printed to PDF on A4 and on Letter with
// print media emulated, each page rendered to PNG and looked at. Page 1: the verdict in one line,
// the job, the date, the inputs by their labels with units, the case link as a QR code, and no
// field path of the case. Then "Program this" (the axes to run in the control's units), the
// record's views without the solver's internals, and the polynomials in rad as an appendix at the
// end. Every plot and table kept whole (each fits a page and may not be broken), every plot with
// its colour bar within the printable width, the right margin of every page blank; no page blank.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import QRCode from 'qrcode';
import { afterError, afterResult, base, dataCase, openPage, openParts, pngRegions, pngStats, settled, shots, useBrowser } from './support.mjs';

useBrowser();
const mmToPx = (mm) => (mm / 25.4) * 96;
const PAPER = { A4: { width: 210, height: 297 }, Letter: { width: 215.9, height: 279.4 } };
const MARGIN = 12;  // mm, the stylesheet's @page margin
const JOB = { number: 'A-2026-117', customer: 'Zahnradwerk Süd GmbH', hobSerial: 'H 4711', operator: 'K. Weber', notes: 'Second pass after dressing.' };
// A case's field path ("hob.normalModule", "job.number") or a field's own name in camel case
// ("normalModule", "rMin", "hobSerial"): neither may be printed.
const JSON_NAME = /\b(format|hob|wheel|setup|machine|grid|axes|measured|correction|inspection|passes|job|gearEffect|topography)\.[A-Za-z]|\b[a-z]{2,}[A-Z][a-z]+|\b[rx](Min|Max)\b/;

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
  // The job, typed in its fields; it goes into the case (and so the link) and onto page 1.
  await page.click('#job-details > summary');
  for (const [key, text] of Object.entries(JOB)) await afterResult(page, () => page.fill(`[data-field="job.${key}"]`, text));
  assert.deepEqual(JSON.parse(decodeURIComponent(await page.evaluate(() => location.hash.slice('#case='.length)))).job, JOB);
  // The hob's relief, so that the effect on the gear is in the record.
  await afterResult(page, () => page.fill('[data-field="hob.gashes"]', '12'));
  await afterResult(page, () => page.fill('[data-field="hob.relief"]', '4.5'));
  await openParts(page, 'what-if-details');  // "Simulate a machine error...", on demand (issue 23)
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
    // Every plot's drawing, colour bar and legend within the plot's box and the printable width.
    const overflows = await page.evaluate((w) => [...document.querySelectorAll('.plot')].filter((e) => e.offsetParent && e.data).flatMap((e) => {
      const box = e.getBoundingClientRect();
      return [...e.querySelectorAll('.main-svg, .colorbar, .legend, .infolayer .g-gtitle')].map((g) => [e.id, g.getAttribute('class'), g.getBoundingClientRect()])
        .filter(([, , r]) => r.width > 0 && (r.right > Math.min(box.right, w) + 1 || r.left < box.left - 1))
        .map(([id, cls, r]) => `${id} ${cls}: ${Math.round(r.left)}..${Math.round(r.right)} px in ${Math.round(box.left)}..${Math.round(box.right)} (page ${w})`);
    }), width);
    assert.deepEqual(overflows, [], `${format}: drawn past its box`);
    // The NC program one block a line: a block wider than the paper goes on lines indented under
    // its first (a SINUMERIK "Y=PO(...)" at the margin would read as a block of its own).
    const ncLines = await page.$$eval('#report-program .nc-block', (blocks) => blocks.map((b) => {
      const range = document.createRange();
      range.selectNodeContents(b);
      const lefts = [...new Set([...range.getClientRects()].filter((r) => r.width > 0).map((r) => Math.round(r.top)))]
        .map((top) => Math.min(...[...range.getClientRects()].filter((r) => r.width > 0 && Math.round(r.top) === top).map((r) => r.left)));
      return { text: b.textContent.slice(0, 24), lefts };
    }));
    assert.ok(ncLines.length >= 3, `${format}: ${JSON.stringify(ncLines)}`);
    assert.ok(ncLines.some((b) => b.lefts.length > 1), `${format}: no block of the program wraps at the paper's width`);
    for (const b of ncLines) {
      for (const left of b.lefts.slice(1)) assert.ok(left >= b.lefts[0] + 10, `${format}: "${b.text}…" continues at ${left} px, its block begins at ${b.lefts[0]} px`);
    }
    // What page 1 and "Program this" must print: the page's own texts.
    const verdict = await page.textContent('#report-verdict');
    const inputs = await page.$$eval('#report-inputs tbody tr:not(.report-group)', (rows) => rows.map((r) => {
      const c = [...r.children].map((x) => x.textContent.replace(/\s+/g, ' ').trim());
      return [c[0], [c[1], c[2]].filter(Boolean).join(' ')];
    }));
    const programRows = await page.$$eval('#report-axes tbody tr', (rows) => rows.map((r) => [r.children[0].textContent.trim().split(' ')[0],
      [...r.children].slice(1).map((c) => c.textContent.replace(/\s+/g, ' ').trim())]));
    assert.deepEqual(programRows.map((r) => r[0]), ['X', 'Y', 'Z', 'A', 'B']);
    // In the control's units: A in degrees, its a1 per degree of hob rotation (1 deg/deg).
    assert.deepEqual(await page.$$eval('#report-axes tbody th', (t) => t.map((x) => x.textContent)), ['X (mm)', 'Y (mm)', 'Z (mm)', 'A (deg)', 'B (deg)']);
    assert.deepEqual(await page.$$eval('#report-axes thead th', (t) => t.map((x) => x.textContent)), ['axis', 'a0', 'a1 (per deg)', 'a2 (per deg^2)', 'a3 (per deg^3)', 'a4 (per deg^4)']);
    assert.ok(Math.abs(Number(programRows[3][1][1]) - 1) < 1e-4, `A's a1 ${programRows[3][1][1]} deg/deg`);
    // The QR code holds the link: the page's code is the library's for location.href, and the
    // library's segments read back to the link.
    const { link, svg, qr } = await page.evaluate(() => {
      const r = document.querySelector('#report-qr svg').getBoundingClientRect();
      return { link: location.href, svg: document.querySelector('#report-qr').innerHTML,
        qr: { x: r.x + scrollX, y: r.y + scrollY, width: r.width, height: r.height } };
    });
    const modules = (text) => /<path stroke="#000000" d="([^"]+)"/.exec(text)[1];
    assert.ok(modules(svg) === modules(await QRCode.toString(link, { type: 'svg', errorCorrectionLevel: 'L', margin: 4 })), `${format}: the code is not the link's`);
    const code = QRCode.create(link, { errorCorrectionLevel: 'L' });
    assert.equal(code.segments.map((g) => (typeof g.data === 'string' ? g.data : Buffer.from(g.data).toString('utf8'))).join(''), link);
    assert.ok(code.version <= 40 && qr.width >= mmToPx(30), `version ${code.version}, ${qr.width} px`);
    // Printed as the browser's own print does: the window as it was (1366 px wide), print media
    // emulated, the pages laid out at the paper's width. Every plot is then drawn to the printable
    // width (less its card's insets): none as wide as the window's layout.
    await page.emulateMedia({ media: 'screen' });
    await page.setViewportSize({ width: 1366, height: 900 });
    await page.waitForFunction(() => [...document.querySelectorAll('.plot')].every((e) => !e.layout || e.layout.width == null));
    await page.emulateMedia({ media: 'print' });
    await page.waitForFunction(() => [...document.querySelectorAll('.plot')].filter((e) => e.offsetParent && e.data)
      .every((e) => typeof e.layout.width === 'number'));
    const pastThePaper = await page.evaluate((w) => [...document.querySelectorAll('.plot')].filter((e) => e.offsetParent && e.data).flatMap((e) =>
      [...e.querySelectorAll('.main-svg, .colorbar')].map((g) => [e.id, g.getAttribute('class'), g.getBoundingClientRect().right])
        .filter(([, , right]) => right > w + 1).map(([id, cls, right]) => `${id} ${cls} to ${Math.round(right)} px`)), width);
    assert.deepEqual(pastThePaper, [], `${format}: drawn past the printable width (${width} px) as the browser prints`);
    // A pass that draws the plots while print media apply (here the redraw after the window's
    // width changed, which had come 200 ms after the print's relayout and drawn them at the window's
    // width): at the printable width too.
    await page.setViewportSize({ width: 1300, height: 900 });
    await settled(page);
    const pastAfterRedraw = await page.evaluate((w) => [...document.querySelectorAll('.plot')].filter((e) => e.offsetParent && e.data).flatMap((e) =>
      [...e.querySelectorAll('.main-svg, .colorbar')].map((g) => [e.id, g.getAttribute('class'), g.getBoundingClientRect().right])
        .filter(([, , right]) => right > w + 1).map(([id, cls, right]) => `${id} ${cls} to ${Math.round(right)} px`)), width);
    assert.deepEqual(pastAfterRedraw, [], `${format}: drawn past the printable width (${width} px) by a redraw while printing`);
    await page.setViewportSize({ width: 1366, height: 900 });
    await settled(page);
    const pdf = path.join(out, `report-${format}.pdf`);
    writeFileSync(pdf, await page.pdf({ format, printBackground: true }));
    const pages = Number(/Pages:\s+(\d+)/.exec(execFileSync('pdfinfo', [pdf], { encoding: 'utf8' }))[1]);
    assert.ok(pages >= 3 && pages <= 8, `${format}: ${pages} pages`);
    const first = execFileSync('pdftotext', ['-f', '1', '-l', '1', '-layout', pdf, '-'], { encoding: 'utf8' });
    const firstFlat = first.replace(/\s+/g, ' ');
    assert.match(first, /HobSharp report/);
    assert.match(first, /Printed \d{4}-\d\d-\d\d/);
    // The verdict in one line: the class with its conformity, the verdict's word, the face's rms
    // measured and predicted, with the condition the bound holds on when the verdict states one.
    assert.ok(firstFlat.includes(verdict), `${format}: the verdict "${verdict}" on page 1`);
    assert.match(verdict, /^Class (AA|A|B|C|D)\*? — (conforms|undecided|does not conform)(, the gashes' spacing not measured)?( \(\* on a series value, not confirmed\))?; (Correctable|Uncertain|Partly uncorrectable)[^:]*: face [\d.]+ µm rms measured, at most [\d.e-]+ µm rms after the correction( if the error the face cannot show is no larger than the one it shows)?(; that is with the exact axes, and the machine's position resolution sets a floor of about [\d.]+ µm rms)?\.$/);
    // The rake face's class with its conformity and the proven class.
    assert.match(firstFlat, /Rake face \(DIN 3968\): Class (AA|A|B|C|D) — (conforms|undecided|does not conform) \(ISO 14253-1, U95 = 2 µm\); proven class (AA|A|B|C|D|none)\./);
    // The job, by the form's labels.
    for (const [label, key] of [['Job number', 'number'], ['Customer', 'customer'], ['Hob serial number', 'hobSerial'], ['Operator', 'operator'], ['Notes', 'notes']]) {
      assert.ok(firstFlat.includes(`${label} ${JOB[key]}`), `${format}: ${label} ${JOB[key]}`);
    }
    // The inputs by their labels, each value with its unit, as the form shows them.
    for (const [label, value] of inputs) assert.ok(firstFlat.includes(`${label} ${value}`), `${format}: "${label} ${value}" on page 1`);
    assert.ok(inputs.length >= 20, JSON.stringify(inputs));
    assert.ok(firstFlat.includes('Normal module mn 7 mm') && /Outer diameter dw \d+ mm/.test(firstFlat), firstFlat);
    // The case link as a QR code, and no printed link; no field path anywhere on the page.
    assert.match(firstFlat, /Case link: scan the code/);
    assert.doesNotMatch(first, /http|#case=/);
    assert.ok(!JSON_NAME.test(first), `${format}: a field's path on page 1: ${JSON_NAME.exec(first)}`);
    const all = execFileSync('pdftotext', ['-layout', pdf, '-'], { encoding: 'utf8' });
    for (const words of ['Program this', 'Deviation topography', 'Correctable', 'Machine error identified', 'Grinding passes']) assert.ok(all.includes(words), `${format}: ${words}`);
    // No solver internals in the record; no field path anywhere.
    const internals = /Precision demand|1 part in|iterations?\b|Solver \(|Axes the control can run/.exec(all);
    assert.ok(!internals, `${format}: solver internals printed: ${internals && all.slice(internals.index - 200, internals.index + 60)}`);
    assert.ok(!JSON_NAME.test(all), `${format}: a field's path: ${all.slice(Math.max(0, JSON_NAME.exec(all)?.index - 200), JSON_NAME.exec(all)?.index + 60)}`);
    // "Program this" (the axes to run in the control's units, deg and mm) on page 2, the axes in rad
    // (Tab. 2) only in the appendix, which closes the report.
    const pageText = (k) => execFileSync('pdftotext', ['-f', String(k), '-l', String(k), '-layout', pdf, '-'], { encoding: 'utf8' });
    const second = pageText(2);
    assert.match(second, /Program this/);
    // With the NC program the page offers for the control chosen (Sinumerik by default).
    assert.match(second, /NC program: .*SINUMERIK/i);
    assert.match(all, /N10 G90 G1 X-?[\d.]+ Y-?[\d.]+ Z-?[\d.]+ A-?[\d.]+ B-?[\d.]+\s+N20 POLY /);
    for (const [axis, cells] of programRows) {
      const line = second.split('\n').find((l) => new RegExp(`^\\s*${axis}\\s`).test(l)) || '';
      assert.equal(line.trim().replace(/\s+/g, ' '), `${axis} (${['A', 'B'].includes(axis) ? 'deg' : 'mm'}) ${cells.join(' ')}`, `${format}: axis ${axis}`);
    }
    const appendix = [...Array(pages).keys()].map((k) => k + 1).filter((k) => /Appendix: Five-axis CNC polynomials/.test(pageText(k)));
    assert.equal(appendix.length, 1, `${format}: the appendix's heading once`);
    for (let k = 1; k < appendix[0]; k++) assert.doesNotMatch(pageText(k), /Tab\. 2|Uncorrected \(nominal/, `${format}: Tab. 2 before the appendix, page ${k}`);
    for (let k = appendix[0]; k <= pages; k++) assert.doesNotMatch(pageText(k), /Grinding passes|Deviation topography/, `${format}: the body after the appendix, page ${k}`);
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
      const png = readFileSync(path.join(out, f));
      const s = await pngStats(page, png);
      assert.ok(s.inked > 0.01 && s.colours > 20, `${format} ${f}: ${JSON.stringify(s)}`);
      // Nothing in the right (or left) margin: a plot or colour bar past the printable width
      // would print there. At 60 dpi the 12 mm margin is 28 px; the outer 24 px are checked.
      const [w, h] = [Math.round((paper.width / 25.4) * 60), Math.round((paper.height / 25.4) * 60)];
      const [right, left] = await pngRegions(page, png, [{ x: w - 24, y: 0, width: 24, height: h }, { x: 0, y: 0, width: 24, height: h }]);
      assert.equal(right.inked, 0, `${format} ${f}: something prints in the right margin`);
      assert.equal(left.inked, 0, `${format} ${f}: something prints in the left margin`);
    }
    // The QR code on page 1, printed: rendered at 150 dpi, its box holds dark and light modules.
    execFileSync('pdftoppm', ['-r', '150', '-f', '1', '-l', '1', '-png', pdf, path.join(out, `qr-${format}`)]);
    const qrPng = readdirSync(out).find((f) => f.startsWith(`qr-${format}`) && f.endsWith('.png'));
    const px = (v) => ((v / 96) * 150);
    const [qrBox] = await pngRegions(page, readFileSync(path.join(out, qrPng)), [{ x: px(qr.x) + mmToPx(MARGIN) * 150 / 96, y: px(qr.y) + mmToPx(MARGIN) * 150 / 96, width: px(qr.width), height: px(qr.height) }]);
    assert.ok(qrBox.inked > 0.25 && qrBox.inked < 0.75, `${format}: the QR code printed: ${JSON.stringify(qrBox)}`);
    await page.emulateMedia({ media: 'screen' });
  }
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

// Page 1's verdict line keeps the correction's verdict: its word (Uncertain), the condition the
// bound holds on and the part of the face that may stay unground; and the class's * (a series
// value) as the inspection's table shows it. Printed to PDF as the browser prints, page 1 rendered.
test("page 1 carries the verdict's word, its condition and warning, and the class's series mark", async () => {
  const page = await openPage(base, { viewport: { width: 1366, height: 900 } });
  await afterResult(page, () => page.setInputFiles('#load-case', dataCase('unground-sample-pass.json')));
  assert.match(await page.textContent('#verdict'), /^Uncertain: .* if the error the face cannot show is no larger than the one it shows, .*\(part of it would stay unground\)/);
  await settled(page);
  await page.emulateMedia({ media: 'print' });
  const out = path.join(shots, 'report');
  mkdirSync(out, { recursive: true });
  const pdf = path.join(out, 'report-uncertain.pdf');
  writeFileSync(pdf, await page.pdf({ format: 'A4', printBackground: true }));
  const first = execFileSync('pdftotext', ['-f', '1', '-l', '1', pdf, '-'], { encoding: 'utf8' }).replace(/\s+/g, ' ');
  assert.ok(first.includes('Class B* — conforms, the gashes\' spacing not measured (* on a series value, not confirmed); Uncertain: face 149 µm rms measured, at most 106 µm rms after the correction '
    + 'if the error the face cannot show is no larger than the one it shows; part of the face may stay unground.'), first);
  assert.ok(first.includes("Rake face (DIN 3968): Class B* — conforms (ISO 14253-1, U95 = 2 µm); proven class B* (* the class and the proven class rest on "
    + "a series value, not confirmed: enter the hob maker's table). The gashes' spacing is not measured: the class rests on the face's checks alone."), first);
  execFileSync('pdftoppm', ['-r', '80', '-f', '1', '-l', '1', '-png', pdf, path.join(out, 'uncertain-page')]);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

// A link too long for a QR code (a 30 x 30 measured grid: about 9 kB): page 1 says so and what to
// do instead, and prints no code that could not be read back.
test('a case link too long for a QR code: page 1 says to keep the case file instead', async () => {
  const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
  const n = 30;
  const measured = Array.from({ length: n }, (_, i) => Array.from({ length: n }, (_, j) => Number((Math.sin(i * 0.7 + j * 0.3) * 3.2117).toFixed(4))));
  const c = { ...paper, grid: { ...paper.grid, radial: n, axial: n }, measured };
  const page = await openPage(`${base}#case=${encodeURIComponent(JSON.stringify(c))}`, { viewport: { width: 1366, height: 900 } });
  await page.waitForFunction(() => /too long for a QR code/.test(document.querySelector('#report-link-note').textContent), null, { timeout: 30000 });
  const bytes = await page.evaluate(() => new TextEncoder().encode(location.href).length);
  assert.ok(bytes > 2953, `${bytes} bytes`);
  assert.equal(await page.$$eval('#report-qr svg', (s) => s.length), 0);
  await page.emulateMedia({ media: 'print' });
  const pdf = path.join(shots, 'report', 'report-long-link.pdf');
  writeFileSync(pdf, await page.pdf({ format: 'A4', printBackground: true }));
  const first = execFileSync('pdftotext', ['-f', '1', '-l', '1', pdf, '-'], { encoding: 'utf8' }).replace(/\s+/g, ' ');
  assert.match(first, new RegExp(`The case link \\(${bytes} bytes\\) is too long for a QR code \\(at most 2953 bytes\\): save the case file \\("Save case"\\) and keep it with this report\\.`));
  assert.doesNotMatch(first, /http|#case=/);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

// The job's fields (issue 22): a case that names a job opens them filled; a text too long is
// refused at its field in the label's words, and the job of the last good result stays.
test("the job's fields: filled from a case, a text too long named by its label", async () => {
  const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
  const page = await openPage(`${base}#case=${encodeURIComponent(JSON.stringify({ ...paper, job: JOB }))}`, { viewport: { width: 1366, height: 900 } });
  await page.waitForFunction(() => document.querySelector('#report-verdict').textContent !== '');
  assert.equal(await page.$eval('#job-details', (d) => d.open), true, 'open when the case names a job');
  for (const [key, text] of Object.entries(JOB)) assert.equal(await page.inputValue(`[data-field="job.${key}"]`), text);
  assert.deepEqual(await page.$$eval('#report-job th', (t) => t.map((x) => x.textContent)), ['Job number', 'Customer', 'Hob serial number', 'Operator', 'Notes']);
  // The field takes at most 60 characters as typed; a script can set more.
  await afterError(page, () => page.$eval('[data-field="job.number"]', (el) => {
    el.value = '7'.repeat(61);
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }));
  const note = page.locator('label:has([data-field="job.number"]) .field-message');
  assert.equal((await note.textContent()).trim(), 'Job number must be at most 60 characters; got 61.');
  assert.doesNotMatch(await page.textContent('#status'), /job\./);
  assert.equal(JSON.parse(decodeURIComponent(await page.evaluate(() => location.hash.slice('#case='.length)))).job.number, JOB.number, 'the link keeps the last good job');
  await page.locator('#job-details').screenshot({ path: path.join(shots, 'report', 'job-fields.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
