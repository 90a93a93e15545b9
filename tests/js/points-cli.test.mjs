// The CLI with a points CSV (docs/measured-points.md): node wasm/cli.mjs case.json --points
// file.csv [--points-out prefix]; the written measured and predicted points read back; malformed
// files and refused points are named on stderr with a non-zero exit.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { readPoints } from '../../wasm/lib/points-csv.js';

const root = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const paperFile = path.join(root, 'tests', 'data', 'tab1.json');
const pointsFile = path.join(root, 'tests', 'data', 'points-2000.csv');
const cli = (...args) => spawnSync(process.execPath, [path.join(root, 'wasm', 'cli.mjs'), ...args], { encoding: 'utf8', maxBuffer: 64 << 20 });
const dir = mkdtempSync(path.join(tmpdir(), 'hobsharp-points-cli-'));

test('--points corrects the case at the file\'s points, and --points-out writes what reads back', async () => {
  const prefix = path.join(dir, 'job7');
  const run = cli(paperFile, '--points', pointsFile, '--points-out', prefix);
  assert.equal(run.status, 0, run.stderr);
  const r = JSON.parse(run.stdout);
  const points = readPoints(readFileSync(pointsFile, 'utf8')).points;
  assert.equal(points.length, 2000);
  const c = r.correction;
  assert.deepEqual(c.pointMeasured, points, 'the rows are the file\'s points, in its order');
  assert.equal(c.pointResidual.length, 2000);
  assert.equal(r.inspection.source, 'measuredPoints');
  // A known machine error: corrected to what the directions within the probe noise (0.5 µm) leave.
  assert.ok(c.rmsBefore > 10, `rms measured ${c.rmsBefore}`);
  assert.ok(c.rmsAfter < 0.02 * c.rmsBefore, `rms after ${c.rmsAfter}`);
  assert.match(c.verdict, /^Correctable/);
  assert.equal(c.residual.length, 5, 'the predicted face on the grid');
  // The same as the module given the points in the case.
  const paper = JSON.parse(readFileSync(paperFile, 'utf8'));
  const hobsharp = await loadHobSharp();
  assert.equal(run.stdout, hobsharp.evaluateToJson(JSON.stringify({ ...paper, measuredPoints: points })) + '\n');
  // The round trip: written, read back, the same points to the last bit.
  assert.deepEqual(readPoints(readFileSync(`${prefix}-measured.csv`, 'utf8')).points, points);
  assert.deepEqual(readPoints(readFileSync(`${prefix}-predicted.csv`, 'utf8')).points, c.pointResidual);
  // And the predicted points, given back as a measurement, are what the corrected axes would leave:
  // nothing left to correct.
  const again = hobsharp.evaluate({ ...paper, axes: c.axes, measuredPoints: readPoints(readFileSync(`${prefix}-predicted.csv`, 'utf8')).points });
  assert.ok(Math.abs(again.correction.rmsBefore - c.rmsAfter) < 1e-6 * c.rmsBefore, `${again.correction.rmsBefore} ${c.rmsAfter}`);
});

test('malformed points files and refused points are named on stderr', () => {
  const bad = path.join(dir, 'bad.csv');
  writeFileSync(bad, 'r,x,deviation\n19,1,2\n');
  let run = cli(paperFile, '--points', bad);
  assert.equal(run.status, 1);
  assert.equal(run.stdout, '');
  assert.equal(run.stderr, `${bad}: Line 1, column 1: the column "r" has no unit: write "r (mm)".\n`);
  writeFileSync(bad, 'r (mm),x (mm),deviation (µm)\n19,1,2\n20,x,3\n');
  run = cli(paperFile, '--points', bad);
  assert.equal(run.status, 1);
  assert.match(run.stderr, /bad\.csv: Line 3, column 2: "x" is not a number \(x, mm\)\./);
  const lines = readFileSync(pointsFile, 'utf8').trim().split('\n');
  lines[3] = '5,0,1';
  writeFileSync(bad, lines.join('\n'));
  run = cli(paperFile, '--points', bad);
  assert.equal(run.status, 1);
  // Issue 22: the point in words, counted from 1 (this read measuredPoints[2] before).
  assert.match(run.stderr, /bad\.csv: Measured point 3: \(r, x\) = \(5, 0\) mm is off the rake face/);
  lines[3] = lines[2];
  writeFileSync(bad, lines.join('\n'));
  run = cli(paperFile, '--points', bad);
  assert.match(run.stderr, /Measured point 3: .* within 0\.001 mm of measured point 2: the same point measured twice/);
  writeFileSync(bad, readFileSync(pointsFile, 'utf8').trim().split('\n').slice(0, 11).join('\n'));
  run = cli(paperFile, '--points', bad);
  assert.match(run.stderr, /Measured points: 10 points are too few for the 25 free coefficients/);
  assert.equal(cli(paperFile, '--points').status, 2, 'a usage error');
  // Nothing to write is no reason to lose the result (an independent review, 2026-12-07).
  run = cli(paperFile, '--points-out', path.join(dir, 'none'));
  assert.equal(run.status, 0);
  assert.ok(JSON.parse(run.stdout).topography);
  assert.equal(run.stderr, '--points-out: nothing written: the case has no measured face.\n');
});

// What the page shows beside a points file, the CLI says on stderr; points on the grid give the
// grid's result, and --points-out says it writes nothing (an independent review, 2026-12-07: the
// CLI kept the points alone, so deviations in mm under a µm header read as a face within the
// noise without a word, and lines before the header were dropped silently).
test('the CLI says what the points reader warns of, and points on the grid keep their result', async () => {
  const hobsharp = await loadHobSharp();
  const paper = JSON.parse(readFileSync(paperFile, 'utf8'));
  const { r, x } = hobsharp.evaluate(paper).topography;
  const rows = [];
  r.forEach((ri, i) => x.forEach((xj, j) => rows.push(`${ri},${xj},${(Math.sin(i + 2 * j) * 0.004).toPrecision(3)}`)));
  const header = 'r (mm),x (mm),deviation (µm)';
  const small = path.join(dir, 'small.csv');
  writeFileSync(small, [header, ...rows].join('\n'));
  let run = cli(paperFile, '--points', small, '--points-out', path.join(dir, 'grid'));
  assert.equal(run.status, 0, run.stderr);
  assert.match(run.stderr, /small\.csv: warning: The largest \|deviation\| is 0\.004 µm, below what a probe resolves: these look like mm/);
  assert.match(run.stderr, /--points-out: nothing written: the points lie on the grid, and the result is the grid's\.\n$/);
  assert.equal(JSON.parse(run.stdout).inspection.source, 'measuredPoints');
  assert.ok(JSON.parse(run.stdout).correction.verdict);
  const gridCase = path.join(dir, 'grid.json');
  writeFileSync(gridCase, JSON.stringify({ ...paper, measured: r.map((_, i) => x.map((_, j) => 0.5 * Math.sin(i + j))) }));
  run = cli(gridCase, '--points-out', path.join(dir, 'grid'));
  assert.equal(run.status, 0, run.stderr);
  assert.equal(run.stderr, '--points-out: nothing written: the measurement is a grid, not points.\n');
  const before = path.join(dir, 'before.csv');
  writeFileSync(before, ['19.5,-65,1', '20,-61.7,0.5', header, ...rows.map((l) => l.replace(/,[^,]*$/, ',1.5'))].join('\n'));
  run = cli(paperFile, '--points', before);
  assert.equal(run.status, 0, run.stderr);
  assert.match(run.stderr, /before\.csv: Skipped 2 lines/);
});

test("the results CSV's point blocks read back as points CSVs, in either style", async () => {
  const { resultsCsv } = await import('../../web/src/io/results-csv.js');
  const { setModuleLimits } = await import('../../web/src/limits.js');
  const hobsharp = await loadHobSharp();
  setModuleLimits(hobsharp.limits());
  const paper = JSON.parse(readFileSync(paperFile, 'utf8'));
  const points = readPoints(readFileSync(pointsFile, 'utf8')).points.slice(0, 300);
  const caseObject = { ...paper, measuredPoints: points };
  const r = hobsharp.evaluate(caseObject);
  for (const style of ['comma', 'semicolon']) {
    const lines = resultsCsv(r, { caseObject, style }).split('\n');
    const block = (title) => {
      const start = lines.indexOf(`# ${title}`);
      assert.ok(start > 0, title);
      return lines.slice(start, lines.indexOf('', start)).join('\n');
    };
    assert.deepEqual(readPoints(block('measured points')).points, points, style);
    assert.deepEqual(readPoints(block('predicted at the measured points after correction, on the identified machine')).points, r.correction.pointResidual, style);
    assert.ok(!lines.some((l) => l.startsWith('measuredPoints')), 'the points are not an input row');
  }
});
