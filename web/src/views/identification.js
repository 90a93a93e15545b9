// The correction's identification of the machine error, shown when the result has its fields
// (web/src/identification.js): the solver's status and iterations; per axis what the face tells of
// its error (its value read on its own with its standard uncertainty, or why not) and the proposed
// change; the combinations the face does not split, in words; the precision demand; the axes
// as the NC program carries them with their re-simulated sum of squares beside the exact
// proposal's. Units are the result fields' own (fieldUnit).
import { AXES, AXIS_UNIT } from '../limits.js';
import { fieldPresent, fieldUnit as describedUnit } from '../result-fields.js';

const fieldUnit = (path) => describedUnit(path) || '';
import { escapeHtml, fixed, fmt, motionSymbol, polynomialText, signed } from '../format.js';
import { figureTexts } from '../figures.js';
import { READING_WORDS, combinationSentences, errorRows, precisionTable, roundedFigures, statusText } from '../identification.js';

const $ = (selector) => document.querySelector(selector);
const withUnit = (v, unit) => (v === null ? '—' : `${fmt(v, 4)} ${escapeHtml(unit)}`);

function renderErrors(c) {
  const rows = errorRows(c, AXES, fieldUnit);
  $('#identified-error').hidden = !rows.length;
  $('#identified-error tbody').innerHTML = rows.map((r) => {
    const read = r.error !== null
      ? `<td class="num" data-col="error">${withUnit(r.error, r.errorUnit)}</td>
    <td class="num" data-col="uncertainty">${r.uncertainty === null ? '—' : `± ${fmt(r.uncertainty, 3)} ${escapeHtml(r.errorUnit)}${
      r.secondOrder !== null && r.secondOrder > r.uncertainty
        ? `<span class="beyond" data-col="second-order">; ${escapeHtml(r.secondOrderLabel)} ${fmt(r.secondOrder, 2)} ${escapeHtml(r.errorUnit)}</span>` : ''}`}</td>`
      : `<td colspan="2" class="reading" data-col="reading">${escapeHtml(READING_WORDS[r.reading] || 'not read on its own')}</td>`;
    return `<tr data-axis="${r.axis}" data-reading="${escapeHtml(r.reading || '')}"><th>${r.axis}</th>${read}
    <td class="num" data-col="change">${withUnit(r.change, r.changeUnit)}${r.changeOverFace === null ? ''
      : `<span class="beyond" data-col="change-over-face"><span class="figure">${withUnit(r.changeOverFace, r.changeUnit)}</span> over the whole face*</span>`}</td></tr>`;
  }).join('');
  // What "over the whole face" means, once under the table, where a row says it.
  $('#change-over-face-note').hidden = !rows.some((r) => r.changeOverFace !== null);
  const words = combinationSentences(c);
  $('#identified-words').hidden = !words.length;
  $('#identified-words ul').innerHTML = words.map((w) => `<li>${escapeHtml(w)}</li>`).join('');
}

function renderPrecision(c) {
  const t = precisionTable(c.precision, AXES, fieldUnit);
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
  const digits = { sse: (v) => fmt(v, 4), max: (v) => fixed(v, 3), thickness: (v) => signed(v, 3) };
  const text = (x) => figureTexts(['sse', 'max', 'thickness'], (q) => `correction.${q}Rounded`, (q) => digits[q](x[q])).join(', ');
  $('#rounded-sse').textContent = `On the identified machine, re-simulated, the rounded axes leave ${text(f.rounded)}; the exact proposal ${text(f.exact)}. The exact axes leave at most the verdict's bound.`;
}

export function mountIdentification(store) {
  store.on('result', ({ result }) => {
    const c = result.correction;
    // There when the result has the correction's fields (the schema's `when`: only with a measurement).
    const shown = fieldPresent(result, 'correction.status');
    $('#identification').hidden = !shown;
    if (!shown) return;
    $('#solver-status').textContent = statusText(c);
    renderErrors(c);
    renderPrecision(c);
    renderRounded(c, result);
  });
}
