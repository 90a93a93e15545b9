// The NC programs (issue 22, item 1; wasm/lib/nc-program.js, docs/nc-programs.md) read back by an
// interpreter of the tests' own (nc-interpreter.mjs) to the axes to run, evaluated from the
// calculator's polynomials in rad (not from the program's conversion): within 1 µm and 1e-4 deg
// at 101 points over the motion range, on a helical and a straight gash, nominal and corrected,
// for the three controls; and the controls' limits: the degree of a block, the digits, the joins,
// HEIDENHAIN's t from 1 to 0, the CLI.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import { setModuleLimits } from '../../wasm/lib/limits.js';
import { NC_DIALECTS, heidenhainK, ncProgram, sinumerikReal } from '../../wasm/lib/nc-program.js';
import { coefficientsText, positionsCsv, programNote } from '../../web/src/machine-axes.js';
import { axesToRun, machineCoefficients, programFor } from '../../wasm/lib/axes-to-run.js';
import { AXES, readHeidenhain, readSinumerik } from './nc-interpreter.mjs';

const root = fileURLToPath(new URL('../../', import.meta.url));
const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const hobsharp = await loadHobSharp();
const limits = hobsharp.limits();
setModuleLimits(limits);
const digits = limits.correction.coefficientDigits;
const DEG = 180 / Math.PI;
const TOLERANCE = { linear: 1e-3 /* mm: 1 µm */, rotary: 1e-4 /* deg */ };

// The cases: a helical and a straight gash, nominal and corrected (a machine error measured).
function straight(c) {
  const s = structuredClone(c);
  s.hob.gash = 'straight';
  delete s.hob.gashLead;
  delete s.hob.hand;
  s.setup.settingAngle = 0;
  delete s.setup.centerDistance;
  return s;
}
function corrected(c, degree = c.degree) {
  const nominal = hobsharp.evaluate({ ...c, degree }).axes;
  const actual = structuredClone(nominal);
  // A machine error of a few µm over the face: per rad^k (helical) or per mm^k (straight, +-70 mm).
  const helical = (c.hob.gash || 'helical') === 'helical';
  actual.Z[0] -= 0.01;
  actual.B[2] += helical ? 0.001 : 2e-7;
  actual.X[3] += helical ? 0.5 : 1e-7;
  // A quartic Z error, so that the corrected axes carry a real fourth-degree term (a cubic program
  // needs several pieces for it).
  if (helical && degree >= 4) actual.Z[4] += 0.002;
  const measured = hobsharp.evaluate({ ...c, degree, axes: actual }).topography.normal;
  return { ...c, degree, measured, correction: { probeNoise: 1e-4 } };
}
const CASES = {
  'helical, nominal': paper,
  'helical, corrected': corrected(paper),
  'straight, nominal': straight(paper),
  'straight, corrected': corrected(straight(paper)),
};
const evaluated = Object.fromEntries(Object.entries(CASES).map(([k, c]) => [k, { caseObject: c, result: hobsharp.evaluate(c) }]));

// The axes to run at a motion value in the program's unit (deg or mm), from the calculator's
// polynomials in rad: X, Y, Z in mm, A, B in deg.
function axesAt(result, axes, x) {
  const helical = result.setup.motionUnit === 'rad';
  const w = helical ? x / DEG : x;
  return Object.fromEntries(AXES.map((a) => {
    const v = axes[a].reduceRight((s, c) => s * w + c, 0);
    return [a, a === 'A' || a === 'B' ? v * DEG : v];
  }));
}
const range = (result) => {
  const f = result.setup.motionUnit === 'rad' ? DEG : 1;
  return { lo: result.motion.min * f, hi: result.motion.max * f };
};

// The largest deviation of a program read back from the axes at 101 points over the range.
// position(x) gives the program's five axes at motion value x.
function deviation(result, axes, position) {
  const { lo, hi } = range(result);
  const worst = { linear: 0, rotary: 0 };
  for (let i = 0; i <= 100; i++) {
    const x = lo + (hi - lo) * i / 100;
    const want = axesAt(result, axes, x), got = position(x);
    for (const a of AXES) {
      const kind = a === 'A' || a === 'B' ? 'rotary' : 'linear';
      const d = Math.abs(got[a] - want[a]);
      assert.ok(Number.isFinite(d), `${a} at ${x}`);
      worst[kind] = Math.max(worst[kind], d);
    }
  }
  return worst;
}
// The program's five axes at a motion value: Sinumerik's n blocks share the range equally (the
// header says so), block i's parameter running from 0 at its start to its PL at its end.
const sinumerikPosition = (program, lo, hi) => (x) => {
  const n = program.segments.length, h = (hi - lo) / n;
  const i = Math.min(n - 1, Math.floor((x - lo) / h));
  const before = program.segments.slice(0, i).reduce((s, g) => s + g.PL, 0);
  return program.at(before + program.segments[i].PL * (x - lo - i * h) / h);
};
// HEIDENHAIN: its n blocks share the range equally (the program's header says so); block i runs
// from t = 1 at its start to t = 0 at its end.
const heidenhainPosition = (program, lo, hi, reversed = false) => (x) => {
  const n = program.blocks.length, h = (hi - lo) / n;
  const i = Math.min(n - 1, Math.floor((x - lo) / h));
  const t = (lo + (i + 1) * h - x) / h;
  return program.at(i, reversed ? 1 - t : t);
};

for (const [name, { caseObject, result }] of Object.entries(evaluated)) {
  for (const dialect of NC_DIALECTS) {
    test(`${name}: the ${dialect} program reads back to the axes to run within 1 µm and 1e-4 deg`, () => {
      const run = axesToRun(result, caseObject.axes);
      assert.equal(run.kind, name.endsWith('corrected') ? 'corrected' : 'nominal');
      const axes = name.endsWith('corrected') ? result.correction.roundedAxes : result.axes;
      assert.equal(run.axes, axes);
      const p = programFor(result, caseObject, dialect, { digits, date: new Date('2026-11-26T12:00:00Z') });
      const { lo, hi } = range(result);
      let worst;
      if (dialect === 'heidenhain') {
        const program = readHeidenhain(p.text);
        assert.equal(program.blocks.length, p.pieces);
        assert.match(p.text, new RegExp(`; ${p.pieces} SPL blocks?, each ${Number(((hi - lo) / p.pieces).toFixed(6))} `));
        worst = deviation(result, axes, heidenhainPosition(program, lo, hi));
        // The start: the linear block to the axes at the range's start (4 decimals).
        const s = axesAt(result, axes, lo);
        for (const a of AXES) assert.ok(Math.abs(program.start[a] - s[a]) <= 5.01e-5, `${a} starts at ${program.start[a]}, not ${s[a]}`);
      } else {
        const program = readSinumerik(p.text);
        assert.equal(program.segments.length, p.pieces);
        // Each block's parameter runs over [0, 1]: a2 .. a5 are mm or deg over the block, of the
        // size of the motion, not per deg^k (a control rounding them to its resolution keeps them).
        assert.ok(program.segments.every((g) => g.PL === 1), 'PL = 1 in every block');
        assert.match(p.text, new RegExp(`; ${p.pieces} POLY blocks? of degree \\d at most, each ${Number(((hi - lo) / p.pieces).toFixed(6))} `));
        worst = deviation(result, axes, sinumerikPosition(program, lo, hi));
        const s = axesAt(result, axes, lo);
        for (const a of AXES) assert.ok(Math.abs(program.start[a] - s[a]) <= 5.01e-7, `${a} starts at ${program.start[a]}, not ${s[a]}`);
      }
      assert.ok(worst.linear <= TOLERANCE.linear, `X, Y, Z off by ${worst.linear * 1000} µm`);
      assert.ok(worst.rotary <= TOLERANCE.rotary, `A, B off by ${worst.rotary} deg`);
      // The deviation the program states is what the reading finds (its own samples are finer).
      assert.ok(worst.linear * 1000 <= p.largestDeviation.linear * 1.05 + 1e-6, `${worst.linear * 1000} µm read, ${p.largestDeviation.linear} µm stated`);
      assert.ok(worst.rotary <= p.largestDeviation.rotary * 1.05 + 1e-9, `${worst.rotary} deg read, ${p.largestDeviation.rotary} deg stated`);
      // The header names the hob, the axes and the date, and states the deviation.
      assert.match(p.text, /; Hob: module 7 mm, outer diameter 80 mm, (helical gash, right hand, lead 876.56 mm|straight gash)\n/);
      assert.match(p.text, name.endsWith('corrected') ? /; Axes: the corrected proposal, as the NC program carries it\n/ : /; Axes: nominal, no correction\n/);
      assert.match(p.text, /; Date: 2026-11-26\n/);
      assert.match(p.text, /; Largest deviation of this program from the axes: [\d.]+ um \(X Y Z\), [\de.-]+ deg \(A B\)\.\n/);
      if (name.endsWith('corrected')) {
        // The rounding's cost: the correction's own figures, to 3 digits.
        const rms = Number(p.text.match(/face on the identified machine with these coefficients ([\d.e-]+) um rms;/)[1]);
        const floor = Number(p.text.match(/position resolution sets ([\d.e-]+) um rms\./)[1]);
        assert.ok(Math.abs(rms / result.correction.rmsRounded - 1) < 5e-3, `${rms} um rms stated`);
        assert.ok(Math.abs(floor / result.correction.resolutionFloor - 1) < 5e-3, `${floor} um rms stated`);
      }
    });
  }
}

// What the control takes: the degree of each block, the syntax, the digits.
test('the blocks: degree 5 in X=PO(...), degree 3 in PO[X]=(...), HEIDENHAIN K3 K2 K1 per axis; digits as the control keeps them', () => {
  const { caseObject, result } = evaluated['helical, corrected'];
  for (const dialect of NC_DIALECTS) {
    const { text } = programFor(result, caseObject, dialect, { digits });
    const body = text.split('\n').filter((l) => l && !/^(\d+ )?;/.test(l));
    for (const line of body) {
      const code = line.replace(/;.*$/, '');
      assert.doesNotMatch(code, /\d[eE][-+]?\d/, `no JavaScript exponent: ${line}`);
      for (const n of code.match(/\d+\.\d+/g) || []) {
        assert.ok(n.replace('.', '').replace(/^0+/, '').length <= digits, `${n}: at most ${digits} significant digits`);
      }
    }
    if (dialect === 'sinumerik') {
      const polys = body.flatMap((l) => [...l.matchAll(/([XYZAB])=PO\(([^)]*)\)/g)]);
      assert.ok(polys.length > 0);
      assert.ok(polys.every((m) => m[2].split(',').length <= 5), 'end point and a2 .. a5 at most');
      assert.ok(polys.some((m) => m[2].split(',').length === 4), 'the quartic axes carry a2 .. a4 (degree 4)');
      assert.doesNotMatch(text, /PO\[/);
    } else if (dialect === 'sinumerik-cubic') {
      const polys = body.flatMap((l) => [...l.matchAll(/PO\[([XYZAB])\]=\(([^)]*)\)/g)]);
      assert.ok(polys.length > 0 && polys.every((m) => m[2].split(',').length <= 3), 'end point and a2, a3 at most');
      assert.doesNotMatch(text, /=PO\(/);
    }
    if (dialect !== 'heidenhain') {
      for (const line of body) {
        for (const [, n] of line.matchAll(/(?:[XYZAB]|PO\(|PO\[[XYZAB]\]=\()(-?\d+\.\d+)/g)) assert.ok(n.split('.')[1].length <= 6, `${n}: positions to 6 decimals`);
        const pl = line.match(/PL=([\d.]+)/);
        if (pl) assert.ok(/^\d+(\.\d{1,4})?$/.test(pl[1]) && Number(pl[1]) >= 0.0001 && Number(pl[1]) <= 99999.9999, `PL=${pl[1]}`);
      }
      assert.match(body[0], /^N10 G90 G1 X-?[\d.]+ Y-?[\d.]+ Z-?[\d.]+ A-?[\d.]+ B-?[\d.]+$/);
      assert.match(body[1], /^N20 POLY /);
    } else {
      // readHeidenhain checks every coordinate (4 decimals) and K (8 decimals, exponent).
      readHeidenhain(text);
      assert.match(body[1], /^\d+ L X[-+][\d.]+ Y[-+][\d.]+ Z[-+][\d.]+ A[-+][\d.]+ B[-+][\d.]+$/);
    }
  }
});

// A HEIDENHAIN spline takes two to five axes (iTNC 530 manual, 12.7): where fewer than two move in
// a block (a straight gash, nominal: X alone), the first still ones are written with zero K at
// their positions, up to two. The cubic SINUMERIK
// header names the coefficients it writes (a2 .. a3), the quintic one a2 .. a5.
test('a HEIDENHAIN spline block has two axes at least; each SINUMERIK header names its own coefficients', () => {
  const { caseObject, result } = evaluated['straight, nominal'];
  const { text } = programFor(result, caseObject, 'heidenhain', { digits });
  const blocks = text.split('\n').filter((l) => /^\d+ SPL /.test(l));
  assert.ok(blocks.length > 0);
  const axesOf = (l) => [...l.replace(/;.*$/, '').matchAll(/ ([XYZAB])[-+][\d.]+(?= |$)/g)].map((m) => m[1]);
  assert.ok(blocks.some((l) => axesOf(l).length === 2 && / K3Y\+0\.0 K2Y\+0\.0 K1Y\+0\.0/.test(l)), blocks.join('\n'));
  for (const l of blocks) assert.ok(axesOf(l).length >= 2, `a spline of fewer than two axes: ${l}`);
  // The reader the round trips use refuses such a block too: the program with Y's zero-K words cut out.
  const oneAxis = text.replace(/ Y[-+][\d.]+(?= K)/, '').replace(/ K3Y\+0\.0 K2Y\+0\.0 K1Y\+0\.0/, '');
  assert.notEqual(oneAxis, text);
  assert.throws(() => readHeidenhain(oneAxis), /an SPL block takes two to five axes, this one 1/);
  // (It reads back to the axes: "straight, nominal: the heidenhain program reads back ..." above.)
  const cubic = programFor(evaluated['helical, corrected'].result, evaluated['helical, corrected'].caseObject, 'sinumerik-cubic', { digits }).text;
  assert.match(cubic, /so a2 \.\. a3 are mm or deg over the block/);
  const quintic = programFor(evaluated['helical, corrected'].result, evaluated['helical, corrected'].caseObject, 'sinumerik', { digits }).text;
  assert.match(quintic, /so a2 \.\. a5 are mm or deg over the block/);
});

// Axes of degree 6 (the calculator goes up to 6): the quintic program splits them into pieces
// of degree 5 that match value, slope and curvature, within 0.01 µm and 1e-6 deg.
test('degree-6 axes: quintic pieces within 0.01 µm and 1e-6 deg; cubic ones too; read back within 1 µm and 1e-4 deg', () => {
  const caseObject = corrected(paper, 6);
  const result = hobsharp.evaluate(caseObject);
  const axes = result.correction.roundedAxes;
  assert.equal(axes.X.length, 7);
  assert.ok(Math.abs(axes.A[6]) > 1e-6, 'a real sixth-degree term');
  const { lo, hi } = range(result);
  for (const dialect of NC_DIALECTS) {
    const p = programFor(result, caseObject, dialect, { digits });
    assert.ok(p.pieces > 1, `${dialect}: ${p.pieces} pieces`);
    // Full blocks (five axes, degree 5) stay under 512 characters a block.
    const longest = Math.max(...p.text.split('\n').map((l) => l.length));
    assert.ok(longest <= 512, `${dialect}: a block of ${longest} characters`);
    let worst;
    if (dialect === 'heidenhain') {
      worst = deviation(result, axes, heidenhainPosition(readHeidenhain(p.text), lo, hi));
    } else {
      const program = readSinumerik(p.text);
      assert.ok(program.segments.every((s) => AXES.every((a) => s.poly[a].length <= (dialect === 'sinumerik' ? 6 : 4))));
      worst = deviation(result, axes, sinumerikPosition(program, lo, hi));
      // The pieces alone (the positions written to 6 decimals add at most 0.0005 µm, 5e-7 deg).
      assert.ok(p.largestDeviation.linear <= 0.01 + 0.0005 && p.largestDeviation.rotary <= 1e-6 + 5e-7, JSON.stringify(p.largestDeviation));
    }
    assert.ok(worst.linear <= TOLERANCE.linear && worst.rotary <= TOLERANCE.rotary, `${dialect}: ${JSON.stringify(worst)}`);
  }
  // One block would not do: the sixth-degree term alone over the range is more than 1 µm or 1e-4 deg.
  const m = machineCoefficients(axes, true);
  const h = (hi - lo) / 2;
  assert.ok(Math.abs(m.A[6]) * h ** 6 > 1e-6, 'the split is needed');
});

// The joins of cubic pieces: position and slope continuous (Sinumerik), the start within 1 µm of
// the previous end and a change of direction below 0.1 deg (HEIDENHAIN).
test('cubic joins: continuous position and slope; HEIDENHAIN tangent within 0.1 deg', () => {
  const { caseObject, result } = evaluated['helical, corrected'];
  const cubic = readSinumerik(programFor(result, caseObject, 'sinumerik-cubic', { digits }).text);
  assert.ok(cubic.segments.length > 1);
  const value = (c, p) => c.reduceRight((s, a) => s * p + a, 0);
  // Per degree of hob rotation: each block's parameter runs over [0, PL] while the hob turns h.
  const { lo, hi } = range(result);
  const h = (hi - lo) / cubic.segments.length;
  const slope = (c, p, PL) => c.slice(1).reduceRight((s, a, k) => s * p + a * (k + 1), 0) * PL / h;
  for (let i = 0; i + 1 < cubic.segments.length; i++) {
    const left = cubic.segments[i], right = cubic.segments[i + 1];
    for (const a of AXES) {
      assert.equal(value(right.poly[a], 0), cubic.segments[i + 1].poly[a][0]);
      assert.ok(Math.abs(value(left.poly[a], left.PL) - right.poly[a][0]) < 1e-9, `${a} position at join ${i + 1}`);
      const jump = Math.abs(slope(left.poly[a], left.PL, left.PL) - slope(right.poly[a], 0, right.PL));
      assert.ok(jump < 1e-6, `${a} slope jumps by ${jump} per deg at join ${i + 1}`);
    }
  }
  const tnc = readHeidenhain(programFor(result, caseObject, 'heidenhain', { digits }).text);
  assert.ok(tnc.blocks.length > 1);
  const angle = (u, v) => {
    const dot = u.reduce((s, x, k) => s + x * v[k], 0), nu = Math.hypot(...u), nv = Math.hypot(...v);
    return Math.acos(Math.min(1, dot / nu / nv)) * DEG;
  };
  let largest = 0;
  for (let i = 0; i + 1 < tnc.blocks.length; i++) {
    // The end of block i is t = 0, the start of block i + 1 is t = 1; the blocks are equally long.
    const end = tnc.at(i, 0), begin = tnc.at(i + 1, 1);
    for (const a of AXES) assert.ok(Math.abs(end[a] - begin[a]) <= 1e-3, `${a} at join ${i + 1}`);
    for (const set of [['X', 'Y', 'Z'], AXES]) {
      const u = set.map((a) => tnc.slope(i, 0)[a]), v = set.map((a) => tnc.slope(i + 1, 1)[a]);
      largest = Math.max(largest, angle(u, v));
    }
  }
  assert.ok(largest < 0.1, `the direction changes by ${largest} deg at a join`);
});

// t runs from 1 at a block's start to 0 at its end: read the other way round, the program misses
// the axes; and a Sinumerik program read with its parameter in degrees (PL the block's length)
// misses them too. The comparison can fail.
test('HEIDENHAIN t from 1 to 0, Sinumerik PL: read otherwise, the comparison fails', () => {
  const { caseObject, result } = evaluated['helical, corrected'];
  const axes = result.correction.roundedAxes;
  const { lo, hi } = range(result);
  const tnc = readHeidenhain(programFor(result, caseObject, 'heidenhain', { digits }).text);
  const b = tnc.blocks[0];
  const start = tnc.at(0, 1), end = tnc.at(0, 0);
  for (const a of AXES) {
    assert.ok(Math.abs(start[a] - tnc.start[a]) <= 1e-3, `${a}: t = 1 is the start`);
    assert.equal(end[a], b.end[a], `${a}: t = 0 is the end point`);
  }
  const reversed = deviation(result, axes, heidenhainPosition(tnc, lo, hi, true));
  assert.ok(reversed.linear > TOLERANCE.linear, `t read from 0 to 1 is off by ${reversed.linear} mm`);
  const text = programFor(result, caseObject, 'sinumerik', { digits }).text;
  const inDegrees = readSinumerik(text.replace(/ PL=1\b/g, ` PL=${hi - lo}`));
  assert.equal(inDegrees.segments.length, 1);
  const off = deviation(result, axes, (x) => inDegrees.at(Math.min(x - lo, hi - lo)));
  assert.ok(off.linear > TOLERANCE.linear, 'p in degrees is not the program');
});

test('the header names the job from the case\'s job, in plain ASCII; the file is named for it', () => {
  const { result } = evaluated['helical, nominal'];
  const caseObject = { ...paper, job: { number: 'J-4711', customer: 'Müller Verzahnung; GmbH', hobSerial: 'H 123', operator: 'A. Weiß', notes: 'first pass\nafter regrind' } };
  for (const dialect of NC_DIALECTS) {
    const p = programFor(result, caseObject, dialect, { digits, date: new Date('2026-11-26T08:00:00Z') });
    assert.match(p.text, /; Job: job J-4711, customer Muller Verzahnung, GmbH, hob serial H 123, operator A\. Wei\? ?/);
    assert.match(p.text, /; Notes: first pass after regrind\n/);
    assert.ok(/^[\x20-\x7e\n]*$/.test(p.text), 'plain ASCII');
    // The cubic SINUMERIK program is told from the degree-5 one by _P3, which leaves no room for the date here.
    assert.equal(p.fileName, { sinumerik: 'HOBSHARP_J_4711_20261126.mpf', 'sinumerik-cubic': 'HOBSHARP_J_4711_P3.mpf', heidenhain: 'HOBSHARP_J_4711_20261126.h' }[dialect]);
    if (dialect === 'heidenhain') assert.match(p.text, /^0 BEGIN PGM HOBSHARP_J_4711_20261126 MM\n/);
  }
  const none = programFor(result, paper, 'sinumerik', { digits, date: new Date('2026-11-26T08:00:00Z') });
  assert.match(none.text, /; Job: \(none given\)\n/);
  assert.equal(none.fileName, 'HOBSHARP_M7_20261126.mpf');
  // Both SINUMERIK dialects write .mpf: one name had let the second download replace the first.
  assert.equal(programFor(result, paper, 'sinumerik-cubic', { digits, date: new Date('2026-11-26T08:00:00Z') }).fileName, 'HOBSHARP_M7_20261126_P3.mpf');
  // A derived case's module: 4 significant digits in the name (a review found HOBSHARP_M8_110317242852).
  const derived = programFor(result, { ...paper, hob: { ...paper.hob, normalModule: 8.11031724285288 } }, 'sinumerik', { digits, date: new Date('2026-11-26T08:00:00Z') });
  assert.equal(derived.fileName, 'HOBSHARP_M8_11_20261126.mpf');
  // A job number too long for the date beside it in 24 characters: the date left out whole, never
  // cut to "202611" (the review of 2026-12-07 found HOBSHARP_J_4711_A_202612).
  const long = programFor(result, { ...paper, job: { number: 'J-4711-A' } }, 'sinumerik', { digits, date: new Date('2026-11-26T08:00:00Z') });
  assert.equal(long.fileName, 'HOBSHARP_J_4711_A.mpf');
  const longer = programFor(result, { ...paper, job: { number: 'ORDER-2026-000123456' } }, 'heidenhain', { digits, date: new Date('2026-11-26T08:00:00Z') });
  assert.equal(longer.fileName, 'HOBSHARP_ORDER_2026_0001.h');
  assert.ok(longer.fileName.length <= 24 + 2);
  assert.match(programNote(none), /^1 POLY block of degree 5 at most; largest deviation from the axes [\d.e-]+ µm \(X, Y, Z\), [\d.e-]+° \(A, B\)\.$/);
});

test('numbers as the controls write them: Sinumerik plain decimals or EX, HEIDENHAIN K mantissa and exponent', () => {
  assert.equal(sinumerikReal(-2.62109120000001e-9, 10), '-2.6210912EX-9');
  assert.equal(sinumerikReal(139.509430167272, 10), '139.5094302');
  assert.equal(sinumerikReal(0.000123456789012, 10), '0.000123456789');
  assert.equal(sinumerikReal(-0.00030000000000000003, 10), '-0.0003');
  assert.equal(sinumerikReal(0, 10), '0');
  assert.equal(heidenhainK(159.8338), '+1.598338 E+2');
  assert.equal(heidenhainK(-0.0003), '-3.0 E-4');
  assert.equal(heidenhainK(-7.30849938), '-7.30849938');
  assert.equal(heidenhainK(9.999999996), '+1.0 E+1');
  assert.equal(heidenhainK(0), '+0.0');
});

test('a program the control cannot take is refused in words', () => {
  const axes = Object.fromEntries(AXES.map((a) => [a, [0, 1]]));
  assert.throws(() => ncProgram({ axes, helical: true, motion: { min: 0, max: 10 }, dialect: 'fanuc' }), /^Error: NC program: the control must be one of sinumerik, sinumerik-cubic, heidenhain; got fanuc\.$/);
  assert.throws(() => ncProgram({ axes, helical: true, motion: { min: 1, max: 1 }, dialect: 'sinumerik' }), /motion range is empty/);
  assert.throws(() => ncProgram({ axes: { ...axes, B: [NaN] }, helical: true, motion: { min: 0, max: 1 }, dialect: 'sinumerik' }), /axis B has no finite coefficients/);
  assert.throws(() => ncProgram({ axes: { ...axes, X: [1e6] }, helical: true, motion: { min: 0, max: 1 }, dialect: 'heidenhain' }), /beyond \+-99999\.9999/);
});

test('the CLI prints the program the page offers; a control it does not know is a usage error', () => {
  const run = (...args) => spawnSync(process.execPath, ['wasm/cli.mjs', ...args], { cwd: root, encoding: 'utf8' });
  const { result } = evaluated['helical, nominal'];
  for (const dialect of NC_DIALECTS) {
    const out = run('tests/data/tab1.json', '--nc', dialect);
    assert.equal(out.status, 0, out.stderr);
    const page = programFor(result, paper, dialect, { digits });
    const undated = (t) => t.replace(/Date: [\d-]+/, 'Date: -').replace(/HOBSHARP_M7_\d+/g, 'HOBSHARP_M7');
    assert.equal(undated(out.stdout), undated(page.text));
    if (dialect === 'heidenhain') readHeidenhain(out.stdout); else readSinumerik(out.stdout);
  }
  const bad = run('tests/data/tab1.json', '--nc', 'fanuc');
  assert.equal(bad.status, 2);
  assert.match(bad.stderr, /^--nc: the control must be one of sinumerik, sinumerik-cubic, heidenhain; got fanuc\.\nusage: node wasm\/cli\.mjs case\.json .*\[--nc sinumerik\|sinumerik-cubic\|heidenhain\]/);
  assert.equal(run('tests/data/tab1.json', '--nc').status, 2);
  const missing = run('no-such-case.json', '--nc', 'sinumerik');
  assert.equal(missing.status, 1);
  assert.equal(missing.stdout, '');
});

// "Copy coefficients" and the positions CSV: digits that mean something, the decimal comma.
test('the copied coefficients carry no zero terms; the positions CSV has 6 decimals and honours the decimal comma', () => {
  const { result } = evaluated['helical, nominal'];
  const text = coefficientsText(machineCoefficients(result.axes, true), true, digits);
  assert.doesNotMatch(text, /[-+] 0 \*/);
  assert.match(text, /^X \(mm\) = 22\.40029899 \+ 2\.434888889 \* phi \(deg\)\n/);
  assert.match(text, /\nY \(mm\) = 39\.30756771\n/);
  assert.match(text, /\nA \(deg\) = 1 \* phi \(deg\)\n/);
  const zero = coefficientsText({ X: [0, 0], Y: [-1.5, 0, -2e-9], Z: [0], A: [0], B: [0] }, false, digits);
  assert.match(zero, /^X \(mm\) = 0\nY \(mm\) = -1\.5 - 2e-9 \* s \(mm\)\^2\n/);
  const rows = [[-33.66617, -59.57270000000001, 39.3075677, -116.4459604586, -33.66617, 12.626], [0, 22.4, 39.3, -116.4, -1e-12, 12.6]];
  const comma = positionsCsv(rows, true).split('\n');
  assert.equal(comma[1], '-33.666170,-59.572700,39.307568,-116.445960,-33.666170,12.626000');
  assert.equal(comma[2], '0.000000,22.400000,39.300000,-116.400000,0.000000,12.600000');
  const semicolon = positionsCsv(rows, true, { decimalComma: true }).split('\n');
  assert.equal(semicolon[0], '\uFEFFhob rotation (deg);X (mm);Y (mm);Z (mm);A (deg);B (deg)');
  assert.equal(semicolon[1], '-33,666170;-59,572700;39,307568;-116,445960;-33,666170;12,626000');
});
