// A deviation topography as a 3D surface: Plotly's surface trace (WebGL). Dragging turns it, the
// wheel zooms, and the pointer shows the grid point's r, x and deviation with their units.
import { DEVIATION_SCALE, deviationColourBar } from './colours.js';
import { isNarrowPlot, plotWidth, reactPlot } from './config.js';
import { gridAxisTitles, gridHover } from './grid-units.js';

// The box is 1.4 : 1 : 0.6, seen from far enough that the axis titles stay inside the plot: in a
// plot narrower than WIDE px (a half-width card), from further away in proportion, at most 1.3
// times. On a phone (narrower than NARROW_PLOT px) the colour bar lies under the scene, which then
// has the plot's whole width.
const WIDE = 760;
// narrow: isNarrowPlot of the plot, whose width (px, 0 when unknown) this is.
const scene = (width, narrow) => {
  // (On a phone the scene has the width the colour bar took beside it, and is seen a little nearer.)
  const k = narrow ? 1.1 : Math.min(1.3, Math.max(1, WIDE / (width || WIDE)));
  return {
    aspectmode: 'manual', aspectratio: { x: 1.4, y: 1, z: 0.6 },
    camera: { eye: { x: 2.0 * k, y: -2.9 * k, z: 1.5 * k }, center: { x: 0, y: 0, z: -0.12 } },
  };
};

// No zero lines (they stood out of the surface as stray vertical lines) and no spike lines.
const axis = (title, extra = {}) => ({
  title: { text: title, font: { size: 12 } }, tickfont: { size: 11 }, nticks: 5, zeroline: false, showspikes: false, ...extra,
});

// spec: {x (along the gash), y (radii), z (rows along y of values along x), range (± of the colour
// scale and of the z axis, shared with the plot it is compared with), title}
// The surface trace is registered on first use (see plotly-bundle.js).
export function drawSurface(Plotly, el, { x, y, z, range, title }) {
  self.plotlySurface();
  const titles = gridAxisTitles();
  const width = plotWidth(el);
  const narrow = isNarrowPlot(el);
  const bar = deviationColourBar();
  return reactPlot(Plotly, el, [{
    type: 'surface', x, y, z, cmin: -range, cmax: range, colorscale: DEVIATION_SCALE,
    colorbar: narrow ? { ...bar, orientation: 'h', x: 0.5, xanchor: 'center', y: 0, yanchor: 'top', len: 0.8,
      title: { ...bar.title, text: bar.title.text.replaceAll('<br>', ' '), side: 'top' } } : bar,
    hovertemplate: gridHover(),
  }], {
    // The title on the left, clear of the mode bar.
    title: { text: `${title} (3D)`, font: { size: 14 }, x: 0.02, xanchor: 'left' }, height: narrow ? 460 : 400,
    margin: { t: 36, r: 10, b: narrow ? 90 : 0, l: 0 },
    scene: {
      ...scene(width, narrow),
      xaxis: axis(titles.x), yaxis: axis(titles.y),
      zaxis: axis(titles.z, { range: [-range, range] }),
    },
  });
}
