// Per gash, under the inspection's checks: its deviation at the pitch radius, the single pitch
// deviation to the next gash and the pitch jump (DIN 3968 items 8 and 9), and, from one topography
// per gash, its own face checks; and the A-axis indexing correction that brings it to the mean of
// all (inspection.perGash, inspection.spacing, inspection.indexCorrectionDeg). Units are the
// result fields' own.
import { escapeHtml, fixed } from '../format.js';
import { fieldUnit } from '../result-fields.js';

const $ = (selector) => document.querySelector(selector);
const at = (list, k) => (list && k < list.length ? list[k] : null);

export function perGashRows(i) {
  const n = (i.indexCorrectionDeg || []).length;
  const p = i.perGash || {}, s = i.spacing || {};
  return Array.from({ length: n }, (_, k) => ({
    gash: k + 1,
    deviation: at(p.deviation, k),
    pitch: at(s.adjacent, k),
    jump: at(s.pitchJump, k),
    form: at(p.cuttingFaceForm, k),
    alignment: at(p.radialAlignment, k),
    lead: at(p.gashLead, k),
    index: i.indexCorrectionDeg[k],
  }));
}

// The columns: [key, heading, the field that states the unit, digits].
const COLUMNS = [
  ['deviation', 'deviation at r_p', 'inspection.perGash.deviation', 3],
  ['pitch', 'single pitch to the next gash', 'inspection.spacing.adjacent', 3],
  ['jump', 'pitch jump from the pitch before', 'inspection.spacing.pitchJump', 3],
  ['form', 'form', 'inspection.perGash.cuttingFaceForm', 3],
  ['alignment', 'radial alignment', 'inspection.perGash.radialAlignment', 3],
  ['lead', 'gash lead', 'inspection.perGash.gashLead', 3],
  ['index', 'A index correction', 'inspection.indexCorrectionDeg', 6],
];

export function mountPerGash(store) {
  store.on('result', ({ result }) => {
    const i = result.inspection;
    const rows = i ? perGashRows(i) : [];
    $('#per-gash').hidden = !rows.length;
    if (!rows.length) return;
    const cols = COLUMNS.filter(([key]) => rows.some((r) => r[key] !== null));
    const heading = (text, path) => { const unit = fieldUnit(path); return unit ? `${text} (${unit})` : text; };
    $('#per-gash thead').innerHTML = `<tr><th>gash</th>${cols.map(([, text, path]) => `<th>${escapeHtml(heading(text, path))}</th>`).join('')}</tr>`;
    $('#per-gash tbody').innerHTML = rows.map((r) => `<tr data-gash="${r.gash}"><th>${r.gash}</th>${cols.map(([key, , , digits]) =>
      `<td class="num">${fixed(r[key], digits)}</td>`).join('')}</tr>`).join('');
  });
}
