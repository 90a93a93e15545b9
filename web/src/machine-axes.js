// The axes in the units a sharpening machine's control takes (pure, with Node tests): X, Y, Z in
// mm and A, B in degrees, each a polynomial of the hob rotation in degrees (helical gash) or of
// the travel in mm (straight gash), and a table of axis positions over the motion range.
// The calculator's polynomials are of phi in rad with A and B in rad (docs/conventions.md).
// The converted polynomials, the axes to run and their NC program, shared with the CLI, are
// wasm/lib/axes-to-run.js.
import { AXES, isRotary } from './limits.js';
import { fmt } from './format.js';
import { polynomialAt } from '../../wasm/lib/polynomial.js';
import { machineCoefficients } from '../../wasm/lib/axes-to-run.js';
import { keepsAxesRun } from '../../wasm/lib/pass-bound.js';

const DEG = 180 / Math.PI;

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

// A position as the table writes it: POSITION_DECIMALS decimals (1 nm, 1e-6 deg: ten times finer
// than the machine's 0.1 µm and 1e-4 deg), no negative zero.
export const POSITION_DECIMALS = 6;
export function positionText(x, decimals = POSITION_DECIMALS) {
  const s = x.toFixed(decimals);
  return /^-0\.?0*$/.test(s) ? s.slice(1) : s;
}

// The positions as CSV: a comma and a decimal point, or (decimalComma, the page's "1,5; 2,5"
// choice) a semicolon and a decimal comma as a German spreadsheet reads them.
export function positionsCsv(rows, helical, { decimalComma = false } = {}) {
  const sep = decimalComma ? ';' : ',';
  const num = (x) => (decimalComma ? positionText(x).replace('.', ',') : positionText(x));
  const head = [helical ? 'hob rotation (deg)' : 'travel (mm)', ...AXES.map((a) => `${a} (${isRotary(a) ? 'deg' : 'mm'})`)];
  return '\uFEFF' + [head.join(sep), ...rows.map((r) => r.map(num).join(sep))].join('\n') + '\n';
}

// A coefficient as the NC program carries it: `digits` significant digits (limits().correction.
// coefficientDigits, the digits correction.roundedAxes is rounded to), no more.
export const programmed = (c, digits) => String(Number(c.toPrecision(digits)));

// The coefficients as text for the clipboard: one line per axis, each to `digits` significant digits.
export function coefficientsText(m, helical, digits) {
  const symbol = helical ? 'phi (deg)' : 's (mm)';
  const p = (c) => programmed(c, digits);
  // A term that rounds to 0 is left out (no "+ 0 * phi^2"); an axis with none left reads 0.
  const line = (a) => {
    const terms = m[a].map((c, k) => [Number(p(c)), k]).filter(([c]) => c !== 0);
    if (!terms.length) return '0';
    return terms.map(([c, k], i) => {
      const sign = c < 0 ? '-' : '+';
      const value = k === 0 ? p(Math.abs(c)) : `${p(Math.abs(c))} * ${symbol}${k > 1 ? `^${k}` : ''}`;
      return i === 0 ? `${c < 0 ? '-' : ''}${value}` : `${sign} ${value}`;
    }).join(' ');
  };
  return AXES.map((a) => `${a} (${isRotary(a) ? 'deg' : 'mm'}) = ${line(a)}`).join('\n') + '\n';
}

// The face the rounded axes grind on the identified machine (re-simulated with the identified
// error, the measurement's misfit kept, noise and all; what the pass leaves is the verdict's bound) and the pass's floor the position resolution sets, in
// words with the units `unitOf(path)` gives (the module's resultFields()); '' without them.
export function roundedFiguresText(c, unitOf) {
  // The axes shown are the axes run where the correction stops or changes nothing: no proposal to speak of.
  if (!c || !c.roundedAxes || keepsAxesRun(c)) return '';
  const v = (path) => {
    const x = c[path.slice('correction.'.length)];
    return `${fmt(x, 3)}${Number.isFinite(x) ? ` ${unitOf(path)}` : ''}`;
  };
  return `With these axes the identified machine grinds ${v('correction.rmsRounded')} rms (re-simulated, this measurement's misfit kept; the exact axes leave at most the verdict's bound). ` +
    `The floor the position resolution sets (each axis position quantised to its step): ${v('correction.resolutionFloor')} rms.`;
}

// The program in words beside its buttons: its blocks and its largest deviation from the axes.
export function programNote(p) {
  const kind = p.dialect === 'heidenhain' ? 'SPL' : 'POLY';
  return `${p.pieces} ${kind} block${p.pieces > 1 ? 's' : ''} of degree ${p.degree} at most; largest deviation from the axes ` +
    `${fmt(p.largestDeviation.linear, 2)} µm (X, Y, Z), ${fmt(p.largestDeviation.rotary, 2)}° (A, B).`;
}
