// The wheel's axial profile (Fig. 4), and its points as CSV for a dresser.
import { fixed } from '../format.js';
import { download } from '../io/files.js';
import { profileCsv } from '../io/results-csv.js';
import { pinnedProfile } from './pin.js';

function drawWheel(Plotly, r, state) {
  const p = r.wheelProfile;
  const pinned = pinnedProfile(state);
  const note = document.querySelector('#wheel-pin');
  note.hidden = !pinned;
  note.textContent = pinned ? pinned.text : '';
  return Plotly.react('plot-wheel', [...(pinned ? [pinned.trace] : []), {
    x: p.Z, y: p.R, mode: 'lines+markers', marker: { size: 4 }, name: 'axial profile',
    text: p.r.map((v) => `tooth-face radius r = ${fixed(v, 3)} mm`),
    hovertemplate: 'Z = %{x:.4f} mm<br>R = %{y:.4f} mm<br>%{text}<extra></extra>',
  }], {
    title: { text: 'Wheel axial profile (R against Z)' }, height: 360, margin: { t: 40, r: 20, b: 50, l: 60 },
    xaxis: { title: { text: 'Z, along the wheel axis (mm)' } },
    yaxis: { title: { text: 'R, wheel radius (mm)' }, scaleanchor: 'x', scaleratio: 1 },
  }, { responsive: true, displaylogo: false });
}

export function mountWheel(store, plots) {
  plots.add(({ Plotly, result, state }) => drawWheel(Plotly, result, state));
  document.querySelector('#download-profile').addEventListener('click', () => {
    if (store.state.result) download('hobsharp-wheel-profile.csv', profileCsv(store.state.result), 'text/csv');
  });
}
