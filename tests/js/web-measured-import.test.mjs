// A measured grid as real files bring it (wasm/lib/measured-grid.js): the page's own export
// with its positions, semicolons with decimal commas, values in mm by mistake, a transposed grid,
// and the orientation options of the preview.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { orient, readMeasured, checkShape } from '../../wasm/lib/measured-grid.js';
import { resultsCsv } from '../../web/src/io/results-csv.js';
import { setModuleLimits } from '../../web/src/limits.js';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { readFileSync } from 'node:fs';

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const grid = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (_, j) => Math.round(((i - 2) * (j - 4) + 0.5) * 1000) / 1000));

// The block of the results CSV that holds one grid, as a user copies it out of the file.
function exportedBlock(text, title) {
  const lines = text.split('\n');
  const start = lines.findIndex((l) => l.startsWith(`# ${title}`));
  const end = lines.indexOf('', start);
  return lines.slice(start, end).join('\n');
}

test("the page's own exported grid reads back, header row and r column recognised", async () => {
  const hobsharp = await loadHobSharp();
  setModuleLimits(hobsharp.limits());
  const axes = hobsharp.evaluate(paper).axes;
  axes.Z[0] += 0.01;  // the face ground 10 µm off, so that the export holds a plausible grid
  const r = hobsharp.evaluate({ ...paper, axes });
  const block = exportedBlock(resultsCsv(r), 'simulated normal deviation');
  const read = readMeasured(block, r.topography);
  assert.deepEqual(read.values, r.topography.normal);
  assert.deepEqual(read.notes, ['a header row of 9 x positions (mm)', 'a first column of 5 r positions (mm)']);
  assert.deepEqual(read.warnings, []);
  // The whole row block with positions but no header: r recognised by its values.
  const noHeader = block.split('\n').slice(2).join('\n');
  assert.deepEqual(readMeasured(noHeader, r.topography).values, r.topography.normal);
  // Positions that are not the grid's are refused, naming the line and column.
  const shifted = block.replace(/^(r \\ x,)([-\d.e]+)/m, (_, a, x) => `${a}${Number(x) + 1}`);
  assert.throws(() => readMeasured(shifted, r.topography), /^Error: Line 2, column 2: the column is at x = [-\d.]+ mm, but the grid's axial line 1 is at x = [-\d.]+ mm\./);
  const lines = block.split('\n');
  lines[4] = lines[4].replace(/^[-\d.e]+/, '99');
  assert.throws(() => readMeasured(lines.join('\n'), r.topography), /^Error: Line 5: the row is at r = 99 mm, but the grid's radial line 3 is at r = [\d.]+ mm\. Set the grid lines \(Polynomials and measuring grid\) to the measured positions, or give the values without positions\.$/);
});

const positions = { r: [36.7, 38.4, 40, 41.6, 43.3], x: [-40, -30, -20, -10, 0, 10, 20, 30, 40] };

test('semicolons with decimal commas, as a German spreadsheet writes them', () => {
  const text = '\uFEFFr;' + positions.x.join(';') + '\n' + grid.map((row, i) => [positions.r[i], ...row].map((v) => String(v).replace('.', ',')).join(';')).join('\r\n');
  const read = readMeasured(text, positions);
  assert.deepEqual(read.values, grid);
  assert.ok(read.notes.includes('semicolons or tabs with decimal commas'));
  const tabs = grid.map((row) => row.map((v) => String(v).replace('.', ',')).join('\t')).join('\n');
  assert.deepEqual(readMeasured(tabs, positions).values, grid);
  assert.deepEqual(readMeasured('1,5;−2,25;+3\n', { r: [1], x: [1, 2, 3] }).values, [[1.5, -2.25, 3]], 'a typographic minus too');
});

test('values in mm are flagged, and the mm option makes them µm', () => {
  const mm = grid.map((row) => row.map((v) => v / 1000));
  const read = readMeasured(mm.map((r) => r.join(',')).join('\n'), positions);
  assert.equal(read.suggest.mm, true);
  assert.equal(read.warnings[0].kind, 'mm');
  assert.match(read.warnings[0].text, /these look like mm\. Tick "values in mm"/);
  assert.deepEqual(orient(read.values, { mm: true }).flat().map((v) => Math.round(v * 1000) / 1000), grid.flat());
  assert.equal(readMeasured(grid.map((r) => r.join(',')).join('\n'), positions).suggest.mm, false);
  assert.deepEqual(readMeasured('0,0\n0,0', { r: [1, 2], x: [1, 2] }).warnings, [], 'a zero grid is not in mm');
});

test('a transposed grid is recognised, and the options reorient it as ticked', () => {
  const t = orient(grid, { transpose: true });
  assert.equal(t.length, 9);
  const read = readMeasured(t.map((r) => r.join(',')).join('\n'), positions);
  assert.equal(read.suggest.transpose, true);
  assert.equal(read.warnings[0].kind, 'transpose');
  assert.match(read.warnings[0].text, /9 rows of 5 values: .* Tick "transpose"/);
  assert.deepEqual(orient(read.values, { transpose: true }), grid);
  assert.throws(() => checkShape(read.values, 5, 9), /grid has 5 radial lines .* the CSV has 9 rows/);
  const g = [[1, 2, 3], [4, 5, 6]];
  assert.deepEqual(orient(g, { flipRadial: true }), [[4, 5, 6], [1, 2, 3]]);
  assert.deepEqual(orient(g, { flipAxial: true }), [[3, 2, 1], [6, 5, 4]]);
  assert.deepEqual(orient(g, { negate: true, mm: true }), [[-1000, -2000, -3000], [-4000, -5000, -6000]]);
  assert.deepEqual(g, [[1, 2, 3], [4, 5, 6]], 'the values read are not changed in place');
  assert.ok(!Object.is(orient([[0]], { negate: true })[0][0], -0), 'no -0');
});
