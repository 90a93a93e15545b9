// The plots (Plotly only): the bundle's trace types, and what an engineer tripped on (issue 9,
// item 6): the axis plot shows the correction in µm and arc-seconds, measured and corrected share
// one colour scale that says which colour is excess material, legends keep clear of axis titles,
// the red singular values are explained, and the 3D surfaces keep their titles and name their
// hover values. At 1366 x 768, as the engineer saw it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { after_, frames, ON_DEMAND, openPage, plotted, shots, useBrowser } from './support.mjs';
import { surfacesDrawn } from './surfaces.mjs';

useBrowser();
const viewport = { width: 1366, height: 768 };
const ARCSEC_PER_RAD = (180 / Math.PI) * 3600;

// A measured grid (µm) that the correction mostly takes away: tilted, curved.
async function correct(page) {
  const grid = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (_, j) => (0.5 * i - 0.2 * j + 0.1 * i * j).toFixed(2)).join(', '));
  await page.fill('#measured-csv', grid.join('\n'));
  await after_(page, 'draws', () => page.click('#use-measured'));
}

const overlap = (a, b) => a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
const box = (page, selector) => page.locator(selector).boundingBox();

// The surface trace is in the bundle but registered only when the first 3D surface is drawn.
test('the plot bundle registers the heatmap, bar and scatter traces, the surface on demand, and each plot uses its own', async () => {
  const page = await openPage(undefined, { viewport, open: ON_DEMAND });
  await plotted(page);
  const traces = () => page.evaluate(() => Object.keys(window.Plotly.PlotSchema.get().traces).sort());
  assert.deepEqual(await traces(), ['bar', 'heatmap', 'scatter']);
  await page.evaluate(() => window.plotlySurface());
  assert.deepEqual(await traces(), ['bar', 'heatmap', 'scatter', 'surface']);
  const types = await page.evaluate(() => Object.fromEntries(['plot-axes', 'plot-wheel', 'plot-before-2d', 'gallery']
    .map((id) => [id, [...new Set(document.getElementById(id)._fullData.map((t) => t.type))]])));
  assert.deepEqual(types, { 'plot-axes': ['scatter'], 'plot-wheel': ['scatter'], 'plot-before-2d': ['heatmap'], gallery: ['heatmap'] });
  assert.equal(await page.evaluate(() => document.getElementById('gallery')._fullData.length), 25);
  // Without a correction the axis plot shows the nominal motions in the axes' own units (limits().axes).
  assert.deepEqual(await page.evaluate(() => { const l = document.getElementById('plot-axes').layout; return [l.yaxis.title.text, l.yaxis2.title.text]; }),
    ['X, Y, Z (mm)', 'A, B (rad)']);
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('with a correction: the axis plot shows corrected − nominal in µm and arc-seconds, clear of its legend', async () => {
  const page = await openPage(undefined, { viewport, open: ON_DEMAND });
  await plotted(page);
  await correct(page);
  const plot = await page.evaluate(() => {
    const gd = document.getElementById('plot-axes');
    return { data: gd.data.map((t) => ({ name: t.name, x: t.x, y: t.y })), y: gd.layout.yaxis.title.text, y2: gd.layout.yaxis2.title.text };
  });
  assert.match(plot.y, /µm/);
  assert.match(plot.y2, /arc-seconds/);
  // The coefficients table (9 significant digits) gives the expected difference at every point.
  const coefficient = async (set, a, k) => Number((await page.textContent(`[data-coef="${set} ${a} ${k}"]`)).replace('−', '-'));
  for (const a of ['X', 'Y', 'Z', 'A', 'B']) {
    const trace = plot.data.find((t) => t.name.includes(a));
    assert.ok(trace, `a trace for ${a}`);
    const [scale, tolerance] = ['A', 'B'].includes(a) ? [ARCSEC_PER_RAD, 0.01] : [1000, 0.01];
    const change = [];
    for (let k = 0; k <= 4; k++) change.push((await coefficient('corrected', a, k)) - (await coefficient('nominal', a, k)));
    trace.x.forEach((t, i) => {
      const expected = scale * change.reduceRight((acc, c) => acc * t + c, 0);
      assert.ok(Math.abs(trace.y[i] - expected) < tolerance, `${a} at ${t}: ${trace.y[i]} against ${expected}`);
    });
  }
  const largest = Math.max(...plot.data.filter((t) => /[XYZ]/.test(t.name)).flatMap((t) => t.y.map(Math.abs)));
  assert.ok(largest > 0.5 && largest < 1000, `the slides' correction is µm-sized on the plot: ${largest}`);
  // The legend keeps clear of the x-axis title, the y-axis titles, the title and the curves.
  const legend = await box(page, '#plot-axes .legend');
  for (const other of ['.g-xtitle', '.g-ytitle', '.g-y2title', '.g-gtitle', '.nsewdrag']) {
    assert.ok(!overlap(legend, await box(page, `#plot-axes ${other}`)), `the legend overlaps ${other}`);
  }
  await page.locator('#axes-section').screenshot({ path: path.join(shots, 'axes-correction.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('with a correction: the maps share one colour scale that says blue is excess material; the red singular values are explained', async () => {
  const page = await openPage(undefined, { viewport, open: ON_DEMAND });
  await plotted(page);
  await correct(page);
  const maps = await page.evaluate(() => ['plot-before-2d', 'plot-after-2d'].map((id) => {
    const t = document.getElementById(id)._fullData[0];
    const scale = t.colorscale;
    return { zmin: t.zmin, zmax: t.zmax, largest: Math.max(...t.z.flat().map(Math.abs)), top: scale[scale.length - 1][1],
             bar: document.querySelector(`#${id} .cbtitle`).textContent };
  }));
  assert.equal(maps[0].zmax, maps[1].zmax, 'one range');
  assert.equal(maps[0].zmin, maps[1].zmin, 'one range');
  assert.equal(maps[0].zmin, -maps[0].zmax);
  assert.ok(maps[0].zmax >= Math.max(maps[0].largest, maps[1].largest));
  for (const m of maps) {
    assert.match(m.bar, /blue: excess\s*material/);
    const [r, , b] = m.top.match(/\d+/g).map(Number);
    assert.ok(b > 2 * r, `the positive end (excess) is blue: ${m.top}`);
  }
  const singular = await page.evaluate(() => document.getElementById('plot-singular').data.map((t) => ({ name: t.name, colour: t.marker.color, n: t.x.length })));
  const red = singular.find((t) => t.colour === '#c53030');
  assert.ok(red && red.n > 0, 'some singular values are left out (red)');
  assert.match(red.name, /left out/);
  // The title counts the blue bars: the directions used, which need not be the largest.
  const blue = singular.find((t) => t.colour === '#2b6cb0');
  const title = await page.evaluate(() => document.getElementById('plot-singular').layout.title.text);
  assert.equal(Number(/\((\d+) used\)/.exec(title)[1]), blue.n, title);
  const legend = (await page.locator('#plot-singular .legendtext').allTextContents()).join(' | ');
  assert.match(legend, /used in the correction \| left out/);
  const box_ = await box(page, '#plot-singular .legend');
  for (const other of ['.g-xtitle', '.g-ytitle', '.g-gtitle', '.nsewdrag']) {
    assert.ok(!overlap(box_, await box(page, `#plot-singular ${other}`)), `the legend overlaps ${other}`);
  }
  await page.locator('#topography-section').screenshot({ path: path.join(shots, 'maps-shared-scale.png') });
  await page.locator('#plot-singular').screenshot({ path: path.join(shots, 'singular-values.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});

test('the 3D surfaces: drawn on demand, one scale, titles inside the plot, hover with names and units', async () => {
  const page = await openPage(undefined, { viewport, open: ON_DEMAND });
  await plotted(page);
  assert.equal(await page.isVisible('#plot-before-3d'), false, 'the maps come alone by default');
  await correct(page);
  await surfacesDrawn(page, ['#plot-before-3d', '#plot-after-3d']);
  const ranges = await page.evaluate(() => ['plot-before-3d', 'plot-after-3d'].map((id) => {
    const gd = document.getElementById(id);
    return [gd._fullData[0].cmin, gd._fullData[0].cmax, ...gd._fullLayout.scene.zaxis.range];
  }));
  // Plotly may carry a z range given as ±3.6 as ±3.6000000000000005 for one surface: equal to 1e-12.
  ranges[0].forEach((v, i) => assert.ok(Math.abs(v - ranges[1][i]) <= 1e-12 * Math.abs(v), `measured and after correction share the colour and z ranges: ${ranges}`));
  const titles = await page.evaluate(() => ['xaxis', 'yaxis', 'zaxis'].map((a) => document.getElementById('plot-before-3d')._fullLayout.scene[a].title.text));
  assert.deepEqual(titles, ['x along the gash (mm)', 'r root to tip (mm)', 'deviation (µm)']);
  // No spike or zero lines standing out of the surface; the title on the left, where the mode bar is not.
  const [spikes, titleX] = await page.evaluate(() => {
    const l = document.getElementById('plot-before-3d')._fullLayout;
    return [['xaxis', 'yaxis', 'zaxis'].map((a) => l.scene[a].showspikes || l.scene[a].zeroline), l.title.x];
  });
  assert.deepEqual(spikes, [false, false, false]);
  assert.ok(titleX < 0.1, `the 3D title starts at the left (x ${titleX})`);
  // The pointer over the surface: the hover label names r, x and the deviation, with units.
  await page.locator('#plot-before-3d').scrollIntoViewIfNeeded();
  const scene = await page.locator('#plot-before-3d').boundingBox();
  let text = '';
  for (let y = 0.4; y < 0.9 && !text; y += 0.05) {
    for (let x = 0.2; x < 0.8 && !text; x += 0.05) {
      await page.mouse.move(scene.x + scene.width * x, scene.y + scene.height * y);
      await frames(page);  // the scene draws its hover label on its next frame
      text = (await page.locator('#plot-before-3d .hovertext').allTextContents()).join('');
    }
  }
  assert.match(text, /^r = \d+\.\d\d mm\s*x = -?\d+\.\d\d mm\s*deviation -?\d+\.\d{3} µm$/);
  await page.locator('#topography-section').screenshot({ path: path.join(shots, 'topography-3d.png') });
  // The link keeps what the page shows: the surfaces, and the circular deviation once chosen.
  await after_(page, 'draws', () => page.check('input[name="view"][value="circular"]'));
  const linkPage = () => JSON.parse(decodeURIComponent(page.url().split('#case=')[1])).page;
  assert.deepEqual(linkPage(), { view: 'circular', surfaces: true });
  const linked = await openPage(page.url(), { viewport, open: ON_DEMAND });
  await plotted(linked);
  await linked.waitForFunction(() => !document.getElementById('plot-before-3d').hidden);
  assert.equal(await linked.isChecked('#show-3d'), true, 'the link opens with the 3D surfaces');
  assert.equal(await linked.isChecked('input[name="view"][value="circular"]'), true, 'and the circular deviation');
  assert.equal(await linked.textContent('#figures-before'), await page.textContent('#figures-before'), 'the circular figures');
  assert.deepEqual(linked.problems, []);
  await linked.context().close();
  await page.check('input[name="view"][value="normal"]');
  await page.uncheck('#show-3d');
  assert.equal(await page.isVisible('#plot-before-3d'), false);
  assert.equal(linkPage(), undefined, 'the defaults: no page member');
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
