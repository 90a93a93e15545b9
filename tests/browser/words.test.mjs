// The page's limits from the module, its keyboard and screen-reader access, and its words: what
// an engineer trying the page tripped on (issue 9, items 2 and 6).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { after_, afterResult, base, ON_DEMAND, openPage, shots, useBrowser } from './support.mjs';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { fixed, fmt, signed } from '../../web/src/format.js';
import { gridFigures } from '../../web/src/figures.js';

useBrowser();
const hobsharp = await loadHobSharp();
const paper = readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8');

async function formLimits(page) {
  return page.evaluate(() => {
    const $ = (s) => document.querySelector(s);
    const degree = $('[data-field="degree"]'), radial = $('[data-field="grid.radial"]'), axial = $('[data-field="grid.axial"]');
    return {
      degree: [Number(degree.min), Number(degree.max), Number(degree.placeholder)], degreeText: $('[data-limit="degree"]').textContent,
      grid: [Number(radial.max), Number(axial.max)], placeholders: [Number(radial.placeholder), Number(axial.placeholder)],
    };
  });
}

test("the form's grid limit, degree range and default grid are the module's", async () => {
  const limits = hobsharp.limits();
  const page = await openPage(base, { open: ON_DEMAND });
  assert.deepEqual(await formLimits(page), {
    degree: [limits.degree.min, limits.degree.max, limits.degree.default], degreeText: `${limits.degree.min} to ${limits.degree.max}`,
    grid: [limits.maxGridLines, limits.maxGridLines], placeholders: [limits.defaultGrid.radial, limits.defaultGrid.axial],
  });
  await page.context().close();

  // A module with other limits: the page shows those, and the CSV message names its grid limit.
  const worker = `importScripts('hobsharp-web.js', 'worker-main.js');
    hobsharpWorkerMain(self, () => HobSharpModule().then((m) => {
      const own = m.limits;
      m.limits = () => Object.assign(own(), { maxGridLines: 150, degree: { min: 2, max: 5, default: 3 }, defaultGrid: { radial: 4, axial: 7 } });
      return m;
    }));`;
  const other = await openPage(undefined, {
    prepare: (context) => context.route('**/worker.js', (route) => route.fulfill({ contentType: 'text/javascript', body: worker })),
  });
  assert.deepEqual(await formLimits(other), { degree: [2, 5, 3], degreeText: '2 to 5', grid: [150, 150], placeholders: [4, 7] });
  assert.deepEqual(other.problems, []);
  await other.context().close();
});

// The file choosers are caught from the page's start: a listener added only just before the key
// press (Promise.all of waitForEvent and press) let the press win the race now and then on a
// loaded machine, and the chooser then opened unseen.
async function openWatchingChoosers() {
  const choosers = [];
  let waiting = null;  // resolves the chooser the test waits for
  const page = await openPage(undefined, {
    prepare: (context) => context.on('page', (p) => p.on('filechooser', (c) => {
      choosers.push(c);
      if (waiting) waiting();
    })),
  });
  page.chooserAfter = async (press) => {
    const before = choosers.length;
    const opened = new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error('no file chooser opened within 10 s of the key')), 10000);
      waiting = () => { if (choosers.length > before) { clearTimeout(timer); waiting = null; resolve(); } };
    });
    await press();
    if (waiting) waiting();  // it may have opened during the press
    await opened;
    return choosers[before];
  };
  return page;
}

test('"Load case…" and "Upload CSV…" are reached with Tab and open the file chooser with Enter or Space', async () => {
  const page = await openWatchingChoosers();
  const focused = () => page.evaluate(() => document.activeElement.textContent.trim());
  await page.focus('#preset-paper');
  await page.keyboard.press('Tab');
  assert.equal(await focused(), 'Load case…');
  const c = JSON.parse(paper);
  c.machine.K1 = 121;
  const chooser = await page.chooserAfter(() => page.keyboard.press('Enter'));
  await afterResult(page, () => chooser.setFiles({ name: 'k1.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(c)) }));
  assert.equal(await page.inputValue('[data-field="machine.K1"]'), '121');

  await page.focus('#measured-csv');
  await page.keyboard.press('Tab');
  assert.equal(await focused(), 'Upload CSV…');
  const csv = await page.chooserAfter(() => page.keyboard.press('Space'));
  assert.equal(await csv.element().getAttribute('id'), 'measured-file');
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('the lock boxes, the offsets and the CSV box have names of their own; one live region', async () => {
  const page = await openPage(base, { open: ON_DEMAND });
  const units = Object.fromEntries(hobsharp.limits().axes.map((a) => [a.name, a.unit]));
  const sup = ['', '', '²', '³', '⁴', '⁵', '⁶'];
  const locks = await page.$$eval('[data-lock]', (els) => els.map((el) => el.getAttribute('aria-label')));
  assert.equal(locks.length, 25);
  assert.equal(new Set(locks).size, 25, 'every lock has a name of its own');
  for (const a of Object.keys(units)) {
    for (let k = 0; k <= 4; k++) {
      const unit = k === 0 ? units[a] : `${units[a]}/rad${sup[k]}`;
      assert.equal(await page.getByRole('checkbox', { name: `Lock ${a} a${k} (${unit})`, exact: true }).count(), 1, `${a} a${k}`);
      assert.equal(await page.getByRole('spinbutton', { name: `Offset of ${a} a${k} (${unit})`, exact: true }).count(), 1);
    }
    assert.equal(await page.getByRole('checkbox', { name: `Lock every coefficient of ${a}`, exact: true }).count(), 1);
  }
  assert.equal(await page.getByRole('textbox', { name: 'Paste or upload a measured grid', exact: true }).count(), 1);

  // After a recompute, the accessibility tree has one live region: the status line, polite.
  await afterResult(page, () => page.fill('[data-field="setup.tilt"]', '16'));
  const cdp = await page.context().newCDPSession(page);
  const { nodes } = await cdp.send('Accessibility.getFullAXTree');
  const live = nodes.filter((n) => !n.ignored && (n.properties || []).some((p) => p.name === 'live' && p.value.value !== 'off'));
  const roots = live.filter((n) => !live.some((m) => (m.childIds || []).includes(n.nodeId)));
  assert.deepEqual(roots.map((n) => [n.role.value, n.properties.find((p) => p.name === 'live').value.value]), [['status', 'polite']]);
  assert.equal(await page.locator('[aria-live]:not([aria-live="off"]), [role=status], [role=log], output:not([aria-live="off"])').count(), 1);
  await page.context().close();
});

test("the words: no −0.000, no hand for a straight gash, the status, the verdict, rad/rad²", async () => {
  const page = await openPage(base, { open: ON_DEMAND });
  const thickness = hobsharp.evaluate(JSON.parse(paper)).topography.thickness;
  assert.ok(thickness < 0 && thickness > -0.0005, `the paper's thickness error ${thickness} rounds to -0.000`);
  assert.match(await page.textContent('#figures-before'), /thickness error 0\.000 µm · /);
  assert.match(await page.textContent('#status'), /^Updated — (\d+|under 1) ms$/);
  assert.match(await page.textContent('[data-derived="settingAngle"]'), /^(used: 12\.626°|auto: 12\.62\d\d° \(the gash helix angle, right hand\))$/);

  await page.fill('[data-field="setup.settingAngle"]', '');
  await page.fill('[data-field="setup.centerDistance"]', '');
  await afterResult(page, () => page.selectOption('[data-field="hob.gash"]', 'straight'));
  await page.waitForFunction(() => /straight/.test(document.querySelector('[data-derived="settingAngle"]').textContent));
  assert.equal(await page.textContent('[data-derived="settingAngle"]'), 'auto: 0.0000° (straight gash: no helix to follow)');

  await afterResult(page, () => page.click('#preset-paper'));
  // A machine error to correct (a perfect face is within the probe noise: the verdict says stop).
  await page.fill('[data-offset="Z 0"]', '-0.01');
  await page.dispatchEvent('[data-offset="Z 0"]', 'change');
  await after_(page, 'results', () => page.click('#generate-error'));
  await page.waitForFunction(() => document.querySelector('#verdict').dataset.sseAfter !== undefined);
  const verdict = await page.textContent('#verdict');
  assert.doesNotMatch(verdict, /amplif|singular/);
  assert.match(verdict, /The correction changes \d+ independent combinations? of the coefficients/);
  const unobservable = await page.textContent('#unobservable');
  assert.match(unobservable, /rad\/rad² on A a2/);
  assert.doesNotMatch(unobservable, /\^/);
  await page.locator('#measured-section').screenshot({ path: path.join(shots, 'words-measured.png') });
  await page.context().close();
});

test('the circular view shows the figures of the circular deviation', async () => {
  const page = await openPage(base, { open: ON_DEMAND });
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save-case')]);
  const t = hobsharp.evaluate(JSON.parse(readFileSync(await download.path(), 'utf8'))).topography;
  const normal = await page.textContent('#figures-before');
  assert.equal(normal, `rms ${fixed(t.rms, 3)} µm · peak-to-valley ${fixed(t.peakToValley, 3)} µm · largest |deviation| ${fixed(t.max, 3)} µm · ` +
    `thickness error ${signed(t.thickness, 3)} µm · sum of squares ${fmt(t.sse, 6)} µm²`);
  await page.check('input[name="view"][value="circular"]');
  const c = gridFigures(t.circular);
  assert.notEqual(fmt(c.sse, 6), fmt(t.sse, 6));
  assert.equal(await page.textContent('#figures-before'),
    `rms ${fixed(c.rms, 3)} µm · peak-to-valley ${fixed(c.peakToValley, 3)} µm · largest |deviation| ${fixed(c.max, 3)} µm · ` +
    `thickness error ${signed(t.thickness, 3)} µm · sum of squares ${fmt(c.sse, 6)} µm²`);
  await page.context().close();
});
