// The validation campaign's plot (tests/validation/plot.mjs), its figure without a browser: one
// empirical distribution function per class of the committed run (docs/validation/), the targets'
// limits as dashed lines, the class titles in the legend, nothing outside the axis's range and
// nothing that is not a finite number.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { X_RANGE, ecdf, figure, targetOf } from '../validation/plot.mjs';

const committed = JSON.parse(readFileSync(new URL('../../docs/validation/validation.json', import.meta.url), 'utf8'));

test('one step curve per class, from 0 to 1, its titles in the legend; seed and count in the title', () => {
  const { data, layout } = figure(committed);
  const curves = data.filter((t) => t.legendgroup && committed.classes.some((k) => k.class === t.legendgroup));
  assert.equal(curves.length, committed.classes.length);
  committed.classes.forEach((k, i) => {
    const t = curves[i];
    assert.ok(t.name.startsWith(`${k.title}: `), t.name);
    assert.equal(t.line.shape, 'hv');
    assert.equal(t.y[0], 0);
    assert.equal(t.y.at(-1), 1);
    assert.ok(t.y.every((v, j) => j === 0 || v >= t.y[j - 1]), 'the share only rises');
    assert.equal(t.x.length, k.finals.length + 2, 'a step per scenario, from the left edge to the right');
    assert.ok(t.x.every((v) => v >= X_RANGE[0] && v <= X_RANGE[1]), 'every value within 1e-4 .. 1e3 µm');
  });
  assert.deepEqual(layout.xaxis.range, [-4, 3]);
  assert.equal(layout.xaxis.type, 'log');
  assert.match(layout.title.text, new RegExp(`seed ${committed.seed}, ${committed.scenarios} scenarios`));
  for (const t of data) for (const v of [...t.x, ...t.y]) assert.ok(Number.isFinite(v), `${t.name}: ${v}`);
  // The medium class's share within its limit is the table's: the curve at 0.1 µm.
  const medium = committed.classes.find((k) => k.class === 'medium');
  const within = medium.finals.filter((v) => v <= 0.1).length / medium.finals.length;
  assert.ok(Math.abs(within - medium.targets[0].share) < 1e-12);
  const percent = Math.floor(100 * medium.targets[0].share + 1e-9);
  const judged = medium.count - medium.unjudged;
  assert.match(curves[1].name, new RegExp(`${percent} % within 0\\.1 µm \\(asked 95 %\\), ${judged} scenarios`));
});

test('a dashed line at each target: 0.1 µm for five classes, 0.35 µm for the noisy one, with the shares asked', () => {
  const { data } = figure(committed);
  const lines = data.filter((t) => t.line && t.line.dash === 'dash');
  assert.deepEqual(lines.map((t) => t.x), [[0.1, 0.1], [0.35, 0.35]]);
  assert.match(lines[0].name, /^target: at most 0\.1 µm rms \(5 classes\)$/);
  assert.equal(lines[1].name, 'target: at most 0.35 µm rms (10 µm rms axis error, probe noise 0.5 µm, one pass)');
  const noisy = data.find((t) => t.legendgroup === 'noisy');
  assert.equal(lines[1].line.color, noisy.line.color, 'the noisy class\'s limit in its colour');
  const asked = data.filter((t) => t.legendgroup === 'asked');
  assert.deepEqual(asked.map((t) => [t.x, t.y]), [[[0.1, 0.1], [0.95, 0.9]], [[0.35], [0.9]]]);
});

test('values off the axis are drawn at its edge and counted; values that are not numbers are left out and counted', () => {
  const c = ecdf([1e-12, 0, 0.5, 2e3, null, NaN]);
  assert.deepEqual(c.x, [1e-4, 1e-4, 1e-4, 0.5, 1e3, 1e3]);
  assert.deepEqual(c.y, [0, 0.25, 0.5, 0.75, 1, 1]);
  assert.deepEqual([c.n, c.below, c.above, c.dropped], [4, 2, 1, 2]);
  const json = { seed: 1, scenarios: 6, classes: [{ class: 'noisy', title: 'noisy', finals: [1e-12, null], targets: [] }] };
  const { data } = figure(json);
  assert.match(data[0].name, /1 scenarios, 1 not a number, 1 below 0\.0001 µm/);
  assert.equal(ecdf([]).y.at(-1), 0, 'no scenario: no share');
});

test('a validation.json from before the targets carried their limits: 0.35 µm for the noisy class, 0.1 µm for the others', () => {
  assert.equal(targetOf({ class: 'noisy', targets: [{ required: 0.9, share: 0.94 }] }).limit, 0.35);
  assert.equal(targetOf({ class: 'medium', targets: [{ required: 0.95 }] }).limit, 0.1);
  assert.equal(targetOf({ class: 'medium', targets: [{ limit: 0.2 }] }).limit, 0.2);
  assert.throws(() => figure({ seed: 1 }), /no scenario classes/);
});

test('the manual page (docs/validation.md) shows the committed run: its table, seed, count and plot', () => {
  const page = readFileSync(new URL('../../docs/validation.md', import.meta.url), 'utf8');
  const table = readFileSync(new URL('../../docs/validation/validation.md', import.meta.url), 'utf8');
  const rows = table.split('\n').filter((l) => l.startsWith('|'));
  assert.ok(rows.length > 10);
  for (const row of rows) assert.ok(page.includes(`${row}\n`), `docs/validation.md is out of date (./hobsharp.sh validate --docs): ${row}`);
  assert.ok(page.includes(`Seed ${committed.seed}, ${committed.scenarios} scenarios`));
  assert.ok(page.includes('](validation/validation.png)'));
});
