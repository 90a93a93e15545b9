// The axis polynomials: Tab. 2 (nominal and corrected), the coefficients with their units, and
// the axis motions over the motion range (web/src/plots/axis-motion.js).
import { AXES, AXIS_NAMES, AXIS_UNIT, coefficientUnit } from '../limits.js';
import { fmt, motionSymbol, motionUnit, polynomialText } from '../format.js';
import { pinnedCoefficients, pinnedPolynomial } from './pin.js';
import { drawAxisMotion } from '../plots/axis-motion.js';

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
  $('#coefficients thead').innerHTML = '<tr><th>coefficient</th><th>unit</th><th>nominal</th><th>corrected</th><th title="the corrected coefficient less the nominal one: not the change from the axes run, which differs after a first pass (the results file gives that)">corrected − nominal</th>' +
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

export function mountAxes(store, plots) {
  const render = (state) => { renderTab2(state.result, state); renderCoefficients(state.result, state); };
  store.on('result', (_, state) => render(state));
  store.on('view', (_, state) => { if (state.result) render(state); });  // a result pinned or unpinned
  plots.add(({ Plotly, result }) => drawAxisMotion(Plotly, 'plot-axes', result), { el: ['#plot-axes'] });
}
