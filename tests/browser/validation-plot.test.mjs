// The validation campaign's plot as ./hobsharp.sh validate writes it (tests/validation/plot.mjs):
// the committed run's JSON drawn by the project's Plotly in Debian's Chromium, a PNG (and an SVG)
// written beside it, holding the class titles, the seed and the scenario count; a file it cannot
// read is refused with a message and exit code 1. The PNG is copied to test-output/browser/.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { copyFileSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { root, shots } from './support.mjs';

const run = promisify(execFile);
const script = path.join(root, 'tests', 'validation', 'plot.mjs');
const committed = path.join(root, 'docs', 'validation', 'validation.json');

test('the plot of the committed run: a PNG and an SVG beside the JSON, with its titles, seed and count', async () => {
  const dir = mkdtempSync(path.join(tmpdir(), 'hobsharp-plot-'));
  try {
    copyFileSync(committed, path.join(dir, 'validation.json'));
    const { stdout } = await run(process.execPath, [script, dir, '--svg'], { cwd: root });
    assert.match(stdout, /Written: .*validation\.png, .*validation\.svg/);
    const png = readFileSync(path.join(dir, 'validation.png'));
    assert.equal(png.subarray(1, 4).toString(), 'PNG');
    assert.deepEqual([png.readUInt32BE(16), png.readUInt32BE(20)], [1650, 1470], '1100 x 980 at scale 1.5');
    assert.ok(png.length > 50000, `${png.length} bytes: the curves are drawn`);
    copyFileSync(path.join(dir, 'validation.png'), path.join(shots, 'validation-plot.png'));
    const svg = readFileSync(path.join(dir, 'validation.svg'), 'utf8');
    const json = JSON.parse(readFileSync(committed, 'utf8'));
    assert.ok(svg.includes(`seed ${json.seed}, ${json.scenarios} scenarios`));
    for (const k of json.classes) assert.ok(svg.includes(k.title.replace(/&/g, '&amp;')), k.title);
    assert.ok(svg.includes('target: at most 0.35 µm rms'));
    assert.equal((svg.match(/class="trace scatter/g) || []).length, json.classes.length + 2 + 2, 'the curves, two limits, two sets of shares');
    assert.doesNotMatch(svg, /NaN|Infinity|undefined/);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});

test('a file that is not a campaign\'s JSON is refused with a message', async () => {
  const dir = mkdtempSync(path.join(tmpdir(), 'hobsharp-plot-'));
  try {
    writeFileSync(path.join(dir, 'validation.json'), '{"seed": 1}');
    await assert.rejects(run(process.execPath, [script, path.join(dir, 'validation.json')], { cwd: root }),
      (e) => e.code === 1 && /no scenario classes/.test(e.stderr));
    await assert.rejects(run(process.execPath, [script, path.join(dir, 'none.json')], { cwd: root }),
      (e) => e.code === 1 && /cannot read/.test(e.stderr));
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
