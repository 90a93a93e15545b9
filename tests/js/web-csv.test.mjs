// Measured grids as CSV (wasm/lib/csv.js): what the paste box and the upload accept and refuse.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { MAX_MEASURED_BYTES, gridToCsv, measuredText } from '../../wasm/lib/csv.js';
import { parseMeasuredCsv } from '../../wasm/lib/measured-grid.js';
import { nestingDepth } from '../../wasm/lib/nesting.js';

const grid = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (_, j) => Math.round((i - 2) * (j - 4) * 1000) / 1000 + 0.125));

test('a grid reads back from its CSV, with any separator, comments, blank lines and CRLF', () => {
  assert.deepEqual(parseMeasuredCsv(gridToCsv(grid), 5, 9), grid);
  const text = ['# measured on the machine, µm', '', ...grid.map((row, i) => row.join([',', ';', '\t', ' ', ' , '][i]))].join('\r\n');
  assert.deepEqual(parseMeasuredCsv(text, 5, 9), grid);
  assert.equal(gridToCsv([[1.23456, -2]], 2), '1.23, -2.00');
  assert.equal(gridToCsv([[-0.00001, -0, 1e-9]], 4), '0.0000, 0.0000, 0.0000', 'no -0.0000 in a generated grid');
});

test('a grid of the wrong shape is refused, naming rows and columns', () => {
  assert.throws(() => parseMeasuredCsv('1,2,3\n4,5,6', 5, 9), /grid has 5 radial lines .* the CSV has 2 rows/);
  const short = grid.map((row, i) => (i === 3 ? row.slice(0, 8) : row));
  assert.throws(() => parseMeasuredCsv(gridToCsv(short), 5, 9), /^Error: Row 4 has 8 values; the grid has 9 axial lines\.$/);
});

test('a cell that is not a number is named by row and column', () => {
  const text = gridToCsv(grid).split('\n').map((l, i) => (i === 2 ? l.replace(/^([^,]+,[^,]+,)[^,]+/, '$1 x') : l)).join('\n');
  assert.throws(() => parseMeasuredCsv(text, 5, 9), /Line 3, column 3: "x" is not a number/);
  assert.throws(() => parseMeasuredCsv('1,NaN', 1, 2), /Line 1, column 2: "NaN"/);
  assert.throws(() => parseMeasuredCsv('1,1e999', 1, 2), /Line 1, column 2: "1e999"/);
});

test('empty or oversized text is refused', () => {
  assert.throws(() => parseMeasuredCsv('', 5, 9), /empty/);
  assert.throws(() => parseMeasuredCsv('# only a comment\n\n', 5, 9), /empty/);
  assert.throws(() => parseMeasuredCsv('0.5,'.repeat(MAX_MEASURED_BYTES / 4 + 1), 5, 9), /is 2\.0 MB; .*the limit is 2 MB/);
});

test('what a case file held as measured becomes text for the box, whatever it was, however deep', () => {
  assert.equal(measuredText([[1, 2], [3, 4]]), '1, 2\n3, 4');
  assert.equal(measuredText([1, 2, 3]), '[1,2,3]');
  assert.equal(measuredText({ rows: 'x' }), '{"rows":"x"}');
  let deep = [];
  for (let i = 0; i < 5000; i++) deep = [deep];
  assert.equal(measuredText(deep), '(lists nested more than 32 deep)');
  assert.equal(nestingDepth(deep), 33, 'counted no further than the limit + 1');
  assert.equal(nestingDepth([[1, 2], [3]]), 2);
  assert.equal(nestingDepth({ a: [{ b: [] }], c: 1 }), 4);
  assert.equal(nestingDepth(7), 0);
});
