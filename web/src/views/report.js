// The printed report (the browser's print, A4 or Letter; the print stylesheet in style.css). Its
// first page, which only print shows: the verdict in one line (report-lines.js), the date, the
// rake face's class with its conformity and proven class, the job, the inputs with their labels
// and units (the form's own), and the case link as a QR code (npm "qrcode"). Then "Program
// this": the axes to run in the control's units (the page's "Axes to run": wasm/lib/axes-to-run.js's axesToRun)
// with the NC program they belong to (the one offered beside them, event 'ncProgram'). The views the record
// needs follow, each kept whole on a page; the exact polynomials (Tab. 2) close it as an
// appendix. For print the plots are redrawn to the printable width, and back after.
import QRCode from 'qrcode';
import { AXES, CORRECTION } from '../limits.js';
import { escapeHtml } from '../format.js';
import { unitText } from '../result-fields.js';
import { machineUnit, programmed, roundedFiguresText } from '../machine-axes.js';
import { axesToRun, machineCoefficients } from '../../../wasm/lib/axes-to-run.js';
import { LINK_TOO_LONG, QR_MOST_BYTES, jobRows, linkBytes, reportDateLine, reportInputRows, reportInspectionLine, verdictLine } from '../report-lines.js';
import { fieldNames, fieldUnits } from './field-names.js';
import { openForPrint } from './on-demand.js';
import { rowsOf } from './inspection.js';

const $ = (selector) => document.querySelector(selector);

// The form's labels (as HTML, with their symbols) and units of the case's fields, and its groups'
// headings: what the report's inputs table shows instead of the case's field paths.
function formWords() {
  const names = fieldNames();
  const labels = {}, units = {}, groups = {};
  for (const [path, name] of Object.entries(names)) labels[path] = name.html;
  for (const fieldset of document.querySelectorAll('#inputs fieldset[data-group]')) groups[fieldset.dataset.group] = names[fieldset.dataset.group].html;
  Object.assign(units, fieldUnits());
  return { labels, units, groups, text: Object.fromEntries(Object.entries(names).map(([p, n]) => [p, n.text])) };
}

function renderInputs(result, caseObject) {
  const words = formWords();
  const rows = reportInputRows(result, caseObject, words);
  let group = null;
  const body = rows.map((r) => {
    const head = r.group !== group ? `<tr class="report-group"><th colspan="3">${r.group}</th></tr>` : '';
    group = r.group;
    return `${head}<tr><td>${r.label}${r.derived ? ' <small>(derived)</small>' : ''}</td><td class="num">${escapeHtml(r.value)}</td><td>${escapeHtml(r.unit)}</td></tr>`;
  }).join('');
  $('#report-inputs').innerHTML = `<table class="grid-table report-table"><caption>Inputs</caption><tbody>${body}</tbody></table>`;
  const job = jobRows(caseObject.job, words.text);
  $('#report-job').innerHTML = job.length
    ? `<table class="grid-table report-table"><caption>Job</caption><tbody>${job.map(([label, text]) =>
      `<tr><th>${escapeHtml(label)}</th><td class="report-text">${escapeHtml(text)}</td></tr>`).join('')}</tbody></table>`
    : '<p>Job: none given (the job number, customer, hob serial and operator are typed under "Job" above the inputs).</p>';
}

// "Program this": the axes to run in the control's units, as the page's "Axes to run" shows them.
function renderProgramAxes(state) {
  const { axes, words } = axesToRun(state.result, state.resultCase && state.resultCase.axes);
  const source = `(${words})`;
  const helical = state.result.setup.motionUnit === 'rad';
  const m = machineCoefficients(axes, helical);
  const degree = axes.X.length - 1;
  $('#report-program-source').textContent = source;
  // The unit of a cell is its row's (mm or deg) per its column's power of the motion (deg or mm):
  // machineUnit's "mm/deg^2" split so that the numbers fit the paper's width.
  const per = (k) => machineUnit(AXES[0], k, helical).split('/')[1];
  $('#report-axes thead').innerHTML = `<tr><th>axis</th>${Array.from({ length: degree + 1 }, (_, k) =>
    `<th>a${k}${k ? ` <span class="unit">(per ${per(k)})</span>` : ''}</th>`).join('')}</tr>`;
  $('#report-axes tbody').innerHTML = AXES.map((a) => `<tr data-axis="${a}"><th>${a} <span class="unit">(${machineUnit(a, 0, helical)})</span></th>${m[a].map((c, k) =>
    `<td class="num" title="${machineUnit(a, k, helical)}">${programmed(c, CORRECTION.coefficientDigits)}</td>`).join('')}</tr>`).join('');
  $('#report-axes-figures').textContent = roundedFiguresText(state.result.correction, unitText);
}

// The NC program the axes belong to, printed under them: the one the page offers beside "Axes to
// run" for the control chosen (views/machine-axes.js emits it as 'ncProgram'), or none.
function showReportProgram(program) {
  const box = $('#report-program');
  const text = program && typeof program.text === 'string' ? program.text : '';
  box.hidden = !text;
  $('#report-program-name').textContent = text ? `NC program: ${program.name || ''}` : '';
  // One block a line: a block wider than the paper wraps onto indented lines (style.css), so that
  // no continuation reads as a block of its own (a SINUMERIK "Y=PO(...)" alone is a valid block).
  const pre = $('#report-program-text');
  pre.replaceChildren(...(text ? text.replace(/\n$/, '').split('\n') : []).map((line) => {
    const block = document.createElement('span');
    block.className = 'nc-block';
    block.textContent = line;
    return block;
  }));
}

// The case link as a QR code, or a sentence when it is too long for one. Returns a promise.
let shownLink = null;
export function renderLink(link = location.href) {
  if (link === shownLink) return Promise.resolve();
  shownLink = link;
  const box = $('#report-qr'), note = $('#report-link-note');
  const bytes = linkBytes(link);
  if (bytes > QR_MOST_BYTES) {
    box.innerHTML = '';
    box.hidden = true;
    note.textContent = LINK_TOO_LONG(bytes);
    return Promise.resolve();
  }
  return QRCode.toString(link, { type: 'svg', errorCorrectionLevel: 'L', margin: 4 }).then((svg) => {
    if (shownLink !== link) return;
    box.innerHTML = svg;
    box.hidden = false;
    // A module of about 0.33 mm, so that a phone reads it off paper: 30 to 60 mm wide.
    const size = Math.min(60, Math.max(30, 0.33 * Number(/viewBox="0 0 (\d+)/.exec(svg)[1])));
    box.style.setProperty('--qr-size', `${size.toFixed(1)}mm`);
    box.dataset.bytes = String(bytes);
    note.textContent = 'Case link: scan the code to open this case in the calculator.';
  }, (e) => {
    box.hidden = true;
    note.textContent = `The case link could not be made a QR code (${e.message}): save the case file ("Save case") and keep it with this report.`;
  });
}

// The printable width, CSS px: the narrower of A4 (210 mm) and Letter (215.9 mm) less the
// stylesheet's 12 mm margins (@page), so that one layout fits either paper.
export const PRINTABLE_WIDTH = Math.floor(((Math.min(210, 215.9) - 2 * 12) / 25.4) * 96);

// A plot's width in print: the printable width less the insets of the card it sits in (the same
// on its left and right), and no wider than its box.
function printWidth(el) {
  const inset = el.getBoundingClientRect().left - document.documentElement.getBoundingClientRect().left;
  return Math.max(200, Math.floor(Math.min(el.clientWidth, PRINTABLE_WIDTH - 2 * inset)));
}

export function mountReport(store) {
  store.on('ncProgram', ({ program }) => showReportProgram(program));
  store.on('result', ({ result, caseObject }, state) => {
    // The class with the series marks the inspection's table shows (views/inspection.js).
    const rows = result.inspection ? rowsOf(result.inspection, state.extra) : [];
    $('#report-verdict').textContent = verdictLine(result, unitText, rows);
    $('#report-date').textContent = reportDateLine(caseObject);
    $('#report-inspection').textContent = reportInspectionLine(result.inspection, rows);
    renderInputs(result, caseObject);
    renderProgramAxes(state);
    // The link is written after the result (io/url.js): the code follows it.
    queueMicrotask(() => renderLink());
  });
  // The plots at the printable width while printing (their heights as drawn), at the screen's after.
  // The browser lays the printed pages out at the paper's width, not the window's, and tells the
  // page only that print media now apply: the width comes from the paper (printWidth), never from
  // the window's layout, so that a map and its colour bar stay within the card.
  // The parts on demand that the report prints are opened first, and closed after the plots in
  // them are back at the screen's width.
  const resize = () => {
    renderLink();
    const printing = window.matchMedia('print').matches;
    if (printing) {
      openForPrint(true);
      store.emit('print');  // the plots in the parts just opened drawn (plots/passes.js)
    }
    if (self.Plotly) {
      for (const el of document.querySelectorAll('.plot')) {
        if (!el.data || el.offsetParent === null) continue;
        self.Plotly.relayout(el, { width: printing ? printWidth(el) : null }).catch(() => {});
      }
    }
    if (!printing) openForPrint(false);
  };
  const media = window.matchMedia('print');
  media.addEventListener('change', resize);
  window.addEventListener('beforeprint', resize);
  window.addEventListener('afterprint', resize);
  $('#print-report').addEventListener('click', () => { renderLink(); window.print(); });
}
