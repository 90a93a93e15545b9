// Per gash, under the inspection's checks: its deviation at the pitch radius and, from one
// topography per gash, its own face checks; and the A-axis indexing correction that brings it to
// the mean of all (inspection.perGash, inspection.indexCorrectionDeg).
import { escapeHtml, fixed } from '../format.js';

const $ = (selector) => document.querySelector(selector);

export function perGashRows(i) {
  const n = (i.indexCorrectionDeg || []).length;
  const p = i.perGash || {};
  return Array.from({ length: n }, (_, k) => ({
    gash: k + 1,
    deviation: p.deviation ? p.deviation[k] : null,
    form: p.cuttingFaceForm ? p.cuttingFaceForm[k] : null,
    alignment: p.radialAlignment ? p.radialAlignment[k] : null,
    lead: p.gashLead ? p.gashLead[k] : null,
    index: i.indexCorrectionDeg[k],
  }));
}

export function mountPerGash(store) {
  store.on('result', ({ result }) => {
    const i = result.inspection;
    const rows = i ? perGashRows(i) : [];
    $('#per-gash').hidden = !rows.length;
    if (!rows.length) return;
    const cols = [['deviation', 'deviation at r_p (µm)', 3], ['form', 'form (µm)', 3], ['alignment', 'radial alignment (µm)', 3],
      ['lead', 'gash lead (µm per 100 mm)', 3], ['index', 'A index correction (deg)', 6]].filter(([key]) => rows.some((r) => r[key] !== null));
    $('#per-gash thead').innerHTML = `<tr><th>gash</th>${cols.map(([, label]) => `<th>${escapeHtml(label)}</th>`).join('')}</tr>`;
    $('#per-gash tbody').innerHTML = rows.map((r) => `<tr data-gash="${r.gash}"><th>${r.gash}</th>${cols.map(([key, , digits]) =>
      `<td class="num">${fixed(r[key], digits)}</td>`).join('')}</tr>`).join('');
  });
}
