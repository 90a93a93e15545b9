// The wheel as a surface of its own (issue 12) through the WebAssembly module: wheel.profileOffset
// and wheel.measuredProfile in the case, the result's wheelOffset and wheelProfile.dressed* fields
// against the native build, the sign and the sensitivities to the offset's points, the measured
// wheel's round trip, and the refusals with the field named.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadHobSharp, HobSharpError } from '../../wasm/hobsharp.mjs';
import { native, paper } from './native-build.mjs';
import { wheelEdgeText } from '../../web/src/views/wheel-edge.js';

const hobsharp = await loadHobSharp();

// The contact range of Tab. 1: the extremes of wheelProfile.R of the conjugate wheel.
const conjugate = hobsharp.evaluate(paper());
const Rmin = Math.min(...conjugate.wheelProfile.R), Rmax = Math.max(...conjugate.wheelProfile.R);
const evenR = (n) => Array.from({ length: n }, (_, k) => Rmin + (Rmax - Rmin) * k / (n - 1));
const withOffset = (offset, R = evenR(offset.length)) => {
  const c = paper();
  c.wheel.profileOffset = { R, offset };
  return c;
};
const maxAbs = (m) => Math.max(...m.flat().map(Math.abs));
const diff = (a, b) => a.map((row, i) => row.map((x, j) => x - b[i][j]));

test('a dressed wheel: the module agrees with the native build, the fields have their shapes', () => {
  const c = withOffset([2, -3, 4, 1, -1.5]);
  const w = hobsharp.evaluate(c), n = native(c);
  for (const key of ['R', 'offset']) {
    assert.equal(w.wheelOffset[key].length, 5, key);
    w.wheelOffset[key].forEach((x, i) => assert.ok(Math.abs(x - n.wheelOffset[key][i]) <= 1e-9 * Math.max(1, Math.abs(x)), `${key}[${i}]`));
  }
  // KNOWN GAP: with a non-zero offset the module's derivatives (wheelOffset.sensitivities and
  // .thickness, and the axis sensitivities) differ from the native build's by up to 3e-4 of their
  // size, in proportion to the offset (zero offset: 1e-14), while every face agrees to the last
  // digit; natively they agree with central differences to 1.4e-8. Cause not found yet; held here
  // to 1e-3 so that the gap is visible and cannot grow unnoticed.
  assert.equal(w.wheelOffset.thickness.length, 5);
  w.wheelOffset.thickness.forEach((x, i) => assert.ok(Math.abs(x - n.wheelOffset.thickness[i]) <= 1e-3 * Math.max(1, Math.abs(x)), `thickness[${i}]`));
  assert.deepEqual(w.wheelOffset.offset, [2, -3, 4, 1, -1.5]);
  assert.equal(w.wheelOffset.sensitivities.length, 5, 'one topography per point');
  assert.equal(w.wheelOffset.sensitivities[0].length, 5);
  assert.equal(w.wheelOffset.sensitivities[0][0].length, 9);
  assert.ok(maxAbs(diff(w.topography.normal, n.topography.normal)) < 1e-9);
  for (const key of ['offset', 'dressedR', 'dressedZ']) {
    assert.equal(w.wheelProfile[key].length, w.wheelProfile.R.length, key);
    w.wheelProfile[key].forEach((x, i) => assert.ok(Math.abs(x - n.wheelProfile[key][i]) <= 1e-9 * Math.max(1, Math.abs(x)), `${key}[${i}]`));
  }
  // The spline goes through its points: the profile's ends are the contact range's ends.
  const ends = [0, w.wheelProfile.R.length - 1];
  for (const k of ends) {
    const i = Math.abs(w.wheelProfile.R[k] - Rmin) < 1e-9 ? 0 : 4;
    assert.ok(Math.abs(w.wheelProfile.offset[k] - w.wheelOffset.offset[i]) < 1e-9, `offset at the end ${k}`);
  }
  // Without an offset the fields are not there.
  assert.equal(conjugate.wheelOffset, undefined);
  assert.equal(conjugate.wheelProfile.dressedR, undefined);
});

test('zero offset grinds today\'s face; + 5 µm of wheel removes 5 µm of material everywhere', () => {
  const zero = hobsharp.evaluate(withOffset([0, 0, 0]));
  assert.ok(maxAbs(diff(zero.topography.normal, conjugate.topography.normal)) < 1e-9);
  const five = hobsharp.evaluate(withOffset([5, 5]));
  assert.ok(maxAbs(five.topography.normal.map((row) => row.map((x) => x + 5))) < 1e-6, 'the face is -5 µm');
  assert.ok(five.topography.thickness <= -5 + 1e-6, `thickness ${five.topography.thickness} µm: thinner by at least 5 µm`);
});

test('wheelOffset.sensitivities agree with central differences of the module\'s faces', () => {
  const offset = [2, -3, 4, 1, -1.5];
  const S = hobsharp.evaluate(withOffset(offset)).wheelOffset.sensitivities;
  const largest = Math.max(...S.map(maxAbs));
  assert.ok(largest > 0.3, `largest ${largest} µm per µm`);
  const h = 0.1;
  for (const k of [0, 2, 4]) {
    const plus = offset.slice(), minus = offset.slice();
    plus[k] += h; minus[k] -= h;
    const tp = hobsharp.evaluate(withOffset(plus)).topography.normal, tm = hobsharp.evaluate(withOffset(minus)).topography.normal;
    const cd = diff(tp, tm).map((row) => row.map((x) => x / (2 * h)));
    // Natively 1.4e-8 of the largest (tests/test_wheel_surface.cpp); the module 1.3e-5: see KNOWN GAP above.
    assert.ok(maxAbs(diff(cd, S[k])) < 1e-4 * largest, `point ${k}: ${maxAbs(diff(cd, S[k]))}`);
  }
});

test('a measured wheel: the dressed profile read back gives the same offset and the same face', () => {
  const dressed = hobsharp.evaluate(withOffset([2, -3, 4, 1, -1.5]));
  // As a dresser would measure it: (R, Z) in increasing R.
  const order = dressed.wheelProfile.dressedR.map((_, i) => i).sort((a, b) => dressed.wheelProfile.dressedR[a] - dressed.wheelProfile.dressedR[b]);
  const c = paper();
  c.wheel.measuredProfile = { R: order.map((i) => dressed.wheelProfile.dressedR[i]), Z: order.map((i) => dressed.wheelProfile.dressedZ[i]) };
  const measured = hobsharp.evaluate(c);
  assert.equal(measured.wheelOffset.R.length, order.length);
  order.forEach((i, k) => {
    assert.ok(Math.abs(measured.wheelOffset.R[k] - dressed.wheelProfile.R[i]) < 1e-9, `foot ${k}`);
    assert.ok(Math.abs(measured.wheelOffset.offset[k] - dressed.wheelProfile.offset[i]) < 1e-6, `offset ${k}`);
  });
  // (R, Z) -> offset -> (R, Z): the measured wheel's dressed profile is the measured one.
  const back = order.map((i) => i);
  back.forEach((i, k) => {
    assert.ok(Math.abs(measured.wheelProfile.dressedR[i] - c.wheel.measuredProfile.R[k]) < 1e-6, `R ${k}`);
    assert.ok(Math.abs(measured.wheelProfile.dressedZ[i] - c.wheel.measuredProfile.Z[k]) < 1e-6, `Z ${k}`);
  });
  assert.ok(maxAbs(diff(measured.topography.normal, dressed.topography.normal)) < 0.01, 'the same face within 0.01 µm');
});

const refusals = [
  ['one point', (c) => { c.wheel.profileOffset = { R: [40], offset: [1] }; }, 'wheel.profileOffset.R', /at least 2 points/],
  ['R not increasing', (c) => { c.wheel.profileOffset = { R: [40, 35], offset: [1, 2] }; }, 'wheel.profileOffset.R[1]', /must be greater/],
  ['R outside the contact range', (c) => { c.wheel.profileOffset = { R: [20, 40], offset: [1, 2] }; }, 'wheel.profileOffset.R[0]', /outside the wheel's contact range/],
  ['lists of different lengths', (c) => { c.wheel.profileOffset = { R: [35, 40], offset: [1] }; }, 'wheel.profileOffset.offset', /one value per radius/],
  ['null as an offset', (c) => { c.wheel.profileOffset = { R: [35, 40], offset: [1, null] }; }, 'wheel.profileOffset.offset[1]', /must be a number/],
  ['a measured wheel short of the range', (c) => {
    const d = conjugate.wheelProfile, n = d.R.length;
    const idx = Array.from({ length: n - 20 }, (_, k) => k + 10).sort((a, b) => d.R[a] - d.R[b]);
    c.wheel.measuredProfile = { R: idx.map((i) => d.R[i]), Z: idx.map((i) => d.Z[i]) };
  }, 'wheel.measuredProfile', /whole contact range/],
];

for (const [name, change, field, message] of refusals) {
  test(`refused: ${name}`, () => {
    const c = paper();
    change(c);
    assert.throws(() => hobsharp.evaluate(c), (e) => {
      assert.ok(e instanceof HobSharpError, 'a HobSharpError');
      assert.equal(e.code, 'InvalidInput');
      assert.equal(e.field, field);
      assert.match(e.message, message);
      // A wheel file's words when the job refuses its points (issue 22): the point counted from 1,
      // never the path; what the case file's reader refuses starts with the path.
      if (e.message.startsWith('Wheel file')) {
        assert.ok(!/wheel\.|\[\d+\]/.test(e.message), e.message);
        const k = /\[(\d+)\]$/.exec(field);
        if (k) assert.ok(e.message.startsWith(`Wheel file, point ${Number(k[1]) + 1}: `), e.message);
      } else {
        assert.ok(e.message.startsWith(field), e.message);
      }
      return true;
    });
    // The module stays usable.
    assert.ok(maxAbs(diff(hobsharp.evaluate(paper()).topography.normal, conjugate.topography.normal)) === 0);
  });
}

// The edge check's margin (envelope.cpp, pastEnvelopeEdge: the crossings a motion step either side of
// each envelope point): offsets alternating +-a µm over 9 radii grind the face up to a = 53.5 µm and
// are refused from 54 µm on (measured 2026-12-02; the crossings by chord steps decide as Newton's
// method did, on these 21 amplitudes from 50 to 60 µm the same output).
test('the edge of the envelope: +-53 µm grinds, +-55 µm curves past the edge', () => {
  const alternating = (a) => withOffset(Array.from({ length: 9 }, (_, k) => (k % 2 ? a : -a)));
  assert.ok(Number.isFinite(hobsharp.evaluate(alternating(53)).topography.rms));
  assert.throws(() => hobsharp.evaluate(alternating(55)), (e) => e.field === 'wheel.profileOffset' && /curves too sharply/.test(e.message));
});

test('an offset too sharp to grind blames the wheel, not the grid or the measurement', () => {
  const c = withOffset(Array.from({ length: 9 }, (_, k) => (k % 2 ? 9000 : -9000)));
  assert.throws(() => hobsharp.evaluate(c), (e) => e instanceof HobSharpError && e.code === 'Unsolvable' && e.field === 'wheel.profileOffset' &&
    /^Wheel file: the dressed wheel's profile curves too sharply to grind the face near r = /.test(e.message) && !/grid/.test(e.message));
  // With a measured grid too, the wheel is blamed (the page shows it at the wheel, not at the grid).
  const measured = { ...c, measured: hobsharp.evaluate(paper()).topography.normal };
  assert.throws(() => hobsharp.evaluate(measured), (e) => e.field === 'wheel.profileOffset' && /^Wheel file:/.test(e.message));
});

// The edge of the wheel's envelope (docs/method.md): seed 2026's scenario 311 of the validation
// campaign as a case file, whose conjugate profile turns back 0.077 mm below the tip. The module
// says where, in mm and in words; Tab. 1's profile reaches the tip, and says nothing. A dressed
// wheel cannot be simulated past the edge: refused at the setup's tilt, saying why, not blaming
// the wheel; with the conjugate wheel the face is simulated (its tip band the envelope's formal
// solution, which the words say not to rely on).
test('a conjugate profile that turns back below the tip is said, with its radius', async () => {
  const { readFileSync } = await import('node:fs');
  const edgeCase = () => JSON.parse(readFileSync(new URL('../data/wheel-edge.json', import.meta.url), 'utf8'));
  const r = hobsharp.evaluate(edgeCase());
  const tip = r.setup.outerRadius;
  assert.ok(r.wheelProfile.turnRadius > tip - 0.1 && r.wheelProfile.turnRadius < tip - 0.05, `turns at ${r.wheelProfile.turnRadius}`);
  assert.match(r.wheelProfile.edge, /^The wheel cannot grind the top 0\.077 mm of the face as designed: the conjugate wheel's profile turns back at the face radius r = 23\.915 mm, below the tip \(r = 23\.992 mm\)/);
  assert.match(r.wheelProfile.edge, /The face figures above r = 23\.915 mm are not what the machine grinds; do not rely on them\./);
  // The profile's points do not show it: R falls over the last interval too, the turn and the way
  // back lying inside it. The meridian's speed at each point finds it (wheel_profile_turn.h).
  const R = r.wheelProfile.R, n = R.length;
  assert.ok(R[n - 1] < R[n - 2] && R[n - 2] < R[n - 3], 'the sampled profile falls to the tip');

  const p = hobsharp.evaluate(paper());
  assert.equal(p.wheelProfile.edge, '');
  assert.equal(p.wheelProfile.turnRadius, p.setup.outerRadius);
  // The page's warning (views/wheel-edge.js) is the module's sentence, and nothing for Tab. 1.
  assert.equal(wheelEdgeText(r), r.wheelProfile.edge);
  assert.equal(wheelEdgeText(p), '');
  assert.equal(wheelEdgeText(undefined), '');

  const dressed = edgeCase();
  const Rs = r.wheelProfile.R, lo = Math.min(...Rs), hi = Math.max(...Rs);
  dressed.wheel.profileOffset = { R: [lo, (lo + hi) / 2, hi], offset: [0, 0, 0] };
  assert.throws(() => hobsharp.evaluate(dressed), (e) => e instanceof HobSharpError && e.field === 'setup.tilt' &&
    /^Setup: a dressed wheel cannot be simulated near r = 23\.992 mm, x = .* The wheel cannot grind the top 0\.077 mm/.test(e.message) &&
    !/Wheel file/.test(e.message));
  assert.ok(hobsharp.evaluate(paper()).topography, 'the module lives on');
});
