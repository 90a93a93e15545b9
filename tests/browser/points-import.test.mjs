// A measurement at the measuring machine's own points in the page (issue 11, item 1;
// docs/measured-points.md): a points CSV uploaded is previewed, then corrected as points; a file the
// reader refuses, or points the calculator refuses, leave the page as it was.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync, mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { after_, afterResult, base, ON_DEMAND, openPage, openParts, plotted, root, settled, shots, useBrowser } from './support.mjs';

useBrowser();
const desk = { viewport: { width: 1366, height: 900 } };
const pointsCsv = readFileSync(path.join(root, 'tests', 'data', 'points-2000.csv'), 'utf8');
const dir = mkdtempSync(path.join(tmpdir(), 'hobsharp-points-'));
const file = (name, text) => {
  const p = path.join(dir, name);
  writeFileSync(p, text);
  return p;
};
const previewRows = (page) => page.$$eval('#measured-preview-table tbody tr', (rows) => rows.map((r) => [...r.querySelectorAll('td')].map((c) => c.textContent)));
const state = (page) => page.evaluate(() => ({
  verdict: document.querySelector('#verdict').textContent,
  sseBefore: document.querySelector('#verdict').dataset.sseBefore,
  box: document.querySelector('#measured-csv').value.length,
  title: document.querySelector('#before-title').textContent,
}));

test('a points CSV is previewed, corrected as points, and the maps show the grid', async () => {
  const page = await openPage(base, desk);
  await page.waitForFunction(() => window.hobsharpTimings.results > 0);
  // No points, no marks: the simulated face's map alone, without a legend.
  await plotted(page);
  assert.deepEqual(await page.evaluate(() => [document.querySelector('#plot-before-2d').data.map((t) => t.type),
    document.querySelectorAll('#plot-before-2d .legend').length]), [['heatmap'], 0]);
  // The machine's file, as a German spreadsheet saves it: semicolons, decimal commas, a BOM, CRLF.
  const german = '\uFEFF' + pointsCsv.trim().split('\n').map((l) => l.replace(/,/g, ';').replace(/\./g, ',')).join('\r\n') + '\r\n';
  const n = Number(await page.getAttribute('#measured-preview', 'data-previews'));
  await afterResult(page, () => page.setInputFiles('#measured-file', file('probe-run.csv', german)));
  await page.waitForFunction((k) => Number(document.querySelector('#measured-preview').dataset.previews) > k, n);
  assert.equal(await page.textContent('#measured-read'),
    'Read a points file: 2000 points, semicolons with decimal commas. Preview (r and x in mm, deviation in µm, as it would be used):');
  const first = pointsCsv.split('\n')[1].split(',').map(Number);
  const rows = await previewRows(page);
  assert.equal(rows.length, 13, '12 points and a row saying how many more');
  assert.deepEqual(rows[0].map(Number), first.map((v) => Math.round(v * 1000) / 1000));
  assert.equal(await page.isDisabled('[data-orient="transpose"]'), true, 'a grid option does not apply to points');
  assert.equal(await page.isHidden('#measured-error'), true);
  // The correction: made at the points, down to rounding (the file is a known machine error).
  const verdict = await page.textContent('#verdict');
  assert.match(verdict, /Correctable/);
  const s = await state(page);
  assert.ok(Number(s.sseBefore) > 100, `a real error measured: ${s.sseBefore}`);
  assert.match(s.title, /^Measured at 2000 points/);
  await page.locator('#measured-section .pair > div:first-child').screenshot({ path: path.join(shots, 'points-import-preview.png') });
  // The probe points on both maps: a scatter trace over the heatmap, on its axes (r up, x across,
  // mm), in the legend as "probe points". The plotting library must hold the scatter trace: an
  // unknown trace type draws an empty frame without a word.
  assert.equal(await page.evaluate(() => Boolean(window.Plotly.PlotSchema.get().traces.scatter)), true, 'the bundle has the scatter trace');
  await page.waitForFunction(() => ['plot-before-2d', 'plot-after-2d'].every((id) =>
    document.querySelectorAll(`#${id} .scatterlayer .trace .point`).length === 2000));
  for (const id of ['plot-before-2d', 'plot-after-2d']) {
    const m = await page.evaluate((sel) => {
      const el = document.querySelector(sel);
      const s = el.data.find((t) => t.type === 'scatter');
      const heat = el.data.find((t) => t.type === 'heatmap');
      // Where the first point is drawn, against where the axes put its (x, r).
      const xa = el._fullLayout.xaxis, ya = el._fullLayout.yaxis;
      const dot = el.querySelector('.scatterlayer .trace .point').getBoundingClientRect();
      const plot = el.querySelector('.bglayer rect, .draglayer .nsewdrag').getBoundingClientRect();
      return { name: s.name, n: s.x.length, x0: s.x[0], y0: s.y[0], xaxis: s.xaxis || 'x', heatAxis: heat.xaxis || 'x',
        legend: [...el.querySelectorAll('.legend .legendtext')].map((t) => t.textContent),
        dx: dot.x + dot.width / 2 - plot.x - xa.l2p(s.x[0]), dy: dot.y + dot.height / 2 - plot.y - ya.l2p(s.y[0]) };
    }, `#${id}`);
    assert.equal(m.name, 'probe points');
    assert.deepEqual(m.legend, ['probe points'], id);
    assert.equal(m.n, 2000);
    assert.deepEqual([m.y0, m.x0], first.slice(0, 2), `${id}: the first point at its r and x in mm`);
    assert.equal(m.xaxis, m.heatAxis, 'the same axes as the map');
    assert.ok(Math.abs(m.dx) < 1.5 && Math.abs(m.dy) < 1.5, `${id}: the first point drawn at its place (${m.dx}, ${m.dy} px off)`);
  }
  await page.locator('#topography-section').screenshot({ path: path.join(shots, 'points-import-maps.png') });
  // The circular view changes the maps, not the points the figures are of: they stay the points'
  // (the circular grids are the faces the identified error grinds, without the points' misfit, and
  // their figures made the face after the pass read 0.000 µm rms).
  const figures = () => page.evaluate(() => [document.querySelector('#figures-before').textContent,
    document.querySelector('#figures-after').textContent, document.querySelector('#before-title').textContent]);
  const [beforeNormal, afterNormal] = await figures();
  assert.match(afterNormal, /^At the 2000 points: /);
  await after_(page, 'draws', () => page.check('input[name="view"][value="circular"]'));
  const [beforeCircular, afterCircular, titleCircular] = await figures();
  assert.equal(beforeCircular, beforeNormal);
  assert.equal(afterCircular, afterNormal.replace('At the 2000 points: ', 'At the 2000 points, normal deviation: '));
  assert.match(titleCircular, /^Measured at 2000 points \(figures at the points, normal deviation; map: as the axes explain it\)/);
  await after_(page, 'draws', () => page.check('input[name="view"][value="normal"]'));

  // A file the reader refuses (no units): the message names the line; nothing else changes.
  await page.setInputFiles('#measured-file', file('no-units.csv', 'r,x,deviation\n19,1,2\n'));
  await page.waitForFunction(() => !document.querySelector('#measured-error').hidden);
  // Issue 22: the file named, and what is in use (this read 'Line 1, column 1: ...' alone before).
  assert.equal(await page.textContent('#measured-error'),
    'no-units.csv is refused: Line 1, column 1: the column "r" has no unit: write "r (mm)". In use: probe-run.csv (2000 points).');
  assert.equal((await state(page)).sseBefore, s.sseBefore);
  assert.match((await state(page)).title, /^Measured at 2000 points/);

  // Points the calculator refuses (one off the rake face): named, and the points before stay in use.
  const lines = pointsCsv.trim().split('\n');
  lines[3] = '5,0,1';
  await afterResult(page, () => page.setInputFiles('#measured-file', file('off-face.csv', lines.join('\n'))));
  // Issue 22: the point in words, counted from 1 (this read `measuredPoints[2]: ...` before).
  assert.match(await page.textContent('#measured-error'), /^off-face\.csv is refused: Measured point 3: \(r, x\) = \(5, 0\) mm is off the rake face/);
  const after = await state(page);
  assert.equal(after.sseBefore, s.sseBefore, 'the correction shown is the one before');
  assert.match(after.title, /^Measured at 2000 points/);
  await page.locator('#measured-section .pair > div:first-child').screenshot({ path: path.join(shots, 'points-import-refused.png') });

  // Points over the middle third of the face along x span less motion than the program runs: the
  // change table says what the program changes over the whole face, beside the points' figure.
  const xs = lines.slice(1).map((l) => Number(l.split(',')[1]));
  const [x0, x1] = [Math.min(...xs), Math.max(...xs)];
  const middle = [lines[0], ...pointsCsv.trim().split('\n').slice(1).filter((l) => {
    const x = Number(l.split(',')[1]);
    return x > x0 + (x1 - x0) / 3 && x < x1 - (x1 - x0) / 3;
  })];
  await afterResult(page, () => page.setInputFiles('#measured-file', file('middle-third.csv', middle.join('\n'))));
  assert.match((await state(page)).title, new RegExp(`^Measured at ${middle.length - 1} points`));
  const beyond = await page.$$eval('#identified-error [data-col="change-over-face"]', (cells) => cells.map((c) => c.textContent));
  assert.ok(beyond.length > 0, 'some axis changes more beyond the points');
  for (const b of beyond) assert.match(b, /^[+−-]?[\d.]+(e[+−-]?\d+)? µ(m|rad) over the whole face\*$/);
  assert.match(await page.textContent('#change-over-face-note'), /^\* The change over the whole motion range the program runs, beyond the probe\s+points/);
  await page.evaluate(() => { for (const d of document.querySelectorAll('details')) if (d.contains(document.querySelector('#identified-error'))) d.open = true; });
  assert.ok(await page.isVisible('#change-over-face-note'));
  await page.locator('#identified-error').screenshot({ path: path.join(shots, 'points-change-over-face.png') });
  // On a phone at the machine (390 px): the table within its box, no sideways scroll, and each
  // change cell the points' figure on one line, the whole face's under it with its figure and unit
  // on one line, the words at most two more.
  // Every part on demand opened and the 3D surfaces shown: each of their plots drawn as it opens.
  await openParts(page, ...ON_DEMAND);
  await page.check('#show-3d');
  await page.waitForFunction(() => Boolean(document.querySelector('#plot-after-3d').data));
  await settled(page);
  // Each drawn plot: its id, the height Plotly drew it at, its box's height, and (the gallery) its
  // columns, or (the pass history) its rows of panels.
  const heights = () => page.$$eval('.plot, #gallery', (els) => els.filter((el) => el.data && el.offsetParent !== null)
    .map((el) => {
      const L = el._fullLayout;
      const columns = new Set(Object.keys(L).filter((k) => /^xaxis\d*$/.test(k)).map((k) => L[k].domain[0].toFixed(3))).size;
      return [el.id, L.height, el.clientHeight, columns];
    }));
  const drawn = await heights();
  assert.deepEqual(drawn.filter(([id]) => /2d$/.test(id)).map(([, h]) => h), [330, 330], 'the maps with the points marked');
  for (const id of ['plot-before-3d', 'plot-after-3d', 'plot-passes', 'plot-wheel', 'plot-axes', 'plot-singular', 'gallery']) {
    assert.ok(drawn.some(([d]) => d === id), `${id} is drawn: ${JSON.stringify(drawn)}`);
  }
  const of = (list, id) => list.find(([d]) => d === id);
  assert.equal(of(drawn, 'gallery')[3], 5, 'the gallery in 5 columns at 1366 px');
  assert.equal(of(drawn, 'plot-passes')[3], 4, 'the pass history\'s 4 panels side by side');
  // The window resized as a phone's does (turned, then its toolbar sliding away): each plot drawn
  // again for the new width (the gallery in 2 columns, the pass history two by two), then kept at
  // its height while only the height changes; its box as high as the plot; nothing thrown
  // (Plotly's responsive resize had shrunk the plots to 200 px and thrown "Something went wrong
  // with axis scaling" from the maps' colour bars, and kept the gallery's 5 columns on a phone).
  await page.evaluate(() => {
    window.mapResizes = 0;
    document.querySelector('#plot-before-2d').on('plotly_relayout', () => { window.mapResizes += 1; });
    // A resize that throws never relays out: counted as well, so that the test fails on its message.
    window.addEventListener('unhandledrejection', () => { window.mapResizes += 1; });
    window.addEventListener('error', () => { window.mapResizes += 1; });
  });
  let resizes = 0, phoneDrawn = null;
  for (const [width, height] of [[390, 844], [390, 700], [390, 2000], [390, 844]]) {
    await page.setViewportSize({ width, height });
    // Plotly's own resize, after the window's (debounced): the map relaid out once more.
    await page.waitForFunction((n) => window.mapResizes > n, resizes);
    resizes = await page.evaluate(() => window.mapResizes);
    await settled(page);
    // The pass history draws on its own: two by two on a phone (580 px high).
    await page.waitForFunction(() => document.querySelector('#plot-passes')._fullLayout.height === 580);
    const now = await heights();
    for (const [id, h, box] of now) assert.equal(box, h, `${id}'s box as high as the plot`);
    if (!phoneDrawn) phoneDrawn = now;
    else assert.deepEqual(now, phoneDrawn);
  }
  assert.deepEqual(page.problems, []);
  assert.equal(of(phoneDrawn, 'gallery')[3], 2, 'the gallery in 2 columns on a phone');
  assert.equal(of(phoneDrawn, 'plot-passes')[3], 2, 'the pass history two by two on a phone');
  assert.equal(of(phoneDrawn, 'plot-passes')[1], 580);
  for (const id of ['plot-singular', 'plot-wheel', 'plot-before-3d', 'gallery', 'plot-passes']) {
    await page.locator(`#${id}`).scrollIntoViewIfNeeded();
    await page.locator(`#${id}`).screenshot({ path: path.join(shots, `points-390-${id}.png`) });
  }
  await page.locator('#identified-error').scrollIntoViewIfNeeded();
  const phone = await page.evaluate(() => {
    const table = document.querySelector('#identified-error');
    const box = table.closest('.scroll');
    const lines = (node) => {
      const range = document.createRange();
      range.selectNodeContents(node);
      return new Set([...range.getClientRects()].map((r) => Math.round(r.top))).size;
    };
    return {
      overflow: box.scrollWidth - box.clientWidth,
      right: table.getBoundingClientRect().right,
      page: document.documentElement.scrollWidth,
      cells: [...table.querySelectorAll('td[data-col="change"]')].map((td) => {
        const over = td.querySelector('.beyond');
        // The points' figure: the cell's text before the span.
        return { points: lines(td.firstChild), over: over ? lines(over) : 0, figure: over ? lines(over.querySelector('.figure')) : 0 };
      }),
    };
  });
  await page.locator('#identification').screenshot({ path: path.join(shots, 'points-change-over-face-390.png') });
  // With every part open (the correction's options' fieldset had taken the page 5 px wide).
  assert.ok(phone.overflow <= 0 && phone.right <= 390 && phone.page <= 390, JSON.stringify(phone));
  await page.locator('#correction-options').screenshot({ path: path.join(shots, 'points-correction-options-390.png') });
  // Each of its controls whole within it (the method's select had run past its right edge).
  const options = await page.$$eval('#correction-options select, #correction-options input', (els) => {
    const box = document.querySelector('#correction-options').getBoundingClientRect();
    return els.filter((el) => el.offsetParent !== null).map((el) => ({ id: el.id || el.dataset.field, right: el.getBoundingClientRect().right, box: box.right }));
  });
  for (const o of options) assert.ok(o.right <= o.box, JSON.stringify(o));
  for (const c of phone.cells) assert.ok(c.points === 1 && c.over <= 3 && c.figure <= 1, JSON.stringify(phone.cells));
  assert.ok(phone.cells.some((c) => c.over > 0));
  await page.locator('#plot-before-2d').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(shots, 'points-maps-390-after-resize.png') });
  // Cleared: the plots emptied give their height back (no empty 330 px box under "No correction yet").
  await afterResult(page, () => page.click('#clear-measured'));
  await settled(page);
  assert.deepEqual(await page.$$eval('#plot-after-2d, #plot-singular', (els) => els.map((el) => el.style.height)), ['', '']);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
