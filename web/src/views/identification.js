// The correction's identification of the machine error, shown when the result has its fields
// (web/src/identification.js): the solver's status and iterations; per axis the identified error
// with its standard uncertainty and the proposed change; the precision demand; the axes as the NC
// program carries them, with their re-simulated sum of squares beside the exact proposal's.
import { AXES, AXIS_UNIT } from '../limits.js';
import { escapeHtml, fixed, fmt, motionSymbol, polynomialText, signed } from '../format.js';
import { errorRows, precisionTable, roundedFigures, statusText } from '../identification.js';

const $ = (selector) => document.querySelector(selector);
const withUnit = (v, unit) => (v === null ? '—' : `${fmt(v, 4)} ${unit}`);

function renderErrors(c) {
  const rows = errorRows(c, AXES);
  $('#identified-error').hidden = !rows.length;
  $('#identified-error tbody').innerHTML = rows.map((r) => `<tr data-axis="${r.axis}"><th>${r.axis}</th>
    <td class="num" data-col="error">${withUnit(r.error, r.unit)}</td>
    <td class="num" data-col="uncertainty">${r.uncertainty === null ? '—' : `± ${fmt(r.uncertainty, 3)} ${r.unit}`}</td>
    <td class="num" data-col="change">${withUnit(r.change, r.unit)}</td></tr>`).join('');
}

function renderPrecision(c) {
  const t = precisionTable(c.precision, AXES);
  $('#precision-demand').hidden = !t;
  if (!t) return;
  $('#precision-demand thead').innerHTML = `<tr><th>axis</th>${t.columns.map((q) => `<th>${escapeHtml(q.label)}</th>`).join('')}</tr>`;
  $('#precision-demand tbody').innerHTML = t.rows.map((r) => `<tr data-axis="${r.axis}"><th>${r.axis}</th>${r.values.map((v, i) =>
    `<td class="num">${v === null ? '—' : `${fmt(v, 4)} ${escapeHtml(t.columns[i].unit(r.axis))}`}</td>`).join('')}</tr>`).join('');
}

function renderRounded(c, r) {
  const box = $('#rounded-axes');
  box.hidden = !c.roundedAxes;
  if (!c.roundedAxes) return;
  const symbol = motionSymbol(r);
  $('#rounded-axes-list').innerHTML = AXES.map((a) => `<li data-rounded-axis="${a}">${a} (${AXIS_UNIT[a]}) = ${
    escapeHtml(polynomialText(c.roundedAxes[a] || [], symbol))}</li>`).join('');
  const f = roundedFigures(c);
  const text = (x) => `sum of squares ${fmt(x.sse, 4)} µm², largest |deviation| ${fixed(x.max, 3)} µm, thickness error ${signed(x.thickness, 3)} µm`;
  $('#rounded-sse').textContent = `Predicted with the rounded axes, re-simulated: ${text(f.rounded)}. With the exact proposal: ${text(f.exact)}.`;
}

export function mountIdentification(store) {
  store.on('result', ({ result }) => {
    const c = result.correction;
    const shown = Boolean(c) && ['status', 'identifiedError', 'axisChange', 'precision', 'roundedAxes'].some((k) => k in c);
    $('#identification').hidden = !shown;
    if (!shown) return;
    $('#solver-status').textContent = statusText(c);
    renderErrors(c);
    renderPrecision(c);
    renderRounded(c, result);
  });
}
