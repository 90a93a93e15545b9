// The page's part of ./hobsharp.sh bench: how long after opening the page shows the paper
// example's first result (Tab. 2), in Debian's headless Chromium, cold (a new browser context each
// time), served by python3 on localhost. Target: within 1 s.
import { spawn } from 'node:child_process';
import net from 'node:net';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const root = path.join(path.dirname(fileURLToPath(import.meta.url)), '..');
const site = process.env.HOBSHARP_SITE || path.join(root, 'build', 'wasm', 'site');
const runs = 7;

const port = await new Promise((resolve) => {
  const s = net.createServer().listen(0, '127.0.0.1', () => { const { port: p } = s.address(); s.close(() => resolve(p)); });
});
const server = spawn('/usr/bin/python3', ['-m', 'http.server', String(port), '--bind', '127.0.0.1', '--directory', site], { stdio: 'ignore' });
const url = `http://127.0.0.1:${port}/`;
for (let i = 0; i < 100; i++) {
  try { if ((await fetch(url)).ok) break; } catch { await new Promise((r) => setTimeout(r, 100)); }
}
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update'],
});
const first = [], plotted = [];
try {
  for (let i = 0; i < runs; i++) {
    const context = await browser.newContext();
    const page = await context.newPage();
    await page.goto(url);
    await page.waitForFunction(() => window.hobsharpTimings && window.hobsharpTimings.draws > 0, null, { timeout: 60000 });
    const t = await page.evaluate(() => window.hobsharpTimings);
    first.push(t.firstResult);
    plotted.push(t.plotted);
    await context.close();
  }
} finally {
  await browser.close();
  server.kill();
}
const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
console.log(`\nthe page, ${runs} cold opens in headless Chromium (ms after navigation):`);
console.log(`  first result (Tab. 2 on screen): median ${median(first).toFixed(0)}, best ${Math.min(...first).toFixed(0)}, worst ${Math.max(...first).toFixed(0)}  (target < 1000)`);
console.log(`  first plots drawn:               median ${median(plotted).toFixed(0)}, best ${Math.min(...plotted).toFixed(0)}, worst ${Math.max(...plotted).toFixed(0)}`);
