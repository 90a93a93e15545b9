// The case in the page's address (web/src/io/url.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { MAX_LINK_VALUES, caseFromHash, caseToHash } from '../../web/src/io/url.js';

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));

test('a case goes into the address and comes back the same', () => {
  const c = { ...paper, measured: [[0.5, -1e-7], [3, 4]], correction: { lockedAxes: ['A'], locked: ['B a2'] }, note: 'ψ & γ #1 %' };
  const hash = caseToHash(c);
  assert.match(hash, /^#case=[^#\s]*$/);
  assert.deepEqual(caseFromHash(hash), { case: c });
});

test('a measured grid too large for a link is left out of it, with its locks', () => {
  const measured = Array.from({ length: 51 }, () => Array(51).fill(0.5));
  assert.ok(51 * 51 > MAX_LINK_VALUES);
  const back = caseFromHash(caseToHash({ ...paper, measured, correction: { locked: ['X a0'] } })).case;
  assert.deepEqual(back, paper);
  assert.deepEqual(caseFromHash(caseToHash({ ...paper, measured: measured.slice(0, 40).map((r) => r.slice(0, 40)) })).case.measured.length, 40);
});

test('an address without a case gives null; an unreadable one says why', () => {
  assert.equal(caseFromHash(''), null);
  assert.equal(caseFromHash('#results'), null);
  assert.match(caseFromHash('#case=%7B%22format').error, /no readable case/);
  assert.match(caseFromHash('#case=%E0%A4%A').error, /no readable case/);
  assert.deepEqual(caseFromHash('#case=%5B1%5D'), { case: [1] });  // read; the calculator judges it
});

test('the grinding passes go into the link; a history too large for it is left out as a whole', () => {
  const grid = (rows, cols) => Array.from({ length: rows }, () => Array(cols).fill(0.25));
  const pass = (rows, cols) => ({ axes: { X: [1], Y: [2], Z: [3], A: [4], B: [5] }, measured: grid(rows, cols) });
  const small = { ...paper, measured: grid(5, 9), passes: [pass(5, 9), pass(5, 9)] };
  assert.deepEqual(caseFromHash(caseToHash(small)).case, small);
  // 30 x 30 now and two passes of it: 2700 values, over the limit; the grid alone fits.
  const large = { ...paper, measured: grid(30, 30), correction: { locked: ['X a0'] }, passes: [pass(30, 30), pass(30, 30)] };
  assert.ok(3 * 900 > MAX_LINK_VALUES && 900 <= MAX_LINK_VALUES);
  const back = caseFromHash(caseToHash(large)).case;
  assert.equal(back.passes, undefined);
  assert.deepEqual(back.measured, large.measured);
  assert.deepEqual(back.correction, large.correction);
});
