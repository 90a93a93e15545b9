// The deviation topography of the rake face, before and after correction, normal or circular
// (a measurement at the machine's own points marked on both maps):
// the figures (rms, peak-to-valley, largest deviation, thickness error, sum of squares), a map and, on demand, a 3D
// surface.
import { fixed, fmt, signed } from '../format.js';
import { colourRange } from '../plots/colours.js';
import { drawMap } from '../plots/maps.js';
import { drawSurface } from '../plots/surface.js';
import { purgePlot } from '../plots/config.js';
import { FACE_FIGURES, figureTexts, gridFigures } from '../figures.js';
import { comparedToPinned } from './pin.js';

const $ = (selector) => document.querySelector(selector);

// The circular view's sum of squares and largest deviation are of its own grid; the thickness
// error is the same in both views (the circular deviation at the mean point).
const numbersOf = (f, circularGrid) =>
  (circularGrid ? { ...gridFigures(circularGrid), thickness: f.thickness } : f);

// Led by the figures that compare between grids of any density; the paper's sum of squares last.
// Labels and units are the module's (topography.<figure>).
const DIGITS = { rms: (v) => fixed(v, 3), peakToValley: (v) => fixed(v, 3), max: (v) => fixed(v, 3), thickness: (v) => signed(v, 3),
  sse: (v) => fmt(v, 6) };
function figuresText(numbers) {
  return figureTexts(FACE_FIGURES, (q) => `topography.${q}`, (q) => DIGITS[q](numbers[q])).join(' · ');
}

// What the two columns show for a result: the simulated face, or measured and after correction
// (with their figures as numbers, for a comparison with a pinned result).
function topographyViews(r, caseObject, view) {
  const circular = view === 'circular';
  const viewName = circular ? 'circular deviation' : 'normal deviation';
  if (r.correction) {
    const c = r.correction;
    // Points off the grid (docs/measured-points.md): the figures are the points' in both views (the
    // circular grids are the faces the identified error grinds, without the points' misfit: their
    // figures would show a face after the pass with nothing left), the maps those faces.
    const points = Boolean(c.pointMeasured);
    const beforeNumbers = numbersOf({ sse: c.sseBefore, max: c.maxBefore, thickness: c.thicknessBefore, rms: c.rmsBefore,
      peakToValley: c.peakToValleyBefore }, circular && !points && c.measuredCircular);
    const afterNumbers = numbersOf({ sse: c.sseAfter, max: c.maxAfter, thickness: c.thicknessAfter, rms: c.rmsAfter,
      peakToValley: c.peakToValleyAfter }, circular && !points && c.residualCircular);
    return {
      beforeTitle: points
        ? `Measured at ${c.pointMeasured.length} points (figures at the points${circular ? ', normal deviation' : ''}; map: as the axes explain it)`
        : 'Measured',
      before: circular ? c.measuredCircular : caseObject.measured || c.measuredOnGrid, beforeName: `Measured ${viewName}`,
      beforeNumbers, beforeFigures: figuresText(beforeNumbers),
      after: circular ? c.residualCircular : c.residual, afterName: `After correction, ${viewName}`,
      afterNumbers,
      afterFigures: (points ? `At the ${c.pointMeasured.length} points${circular ? ', normal deviation' : ''}: ` : '') + figuresText(afterNumbers),
      // Where the probe touched, marked on both maps, with the point's own figure.
      beforePoints: c.pointMeasured ? { list: c.pointMeasured, what: 'measured normal deviation' } : null,
      afterPoints: c.pointResidual ? { list: c.pointResidual, what: 'normal deviation on the identified machine' } : null,
    };
  }
  const t = r.topography;
  const beforeNumbers = numbersOf({ sse: t.sse, max: t.max, thickness: t.thickness, rms: t.rms, peakToValley: t.peakToValley },
    circular && t.circular);
  return {
    beforeTitle: 'Ground face (simulated for the axes run)',
    before: circular ? t.circular : t.normal, beforeName: `Simulated ${viewName}`,
    beforeNumbers, beforeFigures: figuresText(beforeNumbers),
    after: null, afterFigures: 'No correction yet: give a measured topography in step 2 above.',
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

// The 3D surfaces are drawn only while "3D surfaces" is ticked (state.surfaces): Plotly's WebGL
// surface takes seconds in a browser without a graphics card, so the maps come first and alone by default.

// Measured and after correction share one colour range (and z range), so that they compare.
function drawSurfaces({ Plotly, result: r, state }) {
  const v = shown(state);
  const [before, after] = [$('#plot-before-3d'), $('#plot-after-3d')];
  if (!state.surfaces) return;
  const range = colourRange(v.before, v.after);
  const spec = (z, title) => ({ x: r.topography.x, y: r.topography.r, z, range, title });
  after.hidden = !v.after;
  return Promise.all([drawSurface(Plotly, before, spec(v.before, v.beforeName)),
    v.after ? drawSurface(Plotly, after, spec(v.after, v.afterName)) : purgePlot(Plotly, after)]);
}

function drawMaps({ Plotly, result: r, state }) {
  const v = shown(state);
  const range = colourRange(v.before, v.after);
  const spec = (z, title, points) => ({ x: r.topography.x, y: r.topography.r, z, range, title, points });
  return Promise.all([drawMap(Plotly, 'plot-before-2d', spec(v.before, v.beforeName, v.beforePoints)),
    v.after ? drawMap(Plotly, 'plot-after-2d', spec(v.after, v.afterName, v.afterPoints)) : purgePlot(Plotly, 'plot-after-2d')]);
}

// The switch shows state.surfaces (a loaded case or link may set it); opening the surfaces draws
// them, closing them frees their WebGL.
function mount3dSwitch(store, plots) {
  $('#show-3d').addEventListener('change', (event) => store.setSurfaces(event.target.checked));
  store.on('surfaces', (_, state) => {
    const [before, after] = [$('#plot-before-3d'), $('#plot-after-3d')];
    $('#show-3d').checked = state.surfaces;
    before.hidden = after.hidden = !state.surfaces;
    if (state.surfaces) plots.redraw();
    else if (self.Plotly) { purgePlot(self.Plotly, before); purgePlot(self.Plotly, after); }
  });
}

export function mountTopography(store, plots) {
  const radios = document.querySelectorAll('input[name="view"]');
  store.on('result', (_, state) => renderFigures(state));
  store.on('view', (_, state) => {
    for (const input of radios) input.checked = input.value === state.view;  // a loaded case may set it
    if (state.result) renderFigures(state);
  });
  for (const input of radios) input.addEventListener('change', () => store.setView(input.value));
  mount3dSwitch(store, plots);
  plots.add(drawMaps);
  plots.add(drawSurfaces, { later: true });
}
