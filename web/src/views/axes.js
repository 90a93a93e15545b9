// The axis polynomials: Tab. 2 (nominal and corrected), the coefficients with their units, and
// the five axis motions over the motion range.
import { AXES, AXIS_NAMES, AXIS_UNIT, coefficientUnit, isRotary } from '../limits.js';
import { fmt, motionSymbol, motionUnit, polynomialText } from '../format.js';
import { pinnedCoefficients, pinnedPolynomial } from './pin.js';

const $ = (selector) => document.querySelector(selector);

function renderTab2(r, state) {
  const symbol = motionSymbol(r);
  const corrected = r.correction && r.correction.axes;
  $('#tab2 tbody').innerHTML = AXES.map((a) => `<tr>
      <th>${AXIS_NAMES[a]} <span class="unit">(${AXIS_UNIT[a]})</span></th>
      <td data-set="nominal" data-axis="${a}"><span class="poly">${polynomialText(r.axes[a], symbol)}</span>${pinnedPolynomial(state, 'nominal', a)}</td>
      <td data-set="corrected" data-axis="${a}"><span class="poly">${corrected ? polynomialText(corrected[a], symbol) : '—'}</span>${pinnedPolynomial(state, 'corrected', a)}</td>
    </tr>`).join('');
}

function renderCoefficients(r, state) {
  const corrected = r.correction && r.correction.axes;
  const pinned = pinnedCoefficients(state);
  const degree = r.axes.X.length - 1;
  const per = motionUnit(r);
  $('#coefficients thead').innerHTML = '<tr><th>coefficient</th><th>unit</th><th>nominal</th><th>corrected</th><th>change</th>' +
    `${pinned ? '<th>nominal, difference to pinned</th>' : ''}</tr>`;
  const rows = [];
  for (const a of AXES) {
    for (let k = 0; k <= degree; k++) {
      const n = r.axes[a][k], c = corrected ? corrected[a][k] : undefined;
      rows.push(`<tr><td>${a} a${k}</td><td>${coefficientUnit(a, k, per)}</td>
        <td class="num" data-coef="nominal ${a} ${k}">${fmt(n, 9)}</td>
        <td class="num" data-coef="corrected ${a} ${k}">${corrected ? fmt(c, 9) : '—'}</td>
        <td class="num">${corrected ? fmt(c - n, 6) : '—'}</td>${pinned
          ? `<td class="num pin-diff" data-pin-coef="${a} ${k}">${pinned.axes ? fmt(pinned.axes[a][k], 6) : '—'}</td>` : ''}</tr>`);
    }
  }
  $('#coefficients tbody').innerHTML = rows.join('');
}

const polyAt = (c, t) => c.reduceRight((acc, a) => acc * t + a, 0);

function drawAxisPlot(Plotly, r) {
  const n = 121, lo = r.motion.min, hi = r.motion.max;
  const t = Array.from({ length: n }, (_, i) => lo + ((hi - lo) * i) / (n - 1));
  const traces = [];
  const add = (axes, dash, label) => {
    for (const a of AXES) {
      traces.push({
        x: t, y: t.map((v) => polyAt(axes[a], v)), name: `${a} ${label}`, mode: 'lines',
        yaxis: isRotary(a) ? 'y2' : 'y', line: { dash },
      });
    }
  };
  add(r.axes, 'solid', '(nominal)');
  if (r.correction) add(r.correction.axes, 'dot', '(corrected)');
  return Plotly.react('plot-axes', traces, {
    title: { text: 'Axis motions over the motion range' }, margin: { t: 40, r: 60, b: 50, l: 60 }, height: 320,
    xaxis: { title: { text: `${motionSymbol(r)} (${motionUnit(r)})` } },
    yaxis: { title: { text: 'X, Y, Z (mm)' } },
    yaxis2: { title: { text: 'A, B (rad)' }, overlaying: 'y', side: 'right' },
    legend: { orientation: 'h', y: -0.25 },
  }, { responsive: true, displaylogo: false });
}

export function mountAxes(store, plots) {
  const render = (state) => { renderTab2(state.result, state); renderCoefficients(state.result, state); };
  store.on('result', (_, state) => render(state));
  store.on('view', (_, state) => { if (state.result) render(state); });  // a result pinned or unpinned
  plots.add(({ Plotly, result }) => drawAxisPlot(Plotly, result), { plotly: true });
}
