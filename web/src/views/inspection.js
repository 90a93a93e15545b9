// The rake-face inspection (web/src/inspection-table.js): the class verdict at the top of the
// topography, measured and predicted after the correction, and the table of checks under it.
import { escapeHtml, fixed } from '../format.js';
import { inspectionRows, verdictSentence } from '../inspection-table.js';

const $ = (selector) => document.querySelector(selector);
const value = (v, unit) => (v === null ? '—' : `${fixed(v, 3)} ${unit}`);

export function mountInspection(store) {
  store.on('result', ({ result }) => {
    const i = result.inspection;
    $('#inspection').hidden = !i;
    if (!i) return;
    $('#inspection-verdict').textContent = verdictSentence(i);
    const rows = inspectionRows(i);
    const after = rows.some((r) => r.after);
    $('#inspection-table thead').innerHTML = `<tr><th>check</th><th>value</th><th>grade</th><th>class tolerances</th>${
      after ? '<th>after correction</th><th>grade after</th>' : ''}</tr>`;
    $('#inspection-table tbody').innerHTML = rows.map((r) => `<tr data-check="${r.check}"><th>${escapeHtml(r.label)}</th>
      <td class="num">${value(r.value, escapeHtml(r.unit))}</td><td>${escapeHtml(r.grade)}</td><td>${escapeHtml(r.tolerances)}</td>${
      after ? `<td class="num">${r.after ? value(r.after.value, escapeHtml(r.unit)) : '—'}</td><td>${r.after ? escapeHtml(r.after.grade) : '—'}</td>` : ''}</tr>`).join('');
  });
}
