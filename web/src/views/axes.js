// The axis polynomials: Tab. 2 (nominal and corrected), the coefficients with their units, and
// the axis motions over the motion range (web/src/plots/axis-motion.js).
import { AXES, AXIS_NAMES, AXIS_UNIT, coefficientUnit } from '../limits.js';
import { fmt, motionSymbol, motionUnit, polynomialText } from '../format.js';
import { drawAxisMotion } from '../plots/axis-motion.js';

const $ = (selector) => document.querySelector(selector);

function renderTab2(r) {
  const symbol = motionSymbol(r);
  const corrected = r.correction && r.correction.axes;
  $('#tab2 tbody').innerHTML = AXES.map((a) => `<tr>
      <th>${AXIS_NAMES[a]} <span class="unit">(${AXIS_UNIT[a]})</span></th>
      <td data-set="nominal" data-axis="${a}">${polynomialText(r.axes[a], symbol)}</td>
      <td data-set="corrected" data-axis="${a}">${corrected ? polynomialText(corrected[a], symbol) : '—'}</td>
    </tr>`).join('');
}

function renderCoefficients(r) {
  const corrected = r.correction && r.correction.axes;
  const degree = r.axes.X.length - 1;
  const per = motionUnit(r);
  $('#coefficients thead').innerHTML = '<tr><th>coefficient</th><th>unit</th><th>nominal</th><th>corrected</th><th>change</th></tr>';
  const rows = [];
  for (const a of AXES) {
    for (let k = 0; k <= degree; k++) {
      const n = r.axes[a][k], c = corrected ? corrected[a][k] : undefined;
      rows.push(`<tr><td>${a} a${k}</td><td>${coefficientUnit(a, k, per)}</td>
        <td class="num" data-coef="nominal ${a} ${k}">${fmt(n, 9)}</td>
        <td class="num" data-coef="corrected ${a} ${k}">${corrected ? fmt(c, 9) : '—'}</td>
        <td class="num">${corrected ? fmt(c - n, 6) : '—'}</td></tr>`);
    }
  }
  $('#coefficients tbody').innerHTML = rows.join('');
}

export function mountAxes(store, plots) {
  store.on('result', ({ result }) => { renderTab2(result); renderCoefficients(result); });
  plots.add(({ Plotly, result }) => drawAxisMotion(Plotly, 'plot-axes', result));
}
