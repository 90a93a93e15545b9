// The validation campaign's plot (docs/validation.md): from a validation.json, one empirical
// distribution function per scenario class of the face left between the probe points (µm rms, log
// axis from 1e-4 to 1e3), the targets' limits as dashed lines with the share each asks for, the
// class titles in the legend and the seed and scenario count in the title. Written beside the
// JSON as validation.png (and validation.svg with --svg).
//
//   node tests/validation/plot.mjs [validation.json | its folder] [--svg]
//
// Drawn by the project's own Plotly (node_modules/plotly.js/dist, read from disk; every network
// request is refused) in Debian's Chromium through playwright-core, launched as the browser tests
// launch it (tests/browser/support.mjs). figure() is pure and tested without a browser.
import { existsSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const require = createRequire(import.meta.url);
export const PLOTLY = require.resolve('plotly.js/dist/plotly-basic.min.js');
export const CHROMIUM = {
  executablePath: '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update'],
};

// The x axis, µm rms: values outside are drawn at its edge (and the legend says how many).
export const X_RANGE = [1e-4, 1e3];
export const SIZE = { width: 1100, height: 980, scale: 1.5 };
// Okabe and Ito's colours, told apart with any colour vision.
const COLOURS = ['#0072b2', '#e69f00', '#009e73', '#cc79a7', '#d55e00', '#56b4e9', '#000000', '#f0e442'];
const GREY = '#555555';
// The limits of the targets when a validation.json does not carry them (before each class's
// target had its "limit"): 0.35 µm for the noisy class, 0.1 µm for every other.
const DEFAULT_LIMIT = { noisy: 0.35 };

// Whole percent, rounded down as the table writes it (campaign.cpp): 89.6 % of 90 % never reads as 90 %.
const percent = (share) => `${Math.floor(100 * share + 1e-9)} %`;
const micrometres = (v) => `${Number(v.toPrecision(3))} µm`;

// The class's target the plot draws: its first (the face left, not the rounded axes'), with its
// limit (µm rms) and the share it asks for.
export function targetOf(k) {
  const t = (k.targets || [])[0] || {};
  const limit = Number.isFinite(t.limit) && t.limit > 0 ? t.limit : DEFAULT_LIMIT[k.class] || 0.1;
  return { limit, required: Number.isFinite(t.required) ? t.required : null, share: Number.isFinite(t.share) ? t.share : null };
}

// The empirical distribution function of `finals` as a step line: {x, y, below, above, dropped}
// with x clamped to X_RANGE (below / above: how many were moved to its edges) and the values that
// are not finite numbers dropped (counted).
export function ecdf(finals) {
  const values = (finals || []).filter((v) => typeof v === 'number' && Number.isFinite(v)).sort((a, b) => a - b);
  const n = values.length;
  const [lo, hi] = X_RANGE;
  const x = [lo], y = [0];
  values.forEach((v, i) => { x.push(Math.min(hi, Math.max(lo, v))); y.push((i + 1) / n); });
  x.push(hi); y.push(n ? 1 : 0);
  return { x, y, n, below: values.filter((v) => v < lo).length, above: values.filter((v) => v > hi).length,
           dropped: (finals || []).length - n };
}

// {data, layout} of the plot for a parsed validation.json.
export function figure(json) {
  if (!json || !Array.isArray(json.classes) || !json.classes.length) throw new Error('the file holds no scenario classes');
  const data = [];
  const classes = json.classes.map((k, i) => ({ k, colour: COLOURS[i % COLOURS.length], target: targetOf(k), curve: ecdf(k.finals) }));
  for (const { k, colour, target, curve } of classes) {
    const notes = [];
    if (target.share !== null) notes.push(`${percent(target.share)} within ${micrometres(target.limit)}${target.required !== null ? ` (asked ${percent(target.required)})` : ''}`);
    notes.push(`${curve.n} scenarios`);
    if (k.unjudged) notes.push(`${k.unjudged} not judged`);
    if (curve.dropped) notes.push(`${curve.dropped} not a number`);
    if (curve.below) notes.push(`${curve.below} below ${X_RANGE[0]} µm`);
    if (curve.above) notes.push(`${curve.above} above ${X_RANGE[1]} µm`);
    data.push({
      type: 'scatter', mode: 'lines', x: curve.x, y: curve.y, line: { shape: 'hv', color: colour, width: 2.2 },
      name: `${k.title || k.class}: ${notes.join(', ')}`, legendgroup: k.class,
    });
  }
  // One dashed line per limit, in its class's colour when it is one class's alone; then the shares
  // the targets ask for at each limit: a class meets its target when its curve passes through or
  // above its mark.
  const limits = [...new Set(classes.map((c) => c.target.limit))].sort((a, b) => a - b);
  const groups = limits.map((limit) => {
    const of = classes.filter((c) => c.target.limit === limit);
    return { limit, of, colour: of.length === 1 ? of[0].colour : GREY };
  });
  for (const { limit, of, colour } of groups) {
    const whose = of.length === 1 ? of[0].k.title || of[0].k.class : `${of.length} classes`;
    data.push({
      type: 'scatter', mode: 'lines', x: [limit, limit], y: [0, 1], line: { color: colour, dash: 'dash', width: 1.5 },
      name: `target: at most ${micrometres(limit)} rms (${whose})`, hoverinfo: 'skip',
    });
  }
  let shown = false;
  for (const { limit, of, colour } of groups) {
    const asked = [...new Set(of.map((c) => c.target.required).filter((r) => r !== null))];
    if (!asked.length) continue;
    data.push({
      type: 'scatter', mode: 'markers+text', x: asked.map(() => limit), y: asked, text: asked.map(percent),
      textposition: 'middle left', textfont: { color: colour, size: 12 },
      marker: { symbol: 'line-ew-open', size: 16, color: colour, line: { width: 2, color: colour } },
      name: 'the share the target asks for at its limit', showlegend: !shown, legendgroup: 'asked', hoverinfo: 'skip',
    });
    shown = true;
  }
  const seconds = Number.isFinite(json.seconds) ? `, ${Math.round(json.seconds)} s` : '';
  const layout = {
    width: SIZE.width, height: SIZE.height, font: { family: 'DejaVu Sans, Liberation Sans, sans-serif', size: 13 },
    title: {
      text: `HobSharp validation campaign: seed ${json.seed}, ${json.scenarios} scenarios${seconds}<br>` +
            '<span style="font-size:13px">the face left between the probe points (a grid 4 times as dense) after each class\'s passes</span>',
      x: 0.5, xanchor: 'center',
    },
    margin: { t: 80, r: 30, b: 70, l: 75 },
    xaxis: {
      type: 'log', range: X_RANGE.map(Math.log10), title: { text: 'face rms left between the probe points (µm)' },
      exponentformat: 'power', dtick: 1, showgrid: true, gridcolor: '#e4e4e4', zeroline: false, showline: true, linecolor: '#444', mirror: true,
    },
    yaxis: {
      range: [0, 1.02], title: { text: 'share of scenarios' }, dtick: 0.1, showgrid: true, gridcolor: '#e4e4e4', zeroline: false,
      showline: true, linecolor: '#444', mirror: true,
    },
    // Under the plot: the class titles are long, and the curves fill the plot's width.
    legend: { orientation: 'v', x: 0, xanchor: 'left', y: -0.12, yanchor: 'top', font: { size: 12 } },
    showlegend: true, plot_bgcolor: 'white', paper_bgcolor: 'white',
  };
  return { data, layout };
}

// Renders the figure of `json` to PNG (and SVG) files.
export async function render(json, { png, svg } = {}) {
  const { chromium } = await import('playwright-core');
  const { data, layout } = figure(json);
  const browser = await chromium.launch(CHROMIUM);
  try {
    const page = await browser.newPage({ viewport: { width: SIZE.width, height: SIZE.height } });
    await page.route('**/*', (route) => route.abort());  // nothing from the network
    const problems = [];
    page.on('pageerror', (e) => problems.push(e.message));
    await page.setContent('<!doctype html><meta charset="utf-8"><body style="margin:0"><div id="plot"></div></body>');
    await page.addScriptTag({ path: PLOTLY });
    const images = await page.evaluate(async ([data, layout, size, withSvg]) => {
      const gd = document.getElementById('plot');
      await self.Plotly.newPlot(gd, data, layout, { staticPlot: true });
      const options = { width: size.width, height: size.height };
      return {
        png: await self.Plotly.toImage(gd, { ...options, format: 'png', scale: size.scale }),
        svg: withSvg ? await self.Plotly.toImage(gd, { ...options, format: 'svg' }) : null,
      };
    }, [data, layout, SIZE, Boolean(svg)]);
    if (problems.length) throw new Error(`the plot failed in the browser: ${problems.join('; ')}`);
    const pngPrefix = 'data:image/png;base64,';
    if (!images.png.startsWith(pngPrefix)) throw new Error('Plotly gave no PNG');
    writeFileSync(png, Buffer.from(images.png.slice(pngPrefix.length), 'base64'));
    if (svg) writeFileSync(svg, decodeURIComponent(images.svg.replace(/^data:image\/svg\+xml,/, '')));
  } finally {
    await browser.close();
  }
}

async function main(argv) {
  const svg = argv.includes('--svg');
  const rest = argv.filter((a) => a !== '--svg');
  if (rest.length > 1 || rest.some((a) => a.startsWith('-'))) {
    console.error('usage: node tests/validation/plot.mjs [validation.json | its folder] [--svg]');
    return 2;
  }
  let file = rest[0] || path.join('build', 'validation', 'validation.json');
  if (existsSync(file) && statSync(file).isDirectory()) file = path.join(file, 'validation.json');
  let json;
  try {
    json = JSON.parse(readFileSync(file, 'utf8'));
  } catch (e) {
    console.error(`plot: cannot read ${file}: ${e.message}`);
    return 1;
  }
  const dir = path.dirname(file);
  const out = { png: path.join(dir, 'validation.png'), svg: svg ? path.join(dir, 'validation.svg') : null };
  try {
    await render(json, out);
  } catch (e) {
    console.error(`plot: ${file}: ${e.message}`);
    return 1;
  }
  console.log(`Written: ${[out.png, out.svg].filter(Boolean).join(', ')}`);
  return 0;
}

if (process.argv[1] && pathToFileURL(path.resolve(process.argv[1])).href === import.meta.url) {
  process.exitCode = await main(process.argv.slice(2));
}
