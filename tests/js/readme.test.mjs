// The table of result fields in docs/api.md (once the README's) is the module's own description
// of the result; the table of limits the module's description of its limits, and limits() holds
// exactly the entries described.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { LIMITS_BEGIN, LIMITS_END, fieldTable, limitTable, readmeTable, readmePath } from './readme-table.mjs';

const hobsharp = await loadHobSharp();

test('the table of result fields in docs/api.md is made from resultFields()', () => {
  const inReadme = readmeTable(readFileSync(readmePath, 'utf8'));
  assert.notEqual(inReadme, null, 'docs/api.md has the result-fields markers');
  assert.equal(inReadme, fieldTable(hobsharp.resultFields()),
    'docs/api.md is out of date: run node tests/js/readme-table.mjs --write');
});

test('every listed field is in the result of a measured case, and nothing else is', () => {
  const c = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
  c.measured = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (__, j) => (i - 2) * (j - 4) * 0.1));
  // With one topography per gash, so that the inspection's spacing and per-gash fields are there too.
  // (one per gash of the hob's 12, below)
  c.inspection = { gashTopographies: [0, 1.5, -2, 0.5, 1, 0, 1.5, -2, 0.5, 1, 0, -1].map((d) => c.measured.map((row) => row.map((v) => v + d))) };
  // A dressed wheel, so that the wheel offset's fields are there too (contact range R 29.53 to 50.0 mm).
  c.wheel.profileOffset = { R: [30, 40, 49.9], offset: [1, -1, 0.5] };
  // The hob's relief, so that the gear effect's fields are there too.
  Object.assign(c.hob, { gashes: 12, relief: 4.5 });
  // And the wheel-profile correction, so that its fields are there too.
  c.correction = { wheel: true };
  const r = hobsharp.evaluate(c);
  const fields = hobsharp.resultFields();
  const listed = new Set(fields.map((f) => f.path));
  // The fields of a measurement at points off the grid (docs/measured-points.md): in the result
  // of the same values as points 0.01 mm off the grid's radii, and not in the grid's.
  const { measured, ...withoutGrid } = c;
  const measuredPoints = measured.flatMap((row, i) => row.map((v, j) => [r.topography.r[i] + (i === 0 ? 0.01 : -0.01), r.topography.x[j], v]));
  // (the wheel correction takes a grid: with points off it, it is refused, so it is left out here)
  const rp = hobsharp.evaluate({ ...withoutGrid, measuredPoints, correction: {} });
  const pointsOnly = fields.filter((f) => /measuredPoints/.test(f.when)).map((f) => f.path);
  assert.deepEqual(pointsOnly, ['correction.pointMeasured', 'correction.pointResidual', 'correction.measuredOnGrid']);
  for (const f of fields) {
    const at = (result) => f.path.split('.').reduce((o, k) => (o === undefined ? undefined : o[k]), result);
    const pointsField = pointsOnly.includes(f.path);
    assert.notEqual(at(pointsField ? rp : r), undefined, `${f.path} is in the result`);
    if (pointsField) assert.equal(at(r), undefined, `${f.path} only with points`);
  }
  // The leaves of the result (an axes object {X: [a0..], .., B: [..]} counts as one field; a
  // per-axis object {X: number, ..} as five).
  const found = [];
  const stack = [[r, '']];
  while (stack.length) {
    const [v, p] = stack.pop();
    if (v && typeof v === 'object' && !Array.isArray(v) && !('X' in v && 'B' in v && Array.isArray(v.X))) {
      for (const [k, x] of Object.entries(v)) stack.push([x, p ? `${p}.${k}` : k]);
    } else found.push(p);
  }
  assert.deepEqual(found.filter((p) => !listed.has(p)), []);
  assert.equal(found.length + pointsOnly.length, listed.size);
});

test('the table of limits in docs/api.md is made from limitFields(), and limits() holds exactly its entries', () => {
  const entries = hobsharp.limitFields();
  assert.equal(readmeTable(readFileSync(readmePath, 'utf8'), LIMITS_BEGIN, LIMITS_END), limitTable(entries),
    'docs/api.md is out of date: run node tests/js/readme-table.mjs --write');
  const limits = hobsharp.limits();
  const at = (path) => path.split('.').reduce((o, k) => (o === undefined ? undefined : o[k]), limits);
  for (const e of entries) assert.notEqual(at(e.path), undefined, `${e.path} is in limits()`);
  // Every leaf of limits() lies in an entry described (a range or a document is one entry).
  const described = new Set(entries.map((e) => e.path));
  const undescribed = [];
  const stack = [[limits, '']];
  while (stack.length) {
    const [v, p] = stack.pop();
    if (described.has(p)) continue;
    if (v && typeof v === 'object' && !(Array.isArray(v) && v.every((x) => typeof x !== 'object'))) {
      for (const [k, x] of Object.entries(v)) stack.push([x, p ? `${p}.${k}` : k]);
    } else undescribed.push(p);
  }
  assert.deepEqual(undescribed, []);
  // A range's unit is its entry's.
  for (const e of entries.filter((x) => x.kind === 'range')) assert.equal(at(e.path).unit, e.unit || undefined, e.path);
});
