// The deviation colour scale, the same in every plot: red is a deficit of material, grey none,
// blue an excess (Plotly's RdBu, reversed), symmetric about zero.
const STOPS = [
  [0, [178, 10, 28]], [0.3, [230, 145, 90]], [0.4, [220, 170, 132]],
  [0.5, [190, 190, 190]], [0.65, [106, 137, 247]], [1, [5, 10, 172]],
];

// For Plotly: [[0, 'rgb(...)'], ...].
export const DEVIATION_SCALE = STOPS.map(([t, c]) => [t, `rgb(${c.join(',')})`]);

function interpolate(t) {
  let k = 1;
  while (k < STOPS.length - 1 && STOPS[k][0] < t) k++;
  const [t0, c0] = STOPS[k - 1], [t1, c1] = STOPS[k];
  const f = t1 > t0 ? (t - t0) / (t1 - t0) : 0;
  return c0.map((c, i) => Math.round(c + (c1[i] - c) * f));
}
const STEPS = 511;
const TABLE = Array.from({ length: STEPS + 1 }, (_, k) => interpolate(k / STEPS));

// The colour of a value in -range..range, as [r, g, b] (one of 512 steps); `shade` darkens it.
export function colourOf(value, range, shade = 1) {
  const t = Math.min(1, Math.max(0, (value / range + 1) / 2));
  const c = TABLE[Math.round(t * STEPS)] || TABLE[STEPS / 2 + 0.5];
  return shade === 1 ? c : c.map((v) => Math.round(v * shade));
}

export const css = (rgb) => `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;

// The largest |value| of a grid, at least 0.1 µm: the scale's range.
export function colourRange(z) {
  let m = 0;
  for (const row of z) for (const v of row) m = Math.max(m, Math.abs(v));
  return Math.max(m, 0.1);
}

// About `count` round tick values from lo to hi.
export function ticks(lo, hi, count = 5) {
  const span = hi - lo;
  if (!(span > 0)) return [lo];
  const raw = span / count;
  const power = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * power).find((s) => s >= raw);
  const out = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return out;
}

export const tickText = (v) => String(Number(v.toPrecision(6)));
