// The deviation colour scale, the same in every plot: red is a deficit of material, grey none,
// blue an excess (Plotly's RdBu, reversed), symmetric about zero.
import { gridUnits } from './grid-units.js';
export const DEVIATION_SCALE = [
  [0, 'rgb(178,10,28)'], [0.3, 'rgb(230,145,90)'], [0.4, 'rgb(220,170,132)'],
  [0.5, 'rgb(190,190,190)'], [0.65, 'rgb(106,137,247)'], [1, 'rgb(5,10,172)'],
];

// The scale's range for one or more grids: the largest |value| of them all, at least 0.1 µm.
// Plots that are to be compared (measured and after correction) take one range together.
export function colourRange(...grids) {
  let m = 0;
  for (const z of grids) if (z) for (const row of z) for (const v of row) m = Math.max(m, Math.abs(v));
  return Math.max(m, 0.1);
}

// The colour bar beside a deviation plot says what the colours mean, in the grids' unit.
export function deviationColourBar() {
  return {
    title: { text: `${gridUnits().z}<br><span style="color:rgb(5,10,172)">blue: excess<br>material</span><br>` +
                   '<span style="color:rgb(178,10,28)">red: deficit</span>', side: 'top' },
    thickness: 14, len: 0.9, outlinewidth: 0,
  };
}
