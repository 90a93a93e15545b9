// With the wheel corrected too (correction.wheel): the measured face split into what the axes
// remove, what the wheel's proposed offset removes, and what is left (correction.residual), as
// three maps on one colour range, with the share of the measured sum of squares each removes.
import { fixed, withUnit } from '../format.js';
import { fieldLabel, unitText } from '../result-fields.js';
import { colourRange } from '../plots/colours.js';
import { drawMap } from '../plots/maps.js';
import { purgePlot } from '../plots/config.js';

const $ = (selector) => document.querySelector(selector);
const hasSplit = (r) => Boolean(r && r.correction && r.correction.removedByWheel && r.correction.removedByAxes);
const PLOTS = [['plot-removed-axes', 'removedByAxes', 'Removed by the axes'], ['plot-removed-wheel', 'removedByWheel', 'Removed by the wheel'],
  ['plot-left', 'residual', 'Left after both']];

export function shareText(c) {
  const pct = (v) => `${fixed(100 * v, 1)} %`;
  return `Of the measured sum of squares, the axes remove ${pct(c.axesShare)} and the wheel's proposed offset ${pct(c.wheelShare)}; ` +
    `${withUnit(fixed(c.rmsAfter, 3), unitText('correction.rmsAfter'))} ${fieldLabel('correction.rmsAfter')} is left on the identified machine (re-simulated with both; the pass may leave up to the verdict's bound).`;
}

function drawSplit({ Plotly, result: r }) {
  const box = $('#wheel-split');
  box.hidden = !hasSplit(r);
  if (!hasSplit(r)) return Promise.all(PLOTS.map(([id]) => purgePlot(Plotly, id)));
  const c = r.correction;
  $('#wheel-share').textContent = shareText(c);
  const range = colourRange(c.removedByAxes, c.removedByWheel, c.residual);
  return Promise.all(PLOTS.map(([id, key, title]) =>
    drawMap(Plotly, id, { x: r.topography.x, y: r.topography.r, z: c[key], range, title: `${title}, normal deviation` })));
}

export function mountWheelSplit(store, plots) {
  plots.add(drawSplit);
}
