// The axes to run in the control's units (issue 11, item 4): the proposal's coefficients as the NC
// program carries them (issue 20, item 6: 10 significant digits) in mm and degrees per degree of
// hob rotation, the face predicted with them and the floor the position resolution sets (units
// from the module's result fields), copied to the clipboard, and the axis positions over the
// motion range as CSV at a chosen step.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { afterResult, base, ON_DEMAND, openPage, shots, useBrowser } from './support.mjs';
import { readHeidenhain, readSinumerik } from '../js/nc-interpreter.mjs';

useBrowser();

test('the axes to run: degrees, the rounded proposal, copied and sampled', async () => {
  const page = await openPage(base, { viewport: { width: 1366, height: 900 }, permissions: ['clipboard-read', 'clipboard-write'], open: [...ON_DEMAND, 'files-menu'] });
  await page.waitForFunction(() => window.hobsharpTimings.results > 0);
  assert.equal(await page.textContent('#machine-axes-source'), '(nominal; no correction)');
  assert.equal(await page.textContent('#machine-axes-figures'), '');
  const a1 = await page.textContent('#machine-coefficients tr[data-axis="A"] td:nth-child(3)');
  assert.match(a1, /^1 deg\/deg$/, 'A turns with the hob, 1 deg per deg');
  // A correction: its rounded proposal is shown.
  await page.fill('[data-offset="B 0"]', '0.0005');
  await page.dispatchEvent('[data-offset="B 0"]', 'change');
  await afterResult(page, () => page.click('#generate-error'));
  assert.equal(await page.textContent('#machine-axes-source'), '(the corrected proposal, as the NC program carries it)');
  const b0 = Number((await page.textContent('#machine-coefficients tr[data-axis="B"] td:nth-child(2)')).split(' ')[0]);
  assert.equal(b0, Number(b0.toPrecision(10)), `B a0 = ${b0} deg has at most 10 significant digits`);
  const figures = await page.textContent('#machine-axes-figures');
  assert.match(figures, /^With these axes the identified machine grinds [\d.e-]+ µm rms \(re-simulated, this measurement's misfit kept; the exact axes leave at most the verdict's bound\)\. The floor the position resolution sets \(each axis position quantised to its step\): 0\.0\d+ µm rms\.$/);
  await page.click('#copy-axes');
  const copied = await page.evaluate(() => navigator.clipboard.readText());
  assert.match(copied, /^X \(mm\) = /);
  assert.match(copied, /\nB \(deg\) = [-\d.e]+ /);
  assert.ok(copied.includes(String(b0)), 'the clipboard holds the values shown');
  // The positions at 2 deg.
  await page.fill('#positions-step', '2');
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-positions')]);
  const lines = readFileSync(await download.path(), 'utf8').trimEnd().split('\n');
  assert.equal(lines[0], '\uFEFFhob rotation (deg),X (mm),Y (mm),Z (mm),A (deg),B (deg)');
  const rows = lines.slice(1).map((l) => l.split(',').map(Number));
  assert.ok(rows.every((r) => r.length === 6 && r.every(Number.isFinite)));
  assert.ok(Math.abs(rows[1][0] - rows[0][0] - 2) < 1e-9);
  assert.match(await page.textContent('#positions-note'), new RegExp(`^${rows.length} positions\\.$`));
  const off = Math.max(...rows.map((r) => Math.abs(r[4] - r[0])));
  assert.ok(off < 0.01, `A follows the hob rotation (off by at most ${off} deg)`);
  // A bad step is said at the button, nothing downloaded.
  await page.fill('#positions-step', '0');
  await page.click('#download-positions');
  assert.match(await page.textContent('#positions-note'), /^Step: must be a positive number of degrees; got 0\.$/);
  // The positions with decimal commas, when the page's CSV style says so.
  await page.fill('#positions-step', '2');
  await page.selectOption('#csv-style', 'semicolon');
  const [semicolon] = await Promise.all([page.waitForEvent('download'), page.click('#download-positions')]);
  const german = readFileSync(await semicolon.path(), 'utf8').split('\n');
  assert.equal(german[0], '\uFEFFhob rotation (deg);X (mm);Y (mm);Z (mm);A (deg);B (deg)');
  assert.match(german[1], /^-?\d+,\d{6}(;-?\d+,\d{6}){5}$/);
  await page.selectOption('#csv-style', 'comma');
  // The NC program of the axes shown (issue 22): its blocks and deviation beside the buttons,
  // copied for a Sinumerik, downloaded for a HEIDENHAIN, both read back by the tests' interpreter.
  assert.match(await page.textContent('#nc-note'), /^1 POLY block of degree 5 at most; largest deviation from the axes [\d.e-]+ µm \(X, Y, Z\), [\d.e-]+° \(A, B\)\.$/);
  await page.click('#copy-nc');
  const program = await page.evaluate(() => navigator.clipboard.readText());
  assert.match(program, /^; HobSharp NC program: Siemens SINUMERIK 840D sl/);
  assert.match(program, /\n; Axes: the corrected proposal, as the NC program carries it\n/);
  assert.match(program, /\nN10 G90 G1 X-?[\d.]+ Y-?[\d.]+ Z-?[\d.]+ A-?[\d.]+ B-?[\d.]+\nN20 POLY X=PO\(/);
  const sinumerik = readSinumerik(program);
  assert.equal(sinumerik.segments.length, 1);
  assert.match(await page.textContent('#status'), /NC program \(HOBSHARP_M7_\d{8}\.mpf\) is on the clipboard/);
  await page.selectOption('#nc-dialect', 'heidenhain');
  assert.match(await page.textContent('#nc-note'), /^\d+ SPL blocks? of degree 3 at most; largest deviation from the axes 0\.0\d+ µm \(X, Y, Z\), [\d.e-]+° \(A, B\)\.$/);
  const [nc] = await Promise.all([page.waitForEvent('download'), page.click('#download-nc')]);
  assert.match(nc.suggestedFilename(), /^HOBSHARP_M7_\d{8}\.h$/);
  const tnc = readHeidenhain(readFileSync(await nc.path(), 'utf8'));
  assert.ok(tnc.blocks.length >= 1);
  assert.ok(Math.abs(tnc.start.B - b0) < 0.05, `the program starts B near its a0 (${tnc.start.B} deg, ${b0} deg)`);
  await page.locator('#machine-axes').screenshot({ path: path.join(shots, 'machine-axes.png') });
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
