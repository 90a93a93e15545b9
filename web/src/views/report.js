// The printed report (the browser's print, A4 or Letter; the print stylesheet in style.css): a
// head that only print shows, with the date, the rake face's class with its conformity and proven
// class, the hob, wheel and setup data, and the case link; the views the record needs follow (the
// axes to run, the topography maps led by the inspection, the verdict and the correction's
// tables), each kept whole on a page. For print the plots are redrawn to the paper's
// width, and back after.
import { AXES } from '../limits.js';
import { escapeHtml, fmt } from '../format.js';
import { inputRows } from '../io/input-rows.js';
import { classLead } from '../inspection-table.js';

const $ = (selector) => document.querySelector(selector);

// The report's rows of [group, field, value]: the hob, wheel, setup, machine and grid values the
// case gives (io/input-rows.js), the degree, and what was derived.
const GROUPS = ['hob', 'wheel', 'setup', 'machine', 'grid'];
export function reportRows(result, caseObject) {
  const given = inputRows(caseObject).map(([path, v]) => [path.split('.'), v])
    .filter(([p, v]) => p.length === 2 && GROUPS.includes(p[0]) && v !== null && typeof v !== 'object');
  const rows = [];
  for (const group of GROUPS) {
    for (const [[g, field], v] of given) if (g === group) rows.push([group, field, typeof v === 'number' ? fmt(v, 8) : String(v)]);
  }
  if (caseObject.degree !== undefined) rows.push(['axes', 'degree', String(caseObject.degree)]);
  if (!caseObject.setup || caseObject.setup.settingAngle === undefined) rows.push(['setup', 'settingAngle (derived)', `${fmt(result.setup.settingAngle, 8)} deg`]);
  if (caseObject.axes) rows.push(['axes', 'run', AXES.join(', ') + ' as in the case']);
  return rows;
}

// The report's first line: the day, and what was measured (a grid, the machine's points, or nothing).
export function reportDateLine(caseObject, date = new Date()) {
  const points = caseObject.measuredPoints;
  const measured = caseObject.measured ? 'with a measured topography'
    : points ? `with a measured topography at ${points.length} probe points` : 'no measured topography';
  return `Printed ${date.toISOString().slice(0, 10)}; ${measured}.`;
}

// The inspection's line in the report's head: the class with its conformity and the proven class,
// "Rake face (DIN 3968): Class A — conforms (ISO 14253-1, U95 = 2 µm); proven class A." ('' without
// an inspection). The verdict's sentence and the checks lead the topography's page.
export function reportInspectionLine(inspection) {
  const lead = classLead(inspection);
  if (!lead) return '';
  return `Rake face (DIN 3968): ${lead.graded ? `${lead.text}.` : inspection.notGraded || 'Not graded.'}`;
}

export function mountReport(store) {
  store.on('result', ({ result, caseObject }) => {
    $('#report-date').textContent = reportDateLine(caseObject);
    $('#report-inspection').textContent = reportInspectionLine(result.inspection);
    const rows = reportRows(result, caseObject);
    $('#report-inputs').innerHTML = `<table class="grid-table"><thead><tr><th>group</th><th>field</th><th>value</th></tr></thead><tbody>${
      rows.map((r) => `<tr>${r.map((c) => `<td>${escapeHtml(c)}</td>`).join('')}</tr>`).join('')}</tbody></table>`;
  });
  const linkNow = () => { $('#report-link').textContent = location.href; };
  // The plots at the paper's width while printing (their heights as drawn), at the screen's after.
  const resize = () => {
    linkNow();
    if (!self.Plotly) return;
    const printing = window.matchMedia('print').matches;
    for (const el of document.querySelectorAll('.plot')) {
      if (!el.data || el.offsetParent === null) continue;
      self.Plotly.relayout(el, { width: printing ? el.clientWidth : null }).catch(() => {});
    }
  };
  const media = window.matchMedia('print');
  media.addEventListener('change', resize);
  window.addEventListener('beforeprint', resize);
  window.addEventListener('afterprint', resize);
  $('#print-report').addEventListener('click', () => { linkNow(); window.print(); });
}
