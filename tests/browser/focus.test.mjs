// The answer first (issue 23, item 1): on first open at 1366 x 768 at most 45 controls are
// visible (the rest on demand, in closed <details>; Plotly's toolbars only on hover and out of the
// tab order); after a measured face is loaded the summary (the verdict, the class, the face's rms
// before and after, the axes to run with Copy) is on screen without scrolling; a plot on demand is
// drawn when opened; the phone flow (the tilt, a measured face, "Use as next run") at 390 x 844
// never scrolls the page sideways, shows no toolbar and no plot title over another. The speed
// targets are ./hobsharp.sh bench's (tests/benchmark-page.mjs).
// Screenshots: test-output/browser/focus/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import path from 'node:path';
import { afterError, afterResult, base, galleryDrawn, openPage, plotted, root, shots, useBrowser } from './support.mjs';

useBrowser();
const out = path.join(shots, 'focus');
mkdirSync(out, { recursive: true });
const desk = { viewport: { width: 1366, height: 768 } };
const phone = { viewport: { width: 390, height: 844 } };
const face = path.join(root, 'tests', 'data', 'grid-preamble.csv');

// Every control a user sees on the page (anywhere, scrolled to or not): input, select, textarea,
// button, link, a <details>' summary, and Plotly's toolbar buttons. Hidden: display none, no box,
// invisible or transparent (Plotly's toolbar off hover is transparent), or inside a closed
// <details> (other than its summary).
async function visibleControls(page) {
  return page.evaluate(() => {
    const inClosed = (el) => {
      for (let d = el.closest('details:not([open])'); d; d = d.parentElement && d.parentElement.closest('details:not([open])')) {
        const summary = d.querySelector(':scope > summary');
        if (!(summary && summary.contains(el))) return true;
      }
      return false;
    };
    const shown = (el) => {
      const r = el.getBoundingClientRect();
      if (r.width === 0 || r.height === 0 || inClosed(el)) return false;
      for (let a = el; a; a = a.parentElement) {
        const s = getComputedStyle(a);
        if (s.display === 'none' || s.visibility === 'hidden' || Number(s.opacity) === 0) return false;
      }
      return true;
    };
    return [...document.querySelectorAll('input, select, textarea, button, a[href], summary, .modebar-btn')].filter(shown)
      .map((el) => `${el.tagName.toLowerCase()} ${el.id || el.dataset.field || el.getAttribute('aria-label') || el.textContent.trim().slice(0, 30)}`);
  });
}

// The page's horizontal scroll: none when the page is no wider than the screen.
const scrollsSideways = (page) => page.evaluate(() => document.scrollingElement.scrollWidth > window.innerWidth);

// The boxes (page px) of the elements named, as the screen shows them from the top.
const boxes = (page, selectors) => page.evaluate((list) => Object.fromEntries(list.map((s) => {
  const r = document.querySelector(s).getBoundingClientRect();
  return [s, { top: r.top, bottom: r.bottom, left: r.left, right: r.right, height: r.height }];
})), selectors);

// Every plot's title and panel titles (Plotly's g-gtitle and annotations) as boxes, and the pairs
// of them that overlap within a plot.
const overlappingTitles = (page) => page.evaluate(() => [...document.querySelectorAll('.js-plotly-plot')].filter((p) => p.offsetParent).flatMap((p) => {
  const titles = [...p.querySelectorAll('.g-gtitle text, .annotation-text-g text')].map((t) => [t.textContent, t.getBoundingClientRect()])
    .filter(([, r]) => r.width > 0);
  const hits = [];
  for (let i = 0; i < titles.length; i++) {
    for (let j = i + 1; j < titles.length; j++) {
      const [a, b] = [titles[i][1], titles[j][1]];
      if (a.left < b.right - 1 && b.left < a.right - 1 && a.top < b.bottom - 1 && b.top < a.bottom - 1) hits.push(`${p.id}: "${titles[i][0]}" over "${titles[j][0]}"`);
    }
  }
  return hits;
}));

// A toolbar shown over a plot's title: each visible modebar's box against the plot's titles.
const toolbarsOverTitles = (page) => page.evaluate(() => [...document.querySelectorAll('.js-plotly-plot')].filter((p) => p.offsetParent).flatMap((p) => {
  const bar = p.querySelector('.modebar-container');
  if (!bar || getComputedStyle(bar).display === 'none') return [];
  const groups = [...bar.querySelectorAll('.modebar-group')].filter((g) => Number(getComputedStyle(g).opacity) > 0);
  if (!groups.length) return [];
  const b = bar.getBoundingClientRect();
  return [...p.querySelectorAll('.g-gtitle text, .annotation-text-g text')].map((t) => t.getBoundingClientRect())
    .filter((r) => r.width > 0 && r.left < b.right && b.left < r.right && r.top < b.bottom && b.top < r.bottom).map(() => p.id);
}));

test('first open at 1366 x 768: at most 45 controls; after a measured face the summary is on screen', async () => {
  const page = await openPage(base, desk);
  await plotted(page);
  const controls = await visibleControls(page);
  console.log(`first open at 1366 x 768: ${controls.length} visible controls: ${controls.join(' | ')}`);
  assert.ok(controls.length <= 45, `${controls.length} visible controls: ${controls.join(' | ')}`);
  // Plotly's toolbars: only on hover, and never a tab stop.
  const bars = await page.$$eval('.modebar-btn', (b) => b.map((x) => x.tabIndex));
  assert.ok(bars.length > 0 && bars.every((t) => t === -1), `toolbar buttons' tab index: ${bars}`);
  assert.equal(controls.filter((c) => /modebar|^button (Download plot|Zoom|Pan|Reset|Autoscale)/.test(c)).length, 0);
  // The first step is said.
  assert.match(await page.textContent('#first-step'), /^First type the hob's data .* load the measured face/);
  await page.screenshot({ path: path.join(out, 'desk-first-open.png') });
  await page.screenshot({ path: path.join(out, 'desk-first-open-page.png'), fullPage: true });

  // A measured face, from its file: the summary shows the verdict, the class, the rms before and
  // after, and the axes to run with Copy, all within the first screen.
  await afterResult(page, () => page.setInputFiles('#measured-file', face));
  await page.waitForFunction(() => document.querySelector('#verdict').textContent !== '');
  await page.evaluate(() => window.scrollTo(0, 0));
  const rms = await page.textContent('#summary-rms');
  // After the pass: the prediction's bound, not the identified machine's figure below it.
  assert.match(rms, /^Face rms: \d+\.\d{3} µm measured → at most \d+\.\d{3} µm after the pass\.$/);
  // The same figures as the module's: the topography's measured rms, the prediction line's bound.
  const before = await page.textContent('#figures-before');
  const [rmsBefore, rmsHigh] = /(\d+\.\d{3}) µm measured → at most (\d+\.\d{3})/.exec(rms).slice(1);
  assert.ok(before.startsWith(`rms ${rmsBefore} µm`), `${rms} / ${before}`);
  const high = Number(/at most ([\d.e+-]+) µm rms/.exec(await page.textContent('#prediction'))[1]);
  assert.ok(Math.abs(Number(rmsHigh) - high) <= 0.0005 + 0.005 * high, `${rms} / bound ${high}`);
  assert.match(await page.textContent('#inspection-lead'), /Class (AA|A|B|C|D) — (conforms|undecided|does not conform)|Not graded/);
  assert.match(await page.textContent('#first-step'), /Run the axes below|no pass to run/);
  await page.screenshot({ path: path.join(out, 'desk-measured.png') });
  await page.screenshot({ path: path.join(out, 'desk-measured-page.png'), fullPage: true });
  const parts = ['#verdict', '#inspection-lead', '#summary-rms', '#machine-coefficients', '#copy-axes', '#copy-nc'];
  const at = await boxes(page, parts);
  const height = await page.evaluate(() => window.innerHeight);
  for (const [s, r] of Object.entries(at)) assert.ok(r.height > 0 && r.top >= 0 && r.bottom <= height, `${s} at ${r.top.toFixed(0)}..${r.bottom.toFixed(0)} px of ${height}`);
  if (!(await page.isHidden('#prediction'))) {
    const p = (await boxes(page, ['#prediction']))['#prediction'];
    assert.ok(p.bottom <= height, `the prediction at ${p.top}..${p.bottom} px`);
  }
  assert.equal(await scrollsSideways(page), false);

  // A plot on demand is drawn when its part is opened, at its width: the gallery and the wheel.
  for (const id of ['#gallery', '#plot-wheel', '#plot-axes']) {
    assert.equal(await page.evaluate((s) => Boolean(document.querySelector(s).data), id), false, `${id} waits while closed`);
  }
  const draws = await page.evaluate(() => window.hobsharpTimings.draws);
  await page.click('#sensitivity-details > summary');
  await page.waitForFunction((n) => window.hobsharpTimings.draws > n, draws);
  // Its 25 maps, each filled once the browser has painted their images.
  const filled = (maps) => maps.length === 25 && maps.every((g) => g.inked > 0.95);
  let gallery = await galleryDrawn(page);
  for (let k = 0; k < 50 && !filled(gallery); k++) {
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    gallery = await galleryDrawn(page);
  }
  assert.ok(filled(gallery), JSON.stringify(gallery));
  await page.click('#wheel-details > summary');
  await page.waitForFunction(() => {
    const el = document.querySelector('#plot-wheel');
    const svg = el.querySelector('.main-svg');
    return svg && Math.abs(svg.getBoundingClientRect().width - el.clientWidth) <= 2;
  });
  await page.locator('#wheel-details').screenshot({ path: path.join(out, 'desk-wheel-opened.png') });
  // The locks: a switch per axis in the correction's options, the single coefficients under them.
  await page.click('#correction-options-details > summary');
  assert.equal(await page.locator('#lock-axes [data-lock-axis]').count(), 5);
  await page.click('#lock-coefficients > summary');
  assert.equal(await page.locator('#lock-coefficient-boxes [data-lock]').count(), 25);
  await page.locator('#correction-options-details').screenshot({ path: path.join(out, 'desk-correction-options.png') });
  assert.equal(await page.locator('#what-if [data-lock], #what-if [data-lock-axis]').count(), 0, 'no lock in the what-if');
  // A refused input on demand opens its part, so that its message is seen at it.
  assert.equal(await page.$eval('#machine-grid-details', (d) => d.open), false);
  await afterError(page, () => page.$eval('[data-field="grid.radial"]', (el) => {
    el.value = '1';
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }));
  assert.equal(await page.$eval('#machine-grid-details', (d) => d.open), true);
  assert.ok(await page.isVisible('label:has([data-field="grid.radial"]) .field-message'));
  // A part a view opens (the tolerance table, to show a message) opens the part around it.
  assert.equal(await page.$eval('#inspection-details', (d) => d.open), false);
  await page.$eval('#tolerance-editor', (d) => { d.open = true; });
  await page.waitForFunction(() => document.querySelector('#inspection-details').open);
  assert.ok(await page.isVisible('#tolerance-table'));
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('the phone flow at 390 x 844: the tilt, a measured face, "Use as next run", never sideways', async () => {
  const page = await openPage(base, phone);
  await plotted(page);
  assert.equal(await scrollsSideways(page), false, 'first open');
  assert.deepEqual(await overlappingTitles(page), []);
  await page.screenshot({ path: path.join(out, 'phone-first-open.png') });
  await page.screenshot({ path: path.join(out, 'phone-first-open-page.png'), fullPage: true });
  await afterResult(page, () => page.fill('[data-field="setup.tilt"]', '17'));
  assert.equal(await scrollsSideways(page), false, 'after the tilt');
  await afterResult(page, () => page.setInputFiles('#measured-file', face));
  await page.waitForFunction(() => document.querySelector('#verdict').textContent !== '');
  await plotted(page);
  assert.equal(await scrollsSideways(page), false, 'after the measured face');
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: path.join(out, 'phone-measured.png') });
  await page.screenshot({ path: path.join(out, 'phone-measured-page.png'), fullPage: true });
  for (const part of ['summary', 'measured-section', 'topography-section']) await page.locator(`#${part}`).screenshot({ path: path.join(out, `phone-measured-${part}.png`) });
  const draws = await page.evaluate(() => window.hobsharpTimings.draws);
  await afterResult(page, () => page.click('#next-run'));
  await page.waitForFunction((n) => window.hobsharpTimings.draws > n, draws);
  await page.waitForFunction(() => !document.querySelector('#pass-history').hidden);
  assert.equal(await scrollsSideways(page), false, 'after "Use as next run"');
  // Every plot shown: no title over another, and no toolbar, even where the finger touched.
  for (const id of ['plot-before-2d', 'plot-passes']) await page.tap(`#${id}`, { position: { x: 200, y: 20 } }).catch(() => page.hover(`#${id}`, { position: { x: 200, y: 20 } }));
  assert.deepEqual(await overlappingTitles(page), []);
  assert.deepEqual(await toolbarsOverTitles(page), []);
  // Every toolbar's buttons out of the tab order, the passes' plot's too (drawn by its own view).
  const tabbable = await page.$$eval('.modebar-btn', (b) => b.filter((x) => x.tabIndex !== -1).map((x) => x.closest('.js-plotly-plot').id));
  assert.deepEqual(tabbable, []);
  assert.ok(await page.$$eval('#plot-passes .modebar-btn', (b) => b.length) > 0);
  await page.locator('#passes-section').screenshot({ path: path.join(out, 'phone-passes.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

// The speed (a keystroke's numbers within 100 ms, the first open's plots within 1.5 times Plotly
// alone) is measured by ./hobsharp.sh bench (tests/benchmark-page.mjs), not by a timed test: on a
// machine busy with other work a timed test fails for the machine's sake.
