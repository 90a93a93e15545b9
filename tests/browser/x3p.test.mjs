// The topography as an ISO 5436-2 X3P file in the page (views/x3p.js, wasm/lib/x3p.js): export the
// measured and the predicted topography, read the measured one back through the preview, and a
// refused file (a wrong MD5, garbage, an XML bomb, a zip without main.xml, another grid) leaves the
// box, the results and the verdict as they were.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { createHash } from 'node:crypto';
import { unzipSync, zipSync, strToU8, strFromU8 } from 'fflate';
import { afterError, afterResult, base, ON_DEMAND, openPage, root, shots, useBrowser } from './support.mjs';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { readX3p, writeX3p } from '../../wasm/lib/x3p.js';

useBrowser();

const paper = JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
const md5 = (bytes) => createHash('md5').update(bytes).digest('hex');
const within1ulp = (a, b, what) => a.forEach((row, j) => row.forEach((v, i) => {
  assert.ok(Math.abs(v - b[j][i]) <= Math.abs(b[j][i]) * 2.3e-16, `${what} row ${j + 1}, column ${i + 1}: ${v} against ${b[j][i]}`);
}));

async function exported(page, kind) {
  await page.selectOption('#x3p-kind', kind);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export-x3p')]);
  assert.match(download.suggestedFilename(), new RegExp(`^hobsharp-${kind}-\\d{4}-\\d\\d-\\d\\d\\.x3p$`));
  return new Uint8Array(readFileSync(await download.path()));
}

test('export the measured and predicted topography as X3P, import the measured one back; a refused file changes nothing', async () => {
  // A face ground with Z 10 µm off, measured: the case the page opens with.
  const hobsharp = await loadHobSharp();
  const axes = hobsharp.evaluate(paper).axes;
  axes.Z[0] += 0.01;
  const measured = hobsharp.evaluate({ ...paper, axes }).topography.normal;
  const withMeasured = { ...paper, measured };
  const expected = hobsharp.evaluate(withMeasured);
  const page = await openPage(`${base}#case=${encodeURIComponent(JSON.stringify(withMeasured))}`, { viewport: { width: 1366, height: 900 }, open: [...ON_DEMAND, 'files-menu'] });
  await page.waitForFunction(() => document.querySelector('#verdict').dataset.sseBefore !== undefined);

  assert.deepEqual(await page.$$eval('#x3p-kind option', (o) => o.map((e) => e.value)), ['measured', 'predicted']);
  const measuredFile = await exported(page, 'measured');
  const readMeasured = readX3p(measuredFile);
  within1ulp(readMeasured.values, measured, 'measured');
  readMeasured.r.forEach((r, j) => assert.ok(Math.abs(r - expected.topography.r[j]) < 1e-9));
  const predicted = readX3p(await exported(page, 'predicted'));
  within1ulp(predicted.values, expected.correction.residual, 'predicted');
  assert.match(predicted.meta.comment, /^normal deviation of the rake face predicted after the correction on the identified machine/);
  assert.match(predicted.meta.comment, new RegExp(`The pass leaves at most ${Number(expected.correction.predictedRmsHigh.toPrecision(3))} µm rms on the probe grid \\(the bound\\)`), 'the file carries the bound');
  const sseBefore = Number(await page.getAttribute('#verdict', 'data-sse-before'));

  // Without a measurement the page offers the simulated face.
  await afterResult(page, () => page.click('#clear-measured'));
  assert.deepEqual(await page.$$eval('#x3p-kind option', (o) => o.map((e) => e.value)), ['simulated']);
  within1ulp(readX3p(await exported(page, 'simulated')).values, hobsharp.evaluate(paper).topography.normal, 'simulated');

  // Import the measured X3P: it goes through the CSV box and the preview, and is used.
  await afterResult(page, () => page.setInputFiles('#measured-x3p-file', { name: 'face.x3p', mimeType: 'application/octet-stream', buffer: Buffer.from(measuredFile) }));
  assert.match(await page.inputValue('#measured-csv'), /^r \\ x,-?\d/);
  assert.equal(await page.isHidden('#measured-preview'), false);
  assert.equal(await page.textContent('#measured-read'),
    'Read 5 × 9 values, with a header row of 9 x positions (mm), a first column of 5 r positions (mm). Preview (µm, as it would be used):');
  assert.equal(await page.isHidden('#measured-error'), true);
  assert.equal(await page.textContent('#x3p-read'), 'Read face.x3p: an X3P surface of 9 × 5 points (float64), from HobSharp hob sharpening calculator; its lines are the grid\'s.');
  const sseAgain = Number(await page.getAttribute('#verdict', 'data-sse-before'));
  assert.ok(Math.abs(sseAgain - sseBefore) <= 1e-9 * sseBefore, `the imported grid gives the same sum of squares: ${sseAgain} against ${sseBefore}`);
  await page.locator('#measured-section .pair > div:first-child').screenshot({ path: path.join(shots, 'x3p-imported.png') });

  // Refused files: each names the file and what is wrong, and nothing on the page changes.
  const f = unzipSync(measuredFile);
  const bomb = strToU8(strFromU8(f['main.xml']).replace('<p:ISO5436_2', '<!DOCTYPE x [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;">]>\n<p:ISO5436_2'));
  const otherGrid = writeX3p({ r: [10, 20, 30], x: [-5, 0, 5], values: [[0, 0, 0], [1, 1, 1], [2, 2, 2]], kind: 'measured' });
  const garbage = Buffer.alloc(3 * 1024 * 1024, 'garbage ');
  const refusals = [
    ['wrong-md5.x3p', zipSync({ ...f, 'md5checksum.hex': strToU8(`${'0'.repeat(32)} *main.xml\n`) }), /^wrong-md5\.x3p is refused: md5checksum\.hex: says 0{32}, but main\.xml's MD5 is [0-9a-f]{32}/],
    ['garbage.x3p', garbage, /^garbage\.x3p is refused: The file is not an X3P container/],
    ['bomb.x3p', zipSync({ ...f, 'main.xml': bomb, 'md5checksum.hex': strToU8(`${md5(bomb)} *main.xml`) }), /^bomb\.x3p is refused: main\.xml, line 2: a <!DOCTYPE> declaration/],
    ['no-main.x3p', zipSync({ 'bindata/data.bin': f['bindata/data.bin'] }), /^no-main\.x3p is refused: The X3P container holds no main\.xml/],
    ['other-grid.x3p', otherGrid, /^other-grid\.x3p is refused: main\.xml, Record3\/MatrixDimension\/SizeY: 3 radial lines, but the grid has 5\./],
  ];
  const before = {
    box: await page.inputValue('#measured-csv'),
    tab2: await page.textContent('#tab2'),
    figures: await page.textContent('#figures-after'),
    inspection: await page.textContent('#inspection-table'),
    sse: await page.getAttribute('#verdict', 'data-sse-before'),
  };
  for (const [name, bytes, message] of refusals) {
    await afterError(page, () => page.setInputFiles('#measured-x3p-file', { name, mimeType: 'application/octet-stream', buffer: Buffer.from(bytes) }));
    assert.match(await page.textContent('#measured-error'), message);
    // The status says what stays in use, as a refused CSV file's does (not "Measurement not used").
    // The X3P file imported before is named as what stays in use, not "the grid in the box".
    assert.match(await page.textContent('#status'), new RegExp(`^${name.replace('.', '\\.')} is refused \\(face\\.x3p stays in use\\): `));
    assert.equal(await page.isHidden('#measured-error'), false);
    assert.equal(await page.inputValue('#measured-csv'), before.box, `${name}: the box is as it was`);
    assert.equal(await page.textContent('#tab2'), before.tab2, `${name}: Tab. 2 is as it was`);
    assert.equal(await page.textContent('#figures-after'), before.figures, `${name}: the figures after correction are as they were`);
    assert.equal(await page.textContent('#inspection-table'), before.inspection, `${name}: the inspection is as it was`);
    assert.equal(await page.getAttribute('#verdict', 'data-sse-before'), before.sse);
    assert.equal(await page.isHidden('#stale-banner'), true, `${name}: the results are not greyed`);
    if (name === 'wrong-md5.x3p') await page.locator('#measured-section .pair > div:first-child').screenshot({ path: path.join(shots, 'x3p-refused.png') });
  }
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
