// The wheel's axial profile (Fig. 4), with the offsets along its normal on a secondary scale in
// µm (as dressed, proposed by the correction, and both: wheel-offsets.js), the dresser path the
// correction proposes, and their points as CSV: the profile, and the dresser path for a CNC dresser.
import { fixed } from '../format.js';
import { download } from '../io/files.js';
import { dresserCsv, profileCsv } from '../io/results-csv.js';
import { offsetRange, wheelOffsetCurves } from '../wheel-offsets.js';
import { pinnedProfile } from './pin.js';
import { isNarrowPlot, reactPlot } from '../plots/config.js';
import { unitText } from '../result-fields.js';

const OFFSET_COLOURS = ['#1b7837', '#b35806', '#542788'];

// The profile's and the offsets' units as the module states them (result-fields.js).
const units = () => ({ R: unitText('wheelProfile.R'), Z: unitText('wheelProfile.Z'), r: unitText('wheelProfile.r'),
  offset: unitText('wheelProfile.offset') });

function drawWheel(Plotly, r, state) {
  const p = r.wheelProfile;
  const u = units();
  const pinned = pinnedProfile(state);
  const note = document.querySelector('#wheel-pin');
  note.hidden = !pinned;
  note.textContent = pinned ? pinned.text : '';
  const dresser = r.correction && r.correction.dresserPath;
  const curves = wheelOffsetCurves(r);
  const traces = [...(pinned ? [pinned.trace] : []), {
    x: p.Z, y: p.R, mode: 'lines+markers', marker: { size: 4 }, name: p.dressedR ? 'conjugate profile (Eqs. 3-6)' : 'axial profile',
    text: p.r.map((v) => `tooth-face radius r = ${fixed(v, 3)} ${u.r}`),
    hovertemplate: `Z = %{x:.4f} ${u.Z}<br>R = %{y:.4f} ${u.R}<br>%{text}<extra></extra>`,
  }];
  if (dresser) {
    traces.push({ x: dresser.Z, y: dresser.R, mode: 'lines', name: 'dresser path (corrected)', line: { dash: 'dash', color: '#542788' },
      hovertemplate: `dresser path<br>Z = %{x:.5f} ${u.Z}<br>R = %{y:.4f} ${u.R}<extra></extra>` });
  }
  curves.forEach((c, i) => {
    const color = OFFSET_COLOURS[i % OFFSET_COLOURS.length];
    traces.push({
      x: c.offset, y: c.R, xaxis: 'x2', mode: c.R.length > 12 ? 'lines' : 'lines+markers', name: `${c.name} (${u.offset}, top scale)`,
      line: { color, width: 2 }, legendgroup: c.name,
      hovertemplate: `${c.name}<br>R = %{y:.3f} ${u.R}<br>offset %{x:.3f} ${u.offset}<extra></extra>`,
    });
    if (c.knots) {
      traces.push({
        x: c.knots.offset, y: c.knots.R, xaxis: 'x2', mode: 'markers', name: `${c.name}: spline points`, showlegend: false,
        legendgroup: c.name, marker: { color, size: 8, symbol: 'diamond' },
        hovertemplate: `${c.name}, spline point<br>R = %{y:.3f} ${u.R}<br>offset %{x:.3f} ${u.offset}<extra></extra>`,
      });
    }
  });
  // On a phone the top axis's title on two lines, and the legend, which wraps to several rows
  // there, in a margin of its own under the x axis's title.
  const narrow = curves.length > 0 && isNarrowPlot('plot-wheel');
  const layout = {
    // With the offsets' scale at the top, its title takes the title's place (the section's heading names the plot).
    title: { text: curves.length ? '' : 'Wheel axial profile (R against Z)' }, height: (curves.length ? 400 : 360) + (narrow ? 120 : 0),
    margin: { t: curves.length ? (narrow ? 80 : 60) : 40, r: 20, b: narrow ? 170 : 50, l: 60 },
    xaxis: { title: { text: `Z, along the wheel axis (${u.Z})` } },
    yaxis: { title: { text: `R, wheel radius (${u.R})` }, scaleanchor: 'x', scaleratio: 1 },
    legend: narrow ? { orientation: 'h', x: 0, xanchor: 'left', y: 0, yref: 'container', yanchor: 'bottom' } : { orientation: 'h', y: -0.2 },
  };
  if (curves.length) {
    layout.xaxis2 = { title: { text: `offset along the profile normal, ${u.offset}${narrow ? '<br>' : ' '}(+ = more wheel), exaggerated` }, overlaying: 'x',
      side: 'top', range: offsetRange(curves), zeroline: true, showgrid: false };
  }
  return reactPlot(Plotly, 'plot-wheel', traces, layout);
}

export function mountWheel(store, plots) {
  plots.add(({ Plotly, result, state }) => drawWheel(Plotly, result, state), { el: ['#plot-wheel'] });
  const dresserButton = document.querySelector('#download-dresser');
  store.on('result', (_, state) => { dresserButton.disabled = !(state.result.correction && state.result.correction.dresserPath); });
  document.querySelector('#download-profile').addEventListener('click', () => {
    if (store.state.result) download('hobsharp-wheel-profile.csv', profileCsv(store.state.result), 'text/csv');
  });
  dresserButton.addEventListener('click', () => {
    const r = store.state.result;
    if (r && r.correction && r.correction.dresserPath) download('hobsharp-dresser-path.csv', dresserCsv(r), 'text/csv');
  });
}
