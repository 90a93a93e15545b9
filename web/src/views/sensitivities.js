// The sensitivities (Fig. 6): every coefficient's topography as a thumbnail, the singular values
// of the correction step, and the unobservable combinations in words.
import { coefficientUnit, isRotary } from '../limits.js';
import { escapeHtml, fixed, fmt, motionUnit } from '../format.js';
import { colourRange } from '../plots/colours.js';
import { drawThumbnail } from '../plots/thumbnail.js';

const $ = (selector) => document.querySelector(selector);

function drawGallery({ result: r }) {
  const s = r.sensitivities;
  const range = Math.max(Math.abs(r.motion.min), Math.abs(r.motion.max)) || 1;
  const per = motionUnit(r);
  const gallery = $('#gallery');
  if (gallery.childElementCount !== s.coefficients.length) {
    gallery.innerHTML = s.coefficients.map((_, j) => `<div class="thumb" id="sens-${j}"></div>`).join('');
  }
  s.coefficients.forEach((name, j) => {
    const [axis, ak] = name.split(' ');
    const k = Number(ak.slice(1));
    // The change of a coefficient that moves the axis by 0.1 mm or 0.01 rad at the range's ends.
    const step = (isRotary(axis) ? 0.01 : 0.1) / Math.pow(range, k);
    const z = s.normal[j].map((row) => row.map((v) => v * step));
    const m = colourRange(z);
    drawThumbnail($(`#sens-${j}`), { z, range: m, title: [`${name} + ${fmt(step, 3)} ${coefficientUnit(axis, k, per)}`, `±${fixed(m, 2)} µm`] });
  });
}

function drawSingular({ Plotly, result: r }) {
  if (!r.correction) return Plotly.purge('plot-singular');
  const sv = r.correction.singularValues;
  const kept = r.correction.rank;
  return Plotly.react('plot-singular', [{
    type: 'bar', x: sv.map((_, i) => i + 1), y: sv.map((v) => Math.max(v, 1e-18)),
    marker: { color: sv.map((_, i) => (i < kept ? '#2b6cb0' : '#c53030')) },
    hovertemplate: 'σ%{x} = %{y:.3e}<extra></extra>',
  }], {
    title: { text: `Singular values of the scaled sensitivity matrix (${kept} used)` }, height: 300,
    margin: { t: 40, r: 10, b: 40, l: 60 }, yaxis: { type: 'log', title: { text: 'σ (unit columns)' } },
    xaxis: { title: { text: 'index' } },
  }, { responsive: true, displaylogo: false });
}

function renderUnobservable(r) {
  $('#unobservable').innerHTML = !r.correction
    ? '<li>Computed with the correction: give a measured topography.</li>'
    : r.correction.unobservable.length
      ? r.correction.unobservable.map((u) => `<li>${escapeHtml(u)}</li>`).join('')
      : '<li>None: every coefficient combination is seen on the grid.</li>';
}

export function mountSensitivities(store, plots) {
  store.on('result', ({ result }) => renderUnobservable(result));
  plots.add(drawGallery, { plotly: false });
  plots.add(drawSingular, { plotly: true });
}
