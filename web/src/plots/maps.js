// A deviation topography as a map (Plotly heatmap), in the module's units (grid-units.js), with the colour bar that says which
// colour is excess material; and, for a measurement at the measuring machine's own points
// (docs/measured-points.md), those points marked on it (a scatter trace on the same axes).
import { DEVIATION_SCALE, deviationColourBar } from './colours.js';
import { gridAxisTitles, gridHover } from './grid-units.js';
import { reactPlot } from './config.js';

// The probe points as a scatter trace: list holds [r, x, deviation] per point (grid-units.js), the
// deviation named by `what` when the pointer is on a point.
export function probePointsTrace(list, what) {
  return {
    type: 'scatter', mode: 'markers', name: 'probe points', showlegend: true,
    x: list.map((p) => p[1]), y: list.map((p) => p[0]), customdata: list.map((p) => p[2]),
    // A few points as rings; many (a scanning probe's thousands) as small dots the map shows through.
    marker: list.length > 300 ? { symbol: 'circle', size: 3, color: 'rgba(0,0,0,0.6)' }
      : { symbol: 'circle-open', size: 7, color: '#111', line: { width: 1.5 } },
    hovertemplate: gridHover(undefined, { what, value: '%{customdata:.3f}', lead: 'probe point<br>' }),
  };
}

// spec: {x, y, z, range (shared with the map it is compared with), title, points (optional:
// {list, what} for probePointsTrace)}
export function drawMap(Plotly, el, { x, y, z, range, title, points = null }) {
  const traces = [{
    type: 'heatmap', x, y, z, showlegend: false,
    colorscale: DEVIATION_SCALE, zmin: -range, zmax: range, colorbar: deviationColourBar(),
    hovertemplate: gridHover(),
  }];
  if (points) traces.push(probePointsTrace(points.list, points.what));
  return reactPlot(Plotly, el, traces, {
    title: { text: `${title} (map)`, font: { size: 14 } }, height: points ? 330 : 300,
    margin: { t: 40, r: 10, b: points ? 80 : 50, l: 60 },
    xaxis: { title: { text: gridAxisTitles().x } }, yaxis: { title: { text: gridAxisTitles().y } },
    showlegend: Boolean(points), legend: { orientation: 'h', x: 0, xanchor: 'left', y: -0.32, yanchor: 'top' },
  });
}
