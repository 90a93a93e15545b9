// The effect on the gear through the WebAssembly module (docs/gear-effect.md): the
// reason without the relief, a measured radial tilt giving fHα plus and a smaller pressure angle
// on both flanks as docs/gear-effect.md's first-order estimate says, the same figures as the native build,
// typed arrays, and bad relief input refused with the field named while the module stays usable.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { loadHobSharp, HobSharpError } from '../../wasm/hobsharp.mjs';
import { native, paper } from './native-build.mjs';

const hobsharp = await loadHobSharp();

const R = [19, 24.25, 29.5, 34.75, 40];
const X = [-70, -52.5, -35, -17.5, 0, 17.5, 35, 52.5, 70];
const grid = (f) => R.map((r) => X.map((x) => f(r, x)));
const withRelief = (c) => ({ ...c, hob: { ...c.hob, gashes: 12, relief: 4.5 } });

test('without the relief the result says what is missing, and nothing else', () => {
  const g = hobsharp.evaluate(paper()).gearEffect;
  assert.deepEqual(Object.keys(g), ['reason']);
  // In the hob form's words, never the case's names (issue 22).
  assert.equal(g.reason, 'No gear effect: no relief is given. Give the number of gashes z and the relief K (the cam rise over ' +
    'one gash pitch, mm), or the side relief angle, in the hob data.');
  const onlyRelief = hobsharp.evaluate({ ...paper(), hob: { ...paper().hob, relief: 4.5 } }).gearEffect;
  assert.match(onlyRelief.reason, /needs the number of gashes z with the relief K/);
  for (const reason of [g.reason, onlyRelief.reason]) assert.doesNotMatch(reason, /hob\./);
});

test('a measured radial tilt: fHα plus, the pressure angle smaller, as estimated; the same as native', () => {
  // 1 µm per mm about the pitch radius; relief 4.5 mm over 12 gashes: k = 8.594 mm/rad.
  const c = withRelief({ ...paper(), measured: grid((r) => 1.0 * (r - 31.25)) });
  const g = hobsharp.evaluate(c).gearEffect;
  assert.equal(g.reason, '');
  assert.equal(g.source, 'measured');
  assert.ok(Math.abs(g.reliefPerRadian - 4.5 * 12 / (2 * Math.PI)) < 1e-12);
  const k = g.reliefPerRadian, a = 20 * Math.PI / 180, helix = Math.atan(31.25 / (876.56 / (2 * Math.PI)));
  const estimate = -1e-3 * k / 31.25 * Math.sin(a) * Math.cos(a) / Math.cos(helix) * 180 / Math.PI * 60;  // arc-min
  for (const flank of ['left', 'right']) {
    assert.ok(g[flank].profileSlope > 1 && g[flank].profileSlope < 2, `${flank} fHα ${g[flank].profileSlope}`);
    assert.ok(Math.abs(g[flank].pressureAngleError - estimate) < 0.05 * Math.abs(estimate), `${flank} ${g[flank].pressureAngleError} vs ${estimate}`);
    assert.equal(g.alongHob[flank].profileSlope.length, 5);
  }
  assert.deepEqual(Array.from(g.alongHob.x).map((x) => Math.round(x * 1000) / 1000), [-43.982, -21.991, 0, 21.991, 43.982]);
  assert.equal(g.profile.left.length, 5);
  assert.equal(g.profile.left[0].length, g.profile.height.length);
  const n = native(c).gearEffect;
  assert.ok(Math.abs(n.left.profileSlope - g.left.profileSlope) < 1e-9);
  assert.ok(Math.abs(n.right.profileForm - g.right.profileForm) < 1e-9);
  assert.ok(Math.abs(n.profile.right[3][7] - g.profile.right[3][7]) < 1e-9);
  // With typed arrays (what the page's worker posts): lists are Float64Arrays, the matrix rows too.
  const t = hobsharp.evaluate(c, { typedArrays: true }).gearEffect;
  assert.ok(t.alongHob.x instanceof Float64Array);
  assert.equal(t.profile.left.length, 5);
  assert.ok(Math.abs(t.profile.left[2][10] - g.profile.left[2][10]) < 1e-15);
});

test('bad relief is refused with the field named, and the module stays usable', () => {
  for (const [hob, field] of [[{ gashes: 0, relief: 4.5 }, 'hob.gashes'], [{ gashes: 12, relief: -1 }, 'hob.relief'],
    [{ sideReliefAngle: 31 }, 'hob.sideReliefAngle'], [{ gashes: 12, relief: 4.5, sideReliefAngle: 3 }, 'hob.sideReliefAngle'],
    [{ relief: 4.5, sideReliefAngle: 5.373 }, 'hob.gashes']]) {
    assert.throws(() => hobsharp.evaluate({ ...paper(), hob: { ...paper().hob, ...hob } }), (e) => {
      assert.ok(e instanceof HobSharpError);
      assert.equal(e.code, 'InvalidInput');
      assert.equal(e.field, field);
      assert.ok(e.message.startsWith(`${field}: `), e.message);
      return true;
    });
  }
  assert.equal(hobsharp.evaluate(withRelief(paper())).gearEffect.reason, '');
});
