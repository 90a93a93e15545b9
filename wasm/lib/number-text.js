// Numbers as text in files and on the page (web/src/format.js re-exports it). Pure.

// v with `digits` decimals; a value that rounds to zero is "0.000", never "-0.000".
export function fixed(v, digits) {
  if (typeof v !== 'number' || !Number.isFinite(v)) return '—';
  const text = v.toFixed(digits);
  return Number(text) === 0 ? (0).toFixed(digits) : text;
}
