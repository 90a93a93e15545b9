// The rake-face inspection (web/src/inspection-table.js; docs/inspection.md) at the top of the
// topography: the class with its conformity (ISO 14253-1) and the proven class first, then the
// verdict with the limiting check and the class after the correction, a warning when U95 is too
// coarse for a tolerance, the rake error, and the table of checks: value, grade (a * where the
// tolerance is a series value, not confirmed), conformity, proven grade, where the tolerance
// comes from, the class tolerances, and after the correction. Under it: the cumulative spread
// (information), what is not graded and what to enter, and the tolerances' sources.
import { INSPECTION } from '../limits.js';
import { escapeHtml, fixed } from '../format.js';
import { SERIES_NOTE, SIMULATED_NOTE, classLead, cumulativeText, inspectionRows, rakeText, uncertaintyWarningText, verdictSentence } from '../inspection-table.js';
import { cellConfidenceOf } from '../tolerance-edit.js';

const $ = (selector) => document.querySelector(selector);
// A figure and its unit, each kept on one line; a narrow column breaks between them.
const value = (v, unit, text = v === null ? null : fixed(v, 3)) => (v === null ? '—' : `<span>${text}</span> <span>${unit}</span>`);
const CONFIDENCE_WORDS = { printed: 'printed', series: 'series*', entered: 'entered' };

function leadHtml(lead, inspection) {
  if (!lead.graded) {
    return `<div class="lead-box" data-part="class" data-conformity="not graded"><strong>Not graded</strong>${
      inspection.notGraded ? ` <small>${escapeHtml(inspection.notGraded.replace(/^Not graded: /, ''))}</small>` : ''}</div>`;
  }
  const conformity = escapeHtml(lead.conformity);
  // A class or proven class on a series value: its *, said under it.
  const note = lead.seriesNote ? `<small data-part="series">${escapeHtml(lead.seriesNote)}</small>` : '';
  // The simulated face: its class, and no decision (no conformity, no proven class).
  if (lead.simulated) return `<div class="lead-box" data-part="class" data-conformity="${conformity}">${escapeHtml(lead.classText)}${note}</div>`;
  if (lead.same) {
    return `<div class="lead-box" data-part="class" data-conformity="${conformity}">${escapeHtml(lead.classText)}; <strong>${
      escapeHtml(lead.provenText)}</strong>${note}</div>`;
  }
  // Different: the class without the uncertainty and the class the measurement proves, side by side.
  return `<div class="lead-box" data-part="class" data-conformity="${conformity}">${escapeHtml(lead.classText)}<small>the class without the uncertainty</small></div>
    <div class="lead-box" data-part="proven" data-conformity="${lead.proven === 'none' ? 'does not conform' : 'conforms'}"><strong>${
      escapeHtml(lead.provenText.replace(/^p/, 'P'))}</strong><small>${lead.proven === 'none'
      ? 'no class holds every graded check within its tolerance less U95' : 'every graded check within its tolerance less U95'}</small></div>${
      note ? `<div class="lead-note">${note}</div>` : ''}`;
}

// The checks' rows with the series marks of the table in use (the case's, or the default).
export const rowsOf = (inspection, extra) =>
  inspectionRows(inspection, { confidenceOf: cellConfidenceOf(extra, INSPECTION.defaultTolerances, inspection.moduleBandIndex) });

function rowHtml(r, after, notGraded) {
  const graded = r.grade !== 'not graded';
  const gradeTitle = !graded ? notGraded : r.series ? `${SERIES_NOTE}. ${r.source}` : '';
  const uText = r.uncertainty === null ? '' : `U95 = ${fixed(r.uncertainty, 2)} ${r.unit}: conforms within the tolerance less U, does not conform beyond it plus U.`;
  // A check of the simulated face: no conformity, no proven grade (nothing measured).
  const undecided = `<td title="${escapeHtml(SIMULATED_NOTE)}">—</td>`;
  const cells = [
    `<td class="num">${value(r.value, escapeHtml(r.unit), r.valueText)}</td>`,
    `<td class="word" data-series="${r.series}"${gradeTitle ? ` title="${escapeHtml(gradeTitle)}"` : ''}>${escapeHtml(graded ? r.gradeText : r.grade)}</td>`,
    !graded ? '<td>—</td>' : !r.decided ? undecided
      : `<td class="word" data-conformity="${escapeHtml(r.conformity)}" title="${escapeHtml(uText)}">${escapeHtml(r.conformity)}</td>`,
    !graded ? '<td>—</td>' : !r.decided ? undecided
      : `<td class="word"${r.provenText.endsWith('*') ? ` title="${escapeHtml(SERIES_NOTE)}"` : ''}>${escapeHtml(r.provenText)}</td>`,
    graded ? `<td class="word" data-confidence="${escapeHtml(r.confidence)}" title="${escapeHtml(r.source)}">${
      escapeHtml(CONFIDENCE_WORDS[r.confidence] || r.confidence)}</td>` : '<td>—</td>',
    `<td class="tolerances">${r.tolerances.split(' · ').map((t) => `<span>${escapeHtml(t)}</span>`).join(' · ')}</td>`,
  ];
  if (after) cells.push(`<td class="num">${r.after ? value(r.after.value, escapeHtml(r.unit), r.after.valueText) : '—'}</td><td class="word">${r.after ? escapeHtml(r.after.grade) : '—'}</td>`);
  return `<tr data-check="${r.check}"><th>${escapeHtml(r.label)}</th>${cells.join('')}</tr>`;
}

function show(result, state) {
  const i = result.inspection;
  $('#inspection').hidden = !i;
  if (!i) return;
  const rows = rowsOf(i, state.extra);
  const lead = classLead(i, undefined, rows);
  $('#inspection-lead').innerHTML = leadHtml(lead, i);
  $('#inspection-lead').dataset.same = String(lead.same);
  $('#inspection-verdict').textContent = verdictSentence(i);
  const warning = uncertaintyWarningText(i);
  $('#inspection-warning').textContent = warning;
  $('#inspection-warning').hidden = !warning;
  $('#inspection-rake').textContent = rakeText(i, result.gearEffect) || '';

  const after = rows.some((r) => r.after);
  $('#inspection-table thead').innerHTML = `<tr><th>check</th><th>value</th><th>grade</th><th title="ISO 14253-1, with the measurement's uncertainty U95">conformity</th>
    <th title="the tightest class whose tolerance less U95 holds the value">proven</th><th title="where the tolerance the grade rests on comes from">tolerance from</th><th>class tolerances</th>${
    after ? '<th title="the face on the identified machine (re-simulated with the identified error), not what the pass is bound to leave">after correction</th><th>grade after</th>' : ''}</tr>`;
  $('#inspection-table tbody').innerHTML = rows.map((r) => rowHtml(r, after, i.notGraded)).join('');

  const starred = rows.filter((r) => r.series);
  const provenStarred = rows.filter((r) => r.decided && r.provenText.endsWith('*'));
  const anySeries = starred.length || rows.some((r) => r.tolerances.includes('*'));
  $('#inspection-series-note').hidden = !anySeries;
  $('#inspection-series-note').textContent = anySeries ? `* ${SERIES_NOTE} (the tolerance table below). ${starred.length
    ? `The grade of the ${starred.map((r) => r.label).join(' and the ')} rests on one.` : 'No grade rests on one.'}${provenStarred.length
    ? ` So does the proven class of the ${provenStarred.map((r) => r.label).join(' and the ')}.` : ''}` : '';
  const cumulative = cumulativeText(i);
  $('#inspection-cumulative').hidden = !cumulative;
  $('#inspection-cumulative').textContent = cumulative || '';
  $('#inspection-not-graded').hidden = !i.notGraded;
  $('#inspection-not-graded span').textContent = i.notGraded || '';
  $('#inspection-not-graded').dataset.check = (rows.find((r) => r.grade === 'not graded') || {}).check || '';
  $('#inspection-not-measured').hidden = !i.notMeasured;
  $('#inspection-not-measured').textContent = i.notMeasured || '';
  const sources = rows.filter((r) => r.source);
  $('#inspection-sources').hidden = !sources.length;
  $('#inspection-sources ul').innerHTML = sources.map((r) => `<li><b>${escapeHtml(r.label)}</b>: ${escapeHtml(r.source)}</li>`).join('');
}

export function mountInspection(store) {
  store.on('result', ({ result }, state) => show(result, state));
  // "Enter tolerances": the tolerance table opened at the first check not graded.
  $('#inspection-enter-tolerances').addEventListener('click', () => {
    $('#tolerance-editor').open = true;
    const check = $('#inspection-not-graded').dataset.check;
    const input = $(`#tolerance-table input[data-check="${check}"]:not([disabled])`) || $('#tolerance-table input:not([disabled])');
    if (input) input.focus();
    $('#tolerance-editor').scrollIntoView({ block: 'nearest' });
  });
}
