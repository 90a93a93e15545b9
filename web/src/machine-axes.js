// The axes in the units a sharpening machine's control takes (pure, with Node tests): X, Y, Z in
// mm and A, B in degrees, each a polynomial of the hob rotation in degrees (helical gash) or of
// the travel in mm (straight gash), and a table of axis positions over the motion range.
// The calculator's polynomials are of phi in rad with A and B in rad (docs/conventions.md).
import { AXES, isRotary } from './limits.js';
import { fmt } from './format.js';
import { polynomialAt } from './polynomial.js';

const DEG = 180 / Math.PI;

// Coefficient a_k of an axis, converted: value factor (deg per rad for A and B) times
// (rad per deg)^k for the motion in degrees (helical); a straight gash's motion stays in mm.
export function machineCoefficients(axes, helical) {
  const out = {};
  for (const a of AXES) {
    const value = isRotary(a) ? DEG : 1;
    out[a] = axes[a].map((c, k) => c * value * (helical ? DEG ** -k : 1));
  }
  return out;
}

export const machineUnit = (axis, k, helical) => {
  const base = isRotary(axis) ? 'deg' : 'mm';
  if (k === 0) return base;
  const per = helical ? 'deg' : 'mm';
  return `${base}/${per}${k > 1 ? `^${k}` : ''}`;
};

// Positions over the motion range [min, max] (rad or mm, as the result gives it), every `step`
// (deg or mm) from min, both ends included: rows [motion (deg or mm), X, Y, Z (mm), A, B (deg)].
// Throws an Error naming the step when it is not a positive number or gives too many rows.
export const MAX_POSITION_ROWS = 10001;
export function axisPositions(axes, min, max, step, helical) {
  if (!(Number.isFinite(step) && step > 0)) throw new Error(`Step: must be a positive number of ${helical ? 'degrees' : 'mm'}; got ${step}.`);
  const lo = helical ? min * DEG : min, hi = helical ? max * DEG : max;
  const n = Math.floor((hi - lo) / step + 1e-9);
  if (n + 2 > MAX_POSITION_ROWS) throw new Error(`Step: ${step} ${helical ? 'deg' : 'mm'} gives more than ${MAX_POSITION_ROWS} rows over the motion range (${(hi - lo).toFixed(3)} ${helical ? 'deg' : 'mm'}); take a larger step.`);
  const m = machineCoefficients(axes, helical);
  const at = (t) => [t, ...AXES.map((a) => polynomialAt(m[a], t))];
  const rows = [];
  for (let i = 0; i <= n; i++) rows.push(at(lo + i * step));
  if (hi - rows[rows.length - 1][0] > 1e-9 * Math.max(1, Math.abs(hi))) rows.push(at(hi));
  return rows;
}

export function positionsCsv(rows, helical) {
  const head = [helical ? 'hob rotation (deg)' : 'travel (mm)', ...AXES.map((a) => `${a} (${isRotary(a) ? 'deg' : 'mm'})`)];
  return '\uFEFF' + [head.join(','), ...rows.map((r) => r.join(','))].join('\n') + '\n';
}

// A coefficient as the NC program carries it: `digits` significant digits (limits().correction.
// coefficientDigits, the digits correction.roundedAxes is rounded to), no more.
export const programmed = (c, digits) => String(Number(c.toPrecision(digits)));

// The coefficients as text for the clipboard: one line per axis, each to `digits` significant digits.
export function coefficientsText(m, helical, digits) {
  const symbol = helical ? 'phi (deg)' : 's (mm)';
  const p = (c) => programmed(c, digits);
  return AXES.map((a) => `${a} (${isRotary(a) ? 'deg' : 'mm'}) = ${m[a].map((c, k) => (k === 0 ? p(c) : `${c >= 0 ? '+ ' : '- '}${p(Math.abs(c))} * ${symbol}${k > 1 ? `^${k}` : ''}`)).join(' ')}`).join('\n') + '\n';
}

// The face predicted with the rounded axes and the pass's floor the position resolution sets, in
// words with the units `unitOf(path)` gives (the module's resultFields()); '' without them.
export function roundedFiguresText(c, unitOf) {
  if (!c || !c.roundedAxes) return '';
  const v = (path) => {
    const x = c[path.slice('correction.'.length)];
    return `${fmt(x, 3)}${Number.isFinite(x) ? ` ${unitOf(path)}` : ''}`;
  };
  return `With these axes the face is predicted at ${v('correction.rmsRounded')} rms (re-simulated). ` +
    `The floor the position resolution sets (each axis position quantised to its step): ${v('correction.resolutionFloor')} rms.`;
}
