// One CSV file per gash (wasm/lib/gash-files.js): gash order by file name, each a measured grid
// of the grid's shape, a file that does not fit named.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readGashTopographies } from '../../wasm/lib/gash-files.js';

const grid = { r: [20, 30], x: [-10, 0, 10] };
const csv = (d) => `${d}, ${d}, ${d}\n${d + 1}, ${d + 1}, ${d + 1}\n`;

test('files in gash order by name, numbers counted as numbers', () => {
  const files = [{ name: 'gash-10.csv', text: csv(10) }, { name: 'gash-2.csv', text: csv(2) }, { name: 'gash-1.csv', text: '\uFEFF1;1;1\n2;2;2\n' }];
  const { names, grids } = readGashTopographies(files, grid);
  assert.deepEqual(names, ['gash-1.csv', 'gash-2.csv', 'gash-10.csv']);
  assert.deepEqual(grids.map((g) => g[0][0]), [1, 2, 10]);
  assert.deepEqual(grids[2], [[10, 10, 10], [11, 11, 11]]);
});

test('a file that does not fit is named; one file is not a hob', () => {
  assert.throws(() => readGashTopographies([{ name: 'a.csv', text: csv(1) }], grid), /at least 2; got 1/);
  assert.throws(() => readGashTopographies([{ name: 'a.csv', text: csv(1) }, { name: 'b.csv', text: '1, 2\n3, 4\n' }], grid),
    /^Error: b\.csv: Row 1 has 2 values; the grid has 3 axial lines\.$/);
  assert.throws(() => readGashTopographies([{ name: 'a.csv', text: csv(1) }, { name: 'b.csv', text: '1, x, 2\n3, 4, 5\n' }], grid),
    /^Error: b\.csv: Line 1, column 2: "x" is not a number/);
  assert.throws(() => readGashTopographies([{ name: 'a.csv', text: csv(1) }, { name: 'b.csv', text: '0.001, 0.002, 0\n0, 0, 0.003\n' }], grid),
    /^Error: b\.csv: The largest \|value\| is 0\.003 µm.*these look like mm\. Give them in µm\.$/);
});
