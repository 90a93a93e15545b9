// A deviation topography as a map (Plotly heatmap), in µm, with the colour bar that says which
// colour is excess material.
import { DEVIATION_SCALE, deviationColourBar } from './colours.js';
import { AXIS_TITLES } from './surface.js';

// spec: {x, y, z, range (shared with the map it is compared with), title}
export function drawMap(Plotly, el, { x, y, z, range, title }) {
  return Plotly.react(el, [{
    type: 'heatmap', x, y, z,
    colorscale: DEVIATION_SCALE, zmin: -range, zmax: range, colorbar: deviationColourBar(),
    hovertemplate: 'r = %{y:.2f} mm<br>x = %{x:.2f} mm<br>deviation %{z:.3f} µm<extra></extra>',
  }], {
    title: { text: `${title} (map)`, font: { size: 14 } }, height: 300, margin: { t: 40, r: 10, b: 50, l: 60 },
    xaxis: { title: { text: AXIS_TITLES.x } }, yaxis: { title: { text: AXIS_TITLES.y } },
  }, { responsive: true, displaylogo: false });
}
