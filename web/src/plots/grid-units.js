// The units of the face's grids as the module states them (result-fields.js): r and x of the
// topography's grid lines and the deviation of every grid the maps and surfaces draw (the
// topography, the correction's residual, the wheel split, a difference to a pinned result: each
// in the topography's unit). '' until the module has described its results.
import { unitText } from '../result-fields.js';

export const gridUnits = () => ({
  r: unitText('topography.r'), x: unitText('topography.x'), z: unitText('topography.normal'),
});

// The axis titles of a map or a surface, with those units.
export function gridAxisTitles(u = gridUnits()) {
  return { x: `x along the gash (${u.x})`, y: `r root to tip (${u.r})`, z: `deviation (${u.z})` };
}

// The pointer's text over a grid point: r, x and the deviation (named `what`) with their units.
export function gridHover(u = gridUnits(), { what = 'deviation', value = '%{z:.3f}', lead = '' } = {}) {
  return `${lead}r = %{y:.2f} ${u.r}<br>x = %{x:.2f} ${u.x}<br>${what} ${value} ${u.z}<extra></extra>`;
}
