// The effect on the gear on the page (issue 11, item 3): the hob's relief typed into the hob form,
// the figures per flank with their units, the plot of the gear's profile deviation per tooth and
// flank and the plot of fHα along the hob, both drawn (not blank); a refused relief is shown at its
// field, the figures before it kept.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { afterError, afterResult, base, openPage, plotted, regions, root, shots, useBrowser } from './support.mjs';

useBrowser();

// Two colours of the plot (left flank blue, right flank red) and how much of its plotting area is inked.
async function plotInk(page, id) {
  const box = await page.evaluate((sel) => {
    const at = document.querySelector(sel).getBoundingClientRect();
    const bg = document.querySelector(`${sel} .bglayer rect, ${sel} .draglayer .nsewdrag`).getBoundingClientRect();
    return { x: bg.x - at.x + 2, y: bg.y - at.y + 2, width: bg.width - 4, height: bg.height - 4 };
  }, `#${id}`);
  const [s] = await regions(page, `#${id}`, [box]);
  return s;
}

test('the gear effect: relief in the hob form, figures per flank, the profile and along-the-hob plots', async () => {
  const paper = JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
  // A measured face tilted along the radius (1 µm/mm) with a gash-lead slope (10 µm per 100 mm).
  const r = [19, 24.25, 29.5, 34.75, 40], x = [-70, -52.5, -35, -17.5, 0, 17.5, 35, 52.5, 70];
  const measured = r.map((ri) => x.map((xj) => 1.0 * (ri - 29.5) + 0.1 * xj));
  const page = await openPage(`${base}#case=${encodeURIComponent(JSON.stringify({ ...paper, measured }))}`,
    { viewport: { width: 1366, height: 1000 } });
  // Without the relief the page says what is missing.
  await page.waitForFunction(() => document.querySelector('#gear-effect-reason').textContent !== '');
  assert.match(await page.textContent('#gear-effect-reason'), /no relief is given\. Give the number of gashes z and the relief K \(the cam rise/);
  assert.doesNotMatch(await page.textContent('#gear-effect-reason'), /hob\./);
  assert.equal(await page.isHidden('#gear-effect'), true);

  await afterResult(page, () => page.fill('[data-field="hob.gashes"]', '12'));
  await afterResult(page, () => page.fill('[data-field="hob.relief"]', '4.5'));
  await page.waitForFunction(() => !document.querySelector('#gear-effect').hidden);
  assert.equal(await page.isHidden('#gear-effect-reason'), true);
  assert.match(await page.textContent('[data-derived="sideReliefAngle"]'), /^at d_p: 5\.\d{3}°, k = 8\.594 mm\/rad$/);
  const rows = await page.$$eval('#gear-effect-table tbody tr', (trs) => trs.map((t) => [...t.children].map((c) => c.textContent.trim())));
  assert.deepEqual(rows.map((t) => t[0]), ['profile slope deviation fHα (largest over the teeth)', 'pressure-angle error of that tooth',
    'profile form deviation ffα (largest)', 'scatter of fHα along the hob']);
  for (const t of rows) for (const cell of t.slice(1)) assert.match(cell, /^-?\d+\.\d{3} (µm|arc-min)$/, cell);
  // The tilt makes more material toward the hob's tip: fHα plus on both flanks, a smaller pressure angle.
  assert.ok(parseFloat(rows[0][1]) > 0 && parseFloat(rows[0][2]) > 0, rows[0].join(' | '));
  assert.ok(parseFloat(rows[1][1]) < 0, rows[1].join(' | '));
  // The gash lead slope tilts the flanks apart, and scatters fHα along the hob.
  assert.notEqual(rows[0][1], rows[0][2]);
  assert.ok(parseFloat(rows[3][1]) > 0, rows[3].join(' | '));
  assert.doesNotMatch(JSON.stringify(rows), /NaN|undefined|Infinity|—/);

  await plotted(page);
  await page.waitForFunction(() => document.querySelectorAll('#plot-gear-profile .scatterlayer .trace').length === 10
    && document.querySelectorAll('#plot-gear-along .scatterlayer .trace').length === 2);
  await page.locator('#gear-effect-section').scrollIntoViewIfNeeded();
  await page.locator('#gear-effect-section').screenshot({ path: path.join(shots, 'gear-effect.png') });
  for (const id of ['plot-gear-profile', 'plot-gear-along']) {
    const s = await plotInk(page, id);
    assert.ok(s.colours > 20, `${id}: ${s.colours} colours, the plot draws lines`);
    assert.ok(s.inked > 0.005, `${id}: ${(100 * s.inked).toFixed(2)} % inked`);
  }
  const legend = await page.$$eval('#plot-gear-along .legendtext', (t) => t.map((e) => e.textContent));
  assert.deepEqual(legend, ['left flank (faces −x₁)', 'right flank (faces +x₁)']);
  const titles = await page.$$eval('#plot-gear-profile .g-xtitle, #plot-gear-profile .g-ytitle', (t) => t.map((e) => e.textContent));
  assert.deepEqual(titles, ['profile deviation on the gear (µm, + = more material)', 'height on the gear tooth (mm, tip up)']);

  // A refused relief: named at its field; the figures on screen stay.
  const before = await page.textContent('#gear-effect-table tbody');
  await afterError(page, () => page.fill('[data-field="hob.relief"]', '-1'));
  assert.equal(await page.getAttribute('[data-field="hob.relief"]', 'aria-invalid'), 'true');
  assert.equal(await page.textContent('#gear-effect-table tbody'), before);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
