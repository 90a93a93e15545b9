// The figures of a deviation grid (rows of µm) as the page shows them beside its map: the sum of
// squares and the largest absolute deviation. The result carries them for the normal deviation;
// the circular view computes its own from its grid. A value that is not finite makes both NaN
// (shown as a dash), never a figure that leaves it out.
export function gridFigures(grid) {
  let sse = 0, max = 0;
  for (const row of grid) {
    for (const v of row) {
      if (!Number.isFinite(v)) return { sse: NaN, max: NaN };
      sse += v * v;
      max = Math.max(max, Math.abs(v));
    }
  }
  return { sse, max };
}
