import { withUnit } from './format.js';
import { fieldLabel, fieldUnit } from './result-fields.js';

// The figures of a deviation grid (rows of µm) as the page shows them beside its map: the rms and
// the peak-to-valley (comparable between grids), the largest absolute deviation, and the sum of
// squares (the paper's figure). The result carries them for the normal deviation; the circular
// view computes its own from its grid. A value that is not finite makes all NaN (shown as a
// dash), never a figure that leaves it out.
export function gridFigures(grid) {
  let sse = 0, max = 0, hi = -Infinity, lo = Infinity, n = 0;
  for (const row of grid) {
    for (const v of row) {
      if (!Number.isFinite(v)) return { sse: NaN, max: NaN, rms: NaN, peakToValley: NaN };
      sse += v * v;
      max = Math.max(max, Math.abs(v));
      hi = Math.max(hi, v);
      lo = Math.min(lo, v);
      n += 1;
    }
  }
  return { sse, max, rms: n ? Math.sqrt(sse / n) : NaN, peakToValley: n ? hi - lo : NaN };
}

// The face's figures as the result names them (topography.<name>, correction.<name>Before and
// <name>After), in the order the page gives them: those that compare between grids of any density
// first, the paper's sum of squares last. Their labels and units are the module's
// (result-fields.js).
export const FACE_FIGURES = ['rms', 'peakToValley', 'max', 'thickness', 'sse'];

// "label value unit" for each figure q of `names`: the label and unit of the field pathOf(q) names
// (result-fields.js), the value as text(q) writes it.
export function figureTexts(names, pathOf, text) {
  return names.map((q) => `${fieldLabel(pathOf(q))} ${withUnit(text(q), fieldUnit(pathOf(q)) || '')}`);
}
