// A measuring machine's files with lines above the table (issue 22, item 3): the grid and points
// readers find the table, keep the date, part and operator they recognise (English and German) and
// say what they skipped; the CLI reads the same points file (it shares wasm/lib/points-csv.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { metaOf, metaText, skippedText } from '../../wasm/lib/preamble.js';
import { looksLikePoints, readPoints } from '../../wasm/lib/points-csv.js';
import { readMeasured } from '../../wasm/lib/measured-grid.js';

const root = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const data = (name) => readFileSync(path.join(root, 'tests', 'data', name), 'utf8');
const pointsText = data('points-preamble.csv');
const gridText = data('grid-preamble.csv');
// The paper's grid (tests/data/tab1.json: 5 x 9 over r 19..40 mm, x -70..70 mm).
const paperGrid = { r: [19, 24.25, 29.5, 34.75, 40], x: Array.from({ length: 9 }, (_, j) => -70 + 17.5 * j) };

test('metadata lines: date, part and operator in English and German, anything else not', () => {
  assert.deepEqual(metaOf('Datum;26.11.2026'), { kind: 'date', value: '26.11.2026' });
  assert.deepEqual(metaOf('Date: 2026-11-26'), { kind: 'date', value: '2026-11-26' });
  assert.deepEqual(metaOf('Part: hob 4711'), { kind: 'part', value: 'hob 4711' });
  assert.deepEqual(metaOf('Werkstück;Wälzfräser 4711;'), { kind: 'part', value: 'Wälzfräser 4711' });
  assert.deepEqual(metaOf('Teil-Nr.: 4711'), { kind: 'part', value: '4711' });
  assert.deepEqual(metaOf('Operator;Meier'), { kind: 'operator', value: 'Meier' });
  assert.deepEqual(metaOf('Bediener\tMeier'), { kind: 'operator', value: 'Meier' });
  assert.deepEqual(metaOf('Prüfer = H. Meier'), { kind: 'operator', value: 'H. Meier' });
  for (const line of ['Uhrzeit;14:32', 'r (mm);x (mm);deviation (µm)', '19;-70;1,5', 'Datum;', 'Klingelnberg P 26']) assert.equal(metaOf(line), null, line);
  assert.equal(metaText({ date: '26.11.2026', part: 'hob 4711', operator: 'Meier' }), 'Part hob 4711, date 26.11.2026, operator Meier.');
  assert.equal(metaText({}), '');
  assert.equal(skippedText([]), '');
  const many = Array.from({ length: 8 }, (_, i) => ({ n: i + 1, text: `line ${i + 1} of a very long report head that goes on` }));
  assert.match(skippedText(many), /^Skipped 8 lines above the table: line 1 "line 1 of a very long report head that g…", .*, and 2 more\.$/);
});

test('a points file with a measuring machine\'s preamble, semicolons and decimal commas', () => {
  assert.equal(looksLikePoints(pointsText), true, 'the page reads it as points, past the lines above the header');
  const read = readPoints(pointsText);
  assert.equal(read.points.length, 300);
  // The first point as written: 36,393;57,997;18,026132 (line 9).
  assert.deepEqual(read.points[0], [36.393, 57.997, 18.026132]);
  assert.deepEqual(read.meta, { date: '26.11.2026', part: 'Wälzfräser 4711', operator: 'Meier' });
  assert.deepEqual(read.skipped.map((s) => s.line), [1, 2, 3, 4, 5, 6], 'the blank line 7 is not counted');
  assert.equal(read.skippedText, 'Skipped 6 lines above the table: line 1 "Klingelnberg P 26;Spanflächenprüfung", line 2 ' +
    '"Datum;26.11.2026", line 3 "Uhrzeit;14:32", line 4 "Werkstück;Wälzfräser 4711", line 5 "Bediener;Meier", line 6 "Messprogramm;SPANFL_01".');
  assert.deepEqual(read.notes, ['300 points', 'semicolons with decimal commas']);
  // The same points as the plain file gives them, to the last bit.
  const plain = readPoints(data('points-2000.csv')).points.slice(0, 300);
  assert.deepEqual(read.points, plain);
  // A file without a preamble has none.
  const none = readPoints('r (mm),x (mm),deviation (µm)\n19.5,-70.2,1.25\n');
  assert.deepEqual([none.meta, none.skipped, none.skippedText], [{}, [], '']);
});

test('a points preamble without a header is named at the line that looks like one, or the first', () => {
  assert.throws(() => readPoints('Datum;26.11.2026\nr;x;deviation\n19;1;2\n'),
    /^Error: Line 2, column 1: the column "r" has no unit: write "r \(mm\)"\.$/);
  assert.throws(() => readPoints('Datum;26.11.2026\nOperator;Meier\n'), /^Error: Line 1: the first line must be the header/);
  assert.throws(() => readPoints('Part: 4711\nr (mm);x (mm);deviation (µm);extra (mm)\n19;1;2;3\n'),
    /^Error: Line 2: the line above the points must be the header .* got 4 columns/);
  // A bad point after the header is still named by its line.
  assert.throws(() => readPoints('Part: 4711\n\nr (mm);x (mm);deviation (µm)\n19;1;2\n20;x;3\n'), /^Error: Line 5, column 2: "x" is not a number \(x, mm\)\./);
});

test('a grid file with a measuring machine\'s preamble, header row and r column, semicolons and decimal commas', () => {
  assert.equal(looksLikePoints(gridText), false);
  const read = readMeasured(gridText, paperGrid);
  assert.equal(read.values.length, 5);
  assert.ok(read.values.every((row) => row.length === 9));
  // Line 9 is the first row: r = 19 mm, then its 9 values.
  const first = gridText.split(/\r?\n/)[8].split(';').slice(1).map((c) => Number(c.replace(',', '.')));
  assert.deepEqual(read.values[0], first);
  assert.deepEqual(read.meta, { date: '2026-11-26', part: 'hob 4711', operator: 'Meier' });
  assert.equal(read.skipped.length, 5);
  assert.match(read.skippedText, /^Skipped 5 lines above the table: line 1 "Zeiss O-INSPECT; rake face", line 2 "Date;2026-11-26", /);
  assert.deepEqual(read.notes, ['semicolons or tabs with decimal commas', 'a header row of 9 x positions (mm)', 'a first column of 5 r positions (mm)']);
  // Before issue 22 this file was refused: "Line 2, column 1: "Datum" is not a number".
  const german = 'Datum;26.11.2026\nTeil;4711\n' + gridText.split(/\r?\n/).slice(7).join('\n');
  const g = readMeasured(german, paperGrid);
  assert.deepEqual(g.values, read.values);
  assert.deepEqual(g.meta, { date: '26.11.2026', part: '4711' });
  // What is not a preamble is still refused at its line and column.
  const lines = gridText.split(/\r?\n/);
  lines[10] = lines[10].replace(/;[^;]*$/, ';abc');
  assert.throws(() => readMeasured(lines.join('\n'), paperGrid), /^Error: Line 11, column 10: "abc" is not a number/);
  // A grid without positions or preamble reads as before.
  assert.deepEqual(readMeasured('1,2,3\n4,5,6', { r: [1, 2], x: [1, 2, 3] }).meta, {});
});

test('the CLI reads the machine\'s points file with its preamble as the page does', async () => {
  const cli = (...args) => spawnSync(process.execPath, [path.join(root, 'wasm', 'cli.mjs'), ...args], { encoding: 'utf8', maxBuffer: 64 << 20 });
  const run = cli(path.join(root, 'tests', 'data', 'tab1.json'), '--points', path.join(root, 'tests', 'data', 'points-preamble.csv'));
  assert.equal(run.status, 0, run.stderr);
  const c = JSON.parse(run.stdout).correction;
  assert.deepEqual(c.pointMeasured, readPoints(pointsText).points, 'the file\'s 300 points, in its order');
  assert.match(c.verdict, /^Correctable/);
  // A point off the face is named in words, counted from 1, never by its JSON path (issue 22).
  const bad = pointsText.split('\r\n');
  bad[8 + 80] = '5;0;1';  // the 81st point
  const file = path.join(root, 'build', 'preamble-off-face.csv');
  (await import('node:fs')).writeFileSync(file, bad.join('\r\n'));
  const refused = cli(path.join(root, 'tests', 'data', 'tab1.json'), '--points', file);
  assert.equal(refused.status, 1);
  assert.match(refused.stderr, /preamble-off-face\.csv: Measured point 81: \(r, x\) = \(5, 0\) mm is off the rake face/);
  assert.doesNotMatch(refused.stderr, /measuredPoints/);
});
