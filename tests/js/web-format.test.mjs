// The page's formatting (web/src/format.js, web/src/limits.js): every number shown goes through it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { escapeHtml, fixed, fmt, motionSymbol, motionUnit, polynomialText, signed, rmsFixed } from '../../web/src/format.js';
import { coefficientUnit, setModuleLimits } from '../../web/src/limits.js';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';

setModuleLimits((await loadHobSharp()).limits());  // the axes' units, as the page has them once its calculator is ready

test('fmt gives 7 significant digits, exponents for tiny and huge values, and a dash for what is not finite', () => {
  assert.equal(fmt(0), '0');
  assert.equal(fmt(1234.56789), '1234.568');
  assert.equal(fmt(-0.000123456789), '-0.0001234568');
  assert.equal(fmt(1.5e-5), '1.5000e-5');
  assert.equal(fmt(2.5e8), '2.5000e+8');
  assert.equal(fmt(139.508856916, 9), '139.508857');
  for (const v of [NaN, Infinity, -Infinity, undefined, null, '3']) assert.equal(fmt(v), '—', String(v));
});

test('fixed and signed round, signed marks a positive value with +, neither shows NaN', () => {
  assert.equal(fixed(12.62584, 4), '12.6258');
  assert.equal(signed(15.6559, 3), '+15.656');
  assert.equal(signed(-0.25, 2), '-0.25');
  assert.equal(signed(0, 3), '0.000');
  for (const f of [fixed, signed]) for (const v of [NaN, Infinity, undefined]) assert.equal(f(v, 3), '—');
});

test('rmsFixed: a face rms to the nanometre below 10 µm, to 4 significant digits above, never NaN', () => {
  assert.equal(rmsFixed(3.2149), '3.215');
  assert.equal(rmsFixed(0.0523), '0.052');
  assert.equal(rmsFixed(149.31), '149.3');
  assert.equal(rmsFixed(6176.695), '6177', 'no false precision on a face of millimetres');
  assert.equal(rmsFixed(NaN), '—');
});

test('polynomialText writes Tab. 2 the way the paper does', () => {
  assert.equal(polynomialText([22.4003, 139.5089, 0, 0, 0], 'φ₁'), '22.4003 + 139.5089 φ₁');
  assert.equal(polynomialText([-116.446, 0, 0], 'φ₁'), '−116.446');
  assert.equal(polynomialText([0, 1, 0], 'φ₁'), '1 φ₁');
  assert.equal(polynomialText([0, 0, 0], 'φ₁'), '0');
  assert.equal(polynomialText([1, -2, 3, -4e-7], 's'), '1 − 2 s + 3 s² − 4.0000e-7 s³');
});

test('the motion parameter and the coefficient units follow the gash', () => {
  const helical = { setup: { motionUnit: 'rad' } }, straight = { setup: { motionUnit: 'mm' } };
  assert.equal(motionUnit(helical), 'rad');
  assert.equal(motionSymbol(helical), 'φ₁');
  assert.equal(motionUnit(straight), 'mm');
  assert.equal(motionSymbol(straight), 's');
  assert.equal(coefficientUnit('X', 0, 'rad'), 'mm');
  assert.equal(coefficientUnit('X', 1, 'rad'), 'mm/rad');
  assert.equal(coefficientUnit('A', 2, 'rad'), 'rad/rad²');
  assert.equal(coefficientUnit('B', 6, 'mm'), 'rad/mm⁶');
});

test('escapeHtml leaves no markup', () => {
  assert.equal(escapeHtml('<b a="1">x & \'y\'</b>'), '&#60;b a=&#34;1&#34;&#62;x &#38; &#39;y&#39;&#60;/b&#62;');
});
