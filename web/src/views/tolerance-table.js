// The inspection's inputs (web/src/tolerance-edit.js): under its table, the tolerance table's
// cells for the hob's module band, AA to D per check (a * on a series value, not confirmed), with
// a button back to the default table, and the gash deviations at the pitch radius, for the spacing
// checks and the indexing correction; at the class, the measurement's uncertainty U95. The case
// keeps them (inspection.tolerances, inspection.gashDeviations, inspection.uncertainty); a refused
// value is named at its input, and the details open to show it.
import { INSPECTION } from '../limits.js';
import { CHECK_WORDS, SERIES_NOTE } from '../inspection-table.js';
import { escapeHtml, fmt } from '../format.js';
import { unitText } from '../result-fields.js';
import { cellConfidence, cellTexts, gashText, gashTopographyCount, isEdited, parseGashDeviations, tableInUse, uncertaintyText, withCell,
  withDefaultTable, withGashDeviations, withGashTopographies, withUncertainty } from '../tolerance-edit.js';
import { checkGashFileCount, readGashTopographies } from '../../../wasm/lib/gash-files.js';
import { MAX_MEASURED_BYTES } from '../../../wasm/lib/csv.js';

const $ = (selector) => document.querySelector(selector);
export const isInspectionField = (field) => /^inspection\b/.test(field || '');

function setError(text) {
  $('#tolerance-error').textContent = text || '';
  $('#tolerance-error').hidden = !text;
  if (text) $('#tolerance-editor').open = true;
}

const label = (check) => (CHECK_WORDS[check] || { label: check }).label;

function render(state) {
  const r = state.result;
  if (!r || !r.inspection || !INSPECTION.defaultTolerances) return;
  const band = r.inspection.moduleBandIndex;
  const table = tableInUse(state.extra, INSPECTION.defaultTolerances);
  const edited = isEdited(state.extra);
  $('#tolerance-band').textContent = band < 0
    ? `The hob's normal module lies outside the table's bands (${table.moduleBands[0]} to ${table.moduleBands[table.moduleBands.length - 1]} mm): nothing to grade.`
    : `Tolerances for the band over ${table.moduleBands[band]} to ${table.moduleBands[band + 1]} mm of normal module, from ${
      edited ? 'the table this case carries (edited)' : 'the default table (DIN 3968; sources in docs/inspection.md)'}. Blank: no tolerance, not graded. *: ${SERIES_NOTE}.`;
  $('#tolerance-default').disabled = !edited;
  const texts = cellTexts(table, Math.max(band, 0), INSPECTION.checks, INSPECTION.classes);
  $('#tolerance-table thead').innerHTML = `<tr><th>check</th>${INSPECTION.classes.map((k) => `<th>${k}</th>`).join('')}</tr>`;
  const active = document.activeElement;
  if (active && active.closest && active.closest('#tolerance-table')) return;  // not under the user's typing
  const unit = (check) => unitText(`inspection.checks.${check}.tolerances`);
  $('#tolerance-table tbody').innerHTML = INSPECTION.checks.map((check) => `<tr data-check="${check}"><th>${
    escapeHtml(label(check))} <span class="unit">${escapeHtml(unit(check))}</span></th>${INSPECTION.classes.map((k) => {
    const series = band >= 0 && texts[check][k] !== '' && cellConfidence(table, { band, check, klass: k, edited }) === 'series';
    return `<td${series ? ' data-confidence="series"' : ''}><input type="text" inputmode="decimal" size="5" data-check="${check}" data-class="${k}" value="${
      escapeHtml(texts[check][k])}"${band < 0 ? ' disabled' : ''} aria-label="${escapeHtml(`${label(check)}, class ${k}${series ? `, ${SERIES_NOTE}` : ''}`)}">${
      series ? `<span class="series-mark" title="${escapeHtml(SERIES_NOTE)}">*</span>` : ''}</td>`;
  }).join('')}</tr>`).join('');
  if (document.activeElement !== $('#gash-deviations')) $('#gash-deviations').value = gashText(state.extra);
  const n = gashTopographyCount(state.extra);
  $('#gash-deviations').placeholder = n ? `from the ${n} gash topographies` : '0, 1.5, -2, …';
  $('#gash-files-clear').disabled = !n;
}

// The chosen files' texts, each within the measured grid's size limit; their count is checked
// before any is read.
async function chosenTexts(input) {
  const files = [...input.files];
  input.value = '';
  if (files.length) checkGashFileCount(files.length);
  return Promise.all(files.map(async (f) => {
    if (f.size > MAX_MEASURED_BYTES) throw new Error(`${f.name} is ${(f.size / 1048576).toFixed(1)} MB; a measured grid is a few hundred kB.`);
    return { name: f.name, text: await f.text() };
  }));
}

// The uncertainty's input: its text, its unit as the result states it, its default and range.
function renderUncertainty(state) {
  const input = $('#inspection-uncertainty');
  if (document.activeElement !== input) input.value = uncertaintyText(state.extra);
  const u = INSPECTION.uncertainty;
  const unit = unitText('inspection.uncertainty');
  $('#inspection-uncertainty-unit').textContent = unit;
  if (!u) return;
  input.placeholder = fmt(u.default, 3);
  $('#inspection-uncertainty-hint').textContent = `ISO 14253-1: a check conforms within its tolerance less U, fails beyond it plus U. Blank: ${
    fmt(u.default, 3)} ${unit}; ${fmt(u.min, 3)} to ${fmt(u.max, 3)} ${unit}.`;
}

function setUncertaintyError(text) {
  const input = $('#inspection-uncertainty');
  $('#inspection-uncertainty-error').textContent = text || '';
  $('#inspection-uncertainty-error').hidden = !text;
  input.classList.toggle('invalid', Boolean(text));
  if (text) input.setAttribute('aria-invalid', 'true'); else input.removeAttribute('aria-invalid');
}

export function mountToleranceTable(store) {
  const commit = (extra, event) => {
    setError('');
    store.setInputs({ extra }, { source: 'inspection', at: event.timeStamp });
    store.emit('commit');
  };
  $('#tolerance-table').addEventListener('change', (event) => {
    const el = event.target;
    const band = store.state.result && store.state.result.inspection.moduleBandIndex;
    if (!el.dataset.check || !(band >= 0)) return;
    commit(withCell(store.state.extra, INSPECTION.defaultTolerances, { band, check: el.dataset.check, klass: el.dataset.class, text: el.value }), event);
  });
  $('#tolerance-default').addEventListener('click', (event) => commit(withDefaultTable(store.state.extra), event));
  $('#gash-deviations').addEventListener('change', (event) => {
    try {
      commit(withGashDeviations(store.state.extra, parseGashDeviations(event.target.value)), event);
    } catch (e) {
      setError(`${e.message} The gash deviations in use are unchanged.`);
    }
  });
  // The inputs and the files' note before a set of gash files was used: put back when the
  // calculator refuses the set, so that the set in use stays and the next edit computes.
  let beforeGashes = null, keepError = false;
  $('#gash-files').addEventListener('change', async (event) => {
    try {
      const files = await chosenTexts(event.target);
      if (!files.length || !store.state.result) return;
      const { names, grids } = readGashTopographies(files, store.state.result.topography);
      beforeGashes = { extra: structuredClone(store.state.extra), read: $('#gash-files-read').textContent };
      commit(withGashTopographies(store.state.extra, grids), event);
      $('#gash-files-read').textContent = `Gashes 1 to ${names.length}: ${names.join(', ')}.`;
    } catch (e) {
      setError(`${e.message} The gashes in use are unchanged.`);
    }
  });
  store.on('refusal', ({ error, caseObject }) => {
    if (!beforeGashes || !caseObject || !/^inspection\.gashTopographies/.test(error.field || '')) return;
    const back = beforeGashes;
    beforeGashes = null;
    keepError = true;  // the refusal stays in view while the set in use is computed again
    $('#gash-files-read').textContent = back.read;
    setError(`${error.message} The gashes in use are unchanged.`);
    store.setInputs({ extra: back.extra }, { source: 'inspection', force: true });
  });
  $('#gash-files-clear').addEventListener('click', (event) => {
    commit(withGashTopographies(store.state.extra, null), event);
    $('#gash-files-read').textContent = '';
  });
  $('#inspection-uncertainty').addEventListener('change', (event) => {
    setUncertaintyError('');
    store.setInputs({ extra: withUncertainty(store.state.extra, event.target.value) }, { source: 'inspection', at: event.timeStamp });
    store.emit('commit');
  });
  store.on('limits', () => renderUncertainty(store.state));
  store.on('result', (_, state) => {
    if (!keepError) setError('');
    keepError = false;
    beforeGashes = null;
    setUncertaintyError(''); render(state); renderUncertainty(state);
  });
  store.on('restore', () => { renderUncertainty(store.state); if (store.state.result) render(store.state); });
  store.on('refusal', ({ error, caseObject }) => {
    if (!caseObject || !isInspectionField(error.field)) return;
    if (error.field === 'inspection.uncertainty') setUncertaintyError(error.message);
    else if (!keepError) setError(error.message);  // (a refused set of gash files says so itself)
  });
}
