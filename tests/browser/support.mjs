// What the browser tests share: the page in Debian's Chromium, driven by playwright-core, served
// on localhost by python3; the store's hooks to wait on; a check that a plot draws something.
// Screenshots go to test-output/browser/.
import { before, after } from 'node:test';
import { spawn } from 'node:child_process';
import { mkdirSync, readFileSync } from 'node:fs';
import net from 'node:net';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

export const root = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const site = process.env.HOBSHARP_SITE || path.join(root, 'build', 'wasm', 'site');
export const shots = path.join(root, 'test-output', 'browser');
// A case file of tests/data/ as the page's file input takes it.
export const dataCase = (name) => ({ name, mimeType: 'application/json', buffer: readFileSync(path.join(root, 'tests', 'data', name)) });
mkdirSync(shots, { recursive: true });

let server, browser;
export let base;

function freePort() {
  return new Promise((resolve) => {
    const s = net.createServer().listen(0, '127.0.0.1', () => { const { port } = s.address(); s.close(() => resolve(port)); });
  });
}

// Resolves when python's server says it listens ("Serving HTTP on ..." on its unbuffered stdout).
function listening(child) {
  return new Promise((resolve, reject) => {
    let said = '';
    child.stdout.on('data', (d) => { said += d; if (said.includes('Serving HTTP')) resolve(); });
    child.on('exit', (code) => reject(new Error(`the test server ended (exit ${code}) before it listened: ${said}`)));
  });
}

// Starts the server and the browser for the test file that calls it.
export function useBrowser() {
  before(async () => {
    const port = await freePort();
    server = spawn('/usr/bin/python3', ['-u', '-m', 'http.server', String(port), '--bind', '127.0.0.1', '--directory', site],
                   { stdio: ['ignore', 'pipe', 'ignore'] });
    base = `http://127.0.0.1:${port}/`;
    await listening(server);
    browser = await chromium.launch({
      executablePath: '/usr/bin/chromium',
      args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update'],
    });
  });

  after(async () => {
    if (browser) await browser.close();
    if (server) server.kill();
  });
}

// The parts of the page kept on demand (issue 23: closed <details>): every one, for a test of what
// they hold, as a user opens them. (The header's menu, "Report and files…", is opened by the tests
// that use it: open, it lies over the top of the results.)
export const ON_DEMAND = ['machine-grid-details', 'what-if-details', 'correction-options-details', 'lock-coefficients',
  'identification-details', 'inspection-details', 'wheel-details', 'axes-details', 'sensitivity-details'];

// A page at url, in a context of its own, not waiting for anything: prepare(context), if given,
// runs before the page opens (to route a request, say); open: the ids of the parts on demand to
// open as the page loads (before its first result, so that its plots are drawn as it opens).
export async function openBare(url = base, { viewport = { width: 1500, height: 1100 }, permissions = [], prepare, open = [] } = {}) {
  const context = await browser.newContext({ viewport, acceptDownloads: true, permissions });
  if (prepare) await prepare(context);
  if (open.length) {
    await context.addInitScript((ids) => document.addEventListener('DOMContentLoaded', () => {
      for (const id of ids) document.getElementById(id).open = true;
    }), open);
  }
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(e.message));
  page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
  page.problems = problems;
  await page.goto(url);
  return page;
}

// The calculator's page, once it has shown its first result.
export async function openPage(url = base, options = {}) {
  const page = await openBare(url, options);
  await page.waitForFunction(() => window.hobsharpTimings && window.hobsharpTimings.results > 0, null, { timeout: 20000 });
  return page;
}

// Opens parts on demand of a page already open (their plots drawn as they open: plots/passes.js).
export async function openParts(page, ...ids) {
  await page.evaluate((list) => { for (const id of list) document.getElementById(id).open = true; }, ids);
}

export const count = (page, what) => page.evaluate((w) => window.hobsharpTimings[w], what);

// Waits for the next result (or refusal) after `action`.
export async function after_(page, what, action) {
  const n = await count(page, what);
  await action();
  await page.waitForFunction(([w, k]) => window.hobsharpTimings[w] > k, [what, n], { timeout: 20000 });
}
export const afterResult = (page, action) => after_(page, 'results', action);
export const afterError = (page, action) => after_(page, 'errors', action);

// Waits until the page has settled: nothing computed or waiting to be, no plot pass under way,
// for two frames (web/src/hooks.js).
export const settled = (page) => page.evaluate(() => window.hobsharpTest.settled());

// Two animation frames: what the browser draws on its own after an event (a WebGL hover label).
export const frames = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

export async function plotted(page) {
  await page.waitForFunction(() => window.hobsharpTimings.draws > 0, null, { timeout: 30000 });
  await settled(page);
}

// Decodes a PNG in the page and, for each box (CSS px from the image's top left; the whole image
// if none), tells how many distinct colours it shows, the share of its pixels that are not white
// (inked) and how many pixels of its outer `border` px are not white (something cut off there).
async function stats(page, png, boxes, border) {
  return page.evaluate(async ([b64, boxes, border]) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const g = c.getContext('2d', { willReadFrequently: true });
    g.drawImage(img, 0, 0);
    return (boxes || [{ x: 0, y: 0, width: img.width, height: img.height }]).map((b) => {
      const [x0, y0] = [Math.max(0, Math.round(b.x)), Math.max(0, Math.round(b.y))];
      const [w, h] = [Math.min(img.width - x0, Math.round(b.width)), Math.min(img.height - y0, Math.round(b.height))];
      const d = g.getImageData(x0, y0, w, h).data;
      const seen = new Set();
      let inked = 0, edge = 0;
      for (let i = 0; i < d.length; i += 4) {
        seen.add((d[i] << 16) | (d[i + 1] << 8) | d[i + 2]);
        const ink = d[i] < 245 || d[i + 1] < 245 || d[i + 2] < 245;
        const p = i / 4, x = p % w, y = Math.floor(p / w);
        if (ink) inked += 1;
        if (ink && (x < border || y < border || x >= w - border || y >= h - border)) edge += 1;
      }
      return { colours: seen.size, inked: inked / (w * h), edge };
    });
  }, [png.toString('base64'), boxes, border]);
}

// The same figures for a whole PNG (a printed page rendered): {colours, inked, edge}.
export async function pngStats(page, png) {
  const [s] = await stats(page, png, null, 0);
  return s;
}

// The same figures for boxes of a PNG (px from its top left): [{colours, inked, edge}].
export const pngRegions = (page, png, boxes, border = 0) => stats(page, png, boxes, border);

// How many distinct colours a rendered element shows: a plot that draws nothing has a handful.
export async function colours(page, selector) {
  const [s] = await stats(page, await page.locator(selector).screenshot(), null, 0);
  return s.colours;
}

// The same for boxes within an element (relative to its top left).
export async function regions(page, selector, boxes, border = 0) {
  return stats(page, await page.locator(selector).screenshot(), boxes, border);
}

// Every heatmap of the sensitivity gallery (one Plotly figure) drawn: 25 images, each filled.
export async function galleryDrawn(page) {
  const boxes = await page.evaluate(() => {
    const at = document.querySelector('#gallery').getBoundingClientRect();
    return [...document.querySelectorAll('#gallery .hm image')].map((e) => {
      const r = e.getBoundingClientRect();
      return { x: r.x - at.x + 1, y: r.y - at.y + 1, width: r.width - 2, height: r.height - 2 };
    });
  });
  return regions(page, '#gallery', boxes);
}

// The gallery's titles (HTML over the figure): for each map, its title's box and lines, and the
// map's box, in page pixels.
export async function galleryTitles(page) {
  return page.evaluate(() => {
    const box = (e) => { const r = e.getBoundingClientRect(); return { top: r.top, bottom: r.bottom, centre: (r.left + r.right) / 2 }; };
    const maps = [...document.querySelectorAll('#gallery .hm image')].map(box);
    return [...document.querySelectorAll('#gallery-titles div')].map((e, k) => ({
      title: box(e), lines: e.innerText.split('\n'), map: maps[k],
    }));
  });
}

export async function tab2(page, set) {
  const out = {};
  for (const a of ['X', 'Y', 'Z', 'A', 'B']) out[a] = (await page.textContent(`#tab2 td[data-set="${set}"][data-axis="${a}"]`)).trim();
  return out;
}
