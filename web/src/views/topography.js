// The deviation topography of the rake face, before and after correction, normal or circular:
// the figures (sum of squares, largest deviation, thickness error), a 3D surface and a map.
import { fixed, fmt, signed } from '../format.js';
import { DEVIATION_SCALE, colourRange } from '../plots/colours.js';
import { gridFigures } from '../figures.js';
import { clearSurface, drawSurface } from '../plots/surface.js';
import { comparedToPinned } from './pin.js';

const $ = (selector) => document.querySelector(selector);
const AXIS_X = 'x, along the gash (mm)', AXIS_R = 'r, root → tip (mm)';

// The circular view's sum of squares and largest deviation are of its own grid; the thickness
// error is the same in both views (the circular deviation at the mean point).
const numbersOf = (sse, max, thickness, circularGrid) =>
  (circularGrid ? { ...gridFigures(circularGrid), thickness } : { sse, max, thickness });

function figuresText({ sse, max, thickness }) {
  return `Sum of squares ${fmt(sse, 6)} µm² · largest |deviation| ${fixed(max, 3)} µm · thickness error ${signed(thickness, 3)} µm`;
}

// What the two columns show for a result: the simulated face, or measured and after correction
// (with their figures as numbers, for a comparison with a pinned result).
function topographyViews(r, caseObject, view) {
  const circular = view === 'circular';
  const viewName = circular ? 'circular deviation' : 'normal deviation';
  if (r.correction) {
    const c = r.correction;
    const beforeNumbers = numbersOf(c.sseBefore, c.maxBefore, c.thicknessBefore, circular && c.measuredCircular);
    const afterNumbers = numbersOf(c.sseAfter, c.maxAfter, c.thicknessAfter, circular && c.residualCircular);
    return {
      beforeTitle: 'Measured',
      before: circular ? c.measuredCircular : caseObject.measured, beforeName: `Measured ${viewName}`,
      beforeNumbers, beforeFigures: figuresText(beforeNumbers),
      after: circular ? c.residualCircular : c.residual, afterName: `After correction, ${viewName}`,
      afterNumbers, afterFigures: figuresText(afterNumbers),
    };
  }
  const t = r.topography;
  const beforeNumbers = numbersOf(t.sse, t.max, t.thickness, circular && t.circular);
  return {
    beforeTitle: 'Ground face (simulated for the axes run)',
    before: circular ? t.circular : t.normal, beforeName: `Simulated ${viewName}`,
    beforeNumbers, beforeFigures: figuresText(beforeNumbers),
    after: null, afterFigures: 'No correction yet: give a measured topography below.',
  };
}

// What is shown: a result's own views, or, while a result is pinned, their difference to it.
const shown = (state) => comparedToPinned(topographyViews(state.result, state.resultCase, state.view), state, topographyViews);

function renderFigures(state) {
  const v = shown(state);
  $('#before-title').textContent = v.beforeTitle;
  $('#figures-before').textContent = v.beforeFigures;
  $('#figures-after').textContent = v.afterFigures;
}

function drawSurfaces({ result: r, state }) {
  const v = shown(state);
  const { x, r: radii } = r.topography;
  const surface = (id, z, title) => drawSurface($(id), {
    x, y: radii, z, range: colourRange(z), height: 380, title: `${title} (3D)`,
    axes: { x: AXIS_X, y: AXIS_R, z: 'deviation (µm)' },
    hover: (i, j) => [`x = ${fixed(x[j], 2)} mm along the gash`, `r = ${fixed(radii[i], 2)} mm`, `deviation ${fixed(z[i][j], 3)} µm`],
  });
  surface('#plot-before-3d', v.before, v.beforeName);
  if (v.after) surface('#plot-after-3d', v.after, v.afterName);
  else clearSurface($('#plot-after-3d'));
}

function drawMaps({ Plotly, result: r, state }) {
  const v = shown(state);
  const map = (id, z, title) => {
    const range = colourRange(z);
    return Plotly.react(id, [{
      type: 'heatmap', x: r.topography.x, y: r.topography.r, z,
      colorscale: DEVIATION_SCALE, zmin: -range, zmax: range, colorbar: { title: { text: 'µm' } },
      hovertemplate: 'x = %{x:.2f} mm<br>r = %{y:.2f} mm<br>%{z:.3f} µm<extra></extra>',
    }], {
      title: { text: `${title} (map)` }, height: 300, margin: { t: 40, r: 10, b: 50, l: 60 },
      xaxis: { title: { text: AXIS_X } }, yaxis: { title: { text: AXIS_R } },
    }, { responsive: true, displaylogo: false });
  };
  return Promise.all([map('plot-before-2d', v.before, v.beforeName),
    v.after ? map('plot-after-2d', v.after, v.afterName) : Plotly.purge('plot-after-2d')]);
}

export function mountTopography(store, plots) {
  store.on('result', (_, state) => renderFigures(state));
  store.on('view', (_, state) => { if (state.result) renderFigures(state); });
  for (const input of document.querySelectorAll('input[name="view"]')) {
    input.addEventListener('change', () => store.setView(input.value));
  }
  plots.add(drawSurfaces, { plotly: false });
  plots.add(drawMaps, { plotly: true });
}
