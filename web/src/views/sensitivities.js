// The sensitivities (Fig. 6): every coefficient's topography as a small map, the singular values
// of the correction step, and the unobservable combinations in words.
import { coefficientUnit, isRotary } from '../limits.js';
import { escapeHtml, fixed, fmt, motionUnit } from '../format.js';
import { colourRange } from '../plots/colours.js';
import { drawGallery } from '../plots/gallery.js';
import { isNarrowPlot, purgePlot, reactPlot } from '../plots/config.js';
import { gridUnits } from '../plots/grid-units.js';

const $ = (selector) => document.querySelector(selector);

function drawSensitivities({ Plotly, result: r }) {
  const s = r.sensitivities;
  const range = Math.max(Math.abs(r.motion.min), Math.abs(r.motion.max)) || 1;
  const per = motionUnit(r);
  const items = s.coefficients.map((name, j) => {
    const [axis, ak] = name.split(' ');
    const k = Number(ak.slice(1));
    // The change of a coefficient that moves the axis by 0.1 mm or 0.01 rad at the range's ends.
    const step = (isRotary(axis) ? 0.01 : 0.1) / Math.pow(range, k);
    const z = s.normal[j].map((row) => row.map((v) => v * step));
    const m = colourRange(z);
    return { z, range: m, title: [`${name} + ${fmt(step, 3)} ${coefficientUnit(axis, k, per)}`, `±${fixed(m, 2)} ${gridUnits().z}`] };
  });
  return drawGallery(Plotly, $('#gallery'), $('#gallery-titles'), r.topography.x, r.topography.r, items);
}

// Blue bars: the directions the correction uses; red: those it leaves out. The nonlinear
// correction's singular values are in µm of face per machine step, and it leaves a direction out
// when the measurement holds it only within the probe noise, or when it would need wild axis
// moves for little gain; usedDirections (1-based) says which it used, not always the largest.
// The linear step's are of the column-scaled matrix, the largest `rank` used.
function drawSingular({ Plotly, result: r }) {
  if (!r.correction) return purgePlot(Plotly, 'plot-singular');
  const c = r.correction;
  const sv = c.singularValues;
  const nonlinear = c.method !== 'linear';
  const used = new Set(c.usedDirections || sv.map((_, k) => k + 1).slice(0, c.rank));
  const bars = (name, colour, pick) => {
    const i = sv.map((_, k) => k).filter(pick);
    return {
      type: 'bar', name, x: i.map((k) => k + 1), y: i.map((k) => Math.max(sv[k], 1e-18)), marker: { color: colour },
      hovertemplate: `σ%{x} = %{y:.3e}${nonlinear ? ' µm per step' : ''}: ${name}<extra></extra>`,
    };
  };
  // On a phone the title and the legend's longer entry on two lines.
  const narrow = isNarrowPlot('plot-singular');
  const br = narrow ? '<br>' : ' ';
  const leftOut = nonlinear ? `left out: within the probe noise,${br}or would need wild axis moves` : 'left out: too small or would amplify noise';
  return reactPlot(Plotly, 'plot-singular', [
    bars('used in the correction', '#2b6cb0', (k) => used.has(k + 1)),
    bars(leftOut, '#c53030', (k) => !used.has(k + 1)),
  ], {
    title: { text: nonlinear ? `Singular values of the sensitivities${br}in machine steps (${used.size} used)`
      : `Singular values of the scaled${br}sensitivity matrix (${used.size} used)`, font: { size: 14 }, y: 0.97 },
    height: narrow ? 400 : 340, margin: { t: narrow ? 140 : 90, r: 10, b: 40, l: 60 }, barmode: 'overlay', showlegend: true,
    legend: { orientation: 'h', x: 0, xanchor: 'left', y: 1.02, yanchor: 'bottom' },
    yaxis: { type: 'log', exponentformat: 'power', title: { text: nonlinear ? 'σ (µm of face per machine step)' : 'σ (unit columns)' } },
    xaxis: { title: { text: 'index' } },
  });
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
  plots.add(drawSingular, { el: ['#plot-singular'] });
  plots.add(drawSensitivities, { later: true, el: ['#gallery'] });
}
