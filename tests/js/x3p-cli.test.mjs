// The command line's X3P options (wasm/cli.mjs, wasm/cli-x3p.mjs): the result's topographies
// written as .x3p, a measured .x3p read into the case, and bad files refused naming the file and
// the element, with the CLI's output otherwise unchanged.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { unzipSync, zipSync, strToU8 } from 'fflate';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { readX3p } from '../../wasm/lib/x3p.js';
import { runOnX3p } from './hostile-files.mjs';

const root = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const cli = path.join(root, 'wasm', 'cli.mjs');
const paperFile = path.join(root, 'tests', 'data', 'tab1.json');
const paper = () => JSON.parse(readFileSync(paperFile, 'utf8'));
const run = (...args) => spawnSync(process.execPath, [cli, ...args], { encoding: 'utf8' });
const within1ulp = (a, b) => a.forEach((row, j) => row.forEach((v, i) => assert.ok(Math.abs(v - b[j][i]) <= Math.abs(b[j][i]) * 2.3e-16, `row ${j + 1}, column ${i + 1}`)));

const hobsharp = await loadHobSharp();
const dir = mkdtempSync(path.join(tmpdir(), 'hobsharp-x3p-'));
// A face ground with Z 10 µm off, as measured.
const axes = hobsharp.evaluate(paper()).axes;
axes.Z[0] += 0.01;
const measured = hobsharp.evaluate({ ...paper(), axes }).topography.normal;
const measuredFile = path.join(dir, 'measured.json');
writeFileSync(measuredFile, JSON.stringify({ ...paper(), measured }));

test('--x3p-out writes the measured and predicted topographies, and the printed result is unchanged', () => {
  const prefix = path.join(dir, 'job');
  const plain = run(measuredFile);
  const out = run(measuredFile, '--x3p-out', prefix);
  assert.equal(out.status, 0, out.stderr);
  assert.equal(out.stdout, plain.stdout);
  assert.equal(out.stderr, `wrote ${prefix}-measured.x3p\nwrote ${prefix}-predicted.x3p\n`);
  const result = JSON.parse(out.stdout);
  within1ulp(readX3p(readFileSync(`${prefix}-measured.x3p`)).values, measured);
  const predicted = readX3p(readFileSync(`${prefix}-predicted.x3p`));
  within1ulp(predicted.values, result.correction.residual);
  // The file says whose face it is and carries the bound on what the pass leaves, in the module's unit.
  assert.ok(predicted.meta.comment.includes(`The pass leaves at most ${Number(result.correction.predictedRmsHigh.toPrecision(3))} µm rms on the probe grid (the bound)`), predicted.meta.comment);
  assert.equal(existsSync(`${prefix}-simulated.x3p`), false);
  // Without a measurement, the simulated face.
  const sim = run(paperFile, '--x3p-out', path.join(dir, 'paper'));
  assert.equal(sim.status, 0, sim.stderr);
  within1ulp(readX3p(readFileSync(path.join(dir, 'paper-simulated.x3p'))).values, JSON.parse(sim.stdout).topography.normal);
});

test('--measured-x3p reads the grid into the case: the same result as the case holding that grid', () => {
  const prefix = path.join(dir, 'again');
  assert.equal(run(measuredFile, '--x3p-out', prefix).status, 0);
  const x3p = `${prefix}-measured.x3p`;
  const out = run(paperFile, '--measured-x3p', x3p);
  assert.equal(out.status, 0, out.stderr);
  const grid = readX3p(readFileSync(x3p)).values;
  assert.deepStrictEqual(JSON.parse(out.stdout), hobsharp.evaluate({ ...paper(), measured: grid }));
  // It takes the place of a measured grid the case already has; both options together.
  const both = run(measuredFile, '--measured-x3p', x3p, '--x3p-out', path.join(dir, 'both'));
  assert.equal(both.status, 0, both.stderr);
  assert.equal(both.stdout, out.stdout);
});

test('bad X3P files and options: the file and the element named on stderr, exit 1 (2 for usage)', () => {
  const x3p = path.join(dir, 'again-measured.x3p');
  const f = unzipSync(readFileSync(x3p));
  const damaged = path.join(dir, 'damaged.x3p');
  writeFileSync(damaged, zipSync({ ...f, 'md5checksum.hex': strToU8(`${'f'.repeat(32)} *main.xml\n`) }));
  const bad = run(paperFile, '--measured-x3p', damaged);
  assert.equal(bad.status, 1);
  assert.equal(bad.stdout, '');
  assert.match(bad.stderr, new RegExp(`^${damaged.replace(/[.\\/]/g, '\\$&')}: md5checksum\\.hex: says f{32}, but main\\.xml's MD5 is`));
  // Another grid: the X3P's lines are not the case's.
  const coarse = paper();
  coarse.grid = { ...coarse.grid, radial: 4 };
  const coarseFile = path.join(dir, 'coarse.json');
  writeFileSync(coarseFile, JSON.stringify(coarse));
  assert.match(run(coarseFile, '--measured-x3p', x3p).stderr, /again-measured\.x3p: main\.xml, Record3\/MatrixDimension\/SizeY: 5 radial lines, but the grid has 4\./);
  assert.match(run(paperFile, '--measured-x3p', path.join(dir, 'none.x3p')).stderr, /none\.x3p: no such file/);
  const usage = run(paperFile, '--measured-x3p');
  assert.equal(usage.status, 2);
  assert.match(usage.stderr, /^--measured-x3p needs a value\nusage: node wasm\/cli\.mjs case\.json \[--points points\.csv\] \[--points-out prefix\] \[--nc sinumerik\|sinumerik-cubic\|heidenhain\] \[--measured-x3p file\.x3p\] \[--x3p-out prefix\]\n$/);
  // A case the calculator refuses is still named by its own file.
  const broken = paper();
  broken.hob.rakeOffset = 40;
  const brokenFile = path.join(dir, 'broken.json');
  writeFileSync(brokenFile, JSON.stringify(broken));
  assert.match(run(brokenFile, '--measured-x3p', x3p).stderr, /broken\.json: hob\.rakeOffset/);
});

test('an X3P whose points run on past their declared size (a zip bomb) is refused naming the file, quickly', () => {
  const prefix = path.join(dir, 'bomb-source');
  assert.equal(run(measuredFile, '--x3p-out', prefix).status, 0);
  const bomb = path.join(dir, 'bomb.x3p');
  writeFileSync(bomb, runOnX3p(unzipSync(readFileSync(`${prefix}-measured.x3p`)), 'bindata/data.bin', 256 * 1024 * 1024));
  // The time of a good file's run (the module's start, the case's evaluation) on this machine now.
  let started = performance.now();
  assert.equal(run(paperFile, '--measured-x3p', `${prefix}-measured.x3p`).status, 0);
  const good = performance.now() - started;
  started = performance.now();
  const out = run(paperFile, '--measured-x3p', bomb);
  const ms = performance.now() - started;
  assert.equal(out.status, 1, out.stdout.slice(0, 200));
  assert.equal(out.stdout, '');
  assert.match(out.stderr, /bomb\.x3p: bindata\/data\.bin in the X3P container inflates to more than the 360 bytes its entry declares: a damaged or hostile file; refused\./);
  assert.ok(ms < Math.max(2000, 1.5 * good), `refused after ${ms} ms (a good file's run: ${good} ms)`);
});
