// Differences between a result and a pinned one (now minus pinned), for the views to show while
// a result is pinned. Pure. Each returns null where the two cannot be compared (another degree,
// another motion parameter, another grid), so that a view says so instead of subtracting unlike
// things.
import { AXES } from './limits.js';

const unitOf = (r) => (r.setup.motionUnit === 'mm' ? 'mm' : 'rad');

// Coefficient by coefficient, axis by axis: {X: [...], ...}, or null.
export function axesDifference(now, pinned, rNow, rPinned) {
  if (!now || !pinned || unitOf(rNow) !== unitOf(rPinned)) return null;
  const out = {};
  for (const a of AXES) {
    if (!now[a] || !pinned[a] || now[a].length !== pinned[a].length) return null;
    out[a] = now[a].map((v, k) => v - pinned[a][k]);
  }
  return out;
}

// Point by point on the grid, or null when the grids differ in shape or place (within 1 nm).
export function gridDifference(now, pinned, rNow, rPinned) {
  if (!now || !pinned || now.length !== pinned.length) return null;
  const same = (a, b) => a.length === b.length && a.every((v, i) => Math.abs(v - b[i]) <= 1e-6);
  if (!same(rNow.topography.r, rPinned.topography.r) || !same(rNow.topography.x, rPinned.topography.x)) return null;
  if (!now.every((row, i) => row.length === pinned[i].length)) return null;
  return now.map((row, i) => row.map((v, j) => v - pinned[i][j]));
}

// A value of the pinned curve y(x) at x, by straight lines between its points; x ascending or
// descending; null outside its range.
function interpolate(xs, ys, x) {
  const up = xs[xs.length - 1] >= xs[0];
  for (let i = 1; i < xs.length; i++) {
    const [a, b] = up ? [xs[i - 1], xs[i]] : [xs[i], xs[i - 1]];
    if (x >= a - 1e-9 && x <= b + 1e-9) {
      const f = xs[i] === xs[i - 1] ? 0 : (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
      return ys[i - 1] + f * (ys[i] - ys[i - 1]);
    }
  }
  return null;
}

// The wheel profile against the pinned one at the same tooth-face radii r: dR and dZ in µm (null
// where r lies outside the pinned profile), and the largest of each with its radius.
export function profileDifference(now, pinned) {
  if (!now || !pinned || pinned.r.length < 2) return null;
  const dR = [], dZ = [];
  let maxR = null, maxZ = null;
  now.r.forEach((r, i) => {
    const R = interpolate(pinned.r, pinned.R, r), Z = interpolate(pinned.r, pinned.Z, r);
    dR.push(R === null ? null : (now.R[i] - R) * 1000);
    dZ.push(Z === null ? null : (now.Z[i] - Z) * 1000);
    if (R !== null && (!maxR || Math.abs(dR[i]) > Math.abs(maxR.value))) maxR = { value: dR[i], r };
    if (Z !== null && (!maxZ || Math.abs(dZ[i]) > Math.abs(maxZ.value))) maxZ = { value: dZ[i], r };
  });
  return maxR ? { r: now.r, dR, dZ, maxR, maxZ } : null;
}

// Figures (sum of squares, largest deviation, thickness error ...) as now minus pinned, by name.
export function figuresDifference(now, pinned) {
  const out = {};
  for (const [name, v] of Object.entries(now || {})) {
    const p = pinned ? pinned[name] : undefined;
    out[name] = typeof v === 'number' && typeof p === 'number' ? v - p : null;
  }
  return out;
}

// The inputs that differ between two cases, as [{path, from, to}]: the numbers and choices of
// the form by their path; a measured grid, run axes or locks as a whole.
export function changedInputs(now, pinned) {
  const out = [];
  const walk = (a, b, path) => {
    const whole = /^(measured|axes|correction)$/.test(path);
    const isObj = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
    if (!whole && (isObj(a) || isObj(b))) {
      const keys = new Set([...Object.keys(isObj(a) ? a : {}), ...Object.keys(isObj(b) ? b : {})]);
      for (const k of keys) walk(isObj(a) ? a[k] : undefined, isObj(b) ? b[k] : undefined, path ? `${path}.${k}` : k);
    } else if (JSON.stringify(a) !== JSON.stringify(b)) {
      out.push({ path, from: b, to: a });
    }
  };
  walk(now || {}, pinned || {}, '');
  return out;
}
