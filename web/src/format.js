// Formatting: every number on the page goes through these; nothing that is not finite is shown.
import { superscript } from './limits.js';
import { fixed } from '../../wasm/lib/number-text.js';

export function fmt(v, significant = 7) {
  if (typeof v !== 'number' || !Number.isFinite(v)) return '—';
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a < 1e-4 || a >= 1e7) return v.toExponential(Math.max(0, significant - 3));
  return String(Number(v.toPrecision(significant)));
}

// A face figure to `significant` digits; a non-zero one below `least` (what no probe tells apart
// from zero: 0.001 µm, 1e-6 µm² of sum of squares) as "below 0.001", never a solver's 2e-11.
// The least face rms the page writes, µm: below it an rms reads "below 0.001".
export const LEAST_RMS = 0.001;
export function faceFigure(v, least, significant = 3) {
  if (typeof v === 'number' && v !== 0 && Math.abs(v) < least) return `below ${least}`;
  return fmt(v, significant);
}

// v with `digits` decimals, never "-0.000" (wasm/lib/number-text.js, shared with the file writers).
export { fixed };

// A face rms in µm for a sentence: to the nanometre (3 decimals) below 10 µm, above it to 4
// significant digits ("149.3", "6177"): a probe tells no nanometre on a face of millimetres.
export function rmsFixed(v) {
  const a = Math.abs(v);
  return fixed(v, Number.isFinite(a) && a >= 10 ? Math.max(0, 3 - Math.floor(Math.log10(a))) : 3);
}

// The same with a + on a positive value (one that does not round to zero).
export function signed(v, digits) {
  const text = fixed(v, digits);
  return text !== '—' && v > 0 && Number(text) !== 0 ? `+${text}` : text;
}

// The motion parameter: phi_1 in rad for a helical gash, s in mm for a straight one.
export function motionUnit(result) { return result && result.setup.motionUnit === 'mm' ? 'mm' : 'rad'; }
export function motionSymbol(result) { return motionUnit(result) === 'mm' ? 's' : 'φ₁'; }

// a0 + a1 t + a2 t² ... as text, zero terms left out, with typographic minus signs.
export function polynomialText(coefficients, symbol) {
  const terms = [];
  coefficients.forEach((c, k) => {
    if (c === 0 && !(k === 0 && coefficients.every((x) => x === 0))) return;
    const value = fmt(Math.abs(c), 7);
    const sign = c < 0 ? '−' : '+';
    const power = k === 0 ? '' : k === 1 ? ` ${symbol}` : ` ${symbol}${superscript(k)}`;
    terms.push({ sign, text: `${value}${power}` });
  });
  return terms.map((t, i) => (i === 0 ? (t.sign === '−' ? '−' : '') : ` ${t.sign} `) + t.text).join('');
}

// A figure with its unit as the schema states it (result-fields.js): deg as ° and arc-min as ′ after
// the number, "per deg" as "per degree"; any other unit after a space.
export function withUnit(text, unit) {
  if (!unit) return text;
  const m = /^(deg|arc-min)(.*)$/.exec(unit);
  if (m) return `${text}${m[1] === 'deg' ? '°' : '′'}${m[2].replace(/\bper deg$/, 'per degree')}`;
  return `${text} ${unit}`;
}

// Text for HTML: the page's own strings go into innerHTML only through this.
export function escapeHtml(text) {
  return String(text).replace(/[&<>"']/g, (ch) => `&#${ch.charCodeAt(0)};`);
}
