// The printed report (the browser's print, A4 or Letter; the print stylesheet in style.css): a
// head that only print shows, with the date, the hob, wheel and setup data, and the case link; the
// views the record needs follow (the axes to run, the topography maps, the verdict and the
// correction's tables), each kept whole on a page. For print the plots are redrawn to the paper's
// width, and back after.
import { AXES } from '../limits.js';
import { escapeHtml, fmt } from '../format.js';

const $ = (selector) => document.querySelector(selector);

// The case's inputs as rows of [group, field, value]: what the form gave and what was derived.
function inputRows(result, caseObject) {
  const rows = [];
  const add = (group, object) => {
    for (const [k, v] of Object.entries(object || {})) {
      if (v !== null && typeof v !== 'object') rows.push([group, k, typeof v === 'number' ? fmt(v, 8) : String(v)]);
    }
  };
  add('hob', caseObject.hob);
  add('wheel', caseObject.wheel);
  add('setup', caseObject.setup);
  add('machine', caseObject.machine);
  add('grid', caseObject.grid);
  if (caseObject.degree !== undefined) rows.push(['axes', 'degree', String(caseObject.degree)]);
  if (!caseObject.setup || caseObject.setup.settingAngle === undefined) rows.push(['setup', 'settingAngle (derived)', `${fmt(result.setup.settingAngle, 8)} deg`]);
  if (caseObject.axes) rows.push(['axes', 'run', AXES.join(', ') + ' as in the case']);
  return rows;
}

export function mountReport(store) {
  store.on('result', ({ result, caseObject }) => {
    $('#report-date').textContent = `Printed ${new Date().toISOString().slice(0, 10)}; ${caseObject.measured ? 'with a measured topography' : 'no measured topography'}.`;
    const rows = inputRows(result, caseObject);
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
