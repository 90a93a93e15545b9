// A measurement at the measuring machine's points as CSV (wasm/lib/points-csv.js): the header
// with units, the accepted spellings, semicolons with decimal commas, a BOM; malformed files
// refused naming the line; the written CSV reads back to the same points.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { POINTS_HEADER, looksLikePoints, orientPoints, pointsToCsv, readPoints } from '../../wasm/lib/points-csv.js';

const points = [[19.125, -70.5, 1.25], [20, 0, -2.5e-3], [33.333333333333336, 12.0625, 0.1 + 0.2], [25, -1e-9, 1234.5]];

test('a points CSV reads with its header, in any accepted spelling and column order', () => {
  const text = `${POINTS_HEADER}\n19.125,-70.5,1.25\n20,0,-0.0025\n`;
  const read = readPoints(text);
  assert.deepEqual(read.points, [[19.125, -70.5, 1.25], [20, 0, -0.0025]]);
  assert.deepEqual(read.notes, ['2 points']);
  assert.deepEqual(read.warnings, []);
  for (const header of ['r [mm],x [mm],deviation [um]', 'R (mm), X (mm), Deviation (μm)', 'radius (mm),axial (mm),dev (µm)']) {
    assert.deepEqual(readPoints(`${header}\n19.125,-70.5,1.25\n`).points, [[19.125, -70.5, 1.25]], header);
  }
  // Columns in another order are put in order r, x, deviation, and said so.
  const swapped = readPoints('deviation (µm),x (mm),r (mm)\n1.25,-70.5,19.125\n');
  assert.deepEqual(swapped.points, [[19.125, -70.5, 1.25]]);
  assert.match(swapped.notes.join(' '), /in the order deviation, x, r/);
  // Deviations in mm are multiplied by 1000.
  const mm = readPoints('r (mm),x (mm),deviation (mm)\n19,1,0.0015\n');
  assert.equal(mm.points[0][2], 1.5);
  assert.match(mm.notes.join(' '), /in mm, multiplied by 1000/);
});

test('semicolons with decimal commas, a BOM, CRLF, comments, blank lines and a typographic minus', () => {
  const text = '\uFEFF# probe run 7\r\nr (mm);x (mm);deviation (µm)\r\n19,125;\u221270,5;1,25\r\n\r\n20;0;-0,0025;\r\n';
  const read = readPoints(text);
  assert.deepEqual(read.points, [[19.125, -70.5, 1.25], [20, 0, -0.0025]]);
  assert.match(read.notes.join(' '), /semicolons with decimal commas/);
  assert.deepEqual(readPoints('r (mm)\tx (mm)\tdeviation (µm)\n19,5\t1\t2\n').points, [[19.5, 1, 2]]);
  assert.ok(looksLikePoints(text));
  assert.ok(!looksLikePoints('r \\ x, -70, -52.5\n19, 1, 2'), 'the grid export is not a points file');
  assert.ok(!looksLikePoints('1, 2, 3\n4, 5, 6'));
});

test('values that look like mm are flagged', () => {
  const read = readPoints(`${POINTS_HEADER}\n19,1,0.001\n20,2,-0.002\n`);
  assert.equal(read.warnings.length, 1);
  assert.equal(read.warnings[0].kind, 'mm');
  assert.match(read.warnings[0].text, /these look like mm/);
});

test('malformed files are refused naming the line', () => {
  const bad = [
    ['', /^Error: The points file is empty\.$/],
    ['19,1,2\n20,2,3\n', /^Error: Line 1: the first line must be the header "r \(mm\),x \(mm\),deviation \(µm\)"/],
    ['r,x,deviation\n19,1,2\n', /^Error: Line 1, column 1: the column "r" has no unit: write "r \(mm\)"\./],
    ['r (mm),x (mm)\n19,1\n', /^Error: Line 1: the first line must be the header .* got 2 columns/],
    ['r (mm),x (mm),deviation (µm),note\n', /^Error: Line 1: .* got 4 columns/],
    ['r (mm),x (mm),height (µm)\n', /^Error: Line 1, column 3: "height \(µm\)" is not one of the columns r, x, deviation\./],
    ['r (mm),x (in),deviation (µm)\n', /^Error: Line 1, column 2: the column "x" is in "in"; it must be in mm\./],
    ['r (mm),r (mm),deviation (µm)\n', /^Error: Line 1, column 2: the column "r" is given twice\./],
    [`${POINTS_HEADER}\n`, /^Error: The points file has a header \(line 1\) but no points\./],
    [`${POINTS_HEADER}\n19,1,2\n\n20,2\n`, /^Error: Line 4: a point needs 3 values \(r, x, deviation\); got 2: "20,2"\./],
    [`${POINTS_HEADER}\n19,1,2,5\n`, /^Error: Line 2: a point needs 3 values .* got 4/],
    [`${POINTS_HEADER}\n19,1,2\n19,abc,2\n`, /^Error: Line 3, column 2: "abc" is not a number \(x, mm\)\./],
    [`${POINTS_HEADER}\n19,1,NaN\n`, /^Error: Line 2, column 3: "NaN" is not a number \(deviation, µm\)\./],
    [`${POINTS_HEADER}\n19,1,Infinity\n`, /^Error: Line 2, column 3: "Infinity" is not a number/],
    [`${POINTS_HEADER}\n19,1,0x10\n`, /^Error: Line 2, column 3: "0x10" is not a number/],
    ['r (mm);x (mm);deviation (µm)\n19,5;1,2,3;2\n', /^Error: Line 2, column 2: "1,2,3" is not a number/],
  ];
  for (const [text, message] of bad) assert.throws(() => readPoints(text), message, JSON.stringify(text.slice(0, 40)));
});

test('10 MB of garbage is refused at once, and 1.9 MB of it at its first line, without a hang', () => {
  let seed = 7;
  const garbage = (n) => {
    const bytes = Buffer.alloc(n);
    for (let i = 0; i < n; ++i) bytes[i] = 32 + ((seed = (seed * 48271) % 2147483647) % 95);
    return bytes.toString('latin1');
  };
  const big = garbage(10 * 1024 * 1024);
  let start = performance.now();
  assert.throws(() => readPoints(big), /^Error: The points file is 10\.0 MB; the limit is 2 MB/);
  assert.ok(performance.now() - start < 100, 'refused before reading');
  const underLimit = garbage(1.9 * 1024 * 1024);
  start = performance.now();
  assert.throws(() => readPoints(underLimit), /^Error: Line 1/);
  // Garbage after a good header: refused at its line.
  assert.throws(() => readPoints(`${POINTS_HEADER}\n19,1,2\n${underLimit.slice(0, 1e6)}`), /^Error: Line 3/);
  const noLines = `${POINTS_HEADER}\n${'1,2,3\n'.repeat(300000)}`;  // 1.8 MB of well-formed points
  assert.equal(readPoints(noLines).points.length, 300000);
  assert.ok(performance.now() - start < 20000, `no hang: took ${performance.now() - start} ms`);
});

test('the written CSV reads back to the same points, in either separator', () => {
  for (const decimalComma of [false, true]) {
    const csv = pointsToCsv(points, { decimalComma });
    assert.ok(csv.startsWith(decimalComma ? 'r (mm);x (mm);deviation (µm)\n' : `${POINTS_HEADER}\n`));
    const read = readPoints(csv);
    assert.deepEqual(read.points, points, 'every number to the last bit');
    assert.ok(looksLikePoints(csv));
  }
});

test('the options that apply to points change the deviation only: sign and mm to µm', () => {
  const points = [[19.5, -70.2, 0.00125], [20, 0, 0], [21, 3, -0.002]];
  assert.deepEqual(orientPoints(points, {}), points);
  assert.deepEqual(orientPoints(points, { transpose: true, flipRadial: true, flipAxial: true }), points, 'a grid\'s options do not apply');
  assert.deepEqual(orientPoints(points, { negate: true }), [[19.5, -70.2, -0.00125], [20, 0, 0], [21, 3, 0.002]]);
  assert.deepEqual(orientPoints(points, { mm: true, negate: true }), [[19.5, -70.2, -1.25], [20, 0, 0], [21, 3, 2]]);
  assert.ok(Object.is(orientPoints(points, { negate: true })[1][2], 0), 'a zero stays +0');
  assert.notEqual(orientPoints(points, {})[0], points[0], 'new points, the read ones unchanged');
});
