// Files that are huge or hostile (issue 22, item 4): each refused quickly, naming the file and
// what is too much, before it is all parsed; no file's values spread into a call (a call takes
// some 100,000 arguments before the stack overflows).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { MAX_WHEEL_POINTS, readWheelCsv, wheelSource } from '../../wasm/lib/wheel-csv.js';
import { MAX_GRID_VALUES } from '../../wasm/lib/csv.js';
import { readMeasured } from '../../wasm/lib/measured-grid.js';
import { setModuleLimits } from '../../wasm/lib/limits.js';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { longGridCsv, wheelCsv } from './hostile-files.mjs';

setModuleLimits((await loadHobSharp()).limits());

const timed = (f) => { const t = performance.now(); f(); return performance.now() - t; };
const grid = { r: [19, 24.25, 29.5, 34.75, 40], x: [-70, -52.5, -35, -17.5, 0, 17.5, 35, 52.5, 70] };

test('a wheel file of 150,000 points (1.6 MB, under the byte limit) is refused naming the count and the limit, at once', () => {
  const text = wheelCsv(150000);
  assert.ok(text.length < 2 * 1024 * 1024 && text.length > 1.5e6, `${text.length} bytes`);
  assert.equal(MAX_WHEEL_POINTS, 2000);
  const ms = timed(() => assert.throws(() => readWheelCsv(text),
    /^Error: The wheel file has 150,000 points; at most 2,000 are read \(a dressed wheel's profile is a few hundred\)\.$/));
  assert.ok(ms < 2000, `${ms} ms`);
  // At the limit it is read, and the words for it need no spread of its values.
  const w = readWheelCsv(wheelCsv(MAX_WHEEL_POINTS));
  assert.equal(w.points.R.length, MAX_WHEEL_POINTS);
});

test('the words for a wheel of any size: no spread of its values into Math.min (150,000 points from a case)', () => {
  const n = 150000;
  const R = Array.from({ length: n }, (_, k) => 30 + (20 * k) / n);
  const offset = R.map((_, k) => Math.sin(k / 50) * 2);
  const s = wheelSource({ wheel: { profileOffset: { R, offset } } });
  assert.match(s.text, /^a dressed wheel: an offset at 150000 points, R 30 to 49\.9998\d* mm, -1\.99\d* to 1\.99\d* µm/);
  assert.match(wheelSource({ wheel: { measuredProfile: { R, Z: offset } } }).text, /^a measured wheel: 150000 profile points, R 30 to 49\.9998/);
});

test('a grid CSV of 990,000 rows is refused naming the line where the values run past the limit, at once', () => {
  const text = longGridCsv(990000);
  assert.ok(text.length < 2 * 1024 * 1024, `${text.length} bytes`);
  assert.equal(MAX_GRID_VALUES, 50000);
  const ms = timed(() => assert.throws(() => readMeasured(text, grid),
    /^Error: Line 50,001: the text holds more than 50,000 values; a measured grid has at most 201 × 201, 40,804 with its positions\. Is this the right file\?$/));
  assert.ok(ms < 2000, `${ms} ms`);
  // A wide grid the same: one line of 60,000 values.
  assert.throws(() => readMeasured(`${Array(60000).fill('1.5').join(',')}\n`, grid), /^Error: Line 1: the text holds more than 50,000 values/);
  // A full 201 × 201 grid with its positions is read (here without the positions' check).
  const full = Array.from({ length: 201 }, () => Array(201).fill('0.5').join(',')).join('\n');
  assert.equal(readMeasured(full, { r: Array(201).fill(NaN), x: Array(201).fill(NaN) }).values.length, 201);
});

test('101 per-gash files are refused by their count, naming it and the most the calculator takes, before any is read', async () => {
  const { readGashTopographies, checkGashFileCount } = await import('../../wasm/lib/gash-files.js');
  const files = Array.from({ length: 101 }, (_, k) => ({ name: `gash-${k + 1}.csv`, get text() { throw new Error('read'); } }));
  const small = { r: [20, 30], x: [-10, 0, 10] };
  assert.throws(() => readGashTopographies(files, small), /^Error: 101 files chosen, one per gash; a hob has at most 100 gashes\.$/);
  assert.throws(() => checkGashFileCount(101), /^Error: 101 files chosen, one per gash; a hob has at most 100 gashes\.$/);
  checkGashFileCount(100);
  assert.throws(() => checkGashFileCount(1), /^Error: Choose one CSV file per gash, at least 2; got 1\.$/);
});

test('a case with per-gash topographies (a 2.2 MB link) gets a link that fits, leaving them out and saying so', async () => {
  const { MAX_LINK_CHARS, caseFromHash, caseLink, caseToHash, leftOutText } = await import('../../web/src/io/url.js');
  const { readFileSync } = await import('node:fs');
  const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
  // 32 gashes of 57 x 57 values of 17 digits each: as the page keeps a measuring machine's files.
  const gashTopographies = Array.from({ length: 32 }, (_, g) => Array.from({ length: 57 }, (_, i) => Array.from({ length: 57 }, (_, j) => Math.sin(g + i * 0.1 + j * 0.37) * 3.3)));
  const c = { ...paper, inspection: { gashTopographies, uncertainty: 1.5 }, measured: [[1, 2], [3, 4]] };
  const whole = `#case=${encodeURIComponent(JSON.stringify(c))}`;
  assert.ok(whole.length > 2e6, `the whole case is ${whole.length} characters`);
  const link = caseLink(c);
  assert.ok(link.hash.length <= MAX_LINK_CHARS + 1, `${link.hash.length} characters`);
  assert.deepEqual(link.leftOut, ['the per-gash topographies']);
  assert.equal(caseToHash(c), link.hash);
  const expected = structuredClone(c);
  delete expected.inspection.gashTopographies;
  assert.deepEqual(caseFromHash(link.hash).case, expected);
  assert.equal(leftOutText(link), 'The link leaves out the per-gash topographies: save the case (a file) to keep it.');
  // The measured grid a link keeps (MAX_LINK_VALUES values, full digits, negative) fits whole.
  const measured = Array.from({ length: 50 }, (_, i) => Array.from({ length: 50 }, (_, j) => -Math.sin(i * 0.37 + j * 0.11) * 3.123456789));
  const withGrid = caseLink({ ...paper, measured, correction: { locked: ['X a0'], lockedAxes: [] } });
  assert.deepEqual(withGrid.leftOut, []);
  assert.deepEqual(caseFromHash(withGrid.hash).case.measured, JSON.parse(JSON.stringify(measured)));  // (-0 is written 0)
  // A job that fits says nothing; one too large for any link gets none.
  assert.deepEqual(caseLink(paper).leftOut, []);
  const huge = caseLink({ ...paper, job: { notes: 'x'.repeat(MAX_LINK_CHARS + 10) } });
  assert.equal(huge.hash, null);
  assert.match(leftOutText(huge), /^This job is too large for a link: 65 kB; a link holds at most 64 kB\. Save the case \(a file\) to hand it on\.$/);
});
